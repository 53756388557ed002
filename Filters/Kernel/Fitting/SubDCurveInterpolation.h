// SubD kernel: the limit masks of a set of curves over the input's points, for solving for
// control polygons whose limit curves pass through given points (SubDInterpolation.h).
//
// Each piece of the curves (SubDCurveRefiner.h: polylines cut at their sharp corners) gives
// every point its limit mask (SubDCurveLimit.h) over the piece's points: the uniform B-spline
// at the point's Greville abscissa for Chaikin and the cubic B-spline, the point itself for
// the interpolating 4-point scheme and for the end points of open pieces (every scheme keeps
// them). The closed masks (1, 6, 1)/8 and (1, 4, 1)/6 are strictly diagonally dominant, so a
// closed polygon's system is always solvable; so are the open ones (their end rows are
// identity rows and the rest diagonally dominant).
#ifndef SubDCurveInterpolation_h
#define SubDCurveInterpolation_h

#include "SubDCurveRefiner.h"
#include "SubDInterpolation.h"

#include <string>
#include <vector>

namespace subd
{
/// One row per input point (numPoints): the limit mask of the point on the curve that uses
/// it, over input point ids. A point on no piece gets an empty row; a point whose pieces give
/// it different masks (a point in the middle of one polyline and on another: the curve
/// filter refines it once per polyline, so it has several limit points) gets an empty row and
/// the reason in `problems` (else empty).
SUBDKERNEL_EXPORT void BuildCurveLimitRows(const CurveRules& rules, const CurvePieces& pieces, Index numPoints,
  std::vector<SparseRow>& rows, std::vector<std::string>& problems);
}

#endif
