#include "vtkSubDAdaptiveTessellation.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <unordered_map>
#include <unordered_set>

namespace
{
using Coord = std::int64_t;
/// A domain's side is 2^Bits units: every corner of a cell down to level Bits is an integer.
constexpr int Bits = 30;
constexpr Coord N = Coord(1) << Bits;

struct P2
{
  Coord X, Y;
};
P2 Mid(P2 a, P2 b)
{
  return { (a.X + b.X) / 2, (a.Y + b.Y) / 2 };
}
bool HasMid(P2 a, P2 b)
{
  return (a.X + b.X) % 2 == 0 && (a.Y + b.Y) % 2 == 0;
}
std::uint64_t Pack(P2 p)
{
  return (static_cast<std::uint64_t>(p.X) << 32) | static_cast<std::uint64_t>(p.Y);
}

using Vec3 = std::array<double, 3>;

/// The limit surface at a point: position and unit normal.
struct SurfacePoint
{
  Vec3 P{ { 0, 0, 0 } };
  Vec3 Normal{ { 0, 0, 0 } };
  bool HasNormal = false;
};

/// How far `q`, a point of a triangle meant to be near `s`, is from the limit surface: its
/// offset along the normal (to first order, the distance to the tangent plane). The whole
/// offset |q - s.P| would count the parametrization's stretch (large on flat faces next to
/// tight rims) as error.
double Distance(const SurfacePoint& s, const Vec3& q)
{
  const Vec3 d{ { q[0] - s.P[0], q[1] - s.P[1], q[2] - s.P[2] } };
  if (!s.HasNormal)
  {
    return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  }
  return std::abs(d[0] * s.Normal[0] + d[1] * s.Normal[1] + d[2] * s.Normal[2]);
}

Vec3 Mean(const Vec3& a, const Vec3& b)
{
  return { { 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2]) } };
}

/// A cell of a domain's tree: 3 (triangle) or 4 (quad) corners, counter-clockwise; a quad's
/// corners from (min u, min v) on, so that its sides 0 and 2 run along u, 1 and 3 along v.
struct Cell
{
  std::array<P2, 4> C;
  int NumCorners;
  std::array<int, 2> Depth; ///< times halved along u and along v (a triangle: both alike)
};

/// How a cell splits: a quad across u (at its u midpoint), across v, or both; a triangle
/// into four at its edge midpoints.
enum Split
{
  NoSplit = 0,
  SplitU = 1,
  SplitV = 2,
  SplitBoth = 3
};

/// The cells a cell splits into.
std::vector<Cell> Children(const Cell& c, int split)
{
  const P2 a = c.C[0], b = c.C[1], cc = c.C[2], d = c.C[3];
  const std::array<int, 2> depth{ { c.Depth[0] + (split & SplitU ? 1 : 0), c.Depth[1] + (split & SplitV ? 1 : 0) } };
  if (c.NumCorners == 3)
  {
    const P2 ab = Mid(a, b), bc = Mid(b, cc), ca = Mid(cc, a);
    return { { { a, ab, ca, {} }, 3, depth }, { { ab, b, bc, {} }, 3, depth }, { { ca, bc, cc, {} }, 3, depth },
      { { bc, ca, ab, {} }, 3, depth } };
  }
  const P2 ab = Mid(a, b), bc = Mid(b, cc), cd = Mid(cc, d), da = Mid(d, a), m = Mid(a, cc);
  switch (split)
  {
    case SplitU:
      return { { { a, ab, cd, d }, 4, depth }, { { ab, b, cc, cd }, 4, depth } };
    case SplitV:
      return { { { a, b, bc, da }, 4, depth }, { { da, bc, cc, d }, 4, depth } };
    default:
      return { { { a, ab, m, da }, 4, depth }, { { ab, b, bc, m }, 4, depth }, { { m, bc, cc, cd }, 4, depth },
        { { da, m, cd, d }, 4, depth } };
  }
}

/// The points a cell is judged by (and splits at): its side midpoints and a quad's centre.
std::vector<P2> SplitPoints(const Cell& c)
{
  std::vector<P2> points;
  for (int i = 0; i < c.NumCorners; ++i)
  {
    points.push_back(Mid(c.C[i], c.C[(i + 1) % c.NumCorners]));
  }
  if (c.NumCorners == 4)
  {
    points.push_back(Mid(c.C[0], c.C[2]));
  }
  return points;
}

// A point of the output, the same from every domain that meets it: a cage vertex, a point of a
// cage edge (numerator over 2N from the edge's first vertex), a point inside a domain, on the
// segment from an edge's midpoint to its polygon's centre (numerator over N), or a polygon's
// centre.
enum KeyKind : std::int64_t
{
  VertexKey,
  EdgeKey,
  InsideKey,
  SpokeKey,
  CentreKey
};
using Key = std::array<std::int64_t, 4>;
struct KeyHash
{
  size_t operator()(const Key& k) const
  {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (std::int64_t v : k)
    {
      h = (h ^ static_cast<std::uint64_t>(v)) * 0xBF58476D1CE4E5B9ull;
      h ^= h >> 31;
    }
    return static_cast<size_t>(h);
  }
};

enum class DomainKind
{
  Quad,      ///< a Catmull-Clark quad over the unit square
  Triangle,  ///< a Loop triangle over the unit triangle
  CornerQuad ///< the quad at corner Sub of a Catmull-Clark polygon that is not a quad
};

struct Domain
{
  subd::Index Face;
  subd::Index Sub;
  DomainKind Kind;
  int MaxDepth;    ///< the settings' deepest level, in this domain's cells
  int TargetDepth; ///< selective: the depth its face asks for
  std::vector<Cell> Active, Leaves;
  std::unordered_map<std::uint64_t, SurfacePoint> Known; ///< the surface at points evaluated
  long long OffTolerance = 0;
};

/// A cell's triangles: its corners and the points of finer cells on its sides, in order
/// around it, and triangles through them.
struct Triangulation
{
  std::vector<P2> Vertices;
  std::vector<std::array<int, 3>> Triangles;
};

class AdaptiveTessellator
{
public:
  AdaptiveTessellator(const vtkSubDCage& cage, const subd::LimitEvaluator& evaluator, bool quads,
    const vtkSubDAdaptiveSettings& settings)
    : Cage(cage)
    , Topo(cage.Level.Topology)
    , Evaluator(evaluator)
    , Quads(quads)
    , Settings(settings)
  {
  }
  bool Run(const std::vector<subd::Index>& faces, vtkSubDLimitSamples& samples, vtkSubDAdaptiveResult& result,
    std::string& error);

private:
  void MakeDomains(const std::vector<subd::Index>& faces);
  bool RefineAll();
  void Refine(Domain& d);
  int WantedSplit(const Domain& d, const Cell& c) const;
  void Evaluate(Domain& d, const std::vector<subd::FaceSample>& at, std::vector<SurfacePoint>& out);
  void EvaluateMissing(Domain& d, const std::vector<P2>& points);
  void RecordPresence();
  Triangulation Triangulate(size_t domain, const Cell& c) const;
  void AddHanging(size_t domain, P2 a, P2 b, std::vector<P2>& out) const;
  bool SplitOffTolerance(Domain& d);
  void Emit(vtkSubDLimitSamples& samples) const;

  Key KeyOf(size_t domain, P2 p) const;
  Key EdgePoint(subd::Index f, subd::Index k, Coord t) const;
  subd::FaceSample SampleAt(const Domain& d, P2 p) const
  {
    subd::FaceSample s;
    s.U = static_cast<double>(p.X) / N;
    s.V = static_cast<double>(p.Y) / N;
    s.SubFace = d.Sub;
    return s;
  }
  bool Fail(const std::string& message);

  const vtkSubDCage& Cage;
  const subd::MeshTopology& Topo;
  const subd::LimitEvaluator& Evaluator;
  const bool Quads;
  const vtkSubDAdaptiveSettings& Settings;
  std::vector<Domain> Domains;
  std::unordered_set<Key, KeyHash> Present; ///< every corner of every leaf
  std::atomic<long long> NumCells{ 0 };
  std::atomic<bool> Failed{ false };
  std::mutex ErrorMutex;
  std::string Error;
};

bool AdaptiveTessellator::Fail(const std::string& message)
{
  std::lock_guard<std::mutex> lock(this->ErrorMutex);
  if (!this->Failed.exchange(true))
  {
    this->Error = message;
  }
  return false;
}

Key AdaptiveTessellator::EdgePoint(subd::Index f, subd::Index k, Coord t) const
{
  const subd::IndexSpan fv = this->Topo.GetFaceVertices(f);
  const subd::Index n = static_cast<subd::Index>(fv.size());
  k = (k + n) % n;
  if (t == 0)
    return { VertexKey, fv[k], 0, 0 };
  if (t == 2 * N)
    return { VertexKey, fv[(k + 1) % n], 0, 0 };
  const subd::Index e = this->Topo.GetFaceEdges(f)[k];
  const bool forward = this->Topo.GetEdgeVertices(e)[0] == fv[k];
  return { EdgeKey, e, forward ? t : 2 * N - t, 0 };
}

Key AdaptiveTessellator::KeyOf(size_t domain, P2 p) const
{
  const Domain& d = this->Domains[domain];
  const Key inside{ InsideKey, static_cast<std::int64_t>(domain), p.X, p.Y };
  switch (d.Kind)
  {
    case DomainKind::Quad:
      if (p.Y == 0)
        return this->EdgePoint(d.Face, 0, 2 * p.X);
      if (p.X == N)
        return this->EdgePoint(d.Face, 1, 2 * p.Y);
      if (p.Y == N)
        return this->EdgePoint(d.Face, 2, 2 * (N - p.X));
      if (p.X == 0)
        return this->EdgePoint(d.Face, 3, 2 * (N - p.Y));
      return inside;
    case DomainKind::Triangle:
      if (p.Y == 0)
        return this->EdgePoint(d.Face, 0, 2 * p.X);
      if (p.X + p.Y == N)
        return this->EdgePoint(d.Face, 1, 2 * p.Y);
      if (p.X == 0)
        return this->EdgePoint(d.Face, 2, 2 * (N - p.Y));
      return inside;
    case DomainKind::CornerQuad:
    default:
    {
      // (0,0) at corner Sub, (N,0) at the middle of edge Sub, (N,N) at the centre, (0,N) at
      // the middle of the edge before.
      const subd::Index n = this->Topo.GetFaceSize(d.Face);
      if (p.X == N && p.Y == N)
        return { CentreKey, d.Face, 0, 0 };
      if (p.Y == 0)
        return this->EdgePoint(d.Face, d.Sub, p.X);
      if (p.X == 0)
        return this->EdgePoint(d.Face, d.Sub - 1, 2 * N - p.Y);
      if (p.X == N)
        return { SpokeKey, d.Face, d.Sub, p.Y };
      if (p.Y == N)
        return { SpokeKey, d.Face, (d.Sub + n - 1) % n, p.X };
      return inside;
    }
  }
}

void AdaptiveTessellator::MakeDomains(const std::vector<subd::Index>& faces)
{
  for (subd::Index f : faces)
  {
    const subd::Index n = this->Topo.GetFaceSize(f);
    const bool corners = this->Quads && n != 4;
    const int offset = corners ? 1 : 0; // a corner quad is a level finer than its face
    const int level = this->Settings.FaceLevels.empty() ? 0 : this->Settings.FaceLevels[f];
    const int maxDepth = std::max(this->Settings.MaximumLevel - offset, 0);
    Domain d{ f, 0, this->Quads ? (corners ? DomainKind::CornerQuad : DomainKind::Quad) : DomainKind::Triangle,
      maxDepth, std::min(std::max(level - offset, 0), maxDepth), {}, {}, {}, 0 };
    const Cell root = this->Quads ? Cell{ { P2{ 0, 0 }, P2{ N, 0 }, P2{ N, N }, P2{ 0, N } }, 4, { 0, 0 } }
                                  : Cell{ { P2{ 0, 0 }, P2{ N, 0 }, P2{ 0, N }, P2{} }, 3, { 0, 0 } };
    d.Active.push_back(root);
    for (subd::Index k = 0; k < (corners ? n : 1); ++k)
    {
      d.Sub = k;
      this->Domains.push_back(d);
    }
  }
  this->NumCells += static_cast<long long>(this->Domains.size());
}

void AdaptiveTessellator::Evaluate(Domain& d, const std::vector<subd::FaceSample>& at, std::vector<SurfacePoint>& out)
{
  std::vector<subd::LimitStencil> stencils;
  std::string error;
  out.assign(at.size(), SurfacePoint());
  if (at.empty())
  {
    return;
  }
  if (!this->Evaluator.EvaluateFace(d.Face, at, stencils, error))
  {
    this->Fail("cell " + std::to_string(this->Cage.FaceCell[d.Face]) + ": " + error);
    return;
  }
  for (size_t i = 0; i < at.size(); ++i)
  {
    SurfacePoint& s = out[i];
    double du[3], dv[3];
    stencils[i].Apply(stencils[i].Weights, subd::PatchValue, this->Cage.Points.data(), 3, s.P.data());
    stencils[i].Apply(stencils[i].Weights, subd::PatchDu, this->Cage.Points.data(), 3, du);
    stencils[i].Apply(stencils[i].Weights, subd::PatchDv, this->Cage.Points.data(), 3, dv);
    s.Normal = { { du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2], du[0] * dv[1] - du[1] * dv[0] } };
    const double length = std::sqrt(s.Normal[0] * s.Normal[0] + s.Normal[1] * s.Normal[1] + s.Normal[2] * s.Normal[2]);
    const double scale = std::sqrt((du[0] * du[0] + du[1] * du[1] + du[2] * du[2]) * (dv[0] * dv[0] + dv[1] * dv[1] + dv[2] * dv[2]));
    s.HasNormal = length > 1e-12 * scale && length > 0.0;
    for (double& x : s.Normal)
    {
      x = s.HasNormal ? x / length : 0.0;
    }
  }
}

void AdaptiveTessellator::EvaluateMissing(Domain& d, const std::vector<P2>& points)
{
  std::vector<P2> missing;
  std::vector<subd::FaceSample> at;
  for (const P2& p : points)
  {
    if (d.Known.count(Pack(p)) == 0)
    {
      missing.push_back(p);
      at.push_back(this->SampleAt(d, p));
      d.Known[Pack(p)]; // reserved: a point listed twice is evaluated once
    }
  }
  std::vector<SurfacePoint> positions;
  this->Evaluate(d, at, positions);
  for (size_t i = 0; i < missing.size(); ++i)
  {
    d.Known[Pack(missing[i])] = positions[i];
  }
}

// Selective: both ways until the face's level. Adaptive: a quad across u when a side along u
// strays from the surface, across v likewise, both ways when only its centre does (a twist);
// a triangle into four when any side or its centre strays.
int AdaptiveTessellator::WantedSplit(const Domain& d, const Cell& c) const
{
  const int allowed = (c.Depth[0] < d.MaxDepth ? SplitU : 0) | (c.Depth[1] < d.MaxDepth ? SplitV : 0);
  if (!this->Settings.FaceLevels.empty())
  {
    return c.Depth[0] < d.TargetDepth ? allowed : NoSplit;
  }
  auto at = [&d](P2 p) -> const SurfacePoint& { return d.Known.at(Pack(p)); };
  auto sideError = [&](int i) {
    const P2 a = c.C[i], b = c.C[(i + 1) % c.NumCorners];
    return Distance(at(Mid(a, b)), Mean(at(a).P, at(b).P));
  };
  const double tolerance = this->Settings.Tolerance;
  if (c.NumCorners == 3)
  {
    return std::max({ sideError(0), sideError(1), sideError(2) }) > tolerance ? allowed : NoSplit;
  }
  const SurfacePoint& centre = at(Mid(c.C[0], c.C[2]));
  const double centreError =
    std::min(Distance(centre, Mean(at(c.C[0]).P, at(c.C[2]).P)), Distance(centre, Mean(at(c.C[1]).P, at(c.C[3]).P)));
  int wanted = (std::max(sideError(0), sideError(2)) > tolerance ? SplitU : 0) |
    (std::max(sideError(1), sideError(3)) > tolerance ? SplitV : 0);
  if (wanted == NoSplit && centreError > tolerance)
  {
    wanted = SplitBoth;
  }
  return wanted & allowed;
}

// Splits the domain's active cells, level by level, until none wants to split.
void AdaptiveTessellator::Refine(Domain& d)
{
  std::vector<P2> points;
  for (const Cell& c : d.Active)
  {
    points.insert(points.end(), c.C.begin(), c.C.begin() + c.NumCorners);
  }
  this->EvaluateMissing(d, points);
  std::vector<Cell> next;
  while (!d.Active.empty() && !this->Failed)
  {
    points.clear();
    for (const Cell& c : d.Active)
    {
      const std::vector<P2> split = SplitPoints(c);
      points.insert(points.end(), split.begin(), split.end());
    }
    this->EvaluateMissing(d, points);
    next.clear();
    for (const Cell& c : d.Active)
    {
      if (const int split = this->WantedSplit(d, c))
      {
        const std::vector<Cell> children = Children(c, split);
        next.insert(next.end(), children.begin(), children.end());
      }
      else
      {
        d.Leaves.push_back(c);
      }
    }
    if ((this->NumCells += static_cast<long long>(next.size())) > this->Settings.MaximumCells)
    {
      this->Fail("the tessellation would need more than " + std::to_string(static_cast<long long>(
        this->Settings.MaximumCells)) + " cells, more than MaximumMemory allows: use a larger tolerance, "
        "a lower MaximumLevel, or a larger MaximumMemory");
    }
    d.Active.swap(next);
  }
  d.Active.clear();
}

bool AdaptiveTessellator::RefineAll()
{
  vtkSMPTools::For(0, static_cast<vtkIdType>(this->Domains.size()), [this](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end && !this->Failed; ++i)
    {
      this->Refine(this->Domains[i]);
    }
  });
  return !this->Failed;
}

void AdaptiveTessellator::RecordPresence()
{
  this->Present.clear();
  for (size_t i = 0; i < this->Domains.size(); ++i)
  {
    for (const Cell& c : this->Domains[i].Leaves)
    {
      for (int k = 0; k < c.NumCorners; ++k)
      {
        this->Present.insert(this->KeyOf(i, c.C[k]));
      }
    }
  }
}

// The points of finer cells strictly between a and b, in order: a point on a cell's side is
// always the midpoint of a dyadic part of it, so halving finds them all.
void AdaptiveTessellator::AddHanging(size_t domain, P2 a, P2 b, std::vector<P2>& out) const
{
  if (!HasMid(a, b))
  {
    return;
  }
  const P2 m = Mid(a, b);
  if (this->Present.count(this->KeyOf(domain, m)) == 0)
  {
    return;
  }
  this->AddHanging(domain, a, m, out);
  out.push_back(m);
  this->AddHanging(domain, m, b, out);
}

// Twice the area of the triangle a, b, c of the parameter plane (exact: integer corners).
Coord Area2(P2 a, P2 b, P2 c)
{
  return (b.X - a.X) * (c.Y - a.Y) - (b.Y - a.Y) * (c.X - a.X);
}

// The smallest angle of the triangle a, b, c of the parameter plane, as its sine.
double SmallestAngleSine(P2 a, P2 b, P2 c)
{
  const P2 p[3] = { a, b, c };
  double smallest = 1.0;
  for (int i = 0; i < 3; ++i)
  {
    const P2 &o = p[i], &x = p[(i + 1) % 3], &y = p[(i + 2) % 3];
    const double ux = static_cast<double>(x.X - o.X), uy = static_cast<double>(x.Y - o.Y);
    const double vx = static_cast<double>(y.X - o.X), vy = static_cast<double>(y.Y - o.Y);
    smallest = std::min(smallest, std::abs(ux * vy - uy * vx) / std::sqrt((ux * ux + uy * uy) * (vx * vx + vy * vy)));
  }
  return smallest;
}

// Triangulates a convex polygon whose sides may hold several points in a row: repeatedly cuts
// off the corner (a vertex where the boundary turns) whose triangle has the largest smallest
// angle. n vertices give n - 2 triangles, none of them flat.
void ClipEars(const std::vector<P2>& polygon, std::vector<std::array<int, 3>>& triangles)
{
  std::vector<int> left(polygon.size());
  for (size_t i = 0; i < left.size(); ++i)
  {
    left[i] = static_cast<int>(i);
  }
  while (left.size() > 3)
  {
    const size_t n = left.size();
    size_t best = n;
    double bestQuality = -1.0;
    for (size_t i = 0; i < n; ++i)
    {
      const P2 a = polygon[left[(i + n - 1) % n]], b = polygon[left[i]], c = polygon[left[(i + 1) % n]];
      // The rest must not become flat: some other vertex off the new side a-c.
      bool restHasArea = false;
      for (size_t k = 2; k + 1 < n && !restHasArea; ++k)
      {
        restHasArea = Area2(a, c, polygon[left[(i + k) % n]]) != 0;
      }
      const double quality = Area2(a, b, c) > 0 && restHasArea ? SmallestAngleSine(a, b, c) : -1.0;
      if (quality > bestQuality)
      {
        bestQuality = quality;
        best = i;
      }
    }
    triangles.push_back({ left[(best + n - 1) % n], left[best], left[(best + 1) % n] });
    left.erase(left.begin() + static_cast<std::ptrdiff_t>(best));
  }
  triangles.push_back({ left[0], left[1], left[2] });
}

// A cell with no point on its sides is one triangle, or a quad's two along the diagonal nearer
// the surface; otherwise its polygon with the points of its finer neighbours, cut into
// triangles corner by corner.
Triangulation AdaptiveTessellator::Triangulate(size_t domain, const Cell& c) const
{
  Triangulation t;
  for (int i = 0; i < c.NumCorners; ++i)
  {
    t.Vertices.push_back(c.C[i]);
    this->AddHanging(domain, c.C[i], c.C[(i + 1) % c.NumCorners], t.Vertices);
  }
  if (t.Vertices.size() == 4 && c.NumCorners == 4)
  {
    const Domain& d = this->Domains[domain];
    auto at = [&d](P2 p) -> const SurfacePoint& { return d.Known.at(Pack(p)); };
    const SurfacePoint& centre = at(Mid(c.C[0], c.C[2]));
    const bool first =
      Distance(centre, Mean(at(c.C[0]).P, at(c.C[2]).P)) <= Distance(centre, Mean(at(c.C[1]).P, at(c.C[3]).P));
    t.Triangles.push_back(first ? std::array<int, 3>{ 0, 1, 2 } : std::array<int, 3>{ 1, 2, 3 });
    t.Triangles.push_back(first ? std::array<int, 3>{ 0, 2, 3 } : std::array<int, 3>{ 1, 3, 0 });
  }
  else
  {
    ClipEars(t.Vertices, t.Triangles);
  }
  return t;
}

// Checks every triangle of the domain's leaves at its edge midpoints and centroid; a leaf with
// a triangle farther from the limit than the tolerance becomes active again, split. True when
// some leaf was split. The domain's samples are evaluated in one call: away from regular
// patches, each call refines the face's neighbourhood anew.
bool AdaptiveTessellator::SplitOffTolerance(Domain& d)
{
  const size_t domain = static_cast<size_t>(&d - this->Domains.data());
  std::vector<Triangulation> triangulations;
  std::vector<size_t> first; // per leaf, its first sample: its vertices', then per triangle
  std::vector<subd::FaceSample> at; // its three edge midpoints and its centroid
  for (const Cell& c : d.Leaves)
  {
    triangulations.push_back(this->Triangulate(domain, c));
    const Triangulation& t = triangulations.back();
    first.push_back(at.size());
    const size_t vertices = at.size();
    for (const P2& v : t.Vertices)
    {
      at.push_back(this->SampleAt(d, v));
    }
    for (const std::array<int, 3>& tri : t.Triangles)
    {
      subd::FaceSample g = at[vertices + tri[0]];
      g.U = g.V = 0.0;
      for (int i = 0; i < 3; ++i)
      {
        const subd::FaceSample a = at[vertices + tri[i]], b = at[vertices + tri[(i + 1) % 3]];
        subd::FaceSample m = a;
        m.U = 0.5 * (a.U + b.U);
        m.V = 0.5 * (a.V + b.V);
        at.push_back(m);
        g.U += a.U / 3.0;
        g.V += a.V / 3.0;
      }
      at.push_back(g);
    }
  }
  std::vector<SurfacePoint> values;
  this->Evaluate(d, at, values);
  std::vector<Cell> kept;
  d.OffTolerance = 0;
  for (size_t l = 0; l < d.Leaves.size() && !this->Failed; ++l)
  {
    const Triangulation& t = triangulations[l];
    const SurfacePoint* corner = &values[first[l]];
    const SurfacePoint* check = corner + t.Vertices.size();
    bool off = false;
    for (const std::array<int, 3>& tri : t.Triangles)
    {
      Vec3 centroid{ { 0, 0, 0 } };
      for (int i = 0; i < 3; ++i)
      {
        off = off || Distance(check[i], Mean(corner[tri[i]].P, corner[tri[(i + 1) % 3]].P)) > this->Settings.Tolerance;
        for (int j = 0; j < 3; ++j)
        {
          centroid[j] += corner[tri[i]].P[j] / 3.0;
        }
      }
      off = off || Distance(check[3], centroid) > this->Settings.Tolerance;
      check += 4;
    }
    const Cell& c = d.Leaves[l];
    const int allowed = (c.Depth[0] < d.MaxDepth ? SplitU : 0) | (c.Depth[1] < d.MaxDepth ? SplitV : 0);
    if (off && allowed != NoSplit)
    {
      const std::vector<Cell> children = Children(c, allowed);
      d.Active.insert(d.Active.end(), children.begin(), children.end());
    }
    else
    {
      d.OffTolerance += off ? static_cast<long long>(t.Triangles.size()) : 0;
      kept.push_back(c);
    }
  }
  d.Leaves.swap(kept);
  this->NumCells += static_cast<long long>(d.Active.size());
  return !d.Active.empty();
}

// The output: one point per key (owned by the first domain that meets it), the triangles.
void AdaptiveTessellator::Emit(vtkSubDLimitSamples& samples) const
{
  std::unordered_map<Key, vtkIdType, KeyHash> ids;
  for (size_t i = 0; i < this->Domains.size(); ++i)
  {
    const Domain& d = this->Domains[i];
    if (samples.Grids.empty() || samples.Grids.back().Face != d.Face)
    {
      samples.Grids.push_back({ d.Face, {}, {} });
    }
    vtkSubDFaceSamples& grid = samples.Grids.back();
    for (const Cell& c : d.Leaves)
    {
      const Triangulation t = this->Triangulate(i, c);
      std::vector<vtkIdType> vertexIds;
      for (const P2& v : t.Vertices)
      {
        auto found = ids.emplace(this->KeyOf(i, v), samples.Count);
        if (found.second)
        {
          grid.Owned.push_back(this->SampleAt(d, v));
          grid.OwnedIds.push_back(samples.Count++);
        }
        vertexIds.push_back(found.first->second);
      }
      for (const std::array<int, 3>& tri : t.Triangles)
      {
        const vtkIdType cell[3] = { vertexIds[tri[0]], vertexIds[tri[1]], vertexIds[tri[2]] };
        samples.Cells->InsertNextCell(3, cell);
        samples.CellFace->InsertNextValue(this->Cage.FaceCell[d.Face]);
      }
    }
  }
}

bool AdaptiveTessellator::Run(const std::vector<subd::Index>& faces, vtkSubDLimitSamples& samples,
  vtkSubDAdaptiveResult& result, std::string& error)
{
  this->MakeDomains(faces);
  bool splitAgain = this->RefineAll();
  while (splitAgain && !this->Failed)
  {
    this->RecordPresence();
    splitAgain = false;
    if (this->Settings.FaceLevels.empty() && !getenv("NOVERIFY"))
    {
      std::atomic<bool> split{ false };
      vtkSMPTools::For(0, static_cast<vtkIdType>(this->Domains.size()), [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType i = begin; i < end && !this->Failed; ++i)
        {
          if (this->SplitOffTolerance(this->Domains[i]))
          {
            split = true;
          }
        }
      });
      splitAgain = split && this->RefineAll();
    }
  }
  if (this->Failed)
  {
    error = this->Error;
    return false;
  }
  result.NumTrianglesOffTolerance = 0;
  for (const Domain& d : this->Domains)
  {
    result.NumTrianglesOffTolerance += d.OffTolerance;
  }
  this->Emit(samples);
  return true;
}
}

bool vtkSubDTessellateAdaptive(const vtkSubDCage& cage, const subd::LimitEvaluator& evaluator, bool quads,
  const std::vector<subd::Index>& faces, const vtkSubDAdaptiveSettings& settings, vtkSubDLimitSamples& samples,
  vtkSubDAdaptiveResult& result, std::string& error)
{
  AdaptiveTessellator tessellator(cage, evaluator, quads, settings);
  return tessellator.Run(faces, samples, result, error);
}
