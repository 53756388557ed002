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

VertexRulePlan PlanVertexRule(const Level& level, Index v)
{
  const MeshTopology& topo = level.Topology;
  VertexRulePlan plan{ VertexRule::Corner, { InvalidIndex, InvalidIndex } };
  const IndexSpan edges = topo.GetVertexEdges(v);
  const IndexSpan faces = topo.GetVertexFaces(v);
  Index sharpCount = 0;
  for (Index e : edges)
  {
    if (IsSharp(level.EdgeSharpness[e]))
    {
      if (sharpCount < 2)
      {
        plan.CreaseEnds[sharpCount] = topo.GetOtherEndpoint(e, v);
      }
      ++sharpCount;
    }
  }
  plan.Rule = ClassifyVertex(level.VertexSharpness[v], sharpCount);
  if ((plan.Rule == VertexRule::Smooth || plan.Rule == VertexRule::Dart) &&
    (faces.size() == 0 || faces.size() != edges.size()))
  {
    plan.Rule = VertexRule::Corner;
  }
  return plan;
}

std::vector<VertexRulePlan> PlanVertexRules(const Level& level)
{
  std::vector<VertexRulePlan> plans(static_cast<size_t>(level.Topology.GetNumVertices()));
  for (Index v = 0; v < level.Topology.GetNumVertices(); ++v)
  {
    plans[v] = PlanVertexRule(level, v);
  }
  return plans;
}

void SetChildTopology(const Level& parent, Level& child, Index numPoints, std::vector<Index> offsets,
  std::vector<Index> vertices, ChildTopology depth)
{
  child.Depth = parent.Depth + 1;
  if (depth == ChildTopology::FacesOnly)
  {
    child.Topology = MeshTopology::BuildFacesOnly(numPoints, std::move(offsets), std::move(vertices));
    return;
  }
  child.Topology = MeshTopology::Build(numPoints, std::move(offsets), std::move(vertices));
  child.EdgeSharpness.assign(static_cast<size_t>(child.Topology.GetNumEdges()), SharpnessSmooth);
  child.VertexSharpness.assign(static_cast<size_t>(numPoints), SharpnessSmooth);
}

void InheritPrimalSharpness(const Level& parent, Level& child, Index firstEdgePoint, Index firstVertexPoint)
{
  const MeshTopology& topo = parent.Topology;
  const MeshTopology& childTopo = child.Topology;
  child.EdgeSharpness.assign(static_cast<size_t>(childTopo.GetNumEdges()), SharpnessSmooth);
  for (Index e = 0; e < topo.GetNumEdges(); ++e)
  {
    const float sharpness = parent.EdgeSharpness[e];
    if (!IsSharp(sharpness))
    {
      continue;
    }
    const float decayed = DecaySharpness(sharpness);
    const Index* ev = topo.GetEdgeVertices(e);
    for (int k = 0; k < 2; ++k)
    {
      const Index half = childTopo.FindEdge(firstEdgePoint + e, firstVertexPoint + ev[k]);
      child.EdgeSharpness[half] = decayed;
    }
  }
  child.VertexSharpness.assign(static_cast<size_t>(childTopo.GetNumVertices()), SharpnessSmooth);
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    child.VertexSharpness[firstVertexPoint + v] = DecaySharpness(parent.VertexSharpness[v]);
  }
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
