#include "SubDMeshTopology.h"

#include <numeric>
#include <utility>
#include <vector>

namespace subd
{
namespace
{
// This topology's indices to a piece's: open addressing in two flat arrays. A piece is small
// and made for every local refinement of the limit evaluator: a hash map's node per entry
// made the allocator most of that work.
class IndexMap
{
public:
  explicit IndexMap(size_t expected)
  {
    size_t size = 16;
    while (size < 2 * expected)
    {
      size *= 2;
    }
    this->Keys.assign(size, InvalidIndex);
    this->Values.resize(size);
  }
  /// The value of `key`, and whether it was new (then `value` was stored for it).
  std::pair<Index, bool> Emplace(Index key, Index value)
  {
    const size_t mask = this->Keys.size() - 1;
    size_t slot = (static_cast<size_t>(key) * 0x9E3779B97F4A7C15ull >> 17) & mask;
    while (this->Keys[slot] != InvalidIndex)
    {
      if (this->Keys[slot] == key)
      {
        return { this->Values[slot], false };
      }
      slot = (slot + 1) & mask;
    }
    this->Keys[slot] = key;
    this->Values[slot] = value;
    return { value, true };
  }

private:
  std::vector<Index> Keys, Values;
};
}

// A piece is small (the faces around a face or a vertex): its relations are worked out
// serially, with maps from this topology's numbering to the piece's.
MeshTopology MeshTopology::ExtractFaces(
  const std::vector<Index>& faces, std::vector<Index>& points, std::vector<Index>& edges) const
{
  size_t corners = 0;
  for (Index f : faces)
  {
    corners += static_cast<size_t>(this->GetFaceSize(f));
  }
  IndexMap pointOf(points.size() + corners), edgeOf(corners);
  for (size_t p = 0; p < points.size(); ++p)
  {
    pointOf.Emplace(points[p], static_cast<Index>(p));
  }
  edges.clear();
  MeshTopology piece;
  piece.FaceVertices.reserve(corners);
  piece.FaceEdges.reserve(corners);
  for (Index f : faces)
  {
    const IndexSpan fv = this->GetFaceVertices(f), fe = this->GetFaceEdges(f);
    for (Index k = 0; k < fv.size(); ++k)
    {
      const std::pair<Index, bool> point = pointOf.Emplace(fv[k], static_cast<Index>(points.size()));
      if (point.second)
      {
        points.push_back(fv[k]);
      }
      piece.FaceVertices.push_back(point.first);
      const std::pair<Index, bool> edge = edgeOf.Emplace(fe[k], static_cast<Index>(edges.size()));
      if (edge.second)
      {
        edges.push_back(fe[k]);
      }
      piece.FaceEdges.push_back(edge.first);
    }
    piece.FaceOffsets.push_back(static_cast<Index>(piece.FaceVertices.size()));
  }
  piece.NumVertices = static_cast<Index>(points.size());
  const Index numEdges = static_cast<Index>(edges.size());
  // Each edge runs the way its first half-edge does, its faces in increasing order, as in Build.
  piece.EdgeVertices.assign(2 * static_cast<size_t>(numEdges), InvalidIndex);
  piece.EdgeFaceOffsets.assign(static_cast<size_t>(numEdges) + 1, 0);
  std::vector<Index> forward(static_cast<size_t>(numEdges), 0);
  for (Index f = 0; f < piece.GetNumFaces(); ++f)
  {
    const Index first = piece.FaceOffsets[f], last = piece.FaceOffsets[f + 1];
    for (Index h = first; h < last; ++h)
    {
      const Index e = piece.FaceEdges[h], from = piece.FaceVertices[h];
      if (piece.EdgeVertices[2 * static_cast<size_t>(e)] == InvalidIndex)
      {
        piece.EdgeVertices[2 * static_cast<size_t>(e)] = from;
        piece.EdgeVertices[2 * static_cast<size_t>(e) + 1] = piece.FaceVertices[h + 1 < last ? h + 1 : first];
      }
      forward[e] += piece.EdgeVertices[2 * static_cast<size_t>(e)] == from;
      ++piece.EdgeFaceOffsets[e + 1];
    }
  }
  std::partial_sum(piece.EdgeFaceOffsets.begin(), piece.EdgeFaceOffsets.end(), piece.EdgeFaceOffsets.begin());
  piece.EdgeFaces.resize(piece.FaceEdges.size());
  std::vector<Index> filled(piece.EdgeFaceOffsets.begin(), piece.EdgeFaceOffsets.end() - 1);
  for (Index f = 0; f < piece.GetNumFaces(); ++f)
  {
    for (Index h = piece.FaceOffsets[f]; h < piece.FaceOffsets[f + 1]; ++h)
    {
      piece.EdgeFaces[filled[piece.FaceEdges[h]]++] = f;
    }
  }
  piece.EdgeTags.resize(static_cast<size_t>(numEdges));
  for (Index e = 0; e < numEdges; ++e)
  {
    const Index count = piece.EdgeFaceOffsets[e + 1] - piece.EdgeFaceOffsets[e];
    EdgeTag& tag = piece.EdgeTags[e];
    tag.Boundary = count == 1;
    tag.NonManifold = this->EdgeTags[edges[e]].NonManifold || EdgeCounts::IsNonManifold(count, forward[e]);
    piece.NumBoundaryEdges += tag.Boundary;
    piece.NumNonManifoldEdges += tag.NonManifold;
  }
  piece.BuildVertexFaces(SerialFor);
  piece.BuildVertexEdges(SerialFor);
  piece.TagVertices(IndexArray(static_cast<size_t>(piece.NumVertices), InvalidIndex), SerialFor);
  return piece;
}
}
