// SubD kernel: the modified butterfly scheme (D. Zorin, P. Schroeder, W. Sweldens,
// "Interpolating Subdivision for Meshes with Arbitrary Topology", SIGGRAPH 1996), an
// interpolating scheme on the triangle split: old vertices stay, and each edge (a0, a1)
// gets a new point from one of these stencils:
//
// - both ends regular (valence 6), or one end on the boundary and the other regular, or both
//   on the boundary: the 10-point butterfly with tension w (Dyn, Levin, Gregory 1990):
//     a (edge ends) 1/2 - w,  b (opposite vertices) 1/8 + 2w,
//     c (four wings, across the edges (a_i, b_j)) -1/16 - w,  d (two tips, a_i's neighbour
//     straight across from the edge) w;
//   w = 0 is the 8-point butterfly of VTK and OpenMesh. A wing missing at a boundary is
//   replaced by its reflection a_i + b_j - a_k (the parallelogram completion, as OpenMesh
//   does); a missing tip by 2 a_i - a_k;
// - otherwise the stencil of each end that is extraordinary (valence K != 6) and interior,
//   averaged when there are two: 3/4 on the vertex and s_j on its j-th neighbour counted
//   from the other end,
//     K = 3: 5/12, -1/12, -1/12;  K = 4: 3/8, 0, -1/8, 0;
//     K >= 5: s_j = (1/4 + cos(2 pi j/K) + 1/2 cos(4 pi j/K)) / K;
// - boundary edges: the 4-point rule -1/16, 9/16, 9/16, -1/16 along the boundary (the
//   midpoint where the boundary does not continue through an end); non-manifold edges:
//   the midpoint.
// Non-manifold vertices are treated like boundary vertices (they have no ring).
//
// Creases are treated like boundaries: a sharp edge takes the boundary's 4-point rule along
// its crease, a vertex with two or more sharp edges has no ring (it takes the boundary
// vertex's place in its neighbours' stencils) and a wing across a crease is reflected like
// a missing one. A dart (one sharp edge) keeps its ring. Semi-sharp edges: sharpness s >= 1
// takes the crease rule, 0 < s < 1 blends s of the crease rule with 1 - s of the smooth one
// (the same transition Catmull-Clark and Loop make when a sharpness reaches zero);
// sharpness decays by one unit per level as in the other primal schemes.
#ifndef SubDButterflyRules_h
#define SubDButterflyRules_h

#include "SubDLevel.h"
#include "SubDStencilTable.h"

namespace subd
{
/// Weight s_j of neighbour j of an extraordinary interior vertex of valence K (the vertex
/// itself gets 1 - sum_j s_j = 3/4).
SUBDKERNEL_EXPORT double ButterflyExtraordinaryWeight(Index K, Index j);

/// Requires every face of `parent` to be a triangle.
SUBDKERNEL_EXPORT StencilTable BuildButterflyStencils(const Level& parent, double tension);
}

#endif
