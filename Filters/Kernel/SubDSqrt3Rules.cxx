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
bool IsBoundaryEdge(const MeshTopology& topo, Index e)
{
  return topo.GetEdgeFaces(e).size() == 1;
}

bool Flippable(const MeshTopology& topo, Index e)
{
  return topo.GetEdgeFaces(e).size() == 2 && !topo.GetEdgeTag(e).NonManifold;
}

// The other end of v's second boundary edge, or v itself when v does not have exactly two.
Index BoundaryNeighbour(const MeshTopology& topo, Index v, Index other)
{
  Index found = v, count = 0;
  for (Index e : topo.GetVertexEdges(v))
  {
    if (IsBoundaryEdge(topo, e))
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
}

LevelRefinement RefineSqrt3(const Level& parent, ChildTopology depth)
{
  const MeshTopology& topo = parent.Topology;
  const Index numFaces = topo.GetNumFaces();
  const Index numVertices = topo.GetNumVertices();
  const bool evenStep = (parent.Depth % 2) == 1; // the step making level Depth + 1

  // In even steps the triangle of a boundary edge is trisected instead of getting a centroid.
  std::vector<Index> trisectedEdge(static_cast<size_t>(numFaces), InvalidIndex);
  if (evenStep)
  {
    for (Index e = 0; e < topo.GetNumEdges(); ++e)
    {
      if (IsBoundaryEdge(topo, e))
      {
        const Index f = topo.GetEdgeFaces(e)[0];
        if (trisectedEdge[f] == InvalidIndex)
        {
          trisectedEdge[f] = e; // a triangle with two boundary edges trisects only one
        }
      }
    }
  }
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
    if (trisectedEdge[f] != InvalidIndex)
    {
      firstEdgePoint[trisectedEdge[f]] = numChildPoints;
      numChildPoints += 2;
    }
  }

  LevelRefinement result;
  StencilTable& table = result.Stencils;
  table = StencilTable(numVertices);
  table.ReserveRows(numChildPoints);
  // Vertex rules: interior manifold vertices relax; boundary vertices move in even steps.
  auto relaxes = [&](Index v) {
    const VertexTag tag = topo.GetVertexTag(v);
    const Index faces = topo.GetVertexFaces(v).size();
    return !tag.Boundary && !tag.NonManifold && faces > 0 && faces == topo.GetVertexEdges(v).size();
  };
  auto boundaryMoves = [&](Index v) {
    return evenStep && topo.GetVertexTag(v).Boundary && !topo.GetVertexTag(v).NonManifold &&
      BoundaryNeighbour(topo, v, InvalidIndex) != v;
  };
  for (Index f = 0; f < numFaces; ++f)
  {
    if (centroidPoint[f] != InvalidIndex)
    {
      table.SetRowSize(centroidPoint[f], 3);
    }
  }
  for (Index v = 0; v < numVertices; ++v)
  {
    table.SetRowSize(firstVertexPoint + v,
      relaxes(v) ? 1 + topo.GetVertexEdges(v).size() : (boundaryMoves(v) ? 3 : 1));
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
    if (relaxes(v))
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
    else if (boundaryMoves(v))
    {
      const Index p = BoundaryNeighbour(topo, v, InvalidIndex);
      const Index q = BoundaryNeighbour(topo, v, p);
      setRow(row, { { p, 4.0 / 27.0 }, { v, 19.0 / 27.0 }, { q, 4.0 / 27.0 } });
    }
    else
    {
      setRow(row, { { v, 1.0 } });
    }
  }
  // Trisection points of boundary edge (a, b), oriented as its triangle runs it.
  auto orientedEnds = [&](Index e, Index f, Index& a, Index& b) {
    const Index* ev = topo.GetEdgeVertices(e);
    const Index corner = topo.FindCorner(ev[0], f);
    const bool forward = topo.GetFaceVertices(f)[(corner + 1) % 3] == ev[1];
    a = forward ? ev[0] : ev[1];
    b = forward ? ev[1] : ev[0];
  };
  for (Index f = 0; f < numFaces; ++f)
  {
    const Index e = trisectedEdge[f];
    if (e == InvalidIndex)
    {
      continue;
    }
    Index a, b;
    orientedEnds(e, f, a, b);
    const Index p = BoundaryNeighbour(topo, a, b), q = BoundaryNeighbour(topo, b, a);
    setRow(firstEdgePoint[e], { { p, 1.0 / 27.0 }, { a, 16.0 / 27.0 }, { b, 10.0 / 27.0 } });
    setRow(firstEdgePoint[e] + 1, { { a, 10.0 / 27.0 }, { b, 16.0 / 27.0 }, { q, 1.0 / 27.0 } });
  }
  table.EndBlock(numChildPoints);

  // Topology.
  Level& child = result.Child;
  std::vector<Index> offsets{ 0 }, vertices;
  auto addTriangle = [&](Index x, Index y, Index z, Index originFace, std::uint8_t hole) {
    vertices.insert(vertices.end(), { x, y, z });
    offsets.push_back(static_cast<Index>(vertices.size()));
    child.FaceOrigin.push_back(parent.FaceOrigin[originFace]);
    child.FaceIsHole.push_back(hole);
  };
  auto vertexPoint = [firstVertexPoint](Index v) { return firstVertexPoint + v; };
  // The point an old edge e of face f is flipped to: the centroid, or in a trisected
  // triangle (a, b, m) the trisection point next to the end of the trisected edge that e
  // shares (x1 next to a, x2 next to b).
  auto apex = [&](Index f, Index e) {
    if (centroidPoint[f] != InvalidIndex)
    {
      return centroidPoint[f];
    }
    Index a, b;
    orientedEnds(trisectedEdge[f], f, a, b);
    const Index* ev = topo.GetEdgeVertices(e);
    const bool touchesA = ev[0] == a || ev[1] == a;
    return firstEdgePoint[trisectedEdge[f]] + (touchesA ? 0 : 1);
  };
  for (Index e = 0; e < topo.GetNumEdges(); ++e)
  {
    const IndexSpan ef = topo.GetEdgeFaces(e);
    if (Flippable(topo, e))
    {
      Index f1 = ef[0], f2 = ef[1], a, b;
      orientedEnds(e, f1, a, b);
      const std::uint8_t hole = parent.FaceIsHole[f1] && parent.FaceIsHole[f2];
      addTriangle(vertexPoint(a), apex(f2, e), apex(f1, e), f1, hole);
      addTriangle(vertexPoint(b), apex(f1, e), apex(f2, e), f2, hole);
      continue;
    }
    // Not flipped (boundary, non-manifold): each face keeps its part next to e, unless e is
    // the trisected edge itself (handled below).
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
  // Trisected boundary triangles (a, b, m): the middle triangle (x1, x2, m); the triangles
  // (a, x1, m) and (x2, b, m) were made above, through the flips of (m, a) and (b, m).
  for (Index f = 0; f < numFaces; ++f)
  {
    const Index e = trisectedEdge[f];
    if (e == InvalidIndex)
    {
      continue;
    }
    const Index m = topo.GetTriangleOppositeVertex(f, e);
    addTriangle(firstEdgePoint[e], firstEdgePoint[e] + 1, vertexPoint(m), f, parent.FaceIsHole[f]);
  }
  SetChildTopology(parent, child, numChildPoints, std::move(offsets), std::move(vertices), depth);
  return result;
}
}
