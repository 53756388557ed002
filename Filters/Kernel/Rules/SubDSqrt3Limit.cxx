#include "SubDSqrt3Limit.h"

#include "SubDDualLimit.h" // NoClosedFormLimit
#include "SubDRingTangents.h"
#include "SubDSqrt3Rules.h"

namespace subd
{
namespace
{

// Whether one of v's triangles has a curve edge (an even step could trisect it).
bool TouchesCurveEdge(const Level& level, Index v)
{
  const MeshTopology& topo = level.Topology;
  for (Index f : topo.GetVertexFaces(v))
  {
    for (Index e : topo.GetFaceEdges(f))
    {
      if (IsSqrt3CurveEdge(level, e))
      {
        return true;
      }
    }
  }
  return false;
}

bool IsSmoothVertex(const Level& level, Index v)
{
  return ClassifySqrt3Vertex(level, v, true) == Sqrt3VertexRule::Relax && CountVertexEdges(level, v, IsSqrt3CurveEdge) == 0;
}

// The masks at the level itself; valid when the next step is odd or no smooth vertex
// touches a curve edge.
bool BuildDirectly(const Level& level, bool tangents, StencilRows& rows, std::string& error)
{
  const MeshTopology& topo = level.Topology;
  std::vector<Index> faces, corners, ring;
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    const Sqrt3VertexRule rule = ClassifySqrt3Vertex(level, v, true);
    if (IsSmoothVertex(level, v) && GetOrderedRing(topo, v, faces, corners, ring))
    {
      const Index n = static_cast<Index>(ring.size());
      if (tangents)
      {
        AppendRingTangentRows(n, [&](Index j, double w) { rows.Add(ring[j], w); }, rows);
        continue;
      }
      const double a = Sqrt3Alpha(n);
      const double b = 3.0 * a / (1.0 + 3.0 * a);
      rows.Add(v, 1.0 - b);
      for (Index p : ring)
      {
        rows.Add(p, b / n);
      }
      rows.EndRow();
      continue;
    }
    const bool noSurface = topo.GetVertexFaces(v).empty();
    if (tangents && !noSurface)
    {
      error = NoClosedFormLimit(level, v, "sqrt(3)", true);
      return false;
    }
    if (rule == Sqrt3VertexRule::Curve)
    {
      const Index a = Sqrt3CurveNeighbour(level, v, InvalidIndex);
      rows.Add(a, 1.0 / 6.0);
      rows.Add(v, 4.0 / 6.0);
      rows.Add(Sqrt3CurveNeighbour(level, v, a), 1.0 / 6.0);
    }
    else if (rule == Sqrt3VertexRule::Fixed || noSurface)
    {
      rows.Add(v, tangents ? 0.0 : 1.0);
      if (tangents)
      {
        rows.EndRow();
        rows.Add(v, 0.0);
      }
    }
    else
    {
      error = NoClosedFormLimit(level, v, "sqrt(3)", false);
      return false;
    }
    rows.EndRow();
  }
  return true;
}
}

bool BuildSqrt3LimitStencils(const Level& level, bool tangents, StencilTable& stencils, std::string& error)
{
  const MeshTopology& topo = level.Topology;
  const bool nextStepEven = (level.Depth % 2) == 1;
  bool needsStep = false;
  for (Index v = 0; v < topo.GetNumVertices() && nextStepEven && !needsStep; ++v)
  {
    needsStep = IsSmoothVertex(level, v) && TouchesCurveEdge(level, v);
  }
  StencilRows rows;
  if (!needsStep)
  {
    if (!BuildDirectly(level, tangents, rows, error))
    {
      return false;
    }
    stencils = rows.ToStencilTable(topo.GetNumVertices());
    return true;
  }
  // Find the vertices without masks here, so that errors name this level's vertices.
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    const bool smooth = IsSmoothVertex(level, v);
    const bool dart = ClassifySqrt3Vertex(level, v, true) == Sqrt3VertexRule::Relax && !smooth;
    if (dart || (tangents && !smooth && !topo.GetVertexFaces(v).empty()))
    {
      error = NoClosedFormLimit(level, v, "sqrt(3)", tangents);
      return false;
    }
  }
  const LevelRefinement step = RefineSqrt3(level, ChildTopology::Full);
  StencilRows childRows;
  if (!BuildDirectly(step.Child, tangents, childRows, error))
  {
    return false;
  }
  const Index first = Sqrt3FirstVertexPoint(level);
  const Index perVertex = tangents ? 2 : 1;
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    for (Index r = 0; r < perVertex; ++r)
    {
      const Index row = (first + v) * perVertex + r;
      for (Index k = childRows.Offsets[row]; k < childRows.Offsets[row + 1]; ++k)
      {
        rows.AddRow(step.Stencils, childRows.Sources[k], childRows.Weights[k]);
      }
      rows.EndRow();
    }
  }
  stencils = rows.ToStencilTable(topo.GetNumVertices());
  return true;
}
}
