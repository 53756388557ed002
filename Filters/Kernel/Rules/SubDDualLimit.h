// SubD kernel: limit points and tangent planes of the dual schemes, Doo-Sabin and the
// midpoint ("simplest") scheme, at the vertices of a level.
//
// A dual scheme does not keep a vertex v; v becomes its V-face, the polygon of v's child
// points, which the next step treats as a face. Both schemes map a face to a polygon with
// the same centroid (Doo-Sabin's weights alpha_ik and the midpoint polygon are circulant
// with unit column sums) that shrinks onto it (the other eigenvalues are below 1: 1/2 and
// 1/4 for Doo-Sabin, Doo and Sabin 1978; |1 + omega^k| / 2 for the midpoint polygon, Peters
// and Reif 1997). So the centroid of v's V-face is a point of the limit surface, and the
// limit point assigned to v:
//   Doo-Sabin, smooth v with n faces:  (1/n) sum over its faces of v's corner point there;
//   midpoint, smooth v of valence n:    v / 2 + (1 / 2n) sum of its neighbours
//                                        (the mean of its edge midpoints).
// Tangent plane there: the V-face's own Fourier modes (SubDRingTangents.h) over its corners
// in order around v.
// Along a crease or boundary both schemes refine the curve on its own. Doo-Sabin refines it
// by Chaikin's rule, whose limit passes through the midpoint of every edge of a refined
// polygon, so a crease vertex's limit point is the mean of its two child points on the
// crease (the clamped rule next to a corner included). The midpoint scheme keeps its crease
// and boundary polygons, so a kept vertex (MidpointKeepsVertex) is its own limit point; so
// is a pinned vertex (IsDualCornerVertex) of Doo-Sabin.
// As OpenSubdiv's limit masks do, the level's sharpness is read as it is now: a semi-sharp
// feature counts as sharp.
// No closed form (an error naming the vertex): a dart (one crease edge) and a non-manifold
// vertex or one of fewer than three faces without a crease; and tangent planes anywhere
// but at smooth vertices (the surface there has one tangent plane per side of the crease,
// and no mask for it is published for these schemes).
#ifndef SubDDualLimit_h
#define SubDDualLimit_h

#include "SubDLevel.h"
#include "SubDStencilTable.h"

#include <string>

namespace subd
{
/// Limit points (one row per vertex of `level`) or, with `tangents`, two tangent rows per
/// vertex (2v, 2v + 1; cross product outside). False with the reason for a vertex that has
/// none. Rows read the level's points.
SUBDKERNEL_EXPORT bool BuildDooSabinLimitStencils(
  const Level& level, bool tangents, StencilTable& stencils, std::string& error);
SUBDKERNEL_EXPORT bool BuildMidpointLimitStencils(
  const Level& level, bool tangents, StencilTable& stencils, std::string& error);

/// What kind of vertex v is, in the words of limit errors ("a dart: ...", "on the boundary"),
/// for the schemes that treat creases as boundaries.
SUBDKERNEL_EXPORT std::string DescribeVertexForLimit(const Level& level, Index v);
/// The error for a vertex of `scheme` without a closed-form limit point (or tangent plane).
SUBDKERNEL_EXPORT std::string NoClosedFormLimit(const Level& level, Index v, const char* scheme, bool tangents);
}

#endif
