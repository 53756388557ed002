#include "SubDSqrt3Rules.h"

#include <algorithm>
#include <cmath>

namespace subd
{
double Sqrt3Alpha(Index n)
{
  const double pi = 3.14159265358979323846;
  return (4.0 - 2.0 * std::cos(2.0 * pi / n)) / 9.0;
}

bool IsSqrt3CurveEdge(const Level& level, Index e)
{
  const MeshTopology& topo = level.Topology;
  const Index faces = topo.GetEdgeFaces(e).size();
  return faces == 1 || (faces == 2 && !topo.GetEdgeTag(e).NonManifold && IsSharp(level.EdgeSharpness[e]));
}

Index Sqrt3CurveNeighbour(const Level& level, Index v, Index other)
{
  const MeshTopology& topo = level.Topology;
  Index found = v, count = 0;
  for (Index e : topo.GetVertexEdges(v))
  {
    if (IsSqrt3CurveEdge(level, e))
    {
      ++count;
      const Index w = topo.GetOtherEndpoint(e, v);
      if (w != other)
      {
        found = w;
      }
    }
  }
  return count == 2 ? found : v;
}

namespace
{
// In even steps, the edge each triangle trisects (or InvalidIndex): every curve edge whose
// triangles trisect nothing else yet, in edge order.
std::vector<Index> ChooseTrisectedEdges(const Level& level, bool evenStep)
{
  const MeshTopology& topo = level.Topology;
  std::vector<Index> trisected(static_cast<size_t>(topo.GetNumFaces()), InvalidIndex);
  if (!evenStep)
  {
    return trisected;
  }
  for (Index e = 0; e < topo.GetNumEdges(); ++e)
  {
    if (!IsSqrt3CurveEdge(level, e))
    {
      continue;
    }
    const IndexSpan ef = topo.GetEdgeFaces(e);
    bool free = true;
    for (Index f : ef)
    {
      free = free && trisected[f] == InvalidIndex;
    }
    if (free)
    {
      for (Index f : ef)
      {
        trisected[f] = e;
      }
    }
  }
  return trisected;
}

}

Sqrt3VertexRule ClassifySqrt3Vertex(const Level& level, Index v, bool evenStep)
{
  const MeshTopology& topo = level.Topology;
  const VertexTag tag = topo.GetVertexTag(v);
  const Index faces = topo.GetVertexFaces(v).size();
  if (tag.NonManifold || faces == 0 || IsSharp(level.VertexSharpness[v]))
  {
    return Sqrt3VertexRule::Fixed;
  }
  Index curves = 0;
  for (Index e : topo.GetVertexEdges(v))
  {
    curves += IsSqrt3CurveEdge(level, e);
  }
  if (!tag.Boundary && curves < 2 && faces == topo.GetVertexEdges(v).size())
  {
    return Sqrt3VertexRule::Relax;
  }
  return evenStep && curves == 2 ? Sqrt3VertexRule::Curve : Sqrt3VertexRule::Fixed;
}

namespace
{
// Sets the sharpness of the child pieces of each sharp edge (the unflipped edge, or the
// three pieces of a trisected one) and of each vertex, one unit down.
void InheritSqrt3Sharpness(const Level& parent, const std::vector<Index>& firstEdgePoint,
  Index firstVertexPoint, Level& child)
{
  const MeshTopology& topo = parent.Topology;
  const MeshTopology& childTopo = child.Topology;
  auto setSharpness = [&](Index a, Index b, float sharpness) {
    const Index edge = childTopo.FindEdge(a, b);
    if (edge != InvalidIndex)
    {
      child.EdgeSharpness[edge] = sharpness;
    }
  };
  for (Index e = 0; e < topo.GetNumEdges(); ++e)
  {
    if (!IsSharp(parent.EdgeSharpness[e]))
    {
      continue;
    }
    const float sharpness = DecaySharpness(parent.EdgeSharpness[e]);
    const Index a = firstVertexPoint + topo.GetEdgeVertices(e)[0];
    const Index b = firstVertexPoint + topo.GetEdgeVertices(e)[1];
    const Index x = firstEdgePoint[e];
    if (x == InvalidIndex)
    {
      setSharpness(a, b, sharpness);
      continue;
    }
    setSharpness(a, x, sharpness);
    setSharpness(x, x + 1, sharpness);
    setSharpness(x + 1, b, sharpness);
  }
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    child.VertexSharpness[firstVertexPoint + v] = DecaySharpness(parent.VertexSharpness[v]);
  }
}
}

LevelRefinement RefineSqrt3(const Level& parent, ChildTopology depth, const ParallelFor& parallelFor)
{
  const MeshTopology& topo = parent.Topology;
  const Index numFaces = topo.GetNumFaces();
  const Index numVertices = topo.GetNumVertices();
  const bool evenStep = (parent.Depth % 2) == 1; // the step making level Depth + 1
  const std::vector<Index> trisectedEdge = ChooseTrisectedEdges(parent, evenStep);

  // Child point numbering.
  std::vector<Index> centroidPoint(static_cast<size_t>(numFaces), InvalidIndex);
  Index numChildPoints = 0;
  for (Index f = 0; f < numFaces; ++f)
  {
    if (trisectedEdge[f] == InvalidIndex)
    {
      centroidPoint[f] = numChildPoints++;
    }
  }
  const Index firstVertexPoint = numChildPoints;
  numChildPoints += numVertices;
  std::vector<Index> firstEdgePoint(static_cast<size_t>(topo.GetNumEdges()), InvalidIndex);
  for (Index f = 0; f < numFaces; ++f)
  {
    const Index e = trisectedEdge[f];
    if (e != InvalidIndex && firstEdgePoint[e] == InvalidIndex)
    {
      firstEdgePoint[e] = numChildPoints;
      numChildPoints += 2;
    }
  }
  // The trisection point of edge e next to its end v.
  auto trisectionPoint = [&](Index e, Index v) {
    return firstEdgePoint[e] + (topo.GetEdgeVertices(e)[0] == v ? 0 : 1);
  };

  LevelRefinement result;
  StencilTable& table = result.Stencils;
  table = StencilTable(numVertices);
  table.ReserveRows(numChildPoints);
  std::vector<Sqrt3VertexRule> rules(static_cast<size_t>(numVertices));
  for (Index v = 0; v < numVertices; ++v)
  {
    rules[v] = ClassifySqrt3Vertex(parent, v, evenStep);
  }
  for (Index f = 0; f < numFaces; ++f)
  {
    if (centroidPoint[f] != InvalidIndex)
    {
      table.SetRowSize(centroidPoint[f], 3);
    }
  }
  for (Index v = 0; v < numVertices; ++v)
  {
    const Index size = rules[v] == Sqrt3VertexRule::Relax ? 1 + topo.GetVertexEdges(v).size()
                                                           : (rules[v] == Sqrt3VertexRule::Curve ? 3 : 1);
    table.SetRowSize(firstVertexPoint + v, size);
  }
  for (Index e = 0; e < topo.GetNumEdges(); ++e)
  {
    if (firstEdgePoint[e] != InvalidIndex)
    {
      table.SetRowSize(firstEdgePoint[e], 3);
      table.SetRowSize(firstEdgePoint[e] + 1, 3);
    }
  }
  table.FinalizeSizes();
  auto setRow = [&](Index row, std::initializer_list<std::pair<Index, double>> entries) {
    Index* src = table.GetMutableSources(row);
    double* wts = table.GetMutableWeights(row);
    for (const auto& entry : entries)
    {
      *src++ = entry.first;
      *wts++ = entry.second;
    }
  };
  for (Index f = 0; f < numFaces; ++f)
  {
    if (centroidPoint[f] != InvalidIndex)
    {
      const IndexSpan fv = topo.GetFaceVertices(f);
      setRow(centroidPoint[f], { { fv[0], 1.0 / 3.0 }, { fv[1], 1.0 / 3.0 }, { fv[2], 1.0 / 3.0 } });
    }
  }
  for (Index v = 0; v < numVertices; ++v)
  {
    const Index row = firstVertexPoint + v;
    if (rules[v] == Sqrt3VertexRule::Relax)
    {
      const IndexSpan edges = topo.GetVertexEdges(v);
      const Index n = edges.size();
      const double alpha = Sqrt3Alpha(n);
      Index* src = table.GetMutableSources(row);
      double* wts = table.GetMutableWeights(row);
      src[0] = v;
      wts[0] = 1.0 - alpha;
      for (Index i = 0; i < n; ++i)
      {
        src[1 + i] = topo.GetOtherEndpoint(edges[i], v);
        wts[1 + i] = alpha / n;
      }
    }
    else if (rules[v] == Sqrt3VertexRule::Curve)
    {
      const Index p = Sqrt3CurveNeighbour(parent, v, InvalidIndex);
      const Index q = Sqrt3CurveNeighbour(parent, v, p);
      setRow(row, { { p, 4.0 / 27.0 }, { v, 19.0 / 27.0 }, { q, 4.0 / 27.0 } });
    }
    else
    {
      setRow(row, { { v, 1.0 } });
    }
  }
  for (Index e = 0; e < topo.GetNumEdges(); ++e)
  {
    if (firstEdgePoint[e] == InvalidIndex)
    {
      continue;
    }
    const Index a = topo.GetEdgeVertices(e)[0], b = topo.GetEdgeVertices(e)[1];
    const Index p = Sqrt3CurveNeighbour(parent, a, b), q = Sqrt3CurveNeighbour(parent, b, a);
    setRow(firstEdgePoint[e], { { p, 1.0 / 27.0 }, { a, 16.0 / 27.0 }, { b, 10.0 / 27.0 } });
    setRow(firstEdgePoint[e] + 1, { { a, 10.0 / 27.0 }, { b, 16.0 / 27.0 }, { q, 1.0 / 27.0 } });
  }
  table.EndBlock(numChildPoints);

  // Topology.
  Level& child = result.Child;
  IndexArray offsets{ 0 }, vertices;
  auto addTriangle = [&](Index x, Index y, Index z, Index originFace, std::uint8_t hole) {
    vertices.insert(vertices.end(), { x, y, z });
    offsets.push_back(static_cast<Index>(vertices.size()));
    child.FaceOrigin.push_back(parent.FaceOrigin[originFace]);
    child.FaceIsHole.push_back(hole);
  };
  auto vertexPoint = [firstVertexPoint](Index v) { return firstVertexPoint + v; };
  // Edge e's ends (a, b) in the order face f runs them.
  auto orientedEnds = [&](Index e, Index f, Index& a, Index& b) {
    const Index* ev = topo.GetEdgeVertices(e);
    const IndexSpan fv = topo.GetFaceVertices(f); // a triangle: its corners, not v's faces
    const Index corner = fv[0] == ev[0] ? 0 : (fv[1] == ev[0] ? 1 : 2);
    const bool forward = fv[(corner + 1) % 3] == ev[1];
    a = forward ? ev[0] : ev[1];
    b = forward ? ev[1] : ev[0];
  };
  // The point an old edge e of face f is flipped to: the centroid, or in a triangle that
  // trisects another edge the trisection point next to the end the two edges share.
  auto apex = [&](Index f, Index e) {
    if (centroidPoint[f] != InvalidIndex)
    {
      return centroidPoint[f];
    }
    const Index t = trisectedEdge[f];
    const Index* ev = topo.GetEdgeVertices(e);
    const Index* tv = topo.GetEdgeVertices(t);
    const Index shared = (ev[0] == tv[0] || ev[0] == tv[1]) ? ev[0] : ev[1];
    return trisectionPoint(t, shared);
  };
  for (Index e = 0; e < topo.GetNumEdges(); ++e)
  {
    const IndexSpan ef = topo.GetEdgeFaces(e);
    if (!ActsAsBoundary(parent, e))
    {
      Index f1 = ef[0], f2 = ef[1], a, b;
      orientedEnds(e, f1, a, b);
      const std::uint8_t hole = parent.FaceIsHole[f1] && parent.FaceIsHole[f2];
      addTriangle(vertexPoint(a), apex(f2, e), apex(f1, e), f1, hole);
      addTriangle(vertexPoint(b), apex(f1, e), apex(f2, e), f2, hole);
      continue;
    }
    // Not flipped (boundary, crease, non-manifold): each face keeps its part next to e,
    // unless e is the edge the face trisects (handled below).
    for (Index f : ef)
    {
      if (e == trisectedEdge[f])
      {
        continue;
      }
      Index a, b;
      orientedEnds(e, f, a, b);
      addTriangle(vertexPoint(a), vertexPoint(b), apex(f, e), f, parent.FaceIsHole[f]);
    }
  }
  // Triangles (a, b, m) trisecting (a, b): the middle triangle (x_a, x_b, m); the triangles
  // (a, x_a, m) and (x_b, b, m) were made above, through the flips of (m, a) and (b, m).
  for (Index f = 0; f < numFaces; ++f)
  {
    const Index e = trisectedEdge[f];
    if (e == InvalidIndex)
    {
      continue;
    }
    Index a, b;
    orientedEnds(e, f, a, b);
    const Index m = topo.GetTriangleOppositeVertex(f, e);
    addTriangle(trisectionPoint(e, a), trisectionPoint(e, b), vertexPoint(m), f, parent.FaceIsHole[f]);
  }
  SetChildTopology(parent, child, numChildPoints, std::move(offsets), std::move(vertices), depth, parallelFor);
  if (depth == ChildTopology::Full)
  {
    InheritSqrt3Sharpness(parent, firstEdgePoint, firstVertexPoint, child);
  }
  return result;
}

Index Sqrt3FirstVertexPoint(const Level& parent)
{
  const std::vector<Index> trisected = ChooseTrisectedEdges(parent, (parent.Depth % 2) == 1);
  return static_cast<Index>(std::count(trisected.begin(), trisected.end(), InvalidIndex));
}
}
