#include "SubDLimitRules.h"

#include "SubDLoopRules.h"

namespace subd
{
namespace
{
// Row sizes and the crease and corner rows, shared by both schemes; `smoothSize(v)` gives
// the size of a smooth row, written afterwards by `writeSmooth(v, src, wts)`.
template <typename SmoothSize, typename WriteSmooth>
StencilTable BuildLimitRows(const Level& level, SmoothSize&& smoothSize, WriteSmooth&& writeSmooth)
{
  const MeshTopology& topo = level.Topology;
  const Index numVertices = topo.GetNumVertices();
  const std::vector<VertexRulePlan> plans = PlanVertexRules(level);
  auto isSmooth = [](VertexRule rule) { return rule == VertexRule::Smooth || rule == VertexRule::Dart; };
  StencilTable table(numVertices);
  table.ReserveRows(numVertices);
  for (Index v = 0; v < numVertices; ++v)
  {
    const VertexRule rule = plans[v].Rule;
    table.SetRowSize(v, isSmooth(rule) ? smoothSize(v) : (rule == VertexRule::Crease ? 3 : 1));
  }
  table.FinalizeSizes();
  for (Index v = 0; v < numVertices; ++v)
  {
    Index* src = table.GetMutableSources(v);
    double* wts = table.GetMutableWeights(v);
    const VertexRulePlan& plan = plans[v];
    src[0] = v;
    if (isSmooth(plan.Rule))
    {
      writeSmooth(v, src, wts);
    }
    else if (plan.Rule == VertexRule::Crease)
    {
      const IndexSpan edges = topo.GetVertexEdges(v);
      src[1] = topo.GetOtherEndpoint(edges[plan.CreaseEdges[0]], v);
      src[2] = topo.GetOtherEndpoint(edges[plan.CreaseEdges[1]], v);
      wts[0] = 4.0 / 6.0;
      wts[1] = wts[2] = 1.0 / 6.0;
    }
    else
    {
      wts[0] = 1.0;
    }
  }
  table.EndBlock(numVertices);
  return table;
}
}

bool BuildCatmullClarkLimitStencils(const Level& level, StencilTable& stencils, std::string& error)
{
  const MeshTopology& topo = level.Topology;
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    for (Index f : topo.GetVertexFaces(v))
    {
      if (topo.GetFaceSize(f) != 4)
      {
        error = "vertex " + std::to_string(v) + " has a face with " + std::to_string(topo.GetFaceSize(f)) +
          " sides; Catmull-Clark limit masks need quads (refine one level first)";
        return false;
      }
    }
  }
  // v, then per face its edge neighbour (leaving v) and its diagonal vertex.
  // Two faces: the corner mask (see the header).
  auto smoothSize = [&topo](Index v) {
    const Index n = topo.GetVertexFaces(v).size();
    return n == 2 ? 1 : 1 + 2 * n;
  };
  auto writeSmooth = [&topo](Index v, Index* src, double* wts) {
    const IndexSpan faces = topo.GetVertexFaces(v);
    const IndexSpan corners = topo.GetVertexFaceCorners(v);
    if (faces.size() == 2)
    {
      wts[0] = 1.0;
      return;
    }
    const double n = static_cast<double>(faces.size());
    const double scale = 1.0 / (n * (n + 5.0));
    wts[0] = n / (n + 5.0);
    for (Index i = 0; i < faces.size(); ++i)
    {
      const IndexSpan fv = topo.GetFaceVertices(faces[i]);
      src[1 + 2 * i] = fv[(corners[i] + 1) % 4];
      wts[1 + 2 * i] = 4.0 * scale;
      src[2 + 2 * i] = fv[(corners[i] + 2) % 4];
      wts[2 + 2 * i] = scale;
    }
  };
  stencils = BuildLimitRows(level, smoothSize, writeSmooth);
  return true;
}

StencilTable BuildLoopLimitStencils(const Level& level)
{
  const MeshTopology& topo = level.Topology;
  auto smoothSize = [&topo](Index v) { return 1 + topo.GetVertexEdges(v).size(); };
  auto writeSmooth = [&topo](Index v, Index* src, double* wts) {
    const IndexSpan edges = topo.GetVertexEdges(v);
    const Index n = edges.size();
    const double chi = 1.0 / (3.0 / (8.0 * LoopBeta(n)) + n);
    wts[0] = 1.0 - n * chi;
    for (Index i = 0; i < n; ++i)
    {
      src[1 + i] = topo.GetOtherEndpoint(edges[i], v);
      wts[1 + i] = chi;
    }
  };
  return BuildLimitRows(level, smoothSize, writeSmooth);
}

StencilTable BuildInterpolatingLimitStencils(const Level& level)
{
  const Index n = level.Topology.GetNumVertices();
  StencilTable table(n);
  table.ReserveRows(n);
  for (Index v = 0; v < n; ++v)
  {
    table.SetRowSize(v, 1);
  }
  table.FinalizeSizes();
  for (Index v = 0; v < n; ++v)
  {
    table.GetMutableSources(v)[0] = v;
    table.GetMutableWeights(v)[0] = 1.0;
  }
  table.EndBlock(n);
  return table;
}
}
