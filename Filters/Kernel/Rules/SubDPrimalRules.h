// SubD kernel: the rules the primal schemes (Catmull-Clark, Loop) share: the crease rule of
// an edge (its midpoint) blended with the scheme's smooth edge rule by the edge's crease
// weight, and a vertex's crease (the cubic B-spline curve rule) and corner rules and the
// semi-sharp transition between a vertex's rule and its child's, as OpenSubdiv's
// Sdc::Scheme::ComputeEdgeVertexMask and ComputeVertexVertexMask compute them.
#ifndef SubDPrimalRules_h
#define SubDPrimalRules_h

#include "SubDLevel.h"
#include "SubDRowWriting.h"

#include <algorithm>

namespace subd
{
/// The crease rule of a vertex between two sharp edges, the cubic B-spline curve rule:
/// 3/4 on the vertex, 1/8 on each far end of the two edges.
constexpr double CreaseVertexWeight = 0.75;
constexpr double CreaseNeighbourWeight = 0.125;

/// The size of an edge row of a primal scheme: 2 (the midpoint) for a crease, else 4 (the
/// two ends and one source on each side).
inline Index PrimalEdgeRowSize(float creaseWeight)
{
  return creaseWeight == 1.0f ? 2 : 4;
}

/// Writes the edge row of a primal scheme (Catmull-Clark, Loop): the midpoint for a crease,
/// else the smooth rule (endWeight on each end, sideWeight on the two sources
/// writeSides(src + 2) names, one per face) blended with the midpoint by creaseWeight
/// (EdgeCreaseWeight), as OpenSubdiv's Sdc::Scheme::ComputeEdgeVertexMask does.
template <typename WriteSides>
void WritePrimalEdgeRow(const Index* ends, float creaseWeight, double endWeight, double sideWeight,
  Index* src, double* wts, WriteSides&& writeSides)
{
  if (creaseWeight == 1.0f)
  {
    RowEntries midpoint{ src, wts, 0 };
    MidpointMask(ends, midpoint);
    return;
  }
  src[0] = ends[0];
  src[1] = ends[1];
  const double crease = creaseWeight;
  const double smooth = 1.0 - crease;
  writeSides(src + 2);
  wts[0] = wts[1] = crease * 0.5 + smooth * endWeight;
  wts[2] = wts[3] = smooth * sideWeight;
}

/// The size of a vertex row of a primal scheme (Catmull-Clark, Loop): `smoothSize` if the
/// vertex or its child takes the smooth rule, else 3 for a crease and 1 for a corner.
inline Index PrimalVertexRowSize(const VertexRulePlan& plan, Index smoothSize)
{
  auto size = [smoothSize](VertexRule rule) {
    return rule == VertexRule::Corner ? 1 : (rule == VertexRule::Crease ? 3 : smoothSize);
  };
  return std::max(size(plan.Rule), size(plan.ChildRule));
}

/// Writes the vertex row of a primal scheme, of PrimalVertexRowSize(plan, smoothSize)
/// entries: the scheme's smooth row (writeSmooth(src, wts) writes smoothSize entries with v
/// in slot 0 and the far end of GetVertexEdges(v)[i] in slot 1 + i), the crease row
/// 3/4 v + 1/8 (a + b) (the cubic B-spline curve rule, a and b the far ends of the two sharp
/// edges), the corner row v' = v, or a transition: ParentWeight times the vertex's mask plus
/// the rest times its child's (OpenSubdiv's Sdc::Scheme::ComputeVertexVertexMask).
template <typename WriteSmooth>
void WritePrimalVertexRow(const MeshTopology& topo, const VertexRulePlan& plan, Index v,
  Index smoothSize, Index* src, double* wts, WriteSmooth&& writeSmooth)
{
  auto isSmooth = [](VertexRule rule) { return rule == VertexRule::Smooth || rule == VertexRule::Dart; };
  if (isSmooth(plan.Rule))
  {
    writeSmooth(src, wts);
    return;
  }
  const bool transition = plan.ChildRule != plan.Rule;
  const double parentWeight = transition ? static_cast<double>(plan.ParentWeight) : 1.0;
  const double childWeight = 1.0 - parentWeight;
  const IndexSpan edges = topo.GetVertexEdges(v);

  // Lay out the least sharp mask (the child's when they differ): the parent's sources are
  // among its slots, so the parent's weights add into them.
  const VertexRule layout = transition ? plan.ChildRule : plan.Rule;
  Index creaseSlots[2];
  if (isSmooth(layout))
  {
    writeSmooth(src, wts);
    for (Index i = 0; i < smoothSize; ++i)
    {
      wts[i] *= childWeight;
    }
    creaseSlots[0] = 1 + plan.CreaseEdges[0];
    creaseSlots[1] = 1 + plan.CreaseEdges[1];
  }
  else if (layout == VertexRule::Crease)
  {
    const Index* ends = transition ? plan.ChildCreaseEdges : plan.CreaseEdges;
    const double scale = transition ? childWeight : 1.0;
    src[0] = v;
    src[1] = topo.GetOtherEndpoint(edges[ends[0]], v);
    src[2] = topo.GetOtherEndpoint(edges[ends[1]], v);
    wts[0] = scale * CreaseVertexWeight;
    wts[1] = wts[2] = scale * CreaseNeighbourWeight;
    creaseSlots[0] = 1;
    creaseSlots[1] = 2;
  }
  else
  {
    src[0] = v;
    wts[0] = 1.0;
    return;
  }
  if (!transition)
  {
    return;
  }
  if (plan.Rule == VertexRule::Corner)
  {
    wts[0] += parentWeight;
  }
  else
  {
    wts[0] += parentWeight * CreaseVertexWeight;
    wts[creaseSlots[0]] += parentWeight * CreaseNeighbourWeight;
    wts[creaseSlots[1]] += parentWeight * CreaseNeighbourWeight;
  }
}
}

#endif
