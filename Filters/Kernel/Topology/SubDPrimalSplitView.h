// SubD kernel: the child of a primal split read from its parent in closed form, without
// being built: the corners and edges of its faces, the ends and faces of its edges, the
// faces and edges around its points, numbered and listed as its own MeshTopology would list
// them (the closed forms of SubDPrimalSplitShape.h, which the built child is assembled from).
//
// For a parent that is closed and manifold (every edge between two faces that run it
// opposite ways, every vertex in one fan) whose faces all have the size of the split's
// children (quads for the quad split, triangles for the triangle split): then parent face g
// has the four children 4g .. 4g + 3 and every child edge has two faces. The view holds two
// numbers per child edge (its number by key, and the child corner it is first met at, where
// its ends are read) and three per parent corner (the corner across its edge, the half of
// its edge at its vertex, the corner of each edge in its first face); the child's own
// topology takes about twenty per child edge.
#ifndef SubDPrimalSplitView_h
#define SubDPrimalSplitView_h

#include "SubDPrimalSplitShape.h"

namespace subd
{
template <typename Shape>
class PrimalSplitView
{
public:
  static constexpr Index FaceSize = Shape::ChildFaceSize;

  PrimalSplitView(const MeshTopology& parent, const ParallelFor& parallelFor)
    : Split{ parent }
    , Numbering(NumberChildEdges(this->Split, parallelFor))
  {
    this->TwinCorner.resize(static_cast<size_t>(parent.GetNumFaceCorners()));
    this->HalfAtCorner.resize(this->TwinCorner.size());
    this->EdgeCorner.resize(static_cast<size_t>(parent.GetNumEdges()));
    parallelFor(0, parent.GetNumFaces(), [&](Index begin, Index end) {
      for (Index g = begin; g < end; ++g)
      {
        for (Index i = 0; i < FaceSize; ++i)
        {
          const Index e = parent.GetFaceEdges(g)[i], h = FaceSize * g + i;
          const IndexSpan faces = parent.GetEdgeFaces(e);
          const Index across = OtherOfTwo(faces, g);
          this->TwinCorner[h] = FaceSize * across + parent.GetEdgePosition(across, e);
          this->HalfAtCorner[h] = this->Numbering.GetEdge(HalfEdgeKey(parent, e, parent.GetFaceVertices(g)[i]));
          if (faces[0] == g)
          {
            this->EdgeCorner[e] = h;
          }
        }
      }
    });
    this->FirstCorner.resize(this->Numbering.EdgeOfKey.size());
    parallelFor(0, parent.GetNumFaces(), [&](Index begin, Index end) {
      for (Index g = begin; g < end; ++g)
      {
        this->Split.VisitCorners(g, [&](Index corner, Index key, bool isNew) {
          if (isNew)
          {
            this->FirstCorner[this->Numbering.GetEdge(key)] = corner;
          }
        });
      }
    });
  }

  /// Whether the view can read the split of `parent` (see above).
  static bool Reads(const MeshTopology& parent)
  {
    for (Index g = 0; g < parent.GetNumFaces(); ++g)
    {
      if (parent.GetFaceSize(g) != FaceSize)
      {
        return false;
      }
    }
    if (parent.GetNumBoundaryEdges() != 0 || parent.GetNumNonManifoldEdges() != 0 ||
      parent.GetNumNonManifoldVertices() != 0)
    {
      return false;
    }
    for (Index e = 0; e < parent.GetNumEdges(); ++e)
    {
      if (parent.GetEdgeFaces(e)[0] == parent.GetEdgeFaces(e)[1])
      {
        return false; // a face on both sides
      }
    }
    return true;
  }

  Index GetNumFaces() const { return 4 * this->Split.Parent.GetNumFaces(); }
  Index GetNumEdges() const { return static_cast<Index>(this->FirstCorner.size()); }
  Index GetNumVertices() const
  {
    return this->Split.GetNumFacePoints() + this->Split.NumEdges + this->Split.Parent.GetNumVertices();
  }

  /// The corners of child face p.
  void GetFaceCorners(Index p, Index* corners) const { this->Split.GetChildCorners(p / 4, p % 4, corners); }

  /// The corners of child face p and the edges leaving them.
  void GetFace(Index p, Index* corners, Index* edges) const
  {
    this->GetFaceCorners(p, corners);
    Index keys[FaceSize];
    this->Split.GetChildEdgeKeys(p / 4, p % 4, keys);
    for (Index k = 0; k < FaceSize; ++k)
    {
      edges[k] = this->Numbering.GetEdge(keys[k]);
    }
  }

  /// The ends of child edge e (from the corner it is first met at to the next) and its two
  /// faces in increasing order: the face it is first met in, and the child across.
  void GetEdge(Index e, Index* ends, Index* faces) const
  {
    const Index corner = this->FirstCorner[e];
    const Index p = corner / FaceSize, slot = corner % FaceSize;
    Index corners[FaceSize];
    this->GetFaceCorners(p, corners);
    ends[0] = corners[slot];
    ends[1] = corners[slot + 1 == FaceSize ? 0 : slot + 1];
    faces[0] = p;
    faces[1] = this->ChildAcross(p, slot);
  }

  /// The faces and the edges around child point `point`, each sorted, as the child's own
  /// lists (WriteChildPointRelations); `faces` may be null for the edges alone. The lists
  /// have at most GetMaxValence entries. An edge point lies in children of the two faces of
  /// its edge; a vertex point ends the halves of its vertex's edges, one leaving each corner.
  void GetPointRelations(Index point, Index* faces, Index* edges, Index& numFaces, Index& numEdges) const
  {
    const MeshTopology& parent = this->Split.Parent;
    const Index firstEdgePoint = this->Split.GetNumFacePoints();
    const Index firstVertexPoint = firstEdgePoint + this->Split.NumEdges;
    Index corners[2 * Shape::EdgePointFacesPerFace];
    if (point < firstEdgePoint)
    {
      Index facePointCorners[FaceSize];
      this->Split.WriteFacePoint(point, this->Numbering, faces ? faces : corners, facePointCorners, edges);
      numFaces = numEdges = FaceSize;
      return;
    }
    if (point < firstVertexPoint)
    {
      const Index e = point - firstEdgePoint;
      const Index sides[2] = { this->EdgeCorner[e], this->TwinCorner[this->EdgeCorner[e]] };
      edges[0] = this->Numbering.GetEdge(2 * e);
      edges[1] = this->Numbering.GetEdge(2 * e + 1);
      for (Index k = 0; k < 2; ++k)
      {
        const Index g = sides[k] / FaceSize, i = sides[k] % FaceSize;
        if (faces)
        {
          const Index at = Shape::EdgePointFacesPerFace * k;
          this->Split.WriteEdgePointFaces(g, i, faces + at, corners + at);
        }
        this->Split.WriteEdgePointEdges(g, i, this->Numbering, edges + 2 + Shape::EdgePointEdgesPerFace * k);
      }
      numFaces = 2 * Shape::EdgePointFacesPerFace;
      numEdges = 2 + 2 * Shape::EdgePointEdgesPerFace;
      SortShortList(edges, edges + numEdges);
      return;
    }
    const Index v = point - firstVertexPoint;
    const IndexSpan vertexFaces = parent.GetVertexFaces(v), vertexCorners = parent.GetVertexFaceCorners(v);
    for (Index k = 0; k < vertexFaces.size(); ++k)
    {
      const Index h = FaceSize * vertexFaces[k] + vertexCorners[k];
      if (faces)
      {
        faces[k] = this->Split.CornerChild(vertexFaces[k], vertexCorners[k]);
      }
      edges[k] = this->HalfAtCorner[h];
    }
    numFaces = numEdges = vertexFaces.size();
    SortShortList(edges, edges + numEdges);
  }
  Index GetMaxValence() const { return std::max(this->Split.Parent.GetMaxValence(), Shape::ChildFaceSize == 4 ? 4 : 6); }

  /// The corners of the four children of child face p split again by the same split,
  /// numbered as that split numbers its points (SubDQuadSplit.h, SubDTriangleSplit.h).
  void WriteSplitFace(Index p, Index* out) const
  {
    Index corners[FaceSize], edges[FaceSize];
    this->GetFace(p, corners, edges);
    for (Index j = 0; j < 4; ++j, out += FaceSize)
    {
      if constexpr (FaceSize == 4)
      {
        GetQuadSplitChild(corners, edges, 4, QuadSplitNumbering{ this->GetNumFaces(), this->GetNumEdges() }, p, j, out);
      }
      else
      {
        GetTriangleSplitChild(corners, edges, TriangleSplitNumbering{ this->GetNumEdges() }, j, out);
      }
    }
  }

private:
  // The child across the edge leaving corner `slot` of child face p: another child of the
  // same parent face, or, across a half of parent edge e, the child at the same vertex in
  // the face across e (where e runs the other way).
  Index ChildAcross(Index p, Index slot) const
  {
    const Index g = p / 4, j = p % 4;
    const Index previous = j == 0 ? FaceSize - 1 : j - 1;
    if constexpr (FaceSize == 4)
    {
      // Child j's corners: v_j, edge j's point, the face point, edge j - 1's point.
      switch (slot)
      {
        case 0: // the half of edge j at v_j, which edge i of the face across ends at
          return 4 * (this->TwinCorner[4 * g + j] / 4) + (this->TwinCorner[4 * g + j] + 1) % 4;
        case 1:
          return 4 * g + (j + 1) % 4;
        case 2:
          return 4 * g + previous;
        default: // the half of edge j - 1 at v_j, which edge i of the face across starts at
          return this->TwinCorner[4 * g + previous];
      }
    }
    else
    {
      // Child j < 3's corners: v_j, edge j's point, edge j - 1's point; child 3 (the middle)
      // meets no edge first.
      switch (slot)
      {
        case 0:
          return 4 * (this->TwinCorner[3 * g + j] / 3) + (this->TwinCorner[3 * g + j] % 3 + 1) % 3;
        case 1:
          return 4 * g + 3;
        default:
          return 4 * (this->TwinCorner[3 * g + previous] / 3) + this->TwinCorner[3 * g + previous] % 3;
      }
    }
  }

  Shape Split;
  ChildEdgeNumbering Numbering;
  IndexArray FirstCorner; // per child edge: the child corner (SubDPrimalSplitShape.h) it is first met at
  IndexArray TwinCorner;   // per parent corner: the corner of the face across its edge that starts that edge
  IndexArray HalfAtCorner; // per parent corner: the child edge that is the half of its edge at its vertex
  IndexArray EdgeCorner;   // per parent edge: its corner in its first face
};

using QuadSplitView = PrimalSplitView<QuadSplitShape>;
using TriangleSplitView = PrimalSplitView<TriangleSplitShape>;
}

#endif
