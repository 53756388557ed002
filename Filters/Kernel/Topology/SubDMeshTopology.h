// SubD kernel: the connectivity of a polygon mesh of any face sizes, in flat arrays.
//
// Built once from faces given as offsets + vertex indices (the layout of vtkCellArray), it
// derives the edges and every incidence relation the subdivision rules query:
// face->edges (edge i of a face joins its corners i and i+1), edge->vertices, edge->faces,
// vertex->faces and vertex->edges, each as count/offset arrays. Edges are numbered in the
// order they are first met walking the faces, which keeps neighbouring data close in memory.
//
// Non-manifold configurations are representable and tagged, never rejected:
// an edge with more than two faces, or whose two faces traverse it in the same direction
// (inconsistent orientation), is tagged non-manifold; a vertex is non-manifold when it lies on
// such an edge or when its faces form more than one fan (a "bow-tie"). The subdivision rules
// treat both as infinitely sharp, as OpenSubdiv does.
#ifndef SubDMeshTopology_h
#define SubDMeshTopology_h

#include "SubDParallel.h"
#include "SubDShortLists.h"
#include "SubDTypes.h"
#include <algorithm>
#include <vector>

namespace subd
{
/// Per-edge topological tags.
struct EdgeTag
{
  std::uint8_t Boundary : 1;    ///< exactly one incident face
  std::uint8_t NonManifold : 1; ///< more than two faces, or inconsistent orientation
};

/// Per-vertex topological tags.
struct VertexTag
{
  std::uint8_t Boundary : 1;    ///< lies on a boundary edge
  std::uint8_t NonManifold : 1; ///< on a non-manifold edge, or faces form several fans
};

class SUBDKERNEL_EXPORT MeshTopology
{
public:
  MeshTopology() = default;

  /// Builds the topology. Preconditions (checked by the caller, see MeshValidation): every
  /// face has >= 3 corners, all indices are in [0, numVertices). A face may repeat a vertex,
  /// as OpenSubdiv reads it: a half-edge from a vertex to itself is an edge of its own, and a
  /// vertex pair met twice in one face is two edges, all of them non-manifold (so an edge
  /// occurs once per face, and a repeated vertex is non-manifold).
  /// `faceOffsets` has numFaces+1 entries, the last one equal to the size of `faceVertices`.
  /// `parallelFor` runs every pass on threads; the topology does not depend on their number.
  static MeshTopology Build(Index numVertices, IndexArray faceOffsets, IndexArray faceVertices,
    const ParallelFor& parallelFor = SerialFor);
  /// The same from std::vector (copied on `parallelFor`'s threads).
  static MeshTopology Build(Index numVertices, const std::vector<Index>& faceOffsets,
    const std::vector<Index>& faceVertices, const ParallelFor& parallelFor = SerialFor);
  /// The topology of some of this one's faces (`faces`, in that order), numbering their
  /// points and edges in the order they are first met: `points` (on entry, points to number
  /// first) and `edges` receive the index in this topology of each. Unlike Build on the same
  /// faces, the edges are this topology's: two edges between one pair of points stay two
  /// (below a face that repeats a point), and an edge non-manifold here stays so.
  MeshTopology ExtractFaces(const std::vector<Index>& faces, std::vector<Index>& points, std::vector<Index>& edges) const;
  Index GetNumVertices() const { return NumVertices; }
  Index GetNumFaces() const { return static_cast<Index>(FaceOffsets.size()) - 1; }
  Index GetNumEdges() const { return static_cast<Index>(EdgeVertices.size() / 2); }
  /// Sum of all face sizes (number of face corners / half-edges).
  Index GetNumFaceCorners() const { return FaceOffsets.back(); }

  Index GetFaceSize(Index f) const { return FaceOffsets[f + 1] - FaceOffsets[f]; }
  Index GetFaceOffset(Index f) const { return FaceOffsets[f]; }
  IndexSpan GetFaceVertices(Index f) const { return Span(FaceVertices, FaceOffsets, f); }
  IndexSpan GetFaceEdges(Index f) const { return Span(FaceEdges, FaceOffsets, f); }

  const Index* GetEdgeVertices(Index e) const { return &EdgeVertices[2 * static_cast<size_t>(e)]; }
  IndexSpan GetEdgeFaces(Index e) const { return Span(EdgeFaces, EdgeFaceOffsets, e); }

  IndexSpan GetVertexFaces(Index v) const { return this->VertexFaceSpan(VertexFaces, v); }
  /// For each face of GetVertexFaces(v), the corner (0..size-1) at which v sits in it.
  IndexSpan GetVertexFaceCorners(Index v) const { return this->VertexFaceSpan(VertexFaceCorners, v); }
  Index GetNumVertexFaces(Index v) const { return VertexFaceOffsets[v + 1] - VertexFaceOffsets[v]; }

  /// False for a faces-only topology (BuildFacesOnly): no list, count or tag around its
  /// vertices, no valence.
  bool HasVertexRelations() const { return VertexEdgeOffsets.size() == static_cast<size_t>(NumVertices) + 1; }
  /// The corner of face f at vertex v, or InvalidIndex (faces of v are sorted: binary search).
  Index FindCorner(Index v, Index f) const;

  /// The faces around a manifold vertex in counter-clockwise order seen from outside (each
  /// next face lies across the edge entering v in the previous one), each with v's corner in
  /// it. A boundary vertex's list starts at the face with the boundary edge leaving v and
  /// ends at the one with the boundary edge entering it. Returns false (and clears the
  /// lists) for non-manifold or isolated vertices.
  bool GetOrderedVertexFaces(Index v, std::vector<Index>& faces, std::vector<Index>& corners) const;
  IndexSpan GetVertexEdges(Index v) const { return Span(VertexEdges, VertexEdgeOffsets, v); }
  /// Calls visit(w) for the vertex w at the other end of each of v's edges, in increasing
  /// order of w: an order that does not depend on how the edges are numbered, so that rows
  /// written from another level can follow it.
  template <typename Visit>
  void ForEachRingVertex(Index v, Visit&& visit) const
  {
    const IndexSpan list = this->GetVertexEdges(v);
    constexpr Index onStack = 64;
    Index stack[onStack];
    std::vector<Index> heap;
    Index* ring = stack;
    if (list.size() > onStack)
    {
      heap.resize(static_cast<size_t>(list.size()));
      ring = heap.data();
    }
    for (Index i = 0; i < list.size(); ++i)
    {
      ring[i] = this->GetOtherEndpoint(list[i], v);
    }
    SortShortList(ring, ring + list.size());
    for (Index i = 0; i < list.size(); ++i)
    {
      visit(ring[i]);
    }
  }

  /// The vertex at the other end of edge `e` from `v`, which must be one of its ends.
  Index GetOtherEndpoint(Index e, Index v) const
  {
    // Without a branch (OtherOfTwo): which end v is changes from edge to edge at random.
    return OtherOfTwo(IndexSpan{ GetEdgeVertices(e), 2 }, v);
  }

  EdgeTag GetEdgeTag(Index e) const { return EdgeTags[e]; }
  VertexTag GetVertexTag(Index v) const { return VertexTags[v]; }

  Index GetNumNonManifoldEdges() const { return NumNonManifoldEdges; }
  Index GetNumNonManifoldVertices() const { return NumNonManifoldVertices; }
  Index GetNumBoundaryEdges() const { return NumBoundaryEdges; }
  Index GetMaxValence() const { return MaxValence; }

  /// Raw arrays (read-only), for splits that emit child topology in bulk.
  const IndexArray& GetFaceOffsetArray() const { return FaceOffsets; }
  const IndexArray& GetFaceVertexArray() const { return FaceVertices; }
  const IndexArray& GetFaceEdgeArray() const { return FaceEdges; }

  /// Keeps only the faces: no edges, no incidence relations, no tags (GetNumEdges() is 0).
  /// For a last level that is only output.
  static MeshTopology BuildFacesOnly(Index numVertices, IndexArray faceOffsets, IndexArray faceVertices);
  bool HasEdges() const { return !FaceEdges.empty() || GetNumFaceCorners() == 0; }
  /// Moves a faces-only topology's face arrays out (offsets, corners): a caller that hands
  /// the faces on (to an output) then needs no copy. Returns false, moving nothing, when the
  /// topology has edges (its relations index them).
  static bool MoveFacesOut(MeshTopology&& topology, IndexArray& faceOffsets, IndexArray& faceVertices);

  /// For a triangle f and one of its edges e: the vertex of f not on e.
  Index GetTriangleOppositeVertex(Index f, Index e) const;
  /// For a triangle f with corners a and b: its third corner (InvalidIndex if a or b is not
  /// one). Reads the face's corners only: rules call it for every edge of a level.
  Index GetTriangleThirdVertex(Index f, Index a, Index b) const
  {
    return ThirdVertex(this->FaceVertices.data() + this->FaceOffsets[f], a, b);
  }
  /// The vertex of a triangle's three `corners` that is neither a nor b, or InvalidIndex
  /// unless exactly two corners are a or b.
  static Index ThirdVertex(const Index* corners, Index a, Index b)
  {
    Index third = InvalidIndex;
    int matches = 0;
    for (Index j = 0; j < 3; ++j)
    {
      const bool onEdge = corners[j] == a || corners[j] == b;
      matches += onEdge;
      third = onEdge ? third : corners[j];
    }
    return matches == 2 ? third : InvalidIndex;
  }

  /// For a mesh whose faces are all triangles (the triangle split's schemes): face f's
  /// vertices and edges, at corners 3f, 3f + 1 and 3f + 2, found without reading the face
  /// offsets (one scattered read fewer where f is far from the faces read before).
  /// (Arrays kept per triangle corner index them the same way, from GetFirstTriangleCorner.)
  static size_t GetFirstTriangleCorner(Index f) { return 3 * static_cast<size_t>(f); }
  const Index* GetTriangleVertices(Index f) const { return this->FaceVertices.data() + GetFirstTriangleCorner(f); }
  const Index* GetTriangleEdges(Index f) const { return this->FaceEdges.data() + GetFirstTriangleCorner(f); }

  /// Returns the edge joining a and b, or InvalidIndex.
  Index FindEdge(Index a, Index b) const;

  /// The position of edge e among face f's edges (e must be one of them). Edge i of a face
  /// joins its corners i and i + 1, so f runs e from GetFaceVertices(f)[i].
  Index GetEdgePosition(Index f, Index e) const
  {
    const IndexSpan fe = this->GetFaceEdges(f);
    if (fe.size() > 16)
    {
      return this->GetEdgePositionInLargeFace(f, e);
    }
    Index i = 0;
    while (fe[i] != e)
    {
      ++i;
    }
    return i;
  }

private:
  // The primal splits know their child's relations and write them directly
  // (SubDPrimalChildTopology).
  friend struct PrimalChildAssembly;

  // GetEdgePosition for faces of more than 16 sides (a scan would make them quadratic).
  Index GetEdgePositionInLargeFace(Index f, Index e) const;
  static IndexSpan Span(const IndexArray& data, const IndexArray& offsets, Index i)
  {
    return IndexSpan{ data.data() + offsets[i], offsets[i + 1] - offsets[i] };
  }
  IndexSpan VertexFaceSpan(const IndexArray& lists, Index v) const
  {
    const Index first = VertexFaceOffsets[v];
    return IndexSpan{ lists.empty() ? nullptr : lists.data() + first, VertexFaceOffsets[v + 1] - first };
  }
  /// Build's pairing of half-edges into edges, each half-edge h with the first half-edge of
  /// its vertex pair (lowest index) and its rank among them. The first's rank is 0: its slot
  /// holds the group's size instead, and whether a pair runs opposite ways (8 bytes per
  /// half-edge rather than 16: half the pages to fault in on a first build).
  struct HalfEdgePair
  {
    Index Representative, RankOrGroup;
    static Index Group(Index size, bool nonManifold) { return 2 * size + (nonManifold ? 1 : 0); }
    Index Rank(Index h) const { return h == this->Representative ? 0 : this->RankOrGroup; }
    // At a group's first half-edge only:
    Index GroupSize() const { return this->RankOrGroup >> 1; }
    bool IsNonManifold() const { return (this->RankOrGroup & 1) != 0; }
  };
  using HalfEdgePairing = LevelArray<HalfEdgePair>; // one per half-edge: its writes share a line
  /// Edges counted by PairHalfEdges as it makes them, for NumberEdges: how many, their faces,
  /// and how many are boundaries and non-manifold.
  struct EdgeCounts
  {
    Index Edges = 0, EdgeFaces = 0, Boundary = 0, NonManifold = 0;
    /// An edge of `faces` half-edges, `forward` of them running the way the first does, is
    /// non-manifold with more than two, or two running the same way.
    static bool IsNonManifold(Index faces, Index forward) { return faces > 2 || (faces == 2 && forward != 1); }
    void Add(Index faces, bool nonManifold)
    {
      ++this->Edges;
      this->EdgeFaces += faces;
      this->Boundary += faces == 1;
      this->NonManifold += nonManifold;
    }
    EdgeCounts& operator+=(const EdgeCounts& other)
    {
      this->Edges += other.Edges;
      this->EdgeFaces += other.EdgeFaces;
      this->Boundary += other.Boundary;
      this->NonManifold += other.NonManifold;
      return *this;
    }
  };
  /// The counts of the edges whose first half-edge lies in each block of faces: block b holds
  /// the faces that start at corners [b << Shift, (b + 1) << Shift), at most 64 blocks of at
  /// least 1024 corners, so that an edge's block is a shift of its face's first corner.
  struct EdgeCountsByBlock
  {
    int Shift = 10;
    std::vector<EdgeCounts> Blocks;

    EdgeCountsByBlock() = default;
    explicit EdgeCountsByBlock(size_t numCorners)
    {
      while ((numCorners >> this->Shift) >= 64)
      {
        ++this->Shift;
      }
      this->Blocks.resize((numCorners >> this->Shift) + 1);
    }
    size_t BlockOf(Index faceStart) const { return static_cast<size_t>(faceStart) >> this->Shift; }
    /// The first face of block b (the number of faces if none starts in it or after).
    Index FirstFaceOf(Index b, const IndexArray& faceOffsets) const;
  };
  /// The first corner of the face holding corner h.
  Index GetFaceStart(Index h, bool allTriangles) const;
  void BuildVertexFaces(const ParallelFor& parallelFor);
  HalfEdgePairing PairHalfEdges(
    bool allTriangles, IndexArray& smallFans, EdgeCountsByBlock& counts, const ParallelFor& parallelFor) const;
  template <typename HalfEdgeAt>
  static void WriteHalfEdgeGroup(HalfEdgePairing& pairing, const EdgeCountsByBlock& counts,
    std::vector<EdgeCounts>& blockCounts, Index count, bool nonManifold, Index firstFaceStart,
    const HalfEdgeAt& halfEdgeAt);
  template <typename CornerAt, typename WriteGroup>
  void PairBySorting(Index v, Index n, bool allTriangles, std::vector<std::uint64_t>& keys, const CornerAt& cornerAt,
    const WriteGroup& writeGroup) const;
  template <typename HalfEdgeAt, typename WriteGroup>
  void WriteVertexPairGroups(Index count, Index forward, bool allTriangles, const HalfEdgeAt& halfEdgeAt,
    const WriteGroup& writeGroup) const;
  void NumberEdges(const HalfEdgePairing& pairing, const EdgeCountsByBlock& counts, const ParallelFor& parallelFor);
  void BuildEdgeFaces(const HalfEdgePairing& pairing, const ParallelFor& parallelFor);
  void BuildVertexEdges(const ParallelFor& parallelFor);
  void TagVertices(const IndexArray& smallFans, const ParallelFor& parallelFor);
  Index CountFans(Index v, std::vector<Index>& scratch) const;

  Index NumVertices = 0;
  IndexArray FaceOffsets{ 0 };
  IndexArray FaceVertices;
  IndexArray FaceEdges;
  IndexArray EdgeVertices;
  IndexArray EdgeFaceOffsets{ 0 };
  IndexArray EdgeFaces;
  IndexArray VertexFaceOffsets{ 0 };
  IndexArray VertexFaces;
  IndexArray VertexFaceCorners;
  IndexArray VertexEdgeOffsets{ 0 };
  IndexArray VertexEdges;
  LevelArray<EdgeTag> EdgeTags;
  LevelArray<VertexTag> VertexTags;
  Index NumNonManifoldEdges = 0;
  Index NumNonManifoldVertices = 0;
  Index NumBoundaryEdges = 0;
  Index MaxValence = 0;
};
}

#endif
