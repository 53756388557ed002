// SubD kernel: limit positions at the vertices of a refined level (the points of the limit
// surface that the vertices converge to), for Catmull-Clark and Loop, with the vertex
// rules of SubDCrease.h (the classification at this level, as OpenSubdiv's
// Far::PrimvarRefiner::Limit does; semi-sharp features still present count as sharp):
//
// Catmull-Clark, smooth or dart vertex v of valence n whose faces are all quads, with edge
// neighbours e_i and face-diagonal vertices f_i (Halstead, Kass, DeRose, "Efficient, Fair
// Interpolation using Catmull-Clark Surfaces", SIGGRAPH 1993, from the eigenanalysis of
// the subdivision matrix):
//     v_inf = (n^2 v + 4 sum e_i + sum f_i) / (n (n + 5)).
// (The often-quoted form in terms of the level-1 edge and face points is the same point.)
// A smooth vertex of two faces (one that a face repeats can be one) keeps its place, as in
// OpenSubdiv, which gives it the corner mask.
// Loop, smooth or dart vertex of valence n (Loop 1987; Hoppe et al. 1994):
//     v_inf = (1 - n chi) v + chi sum v_i,   chi = 1 / (3 / (8 beta(n)) + n),
// beta(n) Loop's weight (SubDLoopRules.h): 1/2 v + 1/12 sum v_i for n = 6.
// Both schemes, crease vertex (two sharp edges to a and b, boundaries included): the limit
// of the uniform cubic B-spline along the crease, (a + 4 v + b) / 6. Corner: v.
//
// Rows are one per vertex of the level, reading that level's points.
#ifndef SubDLimitRules_h
#define SubDLimitRules_h

#include "SubDLevel.h"
#include "SubDStencilTable.h"

#include <string>

namespace subd
{
/// Catmull-Clark limit positions. Returns false (and says which vertex in `error`) when a
/// smooth vertex has a face that is not a quad: refine one level first.
SUBDKERNEL_EXPORT bool BuildCatmullClarkLimitStencils(const Level& level, StencilTable& stencils, std::string& error);

/// Loop limit positions; every face must be a triangle.
SUBDKERNEL_EXPORT StencilTable BuildLoopLimitStencils(const Level& level);

/// The limit positions of an interpolating scheme (linear, bilinear, modified butterfly):
/// the identity, since their vertices never move.
SUBDKERNEL_EXPORT StencilTable BuildInterpolatingLimitStencils(const Level& level);
}

#endif
