#include "SubDMidpointRules.h"
#include "SubDRowWriting.h"

#include <algorithm>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

namespace subd
{
bool MidpointKeepsVertex(const Level& level, Index v)
{
  const MeshTopology& topo = level.Topology;
  const VertexTag tag = topo.GetVertexTag(v);
  if (tag.NonManifold || topo.GetVertexFaces(v).empty())
  {
    return false;
  }
  if (tag.Boundary || IsSharp(level.VertexSharpness[v]))
  {
    return true;
  }
  Index creases = 0;
  for (Index e : topo.GetVertexEdges(v))
  {
    creases += ActsAsBoundary(level, e);
  }
  return creases >= 2;
}

namespace
{
// The halves of each sharp edge next to a kept end, and the kept vertices, inherit their
// sharpness one level down.
void InheritMidpointSharpness(const Level& parent, const std::vector<Index>& keptPoint, Level& child)
{
  const MeshTopology& topo = parent.Topology;
  for (Index e = 0; e < topo.GetNumEdges(); ++e)
  {
    if (!IsSharp(parent.EdgeSharpness[e]))
    {
      continue;
    }
    const Index* ev = topo.GetEdgeVertices(e);
    for (int k = 0; k < 2; ++k)
    {
      const Index half = keptPoint[ev[k]] == InvalidIndex ? InvalidIndex : child.Topology.FindEdge(e, keptPoint[ev[k]]);
      if (half != InvalidIndex)
      {
        child.EdgeSharpness[half] = ChildEdgeSharpness(parent, e, k);
      }
    }
  }
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    if (keptPoint[v] != InvalidIndex)
    {
      child.VertexSharpness[keptPoint[v]] = DecaySharpness(parent.VertexSharpness[v]);
    }
  }
}

// The V-faces. In fan order the edge entering v in one face is the edge leaving v in the
// next, so a smooth vertex's V-face is the midpoints of the leaving edges. A kept vertex's
// fan is cut after each face whose entering edge acts as a boundary (an open fan starts at
// the face with the boundary edge leaving v and ends at the one with the boundary edge
// entering it); each sector of two or more faces gets a V-face from the kept point through
// the midpoints of its leaving edges, ending with the entering edge of its last face. A
// sector of one face would give a triangle of three points on its two boundary-like edges
// (a sliver along a boundary or crease): its kept point goes into the face's F-face at that
// corner instead (insertedAtCorner, indexed by face corner).
void AddVertexFaces(const Level& parent, const std::vector<Index>& keptPoint, std::vector<Index>& insertedAtCorner,
  std::vector<Index>& offsets, std::vector<Index>& vertices, std::vector<Index>& origins,
  std::vector<std::uint8_t>& holes)
{
  const MeshTopology& topo = parent.Topology;
  std::vector<Index> fan, corners;
  std::vector<std::uint8_t> cutAfter;
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    if (!topo.GetOrderedVertexFaces(v, fan, corners))
    {
      continue;
    }
    const Index m = static_cast<Index>(fan.size());
    auto leaving = [&](Index i) { return topo.GetFaceEdges(fan[i])[corners[i]]; };
    auto entering = [&](Index i) {
      const Index n = topo.GetFaceSize(fan[i]);
      return topo.GetFaceEdges(fan[i])[(corners[i] + n - 1) % n];
    };
    const Index kept = keptPoint[v];
    cutAfter.assign(static_cast<size_t>(m), 0);
    Index start = 0;
    if (kept != InvalidIndex)
    {
      Index cuts = 0;
      for (Index i = 0; i < m; ++i)
      {
        cutAfter[i] = ActsAsBoundary(parent, entering(i));
        cuts += cutAfter[i];
      }
      const bool closed = !topo.GetVertexTag(v).Boundary;
      if (closed && cuts < 2)
      {
        cutAfter.assign(static_cast<size_t>(m), 1);
      }
      if (closed)
      {
        while (!cutAfter[start])
        {
          ++start;
        }
        start = (start + 1) % m;
      }
    }
    else if (m < 3)
    {
      continue; // a smooth vertex of two faces (e.g. where a semi-sharp crease ended)
    }
    Index sectorFirst = 0;
    for (Index k = 0; k < m; ++k)
    {
      const Index i = (start + k) % m;
      const bool sectorEnds = cutAfter[i] || k == m - 1;
      if (kept != InvalidIndex && sectorEnds && sectorFirst == k)
      {
        insertedAtCorner[topo.GetFaceOffset(fan[i]) + corners[i]] = kept;
        sectorFirst = k + 1;
        continue;
      }
      if (kept != InvalidIndex && sectorFirst == k)
      {
        vertices.push_back(kept);
      }
      vertices.push_back(leaving(i));
      if (!sectorEnds)
      {
        continue;
      }
      if (kept != InvalidIndex)
      {
        vertices.push_back(entering(i));
      }
      std::uint8_t allHoles = 1;
      Index origin = std::numeric_limits<Index>::max(); // the sector's lowest: see the dual split
      for (Index s = sectorFirst; s <= k; ++s)
      {
        allHoles &= parent.FaceIsHole[fan[(start + s) % m]];
        origin = std::min(origin, parent.FaceOrigin[fan[(start + s) % m]]);
      }
      offsets.push_back(static_cast<Index>(vertices.size()));
      origins.push_back(origin);
      holes.push_back(allHoles);
      sectorFirst = k + 1;
    }
  }
}
}

namespace
{
// The child point of each vertex the split keeps (else InvalidIndex), numbered after the
// midpoints in vertex order, and the number of child points.
struct KeptPoints
{
  std::vector<Index> PointOf;
  Index NumChildPoints = 0;
};

KeptPoints NumberKeptPoints(const Level& parent)
{
  const MeshTopology& topo = parent.Topology;
  KeptPoints kept{ std::vector<Index>(static_cast<size_t>(topo.GetNumVertices()), InvalidIndex), topo.GetNumEdges() };
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    if (MidpointKeepsVertex(parent, v))
    {
      kept.PointOf[v] = kept.NumChildPoints++;
    }
  }
  return kept;
}

// The rows, one at a time (SubDRowWriting.h): the edges' midpoints, then the kept vertices'
// copies.
class MidpointRowWriter
{
public:
  MidpointRowWriter(const Level& parent, const KeptPoints& kept)
    : Topology(parent.Topology)
  {
    for (Index v = 0; v < static_cast<Index>(kept.PointOf.size()); ++v)
    {
      if (kept.PointOf[v] != InvalidIndex)
      {
        this->KeptVertices.push_back(v);
      }
    }
  }
  explicit MidpointRowWriter(const Level& parent)
    : MidpointRowWriter(parent, NumberKeptPoints(parent))
  {
  }
  Index GetNumParents() const { return this->Topology.GetNumVertices(); }
  Index GetNumRows() const { return this->Topology.GetNumEdges() + static_cast<Index>(this->KeptVertices.size()); }
  std::vector<Index> GetBlockEnds() const { return { this->GetNumRows() }; }
  Index GetMaxRowSize() const { return 2; }
  Index WriteRow(Index row, Index* sources, double* weights) const
  {
    RowEntries entries{ sources, weights, this->GetNumParents() };
    this->VisitSmoothRow(row, entries);
    return entries.Size;
  }
  template <typename Entries>
  bool VisitSmoothRow(Index row, Entries& entries) const
  {
    const Index numEdges = this->Topology.GetNumEdges();
    if (row < numEdges)
    {
      MidpointMask(this->Topology.GetEdgeVertices(row), entries);
    }
    else
    {
      CopyMask(this->KeptVertices[row - numEdges], entries);
    }
    return true;
  }

private:
  const MeshTopology& Topology;
  std::vector<Index> KeptVertices; // the vertex of each kept point
};

// The child level (the split without its stencils).
Level SplitWithKeptPoints(const Level& parent, const std::vector<Index>& keptPoint, Index numChildPoints,
  ChildTopology depth, const ParallelFor& parallelFor)
{
  const MeshTopology& topo = parent.Topology;
  // V-faces first (kept aside: they follow the F-faces), because a sector of a single face
  // puts its kept point into that face's F-face instead.
  std::vector<Index> insertedAtCorner(static_cast<size_t>(topo.GetNumFaceCorners()), InvalidIndex);
  std::vector<Index> vOffsets{ 0 }, vVertices, vOrigins;
  std::vector<std::uint8_t> vHoles;
  AddVertexFaces(parent, keptPoint, insertedAtCorner, vOffsets, vVertices, vOrigins, vHoles);

  Level child;
  IndexArray offsets{ 0 }, vertices;
  for (Index f = 0; f < topo.GetNumFaces(); ++f)
  {
    const IndexSpan edges = topo.GetFaceEdges(f);
    for (Index j = 0; j < edges.size(); ++j)
    {
      const Index inserted = insertedAtCorner[topo.GetFaceOffset(f) + j];
      if (inserted != InvalidIndex)
      {
        vertices.push_back(inserted); // corner j lies between the edges entering and leaving it
      }
      vertices.push_back(edges[j]);
    }
    offsets.push_back(static_cast<Index>(vertices.size()));
  }
  child.FaceOrigin.assign(parent.FaceOrigin.begin(), parent.FaceOrigin.end());
  child.FaceIsHole.assign(parent.FaceIsHole.begin(), parent.FaceIsHole.end());
  const Index base = static_cast<Index>(vertices.size());
  vertices.insert(vertices.end(), vVertices.begin(), vVertices.end());
  for (size_t k = 1; k < vOffsets.size(); ++k)
  {
    offsets.push_back(base + vOffsets[k]);
  }
  child.FaceOrigin.insert(child.FaceOrigin.end(), vOrigins.begin(), vOrigins.end());
  child.FaceIsHole.insert(child.FaceIsHole.end(), vHoles.begin(), vHoles.end());

  SetChildTopology(parent, child, numChildPoints, std::move(offsets), std::move(vertices), depth, parallelFor);
  if (depth == ChildTopology::Full)
  {
    InheritMidpointSharpness(parent, keptPoint, child);
  }
  return child;
}
}

LevelRefinement RefineMidpoint(const Level& parent, ChildTopology depth, const ParallelFor& parallelFor)
{
  const KeptPoints kept = NumberKeptPoints(parent);
  const MidpointRowWriter writer(parent, kept);
  LevelRefinement result;
  result.Stencils = WriteStencilTable(writer, 2 * static_cast<size_t>(writer.GetNumRows()));
  result.Child = SplitWithKeptPoints(parent, kept.PointOf, kept.NumChildPoints, depth, parallelFor);
  return result;
}

Level SplitMidpoint(const Level& parent, ChildTopology depth, const ParallelFor& parallelFor)
{
  const KeptPoints kept = NumberKeptPoints(parent);
  return SplitWithKeptPoints(parent, kept.PointOf, kept.NumChildPoints, depth, parallelFor);
}

std::shared_ptr<const RowSource> MakeMidpointRowSource(std::shared_ptr<const Level> parent)
{
  return std::make_shared<WrittenRows<MidpointRowWriter>>(std::move(parent));
}
}
