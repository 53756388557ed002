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
#include "SubDPrimalRules.h"
#include "SubDRowWriting.h"
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

/// Loop's smooth edge weights (on each end, on each vertex opposite the edge); the crease
/// rule blends them with the midpoint (WritePrimalEdgeRow).
constexpr double LoopEdgeEndWeight = 0.375;
constexpr double LoopEdgeOppositeWeight = 0.125;

/// The smooth edge point of an edge with ends `ends` and opposite vertices `opposite`.
template <typename Entries>
void LoopSmoothEdgeMask(const Index* ends, const Index* opposite, Entries& entries)
{
  entries.Parent(ends[0], LoopEdgeEndWeight);
  entries.Parent(ends[1], LoopEdgeEndWeight);
  entries.Parent(opposite[0], LoopEdgeOppositeWeight);
  entries.Parent(opposite[1], LoopEdgeOppositeWeight);
}

/// The smooth vertex point of v from the new edge points around it (the form that reads
/// them): (1 - 8/5 n beta) v + 8/5 beta sum(E_i), n edges; edgePoint(i) names the i-th.
template <typename EdgePoint, typename Entries>
void LoopSmoothVertexMask(Index v, Index n, double beta, EdgePoint&& edgePoint, Entries& entries)
{
  entries.Parent(v, 1.0 - 1.6 * n * beta);
  for (Index i = 0; i < n; ++i)
  {
    entries.Child(edgePoint(i), 1.6 * beta);
  }
}

/// The same vertex point from the parent's ring (the form a crease's semi-sharp transition
/// blends with the crease rule, WritePrimalVertexRow): (1 - n beta) v + beta sum(v_i).
template <typename Entries>
void LoopRingVertexMask(const MeshTopology& topo, Index v, IndexSpan edges, double beta, Entries& entries)
{
  entries.Parent(v, 1.0 - edges.size() * beta);
  for (Index e : edges)
  {
    entries.Parent(topo.GetOtherEndpoint(e, v), beta);
  }
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
  /// Smooth edges (two faces, not sharp), vertices with a closed fan and nothing sharp at or
  /// around them (FindSmoothClosedVertices): their masks; false for other rows.
  template <typename Entries>
  bool VisitSmoothRow(Index row, Entries& entries) const;

private:
  const Level& Parent;
  const MeshTopology& Topology;
  TriangleSplitNumbering Number;
  Index MaxRowSize;
  LoopBetas Beta;
  std::vector<std::uint8_t> SmoothVertex; // FindSmoothClosedVertices
};

template <typename Entries>
SUBD_ALWAYS_INLINE bool LoopRowWriter::VisitSmoothRow(Index row, Entries& entries) const
{
  const MeshTopology& topo = this->Topology;
  const Index firstVertexPoint = this->Number.VertexPoint(0);
  if (row < firstVertexPoint)
  {
    const Index e = row;
    if (!IsSmoothEdge(this->Parent, e))
    {
      return false;
    }
    const IndexSpan ef = topo.GetEdgeFaces(e);
    const Index* ev = topo.GetEdgeVertices(e);
    // Every face is a triangle: their corners without reading the face offsets.
    const Index opposite[2] = { MeshTopology::ThirdVertex(topo.GetTriangleVertices(ef[0]), ev[0], ev[1]),
      MeshTopology::ThirdVertex(topo.GetTriangleVertices(ef[1]), ev[0], ev[1]) };
    LoopSmoothEdgeMask(ev, opposite, entries);
    return true;
  }
  const Index v = row - firstVertexPoint;
  if (!this->SmoothVertex[v])
  {
    return false;
  }
  const IndexSpan edges = topo.GetVertexEdges(v);
  LoopSmoothVertexMask(
    v, edges.size(), this->Beta(edges.size()), [&](Index i) { return this->Number.EdgePoint(edges[i]); }, entries);
  return true;
}
}

#endif
