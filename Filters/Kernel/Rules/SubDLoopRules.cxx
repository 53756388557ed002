#include "SubDLoopRules.h"
#include "SubDRowWriting.h"

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
  const MeshTopology& topo = this->Topology;
  if (row < this->Number.VertexPoint(0))
  {
    const Index e = row;
    const float creaseWeight = EdgeCreaseWeight(this->Parent, e);
    WritePrimalEdgeRow(topo.GetEdgeVertices(e), creaseWeight, 0.375, 0.125, sources, weights, [&](Index* sides) {
      const IndexSpan ef = topo.GetEdgeFaces(e);
      sides[0] = topo.GetTriangleOppositeVertex(ef[0], e);
      sides[1] = topo.GetTriangleOppositeVertex(ef[1], e);
    });
    return PrimalEdgeRowSize(creaseWeight);
  }
  const Index v = row - this->Number.VertexPoint(0);
  const IndexSpan edges = topo.GetVertexEdges(v);
  if (this->SmoothVertex[v])
  {
    // Every edge point around v follows the smooth rule: the form that reads them.
    return WriteLoopSmoothVertexRow(v, edges.size(), this->Beta(edges.size()),
      [&](Index i) { return this->GetNumParents() + this->Number.EdgePoint(edges[i]); }, sources, weights);
  }
  const VertexRulePlan plan = PlanVertexRule(this->Parent, v);
  WritePrimalVertexRow(topo, plan, v, 1 + edges.size(), sources, weights, [&](Index* src, double* wts) {
    const Index n = edges.size();
    src[0] = v;
    const double beta = this->Beta(n);
    wts[0] = 1.0 - n * beta;
    for (Index i = 0; i < n; ++i)
    {
      src[1 + i] = topo.GetOtherEndpoint(edges[i], v);
      wts[1 + i] = beta;
    }
  });
  return PrimalVertexRowSize(plan, 1 + edges.size());
}
}
