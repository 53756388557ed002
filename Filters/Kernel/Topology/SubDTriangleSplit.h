// SubD kernel: the triangle split (primal triangle quadrisection, "PTQ") used by Loop,
// the modified butterfly and linear subdivision of triangle meshes.
//
// Every triangle becomes four: one at each corner and one in the middle, joining the three
// new edge points. Child points are numbered in two blocks:
//   edge e   -> child point e
//   vertex v -> child point E + v
// and the children of triangle f are faces 4f + j (j = 0, 1, 2: the corner triangle
// (vertex point of v_j, edge point of edge j, edge point of edge j-1)) and 4f + 3, the middle
// triangle (edge points of edges 0, 1, 2), all keeping the parent's orientation. Child tags
// follow the same inheritance as the quad split (SubDQuadSplit.h).
#ifndef SubDTriangleSplit_h
#define SubDTriangleSplit_h

#include "SubDLevel.h"

namespace subd
{
/// Requires every face of `parent` to be a triangle.
SUBDKERNEL_EXPORT Level SplitTriangles(
  const Level& parent, ChildTopology depth, const ParallelFor& parallelFor = SerialFor);

/// Child point numbering of the triangle split (see above).
struct TriangleSplitNumbering
{
  Index NumEdges;
  Index EdgePoint(Index e) const { return e; }
  Index VertexPoint(Index v) const { return NumEdges + v; }
};

/// The corners of the child j (0, 1, 2: at corner j; 3: the middle) of a triangle whose
/// corners and edges are `fv` and `fe` (see above), in `number`'s points.
SUBD_ALWAYS_INLINE void GetTriangleSplitChild(
  const Index* fv, const Index* fe, const TriangleSplitNumbering& number, Index j, Index* out)
{
  if (j == 3)
  {
    out[0] = number.EdgePoint(fe[0]);
    out[1] = number.EdgePoint(fe[1]);
    out[2] = number.EdgePoint(fe[2]);
    return;
  }
  out[0] = number.VertexPoint(fv[j]);
  out[1] = number.EdgePoint(fe[j]);
  out[2] = number.EdgePoint(fe[j == 0 ? 2 : j - 1]);
}

/// The same for triangle f of `topo` (every face a triangle: no offsets to read).
SUBD_ALWAYS_INLINE void GetTriangleSplitChild(
  const MeshTopology& topo, const TriangleSplitNumbering& number, Index f, Index j, Index* out)
{
  GetTriangleSplitChild(topo.GetTriangleVertices(f), topo.GetTriangleEdges(f), number, j, out);
}
}

#endif
