#include "SubDLevel.h"
#include "SubDCrease.h"

#include <algorithm>
#include <numeric>

namespace subd
{
Index Level::GetNumSharpEdges(Index v) const
{
  Index count = 0;
  for (Index e : this->Topology.GetVertexEdges(v))
  {
    count += IsSharp(this->EdgeSharpness[e]);
  }
  return count;
}

bool Level::HasHoles() const
{
  return std::any_of(
    this->FaceIsHole.begin(), this->FaceIsHole.end(), [](std::uint8_t h) { return h != 0; });
}

Level MakeBaseLevel(MeshTopology topology, const BaseTags& tags, BoundaryRule rule)
{
  Level level;
  level.Topology = std::move(topology);
  const MeshTopology& topo = level.Topology;
  const Index numEdges = topo.GetNumEdges();
  const Index numVertices = topo.GetNumVertices();
  const Index numFaces = topo.GetNumFaces();

  level.EdgeSharpness = tags.EdgeSharpness;
  level.EdgeSharpness.resize(static_cast<size_t>(numEdges), SharpnessSmooth);
  level.VertexSharpness = tags.VertexSharpness;
  level.VertexSharpness.resize(static_cast<size_t>(numVertices), SharpnessSmooth);
  level.FaceIsHole = tags.FaceIsHole;
  level.FaceIsHole.resize(static_cast<size_t>(numFaces), 0);
  level.FaceOrigin.resize(static_cast<size_t>(numFaces));
  std::iota(level.FaceOrigin.begin(), level.FaceOrigin.end(), 0);

  // Holes first: they depend on the explicit sharpness, before boundaries are sharpened.
  if (rule == BoundaryRule::None)
  {
    for (Index v = 0; v < numVertices; ++v)
    {
      const IndexSpan edges = topo.GetVertexEdges(v);
      const IndexSpan faces = topo.GetVertexFaces(v);
      if (edges.size() == faces.size() && !topo.GetVertexTag(v).NonManifold)
      {
        continue; // manifold interior vertex
      }
      const bool exclude = std::any_of(edges.begin(), edges.end(), [&](Index e) {
        return topo.GetEdgeFaces(e).size() == 1 && !IsInfinitelySharp(level.EdgeSharpness[e]);
      });
      if (exclude)
      {
        for (Index f : faces)
        {
          level.FaceIsHole[f] = 1;
        }
      }
    }
  }

  for (Index e = 0; e < numEdges; ++e)
  {
    const EdgeTag tag = topo.GetEdgeTag(e);
    if (tag.Boundary || tag.NonManifold)
    {
      level.EdgeSharpness[e] = SharpnessInfinite;
    }
  }

  for (Index v = 0; v < numVertices; ++v)
  {
    const IndexSpan edges = topo.GetVertexEdges(v);
    const IndexSpan faces = topo.GetVertexFaces(v);
    const bool topologicalCorner = faces.size() == 1 && edges.size() == 2;
    if (topologicalCorner && rule == BoundaryRule::EdgeAndCorner)
    {
      level.VertexSharpness[v] = SharpnessInfinite;
    }
    else if (topo.GetVertexTag(v).NonManifold)
    {
      Index boundaryEdges = 0, nonManifoldEdges = 0;
      for (Index e : edges)
      {
        boundaryEdges += topo.GetEdgeTag(e).Boundary;
        nonManifoldEdges += topo.GetEdgeTag(e).NonManifold;
      }
      const bool insideNonManifoldCrease =
        nonManifoldEdges == 2 && boundaryEdges == 0 && faces.size() > edges.size();
      if (!insideNonManifoldCrease)
      {
        level.VertexSharpness[v] = SharpnessInfinite;
      }
    }
  }
  return level;
}
}
