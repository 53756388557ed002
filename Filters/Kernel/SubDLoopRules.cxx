#include "SubDLoopRules.h"
#include "SubDTriangleSplit.h"

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
  const Index numEdges = topo.GetNumEdges();
  const Index numVertices = topo.GetNumVertices();
  const TriangleSplitNumbering number{ numEdges };

  const std::vector<VertexRulePlan> plans = PlanVertexRules(parent);
  const std::vector<float> creaseWeights = EdgeCreaseWeights(parent);

  StencilTable table(numVertices);
  table.ReserveRows(numEdges + numVertices);
  for (Index e = 0; e < numEdges; ++e)
  {
    table.SetRowSize(number.EdgePoint(e), PrimalEdgeRowSize(creaseWeights[e]));
  }
  for (Index v = 0; v < numVertices; ++v)
  {
    table.SetRowSize(number.VertexPoint(v), PrimalVertexRowSize(plans[v], 1 + topo.GetVertexEdges(v).size()));
  }
  table.FinalizeSizes();

  for (Index e = 0; e < numEdges; ++e)
  {
    WritePrimalEdgeRow(topo.GetEdgeVertices(e), creaseWeights[e], 0.375, 0.125,
      table.GetMutableSources(number.EdgePoint(e)), table.GetMutableWeights(number.EdgePoint(e)),
      [&](Index* sides) {
        const IndexSpan ef = topo.GetEdgeFaces(e);
        sides[0] = topo.GetTriangleOppositeVertex(ef[0], e);
        sides[1] = topo.GetTriangleOppositeVertex(ef[1], e);
      });
  }
  for (Index v = 0; v < numVertices; ++v)
  {
    Index* src = table.GetMutableSources(number.VertexPoint(v));
    double* wts = table.GetMutableWeights(number.VertexPoint(v));
    const IndexSpan edges = topo.GetVertexEdges(v);
    WritePrimalVertexRow(topo, plans[v], v, 1 + edges.size(), src, wts, [&](Index* src, double* wts) {
      const Index n = edges.size();
      src[0] = v;
      const double beta = n == 6 ? 0.0625 : LoopBeta(n);
      wts[0] = 1.0 - n * beta;
      for (Index i = 0; i < n; ++i)
      {
        src[1 + i] = topo.GetOtherEndpoint(edges[i], v);
        wts[1 + i] = beta;
      }
    });
  }
  table.EndBlock(numEdges + numVertices);
  return table;
}
}
