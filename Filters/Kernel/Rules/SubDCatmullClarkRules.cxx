#include "SubDCatmullClarkRules.h"
#include "SubDCrease.h"

#include <algorithm>

namespace subd
{
StencilTable BuildCatmullClarkStencils(const Level& parent, bool smoothTriangles)
{
  const MeshTopology& topo = parent.Topology;
  // Face rows hold a face's corners; smooth edge rows 4 entries, smooth vertex rows 1 + 2n.
  const size_t expected = static_cast<size_t>(topo.GetNumFaceCorners()) * 3 + 4 * static_cast<size_t>(topo.GetNumEdges()) +
    static_cast<size_t>(topo.GetNumVertices());
  return WriteStencilTable(CatmullClarkRowWriter(parent, SerialFor, smoothTriangles), expected);
}

CatmullClarkRowWriter::CatmullClarkRowWriter(const Level& parent, const ParallelFor& parallelFor, bool smoothTriangles)
  : Parent(parent)
  , Topology(parent.Topology)
  , Number{ parent.Topology.GetNumFaces(), parent.Topology.GetNumEdges() }
  , SmoothVertex(FindSmoothClosedVertices(parent, parallelFor))
  , SmoothTriangles(smoothTriangles)
{
  const MeshTopology& topo = this->Topology;
  for (Index f = 0; f < topo.GetNumFaces(); ++f)
  {
    this->MaxRowSize = std::max(this->MaxRowSize, topo.GetFaceSize(f));
  }
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    this->MaxRowSize = std::max(this->MaxRowSize, 1 + 2 * topo.GetVertexFaces(v).size());
  }
}

Index CatmullClarkRowWriter::WriteRow(Index row, Index* sources, double* weights) const
{
  RowEntries entries{ sources, weights, this->GetNumParents() };
  if (this->VisitSmoothRow(row, entries))
  {
    return entries.Size;
  }
  if (row < this->Number.VertexPoint(0))
  {
    return this->WriteEdgeRow(row - this->Number.NumFaces, sources, weights);
  }
  return this->WriteVertexRow(row - this->Number.VertexPoint(0), sources, weights);
}

Index CatmullClarkRowWriter::WriteEdgeRow(Index e, Index* sources, double* weights) const
{
  // Sources >= numParents name child points of this level: here the face points.
  const Index numParents = this->GetNumParents();
  const float creaseWeight = EdgeCreaseWeight(this->Parent, e);
  const IndexSpan faces = this->Topology.GetEdgeFaces(e);
  const double faceWeight = creaseWeight < 1.0f // then the edge has two faces
    ? CatmullClarkEdgeFaceWeightOf(this->Topology, faces, this->SmoothTriangles)
    : CatmullClarkEdgeFaceWeight;
  WritePrimalEdgeRow(this->Topology.GetEdgeVertices(e), creaseWeight, 0.5 - faceWeight, faceWeight, sources, weights,
    [&](Index* sides) {
      const IndexSpan ef = this->Topology.GetEdgeFaces(e);
      sides[0] = numParents + this->Number.FacePoint(ef[0]);
      sides[1] = numParents + this->Number.FacePoint(ef[1]);
    });
  return PrimalEdgeRowSize(creaseWeight);
}

Index CatmullClarkRowWriter::WriteVertexRow(Index v, Index* sources, double* weights) const
{
  const MeshTopology& topo = this->Topology;
  const IndexSpan edges = topo.GetVertexEdges(v);
  const IndexSpan faces = topo.GetVertexFaces(v);
  const Index smoothSize = 1 + 2 * faces.size();
  const VertexRulePlan plan = PlanVertexRule(this->Parent, v);
  WritePrimalVertexRow(topo, plan, v, smoothSize, sources, weights, [&](Index* src, double* wts) {
    RowEntries ring{ src, wts, this->GetNumParents() };
    CatmullClarkRingVertexMask(
      topo, v, edges, faces.size(), [&](Index i) { return this->Number.FacePoint(faces[i]); }, ring);
  });
  return PrimalVertexRowSize(plan, smoothSize);
}
}
