// SubD kernel: how the children of the primal splits (the quad split, SubDQuadSplit.h, and
// the triangle split, SubDTriangleSplit.h) sit in their parent, in closed form, and the
// numbering of the child edges that MeshTopology::Build would give them.
//
// Child edges are named by keys before they are numbered: the halves of parent edge e are
// HalfEdgeKey (2e, 2e + 1), the edges inside parent faces follow from 2E on. Build numbers
// edges by first meeting, walking the child faces and their corners in order; a half of
// parent edge e is first met in the first face of e, an edge inside a face in that face.
// Counting each parent face's new edges and summing the counts gives every parent face the
// first number of its edges (NumberChildEdges). Read by the child topology
// (SubDPrimalChildTopology.h).
#ifndef SubDPrimalSplitShape_h
#define SubDPrimalSplitShape_h

#include "SubDLevel.h"
#include "SubDMeshTopology.h"
#include "SubDParallel.h"
#include "SubDQuadSplit.h"
#include "SubDShortLists.h"
#include "SubDTriangleSplit.h"

#include <algorithm>
#include <numeric>
#include <type_traits>

namespace subd
{
/// The child edges' numbers: FirstEdgeOfFace[f] is the first number of the edges first met
/// among face f's children (F + 1 entries, the last the number of child edges); GetEdge(key)
/// the number of the edge of each key.
struct ChildEdgeNumbering
{
  IndexArray FirstEdgeOfFace;
  IndexArray EdgeOfKey;

  Index GetEdge(Index key) const { return this->EdgeOfKey[key]; }
};

// Walking the faces in order, an edge is first met in the first of its faces (they are
// listed in increasing order). Where no edge is non-manifold, an edge has one face or two
// that run it opposite ways, and the first is the one whose half-edge along it starts where
// the edge does (an edge takes its ends from its first half-edge): one read, where the
// edge's list of faces takes two dependent ones. `from` is the vertex f's half-edge along e
// starts at.
inline bool IsFirstFace(const MeshTopology& topo, Index e, Index f, Index from)
{
  if (topo.GetNumNonManifoldEdges() == 0)
  {
    return topo.GetEdgeVertices(e)[0] == from;
  }
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
    const Index n = fe.size(), first = this->Parent.GetFaceOffset(f);
    // Each edge's first face is looked up once (a read out of order), though two children
    // hold a half of it.
    const bool lastMetHere = IsFirstFace(this->Parent, fe[n - 1], f, fv[n - 1]);
    bool previousMetHere = lastMetHere;
    for (Index j = 0; j < n; ++j)
    {
      const Index h = first + j;
      const bool metHere = j + 1 == n ? lastMetHere : IsFirstFace(this->Parent, fe[j], f, fv[j]);
      Index keys[4];
      this->GetChildEdgeKeys(f, j, keys);
      visit(4 * h, keys[0], metHere);
      visit(4 * h + 1, keys[1], j != n - 1);
      visit(4 * h + 2, keys[2], j == 0);
      visit(4 * h + 3, keys[3], previousMetHere);
      previousMetHere = metHere;
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
    keys[0] = StartHalfKey(this->Parent, fe[j], fv[j]);
    keys[1] = inside + first + j;
    keys[2] = inside + first + previous;
    keys[3] = EndHalfKey(this->Parent, fe[previous], fv[previous]);
  }
  // The edges inside f, each with its two faces in increasing order.
  template <typename Visit>
  void VisitInteriorEdges(Index f, Visit&& visit) const
  {
    const Index first = this->Parent.GetFaceOffset(f), n = this->Parent.GetFaceSize(f);
    for (Index key = 2 * this->NumEdges + first; key < 2 * this->NumEdges + first + n; ++key)
    {
      Index faces[2];
      this->GetInteriorEdgeFaces(f, key, faces);
      visit(key, faces[0], faces[1]);
    }
  }
  // The two faces, in increasing order, of the edge inside f with key `key`: the children
  // at the corners its edge point lies between.
  void GetInteriorEdgeFaces(Index f, Index key, Index* faces) const
  {
    const Index first = this->Parent.GetFaceOffset(f), h = key - 2 * this->NumEdges;
    const bool last = h + 1 == first + this->Parent.GetFaceSize(f);
    faces[0] = last ? first : h;
    faces[1] = last ? h : h + 1;
  }
  Index GetNumChildren(Index f) const { return this->Parent.GetFaceSize(f); }
  // The corners of f's child j, in the split's child points.
  void GetChildCorners(Index f, Index j, Index* corners) const
  {
    GetQuadSplitChild(this->Parent, QuadSplitNumbering{ this->Parent.GetNumFaces(), this->NumEdges }, f, j, corners);
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
  void WriteEdgePointEdges(Index g, Index i, const ChildEdgeNumbering& numbering, Index* edges) const
  {
    edges[0] = numbering.GetEdge(2 * this->NumEdges + this->Parent.GetFaceOffset(g) + i);
  }
  Index GetFacePointSize(Index f) const { return this->Parent.GetFaceSize(f); }
  // The face point of f: corner 2 of each child of f, at the end of every edge inside f.
  void WriteFacePoint(Index f, const ChildEdgeNumbering& numbering, Index* faces, Index* corners, Index* edges) const
  {
    const Index first = this->Parent.GetFaceOffset(f), n = this->Parent.GetFaceSize(f);
    for (Index j = 0; j < n; ++j)
    {
      faces[j] = first + j;
      corners[j] = 2;
      edges[j] = numbering.GetEdge(2 * this->NumEdges + first + j);
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
    // Each edge's first face looked up once (as for quads).
    const bool metHere[3] = { IsFirstFace(this->Parent, fe[0], f, fv[0]), IsFirstFace(this->Parent, fe[1], f, fv[1]),
      IsFirstFace(this->Parent, fe[2], f, fv[2]) };
    for (Index j = 0; j < 4; ++j)
    {
      Index keys[3];
      this->GetChildEdgeKeys(f, j, keys);
      const Index corner = 12 * f + 3 * j;
      const bool middle = j == 3;
      visit(corner, keys[0], !middle && metHere[j]);
      visit(corner + 1, keys[1], !middle);
      visit(corner + 2, keys[2], !middle && metHere[j == 0 ? 2 : j - 1]);
    }
  }
  // The keys of the edges leaving the corners of f's child j: for a corner child, the half of
  // edge j at v_j, the edge inside f opposite the child's corner, the half of edge j - 1 at
  // v_j; for the middle triangle (j = 3), from the edge point of edge j to that of edge j + 1
  // is the edge opposite corner j + 1.
  void GetChildEdgeKeys(Index f, Index j, Index* keys) const
  {
    const Index inside = 2 * this->NumEdges + 3 * f;
    if (j == 3)
    {
      keys[0] = inside + 1;
      keys[1] = inside + 2;
      keys[2] = inside;
      return;
    }
    const Index *fv = this->Parent.GetTriangleVertices(f), *fe = this->Parent.GetTriangleEdges(f);
    keys[0] = StartHalfKey(this->Parent, fe[j], fv[j]);
    keys[1] = inside + j;
    keys[2] = EndHalfKey(this->Parent, fe[j == 0 ? 2 : j - 1], fv[j == 0 ? 2 : j - 1]);
  }
  template <typename Visit>
  void VisitInteriorEdges(Index f, Visit&& visit) const
  {
    for (Index key = 2 * this->NumEdges + 3 * f; key < 2 * this->NumEdges + 3 * f + 3; ++key)
    {
      Index faces[2];
      this->GetInteriorEdgeFaces(f, key, faces);
      visit(key, faces[0], faces[1]);
    }
  }
  // The edge inside f opposite the corner of its child j lies between that child and the
  // middle triangle.
  void GetInteriorEdgeFaces(Index f, Index key, Index* faces) const
  {
    faces[0] = 4 * f + (key - 2 * this->NumEdges - 3 * f);
    faces[1] = 4 * f + 3;
  }
  Index GetNumChildren(Index) const { return 4; }
  // The corners of f's child j, in the split's child points.
  void GetChildCorners(Index f, Index j, Index* corners) const
  {
    GetTriangleSplitChild(this->Parent, TriangleSplitNumbering{ this->NumEdges }, f, j, corners);
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
  void WriteEdgePointEdges(Index g, Index i, const ChildEdgeNumbering& numbering, Index* edges) const
  {
    const Index inside = 2 * this->NumEdges + 3 * g;
    edges[0] = numbering.GetEdge(inside + i);
    edges[1] = numbering.GetEdge(inside + (i == 2 ? 0 : i + 1));
  }
  Index GetFacePointSize(Index) const { return 0; }
  void WriteFacePoint(Index, const ChildEdgeNumbering&, Index*, Index*, Index*) const {}
};

/// The faces around child point `point` in increasing order, with the point's corner in each,
/// and its edges, sorted: the lists MeshTopology::Build gives. Writes their sizes. For an
/// edge or vertex point, `faces` and `corners` may be null: the edges alone, read without the
/// parent's lists of faces around its vertices.
template <typename Shape>
void WriteChildPointRelations(const Shape& shape, const ChildEdgeNumbering& numbering, Index point, Index* faces,
  Index* corners, Index* edges, Index& numFaces, Index& numEdges)
{
  const MeshTopology& parent = shape.Parent;
  const Index firstEdgePoint = shape.GetNumFacePoints();
  const Index firstVertexPoint = firstEdgePoint + shape.NumEdges;
  if (point < firstEdgePoint)
  {
    shape.WriteFacePoint(point, numbering, faces, corners, edges);
    numFaces = numEdges = shape.GetFacePointSize(point);
    return;
  }
  if (point < firstVertexPoint)
  {
    // The children of the faces of an edge come in the faces' (increasing) order, so the
    // edge point's faces are sorted face by face; its few edges are sorted at the end.
    const Index e = point - firstEdgePoint;
    edges[0] = numbering.EdgeOfKey[2 * e]; // halves are always stored
    edges[1] = numbering.EdgeOfKey[2 * e + 1];
    const IndexSpan parentFaces = parent.GetEdgeFaces(e);
    for (Index k = 0; k < parentFaces.size(); ++k)
    {
      const Index g = parentFaces[k];
      const Index i = parent.GetEdgePosition(g, e);
      if (faces)
      {
        shape.WriteEdgePointFaces(g, i, faces + Shape::EdgePointFacesPerFace * k, corners + Shape::EdgePointFacesPerFace * k);
      }
      shape.WriteEdgePointEdges(g, i, numbering, edges + 2 + Shape::EdgePointEdgesPerFace * k);
    }
    numFaces = Shape::EdgePointFacesPerFace * parentFaces.size();
    numEdges = 2 + Shape::EdgePointEdgesPerFace * parentFaces.size();
    SortShortList(edges, edges + numEdges);
    return;
  }
  // A vertex point sits at corner 0 of the child at its vertex's corner in each face, and
  // ends the halves of its vertex's edges.
  const Index v = point - firstVertexPoint;
  if (faces)
  {
    const IndexSpan parentFaces = parent.GetVertexFaces(v);
    const IndexSpan parentCorners = parent.GetVertexFaceCorners(v);
    for (Index k = 0; k < parentFaces.size(); ++k)
    {
      faces[k] = shape.CornerChild(parentFaces[k], parentCorners[k]);
      corners[k] = 0;
    }
  }
  const IndexSpan parentEdges = parent.GetVertexEdges(v);
  for (Index k = 0; k < parentEdges.size(); ++k)
  {
    // An edge from v to itself is listed twice: its two halves.
    const bool again = k > 0 && parentEdges[k - 1] == parentEdges[k];
    edges[k] = numbering.EdgeOfKey[HalfEdgeKey(parent, parentEdges[k], v) + (again ? 1 : 0)];
  }
  numFaces = parent.GetNumVertexFaces(v);
  numEdges = parentEdges.size();
  SortShortList(edges, edges + numEdges);
}

/// Numbers the child edges of `shape`'s split.
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
