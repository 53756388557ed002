#include "SubDLocalLevel.h"

#include <algorithm>

namespace subd
{
namespace
{
// The piece of `level` around `face`, as a level of its own; `points` receives the level's
// index of each of its points.
Level ExtractPiece(const Level& level, Index face, std::vector<Index>& points)
{
  const MeshTopology& topo = level.Topology;
  std::vector<Index> faces{ face };
  for (Index v : topo.GetFaceVertices(face))
  {
    for (Index g : topo.GetVertexFaces(v))
    {
      if (std::find(faces.begin(), faces.end(), g) == faces.end())
      {
        faces.push_back(g);
      }
    }
  }
  if (level.Creasing == CreaseMethod::Chaikin)
  {
    // Chaikin creasing gives the far half of a semi-sharp spoke a sharpness averaged over
    // the edges at the spoke's far end, and the spoke's edge point reads it: where such an
    // end has semi-sharp edges, the piece takes all its faces too.
    const size_t numNear = faces.size();
    std::vector<Index> ends;
    for (size_t i = 0; i < numNear; ++i)
    {
      for (Index v : topo.GetFaceVertices(faces[i]))
      {
        const IndexSpan edges = topo.GetVertexEdges(v);
        const bool semiSharp = std::any_of(edges.begin(), edges.end(),
          [&level](Index e) { return IsSemiSharp(level.EdgeSharpness[e]); });
        if (semiSharp && std::find(ends.begin(), ends.end(), v) == ends.end())
        {
          ends.push_back(v);
        }
      }
    }
    for (Index v : ends)
    {
      for (Index g : topo.GetVertexFaces(v))
      {
        if (std::find(faces.begin(), faces.end(), g) == faces.end())
        {
          faces.push_back(g);
        }
      }
    }
  }
  points.clear();
  std::vector<Index> edges;
  Level piece;
  piece.Topology = topo.ExtractFaces(faces, points, edges);
  piece.Depth = level.Depth;
  piece.Creasing = level.Creasing;
  const MeshTopology& local = piece.Topology;
  piece.EdgeSharpness.resize(static_cast<size_t>(local.GetNumEdges()));
  for (Index e = 0; e < local.GetNumEdges(); ++e)
  {
    // The piece's own border is a boundary the rules must not see as smooth (it is never read).
    piece.EdgeSharpness[e] = local.GetEdgeFaces(e).size() == 2 ? level.EdgeSharpness[edges[e]] : SharpnessInfinite;
  }
  piece.VertexSharpness.resize(points.size());
  for (size_t p = 0; p < points.size(); ++p)
  {
    piece.VertexSharpness[p] = level.VertexSharpness[points[p]];
  }
  piece.FaceIsHole.resize(faces.size());
  piece.FaceOrigin.resize(faces.size());
  for (size_t g = 0; g < faces.size(); ++g)
  {
    piece.FaceIsHole[g] = level.FaceIsHole.empty() ? 0 : level.FaceIsHole[faces[g]];
    piece.FaceOrigin[g] = level.FaceOrigin.empty() ? 0 : level.FaceOrigin[faces[g]];
  }
  return piece;
}
}

LocalLevel ExtractLocalLevel(const Level& level, Index face, std::vector<Index>& supportPoints)
{
  LocalLevel local;
  local.Mesh = ExtractPiece(level, face, supportPoints);
  const Index n = static_cast<Index>(supportPoints.size());
  local.SupportSize = n;
  local.Weights.assign(static_cast<size_t>(n) * n, 0.0);
  for (Index p = 0; p < n; ++p)
  {
    local.Weights[static_cast<size_t>(p) * n + p] = 1.0;
  }
  return local;
}

LocalLevel ExtractLocalLevel(const LocalLevel& source, Index face)
{
  LocalLevel local;
  std::vector<Index> points;
  local.Mesh = ExtractPiece(source.Mesh, face, points);
  local.SupportSize = source.SupportSize;
  local.Weights.resize(points.size() * static_cast<size_t>(source.SupportSize));
  for (size_t p = 0; p < points.size(); ++p)
  {
    std::copy_n(source.GetWeights(points[p]), source.SupportSize, local.Weights.begin() + p * source.SupportSize);
  }
  return local;
}

LocalLevel RefineLocalLevel(const Scheme& scheme, const LocalLevel& local)
{
  LevelRefinement refined = scheme.RefineLevel(local.Mesh, ChildTopology::Full);
  LocalLevel child;
  child.Mesh = std::move(refined.Child);
  child.SupportSize = local.SupportSize;
  child.Weights.resize(static_cast<size_t>(child.Mesh.Topology.GetNumVertices()) * local.SupportSize);
  refined.Stencils.Apply(local.Weights.data(), child.Weights.data(), static_cast<int>(local.SupportSize));
  return child;
}

Index ChildFace(const Level& parent, Index face, Index corner, bool triangleSplit)
{
  return triangleSplit ? 4 * face + corner : parent.Topology.GetFaceOffset(face) + corner;
}
}
