// SubD kernel: limit points and tangent planes of Kobbelt's sqrt(3) scheme (SubDSqrt3Rules.h)
// at the vertices of a level (L. Kobbelt, "sqrt(3)-Subdivision", SIGGRAPH 2000, section 4).
//
// Smooth vertex v of valence n, none of whose triangles has a boundary or crease edge: one
// step maps v and its ring p_i to v' = (1 - a) v + (a / n) sum p_i, a = alpha_n, and to the
// centroids of its triangles, which are v''s ring. On the ring means q = (1/n) sum p_i this is
// the 2x2 matrix [[1 - a, a], [1/3, 2/3]], whose eigenvalue-1 left eigenvector gives
//     v_inf = (1 - b) v + (b / n) sum p_i,   b = 3a / (1 + 3a)    (Kobbelt's limit mask).
// The map is circulant on the ring (each centroid takes 1/3 of two neighbours, a half turn
// further), so the tangent plane is spanned by the ring's Fourier pair (SubDRingTangents.h).
// A triangle of v with a boundary or crease edge breaks this only in an even step, which
// trisects that edge and gives v new neighbours: when the next step is even and such a
// vertex exists, the level is refined once and the masks of the refined level composed
// with that step (after it, the next step is odd, which keeps every triangle of v's ring
// free of curve edges).
// Vertex on a boundary or crease (two curve edges, to a and b): the curve is refined every
// second step by the cubic B-spline masks, so its limit is (a + 4 v + b) / 6. Fixed
// vertices (corners, sharp, non-manifold) stay. As OpenSubdiv's limit masks do, the level's
// sharpness is read as it is now: a semi-sharp feature counts as sharp.
// No closed form (an error naming the vertex): a dart; tangent planes anywhere but at smooth
// vertices.
#ifndef SubDSqrt3Limit_h
#define SubDSqrt3Limit_h

#include "SubDLevel.h"
#include "SubDStencilTable.h"

#include <string>

namespace subd
{
/// Limit points (one row per vertex) or, with `tangents`, two tangent rows per vertex (2v,
/// 2v + 1; cross product outside), over the points of `level` (full topology).
SUBDKERNEL_EXPORT bool BuildSqrt3LimitStencils(
  const Level& level, bool tangents, StencilTable& stencils, std::string& error);
}

#endif
