#include "SubDDualSplit.h"
#include "SubDFaceBlocks.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>

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

namespace
{
// IsDualCornerVertex with `actsAsBoundary(e)` answering ActsAsBoundary.
template <typename EdgeTest>
bool IsCornerVertexWith(const Level& level, Index v, EdgeTest&& actsAsBoundary)
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
    creases += actsAsBoundary(e);
  }
  if (creases == 0 || creases > 2)
  {
    return creases > 2;
  }
  const IndexSpan corners = topo.GetVertexFaceCorners(v);
  for (Index i = 0; i < faces.size(); ++i)
  {
    const auto edges = CornerEdges(topo, faces[i], corners[i]);
    if (actsAsBoundary(edges.first) && actsAsBoundary(edges.second))
    {
      // A face inside the crease's turn. At an interior manifold vertex both edges have a
      // face across, whose points on them the face's two points are welded to (TurnCorners).
      const VertexTag tag = topo.GetVertexTag(v);
      return tag.Boundary || tag.NonManifold;
    }
  }
  return false;
}

// DualPoints::TurnCorners: the corners, at vertices that are not corner vertices, whose two
// edges both act as boundaries (in order: ascending).
IndexArray FindTurnCorners(const MeshTopology& topo, const DualPoints& points)
{
  const std::vector<std::uint8_t>& acts = points.EdgeActsAsBoundary;
  IndexArray turnCorners;
  for (Index f = 0; f < topo.GetNumFaces(); ++f)
  {
    const IndexSpan fv = topo.GetFaceVertices(f);
    const IndexSpan fe = topo.GetFaceEdges(f);
    const Index n = fv.size();
    for (Index j = 0; j < n; ++j)
    {
      if (!points.IsCornerVertex[fv[j]] && acts[fe[j]] && acts[fe[(j + n - 1) % n]])
      {
        turnCorners.push_back(topo.GetFaceOffset(f) + j);
      }
    }
  }
  return turnCorners;
}

// The union-find slot of the point of face f's corner at v on f's edge e: the corner, or for
// the incoming edge of a turn corner, its second point's slot (after all corners).
Index SlotOnEdge(const MeshTopology& topo, const IndexArray& turnCorners, Index f, Index v, Index e)
{
  const Index j = topo.FindCorner(v, f);
  const Index corner = topo.GetFaceOffset(f) + j;
  if (turnCorners.empty() || topo.GetFaceEdges(f)[j] == e)
  {
    return corner;
  }
  const auto at = std::lower_bound(turnCorners.begin(), turnCorners.end(), corner);
  return at != turnCorners.end() && *at == corner
    ? topo.GetNumFaceCorners() + static_cast<Index>(at - turnCorners.begin())
    : corner;
}

// Unites the slots (corners, then the turn corners' second points) that are one point:
// across each sharp interior edge the two faces' points on it at each end, and at a corner
// vertex every corner next to a crease edge (the vertex itself).
void UniteWeldedSlots(const Level& level, const DualPoints& points, std::vector<Index>& parent)
{
  const MeshTopology& topo = level.Topology;
  const std::vector<std::uint8_t>& acts = points.EdgeActsAsBoundary;
  for (Index e = 0; e < topo.GetNumEdges(); ++e)
  {
    const IndexSpan ef = topo.GetEdgeFaces(e);
    if (ef.size() != 2 || topo.GetEdgeTag(e).NonManifold || !acts[e])
    {
      continue;
    }
    for (int k = 0; k < 2; ++k)
    {
      const Index v = topo.GetEdgeVertices(e)[k];
      Unite(parent, SlotOnEdge(topo, points.TurnCorners, ef[0], v, e),
        SlotOnEdge(topo, points.TurnCorners, ef[1], v, e));
    }
  }
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    if (!points.IsCornerVertex[v])
    {
      continue;
    }
    Index first = InvalidIndex;
    const IndexSpan faces = topo.GetVertexFaces(v);
    const IndexSpan corners = topo.GetVertexFaceCorners(v);
    for (Index i = 0; i < faces.size(); ++i)
    {
      const auto edges = CornerEdges(topo, faces[i], corners[i]);
      if (points.PinsEveryCorner[v] || acts[edges.first] || acts[edges.second])
      {
        const Index c = topo.GetFaceOffset(faces[i]) + corners[i];
        first = first == InvalidIndex ? c : first;
        Unite(parent, first, c);
      }
    }
  }
}

// The welded numbering (creases or corner vertices): union-find over the slots, each point
// represented by its first slot, always a corner (a turn corner's second point is welded to
// the point across its incoming edge, a corner's or another turn corner's first point).
void NumberWeldedPoints(const Level& level, DualPoints& points)
{
  const MeshTopology& topo = level.Topology;
  const Index numCorners = topo.GetNumFaceCorners();
  points.TurnCorners = FindTurnCorners(topo, points);
  const Index numTurns = static_cast<Index>(points.TurnCorners.size());
  std::vector<Index> parent(static_cast<size_t>(numCorners + numTurns));
  std::iota(parent.begin(), parent.end(), 0);
  UniteWeldedSlots(level, points, parent);
  points.PointOfCorner.resize(static_cast<size_t>(numCorners));
  points.CornerOfPoint.clear();
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
  points.PointBeforeTurnCorner.resize(static_cast<size_t>(numTurns));
  for (Index k = 0; k < numTurns; ++k)
  {
    const Index root = Find(parent, numCorners + k);
    if (root >= numCorners)
    {
      throw std::logic_error("NumberDualPoints: a crease turn's point is welded to no corner");
    }
    points.PointBeforeTurnCorner[k] = points.PointOfCorner[root];
  }
  points.NumPoints = static_cast<Index>(points.CornerOfPoint.size());
  points.Unwelded = points.CornerOfPoint.size() == points.PointOfCorner.size() && numTurns == 0;
  if (points.Unwelded)
  {
    IndexArray().swap(points.PointOfCorner);
    IndexArray().swap(points.CornerOfPoint);
  }
}
}

bool IsDualCornerVertex(const Level& level, Index v)
{
  return IsCornerVertexWith(level, v, [&level](Index e) { return ActsAsBoundary(level, e); });
}

Index DualPointOnEdge(const MeshTopology& topo, const DualPoints& points, Index f, Index v, Index e)
{
  const Index j = topo.FindCorner(v, f);
  const Index corner = topo.GetFaceOffset(f) + j;
  return topo.GetFaceEdges(f)[j] == e ? points.PointOf(corner) : points.PointBefore(corner);
}

DualPoints NumberDualPoints(const Level& level, const ParallelFor& parallelFor)
{
  const MeshTopology& topo = level.Topology;
  const Index numCorners = topo.GetNumFaceCorners();
  const Index numEdges = topo.GetNumEdges();
  const Index numVertices = topo.GetNumVertices();
  DualPoints points;
  std::vector<std::uint8_t>& acts = points.EdgeActsAsBoundary;
  acts.resize(static_cast<size_t>(numEdges));
  parallelFor(0, numEdges, [&](Index begin, Index end) {
    for (Index e = begin; e < end; ++e)
    {
      acts[e] = ActsAsBoundary(level, e);
    }
  });
  points.IsCornerVertex.resize(static_cast<size_t>(numVertices));
  points.PinsEveryCorner.resize(static_cast<size_t>(numVertices));
  parallelFor(0, numVertices, [&](Index begin, Index end) {
    for (Index v = begin; v < end; ++v)
    {
      const bool isCorner = IsCornerVertexWith(level, v, [&acts](Index e) { return acts[e] != 0; });
      points.IsCornerVertex[v] = isCorner;
      points.PinsEveryCorner[v] = isCorner && CountVertexEdges(level, v, [&acts](const Level&, Index e) {
        return acts[e] != 0;
      }) < 2;
    }
  });
  // Only a sharp edge between two faces or a corner vertex welds corners.
  bool welds = std::any_of(points.IsCornerVertex.begin(), points.IsCornerVertex.end(), [](std::uint8_t c) { return c != 0; });
  for (Index e = 0; e < numEdges && !welds; ++e)
  {
    welds = acts[e] && topo.GetEdgeFaces(e).size() == 2 && !topo.GetEdgeTag(e).NonManifold;
  }
  if (welds)
  {
    NumberWeldedPoints(level, points);
    return points;
  }
  points.NumPoints = numCorners; // Unwelded
  return points;
}

namespace
{
// Writes the F-, E- and V-faces of the parent's elements numbered in one sequence: faces,
// then edges, then vertices.
class DualFaceWriter
{
public:
  DualFaceWriter(const Level& parent, const DualPoints& points)
    : Parent(parent)
    , Topo(parent.Topology)
    , Points(points)
  {
  }
  Index GetNumElements() const { return this->Topo.GetNumFaces() + this->Topo.GetNumEdges() + this->Topo.GetNumVertices(); }

  void WriteBlock(Index begin, Index end, FaceBlock& out)
  {
    const Index numFaces = this->Topo.GetNumFaces();
    const Index firstVertex = numFaces + this->Topo.GetNumEdges();
    for (Index element = begin; element < end; ++element)
    {
      if (element < numFaces)
      {
        this->WriteFaceFace(element, out);
      }
      else if (element < firstVertex)
      {
        this->WriteEdgeFace(element - numFaces, out);
      }
      else
      {
        this->WriteVertexFaces(element - firstVertex, out);
      }
    }
  }

private:
  Index CornerPoint(Index f, Index corner) const
  {
    return this->Points.PointOf(this->Topo.GetFaceOffset(f) + corner);
  }

  // F-face: the corner points of face f, both points of a turn corner in order (the one on
  // the edge entering the corner first).
  void WriteFaceFace(Index f, FaceBlock& out) const
  {
    const size_t first = out.BeginFace();
    for (Index j = 0; j < this->Topo.GetFaceSize(f); ++j)
    {
      const Index before = this->Points.PointBefore(this->Topo.GetFaceOffset(f) + j);
      if (before != this->CornerPoint(f, j))
      {
        out.Vertices.push_back(before);
      }
      out.Vertices.push_back(this->CornerPoint(f, j));
    }
    out.EndFaceWithoutRepeats(first, this->Parent.FaceOrigin[f], this->Parent.FaceIsHole[f]);
  }

  // E-face: edge (a, b) runs a->b in face f0 and b->a in f1; the quad runs against f0's side
  // of the edge and then along f1's, so that it is oriented like its neighbours.
  void WriteEdgeFace(Index e, FaceBlock& out) const
  {
    if (this->Points.EdgeActsAsBoundary[e])
    {
      return;
    }
    const IndexSpan ef = this->Topo.GetEdgeFaces(e);
    Index f0 = ef[0], f1 = ef[1];
    Index i0 = this->Topo.GetEdgePosition(f0, e), i1 = this->Topo.GetEdgePosition(f1, e);
    if (this->Topo.GetFaceVertices(f0)[i0] != this->Topo.GetEdgeVertices(e)[0])
    {
      std::swap(f0, f1); // make f0 the face that runs a->b
      std::swap(i0, i1);
    }
    // Edge i of a face joins its corners i and i + 1: in f0 those are a and b, in f1 b and a.
    const size_t first = out.BeginFace();
    out.Vertices.insert(out.Vertices.end(),
      { this->CornerPoint(f0, (i0 + 1) % this->Topo.GetFaceSize(f0)), this->CornerPoint(f0, i0),
        this->CornerPoint(f1, (i1 + 1) % this->Topo.GetFaceSize(f1)), this->CornerPoint(f1, i1) });
    // The lower-numbered origin, not f0's: a rule that does not depend on how edges are
    // numbered, so that pieces of a mesh (numbered alike, by global id) agree on it.
    out.EndFaceWithoutRepeats(first, std::min(this->Parent.FaceOrigin[f0], this->Parent.FaceOrigin[f1]),
      this->Parent.FaceIsHole[f0] && this->Parent.FaceIsHole[f1]);
  }

  // V-faces: one per sector (run of faces between sharp edges) of at least three faces.
  void WriteVertexFaces(Index v, FaceBlock& out)
  {
    if (!this->Topo.GetOrderedVertexFaces(v, this->Fan, this->FanCorners))
    {
      return;
    }
    const Index m = static_cast<Index>(this->Fan.size());
    const bool closed = !this->Topo.GetVertexTag(v).Boundary;
    // SharpAfter[i]: the edge between Fan[i] and the next face, the edge entering v in
    // Fan[i], is sharp; an open fan ends at the boundary.
    this->SharpAfter.assign(static_cast<size_t>(m), 0);
    Index start = 0;
    for (Index i = 0; i < m; ++i)
    {
      const Index entering = CornerEdges(this->Topo, this->Fan[i], this->FanCorners[i]).second;
      this->SharpAfter[i] = this->Points.EdgeActsAsBoundary[entering] || (!closed && i == m - 1);
      if (this->SharpAfter[i] && closed && start == 0)
      {
        start = (i + 1) % m; // sectors of a closed fan start after a sharp edge
      }
    }
    // Walk the fan from `start`, cutting after each sharp edge.
    Index sectorBegin = 0;
    for (Index k = 0; k < m; ++k)
    {
      if (!this->SharpAfter[(start + k) % m] && k != m - 1)
      {
        continue;
      }
      if (k + 1 - sectorBegin >= 3)
      {
        const size_t first = out.BeginFace();
        std::uint8_t allHoles = 1;
        Index origin = std::numeric_limits<Index>::max(); // the sector's lowest, as for E-faces
        for (Index s = sectorBegin; s <= k; ++s)
        {
          const Index i = (start + s) % m;
          out.Vertices.push_back(this->CornerPoint(this->Fan[i], this->FanCorners[i]));
          allHoles &= this->Parent.FaceIsHole[this->Fan[i]];
          origin = std::min(origin, this->Parent.FaceOrigin[this->Fan[i]]);
        }
        out.EndFaceWithoutRepeats(first, origin, allHoles);
      }
      sectorBegin = k + 1;
    }
  }

  const Level& Parent;
  const MeshTopology& Topo;
  const DualPoints& Points;
  std::vector<Index> Fan, FanCorners;     // scratch of WriteVertexFaces
  std::vector<std::uint8_t> SharpAfter;
};

// The sharpness the child inherits: the child edge between the two welded points of a sharp
// edge, and, at a vertex on a crease (a turn included), between the points of its two crease
// edges.
void InheritDualSharpness(const Level& parent, const DualPoints& points, Level& child)
{
  const MeshTopology& topo = parent.Topology;
  const MeshTopology& childTopo = child.Topology;
  auto pointAt = [&](Index f, Index v) { return points.PointOf(topo.GetFaceOffset(f) + topo.FindCorner(v, f)); };
  // The point at v on crease edge e.
  auto pointOn = [&](Index e, Index v) { return DualPointOnEdge(topo, points, topo.GetEdgeFaces(e)[0], v, e); };
  for (Index e = 0; e < topo.GetNumEdges(); ++e)
  {
    if (!IsSharp(parent.EdgeSharpness[e]) || topo.GetEdgeFaces(e).empty())
    {
      continue;
    }
    const Index* ev = topo.GetEdgeVertices(e);
    const Index segment = childTopo.FindEdge(pointOn(e, ev[0]), pointOn(e, ev[1]));
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
        ends[found++] = pointOn(e, v);
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
}

Level SplitDual(
  const Level& parent, const DualPoints& points, ChildTopology depth, const ParallelFor& parallelFor)
{
  EmittedFaces faces = EmitFacesInParallel(DualFaceWriter(parent, points).GetNumElements(), parallelFor,
    [&](Index begin, Index end, FaceBlock& block) { DualFaceWriter(parent, points).WriteBlock(begin, end, block); });
  Level child;
  child.FaceOrigin = std::move(faces.Origins);
  child.FaceIsHole = std::move(faces.Holes);
  SetChildTopology(parent, child, points.NumPoints, std::move(faces.Offsets), std::move(faces.Vertices), depth, parallelFor);
  if (depth == ChildTopology::Full && parent.HasSharpFeatures())
  {
    InheritDualSharpness(parent, points, child);
  }
  return child;
}
}
