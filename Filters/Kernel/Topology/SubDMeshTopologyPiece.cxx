#include "SubDMeshTopology.h"

#include <numeric>
#include <unordered_map>

namespace subd
{
// A piece is small (the faces around a face or a vertex): its relations are worked out
// serially, with hash maps from this topology's numbering to the piece's.
MeshTopology MeshTopology::ExtractFaces(
  const std::vector<Index>& faces, std::vector<Index>& points, std::vector<Index>& edges) const
{
  std::unordered_map<Index, Index> pointOf, edgeOf;
  for (size_t p = 0; p < points.size(); ++p)
  {
    pointOf.emplace(points[p], static_cast<Index>(p));
  }
  edges.clear();
  MeshTopology piece;
  for (Index f : faces)
  {
    const IndexSpan fv = this->GetFaceVertices(f), fe = this->GetFaceEdges(f);
    for (Index k = 0; k < fv.size(); ++k)
    {
      const auto point = pointOf.emplace(fv[k], static_cast<Index>(points.size()));
      if (point.second)
      {
        points.push_back(fv[k]);
      }
      piece.FaceVertices.push_back(point.first->second);
      const auto edge = edgeOf.emplace(fe[k], static_cast<Index>(edges.size()));
      if (edge.second)
      {
        edges.push_back(fe[k]);
      }
      piece.FaceEdges.push_back(edge.first->second);
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
