#include "SubDDualLimit.h"

#include "SubDDooSabinRules.h"
#include "SubDDualSplit.h"
#include "SubDMidpointRules.h"
#include "SubDRingTangents.h"

namespace subd
{
namespace
{
Index CountCreaseEdges(const Level& level, Index v)
{
  return CountVertexEdges(level, v, ActsAsBoundary);
}

bool Fail(const Level& level, Index v, const char* scheme, bool tangents, std::string& error)
{
  error = NoClosedFormLimit(level, v, scheme, tangents);
  return false;
}

// The ring of a smooth vertex (no crease edge, closed fan of three or more faces), or false.
bool SmoothRing(const Level& level, Index v, std::vector<Index>& faces, std::vector<Index>& corners,
  std::vector<Index>& ring)
{
  return CountCreaseEdges(level, v) == 0 && GetOrderedRing(level.Topology, v, faces, corners, ring) &&
    ring.size() >= 3;
}

void AddIdentity(Index v, bool tangents, StencilRows& rows)
{
  rows.Add(v, tangents ? 0.0 : 1.0);
  rows.EndRow();
  if (tangents)
  {
    rows.Add(v, 0.0);
    rows.EndRow();
  }
}
}

std::string NoClosedFormLimit(const Level& level, Index v, const char* scheme, bool tangents)
{
  return "vertex " + std::to_string(v) + " (" + DescribeVertexForLimit(level, v) + ") has no closed-form " + scheme +
    (tangents ? " limit tangent plane" : " limit point");
}

std::string DescribeVertexForLimit(const Level& level, Index v)
{
  const MeshTopology& topo = level.Topology;
  if (topo.GetVertexTag(v).NonManifold)
  {
    return "non-manifold";
  }
  const Index creases = CountCreaseEdges(level, v);
  if (creases == 1)
  {
    return "a dart: a crease ends there";
  }
  if (creases > 0 || IsSharp(level.VertexSharpness[v]))
  {
    return topo.GetVertexTag(v).Boundary ? "on the boundary" : "on a crease or sharp";
  }
  return std::to_string(topo.GetVertexFaces(v).size()) + " faces";
}

bool BuildDooSabinLimitStencils(const Level& level, bool tangents, StencilTable& stencils, std::string& error)
{
  const MeshTopology& topo = level.Topology;
  const DualPoints points = NumberDualPoints(level);
  const StencilTable children = BuildDooSabinStencils(level, points);
  auto childOfCorner = [&](Index f, Index corner) { return points.PointOf(topo.GetFaceOffset(f) + corner); };
  StencilRows rows;
  std::vector<Index> faces, corners, ring;
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    if (topo.GetVertexFaces(v).empty() || (!tangents && points.IsCornerVertex[v]))
    {
      AddIdentity(v, tangents, rows);
      continue;
    }
    if (points.IsCornerVertex[v]) // pinned: no V-face, one tangent plane per face
    {
      return Fail(level, v, "Doo-Sabin", tangents, error);
    }
    if (SmoothRing(level, v, faces, corners, ring))
    {
      const Index n = static_cast<Index>(faces.size());
      auto addCorner = [&](Index j, double w) { rows.AddRow(children, childOfCorner(faces[j], corners[j]), w); };
      if (tangents)
      {
        AppendRingTangentRows(n, addCorner, rows);
      }
      else
      {
        for (Index j = 0; j < n; ++j)
        {
          addCorner(j, 1.0 / n);
        }
        rows.EndRow();
      }
      continue;
    }
    if (tangents || topo.GetVertexTag(v).NonManifold || CountCreaseEdges(level, v) != 2)
    {
      return Fail(level, v, "Doo-Sabin", tangents, error);
    }
    // A crease vertex: its two child points on the crease, on its two crease edges.
    for (Index e : topo.GetVertexEdges(v))
    {
      if (ActsAsBoundary(level, e))
      {
        rows.AddRow(children, DualPointOnEdge(topo, points, topo.GetEdgeFaces(e)[0], v, e), 0.5);
      }
    }
    rows.EndRow();
  }
  stencils = rows.ToStencilTable(topo.GetNumVertices());
  return true;
}

bool BuildMidpointLimitStencils(const Level& level, bool tangents, StencilTable& stencils, std::string& error)
{
  const MeshTopology& topo = level.Topology;
  StencilRows rows;
  std::vector<Index> faces, corners, ring;
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    if (topo.GetVertexFaces(v).empty() || (!tangents && MidpointKeepsVertex(level, v)))
    {
      AddIdentity(v, tangents, rows);
      continue;
    }
    if (MidpointKeepsVertex(level, v) || !SmoothRing(level, v, faces, corners, ring))
    {
      return Fail(level, v, "midpoint", tangents, error);
    }
    const Index n = static_cast<Index>(ring.size());
    if (tangents)
    {
      // The V-face's corners are the midpoints (v + ring_j) / 2; v drops out of the modes.
      AppendRingTangentRows(n, [&](Index j, double w) { rows.Add(ring[j], 0.5 * w); }, rows);
      continue;
    }
    rows.Add(v, 0.5);
    for (Index j = 0; j < n; ++j)
    {
      rows.Add(ring[j], 0.5 / n);
    }
    rows.EndRow();
  }
  stencils = rows.ToStencilTable(topo.GetNumVertices());
  return true;
}
}
