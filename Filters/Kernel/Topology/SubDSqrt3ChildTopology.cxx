#include "SubDSqrt3ChildTopology.h"

#include <algorithm>
#include <numeric>

namespace subd
{
bool Sqrt3ChildTopology::Applies(const Level& parent, Index numPoints)
{
  const MeshTopology& topo = parent.Topology;
  if (numPoints != topo.GetNumFaces() + topo.GetNumVertices() || topo.GetNumBoundaryEdges() > 0 ||
    topo.GetNumNonManifoldEdges() > 0 || topo.GetNumNonManifoldVertices() > 0 ||
    topo.GetNumFaceCorners() != 3 * topo.GetNumFaces())
  {
    return false;
  }
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    if (topo.GetVertexFaces(v).empty())
    {
      return false;
    }
  }
  // A sharp edge is not flipped.
  return std::none_of(parent.EdgeSharpness.begin(), parent.EdgeSharpness.end(), [](float s) { return IsSharp(s); });
}

namespace
{
// One old edge: its faces and its ends in the order its first face runs them.
struct FlippedEdge
{
  Index F1, F2, A, B;

  FlippedEdge(const MeshTopology& topo, Index e)
  {
    const IndexSpan ef = topo.GetEdgeFaces(e);
    const Index i = topo.GetEdgePosition(ef[0], e);
    this->F1 = ef[0];
    this->F2 = ef[1];
    this->A = topo.GetFaceVertices(ef[0])[i];
    this->B = topo.GetFaceVertices(ef[0])[(i + 1) % 3];
  }
};

// The spoke from old vertex v to the centroid of triangle f: its parent corner (the key of
// the spoke) and the other edge of f at v.
struct Spoke
{
  Index Corner, OtherEdge;

  Spoke(const MeshTopology& topo, Index f, Index v, Index e)
  {
    const IndexSpan fv = topo.GetFaceVertices(f);
    const IndexSpan fe = topo.GetFaceEdges(f);
    const Index j = PlaceInTriangle(fv.begin(), v);
    this->Corner = topo.GetFaceOffset(f) + j;
    this->OtherEdge = fe[j] == e ? fe[(j + 2) % 3] : fe[j];
  }
};

// The spokes of old edge e's triangles, in the order the walk meets them: triangle 2e at its
// corners 0 and 2, then triangle 2e + 1 at its corners 0 and 2 (corner 1 of both is the
// flipped edge). `visit(spoke, from, to, slot)` gets each with the ends it runs there and its
// place among the six face edges of the two triangles.
template <typename Visit>
void VisitSpokes(const MeshTopology& parent, Index e, const FlippedEdge& edge, Visit&& visit)
{
  const Index numFaces = parent.GetNumFaces();
  visit(Spoke(parent, edge.F2, edge.A, e), numFaces + edge.A, edge.F2, 0);
  visit(Spoke(parent, edge.F1, edge.A, e), edge.F1, numFaces + edge.A, 2);
  visit(Spoke(parent, edge.F1, edge.B, e), numFaces + edge.B, edge.F1, 3);
  visit(Spoke(parent, edge.F2, edge.B, e), edge.F2, numFaces + edge.B, 5);
}
}

// The child edges' names by what they come from: each old edge's first end (as its first face
// runs it: which of its two triangles holds a vertex), its flipped edge, each corner's spoke.
struct Sqrt3ChildTopology::EdgeNames
{
  IndexArray EdgeStart, FlippedEdge, SpokeEdge;
  /// The child triangle of old edge e at its end v.
  Index TriangleAt(Index e, Index v) const { return 2 * e + (v == this->EdgeStart[e] ? 0 : 1); }
};

void Sqrt3ChildTopology::NumberEdges(
  const MeshTopology& parent, MeshTopology& child, EdgeNames& names, const ParallelFor& parallelFor)
{
  const Index numEdges = parent.GetNumEdges();
  const Index numFaces = parent.GetNumFaces();
  names.EdgeStart.resize(static_cast<size_t>(numEdges));
  // Edges met first in each old edge's triangles: its flipped edge and the spokes whose other
  // edge comes later.
  IndexArray firstNewEdge(static_cast<size_t>(numEdges) + 1);
  firstNewEdge[0] = 0;
  parallelFor(0, numEdges, [&](Index begin, Index end) {
    for (Index e = begin; e < end; ++e)
    {
      const FlippedEdge edge(parent, e);
      names.EdgeStart[e] = edge.A;
      Index count = 1;
      VisitSpokes(parent, e, edge, [&](const Spoke& spoke, Index, Index, int) { count += spoke.OtherEdge > e; });
      firstNewEdge[e + 1] = count;
    }
  });
  std::partial_sum(firstNewEdge.begin(), firstNewEdge.end(), firstNewEdge.begin());
  const Index numChildEdges = firstNewEdge[numEdges];
  // Each edge's ends (as first met) and two triangles.
  names.FlippedEdge.resize(static_cast<size_t>(numEdges));
  names.SpokeEdge.resize(static_cast<size_t>(parent.GetNumFaceCorners()));
  child.EdgeVertices.resize(2 * static_cast<size_t>(numChildEdges));
  child.EdgeFaces.resize(2 * static_cast<size_t>(numChildEdges));
  parallelFor(0, numEdges, [&](Index begin, Index end) {
    for (Index e = begin; e < end; ++e)
    {
      const FlippedEdge edge(parent, e);
      Index next = firstNewEdge[e];
      auto add = [&](Index from, Index to, Index t0, Index t1) {
        child.EdgeVertices[2 * static_cast<size_t>(next)] = from;
        child.EdgeVertices[2 * static_cast<size_t>(next) + 1] = to;
        child.EdgeFaces[2 * static_cast<size_t>(next)] = t0;
        child.EdgeFaces[2 * static_cast<size_t>(next) + 1] = t1;
        return next++;
      };
      VisitSpokes(parent, e, edge, [&](const Spoke& spoke, Index from, Index to, int slot) {
        const Index v = from < numFaces ? to - numFaces : from - numFaces;
        if (slot == 2)
        {
          names.FlippedEdge[e] = add(edge.F2, edge.F1, 2 * e, 2 * e + 1); // triangle 2e, corner 1
        }
        if (spoke.OtherEdge > e)
        {
          names.SpokeEdge[spoke.Corner] = add(from, to, names.TriangleAt(e, v), names.TriangleAt(spoke.OtherEdge, v));
        }
      });
    }
  });
  FillStrided(child.EdgeFaceOffsets, numChildEdges, 2, parallelFor);
  // Face edges: triangle 2e (spoke, flipped, spoke), triangle 2e + 1 (spoke, flipped, spoke).
  child.FaceEdges.resize(child.FaceVertices.size());
  parallelFor(0, numEdges, [&](Index begin, Index end) {
    for (Index e = begin; e < end; ++e)
    {
      Index* edges = child.FaceEdges.data() + 6 * static_cast<size_t>(e);
      VisitSpokes(parent, e, FlippedEdge(parent, e),
        [&](const Spoke& spoke, Index, Index, int slot) { edges[slot] = names.SpokeEdge[spoke.Corner]; });
      edges[1] = names.FlippedEdge[e];
      edges[4] = names.FlippedEdge[e];
    }
  });
}

void Sqrt3ChildTopology::WriteVertexLists(
  const MeshTopology& parent, const EdgeNames& names, MeshTopology& child, const ParallelFor& parallelFor)
{
  const Index numFaces = parent.GetNumFaces();
  const Index numVertices = parent.GetNumVertices();
  // Centroids: six triangles (two per edge of their face) and six edges (three flipped,
  // three spokes). Old vertices: one triangle per edge, one spoke per face.
  const size_t centroidSlots = 6 * static_cast<size_t>(numFaces);
  // As many faces around a point as edges: the parent's vertex-edge lists size them.
  const size_t slots = centroidSlots + parent.VertexEdges.size();
  child.VertexFaces.resize(slots);
  child.VertexFaceCorners.resize(slots);
  child.VertexEdges.resize(slots);
  parallelFor(0, numFaces, [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f)
    {
      Index faceEdges[3] = { parent.GetFaceEdges(f)[0], parent.GetFaceEdges(f)[1], parent.GetFaceEdges(f)[2] };
      std::sort(faceEdges, faceEdges + 3);
      Index* edges = child.VertexEdges.data() + 6 * static_cast<size_t>(f);
      Index* faces = child.VertexFaces.data() + 6 * static_cast<size_t>(f);
      Index* corners = child.VertexFaceCorners.data() + 6 * static_cast<size_t>(f);
      for (int i = 0; i < 3; ++i)
      {
        const Index e = faceEdges[i];
        const bool first = parent.GetEdgeFaces(e)[0] == f; // m1 of (a, m2, m1), (b, m1, m2)
        faces[2 * i] = 2 * e;
        faces[2 * i + 1] = 2 * e + 1;
        corners[2 * i] = first ? 2 : 1;
        corners[2 * i + 1] = first ? 1 : 2;
        edges[i] = names.FlippedEdge[e];
        edges[3 + i] = names.SpokeEdge[parent.GetFaceOffset(f) + i];
      }
      std::sort(edges, edges + 6);
    }
  });
  parallelFor(0, numVertices, [&](Index begin, Index end) {
    for (Index v = begin; v < end; ++v)
    {
      const size_t first = centroidSlots + static_cast<size_t>(parent.VertexEdgeOffsets[v]);
      const IndexSpan vertexEdges = parent.GetVertexEdges(v);
      for (Index i = 0; i < vertexEdges.size(); ++i) // edges sorted: so are their triangles
      {
        child.VertexFaces[first + i] = names.TriangleAt(vertexEdges[i], v);
        child.VertexFaceCorners[first + i] = 0;
      }
      const IndexSpan faces = parent.GetVertexFaces(v), corners = parent.GetVertexFaceCorners(v);
      Index* edges = child.VertexEdges.data() + centroidSlots + parent.VertexFaceOffsets[v];
      for (Index i = 0; i < faces.size(); ++i)
      {
        edges[i] = names.SpokeEdge[parent.GetFaceOffset(faces[i]) + corners[i]];
      }
      std::sort(edges, edges + faces.size());
    }
  });
  // A closed manifold vertex has as many faces as edges: one set of offsets for both lists.
  FillStrided(child.VertexEdgeOffsets, numFaces, 6, parallelFor);
  child.VertexEdgeOffsets.resize(static_cast<size_t>(numFaces + numVertices) + 1);
  const Index base = 6 * numFaces;
  parallelFor(0, numVertices, [&](Index begin, Index end) {
    for (Index v = begin; v < end; ++v)
    {
      child.VertexEdgeOffsets[numFaces + v + 1] = base + parent.VertexEdgeOffsets[v + 1];
    }
  });
  child.VertexFaceOffsets = child.VertexEdgeOffsets;
}

MeshTopology Sqrt3ChildTopology::OfSqrt3Step(
  const MeshTopology& parent, IndexArray offsets, IndexArray vertices, const ParallelFor& parallelFor)
{
  const Index numFaces = parent.GetNumFaces();
  const Index numVertices = parent.GetNumVertices();
  MeshTopology child = MeshTopology::BuildFacesOnly(numFaces + numVertices, std::move(offsets), std::move(vertices));
  EdgeNames names;
  NumberEdges(parent, child, names, parallelFor);
  WriteVertexLists(parent, names, child, parallelFor);
  child.EdgeTags.assign(static_cast<size_t>(child.GetNumEdges()), EdgeTag{ 0, 0 });
  child.VertexTags.assign(static_cast<size_t>(numFaces + numVertices), VertexTag{ 0, 0 });
  child.NumNonManifoldEdges = 0;
  child.NumNonManifoldVertices = 0;
  child.NumBoundaryEdges = 0;
  child.MaxValence = numFaces > 0 ? std::max<Index>(6, parent.GetMaxValence()) : 0;
  return child;
}
}
