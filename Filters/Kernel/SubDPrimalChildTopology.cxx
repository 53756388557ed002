#include "SubDPrimalChildTopology.h"
#include "SubDLevel.h"

#include <algorithm>
#include <numeric>

namespace subd
{
namespace
{
// Walking the faces in order, an edge is first met in the first of its faces (they are
// listed in increasing order).
bool IsFirstFace(const MeshTopology& topo, Index e, Index f)
{
  return topo.GetEdgeFaces(e)[0] == f;
}

// How the quad split's children sit in the parent (SubDQuadSplit.h). Child edge keys: the
// halves of parent edge e are HalfEdgeKey, the edge from the edge point of corner h's
// leaving edge to the face point is 2E + h.
struct QuadSplitShape
{
  const MeshTopology& Parent;
  Index NumEdges = Parent.GetNumEdges();

  static constexpr Index ChildFaceSize = 4;
  static constexpr Index EdgePointFacesPerFace = 2; // children of a face its edge point is in
  static constexpr Index EdgePointEdgesPerFace = 1; // edges inside a face at its edge point
  Index GetNumFacePoints() const { return this->Parent.GetNumFaces(); }
  Index GetNumInteriorEdges() const { return this->Parent.GetNumFaceCorners(); }
  // The child of face f holding the point of f's corner c.
  Index CornerChild(Index f, Index c) const { return this->Parent.GetFaceOffset(f) + c; }

  // Every corner of f's children in order, with the key of the edge leaving it and whether
  // the walk over the child faces meets that edge here first.
  template <typename Visit>
  void VisitCorners(Index f, Visit&& visit) const
  {
    const IndexSpan fv = this->Parent.GetFaceVertices(f), fe = this->Parent.GetFaceEdges(f);
    const Index n = fv.size(), first = this->Parent.GetFaceOffset(f), inside = 2 * this->NumEdges;
    for (Index j = 0; j < n; ++j)
    {
      const Index h = first + j, previous = j == 0 ? n - 1 : j - 1;
      visit(4 * h, HalfEdgeKey(this->Parent, fe[j], fv[j]), IsFirstFace(this->Parent, fe[j], f));
      visit(4 * h + 1, inside + h, j != n - 1);
      visit(4 * h + 2, inside + first + previous, j == 0);
      visit(4 * h + 3, HalfEdgeKey(this->Parent, fe[previous], fv[j]), IsFirstFace(this->Parent, fe[previous], f));
    }
  }
  // The edges inside f, each with its two faces in increasing order.
  template <typename Visit>
  void VisitInteriorEdges(Index f, Visit&& visit) const
  {
    const Index first = this->Parent.GetFaceOffset(f), n = this->Parent.GetFaceSize(f);
    for (Index h = first; h < first + n; ++h)
    {
      const bool last = h + 1 == first + n;
      visit(2 * this->NumEdges + h, last ? first : h, last ? h : h + 1);
    }
  }
  // The children of face g at the edge point of its edge i, in increasing order, and the
  // edge point's corner in each: corner 1 in the child of corner i, 3 in the next one.
  void WriteEdgePointFaces(Index g, Index i, Index* faces, Index* corners) const
  {
    const Index first = this->Parent.GetFaceOffset(g);
    const bool wraps = i + 1 == this->Parent.GetFaceSize(g);
    const Index leaving = first + i, entering = wraps ? first : leaving + 1;
    faces[0] = wraps ? entering : leaving;
    faces[1] = wraps ? leaving : entering;
    corners[0] = wraps ? 3 : 1;
    corners[1] = wraps ? 1 : 3;
  }
  void WriteEdgePointEdges(Index g, Index i, const Index* edgeOfKey, Index* edges) const
  {
    edges[0] = edgeOfKey[2 * this->NumEdges + this->Parent.GetFaceOffset(g) + i];
  }
  Index GetFacePointSize(Index f) const { return this->Parent.GetFaceSize(f); }
  // The face point of f: corner 2 of each child of f, at the end of every edge inside f.
  void WriteFacePoint(Index f, const Index* edgeOfKey, Index* faces, Index* corners, Index* edges) const
  {
    const Index first = this->Parent.GetFaceOffset(f), n = this->Parent.GetFaceSize(f);
    for (Index j = 0; j < n; ++j)
    {
      faces[j] = first + j;
      corners[j] = 2;
      edges[j] = edgeOfKey[2 * this->NumEdges + first + j];
    }
    std::sort(edges, edges + n);
  }
};

// How the triangle split's children sit in the parent (SubDTriangleSplit.h). Child edge
// keys: halves as above, the edge inside triangle f opposite its child corner j 2E + 3f + j.
struct TriangleSplitShape
{
  const MeshTopology& Parent;
  Index NumEdges = Parent.GetNumEdges();

  static constexpr Index ChildFaceSize = 3;
  static constexpr Index EdgePointFacesPerFace = 3;
  static constexpr Index EdgePointEdgesPerFace = 2;
  Index GetNumFacePoints() const { return 0; }
  Index GetNumInteriorEdges() const { return 3 * this->Parent.GetNumFaces(); }
  Index CornerChild(Index f, Index c) const { return 4 * f + c; }

  template <typename Visit>
  void VisitCorners(Index f, Visit&& visit) const
  {
    const IndexSpan fv = this->Parent.GetFaceVertices(f), fe = this->Parent.GetFaceEdges(f);
    const Index inside = 2 * this->NumEdges + 3 * f;
    Index corner = 12 * f;
    for (Index j = 0; j < 3; ++j, corner += 3)
    {
      const Index previous = j == 0 ? 2 : j - 1;
      visit(corner, HalfEdgeKey(this->Parent, fe[j], fv[j]), IsFirstFace(this->Parent, fe[j], f));
      visit(corner + 1, inside + j, true);
      visit(corner + 2, HalfEdgeKey(this->Parent, fe[previous], fv[j]), IsFirstFace(this->Parent, fe[previous], f));
    }
    // The middle triangle: edge point of edge j to that of edge j + 1 is opposite corner j + 1.
    visit(corner, inside + 1, false);
    visit(corner + 1, inside + 2, false);
    visit(corner + 2, inside, false);
  }
  template <typename Visit>
  void VisitInteriorEdges(Index f, Visit&& visit) const
  {
    for (Index j = 0; j < 3; ++j)
    {
      visit(2 * this->NumEdges + 3 * f + j, 4 * f + j, 4 * f + 3);
    }
  }
  // The edge point of edge i of g: corner 1 of child i, corner 2 of child i + 1, corner i
  // of the middle triangle.
  void WriteEdgePointFaces(Index g, Index i, Index* faces, Index* corners) const
  {
    const Index next = i == 2 ? 0 : i + 1;
    const bool wraps = next < i;
    faces[0] = 4 * g + (wraps ? next : i);
    faces[1] = 4 * g + (wraps ? i : next);
    corners[0] = wraps ? 2 : 1;
    corners[1] = wraps ? 1 : 2;
    faces[2] = 4 * g + 3;
    corners[2] = i;
  }
  void WriteEdgePointEdges(Index g, Index i, const Index* edgeOfKey, Index* edges) const
  {
    const Index inside = 2 * this->NumEdges + 3 * g;
    edges[0] = edgeOfKey[inside + i];
    edges[1] = edgeOfKey[inside + (i == 2 ? 0 : i + 1)];
  }
  Index GetFacePointSize(Index) const { return 0; }
  void WriteFacePoint(Index, const Index*, Index*, Index*, Index*) const {}
};
}

// Has MeshTopology's arrays to itself (a friend): writes each one from the parent's.
struct PrimalChildAssembly
{
  template <typename Shape>
  static MeshTopology Assemble(const Shape& shape, IndexArray offsets, IndexArray vertices,
    const ParallelFor& parallelFor);
};

template <typename Shape>
MeshTopology PrimalChildAssembly::Assemble(
  const Shape& shape, IndexArray offsets, IndexArray vertices, const ParallelFor& parallelFor)
{
  const MeshTopology& parent = shape.Parent;
  const Index numFaces = parent.GetNumFaces();
  const Index numEdges = parent.GetNumEdges();
  const Index numVertices = parent.GetNumVertices();
  const Index firstEdgePoint = shape.GetNumFacePoints();
  const Index firstVertexPoint = firstEdgePoint + numEdges;
  const Index numChildEdges = 2 * numEdges + shape.GetNumInteriorEdges();
  const Index numChildVertices = firstVertexPoint + numVertices;
  MeshTopology child = MeshTopology::BuildFacesOnly(numChildVertices, std::move(offsets), std::move(vertices));
  auto forEachFace = [&](auto&& perFace) {
    parallelFor(0, numFaces, [&](Index begin, Index end) {
      for (Index f = begin; f < end; ++f)
      {
        perFace(f);
      }
    });
  };

  // Edges: each parent face numbers the edges first met among its children from the sum of
  // the counts of the faces before it.
  IndexArray firstEdgeOfFace(static_cast<size_t>(numFaces) + 1);
  firstEdgeOfFace[0] = 0;
  forEachFace([&](Index f) {
    Index count = 0;
    shape.VisitCorners(f, [&count](Index, Index, bool isNew) { count += isNew; });
    firstEdgeOfFace[f + 1] = count;
  });
  std::partial_sum(firstEdgeOfFace.begin(), firstEdgeOfFace.end(), firstEdgeOfFace.begin());

  IndexArray edgeOfKey(static_cast<size_t>(numChildEdges));
  child.EdgeVertices.resize(2 * static_cast<size_t>(numChildEdges));
  child.EdgeTags.resize(static_cast<size_t>(numChildEdges));
  child.EdgeFaceOffsets.resize(static_cast<size_t>(numChildEdges) + 1); // counts of every edge below
  child.EdgeFaceOffsets[0] = 0;
  constexpr Index size = Shape::ChildFaceSize;
  forEachFace([&](Index f) {
    Index next = firstEdgeOfFace[f];
    shape.VisitCorners(f, [&](Index corner, Index key, bool isNew) {
      if (!isNew)
      {
        return;
      }
      const Index edge = next++;
      edgeOfKey[key] = edge;
      const Index following = corner % size == size - 1 ? corner - (size - 1) : corner + 1;
      child.EdgeVertices[2 * static_cast<size_t>(edge)] = child.FaceVertices[corner];
      child.EdgeVertices[2 * static_cast<size_t>(edge) + 1] = child.FaceVertices[following];
      const bool half = key < 2 * numEdges;
      child.EdgeTags[edge] = half ? parent.GetEdgeTag(key / 2) : EdgeTag{ 0, 0 };
      child.EdgeFaceOffsets[edge + 1] = half ? parent.GetEdgeFaces(key / 2).size() : 2;
    });
  });
  child.FaceEdges.resize(child.FaceVertices.size());
  forEachFace([&](Index f) {
    shape.VisitCorners(f, [&](Index corner, Index key, bool) { child.FaceEdges[corner] = edgeOfKey[key]; });
  });
  child.NumNonManifoldEdges = 2 * parent.GetNumNonManifoldEdges();
  child.NumBoundaryEdges = 2 * parent.GetNumBoundaryEdges();

  // Edge faces: a half's are the children of its parent edge's faces at its vertex; an edge
  // inside a face has the two children on either side.
  std::partial_sum(child.EdgeFaceOffsets.begin(), child.EdgeFaceOffsets.end(), child.EdgeFaceOffsets.begin());
  child.EdgeFaces.resize(static_cast<size_t>(child.EdgeFaceOffsets.back()));
  parallelFor(0, numEdges, [&](Index begin, Index end) {
    for (Index e = begin; e < end; ++e)
    {
      const IndexSpan faces = parent.GetEdgeFaces(e);
      for (int side = 0; side < 2; ++side)
      {
        const Index v = parent.GetEdgeVertices(e)[side];
        Index* out = child.EdgeFaces.data() + child.EdgeFaceOffsets[edgeOfKey[2 * e + side]];
        for (Index k = 0; k < faces.size(); ++k)
        {
          const Index g = faces[k];
          const Index i = parent.GetEdgePosition(g, e);
          const Index n = parent.GetFaceSize(g);
          const Index corner = parent.GetFaceVertices(g)[i] == v ? i : (i + 1 == n ? 0 : i + 1);
          out[k] = shape.CornerChild(g, corner);
        }
      }
    }
  });
  forEachFace([&](Index f) {
    shape.VisitInteriorEdges(f, [&](Index key, Index a, Index b) {
      Index* out = child.EdgeFaces.data() + child.EdgeFaceOffsets[edgeOfKey[key]];
      out[0] = a;
      out[1] = b;
    });
  });

  // Vertex relations, by the kind of point: face points, edge points, vertex points.
  const size_t numSlots = static_cast<size_t>(numChildVertices) + 1;
  child.VertexFaceOffsets.resize(numSlots); // counts of every point below
  child.VertexEdgeOffsets.resize(numSlots);
  child.VertexFaceOffsets[0] = child.VertexEdgeOffsets[0] = 0;
  child.VertexTags.resize(static_cast<size_t>(numChildVertices));
  // Counts at [point + 1], and the tags: face points are interior, edge points take their
  // edge's, vertex points their vertex's.
  parallelFor(0, numChildVertices, [&](Index begin, Index end) {
    for (Index point = begin; point < end; ++point)
    {
      Index faces, edges;
      VertexTag tag{ 0, 0 };
      if (point < firstEdgePoint)
      {
        faces = edges = shape.GetFacePointSize(point);
      }
      else if (point < firstVertexPoint)
      {
        const Index e = point - firstEdgePoint;
        const Index parentFaces = parent.GetEdgeFaces(e).size();
        faces = Shape::EdgePointFacesPerFace * parentFaces;
        edges = 2 + Shape::EdgePointEdgesPerFace * parentFaces;
        tag = VertexTag{ parent.GetEdgeTag(e).Boundary, parent.GetEdgeTag(e).NonManifold };
      }
      else
      {
        const Index v = point - firstVertexPoint;
        faces = parent.GetVertexFaces(v).size();
        edges = parent.GetVertexEdges(v).size();
        tag = parent.GetVertexTag(v);
      }
      child.VertexFaceOffsets[point + 1] = faces;
      child.VertexEdgeOffsets[point + 1] = edges;
      child.VertexTags[point] = tag;
    }
  });
  child.NumNonManifoldVertices = parent.GetNumNonManifoldEdges() + parent.GetNumNonManifoldVertices();
  child.MaxValence = 0;
  for (size_t v = 1; v < numSlots; ++v)
  {
    child.MaxValence = std::max(child.MaxValence, child.VertexEdgeOffsets[v]);
  }
  std::partial_sum(child.VertexFaceOffsets.begin(), child.VertexFaceOffsets.end(), child.VertexFaceOffsets.begin());
  std::partial_sum(child.VertexEdgeOffsets.begin(), child.VertexEdgeOffsets.end(), child.VertexEdgeOffsets.begin());
  child.VertexFaces.resize(child.FaceVertices.size());
  child.VertexFaceCorners.resize(child.FaceVertices.size());
  child.VertexEdges.resize(child.EdgeVertices.size());
  auto facesOf = [&child](Index v) { return child.VertexFaces.data() + child.VertexFaceOffsets[v]; };
  auto cornersOf = [&child](Index v) { return child.VertexFaceCorners.data() + child.VertexFaceOffsets[v]; };
  auto edgesOf = [&child](Index v) { return child.VertexEdges.data() + child.VertexEdgeOffsets[v]; };

  parallelFor(0, firstEdgePoint, [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f)
    {
      shape.WriteFacePoint(f, edgeOfKey.data(), facesOf(f), cornersOf(f), edgesOf(f));
    }
  });
  // The children of the faces of an edge come in the faces' (increasing) order, so the
  // edge point's faces are sorted face by face; its few edges are sorted at the end.
  parallelFor(0, numEdges, [&](Index begin, Index end) {
    for (Index e = begin; e < end; ++e)
    {
      const Index point = firstEdgePoint + e;
      Index* faces = facesOf(point);
      Index* corners = cornersOf(point);
      Index* edges = edgesOf(point);
      edges[0] = edgeOfKey[2 * e];
      edges[1] = edgeOfKey[2 * e + 1];
      const IndexSpan parentFaces = parent.GetEdgeFaces(e);
      for (Index k = 0; k < parentFaces.size(); ++k)
      {
        const Index g = parentFaces[k];
        const Index i = parent.GetEdgePosition(g, e);
        shape.WriteEdgePointFaces(
          g, i, faces + Shape::EdgePointFacesPerFace * k, corners + Shape::EdgePointFacesPerFace * k);
        shape.WriteEdgePointEdges(g, i, edgeOfKey.data(), edges + 2 + Shape::EdgePointEdgesPerFace * k);
      }
      std::sort(edges, edges + 2 + Shape::EdgePointEdgesPerFace * parentFaces.size());
    }
  });
  // A vertex point sits at corner 0 of the child at its vertex's corner in each face, and
  // ends the halves of its vertex's edges.
  parallelFor(0, numVertices, [&](Index begin, Index end) {
    for (Index v = begin; v < end; ++v)
    {
      const Index point = firstVertexPoint + v;
      const IndexSpan parentFaces = parent.GetVertexFaces(v);
      const IndexSpan parentCorners = parent.GetVertexFaceCorners(v);
      Index* faces = facesOf(point);
      Index* corners = cornersOf(point);
      for (Index k = 0; k < parentFaces.size(); ++k)
      {
        faces[k] = shape.CornerChild(parentFaces[k], parentCorners[k]);
        corners[k] = 0;
      }
      const IndexSpan parentEdges = parent.GetVertexEdges(v);
      Index* edges = edgesOf(point);
      for (Index k = 0; k < parentEdges.size(); ++k)
      {
        edges[k] = edgeOfKey[HalfEdgeKey(parent, parentEdges[k], v)];
      }
      std::sort(edges, edges + parentEdges.size());
    }
  });

  return child;
}

MeshTopology PrimalChildTopology::OfQuadSplit(const MeshTopology& parent, IndexArray offsets,
  IndexArray vertices, const ParallelFor& parallelFor)
{
  return PrimalChildAssembly::Assemble(QuadSplitShape{ parent }, std::move(offsets), std::move(vertices), parallelFor);
}

MeshTopology PrimalChildTopology::OfTriangleSplit(const MeshTopology& parent, IndexArray offsets,
  IndexArray vertices, const ParallelFor& parallelFor)
{
  return PrimalChildAssembly::Assemble(
    TriangleSplitShape{ parent }, std::move(offsets), std::move(vertices), parallelFor);
}

void PrimalChildTopology::SetChildLevel(const Level& parent, Level& child, Split split, Index numChildVertices,
  IndexArray offsets, IndexArray vertices, ChildTopology depth, Index firstEdgePoint,
  Index firstVertexPoint, const ParallelFor& parallelFor)
{
  if (depth == ChildTopology::FacesOnly)
  {
    SetChildTopology(parent, child, numChildVertices, std::move(offsets), std::move(vertices), depth);
    return;
  }
  child.Depth = parent.Depth + 1;
  child.Creasing = parent.Creasing;
  child.Topology = split == Split::Quads
    ? OfQuadSplit(parent.Topology, std::move(offsets), std::move(vertices), parallelFor)
    : OfTriangleSplit(parent.Topology, std::move(offsets), std::move(vertices), parallelFor);
  InheritPrimalSharpness(parent, child, firstEdgePoint, firstVertexPoint);
}
}
