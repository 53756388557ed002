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

bool ActsAsBoundary(const Level& level, Index e)
{
  const MeshTopology& topo = level.Topology;
  return IsSharp(level.EdgeSharpness[e]) || topo.GetEdgeFaces(e).size() != 2 ||
    topo.GetEdgeTag(e).NonManifold;
}

bool Level::HasHoles() const
{
  return std::any_of(
    this->FaceIsHole.begin(), this->FaceIsHole.end(), [](std::uint8_t h) { return h != 0; });
}

bool Level::HasSharpFeatures() const
{
  auto sharp = [](float s) { return IsSharp(s); };
  return std::any_of(this->EdgeSharpness.begin(), this->EdgeSharpness.end(), sharp) ||
    std::any_of(this->VertexSharpness.begin(), this->VertexSharpness.end(), sharp);
}

float ChildEdgeSharpness(const Level& level, Index e, int end)
{
  const float sharpness = level.EdgeSharpness[e];
  if (level.Creasing == CreaseMethod::Uniform || !IsSemiSharp(sharpness))
  {
    return DecaySharpness(sharpness);
  }
  const MeshTopology& topo = level.Topology;
  const IndexSpan edges = topo.GetVertexEdges(topo.GetEdgeVertices(e)[end]);
  std::vector<float> around(static_cast<size_t>(edges.size()));
  for (Index i = 0; i < edges.size(); ++i)
  {
    around[i] = level.EdgeSharpness[edges[i]];
  }
  return SubdivideEdgeSharpnessAtVertex(sharpness, level.Creasing, around.data(), edges.size());
}

namespace
{
/// The rule of a vertex with the given sharpness and the sharpness of its edges; the first
/// two sharp edges' positions go to creaseEdges.
VertexRule ClassifyAround(const MeshTopology& topo, Index v, float vertexSharpness,
  const float* edgeSharpness, Index creaseEdges[2])
{
  const IndexSpan edges = topo.GetVertexEdges(v);
  Index sharpCount = 0;
  for (Index i = 0; i < edges.size(); ++i)
  {
    if (IsSharp(edgeSharpness[i]))
    {
      if (sharpCount < 2)
      {
        creaseEdges[sharpCount] = i;
      }
      ++sharpCount;
    }
  }
  const VertexRule rule = ClassifyVertex(vertexSharpness, sharpCount);
  const bool closedFan = topo.GetVertexFaces(v).size() > 0 && topo.GetVertexFaces(v).size() == edges.size();
  return (rule == VertexRule::Smooth || rule == VertexRule::Dart) && !closedFan ? VertexRule::Corner : rule;
}
}

VertexRulePlan PlanVertexRule(const Level& level, Index v)
{
  const MeshTopology& topo = level.Topology;
  VertexRulePlan plan{ VertexRule::Corner, VertexRule::Corner, { 0, 0 }, { 0, 0 }, 1.0f };
  const IndexSpan edges = topo.GetVertexEdges(v);
  // The common case first, without buffers: nothing sharp at or around v. Such a vertex is
  // smooth now and one level down, or a corner when its faces do not close (as below).
  if (NothingSharpAt(level, v))
  {
    plan.Rule = plan.ChildRule = IsSmoothClosedVertex(level, v) ? VertexRule::Smooth : VertexRule::Corner;
    return plan;
  }
  // Small valences use the stack; a pole of any valence still works.
  constexpr Index stackSize = 32;
  float stackBuffer[2 * stackSize];
  std::vector<float> heapBuffer;
  float* parentSharpness = stackBuffer;
  if (edges.size() > stackSize)
  {
    heapBuffer.resize(2 * static_cast<size_t>(edges.size()));
    parentSharpness = heapBuffer.data();
  }
  float* childSharpness = parentSharpness + std::max(edges.size(), stackSize);
  bool semiSharp = IsSemiSharp(level.VertexSharpness[v]);
  for (Index i = 0; i < edges.size(); ++i)
  {
    parentSharpness[i] = level.EdgeSharpness[edges[i]];
    semiSharp = semiSharp || IsSemiSharp(parentSharpness[i]);
  }
  plan.Rule = ClassifyAround(topo, v, level.VertexSharpness[v], parentSharpness, plan.CreaseEdges);
  plan.ChildRule = plan.Rule;
  std::copy(plan.CreaseEdges, plan.CreaseEdges + 2, plan.ChildCreaseEdges);
  if (!semiSharp || plan.Rule == VertexRule::Smooth || plan.Rule == VertexRule::Dart)
  {
    return plan; // nothing decays, or the smooth rule applies whatever the child does
  }
  for (Index i = 0; i < edges.size(); ++i)
  {
    childSharpness[i] = level.Creasing == CreaseMethod::Uniform
      ? DecaySharpness(parentSharpness[i])
      : SubdivideEdgeSharpnessAtVertex(parentSharpness[i], level.Creasing, parentSharpness, edges.size());
  }
  const float childVertexSharpness = DecaySharpness(level.VertexSharpness[v]);
  plan.ChildRule = ClassifyAround(topo, v, childVertexSharpness, childSharpness, plan.ChildCreaseEdges);
  if (plan.ChildRule != plan.Rule)
  {
    plan.ParentWeight = TransitionWeightAtVertex(
      level.VertexSharpness[v], childVertexSharpness, parentSharpness, childSharpness, edges.size());
  }
  return plan;
}

float EdgeCreaseWeight(const Level& level, Index e)
{
  const float sharpness = level.EdgeSharpness[e];
  if (!IsSharp(sharpness))
  {
    return 0.0f;
  }
  if (level.Topology.GetEdgeFaces(e).size() != 2 ||
    (IsSharp(ChildEdgeSharpness(level, e, 0)) && IsSharp(ChildEdgeSharpness(level, e, 1))))
  {
    return 1.0f;
  }
  return sharpness;
}

std::vector<float> EdgeCreaseWeights(const Level& level)
{
  std::vector<float> weights(static_cast<size_t>(level.Topology.GetNumEdges()));
  for (Index e = 0; e < level.Topology.GetNumEdges(); ++e)
  {
    weights[e] = EdgeCreaseWeight(level, e);
  }
  return weights;
}

std::vector<std::uint8_t> FindSmoothClosedVertices(const Level& level, const ParallelFor& parallelFor)
{
  const MeshTopology& topo = level.Topology;
  std::vector<std::uint8_t> smooth(static_cast<size_t>(topo.GetNumVertices()));
  parallelFor(0, topo.GetNumVertices(), [&](Index begin, Index end) {
    for (Index v = begin; v < end; ++v)
    {
      const Index numEdges = topo.GetVertexEdges(v).size();
      smooth[v] = numEdges > 0 && topo.GetVertexFaces(v).size() == numEdges && !IsSharp(level.VertexSharpness[v]);
    }
  });
  for (Index e = 0; e < topo.GetNumEdges(); ++e)
  {
    if (IsSharp(level.EdgeSharpness[e]))
    {
      smooth[topo.GetEdgeVertices(e)[0]] = smooth[topo.GetEdgeVertices(e)[1]] = 0;
    }
  }
  return smooth;
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

void SetChildTopology(const Level& parent, Level& child, Index numPoints, IndexArray offsets,
  IndexArray vertices, ChildTopology depth, const ParallelFor& parallelFor)
{
  child.Depth = parent.Depth + 1;
  child.Creasing = parent.Creasing;
  child.Linear = parent.Linear;
  if (depth == ChildTopology::FacesOnly)
  {
    child.Topology = MeshTopology::BuildFacesOnly(numPoints, std::move(offsets), std::move(vertices));
    return;
  }
  child.Topology = MeshTopology::Build(numPoints, std::move(offsets), std::move(vertices), parallelFor);
  child.EdgeSharpness.assign(static_cast<size_t>(child.Topology.GetNumEdges()), SharpnessSmooth);
  child.VertexSharpness.assign(static_cast<size_t>(numPoints), SharpnessSmooth);
}

void InheritPrimalSharpness(const Level& parent, Level& child, Index firstEdgePoint, Index firstVertexPoint)
{
  const MeshTopology& topo = parent.Topology;
  const MeshTopology& childTopo = child.Topology;
  child.Linear = parent.Linear;
  if (parent.Linear == LinearPart::All)
  {
    child.EdgeSharpness.assign(static_cast<size_t>(childTopo.GetNumEdges()), SharpnessInfinite);
    child.VertexSharpness.assign(static_cast<size_t>(childTopo.GetNumVertices()), SharpnessInfinite);
    return;
  }
  child.EdgeSharpness.assign(static_cast<size_t>(childTopo.GetNumEdges()), SharpnessSmooth);
  for (Index e = 0; e < topo.GetNumEdges(); ++e)
  {
    const float sharpness = parent.EdgeSharpness[e];
    if (!IsSharp(sharpness))
    {
      continue;
    }
    // The halves: the edge point's edges to the ends' vertex points (two to the same one for
    // an edge from a vertex to itself).
    const Index* ev = topo.GetEdgeVertices(e);
    const Index edgePoint = firstEdgePoint + e;
    for (Index half : childTopo.GetVertexEdges(edgePoint))
    {
      const Index other = childTopo.GetOtherEndpoint(half, edgePoint);
      for (int k = 0; k < 2; ++k)
      {
        if (other == firstVertexPoint + ev[k])
        {
          child.EdgeSharpness[half] = ChildEdgeSharpness(parent, e, k);
        }
      }
    }
  }
  child.VertexSharpness.assign(static_cast<size_t>(childTopo.GetNumVertices()), SharpnessSmooth);
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    child.VertexSharpness[firstVertexPoint + v] = DecaySharpness(parent.VertexSharpness[v]);
  }
  for (Index e = 0; parent.Linear == LinearPart::Boundaries && e < topo.GetNumEdges(); ++e)
  {
    if (topo.GetEdgeTag(e).Boundary)
    {
      child.VertexSharpness[firstEdgePoint + e] = SharpnessInfinite;
    }
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

  level.EdgeSharpness.assign(tags.EdgeSharpness.begin(), tags.EdgeSharpness.end());
  level.EdgeSharpness.resize(static_cast<size_t>(numEdges), SharpnessSmooth);
  level.VertexSharpness.assign(tags.VertexSharpness.begin(), tags.VertexSharpness.end());
  level.VertexSharpness.resize(static_cast<size_t>(numVertices), SharpnessSmooth);
  level.FaceIsHole.assign(tags.FaceIsHole.begin(), tags.FaceIsHole.end());
  level.FaceIsHole.resize(static_cast<size_t>(numFaces), 0);
  level.Creasing = tags.Creasing;
  level.FaceOrigin.resize(static_cast<size_t>(numFaces));
  std::iota(level.FaceOrigin.begin(), level.FaceOrigin.end(), 0);

  // What follows marks boundaries, corners and non-manifold features: a closed manifold mesh
  // (the usual input) has none, and skips the passes over all its vertices and edges.
  if (topo.GetNumBoundaryEdges() == 0 && topo.GetNumNonManifoldEdges() == 0 && topo.GetNumNonManifoldVertices() == 0)
  {
    return level;
  }

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
