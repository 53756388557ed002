// SubD kernel: the quad split (primal quadrilateral quadrisection, "PQQ") used by
// Catmull-Clark and bilinear subdivision.
//
// Every n-sided face becomes n quads meeting at a new face point; every edge gets an edge
// point; every vertex gets a vertex point. Child points are numbered in three blocks:
//   face f   -> child point f
//   edge e   -> child point F + e
//   vertex v -> child point F + E + v
// and the child of face f at corner j is face FaceOffset(f) + j, with corners
//   (vertex point of v_j, edge point of edge j, face point, edge point of edge j-1),
// which keeps the parent's orientation. Child tags: the two halves of an edge inherit its
// sharpness decayed by one level, a vertex point inherits its vertex's decayed sharpness,
// new edges inside a face and new points are smooth; holes and face origins are inherited.
#ifndef SubDQuadSplit_h
#define SubDQuadSplit_h

#include "SubDLevel.h"

namespace subd
{
SUBDKERNEL_EXPORT Level SplitQuads(
  const Level& parent, ChildTopology depth, const ParallelFor& parallelFor = SerialFor);

/// Child point numbering of the quad split (see above).
struct QuadSplitNumbering
{
  Index NumFaces, NumEdges;
  Index FacePoint(Index f) const { return f; }
  Index EdgePoint(Index e) const { return NumFaces + e; }
  Index VertexPoint(Index v) const { return NumFaces + NumEdges + v; }
};

/// The corners of the child at corner j of face f, whose n corners and edges are `fv` and
/// `fe` (see above), in `number`'s points.
inline void GetQuadSplitChild(
  const Index* fv, const Index* fe, Index n, const QuadSplitNumbering& number, Index f, Index j, Index* out)
{
  out[0] = number.VertexPoint(fv[j]);
  out[1] = number.EdgePoint(fe[j]);
  out[2] = number.FacePoint(f);
  out[3] = number.EdgePoint(fe[j == 0 ? n - 1 : j - 1]);
}

/// The same for face f of `topo`.
inline void GetQuadSplitChild(const MeshTopology& topo, const QuadSplitNumbering& number, Index f, Index j, Index* out)
{
  const IndexSpan fv = topo.GetFaceVertices(f);
  GetQuadSplitChild(fv.Data, topo.GetFaceEdges(f).Data, fv.size(), number, f, j, out);
}
}

#endif
