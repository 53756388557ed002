#include "SubDPrimalChildTopology.h"
#include "SubDLevel.h"
#include "SubDPrimalSplitShape.h"

#include <algorithm>
#include <numeric>

namespace subd
{
// Has MeshTopology's arrays to itself (a friend): writes each one from the parent's.
struct PrimalChildAssembly
{
  template <typename Shape>
  static MeshTopology Assemble(const Shape& shape, IndexArray offsets, IndexArray vertices,
    const ParallelFor& parallelFor);
  /// Each edge's ends and tags (each new one from the child face that meets it first), each
  /// face's edges.
  template <typename Shape>
  static void WriteEdges(const Shape& shape, const ChildEdgeNumbering& numbering, MeshTopology& child,
    const ParallelFor& parallelFor);
  /// Each edge's faces: a half's are the children of its parent edge's faces at its vertex;
  /// an edge inside a face has the two children on either side.
  template <typename Shape>
  static void WriteEdgeFaces(const Shape& shape, const ChildEdgeNumbering& numbering, MeshTopology& child,
    const ParallelFor& parallelFor);
  /// The faces and edges around each point, and its tags, by the kind of point: face points
  /// are interior, edge points take their edge's tags, vertex points their vertex's.
  template <typename Shape>
  static void WriteVertexRelations(const Shape& shape, const ChildEdgeNumbering& numbering, MeshTopology& child,
    const ParallelFor& parallelFor);
};

template <typename Shape>
void PrimalChildAssembly::WriteEdges(
  const Shape& shape, const ChildEdgeNumbering& numbering, MeshTopology& child, const ParallelFor& parallelFor)
{
  const MeshTopology& parent = shape.Parent;
  const Index numEdges = parent.GetNumEdges();
  const Index numChildEdges = 2 * numEdges + shape.GetNumInteriorEdges();
  child.EdgeVertices.resize(2 * static_cast<size_t>(numChildEdges));
  child.EdgeTags.resize(static_cast<size_t>(numChildEdges));
  child.EdgeFaceOffsets.resize(static_cast<size_t>(numChildEdges) + 1); // counts of every edge below
  child.EdgeFaceOffsets[0] = 0;
  constexpr Index size = Shape::ChildFaceSize;
  child.FaceEdges.resize(child.FaceVertices.size());
  parallelFor(0, parent.GetNumFaces(), [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f)
    {
      Index next = numbering.FirstEdgeOfFace[f];
      shape.VisitCorners(f, [&](Index corner, Index key, bool isNew) {
        child.FaceEdges[corner] = numbering.EdgeOfKey[key];
        if (!isNew)
        {
          return;
        }
        const Index edge = next++;
        const Index following = corner % size == size - 1 ? corner - (size - 1) : corner + 1;
        child.EdgeVertices[2 * static_cast<size_t>(edge)] = child.FaceVertices[corner];
        child.EdgeVertices[2 * static_cast<size_t>(edge) + 1] = child.FaceVertices[following];
        const bool half = key < 2 * numEdges;
        child.EdgeTags[edge] = half ? parent.GetEdgeTag(key / 2) : EdgeTag{ 0, 0 };
        child.EdgeFaceOffsets[edge + 1] = half ? parent.GetEdgeFaces(key / 2).size() : 2;
      });
    }
  });
  child.NumNonManifoldEdges = 2 * parent.GetNumNonManifoldEdges();
  child.NumBoundaryEdges = 2 * parent.GetNumBoundaryEdges();
}

template <typename Shape>
void PrimalChildAssembly::WriteEdgeFaces(
  const Shape& shape, const ChildEdgeNumbering& numbering, MeshTopology& child, const ParallelFor& parallelFor)
{
  const MeshTopology& parent = shape.Parent;
  const IndexArray& edgeOfKey = numbering.EdgeOfKey;
  std::partial_sum(child.EdgeFaceOffsets.begin(), child.EdgeFaceOffsets.end(), child.EdgeFaceOffsets.begin());
  child.EdgeFaces.resize(static_cast<size_t>(child.EdgeFaceOffsets.back()));
  parallelFor(0, parent.GetNumEdges(), [&](Index begin, Index end) {
    for (Index e = begin; e < end; ++e)
    {
      const IndexSpan faces = parent.GetEdgeFaces(e);
      for (int side = 0; side < 2; ++side)
      {
        Index* out = child.EdgeFaces.data() + child.EdgeFaceOffsets[edgeOfKey[2 * e + side]];
        for (Index k = 0; k < faces.size(); ++k)
        {
          const Index g = faces[k];
          const Index i = parent.GetEdgePosition(g, e);
          const Index n = parent.GetFaceSize(g);
          // Where g runs e from its first end, the half there (side 0) is at corner i, the
          // other at corner i + 1; the other way round otherwise. So an edge from a vertex to
          // itself has a half at each of its two corners.
          const bool startsAtFirstEnd = parent.GetFaceVertices(g)[i] == parent.GetEdgeVertices(e)[0];
          const Index corner = startsAtFirstEnd == (side == 0) ? i : (i + 1 == n ? 0 : i + 1);
          out[k] = shape.CornerChild(g, corner);
        }
      }
    }
  });
  parallelFor(0, parent.GetNumFaces(), [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f)
    {
      shape.VisitInteriorEdges(f, [&](Index key, Index a, Index b) {
        Index* out = child.EdgeFaces.data() + child.EdgeFaceOffsets[edgeOfKey[key]];
        out[0] = a;
        out[1] = b;
      });
    }
  });
}

template <typename Shape>
void PrimalChildAssembly::WriteVertexRelations(
  const Shape& shape, const ChildEdgeNumbering& numbering, MeshTopology& child, const ParallelFor& parallelFor)
{
  const MeshTopology& parent = shape.Parent;
  const Index firstEdgePoint = shape.GetNumFacePoints();
  const Index firstVertexPoint = firstEdgePoint + parent.GetNumEdges();
  const Index numChildVertices = child.GetNumVertices();
  const size_t numSlots = static_cast<size_t>(numChildVertices) + 1;
  child.VertexFaceOffsets.resize(numSlots); // counts of every point below
  child.VertexEdgeOffsets.resize(numSlots);
  child.VertexFaceOffsets[0] = child.VertexEdgeOffsets[0] = 0;
  child.VertexTags.resize(static_cast<size_t>(numChildVertices));
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
  parallelFor(0, numChildVertices, [&](Index begin, Index end) {
    for (Index point = begin; point < end; ++point)
    {
      Index numFaces, numEdges;
      WriteChildPointRelations(shape, numbering, point, child.VertexFaces.data() + child.VertexFaceOffsets[point],
        child.VertexFaceCorners.data() + child.VertexFaceOffsets[point],
        child.VertexEdges.data() + child.VertexEdgeOffsets[point], numFaces, numEdges);
    }
  });
}

template <typename Shape>
MeshTopology PrimalChildAssembly::Assemble(
  const Shape& shape, IndexArray offsets, IndexArray vertices, const ParallelFor& parallelFor)
{
  const MeshTopology& parent = shape.Parent;
  const Index numChildVertices = shape.GetNumFacePoints() + parent.GetNumEdges() + parent.GetNumVertices();
  MeshTopology child = MeshTopology::BuildFacesOnly(numChildVertices, std::move(offsets), std::move(vertices));
  // Edges numbered by first meeting (NumberChildEdges).
  const ChildEdgeNumbering numbering = NumberChildEdges(shape, parallelFor);
  WriteEdges(shape, numbering, child, parallelFor);
  WriteEdgeFaces(shape, numbering, child, parallelFor);
  WriteVertexRelations(shape, numbering, child, parallelFor);
  return child;
}

MeshTopology PrimalChildTopology::OfQuadSplit(
  const MeshTopology& parent, IndexArray offsets, IndexArray vertices, const ParallelFor& parallelFor)
{
  return PrimalChildAssembly::Assemble(QuadSplitShape{ parent }, std::move(offsets), std::move(vertices), parallelFor);
}

MeshTopology PrimalChildTopology::OfTriangleSplit(
  const MeshTopology& parent, IndexArray offsets, IndexArray vertices, const ParallelFor& parallelFor)
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
