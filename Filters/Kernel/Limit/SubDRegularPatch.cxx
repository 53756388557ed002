#include "SubDRegularPatch.h"

#include <algorithm>
#include <array>
#include <map>
#include <utility>
#include <vector>

namespace subd
{
namespace
{
bool IsZeroOrInfinite(float sharpness)
{
  return !IsSharp(sharpness) || IsInfinitelySharp(sharpness);
}

// The face across edge `e` of a face (the other of its two faces), if it can be crossed.
Index FaceAcross(const Level& level, Index face, Index e)
{
  if (!IsSmoothInteriorEdge(level, e))
  {
    return InvalidIndex;
  }
  const IndexSpan faces = level.Topology.GetEdgeFaces(e);
  return faces[0] == face ? faces[1] : faces[0];
}

using Lattice = std::array<int, 2>;

PatchPoint Single(Index p);

// a + b - c, merging repeated points: the point across edge ab of a lattice triangle abc.
PatchPoint Across(Index a, Index b, Index c)
{
  PatchPoint point;
  point.Count = 3;
  point.Points[0] = a;
  point.Points[1] = b;
  point.Points[2] = c;
  point.Weights[0] = point.Weights[1] = 1.0;
  point.Weights[2] = -1.0;
  return point;
}

// Lattice positions of the points around `face` (the faces reached from it through smooth
// edges at its corners), or false when they do not fit one lattice. For Loop, the point
// beyond a sharp edge ab of a triangle abc is the phantom a + b - c: with it Loop's smooth
// rules reproduce the crease rules (the edge point becomes the midpoint, the vertex point
// (1, 6, 1)/8), so the box spline of the extended lattice is the crease's limit surface.
bool Unfold(const Level& level, Index face, PatchKind kind, std::map<Lattice, PatchPoint>& pointAt)
{
  const MeshTopology& topo = level.Topology;
  const Index size = kind == PatchKind::BSpline ? 4 : 3;
  const IndexSpan corners = topo.GetFaceVertices(face);
  // The lattice position of each point placed: a few dozen at most, so a flat list (a hash
  // map's node per point made allocation the cost of every patch gathered).
  std::vector<std::pair<Index, Lattice>> where;
  where.reserve(32);
  auto find = [&where](Index v) {
    return std::find_if(where.begin(), where.end(), [v](const std::pair<Index, Lattice>& w) { return w.first == v; });
  };
  auto at = [&](Index v) { return find(v)->second; }; // v is placed: a corner or a fan's point
  auto place = [&](Index v, Lattice p) {
    auto known = find(v);
    if (known != where.end())
    {
      return known->second == p;
    }
    auto taken = pointAt.emplace(p, Single(v));
    if (!taken.second)
    {
      return false;
    }
    where.emplace_back(v, p);
    return true;
  };
  const Lattice start[4] = { { 1, 1 }, { 2, 1 }, { 2, 2 }, { 1, 2 } };
  const Lattice startTri[3] = { { 0, 0 }, { 1, 0 }, { 0, 1 } };
  for (Index k = 0; k < size; ++k)
  {
    place(corners[k], size == 4 ? start[k] : startTri[k]);
  }
  auto isCorner = [&](Index v) { return std::find(corners.begin(), corners.end(), v) != corners.end(); };
  std::vector<Index> queue{ face };
  std::vector<Index> seen{ face };
  for (size_t q = 0; q < queue.size(); ++q)
  {
    const Index g = queue[q];
    const IndexSpan gv = topo.GetFaceVertices(g);
    const IndexSpan ge = topo.GetFaceEdges(g);
    for (Index k = 0; k < size; ++k)
    {
      const Index a = gv[k], b = gv[(k + 1) % size];
      if (!isCorner(a) && !isCorner(b))
      {
        continue; // only the fans of the face's corners
      }
      const Index h = FaceAcross(level, g, ge[k]);
      if (h == InvalidIndex && size == 3)
      {
        const Index c = gv[(k + 2) % 3];
        const Lattice pa = at(a), pb = at(b), pc = at(c);
        const Lattice phantom{ pa[0] + pb[0] - pc[0], pa[1] + pb[1] - pc[1] };
        if (!pointAt.emplace(phantom, Across(a, b, c)).second)
        {
          return false;
        }
        continue;
      }
      if (h == InvalidIndex || std::find(seen.begin(), seen.end(), h) != seen.end())
      {
        continue;
      }
      if (topo.GetFaceSize(h) != size)
      {
        return false;
      }
      const IndexSpan hv = topo.GetFaceVertices(h);
      const Index r = topo.FindCorner(b, h); // h runs b -> a
      const Lattice pa = at(a), pb = at(b);
      if (size == 3)
      {
        const Lattice pc = at(gv[(k + 2) % 3]);
        if (!place(hv[(r + 2) % 3], { pa[0] + pb[0] - pc[0], pa[1] + pb[1] - pc[1] }))
        {
          return false;
        }
      }
      else
      {
        const Lattice pc = at(gv[(k + 2) % 4]), pd = at(gv[(k + 3) % 4]);
        if (!place(hv[(r + 2) % 4], { 2 * pa[0] - pd[0], 2 * pa[1] - pd[1] }) ||
          !place(hv[(r + 3) % 4], { 2 * pb[0] - pc[0], 2 * pb[1] - pc[1] }))
        {
          return false;
        }
      }
      seen.push_back(h);
      queue.push_back(h);
    }
  }
  return true;
}

PatchPoint Single(Index p)
{
  PatchPoint point;
  point.Count = 1;
  point.Points[0] = p;
  point.Weights[0] = 1.0;
  return point;
}

// 2 a - b, merging repeated points.
PatchPoint Reflect(const PatchPoint& a, const PatchPoint& b)
{
  PatchPoint out;
  auto add = [&out](const PatchPoint& p, double scale) {
    for (int i = 0; i < p.Count; ++i)
    {
      int slot = 0;
      while (slot < out.Count && out.Points[slot] != p.Points[i])
      {
        ++slot;
      }
      if (slot == out.Count)
      {
        out.Points[out.Count] = p.Points[i];
        out.Weights[out.Count++] = 0.0;
      }
      out.Weights[slot] += scale * p.Weights[i];
    }
  };
  add(a, 2.0);
  add(b, -1.0);
  return out;
}
}

bool IsSmoothInteriorEdge(const Level& level, Index e)
{
  return level.Topology.GetEdgeFaces(e).size() == 2 && !level.Topology.GetEdgeTag(e).NonManifold &&
    !IsSharp(level.EdgeSharpness[e]);
}

const int (&BoxSplineLattice())[12][2]
{
  static const int lattice[12][2] = { { 0, 0 }, { 1, 0 }, { 0, 1 }, { -1, 1 }, { -1, 0 }, { 0, -1 },
    { 1, -1 }, { 2, -1 }, { 2, 0 }, { 1, 1 }, { 0, 2 }, { -1, 2 } };
  return lattice;
}

std::vector<Index> SectorFaces(const Level& level, Index face, Index corner)
{
  const MeshTopology& topo = level.Topology;
  const Index v = topo.GetFaceVertices(face)[corner];
  std::vector<Index> sector{ face };
  // Walk one way through the edges leaving v, then the other way through those entering it
  // (unless the first walk came back round a closed fan).
  for (int direction = 0; direction < 2; ++direction)
  {
    Index g = face, c = corner;
    for (;;)
    {
      const Index size = topo.GetFaceSize(g);
      const Index e = topo.GetFaceEdges(g)[direction == 0 ? c : (c + size - 1) % size];
      const Index h = FaceAcross(level, g, e);
      if (h == face)
      {
        return sector;
      }
      if (h == InvalidIndex)
      {
        break;
      }
      sector.insert(direction == 0 ? sector.begin() : sector.end(), h);
      if (sector.size() > topo.GetVertexFaces(v).size())
      {
        return {}; // defensive: a manifold fan cannot be longer
      }
      g = h;
      c = topo.FindCorner(v, h);
    }
  }
  return sector;
}

namespace
{
// IsStableCorner, handing out the vertex's plan for the caller to go on with.
bool StableCorner(const Level& level, Index face, Index corner, Index faceSize, VertexRulePlan& plan)
{
  const MeshTopology& topo = level.Topology;
  const Index v = topo.GetFaceVertices(face)[corner];
  if (!IsZeroOrInfinite(level.VertexSharpness[v]))
  {
    return false;
  }
  for (Index e : topo.GetVertexEdges(v))
  {
    if (!IsZeroOrInfinite(level.EdgeSharpness[e]))
    {
      return false;
    }
  }
  for (Index g : topo.GetVertexFaces(v))
  {
    if (topo.GetFaceSize(g) != faceSize)
    {
      return false;
    }
  }
  plan = PlanVertexRule(level, v);
  return plan.Rule == plan.ChildRule;
}
}

bool IsStableCorner(const Level& level, Index face, Index corner, Index faceSize)
{
  VertexRulePlan plan;
  return StableCorner(level, face, corner, faceSize, plan);
}

bool IsRegularCorner(const Level& level, Index face, Index corner, PatchKind kind)
{
  const MeshTopology& topo = level.Topology;
  const Index v = topo.GetFaceVertices(face)[corner];
  const Index size = kind == PatchKind::BSpline ? 4 : 3;
  VertexRulePlan plan;
  if (!StableCorner(level, face, corner, size, plan))
  {
    return false;
  }
  switch (plan.Rule)
  {
    case VertexRule::Smooth:
      return !topo.GetVertexTag(v).Boundary && !topo.GetVertexTag(v).NonManifold &&
        topo.GetVertexEdges(v).size() == (size == 4 ? 4 : 6) &&
        topo.GetVertexFaces(v).size() == topo.GetVertexEdges(v).size();
    case VertexRule::Crease:
      return SectorFaces(level, face, corner).size() == (kind == PatchKind::BSpline ? 2u : 3u);
    case VertexRule::Corner:
      return kind == PatchKind::BSpline && SectorFaces(level, face, corner).size() == 1;
    default:
      return false;
  }
}

bool GatherRegularPatch(const Level& level, Index face, PatchKind kind, RegularPatch& patch)
{
  const MeshTopology& topo = level.Topology;
  const Index size = kind == PatchKind::BSpline ? 4 : 3;
  if (topo.GetFaceSize(face) != size)
  {
    return false;
  }
  for (Index k = 0; k < size; ++k)
  {
    if (!IsRegularCorner(level, face, k, kind))
    {
      return false;
    }
  }
  std::map<Lattice, PatchPoint> pointAt;
  if (!Unfold(level, face, kind, pointAt))
  {
    return false;
  }
  patch.Kind = kind;
  if (kind == PatchKind::BoxSpline)
  {
    patch.NumPoints = 12;
    for (int i = 0; i < 12; ++i)
    {
      auto found = pointAt.find({ BoxSplineLattice()[i][0], BoxSplineLattice()[i][1] });
      if (found == pointAt.end())
      {
        return false;
      }
      patch.Points[i] = found->second;
    }
    return true;
  }
  patch.NumPoints = 16;
  bool real[16] = {};
  for (int j = 0; j < 4; ++j)
  {
    for (int i = 0; i < 4; ++i)
    {
      auto found = pointAt.find({ i, j });
      real[4 * j + i] = found != pointAt.end();
      if (real[4 * j + i])
      {
        patch.Points[4 * j + i] = found->second;
      }
    }
  }
  auto at = [&patch](int i, int j) -> PatchPoint& { return patch.Points[4 * j + i]; };
  // Phantoms beyond a crease along an edge of the face: reflect through the crease.
  for (int k = 1; k <= 2; ++k)
  {
    if (!real[4 * k + 0])
      at(0, k) = Reflect(at(1, k), at(2, k));
    if (!real[4 * k + 3])
      at(3, k) = Reflect(at(2, k), at(1, k));
    if (!real[k])
      at(k, 0) = Reflect(at(k, 1), at(k, 2));
    if (!real[12 + k])
      at(k, 3) = Reflect(at(k, 2), at(k, 1));
  }
  // Grid corners: along the side whose inner points are real (across the crease that cuts
  // the other side), either way when both are phantoms.
  for (int ci : { 0, 3 })
  {
    for (int cj : { 0, 3 })
    {
      if (real[4 * cj + ci])
      {
        continue;
      }
      const int si = ci == 0 ? 1 : -1, sj = cj == 0 ? 1 : -1;
      if (real[4 * (cj + sj) + ci])
      {
        at(ci, cj) = Reflect(at(ci, cj + sj), at(ci, cj + 2 * sj));
      }
      else
      {
        at(ci, cj) = Reflect(at(ci + si, cj), at(ci + 2 * si, cj));
      }
    }
  }
  return true;
}
}
