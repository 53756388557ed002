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
  /// A leaf: a quad's triangles split it along corners 1-3 (else 0-2) when it has no points
  /// of finer cells on its sides; whether its triangles are farther than the tolerance from
  /// the surface (at the deepest level), as last checked with `CheckedVertices` vertices.
  bool SecondDiagonal = false;
  bool Off = false;
  size_t CheckedVertices = 0;
  bool Recheck = false; ///< its triangles' check found one off, and it can split: to split again
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
};

/// A cell's triangles: its corners and the points of finer cells on its sides, in order
/// around it, and triangles through them.
struct Triangulation
{
  std::vector<P2> Vertices;
  std::vector<std::array<int, 3>> Triangles;
};

/// The domains of one face of the cage (several for a Catmull-Clark polygon that is not a
/// quad): evaluated together, so that the face's neighbourhood is refined once per batch.
struct FaceGroup
{
  size_t First, Last;
};

/// Samples of one face to evaluate in one call: points of its domains' grids, kept in their
/// Known (a point two of the face's domains share, evaluated once for both), and loose points
/// (centroids, midpoints of fan edges) read back by index.
struct Batch
{
  using Destination = std::pair<Domain*, std::uint64_t>;
  std::vector<subd::FaceSample> At;
  std::vector<Destination> Grid; ///< per sample: where a grid point goes (nullptr: loose)
  std::vector<std::pair<size_t, Destination>> Copies; ///< a sample that goes to a second domain too
  std::unordered_map<Key, size_t, KeyHash> Shared;     ///< the samples of points on domain sides
  std::vector<SurfacePoint> Values;

  size_t AddLoose(const subd::FaceSample& s)
  {
    this->At.push_back(s);
    this->Grid.emplace_back(nullptr, 0);
    return this->At.size() - 1;
  }
  static subd::FaceSample GridSample(const Domain& d, P2 p)
  {
    subd::FaceSample s;
    s.U = static_cast<double>(p.X) / N;
    s.V = static_cast<double>(p.Y) / N;
    s.SubFace = d.Sub;
    return s;
  }
};

/// The parameters of the centroid of the triangle a, b, c of domain d.
subd::FaceSample CentroidSample(const Domain& d, P2 a, P2 b, P2 c)
{
  subd::FaceSample s;
  s.U = (static_cast<double>(a.X) + b.X + c.X) / (3.0 * N);
  s.V = (static_cast<double>(a.Y) + b.Y + c.Y) / (3.0 * N);
  s.SubFace = d.Sub;
  return s;
}

Vec3 Centroid(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return { { (a[0] + b[0] + c[0]) / 3.0, (a[1] + b[1] + c[1]) / 3.0, (a[2] + b[2] + c[2]) / 3.0 } };
}

/// A leaf whose triangles are to be checked, and where its check samples start in the batch:
/// per triangle its three edge midpoints and its centroid.
struct LeafCheck
{
  size_t DomainIndex, LeafIndex;
  Triangulation Triangles;
  size_t First;
};

/// The ways a cell may still split: along u and v while below its domain's deepest level.
int AllowedSplit(const Domain& d, const Cell& c)
{
  return (c.Depth[0] < d.MaxDepth ? SplitU : 0) | (c.Depth[1] < d.MaxDepth ? SplitV : 0);
}

/// A quad's two triangles along either diagonal: (0 1 2, 0 2 3), or (1 2 3, 1 3 0).
constexpr int QuadTriangles[2][2][3] = { { { 0, 1, 2 }, { 0, 2, 3 } }, { { 1, 2, 3 }, { 1, 3, 0 } } };

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
  void Refine(const FaceGroup& group);
  int Judge(const Domain& d, Cell& c, const SurfacePoint* centroids) const;
  void Evaluate(subd::Index face, Batch& batch);
  /// Asks `batch` for the surface at grid point p of the domain, unless known.
  void Request(Batch& batch, size_t domain, P2 p);
  /// The surface at every cage vertex of `faces`, once each (VertexPoints).
  bool EvaluateCageVertices(const std::vector<subd::Index>& faces);
  void RecordPresence();
  Triangulation Triangulate(size_t domain, const Cell& c) const;
  void AddHanging(size_t domain, P2 a, P2 b, std::vector<P2>& out) const;
  std::vector<LeafCheck> GatherChecks(const FaceGroup& group, Batch& batch);
  bool Strays(const LeafCheck& check, const SurfacePoint* sample) const;
  bool SplitOffTolerance(const FaceGroup& group);
  long long Emit(vtkSubDLimitSamples& samples) const;

  /// The point's key; `sides`: one per side of a seam (the output's), else one per place.
  Key KeyOf(size_t domain, P2 p, bool sides = false) const;
  Key EdgePoint(subd::Index f, subd::Index k, Coord t, bool sides) const;
  bool Fail(const std::string& message);

  const vtkSubDCage& Cage;
  const subd::MeshTopology& Topo;
  const subd::LimitEvaluator& Evaluator;
  const bool Quads;
  const vtkSubDAdaptiveSettings& Settings;
  std::vector<Domain> Domains;
  std::vector<FaceGroup> Groups;
  std::vector<SurfacePoint> VertexPoints; ///< per cage vertex: shared by all its faces' domains
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

Key AdaptiveTessellator::EdgePoint(subd::Index f, subd::Index k, Coord t, bool sides) const
{
  const subd::IndexSpan fv = this->Topo.GetFaceVertices(f);
  const subd::Index n = static_cast<subd::Index>(fv.size());
  k = (k + n) % n;
  const subd::Index next = (k + 1) % n;
  if (t == 0)
    return { VertexKey, fv[k], sides ? this->Cage.SeamSideOfCorner(f, k) : 0, 0 };
  if (t == 2 * N)
    return { VertexKey, fv[next], sides ? this->Cage.SeamSideOfCorner(f, next) : 0, 0 };
  const subd::Index e = this->Topo.GetFaceEdges(f)[k];
  const bool forward = this->Topo.GetEdgeVertices(e)[0] == fv[k];
  return { EdgeKey, e, forward ? t : 2 * N - t, sides ? this->Cage.SeamSideOfEdge(f, k) : 0 };
}

Key AdaptiveTessellator::KeyOf(size_t domain, P2 p, bool sides) const
{
  const Domain& d = this->Domains[domain];
  const Key inside{ InsideKey, static_cast<std::int64_t>(domain), p.X, p.Y };
  switch (d.Kind)
  {
    case DomainKind::Quad:
      if (p.Y == 0)
        return this->EdgePoint(d.Face, 0, 2 * p.X, sides);
      if (p.X == N)
        return this->EdgePoint(d.Face, 1, 2 * p.Y, sides);
      if (p.Y == N)
        return this->EdgePoint(d.Face, 2, 2 * (N - p.X), sides);
      if (p.X == 0)
        return this->EdgePoint(d.Face, 3, 2 * (N - p.Y), sides);
      return inside;
    case DomainKind::Triangle:
      if (p.Y == 0)
        return this->EdgePoint(d.Face, 0, 2 * p.X, sides);
      if (p.X + p.Y == N)
        return this->EdgePoint(d.Face, 1, 2 * p.Y, sides);
      if (p.X == 0)
        return this->EdgePoint(d.Face, 2, 2 * (N - p.Y), sides);
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
        return this->EdgePoint(d.Face, d.Sub, p.X, sides);
      if (p.X == 0)
        return this->EdgePoint(d.Face, d.Sub - 1, 2 * N - p.Y, sides);
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
      maxDepth, std::min(std::max(level - offset, 0), maxDepth), {}, {}, {} };
    const Cell root = this->Quads ? Cell{ { P2{ 0, 0 }, P2{ N, 0 }, P2{ N, N }, P2{ 0, N } }, 4, { 0, 0 } }
                                  : Cell{ { P2{ 0, 0 }, P2{ N, 0 }, P2{ 0, N }, P2{} }, 3, { 0, 0 } };
    d.Active.push_back(root);
    this->Groups.push_back({ this->Domains.size(), this->Domains.size() + (corners ? n : 1) });
    for (subd::Index k = 0; k < (corners ? n : 1); ++k)
    {
      d.Sub = k;
      this->Domains.push_back(d);
    }
  }
  this->NumCells += static_cast<long long>(this->Domains.size());
}

void AdaptiveTessellator::Evaluate(subd::Index face, Batch& batch)
{
  std::vector<subd::LimitStencil> stencils;
  std::string error;
  batch.Values.assign(batch.At.size(), SurfacePoint());
  if (batch.At.empty())
  {
    return;
  }
  if (!this->Evaluator.EvaluateFace(face, batch.At, stencils, error, 3)) // positions and tangents
  {
    this->Fail("cell " + std::to_string(this->Cage.FaceCell[face]) + ": " + error);
    return;
  }
  for (size_t i = 0; i < batch.At.size(); ++i)
  {
    SurfacePoint& s = batch.Values[i];
    double du[3], dv[3];
    stencils[i].Apply(stencils[i].Weights, subd::PatchValue, this->Cage.Points.data(), 3, s.P.data());
    stencils[i].Apply(stencils[i].Weights, subd::PatchDu, this->Cage.Points.data(), 3, du);
    stencils[i].Apply(stencils[i].Weights, subd::PatchDv, this->Cage.Points.data(), 3, dv);
    s.Normal = { { du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2], du[0] * dv[1] - du[1] * dv[0] } };
    const double length = std::sqrt(s.Normal[0] * s.Normal[0] + s.Normal[1] * s.Normal[1] + s.Normal[2] * s.Normal[2]);
    const double scale =
      std::sqrt((du[0] * du[0] + du[1] * du[1] + du[2] * du[2]) * (dv[0] * dv[0] + dv[1] * dv[1] + dv[2] * dv[2]));
    s.HasNormal = length > 1e-12 * scale && length > 0.0;
    for (double& x : s.Normal)
    {
      x = s.HasNormal ? x / length : 0.0;
    }
    if (batch.Grid[i].first)
    {
      batch.Grid[i].first->Known[batch.Grid[i].second] = s;
    }
  }
  for (const auto& copy : batch.Copies)
  {
    copy.second.first->Known[copy.second.second] = batch.Values[copy.first];
  }
}

void AdaptiveTessellator::Request(Batch& batch, size_t domain, P2 p)
{
  Domain& d = this->Domains[domain];
  auto reserved = d.Known.emplace(Pack(p), SurfacePoint());
  if (!reserved.second)
  {
    return;
  }
  const Key key = this->KeyOf(domain, p);
  if (key[0] == VertexKey)
  {
    reserved.first->second = this->VertexPoints[key[1]];
    return;
  }
  if (key[0] != InsideKey)
  {
    auto shared = batch.Shared.emplace(key, batch.At.size());
    if (!shared.second)
    {
      batch.Copies.emplace_back(shared.first->second, Batch::Destination(&d, Pack(p)));
      return;
    }
  }
  batch.At.push_back(Batch::GridSample(d, p));
  batch.Grid.emplace_back(&d, Pack(p));
}

bool AdaptiveTessellator::EvaluateCageVertices(const std::vector<subd::Index>& faces)
{
  // Each vertex from the first of the faces that has it, at that face's corner.
  std::vector<std::pair<subd::Index, subd::Index>> from(static_cast<size_t>(this->Topo.GetNumVertices()),
    { subd::InvalidIndex, 0 });
  for (subd::Index f : faces)
  {
    const subd::IndexSpan fv = this->Topo.GetFaceVertices(f);
    for (subd::Index k = 0; k < static_cast<subd::Index>(fv.size()); ++k)
    {
      from[fv[k]] = from[fv[k]].first == subd::InvalidIndex ? std::make_pair(f, k) : from[fv[k]];
    }
  }
  this->VertexPoints.assign(from.size(), SurfacePoint());
  vtkSMPTools::For(0, static_cast<vtkIdType>(from.size()), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType v = begin; v < end && !this->Failed; ++v)
    {
      if (from[v].first == subd::InvalidIndex)
      {
        continue;
      }
      Batch batch;
      batch.AddLoose(subd::LimitEvaluator::CornerSample(this->Topo.GetFaceSize(from[v].first), from[v].second,
        this->Quads));
      this->Evaluate(from[v].first, batch);
      this->VertexPoints[v] = batch.Values[0];
    }
  });
  return !this->Failed;
}

// How a cell splits. Selective: both ways until the face's level. Adaptive: a quad across u
// when a side along u strays from the surface, across v likewise, both ways when only its
// diagonal or its triangles' centroids do (a twist); a triangle into four when any side or its
// centroid strays. A leaf keeps the diagonal nearer the surface and whether it strays.
// `centroids`: the surface at the centroids of the cell's triangles (a quad's: QuadTriangles).
int AdaptiveTessellator::Judge(const Domain& d, Cell& c, const SurfacePoint* centroids) const
{
  const int allowed = AllowedSplit(d, c);
  if (!this->Settings.FaceLevels.empty())
  {
    return c.Depth[0] < d.TargetDepth ? allowed : NoSplit;
  }
  auto at = [&d](P2 p) -> const SurfacePoint& { return d.Known.at(Pack(p)); };
  auto sideError = [&](int i) {
    const P2 a = c.C[i], b = c.C[(i + 1) % c.NumCorners];
    return Distance(at(Mid(a, b)), Mean(at(a).P, at(b).P));
  };
  auto centroidError = [&](const int (&t)[3], const SurfacePoint& centroid) {
    return Distance(centroid, Centroid(at(c.C[t[0]]).P, at(c.C[t[1]]).P, at(c.C[t[2]]).P));
  };
  const double tolerance = this->Settings.Tolerance;
  int wanted = NoSplit;
  if (c.NumCorners == 3)
  {
    const int all[3] = { 0, 1, 2 };
    const double error = std::max({ sideError(0), sideError(1), sideError(2), centroidError(all, centroids[0]) });
    wanted = error > tolerance ? SplitBoth : NoSplit;
  }
  else
  {
    const SurfacePoint& centre = at(Mid(c.C[0], c.C[2]));
    double diagonal[2];
    for (int k = 0; k < 2; ++k)
    {
      const int a = QuadTriangles[k][0][0], b = QuadTriangles[k][0][2];
      diagonal[k] = std::max({ Distance(centre, Mean(at(c.C[a]).P, at(c.C[b]).P)),
        centroidError(QuadTriangles[k][0], centroids[2 * k]), centroidError(QuadTriangles[k][1], centroids[2 * k + 1]) });
    }
    c.SecondDiagonal = diagonal[1] < diagonal[0];
    wanted = (std::max(sideError(0), sideError(2)) > tolerance ? SplitU : 0) |
      (std::max(sideError(1), sideError(3)) > tolerance ? SplitV : 0);
    if (wanted == NoSplit && diagonal[c.SecondDiagonal ? 1 : 0] > tolerance)
    {
      wanted = SplitBoth;
    }
  }
  c.Off = wanted != NoSplit;
  c.CheckedVertices = static_cast<size_t>(c.NumCorners);
  return wanted & allowed;
}

// Splits the active cells of a face's domains, level by level, until none wants to split:
// per level one evaluation of their corners, side midpoints, centres and triangles' centroids.
void AdaptiveTessellator::Refine(const FaceGroup& group)
{
  const bool adaptive = this->Settings.FaceLevels.empty();
  std::vector<Cell> next;
  for (bool active = true; active && !this->Failed;)
  {
    Batch batch;
    std::vector<size_t> centroids; // per active cell, its first centroid sample
    for (size_t i = group.First; i < group.Last; ++i)
    {
      Domain& d = this->Domains[i];
      for (const Cell& c : d.Active)
      {
        const int n = c.NumCorners;
        for (int k = 0; k < n; ++k)
        {
          this->Request(batch, i, c.C[k]);
          this->Request(batch, i, Mid(c.C[k], c.C[(k + 1) % n]));
        }
        if (n == 4)
        {
          this->Request(batch, i, Mid(c.C[0], c.C[2]));
        }
        centroids.push_back(batch.At.size());
        for (int t = 0; adaptive && t < (n == 4 ? 4 : 1); ++t)
        {
          const int* v = n == 4 ? QuadTriangles[t / 2][t % 2] : nullptr;
          batch.AddLoose(n == 4 ? CentroidSample(d, c.C[v[0]], c.C[v[1]], c.C[v[2]])
                                : CentroidSample(d, c.C[0], c.C[1], c.C[2]));
        }
      }
    }
    this->Evaluate(this->Domains[group.First].Face, batch);
    active = false;
    size_t cell = 0;
    for (size_t i = group.First; i < group.Last && !this->Failed; ++i)
    {
      Domain& d = this->Domains[i];
      next.clear();
      for (Cell& c : d.Active)
      {
        const SurfacePoint* judged = batch.Values.data() + centroids[cell++];
        if (const int split = this->Judge(d, c, judged))
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
        this->Fail("the tessellation would need more than " +
          std::to_string(static_cast<long long>(this->Settings.MaximumCells)) +
          " cells, more than MaximumMemory allows: use a larger tolerance, a lower MaximumLevel, or a larger "
          "MaximumMemory");
      }
      d.Active.swap(next);
      active = active || !d.Active.empty();
    }
  }
}

bool AdaptiveTessellator::RefineAll()
{
  vtkSMPTools::For(0, static_cast<vtkIdType>(this->Groups.size()), [this](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end && !this->Failed; ++i)
    {
      this->Refine(this->Groups[i]);
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

// A cell with no point on its sides is one triangle, or a quad's two along the diagonal its
// judgement chose; otherwise its polygon with the points of its finer neighbours, cut into
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
    for (const auto& triangle : QuadTriangles[c.SecondDiagonal ? 1 : 0])
    {
      t.Triangles.push_back({ triangle[0], triangle[1], triangle[2] });
    }
  }
  else if (t.Vertices.size() == 3)
  {
    t.Triangles.push_back({ 0, 1, 2 });
  }
  else
  {
    ClipEars(t.Vertices, t.Triangles);
  }
  return t;
}

// The leaves of the face whose triangles were not checked with the points now on their sides,
// their vertices and check points asked of `batch`.
std::vector<LeafCheck> AdaptiveTessellator::GatherChecks(const FaceGroup& group, Batch& batch)
{
  std::vector<LeafCheck> checks;
  for (size_t i = group.First; i < group.Last; ++i)
  {
    const Domain& d = this->Domains[i];
    for (size_t l = 0; l < d.Leaves.size(); ++l)
    {
      Triangulation t = this->Triangulate(i, d.Leaves[l]);
      if (t.Vertices.size() == d.Leaves[l].CheckedVertices)
      {
        continue; // checked with these triangles (points on its sides are only ever added)
      }
      for (const P2& v : t.Vertices)
      {
        this->Request(batch, i, v);
      }
      const size_t first = batch.At.size();
      for (const std::array<int, 3>& tri : t.Triangles)
      {
        const P2 a = t.Vertices[tri[0]], b = t.Vertices[tri[1]], c = t.Vertices[tri[2]];
        for (const auto& edge : { std::make_pair(a, b), std::make_pair(b, c), std::make_pair(c, a) })
        {
          subd::FaceSample m = Batch::GridSample(d, edge.first);
          const subd::FaceSample other = Batch::GridSample(d, edge.second);
          m.U = 0.5 * (m.U + other.U);
          m.V = 0.5 * (m.V + other.V);
          batch.AddLoose(m);
        }
        batch.AddLoose(CentroidSample(d, a, b, c));
      }
      checks.push_back({ i, l, std::move(t), first });
    }
  }
  return checks;
}

// Whether a triangle of the check strays from the surface at an edge midpoint or its centroid
// (`sample`: per triangle those four).
bool AdaptiveTessellator::Strays(const LeafCheck& check, const SurfacePoint* sample) const
{
  const Domain& d = this->Domains[check.DomainIndex];
  auto at = [&d](P2 p) -> const Vec3& { return d.Known.at(Pack(p)).P; };
  const double tolerance = this->Settings.Tolerance;
  for (const std::array<int, 3>& tri : check.Triangles.Triangles)
  {
    const Vec3 &a = at(check.Triangles.Vertices[tri[0]]), &b = at(check.Triangles.Vertices[tri[1]]),
               &c = at(check.Triangles.Vertices[tri[2]]);
    if (Distance(sample[0], Mean(a, b)) > tolerance || Distance(sample[1], Mean(b, c)) > tolerance ||
      Distance(sample[2], Mean(c, a)) > tolerance || Distance(sample[3], Centroid(a, b, c)) > tolerance)
    {
      return true;
    }
    sample += 4;
  }
  return false;
}

// Checks the triangles of the face's leaves that have points of finer neighbours on their
// sides (the others were checked when judged) at their edge midpoints and centroids; a leaf
// with a triangle farther from the limit than the tolerance becomes active again, split. True
// when some leaf was split.
bool AdaptiveTessellator::SplitOffTolerance(const FaceGroup& group)
{
  Batch batch;
  const std::vector<LeafCheck> checks = this->GatherChecks(group, batch);
  this->Evaluate(this->Domains[group.First].Face, batch);
  for (const LeafCheck& check : checks)
  {
    Domain& d = this->Domains[check.DomainIndex];
    Cell& c = d.Leaves[check.LeafIndex];
    c.Off = this->Strays(check, batch.Values.data() + check.First);
    c.CheckedVertices = check.Triangles.Vertices.size();
    c.Recheck = c.Off && AllowedSplit(d, c) != NoSplit;
  }
  bool any = false;
  for (size_t i = group.First; i < group.Last; ++i)
  {
    Domain& d = this->Domains[i];
    std::vector<Cell> kept;
    for (const Cell& c : d.Leaves)
    {
      if (!c.Recheck)
      {
        kept.push_back(c);
        continue;
      }
      const std::vector<Cell> children = Children(c, AllowedSplit(d, c));
      d.Active.insert(d.Active.end(), children.begin(), children.end());
    }
    d.Leaves.swap(kept);
    this->NumCells += static_cast<long long>(d.Active.size());
    any = any || !d.Active.empty();
  }
  return any;
}

// The output: one point per key (owned by the first domain that meets it), the triangles.
// Returns how many are farther than the tolerance from the surface.
long long AdaptiveTessellator::Emit(vtkSubDLimitSamples& samples) const
{
  long long off = 0;
  std::unordered_map<Key, vtkIdType, KeyHash> ids, places; // per point, per place (a seam's sides share one)
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
        auto found = ids.emplace(this->KeyOf(i, v, true), samples.Count);
        if (found.second)
        {
          auto first = places.emplace(this->KeyOf(i, v), samples.Count);
          if (!first.second)
          {
            samples.SamePlace.emplace_back(samples.Count, first.first->second);
          }
          grid.Owned.push_back(Batch::GridSample(d, v));
          grid.OwnedIds.push_back(samples.Count++);
        }
        vertexIds.push_back(found.first->second);
      }
      off += c.Off ? static_cast<long long>(t.Triangles.size()) : 0;
      for (const std::array<int, 3>& tri : t.Triangles)
      {
        const vtkIdType cell[3] = { vertexIds[tri[0]], vertexIds[tri[1]], vertexIds[tri[2]] };
        samples.Cells->InsertNextCell(3, cell);
        samples.CellFace->InsertNextValue(this->Cage.FaceCell[d.Face]);
        samples.CellLevels.push_back(std::max(c.Depth[0], c.Depth[1]) + (d.Kind == DomainKind::CornerQuad ? 1 : 0));
      }
    }
  }
  return off;
}

bool AdaptiveTessellator::Run(const std::vector<subd::Index>& faces, vtkSubDLimitSamples& samples,
  vtkSubDAdaptiveResult& result, std::string& error)
{
  this->MakeDomains(faces);
  bool splitAgain = this->EvaluateCageVertices(faces) && this->RefineAll();
  while (splitAgain && !this->Failed)
  {
    this->RecordPresence();
    splitAgain = false;
    if (this->Settings.FaceLevels.empty())
    {
      std::atomic<bool> split{ false };
      vtkSMPTools::For(0, static_cast<vtkIdType>(this->Groups.size()), [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType i = begin; i < end && !this->Failed; ++i)
        {
          if (this->SplitOffTolerance(this->Groups[i]))
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
  result.NumTrianglesOffTolerance = this->Emit(samples);
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
