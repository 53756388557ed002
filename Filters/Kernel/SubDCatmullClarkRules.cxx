#include "SubDCatmullClarkRules.h"
#include "SubDCrease.h"
#include "SubDQuadSplit.h"

namespace subd
{
StencilTable BuildCatmullClarkStencils(const Level& parent)
{
  const MeshTopology& topo = parent.Topology;
  const Index numFaces = topo.GetNumFaces();
  const Index numEdges = topo.GetNumEdges();
  const Index numVertices = topo.GetNumVertices();
  const QuadSplitNumbering number{ numFaces, numEdges };
  // Sources >= numParents name child points of this level.
  const Index numParents = numVertices;
  auto childSource = [numParents](Index childPoint) { return numParents + childPoint; };

  const std::vector<VertexRulePlan> plans = PlanVertexRules(parent);
  const std::vector<float> creaseWeights = EdgeCreaseWeights(parent);

  StencilTable table(numParents);
  table.ReserveRows(numFaces + numEdges + numVertices);
  for (Index f = 0; f < numFaces; ++f)
  {
    table.SetRowSize(number.FacePoint(f), topo.GetFaceSize(f));
  }
  for (Index e = 0; e < numEdges; ++e)
  {
    table.SetRowSize(number.EdgePoint(e), PrimalEdgeRowSize(creaseWeights[e]));
  }
  for (Index v = 0; v < numVertices; ++v)
  {
    table.SetRowSize(number.VertexPoint(v), PrimalVertexRowSize(plans[v], 1 + 2 * topo.GetVertexFaces(v).size()));
  }
  table.FinalizeSizes();

  for (Index f = 0; f < numFaces; ++f)
  {
    const IndexSpan fv = topo.GetFaceVertices(f);
    const double w = 1.0 / fv.size();
    Index* src = table.GetMutableSources(number.FacePoint(f));
    double* wts = table.GetMutableWeights(number.FacePoint(f));
    for (Index j = 0; j < fv.size(); ++j)
    {
      src[j] = fv[j];
      wts[j] = w;
    }
  }
  table.EndBlock(numFaces);

  for (Index e = 0; e < numEdges; ++e)
  {
    WritePrimalEdgeRow(topo.GetEdgeVertices(e), creaseWeights[e], 0.25, 0.25,
      table.GetMutableSources(number.EdgePoint(e)), table.GetMutableWeights(number.EdgePoint(e)),
      [&](Index* sides) {
        const IndexSpan ef = topo.GetEdgeFaces(e);
        sides[0] = childSource(number.FacePoint(ef[0]));
        sides[1] = childSource(number.FacePoint(ef[1]));
      });
  }

  for (Index v = 0; v < numVertices; ++v)
  {
    Index* src = table.GetMutableSources(number.VertexPoint(v));
    double* wts = table.GetMutableWeights(number.VertexPoint(v));
    const IndexSpan edges = topo.GetVertexEdges(v);
    const IndexSpan faces = topo.GetVertexFaces(v);
    WritePrimalVertexRow(topo, plans[v], v, 1 + 2 * faces.size(), src, wts, [&](Index* src, double* wts) {
      src[0] = v;
      const double n = faces.size();
      const double ringWeight = 1.0 / (n * n);
      wts[0] = (n - 2.0) / n;
      for (Index i = 0; i < edges.size(); ++i)
      {
        src[1 + i] = topo.GetOtherEndpoint(edges[i], v);
        wts[1 + i] = ringWeight;
      }
      for (Index i = 0; i < faces.size(); ++i)
      {
        src[1 + edges.size() + i] = childSource(number.FacePoint(faces[i]));
        wts[1 + edges.size() + i] = ringWeight;
      }
    });
  }
  table.EndBlock(numFaces + numEdges + numVertices);
  return table;
}
}
