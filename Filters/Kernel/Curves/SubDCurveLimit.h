// SubD kernel: limit points and limit tangents of the curve schemes, as stencils.
//
// The limit point of a control point is the limit curve at the parameter where that point's
// basis function peaks (its Greville abscissa); the tangent is the curve's derivative there,
// per unit of the level's parameter (one edge of the control polygon).
// - Cubic B-spline: limit (p_{i-1} + 4 p_i + p_{i+1}) / 6, tangent (p_{i+1} - p_{i-1}) / 2
//   (the uniform cubic B-spline at its knot). Open ends: the end point itself, tangent
//   p_1 - p_0 (the phantom 2 p_0 - p_1 of the end rule, SubDCurveRules.h).
// - Chaikin: limit (p_{i-1} + 6 p_i + p_{i+1}) / 8, tangent (p_{i+1} - p_{i-1}) / 2 (the
//   uniform quadratic B-spline in the middle of the span where p_i's basis peaks). Open
//   polygons are clamped quadratic B-splines: the masks near the ends come from evaluating
//   its basis (Cox-de Boor recursion) at the Greville abscissae (t_{i+1} + t_{i+2}) / 2.
// - 4-point: interpolating, so a point is its own limit. The tangent is a left eigenvector of
//   the scheme's local subdivision matrix for the eigenvalue 1/2 (Dyn, Levin, Gregory 1987;
//   the analysis of Zorin and Schroeder's SIGGRAPH 2000 course notes, chapter 3): from the
//   7x7 stationary matrix of points i-3 .. i+3 in the interior, from the matrix of the first
//   six points at an open end, and for the two points next to an end by refining a window of
//   the polygon (exactly, as a matrix) until their descendants are interior. With w = 0 the
//   limit is the polygon itself; its tangent is taken as the mean of both sides.
#ifndef SubDCurveLimit_h
#define SubDCurveLimit_h

#include "SubDCurveRefiner.h"
#include "SubDStencilTable.h"

namespace subd
{
/// One row per point of `pieces`' numbering (numPoints of them): its limit point.
SUBDKERNEL_EXPORT StencilTable CurveLimitStencils(const CurveRules& rules, const CurvePieces& pieces, Index numPoints);

/// One row per entry of pieces.Points, in that order: the limit tangent of that piece at that
/// point (a corner or a point shared by two pieces gets one row in each).
SUBDKERNEL_EXPORT StencilTable CurveTangentStencils(const CurveRules& rules, const CurvePieces& pieces, Index numPoints);

/// The masks for point j of one polygon of n points, over local indices (for tests and the
/// tables above).
SUBDKERNEL_EXPORT void AppendCurveLimitMask(const CurveRules& rules, Index n, bool closed, Index j, StencilRows& rows);
SUBDKERNEL_EXPORT void AppendCurveTangentMask(const CurveRules& rules, Index n, bool closed, Index j, StencilRows& rows);
}

#endif
