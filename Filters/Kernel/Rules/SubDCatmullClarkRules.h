// SubD kernel: Catmull-Clark masks for one level (E. Catmull, J. Clark, "Recursively
// generated B-spline surfaces on arbitrary topological meshes", CAD 10(6), 1978), with the
// boundary and crease rules of Hoppe et al. (SIGGRAPH 1994) and DeRose et al. (SIGGRAPH 1998)
// in the form OpenSubdiv uses, so the results agree with it to round-off:
//
//   face point   f  = average of the face's n vertices
//   edge point   e  = (v0 + v1 + f0 + f1) / 4                     smooth edge (two faces)
//                e  = (v0 + v1) / 2                               sharp, boundary, non-manifold
//   vertex point v' = (n-2)/n v + 1/n^2 sum(e_i) + 1/n^2 sum(f_i)  Smooth or Dart rule, n faces,
//                     e_i the far ends of the n edges, f_i the new face points; where nothing
//                     around v is sharp, the same from the new edge points E_i:
//                v' = (n-3)/n v + 4/n^2 sum(E_i) - 1/n^2 sum(f_i)  (sum(E_i) = (n v + sum(e_i)
//                     + 2 sum(f_i)) / 4), one read per neighbour instead of two
//                v' = 3/4 v + 1/8 (a + b)                         Crease rule, a, b the far ends
//                                                                  of the two sharp edges
//                v' = v                                           Corner rule
//
// The returned table has three blocks: the face points, the edge points, which read the
// face points of the same level, and the vertex points, which read both. Its rows are numbered like the child
// points of the quad split (SubDQuadSplit.h).
#ifndef SubDCatmullClarkRules_h
#define SubDCatmullClarkRules_h

#include "SubDLevel.h"
#include "SubDQuadSplit.h"
#include "SubDStencilTable.h"

namespace subd
{
SUBDKERNEL_EXPORT StencilTable BuildCatmullClarkStencils(const Level& parent);

/// The smooth vertex row of point v from the new edge and face points (the form that reads
/// them): (n-3)/n v + 4/n^2 sum(E_i) - 1/n^2 sum(F_i), n faces; edgeSource(i) and
/// faceSource(i) name the i-th edge and face point as sources. Returns the row's size.
template <typename EdgeSource, typename FaceSource>
Index WriteCatmullClarkSmoothVertexRow(Index v, Index numEdges, Index numFaces, EdgeSource&& edgeSource,
  FaceSource&& faceSource, Index* sources, double* weights)
{
  const double n = numFaces;
  sources[0] = v;
  weights[0] = (n - 3.0) / n;
  for (Index i = 0; i < numEdges; ++i)
  {
    sources[1 + i] = edgeSource(i);
    weights[1 + i] = 4.0 / (n * n);
  }
  for (Index i = 0; i < numFaces; ++i)
  {
    sources[1 + numEdges + i] = faceSource(i);
    weights[1 + numEdges + i] = -1.0 / (n * n);
  }
  return 1 + numEdges + numFaces;
}

/// The same rows written one at a time (SubDRowWriting.h), each vertex's rule planned as its
/// row is written: what BuildCatmullClarkStencils stores, and what the finest level applies
/// without storing.
class SUBDKERNEL_EXPORT CatmullClarkRowWriter
{
public:
  explicit CatmullClarkRowWriter(const Level& parent, const ParallelFor& parallelFor = SerialFor);
  Index GetNumParents() const { return this->Topology.GetNumVertices(); }
  Index GetNumRows() const { return this->Number.VertexPoint(this->Topology.GetNumVertices()); }
  std::vector<Index> GetBlockEnds() const
  {
    return { this->Number.EdgePoint(0), this->Number.VertexPoint(0), this->GetNumRows() };
  }
  Index GetMaxRowSize() const { return this->MaxRowSize; }
  Index WriteRow(Index row, Index* sources, double* weights) const;
  template <typename T>
  bool ApplySmoothRow(Index row, const T* parents, const T* children, T* dst) const;
  /// Asks for the points ApplySmoothRow reads for `row` (SubDRowWriting.h).
  template <typename T>
  void PrefetchRow(Index row, const T* parents, const T* children) const;
  /// True for the rows ApplySmoothRow evaluates: face points, smooth edges (two faces, not
  /// sharp), vertices with a closed fan and nothing sharp at or around them.
  bool IsSmoothRow(Index row) const
  {
    if (row < this->Number.NumFaces)
    {
      return true;
    }
    const Index firstVertexPoint = this->Number.VertexPoint(0);
    return row < firstVertexPoint ? IsSmoothEdge(this->Parent, row - this->Number.NumFaces)
                                  : this->SmoothVertex[row - firstVertexPoint] != 0;
  }

private:
  Index WriteEdgeRow(Index e, Index* sources, double* weights) const;
  Index WriteVertexRow(Index v, Index* sources, double* weights) const;

  const Level& Parent;
  const MeshTopology& Topology;
  QuadSplitNumbering Number;
  Index MaxRowSize = 4;
  std::vector<std::uint8_t> SmoothVertex; // FindSmoothClosedVertices
};

template <typename T>
inline void CatmullClarkRowWriter::PrefetchRow(Index row, const T* parents, const T* children) const
{
  const MeshTopology& topo = this->Topology;
  auto ask = [](const T* point) { PrefetchPoint(point); };
  if (row < this->Number.NumFaces)
  {
    for (Index v : topo.GetFaceVertices(row))
    {
      ask(parents + 3 * static_cast<size_t>(v));
    }
    return;
  }
  const Index firstVertexPoint = this->Number.VertexPoint(0);
  if (row < firstVertexPoint)
  {
    const Index e = row - this->Number.NumFaces;
    const Index* ev = topo.GetEdgeVertices(e);
    ask(parents + 3 * static_cast<size_t>(ev[0]));
    ask(parents + 3 * static_cast<size_t>(ev[1]));
    for (Index f : topo.GetEdgeFaces(e))
    {
      ask(children + 3 * static_cast<size_t>(this->Number.FacePoint(f)));
    }
    return;
  }
  const Index v = row - firstVertexPoint;
  for (Index e : topo.GetVertexEdges(v))
  {
    ask(children + 3 * static_cast<size_t>(this->Number.EdgePoint(e)));
  }
  for (Index f : topo.GetVertexFaces(v))
  {
    ask(children + 3 * static_cast<size_t>(this->Number.FacePoint(f)));
  }
}

// Face points always; edge points of smooth edges; vertex points of vertices with nothing
// sharp at or around them and a closed fan (PlanVertexRule's smooth case), from the edge
// points. Sources and weights in WriteRow's order.
template <typename T>
SUBD_ALWAYS_INLINE bool CatmullClarkRowWriter::ApplySmoothRow(Index row, const T* parents, const T* children, T* dst) const
{
  const MeshTopology& topo = this->Topology;
  if (!this->IsSmoothRow(row))
  {
    return false;
  }
  PointSum point;
  if (row < this->Number.NumFaces)
  {
    const IndexSpan fv = topo.GetFaceVertices(row);
    const double w = 1.0 / fv.size();
    for (Index v : fv)
    {
      point.Add(w, parents + 3 * static_cast<size_t>(v));
    }
    point.Store(dst);
    return true;
  }
  const Index firstVertexPoint = this->Number.VertexPoint(0);
  if (row < firstVertexPoint)
  {
    const Index e = row - this->Number.NumFaces;
    const IndexSpan ef = topo.GetEdgeFaces(e);
    const Index* ev = topo.GetEdgeVertices(e);
    point.Add(0.25, parents + 3 * static_cast<size_t>(ev[0]));
    point.Add(0.25, parents + 3 * static_cast<size_t>(ev[1]));
    point.Add(0.25, children + 3 * static_cast<size_t>(this->Number.FacePoint(ef[0])));
    point.Add(0.25, children + 3 * static_cast<size_t>(this->Number.FacePoint(ef[1])));
    point.Store(dst);
    return true;
  }
  const Index v = row - firstVertexPoint;
  const IndexSpan edges = topo.GetVertexEdges(v);
  const IndexSpan faces = topo.GetVertexFaces(v);
  const double n = faces.size();
  point.Add((n - 3.0) / n, parents + 3 * static_cast<size_t>(v));
  for (Index e : edges)
  {
    point.Add(4.0 / (n * n), children + 3 * static_cast<size_t>(this->Number.EdgePoint(e)));
  }
  for (Index f : faces)
  {
    point.Add(-1.0 / (n * n), children + 3 * static_cast<size_t>(this->Number.FacePoint(f)));
  }
  point.Store(dst);
  return true;
}
}

#endif
