// SubD kernel: the masks of the curve subdivision schemes, for one control polygon.
//
// A polygon of n points p_0 .. p_{n-1}, open or closed, is refined into its child polygon;
// each child point is a weighted sum of the parent points (rows over local indices 0..n-1).
//
// Closed polygons (indices taken modulo n):
// - Chaikin (Chaikin 1974; Riesenfeld 1975): each edge (p_i, p_{i+1}) gives two children,
//   3/4 p_i + 1/4 p_{i+1} and 1/4 p_i + 3/4 p_{i+1}. The limit is the uniform quadratic
//   B-spline of the polygon.
// - Cubic B-spline (Lane and Riesenfeld 1980): vertex child (p_{i-1} + 6 p_i + p_{i+1}) / 8,
//   then edge child (p_i + p_{i+1}) / 2. The limit is the uniform cubic B-spline.
// - 4-point (Dyn, Levin and Gregory 1987, "A 4-point interpolatory subdivision scheme for curve
//   design"): the vertex is kept, the edge child is -w p_{i-1} + (1/2 + w)(p_i + p_{i+1}) - w p_{i+2}
//   with tension w (1/16 reproduces cubic polynomials; C1 for 0 < w < 1/8).
// Child order: for each i, the child of vertex i (4-point, cubic) then the child(ren) of edge i.
// Chaikin has no vertex children: its children are the two of edge 0, then of edge 1, ...
//
// Open polygons keep both end points (every scheme interpolates its ends) and follow these
// end rules, so that a level's child polygon is again an open polygon of the same kind:
// - Chaikin: the polygon is the control polygon of a quadratic B-spline with clamped
//   (triple) end knots and unit interior knot spacing; one level inserts a knot in the middle
//   of every span (Boehm's knot insertion), which gives p_0, (p_0 + p_1)/2, then the interior
//   pairs 3/4, 1/4 and 1/4, 3/4 of edges 1 .. n-3, then (p_{n-2} + p_{n-1})/2, p_{n-1}: 2n-2
//   points, again clamped with uniform spacing. A 2-point polygon (a straight segment, for
//   which a quadratic does not exist) gains its midpoint.
// - Cubic B-spline: the end points are kept and the interior rules apply elsewhere (the rule
//   of boundary and crease curves: the uniform cubic B-spline of the polygon extended by the
//   phantom points 2 p_0 - p_1 and 2 p_{n-1} - p_{n-2}, whose limit ends at p_0 and p_{n-1}).
// - 4-point: the missing neighbour of an end segment is a phantom point extrapolated by the
//   polynomial through the nearest min(n, 4) points (p_{-1} = 4 p_0 - 6 p_1 + 4 p_2 - p_3 for
//   n >= 4). With w = 1/16 the end segments then reproduce cubics as the interior does, so a
//   polygon sampled from a cubic stays on it up to the ends.
// A single point is its own child.
#ifndef SubDCurveRules_h
#define SubDCurveRules_h

#include "SubDStencilTable.h"
#include "SubDTypes.h"

#include <vector>

namespace subd
{
enum class CurveScheme : int
{
  Chaikin = 0,
  CubicBSpline = 1,
  FourPoint = 2
};

SUBDKERNEL_EXPORT const char* ToString(CurveScheme scheme);

struct CurveRules
{
  CurveScheme Scheme = CurveScheme::CubicBSpline;
  double Tension = 1.0 / 16.0; ///< the 4-point scheme's w
};

/// Whether a polygon of n points is refined as closed: closed polygons need three points.
inline bool IsClosedPolygon(Index n, bool closed)
{
  return closed && n >= 3;
}

/// The number of child points of a polygon of n points (see IsClosedPolygon).
SUBDKERNEL_EXPORT Index CurveChildCount(const CurveRules& rules, Index n, bool closed);

/// Appends one row per child point of a polygon of n points, in child order.
SUBDKERNEL_EXPORT void AppendCurveChildRows(const CurveRules& rules, Index n, bool closed, StencilRows& rows);
}

#endif
