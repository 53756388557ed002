// SubD kernel: Loop masks for one level of triangle subdivision (C. Loop, "Smooth
// Subdivision Surfaces Based on Triangles", M.S. thesis, University of Utah, 1987), with the
// boundary and crease rules of Hoppe et al. (SIGGRAPH 1994) in the form OpenSubdiv uses:
//
//   edge point   e  = 3/8 (v0 + v1) + 1/8 (a + b)     smooth edge, a and b the vertices
//                                                      opposite the edge in its two triangles
//                e  = (v0 + v1) / 2                   sharp, boundary, non-manifold
//   vertex point v' = (1 - n beta) v + beta sum(v_i)   Smooth or Dart rule, n neighbours, with
//                     beta(n) = (1/n) (5/8 - (3/8 + 1/4 cos(2 pi / n))^2)
//                     (beta = 1/16 for n = 6; beta = 3/16 for n = 3); where nothing around
//                     v is sharp, the same from the new edge points E_i:
//                v' = (1 - 8/5 n beta) v + 8/5 beta sum(E_i)   (sum(E_i) = 3/8 n v + 5/8
//                     sum(v_i), each v_i a wing of two edges), one read per neighbour, not two
//                v' = 3/4 v + 1/8 (a + b)            Crease rule
//                v' = v                              Corner rule
//
// Rows are numbered like the child points of the triangle split (SubDTriangleSplit.h), in
// two blocks: the edge points, which read parent points, and the vertex points, which also
// read edge points.
#ifndef SubDLoopRules_h
#define SubDLoopRules_h

#include "SubDLevel.h"
#include "SubDStencilTable.h"
#include "SubDTriangleSplit.h"

#include <vector>

namespace subd
{
/// Loop's weight per neighbour of a smooth vertex of valence n.
SUBDKERNEL_EXPORT double LoopBeta(Index n);

/// LoopBeta as the rows use it: 1/16 exactly for the regular valence 6, the small valences'
/// values computed once per process.
class SUBDKERNEL_EXPORT LoopBetas
{
public:
  LoopBetas();
  double operator()(Index n) const { return n < static_cast<Index>(this->Table.size()) ? this->Table[n] : LoopBeta(n); }

private:
  const std::vector<double>& Table;
};

/// The smooth vertex row of point v from the new edge points (the form that reads them):
/// (1 - 8/5 n beta) v + 8/5 beta sum(E_i), n edges; edgeSource(i) names the i-th edge
/// point as a source. Returns the row's size.
template <typename EdgeSource>
Index WriteLoopSmoothVertexRow(Index v, Index n, double beta, EdgeSource&& edgeSource, Index* sources, double* weights)
{
  sources[0] = v;
  weights[0] = 1.0 - 1.6 * n * beta;
  for (Index i = 0; i < n; ++i)
  {
    sources[1 + i] = edgeSource(i);
    weights[1 + i] = 1.6 * beta;
  }
  return 1 + n;
}

/// Requires every face of `parent` to be a triangle.
SUBDKERNEL_EXPORT StencilTable BuildLoopStencils(const Level& parent);

/// The same rows written one at a time (SubDRowWriting.h), each vertex's rule planned as its
/// row is written: what BuildLoopStencils stores, and what the finest level applies without
/// storing.
class SUBDKERNEL_EXPORT LoopRowWriter
{
public:
  explicit LoopRowWriter(const Level& parent, const ParallelFor& parallelFor = SerialFor);
  Index GetNumParents() const { return this->Topology.GetNumVertices(); }
  Index GetNumRows() const { return this->Number.VertexPoint(this->Topology.GetNumVertices()); }
  std::vector<Index> GetBlockEnds() const { return { this->Number.VertexPoint(0), this->GetNumRows() }; }
  Index GetMaxRowSize() const { return this->MaxRowSize; }
  Index WriteRow(Index row, Index* sources, double* weights) const;
  template <typename T>
  bool ApplySmoothRow(Index row, const T* parents, const T* children, T* dst) const;
  /// Asks for what ApplySmoothRow reads for `row` (SubDRowWriting.h): an edge's end points
  /// and its faces' corners (the third vertices are found there), a vertex's edge points.
  template <typename T>
  void PrefetchRow(Index row, const T* parents, const T* children) const;
  /// True for the rows ApplySmoothRow evaluates: smooth edges (two faces, not sharp),
  /// vertices with a closed fan and nothing sharp at or around them.
  bool IsSmoothRow(Index row) const
  {
    const Index firstVertexPoint = this->Number.VertexPoint(0);
    return row < firstVertexPoint ? IsSmoothEdge(this->Parent, row) : this->SmoothVertex[row - firstVertexPoint] != 0;
  }

private:

  const Level& Parent;
  const MeshTopology& Topology;
  TriangleSplitNumbering Number;
  Index MaxRowSize;
  LoopBetas Beta;
  std::vector<std::uint8_t> SmoothVertex; // FindSmoothClosedVertices
};

// Edge points of smooth edges; vertex points of vertices with nothing sharp at or around
// them and a closed fan (PlanVertexRule's smooth case), from the edge points. Sources and
// weights in WriteRow's order.
template <typename T>
inline void LoopRowWriter::PrefetchRow(Index row, const T* parents, const T* children) const
{
  const MeshTopology& topo = this->Topology;
  const Index firstVertexPoint = this->Number.VertexPoint(0);
  if (row < firstVertexPoint)
  {
    const Index* ev = topo.GetEdgeVertices(row);
    PrefetchPoint(parents + 3 * static_cast<size_t>(ev[0]));
    PrefetchPoint(parents + 3 * static_cast<size_t>(ev[1]));
    for (Index f : topo.GetEdgeFaces(row))
    {
      PrefetchForRead(topo.GetTriangleVertices(f));
    }
    return;
  }
  for (Index e : topo.GetVertexEdges(row - firstVertexPoint))
  {
    PrefetchPoint(children + 3 * static_cast<size_t>(this->Number.EdgePoint(e)));
  }
}

template <typename T>
SUBD_ALWAYS_INLINE bool LoopRowWriter::ApplySmoothRow(Index row, const T* parents, const T* children, T* dst) const
{
  if (!this->IsSmoothRow(row))
  {
    return false;
  }
  const MeshTopology& topo = this->Topology;
  PointSum point;
  const Index firstVertexPoint = this->Number.VertexPoint(0);
  if (row < firstVertexPoint)
  {
    const Index e = row;
    const IndexSpan ef = topo.GetEdgeFaces(e);
    const Index* ev = topo.GetEdgeVertices(e);
    point.Add(0.375, parents + 3 * static_cast<size_t>(ev[0]));
    point.Add(0.375, parents + 3 * static_cast<size_t>(ev[1]));
    // Every face is a triangle: their corners without reading the face offsets.
    const Index b0 = MeshTopology::ThirdVertex(topo.GetTriangleVertices(ef[0]), ev[0], ev[1]);
    const Index b1 = MeshTopology::ThirdVertex(topo.GetTriangleVertices(ef[1]), ev[0], ev[1]);
    point.Add(0.125, parents + 3 * static_cast<size_t>(b0));
    point.Add(0.125, parents + 3 * static_cast<size_t>(b1));
    point.Store(dst);
    return true;
  }
  const Index v = row - firstVertexPoint;
  const IndexSpan edges = topo.GetVertexEdges(v);
  const Index n = edges.size();
  const double beta = this->Beta(n);
  point.Add(1.0 - 1.6 * n * beta, parents + 3 * static_cast<size_t>(v));
  for (Index e : edges)
  {
    point.Add(1.6 * beta, children + 3 * static_cast<size_t>(this->Number.EdgePoint(e)));
  }
  point.Store(dst);
  return true;
}
}

#endif
