#include "SubDLoopRules.h"

#include <algorithm>
#include <cmath>

namespace subd
{
double LoopBeta(Index n)
{
  const double pi = 3.14159265358979323846;
  const double c = 0.375 + 0.25 * std::cos(2.0 * pi / n);
  return (0.625 - c * c) / n;
}

StencilTable BuildLoopStencils(const Level& parent)
{
  const MeshTopology& topo = parent.Topology;
  // Smooth edge rows have 4 entries, smooth vertex rows 1 + n (7 where regular).
  const size_t expected = 4 * static_cast<size_t>(topo.GetNumEdges()) + 7 * static_cast<size_t>(topo.GetNumVertices());
  return WriteStencilTable(LoopRowWriter(parent), expected);
}

LoopRowWriter::LoopRowWriter(const Level& parent, const ParallelFor& parallelFor)
  : Parent(parent)
  , Topology(parent.Topology)
  , Number{ parent.Topology.GetNumEdges() }
  , MaxRowSize(std::max<Index>(4, 1 + parent.Topology.GetMaxValence()))
  , SmoothVertex(FindSmoothClosedVertices(parent, parallelFor))
{
}

LoopBetas::LoopBetas()
  : Table([]() -> const std::vector<double>& {
    static const std::vector<double> table = [] {
      std::vector<double> values(64);
      for (Index n = 1; n < 64; ++n)
      {
        values[n] = n == 6 ? 0.0625 : LoopBeta(n);
      }
      return values;
    }();
    return table;
  }())
{
}

Index LoopRowWriter::WriteRow(Index row, Index* sources, double* weights) const
{
  RowEntries entries{ sources, weights, this->GetNumParents() };
  if (this->VisitSmoothRow(row, entries))
  {
    return entries.Size;
  }
  const MeshTopology& topo = this->Topology;
  if (row < this->Number.VertexPoint(0))
  {
    const Index e = row;
    const float creaseWeight = EdgeCreaseWeight(this->Parent, e);
    WritePrimalEdgeRow(topo.GetEdgeVertices(e), creaseWeight, LoopEdgeEndWeight, LoopEdgeOppositeWeight, sources,
      weights, [&](Index* sides) {
        const IndexSpan ef = topo.GetEdgeFaces(e);
        sides[0] = topo.GetTriangleOppositeVertex(ef[0], e);
        sides[1] = topo.GetTriangleOppositeVertex(ef[1], e);
      });
    return PrimalEdgeRowSize(creaseWeight);
  }
  const Index v = row - this->Number.VertexPoint(0);
  const IndexSpan edges = topo.GetVertexEdges(v);
  const VertexRulePlan plan = PlanVertexRule(this->Parent, v);
  WritePrimalVertexRow(topo, plan, v, 1 + edges.size(), sources, weights, [&](Index* src, double* wts) {
    RowEntries ring{ src, wts, this->GetNumParents() };
    LoopRingVertexMask(topo, v, edges, this->Beta(edges.size()), ring);
  });
  return PrimalVertexRowSize(plan, 1 + edges.size());
}
}
