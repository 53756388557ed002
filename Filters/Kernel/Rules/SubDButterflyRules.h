// SubD kernel: the modified butterfly scheme (D. Zorin, P. Schroeder, W. Sweldens,
// "Interpolating Subdivision for Meshes with Arbitrary Topology", SIGGRAPH 1996), an
// interpolating scheme on the triangle split: old vertices stay, and each edge (a0, a1)
// gets a new point from one of these stencils:
//
// - both ends regular (valence 6), or one end on the boundary and the other regular, or both
//   on the boundary: the 10-point butterfly with tension w (Dyn, Levin, Gregory 1990):
//     a (edge ends) 1/2 - w,  b (opposite vertices) 1/8 + 2w,
//     c (four wings, across the edges (a_i, b_j)) -1/16 - w,  d (two tips, a_i's neighbour
//     straight across from the edge) w;
//   w = 0 is the 8-point butterfly of VTK and OpenMesh. A wing missing at a boundary is
//   replaced by its reflection a_i + b_j - a_k (the parallelogram completion, as OpenMesh
//   does); a missing tip by 2 a_i - a_k;
// - otherwise the stencil of each end that is extraordinary (valence K != 6) and interior,
//   averaged when there are two: 3/4 on the vertex and s_j on its j-th neighbour counted
//   from the other end,
//     K = 3: 5/12, -1/12, -1/12;  K = 4: 3/8, 0, -1/8, 0;
//     K >= 5: s_j = (1/4 + cos(2 pi j/K) + 1/2 cos(4 pi j/K)) / K;
// - boundary edges: the 4-point rule -1/16, 9/16, 9/16, -1/16 along the boundary (the
//   midpoint where the boundary does not continue through an end); non-manifold edges:
//   the midpoint.
// Non-manifold vertices are treated like boundary vertices (they have no ring).
//
// Creases are treated like boundaries: a sharp edge takes the boundary's 4-point rule along
// its crease, a vertex with two or more sharp edges has no ring (it takes the boundary
// vertex's place in its neighbours' stencils) and a wing across a crease is reflected like
// a missing one. A dart (one sharp edge) keeps its ring. Semi-sharp edges: sharpness s >= 1
// takes the crease rule, 0 < s < 1 blends s of the crease rule with 1 - s of the smooth one
// (the same transition Catmull-Clark and Loop make when a sharpness reaches zero);
// sharpness decays by one unit per level as in the other primal schemes.
#ifndef SubDButterflyRules_h
#define SubDButterflyRules_h

#include "SubDLevel.h"
#include "SubDParallel.h"
#include "SubDRowWriting.h"
#include "SubDStencilTable.h"

#include <memory>
#include <vector>

namespace subd
{
/// Weight s_j of neighbour j of an extraordinary interior vertex of valence K (the vertex
/// itself gets 1 - sum_j s_j = 3/4).
SUBDKERNEL_EXPORT double ButterflyExtraordinaryWeight(Index K, Index j);

/// ButterflyExtraordinaryWeight for the valences 3..31, worked out once (two cosines per
/// weight otherwise).
class SUBDKERNEL_EXPORT ButterflyWeightTable
{
public:
  ButterflyWeightTable();
  /// s_0 .. s_{K-1} of valence K, or null when K is not in the table.
  const double* Get(Index K) const
  {
    return K >= 3 && K < static_cast<Index>(this->Weights.size()) ? this->Weights[K].data() : nullptr;
  }

private:
  std::vector<std::vector<double>> Weights; // [K][j]
};

/// The modified butterfly's weights with tension w (0: the 8-point butterfly; 1/16 makes it
/// the 10-point one): on each end of the edge, on each vertex opposite it, on each of the four
/// wings, on each of the two tips.
struct ButterflyWeights
{
  double End, Opposite, Wing, Tip;
  explicit ButterflyWeights(double w)
    : End(0.5 - w)
    , Opposite(0.125 + 2.0 * w)
    , Wing(-0.0625 - w)
    , Tip(w)
  {
  }
};

/// Zorin's stencil of the extraordinary interior vertex `vertex` of valence K for its edge to
/// ring point `start` (K when not in the ring: from 0): put(ring(k), s_j) for the ring's
/// points from `start` on, counter-clockwise, then put(vertex, 1 - sum of the s_j). `table`
/// holds the s_j of valence K, or is null.
template <typename Ring, typename Put>
void PutButterflyExtraordinaryStencil(Index vertex, Index K, Index start, const double* table, Ring&& ring, Put&& put)
{
  double sum = 0.0;
  for (Index j = 0, k = start == K ? 0 : start; j < K; ++j, k = k + 1 == K ? 0 : k + 1)
  {
    const double s = table ? table[j] : ButterflyExtraordinaryWeight(K, j);
    put(ring(k), s);
    sum += s;
  }
  put(vertex, 1.0 - sum);
}

/// Per corner i of each triangle of `topo`: 4 h + p for the triangle h across the triangle's
/// edge i (from corner i to i + 1), that edge being h's edge p; InvalidIndex where the edge
/// has not two distinct faces. The vertex across (the butterfly's wing) is h's corner p + 2
/// (TriangleVertexAcross). Requires every face to be a triangle.
SUBDKERNEL_EXPORT std::shared_ptr<const IndexArray> MakeTriangleFaceAcross(
  const MeshTopology& topo, const ParallelFor& parallelFor);

/// The vertex of `topo` across an edge, from its MakeTriangleFaceAcross entry `packed`
/// (which must not be InvalidIndex): the corner of h not on h's edge p.
inline Index TriangleVertexAcross(const MeshTopology& topo, Index packed)
{
  const Index p = packed % 4;
  return topo.GetTriangleVertices(packed / 4)[p == 0 ? 2 : p - 1];
}

/// Requires every face of `parent` to be a triangle.
SUBDKERNEL_EXPORT StencilTable BuildButterflyStencils(
  const Level& parent, double tension, const ParallelFor& parallelFor = SerialFor);

/// The same rows written one at a time (SubDRowWriting.h), rows numbered like the triangle
/// split's child points: edge points, then the vertex points (copies). Made once, in
/// parallel, with the writer: the triangle across each triangle edge (MakeTriangleFaceAcross,
/// for the butterfly's wings), and the ordered rings of the vertices
/// whose rules walk them (the extraordinary ones; all with tension, for the tips). Requires
/// every face of `parent` to be a triangle.
class SUBDKERNEL_EXPORT ButterflyRowWriter
{
public:
  ButterflyRowWriter(const Level& parent, double tension, const ParallelFor& parallelFor);
  Index GetNumParents() const { return this->Topology.GetNumVertices(); }
  Index GetNumRows() const { return this->Topology.GetNumEdges() + this->Topology.GetNumVertices(); }
  std::vector<Index> GetBlockEnds() const { return { this->GetNumRows() }; }
  /// Twice the longest row: WriteRow builds the smooth rule in the second half of its
  /// buffers before blending it into the row.
  Index GetMaxRowSize() const { return 2 * this->RowBound; }
  Index WriteRow(Index row, Index* sources, double* weights) const;
  /// Vertex points (copies of the parent's vertices), the edge points of the regular
  /// butterfly (RegularButterflyRow) and those of Zorin's stencil at an edge's one
  /// extraordinary end (OneExtraordinaryEnd); false for the other edge points.
  template <typename Entries>
  bool VisitSmoothRow(Index row, Entries& entries) const;
  /// Asks for the topology RegularButterflyRow reads for `row` (SubDRowWriting.h): its ends'
  /// ring kinds and its two triangles' corners, edges and FaceAcross entries.
  template <typename T>
  void PrefetchRow(Index row, const T* parents, const T* children) const;
  /// The row of edge e when it is the regular butterfly, as WriteRow writes it (same sources,
  /// weights and order): e smooth between two triangles, both ends of valence 6 with nothing
  /// sharp at them, and its 10 points (8 without tension) distinct. Returns the row's size,
  /// 0 for any other edge. `sources` and `weights` need room for 10.
  Index RegularButterflyRow(Index e, Index* sources, double* weights) const;

  /// A row under construction in caller storage: weights accumulated per source.
  struct Row
  {
    Index* Sources;
    double* Weights;
    Index Size = 0;
    void Add(Index source, double weight)
    {
      for (Index k = 0; k < this->Size; ++k)
      {
        if (this->Sources[k] == source)
        {
          this->Weights[k] += weight;
          return;
        }
      }
      this->Append(source, weight);
    }
    /// For a source known not to be in the row yet.
    void Append(Index source, double weight)
    {
      this->Sources[this->Size] = source;
      this->Weights[this->Size] = weight;
      ++this->Size;
    }
  };

private:
  /// The end v of edge e whose ring alone makes e's row, as WriteRow writes it: e smooth
  /// between two triangles, v's ring smooth and not of valence 6, the other end's not such a
  /// ring (of valence 6, or none). InvalidIndex for any other edge.
  Index OneExtraordinaryEnd(Index e) const;
  bool HasRing(Index v) const { return this->RingValences[v] > 0; }
  Index RingValence(Index v) const { return this->RingValences[v]; }
  bool IsSmoothRegular(Index v) const { return this->RingKinds[v] == SmoothRegularRing; }
  Index TriangleCornerOfEdge(Index f, Index e) const
  {
    const Index* fe = this->Topology.GetTriangleEdges(f);
    return PlaceInTriangle(fe, e);
  }
  Index RingStart(Index v, Index first) const;
  Index RingFrom(Index v, Index first, Index j) const;
  Index AcrossEdge(Index face, Index x, Index b) const;
  /// The vertex across the edge of `corner` (a corner of a triangle whose edge there has two
  /// faces).
  Index VertexAcross(Index corner) const { return TriangleVertexAcross(this->Topology, (*this->FaceAcross)[corner]); }
  Index OtherCreaseNeighbour(Index v, Index other) const;
  void AddCreaseRule(Index e, double scale, Row& row) const;
  void AddSmoothRule(Index e, Row& row) const;
  void AddWing(Index x, Index b, Index y, Index face, double weight, Row& row) const;
  void AddTip(Index x, Index y, double weight, Row& row) const;

  const Level& Parent;
  const MeshTopology& Topology;
  double Tension;
  Index RowBound = 16;
  // Per vertex: the number of faces of its closed fan when it takes the interior rules (see
  // the constructor), 0 otherwise; and what kind of ring that is.
  enum : std::uint8_t
  {
    NoSmoothRing = 0,     // no ring, or a dart's
    SmoothRing = 1,       // a ring without sharp edges
    SmoothRegularRing = 2 // the same, of valence 6
  };
  IndexArray RingValences;
  LevelArray<std::uint8_t> RingKinds;
  // The counter-clockwise neighbours of the vertices whose rules walk their ring (RingFrom:
  // the extraordinary vertices, and every vertex with a ring when the tips have weight);
  // the butterfly's wings come from FaceAcross instead, so regular vertices store none.
  IndexArray RingOffsets;
  IndexArray RingNeighbours;
  // Per corner of each triangle: the triangle across the edge that starts at the corner
  // (MakeTriangleFaceAcross). Read only where that edge is manifold with two faces.
  std::shared_ptr<const IndexArray> FaceAcross;
  ButterflyWeightTable ExtraordinaryWeights;
  // The vertices with exactly two sharp edges (boundary edges are sharp), in increasing
  // order, each with the other ends of those edges in the order of its edges: what the
  // crease rule reads.
  struct CreaseVertex
  {
    Index Vertex;
    Index Neighbours[2];
  };
  std::vector<CreaseVertex> CreaseVertices;
};

template <typename T>
inline void ButterflyRowWriter::PrefetchRow(Index row, const T*, const T*) const
{
  const MeshTopology& topo = this->Topology;
  if (row >= topo.GetNumEdges())
  {
    return; // a copy: read in order
  }
  const Index* ev = topo.GetEdgeVertices(row);
  for (int end = 0; end < 2; ++end)
  {
    PrefetchForRead(&this->RingKinds[ev[end]]);
    PrefetchForRead(&this->RingValences[ev[end]]);
    PrefetchForRead(&this->RingOffsets[ev[end]]);
  }
  for (Index f : topo.GetEdgeFaces(row))
  {
    PrefetchForRead(topo.GetTriangleVertices(f));
    PrefetchForRead(topo.GetTriangleEdges(f));
    PrefetchForRead(this->FaceAcross->data() + MeshTopology::GetFirstTriangleCorner(f));
  }
  // The stored rings of a row half as far ahead, whose offsets were asked for above by then:
  // the extraordinary rows (most rows of a scanned mesh) walk them.
  const Index nearer = row - PrefetchDistance / 2;
  if (nearer >= 0 && nearer < topo.GetNumEdges())
  {
    for (Index v : { topo.GetEdgeVertices(nearer)[0], topo.GetEdgeVertices(nearer)[1] })
    {
      PrefetchForRead(this->RingNeighbours.data() + this->RingOffsets[v]);
    }
  }
}

template <typename Entries>
inline bool ButterflyRowWriter::VisitSmoothRow(Index row, Entries& entries) const
{
  const Index numEdges = this->Topology.GetNumEdges();
  if (row >= numEdges)
  {
    CopyMask(row - numEdges, entries);
    return true;
  }
  Index sources[10];
  double weights[10];
  const Index size = this->RegularButterflyRow(row, sources, weights);
  for (Index k = 0; k < size; ++k)
  {
    entries.Parent(sources[k], weights[k]);
  }
  if (size > 0)
  {
    return true;
  }
  // Zorin's stencil of the one extraordinary end, in the order AddSmoothRule appends it.
  const Index v = this->OneExtraordinaryEnd(row);
  if (v == InvalidIndex)
  {
    return false;
  }
  const Index* ev = this->Topology.GetEdgeVertices(row);
  const Index K = this->RingValence(v);
  const Index* ring = this->RingNeighbours.data() + this->RingOffsets[v];
  PutButterflyExtraordinaryStencil(v, K, this->RingStart(v, ev[0] == v ? ev[1] : ev[0]),
    this->ExtraordinaryWeights.Get(K), [ring](Index k) { return ring[k]; },
    [&entries](Index source, double weight) { entries.Parent(source, weight); });
  return true;
}
}

#endif
