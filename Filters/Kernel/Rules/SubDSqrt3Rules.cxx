#include "SubDSqrt3Rules.h"
#include "SubDFaceBlocks.h"
#include "SubDRowWriting.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>

namespace subd
{
double Sqrt3Alpha(Index n)
{
  const double pi = 3.14159265358979323846;
  return (4.0 - 2.0 * std::cos(2.0 * pi / n)) / 9.0;
}

bool IsSqrt3CurveEdge(const Level& level, Index e)
{
  const MeshTopology& topo = level.Topology;
  const Index faces = topo.GetEdgeFaces(e).size();
  return faces == 1 || (faces == 2 && !topo.GetEdgeTag(e).NonManifold && IsSharp(level.EdgeSharpness[e]));
}

Index Sqrt3CurveNeighbour(const Level& level, Index v, Index other)
{
  const MeshTopology& topo = level.Topology;
  Index found = v, count = 0;
  for (Index e : topo.GetVertexEdges(v))
  {
    if (IsSqrt3CurveEdge(level, e))
    {
      ++count;
      const Index w = topo.GetOtherEndpoint(e, v);
      if (w != other)
      {
        found = w;
      }
    }
  }
  return count == 2 ? found : v;
}

namespace
{
// In even steps, the edge each triangle trisects: every curve edge whose triangles trisect
// nothing else yet, in edge order. Empty when no triangle trisects one (every odd step, and
// every step of a mesh without boundary or crease, told without a serial pass over its
// edges): a per-face array would be most of a large step's scratch, nearly all InvalidIndex.
std::vector<Index> ChooseTrisectedEdges(const Level& level, bool evenStep, bool creasesInside)
{
  const MeshTopology& topo = level.Topology;
  std::vector<Index> trisected;
  if (!evenStep || (topo.GetNumBoundaryEdges() == 0 && !creasesInside))
  {
    return trisected;
  }
  for (Index e = 0; e < topo.GetNumEdges(); ++e)
  {
    if (!IsSqrt3CurveEdge(level, e))
    {
      continue;
    }
    if (trisected.empty())
    {
      trisected.assign(static_cast<size_t>(topo.GetNumFaces()), InvalidIndex);
    }
    const IndexSpan ef = topo.GetEdgeFaces(e);
    bool free = true;
    for (Index f : ef)
    {
      free = free && trisected[f] == InvalidIndex;
    }
    if (free)
    {
      for (Index f : ef)
      {
        trisected[f] = e;
      }
    }
  }
  return trisected;
}
}

Sqrt3VertexRule ClassifySqrt3Vertex(const Level& level, Index v, bool evenStep, bool creasesInside)
{
  const MeshTopology& topo = level.Topology;
  const VertexTag tag = topo.GetVertexTag(v);
  const Index faces = topo.GetVertexFaces(v).size();
  if (tag.NonManifold || faces == 0 || IsSharp(level.VertexSharpness[v]))
  {
    return Sqrt3VertexRule::Fixed;
  }
  Index curves = 0;
  if (creasesInside || tag.Boundary) // else its curve edges would be boundary edges: none
  {
    for (Index e : topo.GetVertexEdges(v))
    {
      curves += IsSqrt3CurveEdge(level, e);
    }
  }
  if (!tag.Boundary && curves < 2 && faces == topo.GetVertexEdges(v).size())
  {
    return Sqrt3VertexRule::Relax;
  }
  return evenStep && curves == 2 ? Sqrt3VertexRule::Curve : Sqrt3VertexRule::Fixed;
}

bool HasSqrt3InteriorCurveEdge(const Level& level, const ParallelFor& parallelFor)
{
  const MeshTopology& topo = level.Topology;
  std::atomic<bool> found{ false };
  parallelFor(0, topo.GetNumEdges(), [&](Index begin, Index end) {
    bool here = false;
    for (Index e = begin; e < end && !here; ++e)
    {
      // The cheap test first: a curve edge between two triangles is a sharp one.
      here = IsSharp(level.EdgeSharpness[e]) && topo.GetEdgeFaces(e).size() == 2 && IsSqrt3CurveEdge(level, e);
    }
    if (here)
    {
      found = true;
    }
  });
  return found;
}

namespace
{
// Whether the step from `parent` (making level Depth + 1) is an even one (see the header).
bool IsEvenStep(const Level& parent)
{
  return (parent.Depth % 2) == 1;
}

// The child points of one step (see the header): centroids, old vertices, trisection points.
// Where no triangle trisects an edge, its per-face and per-edge tables stay empty: every
// face then has the centroid of its own number and no edge has trisection points.
class Sqrt3Points
{
public:
  Index FirstVertexPoint = 0;
  Index NumPoints = 0;
  bool CreasesInside = false; // HasSqrt3InteriorCurveEdge(parent), which the rows ask too

  Sqrt3Points(const Level& parent, bool evenStep, const ParallelFor& parallelFor)
    : CreasesInside(HasSqrt3InteriorCurveEdge(parent, parallelFor))
    , TrisectedEdges(ChooseTrisectedEdges(parent, evenStep, this->CreasesInside))
  {
    const MeshTopology& topo = parent.Topology;
    const Index numFaces = topo.GetNumFaces();
    if (this->TrisectedEdges.empty())
    {
      this->FirstVertexPoint = numFaces;
      this->NumPoints = numFaces + topo.GetNumVertices();
      return;
    }
    this->CentroidPoints.assign(static_cast<size_t>(numFaces), InvalidIndex);
    for (Index f = 0; f < numFaces; ++f)
    {
      if (this->TrisectedEdges[f] == InvalidIndex)
      {
        this->CentroidPoints[f] = this->NumPoints++;
      }
    }
    this->FirstVertexPoint = this->NumPoints;
    this->NumPoints += topo.GetNumVertices();
    this->FirstEdgePoints.assign(static_cast<size_t>(topo.GetNumEdges()), InvalidIndex);
    for (Index f = 0; f < numFaces; ++f)
    {
      const Index e = this->TrisectedEdges[f];
      if (e != InvalidIndex && this->FirstEdgePoints[e] == InvalidIndex)
      {
        this->FirstEdgePoints[e] = this->NumPoints;
        this->NumPoints += 2;
      }
    }
  }
  /// Whether some triangle trisects an edge instead of getting a centroid.
  bool AnyTrisected() const { return !this->TrisectedEdges.empty(); }
  /// The edge face f trisects, or InvalidIndex.
  Index TrisectedEdge(Index f) const { return this->TrisectedEdges.empty() ? InvalidIndex : this->TrisectedEdges[f]; }
  /// Face f's centroid point, or InvalidIndex for a trisecting face.
  Index CentroidPoint(Index f) const { return this->CentroidPoints.empty() ? f : this->CentroidPoints[f]; }
  /// The first of edge e's two trisection points, or InvalidIndex.
  Index FirstEdgePoint(Index e) const { return this->FirstEdgePoints.empty() ? InvalidIndex : this->FirstEdgePoints[e]; }
  // The trisection point of edge e next to its end v.
  Index TrisectionPoint(const MeshTopology& topo, Index e, Index v) const
  {
    return this->FirstEdgePoint(e) + (topo.GetEdgeVertices(e)[0] == v ? 0 : 1);
  }

private:
  std::vector<Index> TrisectedEdges; // per face (ChooseTrisectedEdges); empty: none
  std::vector<Index> CentroidPoints; // per face, InvalidIndex for a trisecting face; empty: f
  std::vector<Index> FirstEdgePoints; // per edge, InvalidIndex unless trisected; empty: none
};

// The sharpness a child inherits: each sharp edge's, decayed, on the child edges along it
// (from one end to the other, through its two trisection points where it has them), and each
// vertex's, decayed, on its vertex point. Gathered from the parent before the child's
// topology is built (the parent may go meanwhile: SplitSqrt3), set on it after.
struct Sqrt3InheritedSharpness
{
  struct Path
  {
    Index Points[4]; // a, x, x + 1, b; or a, b (Size 2)
    int Size;
    float Sharpness;
  };
  std::vector<Path> SharpEdges;
  LevelArray<float> VertexSharpness; // per parent vertex, decayed (a level array: its memory goes back when freed)
  Index FirstVertexPoint = 0;

  Sqrt3InheritedSharpness(const Level& parent, const Sqrt3Points& points)
    : FirstVertexPoint(points.FirstVertexPoint)
  {
    const MeshTopology& topo = parent.Topology;
    for (Index e = 0; e < topo.GetNumEdges(); ++e)
    {
      if (!IsSharp(parent.EdgeSharpness[e]))
      {
        continue;
      }
      const Index a = points.FirstVertexPoint + topo.GetEdgeVertices(e)[0];
      const Index b = points.FirstVertexPoint + topo.GetEdgeVertices(e)[1];
      const Index x = points.FirstEdgePoint(e);
      const float sharpness = DecaySharpness(parent.EdgeSharpness[e]);
      this->SharpEdges.push_back(x == InvalidIndex ? Path{ { a, b, 0, 0 }, 2, sharpness }
                                                   : Path{ { a, x, x + 1, b }, 4, sharpness });
    }
    this->VertexSharpness.resize(parent.VertexSharpness.size());
    std::transform(parent.VertexSharpness.begin(), parent.VertexSharpness.end(), this->VertexSharpness.begin(),
      [](float s) { return DecaySharpness(s); });
  }

  void SetOn(Level& child) const
  {
    const MeshTopology& childTopo = child.Topology;
    for (const Path& path : this->SharpEdges)
    {
      for (int k = 0; k + 1 < path.Size; ++k)
      {
        const Index edge = childTopo.FindEdge(path.Points[k], path.Points[k + 1]);
        if (edge != InvalidIndex)
        {
          child.EdgeSharpness[edge] = path.Sharpness;
        }
      }
    }
    std::copy(this->VertexSharpness.begin(), this->VertexSharpness.end(),
      child.VertexSharpness.begin() + this->FirstVertexPoint);
  }
};

// The rows of one step, numbered like Sqrt3Points, written one at a time (SubDRowWriting.h).
// What the rows need beyond the parent's topology is worked out once, when the writer is
// made: each vertex's rule, the curve neighbours of the few curve vertices and trisected edges.
class Sqrt3RowWriter
{
public:
  Sqrt3RowWriter(const Level& parent, const ParallelFor& parallelFor)
    : Sqrt3RowWriter(parent, Sqrt3Points(parent, IsEvenStep(parent), parallelFor), parallelFor)
  {
  }
  Sqrt3RowWriter(const Level& parent, const Sqrt3Points& points, const ParallelFor& parallelFor)
    : Topo(parent.Topology)
    , NumVertices(parent.Topology.GetNumVertices())
    , FirstVertexPoint(points.FirstVertexPoint)
    , FirstTrisectionPoint(points.FirstVertexPoint + parent.Topology.GetNumVertices())
    , NumPoints(points.NumPoints)
    , Rules(static_cast<size_t>(this->NumVertices))
  {
    const bool evenStep = IsEvenStep(parent);
    const bool creasesInside = points.CreasesInside;
    parallelFor(0, this->NumVertices, [&](Index begin, Index end) {
      for (Index v = begin; v < end; ++v)
      {
        this->Rules[v] = ClassifySqrt3Vertex(parent, v, evenStep, creasesInside);
      }
    });
    for (Index v = 0; v < this->NumVertices; ++v)
    {
      if (this->Rules[v] == Sqrt3VertexRule::Relax)
      {
        this->MaxRowSize = std::max(this->MaxRowSize, 1 + this->Topo.GetVertexEdges(v).size());
      }
      else if (this->Rules[v] == Sqrt3VertexRule::Curve)
      {
        if (this->CurveSlot.empty())
        {
          this->CurveSlot.assign(static_cast<size_t>(this->NumVertices), InvalidIndex);
        }
        const Index p = Sqrt3CurveNeighbour(parent, v, InvalidIndex);
        this->CurveSlot[v] = static_cast<Index>(this->CurveEnds.size());
        this->CurveEnds.push_back({ p, Sqrt3CurveNeighbour(parent, v, p) });
      }
    }
    const Index numFaces = points.AnyTrisected() ? this->Topo.GetNumFaces() : 0;
    for (Index f = 0; f < numFaces; ++f)
    {
      const Index e = points.TrisectedEdge(f);
      if (e != InvalidIndex && points.FirstEdgePoint(e) == this->FirstTrisectionPoint + 2 * this->NumTrisections())
      {
        const Index a = this->Topo.GetEdgeVertices(e)[0], b = this->Topo.GetEdgeVertices(e)[1];
        this->Trisections.push_back({ a, b, Sqrt3CurveNeighbour(parent, a, b), Sqrt3CurveNeighbour(parent, b, a) });
      }
    }
    if (points.FirstVertexPoint != this->Topo.GetNumFaces()) // some faces trisect an edge instead of a centroid
    {
      for (Index f = 0; f < numFaces; ++f)
      {
        if (points.CentroidPoint(f) != InvalidIndex)
        {
          this->CentroidFace.push_back(f);
        }
      }
    }
    for (Index n = 1; n < MaxTabulatedValence; ++n)
    {
      this->Alphas[n] = Sqrt3Alpha(n);
    }
  }

  Index GetNumParents() const { return this->NumVertices; }
  Index GetNumRows() const { return this->NumPoints; }
  std::vector<Index> GetBlockEnds() const { return { this->NumPoints }; }
  Index GetMaxRowSize() const { return this->MaxRowSize; }

  Index WriteRow(Index row, Index* src, double* wts) const
  {
    RowEntries entries{ src, wts, this->NumVertices };
    if (this->VisitSmoothRow(row, entries))
    {
      return entries.Size;
    }
    if (row < this->FirstTrisectionPoint)
    {
      const Index v = row - this->FirstVertexPoint;
      if (this->Rules[v] == Sqrt3VertexRule::Curve)
      {
        const std::array<Index, 2>& ends = this->CurveEnds[this->CurveSlot[v]];
        entries.Parent(ends[0], 4.0 / 27.0);
        entries.Parent(v, 19.0 / 27.0);
        entries.Parent(ends[1], 4.0 / 27.0);
      }
      else
      {
        CopyMask(v, entries);
      }
      return entries.Size;
    }
    // a, b, p, q: the trisected edge's ends and their neighbours along the curve.
    const std::array<Index, 4>& t = this->Trisections[(row - this->FirstTrisectionPoint) / 2];
    const bool nearA = (row - this->FirstTrisectionPoint) % 2 == 0;
    entries.Parent(nearA ? t[2] : t[0], nearA ? 1.0 / 27.0 : 10.0 / 27.0);
    entries.Parent(nearA ? t[0] : t[1], 16.0 / 27.0);
    entries.Parent(nearA ? t[1] : t[3], nearA ? 10.0 / 27.0 : 1.0 / 27.0);
    return entries.Size;
  }

  // Centroids and relaxed vertices: Kobbelt's masks; false for the curve rules and fixed
  // vertices.
  template <typename Entries>
  bool VisitSmoothRow(Index row, Entries& entries) const
  {
    if (row < this->FirstVertexPoint)
    {
      CentroidMask(this->Topo.GetFaceVertices(this->CentroidFace.empty() ? row : this->CentroidFace[row]), entries);
      return true;
    }
    const Index v = row - this->FirstVertexPoint;
    if (row >= this->FirstTrisectionPoint || this->Rules[v] != Sqrt3VertexRule::Relax)
    {
      return false;
    }
    this->VisitRelaxedRow(v, [&](Index w, double weight) { entries.Parent(w, weight); });
    return true;
  }

private:
  // Calls visit(source, weight) for a relaxed vertex's row: itself, then its ring.
  template <typename Visit>
  void VisitRelaxedRow(Index v, Visit&& visit) const
  {
    const Index valence = this->Topo.GetVertexEdges(v).size();
    const double alpha = this->Alpha(valence);
    visit(v, 1.0 - alpha);
    this->Topo.ForEachRingVertex(v, [&](Index w) { visit(w, alpha / valence); });
  }

  Index NumTrisections() const { return static_cast<Index>(this->Trisections.size()); }
  // Kobbelt's alpha_n for the valences most meshes have, tabulated: the cosine would be most
  // of the cost of a row.
  double Alpha(Index n) const { return n < MaxTabulatedValence ? this->Alphas[n] : Sqrt3Alpha(n); }

  static constexpr Index MaxTabulatedValence = 16;
  const MeshTopology& Topo;
  Index NumVertices, FirstVertexPoint, FirstTrisectionPoint, NumPoints;
  Index MaxRowSize = 3;
  std::vector<Sqrt3VertexRule> Rules;            // per vertex
  std::vector<Index> CentroidFace;               // per centroid point; empty when every face has one
  std::vector<Index> CurveSlot;                  // per vertex: its CurveEnds (empty: no curve vertex)
  std::vector<std::array<Index, 2>> CurveEnds;   // the curve neighbours p, q of a curve vertex
  std::vector<std::array<Index, 4>> Trisections; // a, b, p, q per trisected edge, in point order
  double Alphas[MaxTabulatedValence] = {};
};

// Writes the child triangles of the parent's edges (flipped or kept), then of its faces
// (the middle triangle of a trisected one).
class Sqrt3FaceWriter
{
public:
  Sqrt3FaceWriter(const Level& parent, const Sqrt3Points& points)
    : Parent(parent)
    , Topo(parent.Topology)
    , Points(points)
  {
  }
  Index GetNumElements() const { return this->Topo.GetNumEdges() + this->Topo.GetNumFaces(); }

  void WriteBlock(Index begin, Index end, FaceBlock& out) const
  {
    const Index numEdges = this->Topo.GetNumEdges();
    for (Index element = begin; element < end; ++element)
    {
      if (element < numEdges)
      {
        this->WriteEdgeTriangles(element, out);
      }
      else
      {
        this->WriteMiddleTriangle(element - numEdges, out);
      }
    }
  }

private:
  Index VertexPoint(Index v) const { return this->Points.FirstVertexPoint + v; }
  Index Origin(Index f) const { return this->Parent.FaceOrigin[f]; }
  std::uint8_t Hole(Index f) const { return this->Parent.IsFaceHole(f); }

  // Edge e's ends (a, b) in the order triangle f runs them, from the triangle's corners
  // alone (found without the face offsets): the finest split runs without the faces' edges.
  void OrientedEnds(Index e, Index f, Index& a, Index& b) const
  {
    // Without branches (which corner, which way: coin tosses from edge to edge, see
    // OtherOfTwo): e runs forward in f when the corner after ev[0]'s is ev[1].
    static constexpr Index nextCorner[3] = { 1, 2, 0 };
    const Index* ev = this->Topo.GetEdgeVertices(e);
    const Index* fv = this->Topo.GetTriangleVertices(f);
    const Index i = PlaceInTriangle(fv, ev[0]);
    const Index backward = fv[nextCorner[i]] != ev[1];
    a = ev[backward];
    b = ev[1 - backward];
  }

  // The point an old edge e of face f is flipped to: the centroid, or in a triangle that
  // trisects another edge the trisection point next to the end the two edges share.
  Index Apex(Index f, Index e) const
  {
    const Index centroid = this->Points.CentroidPoint(f);
    if (centroid != InvalidIndex)
    {
      return centroid;
    }
    const Index t = this->Points.TrisectedEdge(f);
    const Index* ev = this->Topo.GetEdgeVertices(e);
    const Index* tv = this->Topo.GetEdgeVertices(t);
    const Index shared = (ev[0] == tv[0] || ev[0] == tv[1]) ? ev[0] : ev[1];
    return this->Points.TrisectionPoint(this->Topo, t, shared);
  }

  // Whether edge e is flipped (two triangles across it), or each of its faces keeps its
  // part next to it (KeepsPartNextTo).
  bool Flips(Index e) const { return !ActsAsBoundary(this->Parent, e); }
  // For an edge not flipped: whether face f keeps a triangle next to it (not when e is the
  // edge f trisects: its middle triangle comes with the face).
  bool KeepsPartNextTo(Index e, Index f) const { return e != this->Points.TrisectedEdge(f); }
  bool Trisects(Index f) const { return this->Points.TrisectedEdge(f) != InvalidIndex; }

  void WriteEdgeTriangles(Index e, FaceBlock& out) const
  {
    const IndexSpan ef = this->Topo.GetEdgeFaces(e);
    if (this->Flips(e))
    {
      Index f1 = ef[0], f2 = ef[1], a, b;
      this->OrientedEnds(e, f1, a, b);
      const std::uint8_t hole = this->Hole(f1) && this->Hole(f2);
      out.AddTriangle(this->VertexPoint(a), this->Apex(f2, e), this->Apex(f1, e), this->Origin(f1), hole);
      out.AddTriangle(this->VertexPoint(b), this->Apex(f1, e), this->Apex(f2, e), this->Origin(f2), hole);
      return;
    }
    // Not flipped (boundary, crease, non-manifold): each face keeps its part next to e,
    // unless e is the edge the face trisects (its middle triangle comes with the face).
    for (Index f : ef)
    {
      if (this->KeepsPartNextTo(e, f))
      {
        Index a, b;
        this->OrientedEnds(e, f, a, b);
        out.AddTriangle(this->VertexPoint(a), this->VertexPoint(b), this->Apex(f, e), this->Origin(f), this->Hole(f));
      }
    }
  }

  // Triangles (a, b, m) trisecting (a, b): the middle triangle (x_a, x_b, m); the triangles
  // (a, x_a, m) and (x_b, b, m) come from the flips of (m, a) and (b, m).
  void WriteMiddleTriangle(Index f, FaceBlock& out) const
  {
    if (!this->Trisects(f))
    {
      return;
    }
    const Index e = this->Points.TrisectedEdge(f);
    Index a, b;
    this->OrientedEnds(e, f, a, b);
    const Index m = this->Topo.GetTriangleOppositeVertex(f, e);
    out.AddTriangle(this->Points.TrisectionPoint(this->Topo, e, a), this->Points.TrisectionPoint(this->Topo, e, b),
      this->VertexPoint(m), this->Origin(f), this->Hole(f));
  }

  const Level& Parent;
  const MeshTopology& Topo;
  const Sqrt3Points& Points;
};

// The child level of one step (without its rows).
Level SplitWithPoints(const Level& parent, const Sqrt3Points& points, ChildTopology depth, const ParallelFor& parallelFor)
{
  const Sqrt3FaceWriter writer(parent, points);
  EmittedFaces faces = EmitFacesInParallel(writer.GetNumElements(), parallelFor,
    [&writer](Index begin, Index end, FaceBlock& block) { writer.WriteBlock(begin, end, block); });
  Level child;
  child.FaceOrigin = std::move(faces.Origins);
  child.FaceIsHole = std::move(faces.Holes);
  SetChildTopology(parent, child, points.NumPoints, std::move(faces.Offsets), std::move(faces.Vertices), depth, parallelFor);
  if (depth == ChildTopology::Full)
  {
    Sqrt3InheritedSharpness(parent, points).SetOn(child);
  }
  return child;
}
}

LevelRefinement RefineSqrt3(const Level& parent, ChildTopology depth, const ParallelFor& parallelFor)
{
  const Sqrt3Points points(parent, IsEvenStep(parent), parallelFor);
  LevelRefinement result;
  result.Stencils = WriteStencilTable(Sqrt3RowWriter(parent, points, parallelFor), parallelFor);
  result.Child = SplitWithPoints(parent, points, depth, parallelFor);
  return result;
}

Level SplitSqrt3(const Level& parent, ChildTopology depth, const ParallelFor& parallelFor)
{
  return SplitWithPoints(parent, Sqrt3Points(parent, IsEvenStep(parent), parallelFor), depth, parallelFor);
}

std::shared_ptr<const RowSource> MakeSqrt3RowSource(std::shared_ptr<const Level> parent, const ParallelFor& parallelFor)
{
  return std::make_shared<WrittenRows<Sqrt3RowWriter>>(std::move(parent), parallelFor);
}

Index Sqrt3FirstVertexPoint(const Level& parent)
{
  return Sqrt3Points(parent, IsEvenStep(parent), SerialFor).FirstVertexPoint;
}
}
