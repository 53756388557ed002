// SubD kernel: Kobbelt's sqrt(3) subdivision (L. Kobbelt, "sqrt(3)-Subdivision", SIGGRAPH
// 2000) on triangle meshes. Each step
//   1. inserts the centroid m = (a + b + c) / 3 of every triangle,
//   2. moves every old vertex v of valence n to (1 - alpha_n) v + (alpha_n / n) sum(v_i),
//      alpha_n = (4 - 2 cos(2 pi / n)) / 9,
//   3. joins each centroid to its triangle's corners and flips every old interior edge, so
//      that the edge (a, b) between triangles T1 (running a->b) and T2 becomes the edge
//      (m1, m2) with the triangles (a, m2, m1) and (b, m1, m2).
// Two steps are a triadic refinement (each edge in three); the face count triples per step.
//
// Child points: centroid of face f -> f, then old vertex v -> F + v.
//
// Boundaries (for now): boundary and non-manifold edges are not flipped (their triangle
// (a, b, m) stays) and boundary and non-manifold vertices keep their position. Kobbelt's
// boundary rule (trisecting boundary edges every second step with the masks 1/27 (10, 16, 1)
// and vertices 1/27 (4, 19, 4)) is not implemented yet.
#ifndef SubDSqrt3Rules_h
#define SubDSqrt3Rules_h

#include "SubDLevel.h"
#include "SubDStencilTable.h"

namespace subd
{
/// Kobbelt's alpha_n.
SUBDKERNEL_EXPORT double Sqrt3Alpha(Index n);

/// Requires every face of `parent` to be a triangle.
SUBDKERNEL_EXPORT StencilTable BuildSqrt3Stencils(const Level& parent);
SUBDKERNEL_EXPORT Level SplitSqrt3(const Level& parent, ChildTopology depth);
}

#endif
