#include "SubDSqrt3Rules.h"
#include "SubDFaceBlocks.h"
#include "SubDSqrt3ChildTopology.h"

#include <algorithm>
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
// In even steps, the edge each triangle trisects (or InvalidIndex): every curve edge whose
// triangles trisect nothing else yet, in edge order.
std::vector<Index> ChooseTrisectedEdges(const Level& level, bool evenStep)
{
  const MeshTopology& topo = level.Topology;
  std::vector<Index> trisected(static_cast<size_t>(topo.GetNumFaces()), InvalidIndex);
  if (!evenStep)
  {
    return trisected;
  }
  for (Index e = 0; e < topo.GetNumEdges(); ++e)
  {
    if (!IsSqrt3CurveEdge(level, e))
    {
      continue;
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

Sqrt3VertexRule ClassifySqrt3Vertex(const Level& level, Index v, bool evenStep)
{
  const MeshTopology& topo = level.Topology;
  const VertexTag tag = topo.GetVertexTag(v);
  const Index faces = topo.GetVertexFaces(v).size();
  if (tag.NonManifold || faces == 0 || IsSharp(level.VertexSharpness[v]))
  {
    return Sqrt3VertexRule::Fixed;
  }
  Index curves = 0;
  for (Index e : topo.GetVertexEdges(v))
  {
    curves += IsSqrt3CurveEdge(level, e);
  }
  if (!tag.Boundary && curves < 2 && faces == topo.GetVertexEdges(v).size())
  {
    return Sqrt3VertexRule::Relax;
  }
  return evenStep && curves == 2 ? Sqrt3VertexRule::Curve : Sqrt3VertexRule::Fixed;
}

namespace
{
// Sets the sharpness of the child pieces of each sharp edge (the unflipped edge, or the
// three pieces of a trisected one) and of each vertex, one unit down.
void InheritSqrt3Sharpness(const Level& parent, const std::vector<Index>& firstEdgePoint,
  Index firstVertexPoint, Level& child)
{
  const MeshTopology& topo = parent.Topology;
  const MeshTopology& childTopo = child.Topology;
  auto setSharpness = [&](Index a, Index b, float sharpness) {
    const Index edge = childTopo.FindEdge(a, b);
    if (edge != InvalidIndex)
    {
      child.EdgeSharpness[edge] = sharpness;
    }
  };
  for (Index e = 0; e < topo.GetNumEdges(); ++e)
  {
    if (!IsSharp(parent.EdgeSharpness[e]))
    {
      continue;
    }
    const float sharpness = DecaySharpness(parent.EdgeSharpness[e]);
    const Index a = firstVertexPoint + topo.GetEdgeVertices(e)[0];
    const Index b = firstVertexPoint + topo.GetEdgeVertices(e)[1];
    const Index x = firstEdgePoint[e];
    if (x == InvalidIndex)
    {
      setSharpness(a, b, sharpness);
      continue;
    }
    setSharpness(a, x, sharpness);
    setSharpness(x, x + 1, sharpness);
    setSharpness(x + 1, b, sharpness);
  }
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    child.VertexSharpness[firstVertexPoint + v] = DecaySharpness(parent.VertexSharpness[v]);
  }
}
}

namespace
{
// The child points of one step (see the header): centroids, old vertices, trisection points.
struct Sqrt3Points
{
  std::vector<Index> TrisectedEdge;  // per face (ChooseTrisectedEdges)
  std::vector<Index> CentroidPoint;  // per face, InvalidIndex for a trisecting face
  Index FirstVertexPoint = 0;
  std::vector<Index> FirstEdgePoint; // per edge, InvalidIndex unless trisected
  Index NumPoints = 0;

  Sqrt3Points(const Level& parent, bool evenStep)
    : TrisectedEdge(ChooseTrisectedEdges(parent, evenStep))
  {
    const MeshTopology& topo = parent.Topology;
    const Index numFaces = topo.GetNumFaces();
    this->CentroidPoint.assign(static_cast<size_t>(numFaces), InvalidIndex);
    for (Index f = 0; f < numFaces; ++f)
    {
      if (this->TrisectedEdge[f] == InvalidIndex)
      {
        this->CentroidPoint[f] = this->NumPoints++;
      }
    }
    this->FirstVertexPoint = this->NumPoints;
    this->NumPoints += topo.GetNumVertices();
    this->FirstEdgePoint.assign(static_cast<size_t>(topo.GetNumEdges()), InvalidIndex);
    for (Index f = 0; f < numFaces; ++f)
    {
      const Index e = this->TrisectedEdge[f];
      if (e != InvalidIndex && this->FirstEdgePoint[e] == InvalidIndex)
      {
        this->FirstEdgePoint[e] = this->NumPoints;
        this->NumPoints += 2;
      }
    }
  }
  // The trisection point of edge e next to its end v.
  Index TrisectionPoint(const MeshTopology& topo, Index e, Index v) const
  {
    return this->FirstEdgePoint[e] + (topo.GetEdgeVertices(e)[0] == v ? 0 : 1);
  }
};

// The rows of one step, written in parallel (each row by one task).
StencilTable BuildSqrt3Stencils(const Level& parent, const Sqrt3Points& points, bool evenStep, const ParallelFor& parallelFor)
{
  const MeshTopology& topo = parent.Topology;
  const Index numFaces = topo.GetNumFaces();
  const Index numVertices = topo.GetNumVertices();
  const Index numEdges = topo.GetNumEdges();
  StencilTable table(numVertices);
  table.ReserveRows(points.NumPoints);
  std::vector<Sqrt3VertexRule> rules(static_cast<size_t>(numVertices));
  parallelFor(0, numVertices, [&](Index begin, Index end) {
    for (Index v = begin; v < end; ++v)
    {
      rules[v] = ClassifySqrt3Vertex(parent, v, evenStep);
      const Index size = rules[v] == Sqrt3VertexRule::Relax ? 1 + topo.GetVertexEdges(v).size()
                                                             : (rules[v] == Sqrt3VertexRule::Curve ? 3 : 1);
      table.SetRowSize(points.FirstVertexPoint + v, size);
    }
  });
  parallelFor(0, numFaces, [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f)
    {
      if (points.CentroidPoint[f] != InvalidIndex)
      {
        table.SetRowSize(points.CentroidPoint[f], 3);
      }
    }
  });
  parallelFor(0, numEdges, [&](Index begin, Index end) {
    for (Index e = begin; e < end; ++e)
    {
      if (points.FirstEdgePoint[e] != InvalidIndex)
      {
        table.SetRowSize(points.FirstEdgePoint[e], 3);
        table.SetRowSize(points.FirstEdgePoint[e] + 1, 3);
      }
    }
  });
  table.FinalizeSizesUnfilled();
  auto setRow = [&](Index row, std::initializer_list<std::pair<Index, double>> entries) {
    Index* src = table.GetMutableSources(row);
    double* wts = table.GetMutableWeights(row);
    for (const auto& entry : entries)
    {
      *src++ = entry.first;
      *wts++ = entry.second;
    }
  };
  parallelFor(0, numFaces, [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f)
    {
      if (points.CentroidPoint[f] != InvalidIndex)
      {
        const IndexSpan fv = topo.GetFaceVertices(f);
        setRow(points.CentroidPoint[f], { { fv[0], 1.0 / 3.0 }, { fv[1], 1.0 / 3.0 }, { fv[2], 1.0 / 3.0 } });
      }
    }
  });
  // Kobbelt's alpha_n for the valences most meshes have, tabulated: the cosine would be
  // most of the cost of a row.
  std::vector<double> alphas(16);
  for (Index n = 1; n < static_cast<Index>(alphas.size()); ++n)
  {
    alphas[n] = Sqrt3Alpha(n);
  }
  parallelFor(0, numVertices, [&](Index begin, Index end) {
    for (Index v = begin; v < end; ++v)
    {
      const Index row = points.FirstVertexPoint + v;
      if (rules[v] == Sqrt3VertexRule::Relax)
      {
        const IndexSpan edges = topo.GetVertexEdges(v);
        const Index n = edges.size();
        const double alpha = n < static_cast<Index>(alphas.size()) ? alphas[n] : Sqrt3Alpha(n);
        Index* src = table.GetMutableSources(row);
        double* wts = table.GetMutableWeights(row);
        src[0] = v;
        wts[0] = 1.0 - alpha;
        for (Index i = 0; i < n; ++i)
        {
          src[1 + i] = topo.GetOtherEndpoint(edges[i], v);
          wts[1 + i] = alpha / n;
        }
      }
      else if (rules[v] == Sqrt3VertexRule::Curve)
      {
        const Index p = Sqrt3CurveNeighbour(parent, v, InvalidIndex);
        const Index q = Sqrt3CurveNeighbour(parent, v, p);
        setRow(row, { { p, 4.0 / 27.0 }, { v, 19.0 / 27.0 }, { q, 4.0 / 27.0 } });
      }
      else
      {
        setRow(row, { { v, 1.0 } });
      }
    }
  });
  parallelFor(0, numEdges, [&](Index begin, Index end) {
    for (Index e = begin; e < end; ++e)
    {
      if (points.FirstEdgePoint[e] == InvalidIndex)
      {
        continue;
      }
      const Index a = topo.GetEdgeVertices(e)[0], b = topo.GetEdgeVertices(e)[1];
      const Index p = Sqrt3CurveNeighbour(parent, a, b), q = Sqrt3CurveNeighbour(parent, b, a);
      setRow(points.FirstEdgePoint[e], { { p, 1.0 / 27.0 }, { a, 16.0 / 27.0 }, { b, 10.0 / 27.0 } });
      setRow(points.FirstEdgePoint[e] + 1, { { a, 10.0 / 27.0 }, { b, 16.0 / 27.0 }, { q, 1.0 / 27.0 } });
    }
  });
  table.EndBlock(points.NumPoints);
  return table;
}

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
    const size_t flips = static_cast<size_t>(std::max<Index>(0, std::min(end, numEdges) - begin));
    out.Reserve(2 * flips, 6 * flips); // two triangles per flipped edge: most of a block
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

  // Edge e's ends (a, b) in the order triangle f runs them.
  void OrientedEnds(Index e, Index f, Index& a, Index& b) const
  {
    const Index i = this->Topo.GetEdgePosition(f, e);
    a = this->Topo.GetFaceVertices(f)[i];
    b = this->Topo.GetFaceVertices(f)[(i + 1) % 3];
  }

  // The point an old edge e of face f is flipped to: the centroid, or in a triangle that
  // trisects another edge the trisection point next to the end the two edges share.
  Index Apex(Index f, Index e) const
  {
    if (this->Points.CentroidPoint[f] != InvalidIndex)
    {
      return this->Points.CentroidPoint[f];
    }
    const Index t = this->Points.TrisectedEdge[f];
    const Index* ev = this->Topo.GetEdgeVertices(e);
    const Index* tv = this->Topo.GetEdgeVertices(t);
    const Index shared = (ev[0] == tv[0] || ev[0] == tv[1]) ? ev[0] : ev[1];
    return this->Points.TrisectionPoint(this->Topo, t, shared);
  }

  void WriteEdgeTriangles(Index e, FaceBlock& out) const
  {
    const IndexSpan ef = this->Topo.GetEdgeFaces(e);
    const LevelArray<std::uint8_t>& isHole = this->Parent.FaceIsHole;
    if (!ActsAsBoundary(this->Parent, e))
    {
      Index f1 = ef[0], f2 = ef[1], a, b;
      this->OrientedEnds(e, f1, a, b);
      const std::uint8_t hole = isHole[f1] && isHole[f2];
      out.AddTriangle(this->VertexPoint(a), this->Apex(f2, e), this->Apex(f1, e), this->Parent.FaceOrigin[f1], hole);
      out.AddTriangle(this->VertexPoint(b), this->Apex(f1, e), this->Apex(f2, e), this->Parent.FaceOrigin[f2], hole);
      return;
    }
    // Not flipped (boundary, crease, non-manifold): each face keeps its part next to e,
    // unless e is the edge the face trisects (its middle triangle comes with the face).
    for (Index f : ef)
    {
      if (e != this->Points.TrisectedEdge[f])
      {
        Index a, b;
        this->OrientedEnds(e, f, a, b);
        out.AddTriangle(this->VertexPoint(a), this->VertexPoint(b), this->Apex(f, e), this->Parent.FaceOrigin[f], isHole[f]);
      }
    }
  }

  // Triangles (a, b, m) trisecting (a, b): the middle triangle (x_a, x_b, m); the triangles
  // (a, x_a, m) and (x_b, b, m) come from the flips of (m, a) and (b, m).
  void WriteMiddleTriangle(Index f, FaceBlock& out) const
  {
    const Index e = this->Points.TrisectedEdge[f];
    if (e == InvalidIndex)
    {
      return;
    }
    Index a, b;
    this->OrientedEnds(e, f, a, b);
    const Index m = this->Topo.GetTriangleOppositeVertex(f, e);
    out.AddTriangle(this->Points.TrisectionPoint(this->Topo, e, a), this->Points.TrisectionPoint(this->Topo, e, b),
      this->VertexPoint(m), this->Parent.FaceOrigin[f], this->Parent.FaceIsHole[f]);
  }

  const Level& Parent;
  const MeshTopology& Topo;
  const Sqrt3Points& Points;
};
}

LevelRefinement RefineSqrt3(const Level& parent, ChildTopology depth, const ParallelFor& parallelFor)
{
  const bool evenStep = (parent.Depth % 2) == 1; // the step making level Depth + 1
  const Sqrt3Points points(parent, evenStep);
  LevelRefinement result;
  result.Stencils = BuildSqrt3Stencils(parent, points, evenStep, parallelFor);

  const Sqrt3FaceWriter writer(parent, points);
  EmittedFaces faces = EmitFacesInParallel(writer.GetNumElements(), parallelFor,
    [&writer](Index begin, Index end, FaceBlock& block) { writer.WriteBlock(begin, end, block); });
  Level& child = result.Child;
  child.FaceOrigin = std::move(faces.Origins);
  child.FaceIsHole = std::move(faces.Holes);
  if (depth == ChildTopology::Full && Sqrt3ChildTopology::Applies(parent, points.NumPoints))
  {
    child.Depth = parent.Depth + 1;
    child.Creasing = parent.Creasing;
    child.Topology = Sqrt3ChildTopology::OfSqrt3Step(
      parent.Topology, std::move(faces.Offsets), std::move(faces.Vertices), parallelFor);
    child.EdgeSharpness.assign(static_cast<size_t>(child.Topology.GetNumEdges()), SharpnessSmooth);
    child.VertexSharpness.assign(static_cast<size_t>(points.NumPoints), SharpnessSmooth);
  }
  else
  {
    SetChildTopology(parent, child, points.NumPoints, std::move(faces.Offsets), std::move(faces.Vertices), depth, parallelFor);
  }
  if (depth == ChildTopology::Full)
  {
    InheritSqrt3Sharpness(parent, points.FirstEdgePoint, points.FirstVertexPoint, child);
  }
  return result;
}

Index Sqrt3FirstVertexPoint(const Level& parent)
{
  const std::vector<Index> trisected = ChooseTrisectedEdges(parent, (parent.Depth % 2) == 1);
  return static_cast<Index>(std::count(trisected.begin(), trisected.end(), InvalidIndex));
}
}
