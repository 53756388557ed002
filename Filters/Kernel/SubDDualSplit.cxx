#include "SubDDualSplit.h"

#include <algorithm>
#include <numeric>

namespace subd
{
namespace
{
// The two edges of face f at its corner j: leaving and entering the corner's vertex.
std::pair<Index, Index> CornerEdges(const MeshTopology& topo, Index f, Index j)
{
  const IndexSpan fe = topo.GetFaceEdges(f);
  const Index n = fe.size();
  return { fe[j], fe[(j + n - 1) % n] };
}

Index Find(std::vector<Index>& parent, Index x)
{
  while (parent[x] != x)
  {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

void Unite(std::vector<Index>& parent, Index a, Index b)
{
  a = Find(parent, a);
  b = Find(parent, b);
  if (a != b)
  {
    parent[std::max(a, b)] = std::min(a, b); // the first corner represents the point
  }
}
}

bool IsDualCornerVertex(const Level& level, Index v)
{
  const MeshTopology& topo = level.Topology;
  const IndexSpan faces = topo.GetVertexFaces(v);
  if (faces.size() == 1 || IsSharp(level.VertexSharpness[v]))
  {
    return true;
  }
  Index creases = 0;
  for (Index e : topo.GetVertexEdges(v))
  {
    creases += ActsAsBoundary(level, e);
  }
  if (creases == 0 || creases > 2)
  {
    return creases > 2;
  }
  for (Index f : faces)
  {
    const auto edges = CornerEdges(topo, f, topo.FindCorner(v, f));
    if (ActsAsBoundary(level, edges.first) && ActsAsBoundary(level, edges.second))
    {
      return true;
    }
  }
  return false;
}

DualPoints NumberDualPoints(const Level& level)
{
  const MeshTopology& topo = level.Topology;
  const Index numCorners = topo.GetNumFaceCorners();
  std::vector<Index> parent(static_cast<size_t>(numCorners));
  std::iota(parent.begin(), parent.end(), 0);
  auto corner = [&topo](Index f, Index v) { return topo.GetFaceOffset(f) + topo.FindCorner(v, f); };
  // Across each sharp interior edge, the two faces' corners at each end are one point.
  for (Index e = 0; e < topo.GetNumEdges(); ++e)
  {
    const IndexSpan ef = topo.GetEdgeFaces(e);
    if (ef.size() != 2 || topo.GetEdgeTag(e).NonManifold || !IsSharp(level.EdgeSharpness[e]))
    {
      continue;
    }
    for (int k = 0; k < 2; ++k)
    {
      const Index v = topo.GetEdgeVertices(e)[k];
      Unite(parent, corner(ef[0], v), corner(ef[1], v));
    }
  }
  // At a corner vertex every corner next to a crease edge is the vertex itself.
  DualPoints points;
  points.IsCornerVertex.resize(static_cast<size_t>(topo.GetNumVertices()));
  points.PinsEveryCorner.resize(static_cast<size_t>(topo.GetNumVertices()));
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    points.IsCornerVertex[v] = IsDualCornerVertex(level, v);
    if (!points.IsCornerVertex[v])
    {
      continue;
    }
    Index creases = 0;
    for (Index e : topo.GetVertexEdges(v))
    {
      creases += ActsAsBoundary(level, e);
    }
    points.PinsEveryCorner[v] = creases < 2;
    Index first = InvalidIndex;
    for (Index f : topo.GetVertexFaces(v))
    {
      const Index j = topo.FindCorner(v, f);
      const auto edges = CornerEdges(topo, f, j);
      if (points.PinsEveryCorner[v] || ActsAsBoundary(level, edges.first) || ActsAsBoundary(level, edges.second))
      {
        const Index c = topo.GetFaceOffset(f) + j;
        first = first == InvalidIndex ? c : first;
        Unite(parent, first, c);
      }
    }
  }
  points.PointOfCorner.resize(static_cast<size_t>(numCorners));
  for (Index c = 0; c < numCorners; ++c)
  {
    const Index root = Find(parent, c);
    if (root == c)
    {
      points.PointOfCorner[c] = static_cast<Index>(points.CornerOfPoint.size());
      points.CornerOfPoint.push_back(c);
    }
    else
    {
      points.PointOfCorner[c] = points.PointOfCorner[root]; // root < c: numbered already
    }
  }
  return points;
}

Level SplitDual(const Level& parent, const DualPoints& points, ChildTopology depth, const ParallelFor& parallelFor)
{
  const MeshTopology& topo = parent.Topology;
  const Index numFaces = topo.GetNumFaces();
  // The child point of corner `corner` of face f.
  auto cornerPoint = [&](Index f, Index corner) { return points.PointOfCorner[topo.GetFaceOffset(f) + corner]; };

  Level child;
  IndexArray offsets{ 0 }, vertices;
  std::vector<Index> origins, holes;
  // Adds the face of the points from `first` on, without repeats of welded points; a face
  // left with fewer than three points is dropped.
  auto addFace = [&](size_t first, Index origin, std::uint8_t hole) {
    auto end = std::unique(vertices.begin() + static_cast<std::ptrdiff_t>(first), vertices.end());
    if (end - vertices.begin() > static_cast<std::ptrdiff_t>(first) + 1 && *(end - 1) == vertices[first])
    {
      --end;
    }
    vertices.erase(end, vertices.end());
    if (vertices.size() - first < 3)
    {
      vertices.resize(first);
      return;
    }
    offsets.push_back(static_cast<Index>(vertices.size()));
    origins.push_back(origin);
    holes.push_back(hole);
  };
  // F-faces: the corner points of each face.
  vertices.reserve(static_cast<size_t>(topo.GetNumFaceCorners()) * 3);
  for (Index f = 0; f < numFaces; ++f)
  {
    const size_t first = vertices.size();
    for (Index j = 0; j < topo.GetFaceSize(f); ++j)
    {
      vertices.push_back(cornerPoint(f, j));
    }
    addFace(first, parent.FaceOrigin[f], parent.FaceIsHole[f]);
  }
  // E-faces: edge (a, b) runs a->b in face f0 and b->a in f1; the quad runs against f0's
  // side of the edge and then along f1's, so that it is oriented like its neighbours.
  for (Index e = 0; e < topo.GetNumEdges(); ++e)
  {
    if (ActsAsBoundary(parent, e))
    {
      continue;
    }
    const IndexSpan ef = topo.GetEdgeFaces(e);
    const Index* ev = topo.GetEdgeVertices(e);
    Index f0 = ef[0], f1 = ef[1];
    Index a = ev[0], b = ev[1];
    Index ca = topo.FindCorner(a, f0);
    if (topo.GetFaceVertices(f0)[(ca + 1) % topo.GetFaceSize(f0)] != b)
    {
      std::swap(f0, f1); // make f0 the face that runs a->b
      ca = topo.FindCorner(a, f0);
    }
    const size_t first = vertices.size();
    vertices.insert(vertices.end(), { cornerPoint(f0, topo.FindCorner(b, f0)), cornerPoint(f0, ca),
                                      cornerPoint(f1, topo.FindCorner(a, f1)),
                                      cornerPoint(f1, topo.FindCorner(b, f1)) });
    addFace(first, parent.FaceOrigin[f0], parent.FaceIsHole[f0] && parent.FaceIsHole[f1]);
  }
  // V-faces: one per sector (run of faces between sharp edges) of at least three faces.
  std::vector<Index> fan, fanCorners;
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    if (!topo.GetOrderedVertexFaces(v, fan, fanCorners))
    {
      continue;
    }
    const Index m = static_cast<Index>(fan.size());
    const bool closed = !topo.GetVertexTag(v).Boundary;
    // sharpAfter[i]: the edge between fan[i] and the next face is sharp (for the last face
    // of an open fan: the boundary).
    std::vector<std::uint8_t> sharpAfter(static_cast<size_t>(m), 0);
    Index start = 0;
    for (Index i = 0; i < m; ++i)
    {
      const Index next = fan[(i + 1) % m];
      const auto edges = CornerEdges(topo, fan[i], fanCorners[i]);
      for (Index e : { edges.first, edges.second })
      {
        const IndexSpan ef = topo.GetEdgeFaces(e);
        const bool shared = std::find(ef.begin(), ef.end(), next) != ef.end() && next != fan[i];
        if ((shared || (!closed && i == m - 1)) && ActsAsBoundary(parent, e))
        {
          sharpAfter[i] = 1;
        }
      }
      if (sharpAfter[i] && closed && start == 0)
      {
        start = (i + 1) % m; // sectors of a closed fan start after a sharp edge
      }
    }
    if (!closed)
    {
      sharpAfter[m - 1] = 1;
    }
    // Walk the fan from `start`, cutting after each sharp edge.
    std::vector<Index> sector;
    for (Index k = 0; k < m; ++k)
    {
      const Index i = (start + k) % m;
      sector.push_back(i);
      if (sharpAfter[i] || k == m - 1)
      {
        if (sector.size() >= 3)
        {
          const size_t first = vertices.size();
          std::uint8_t allHoles = 1;
          for (Index s : sector)
          {
            vertices.push_back(cornerPoint(fan[s], fanCorners[s]));
            allHoles &= parent.FaceIsHole[fan[s]];
          }
          addFace(first, parent.FaceOrigin[fan[sector[0]]], allHoles);
        }
        sector.clear();
      }
    }
  }

  child.FaceOrigin.assign(origins.begin(), origins.end());
  child.FaceIsHole.assign(holes.begin(), holes.end());
  const Index numPoints = static_cast<Index>(points.CornerOfPoint.size());
  SetChildTopology(parent, child, numPoints, std::move(offsets), std::move(vertices), depth, parallelFor);
  if (depth == ChildTopology::Full)
  {
    // Crease segments: the child edge between the two welded points of a sharp edge, and,
    // at a vertex on a crease, between the points of its two crease edges.
    const MeshTopology& childTopo = child.Topology;
    auto pointAt = [&](Index f, Index v) { return cornerPoint(f, topo.FindCorner(v, f)); };
    for (Index e = 0; e < topo.GetNumEdges(); ++e)
    {
      if (!IsSharp(parent.EdgeSharpness[e]) || topo.GetEdgeFaces(e).empty())
      {
        continue;
      }
      const Index f = topo.GetEdgeFaces(e)[0];
      const Index* ev = topo.GetEdgeVertices(e);
      const Index segment = childTopo.FindEdge(pointAt(f, ev[0]), pointAt(f, ev[1]));
      if (segment != InvalidIndex)
      {
        child.EdgeSharpness[segment] = DecaySharpness(parent.EdgeSharpness[e]);
      }
    }
    for (Index v = 0; v < topo.GetNumVertices(); ++v)
    {
      if (IsSharp(parent.VertexSharpness[v]) && !topo.GetVertexFaces(v).empty())
      {
        child.VertexSharpness[pointAt(topo.GetVertexFaces(v)[0], v)] = DecaySharpness(parent.VertexSharpness[v]);
      }
      if (parent.GetNumSharpEdges(v) != 2 || points.IsCornerVertex[v])
      {
        continue;
      }
      // The points next to the two crease edges, and the smaller of their decayed values.
      Index ends[2] = { InvalidIndex, InvalidIndex };
      float sharpness = SharpnessInfinite;
      int found = 0;
      for (Index e : topo.GetVertexEdges(v))
      {
        if (IsSharp(parent.EdgeSharpness[e]) && found < 2 && !topo.GetEdgeFaces(e).empty())
        {
          ends[found++] = pointAt(topo.GetEdgeFaces(e)[0], v);
          sharpness = std::min(sharpness, DecaySharpness(parent.EdgeSharpness[e]));
        }
      }
      const Index segment = found == 2 ? childTopo.FindEdge(ends[0], ends[1]) : InvalidIndex;
      if (segment != InvalidIndex)
      {
        child.EdgeSharpness[segment] = sharpness;
      }
    }
  }
  return child;
}
}
