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
// its ends are read); the child's own topology takes about twenty.
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
  /// faces in increasing order: a half of parent edge pe lies in the children of pe's faces
  /// at its vertex, the first of them where it is first met; an edge inside a parent face
  /// lies between two of that face's children.
  void GetEdge(Index e, Index* ends, Index* faces) const
  {
    const Index corner = this->FirstCorner[e];
    const Index p = corner / FaceSize, slot = corner % FaceSize;
    Index corners[FaceSize], keys[FaceSize];
    this->GetFaceCorners(p, corners);
    ends[0] = corners[slot];
    ends[1] = corners[slot + 1 == FaceSize ? 0 : slot + 1];
    this->Split.GetChildEdgeKeys(p / 4, p % 4, keys);
    const Index key = keys[slot];
    if (key >= 2 * this->Split.NumEdges)
    {
      this->Split.GetInteriorEdgeFaces(p / 4, key, faces);
      return;
    }
    const MeshTopology& parent = this->Split.Parent;
    const Index pe = key / 2, v = parent.GetEdgeVertices(pe)[key % 2];
    const Index g = parent.GetEdgeFaces(pe)[1];
    const Index i = parent.GetEdgePosition(g, pe);
    faces[0] = p;
    faces[1] = this->Split.CornerChild(g, parent.GetFaceVertices(g)[i] == v ? i : (i + 1 == FaceSize ? 0 : i + 1));
  }

  /// The faces (with the point's corner in each) and the edges around child point `point`,
  /// sorted; `faces` and `corners` may be null for the edges alone
  /// (WriteChildPointRelations). The lists have at most GetMaxValence entries.
  void GetPointRelations(Index point, Index* faces, Index* corners, Index* edges, Index& numFaces, Index& numEdges) const
  {
    WriteChildPointRelations(this->Split, this->Numbering, point, faces, corners, edges, numFaces, numEdges);
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
  Shape Split;
  ChildEdgeNumbering Numbering;
  IndexArray FirstCorner; // per child edge: the child corner (SubDPrimalSplitShape.h) it is first met at
};

using QuadSplitView = PrimalSplitView<QuadSplitShape>;
using TriangleSplitView = PrimalSplitView<TriangleSplitShape>;
}

#endif
