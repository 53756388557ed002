#include "SubDSqrt3Rules.h"

#include <cmath>

namespace subd
{
double Sqrt3Alpha(Index n)
{
  const double pi = 3.14159265358979323846;
  return (4.0 - 2.0 * std::cos(2.0 * pi / n)) / 9.0;
}

namespace
{
// A vertex moves when it has a closed manifold fan (interior); others stay.
bool Relaxes(const MeshTopology& topo, Index v)
{
  const VertexTag tag = topo.GetVertexTag(v);
  const Index faces = topo.GetVertexFaces(v).size();
  return !tag.Boundary && !tag.NonManifold && faces > 0 && faces == topo.GetVertexEdges(v).size();
}

bool Flips(const MeshTopology& topo, Index e)
{
  return topo.GetEdgeFaces(e).size() == 2 && !topo.GetEdgeTag(e).NonManifold;
}
}

StencilTable BuildSqrt3Stencils(const Level& parent)
{
  const MeshTopology& topo = parent.Topology;
  const Index numFaces = topo.GetNumFaces();
  const Index numVertices = topo.GetNumVertices();
  StencilTable table(numVertices);
  table.ReserveRows(numFaces + numVertices);
  for (Index f = 0; f < numFaces; ++f)
  {
    table.SetRowSize(f, 3);
  }
  for (Index v = 0; v < numVertices; ++v)
  {
    table.SetRowSize(numFaces + v, Relaxes(topo, v) ? 1 + topo.GetVertexEdges(v).size() : 1);
  }
  table.FinalizeSizes();
  for (Index f = 0; f < numFaces; ++f)
  {
    const IndexSpan fv = topo.GetFaceVertices(f);
    for (Index k = 0; k < 3; ++k)
    {
      table.GetMutableSources(f)[k] = fv[k];
      table.GetMutableWeights(f)[k] = 1.0 / 3.0;
    }
  }
  for (Index v = 0; v < numVertices; ++v)
  {
    Index* src = table.GetMutableSources(numFaces + v);
    double* wts = table.GetMutableWeights(numFaces + v);
    src[0] = v;
    wts[0] = 1.0;
    if (Relaxes(topo, v))
    {
      const IndexSpan edges = topo.GetVertexEdges(v);
      const Index n = edges.size();
      const double alpha = Sqrt3Alpha(n);
      wts[0] = 1.0 - alpha;
      for (Index i = 0; i < n; ++i)
      {
        src[1 + i] = topo.GetOtherEndpoint(edges[i], v);
        wts[1 + i] = alpha / n;
      }
    }
  }
  table.EndBlock(numFaces + numVertices);
  return table;
}

Level SplitSqrt3(const Level& parent, ChildTopology depth)
{
  const MeshTopology& topo = parent.Topology;
  const Index numFaces = topo.GetNumFaces();
  auto vertexPoint = [numFaces](Index v) { return numFaces + v; };
  Level child;
  std::vector<Index> offsets{ 0 }, vertices;
  auto addTriangle = [&](Index a, Index b, Index c, Index originFace, std::uint8_t hole) {
    vertices.insert(vertices.end(), { a, b, c });
    offsets.push_back(static_cast<Index>(vertices.size()));
    child.FaceOrigin.push_back(parent.FaceOrigin[originFace]);
    child.FaceIsHole.push_back(hole);
  };
  for (Index e = 0; e < topo.GetNumEdges(); ++e)
  {
    const IndexSpan ef = topo.GetEdgeFaces(e);
    const Index* ev = topo.GetEdgeVertices(e);
    // Orient the edge as its first face runs it.
    auto runsForward = [&](Index f) {
      const Index corner = topo.FindCorner(ev[0], f);
      return topo.GetFaceVertices(f)[(corner + 1) % 3] == ev[1];
    };
    if (Flips(topo, e))
    {
      Index f1 = ef[0], f2 = ef[1];
      if (!runsForward(f1))
      {
        std::swap(f1, f2);
      }
      const Index a = vertexPoint(ev[0]), b = vertexPoint(ev[1]);
      const std::uint8_t hole = parent.FaceIsHole[f1] && parent.FaceIsHole[f2];
      addTriangle(a, f2, f1, f1, hole);
      addTriangle(b, f1, f2, f2, hole);
      continue;
    }
    for (Index f : ef)
    {
      const bool forward = runsForward(f);
      const Index a = vertexPoint(forward ? ev[0] : ev[1]), b = vertexPoint(forward ? ev[1] : ev[0]);
      addTriangle(a, b, f, f, parent.FaceIsHole[f]);
    }
  }
  const Index numChildPoints = numFaces + topo.GetNumVertices();
  SetChildTopology(child, numChildPoints, std::move(offsets), std::move(vertices), depth);
  return child;
}
}
