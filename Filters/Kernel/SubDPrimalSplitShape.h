// SubD kernel: how the children of the primal splits (the quad split, SubDQuadSplit.h, and
// the triangle split, SubDTriangleSplit.h) sit in their parent, in closed form, and the
// numbering of the child edges that MeshTopology::Build would give them.
//
// Child edges are named by keys before they are numbered: the halves of parent edge e are
// HalfEdgeKey (2e, 2e + 1), the edges inside parent faces follow from 2E on. Build numbers
// edges by first meeting, walking the child faces and their corners in order; a half of
// parent edge e is first met in the first face of e, an edge inside a face in that face.
// Counting each parent face's new edges and summing the counts gives every parent face the
// first number of its edges (NumberChildEdges). Shared by the child topology
// (SubDPrimalChildTopology.h) and by the rows written two levels down (SubDCatmullClarkGrandchildRows.h).
#ifndef SubDPrimalSplitShape_h
#define SubDPrimalSplitShape_h

#include "SubDLevel.h"
#include "SubDMeshTopology.h"
#include "SubDParallel.h"

#include <algorithm>
#include <numeric>

namespace subd
{
// Walking the faces in order, an edge is first met in the first of its faces (they are
// listed in increasing order).
inline bool IsFirstFace(const MeshTopology& topo, Index e, Index f)
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
    const IndexSpan fe = this->Parent.GetFaceEdges(f);
    const Index n = fe.size(), first = this->Parent.GetFaceOffset(f);
    for (Index j = 0; j < n; ++j)
    {
      const Index h = first + j;
      Index keys[4];
      this->GetChildEdgeKeys(f, j, keys);
      visit(4 * h, keys[0], IsFirstFace(this->Parent, fe[j], f));
      visit(4 * h + 1, keys[1], j != n - 1);
      visit(4 * h + 2, keys[2], j == 0);
      visit(4 * h + 3, keys[3], IsFirstFace(this->Parent, fe[j == 0 ? n - 1 : j - 1], f));
    }
  }
  // The keys of the edges leaving the corners of the child of f at its corner j: the half of
  // edge j at v_j, the edge inside f at edge j's point, the one at edge j - 1's point, and
  // the half of edge j - 1 at v_j.
  void GetChildEdgeKeys(Index f, Index j, Index* keys) const
  {
    const IndexSpan fv = this->Parent.GetFaceVertices(f), fe = this->Parent.GetFaceEdges(f);
    const Index n = fv.size(), first = this->Parent.GetFaceOffset(f), inside = 2 * this->NumEdges;
    const Index previous = j == 0 ? n - 1 : j - 1;
    keys[0] = HalfEdgeKey(this->Parent, fe[j], fv[j]);
    keys[1] = inside + first + j;
    keys[2] = inside + first + previous;
    keys[3] = HalfEdgeKey(this->Parent, fe[previous], fv[j]);
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

/// The child edges' numbers: FirstEdgeOfFace[f] is the first number of the edges first met
/// among face f's children (F + 1 entries, the last the number of child edges), EdgeOfKey
/// the number of the edge of each key.
struct ChildEdgeNumbering
{
  IndexArray FirstEdgeOfFace;
  IndexArray EdgeOfKey;
};

template <typename Shape>
ChildEdgeNumbering NumberChildEdges(const Shape& shape, const ParallelFor& parallelFor)
{
  const Index numFaces = shape.Parent.GetNumFaces();
  ChildEdgeNumbering numbering;
  IndexArray& firstEdgeOfFace = numbering.FirstEdgeOfFace;
  firstEdgeOfFace.resize(static_cast<size_t>(numFaces) + 1);
  firstEdgeOfFace[0] = 0;
  parallelFor(0, numFaces, [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f)
    {
      Index count = 0;
      shape.VisitCorners(f, [&count](Index, Index, bool isNew) { count += isNew; });
      firstEdgeOfFace[f + 1] = count;
    }
  });
  std::partial_sum(firstEdgeOfFace.begin(), firstEdgeOfFace.end(), firstEdgeOfFace.begin());
  numbering.EdgeOfKey.resize(static_cast<size_t>(2 * shape.NumEdges + shape.GetNumInteriorEdges()));
  parallelFor(0, numFaces, [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f)
    {
      Index next = firstEdgeOfFace[f];
      shape.VisitCorners(f, [&](Index, Index key, bool isNew) {
        if (isNew)
        {
          numbering.EdgeOfKey[key] = next++;
        }
      });
    }
  });
  return numbering;
}
}

#endif
