#include "SubDMeshTopology.h"
#include "SubDFileByKey.h"
#include "SubDShortLists.h"

#include <algorithm>
#include <cstdint>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <mutex>
#include <numeric>
#include <utility>
#include <vector>

namespace subd
{
MeshTopology MeshTopology::BuildFacesOnly(Index numVertices, IndexArray faceOffsets, IndexArray faceVertices)
{
  MeshTopology topology;
  topology.NumVertices = numVertices;
  topology.FaceOffsets = std::move(faceOffsets);
  topology.FaceVertices = std::move(faceVertices);
  if (topology.FaceOffsets.empty())
  {
    topology.FaceOffsets.push_back(0);
  }
  return topology;
}

bool MeshTopology::MoveFacesOut(MeshTopology&& topology, IndexArray& faceOffsets, IndexArray& faceVertices)
{
  if (topology.HasEdges())
  {
    return false;
  }
  faceOffsets = std::move(topology.FaceOffsets);
  faceVertices = std::move(topology.FaceVertices);
  topology = BuildFacesOnly(topology.NumVertices, {}, {});
  return true;
}

MeshTopology MeshTopology::Build(Index numVertices, const std::vector<Index>& faceOffsets,
  const std::vector<Index>& faceVertices, const ParallelFor& parallelFor)
{
  return Build(numVertices, CopyOnThreads(faceOffsets.begin(), faceOffsets.end(), parallelFor),
    CopyOnThreads(faceVertices.begin(), faceVertices.end(), parallelFor), parallelFor);
}

MeshTopology MeshTopology::Build(
  Index numVertices, IndexArray faceOffsets, IndexArray faceVertices, const ParallelFor& parallelFor)
{
  MeshTopology topology = BuildFacesOnly(numVertices, std::move(faceOffsets), std::move(faceVertices));
  // Faces have at least three corners: three per face on average is three each.
  const bool allTriangles = topology.FaceVertices.size() == 3 * static_cast<size_t>(topology.GetNumFaces());
  topology.BuildVertexFaces(parallelFor);
  IndexArray smallFans;
  EdgeCountsByBlock edgeCounts;
  const HalfEdgePairing pairing = topology.PairHalfEdges(allTriangles, smallFans, edgeCounts, parallelFor);
  topology.NumberEdges(pairing, edgeCounts, parallelFor);
  topology.BuildEdgeFaces(pairing, parallelFor);
  topology.BuildVertexEdges(parallelFor);
  topology.TagVertices(smallFans, parallelFor);
  return topology;
}

// Every pass below runs per face, per vertex or per block of items and writes only its own
// entries, so the topology is the same for any number of threads.
void MeshTopology::BuildVertexFaces(const ParallelFor& parallelFor)
{
  this->VertexFaces.resize(this->FaceVertices.size());
  this->VertexFaceCorners.resize(this->FaceVertices.size());
  auto corners = [this](Index begin, Index end, const auto& visit) {
    for (Index f = begin; f < end; ++f)
    {
      for (Index h = this->FaceOffsets[f]; h < this->FaceOffsets[f + 1]; ++h)
      {
        visit(this->FaceVertices[h], std::make_pair(f, h - this->FaceOffsets[f]));
      }
    }
  };
  auto place = [this](Index slot, const std::pair<Index, Index>& corner) {
    this->VertexFaces[slot] = corner.first;
    this->VertexFaceCorners[slot] = corner.second;
  };
  FileByKey(this->NumVertices, this->GetNumFaces(), corners, place, this->VertexFaceOffsets, parallelFor);
}

namespace
{
// The corner among a vertex's n that follows corner k around it: the one leaving the vertex
// by the edge (or, by vertex ids, toward the vertex) that k enters it by; InvalidIndex at
// the end of an open fan. Matched without branches: the lists are short.
Index FollowerOf(Index k, Index n, const Index* leaving, const Index* entering)
{
  Index follower = InvalidIndex;
  for (Index j = 0; j < n; ++j)
  {
    follower = j != k && leaving[j] == entering[k] ? j : follower;
  }
  return follower;
}

// The neighbours of a vertex's n <= 32 face corners: the vertex each corner's edges leave
// toward and enter from. The usual vertex has at most 8 corners: its neighbours are compared
// 4 at a time (SSE2), the lanes past n holding InvalidIndex, which no vertex matches.
struct CornerNeighbours
{
  static constexpr Index MaxCorners = 32;
  alignas(16) Index Leaving[MaxCorners];
  alignas(16) Index Entering[MaxCorners];
  Index N = 0;

  // Bit j set where lanes[j] == value (Matching) or lanes[j] > value (Above), for j < N (the
  // padding, InvalidIndex, matches no vertex and is below any).
  std::uint32_t Matching(const Index* lanes, Index value) const { return this->Mask<true>(lanes, value); }
  std::uint32_t Above(const Index* lanes, Index value) const { return this->Mask<false>(lanes, value); }
  template <bool equal>
  std::uint32_t Mask(const Index* lanes, Index value) const
  {
#if defined(__SSE2__)
    if (this->N <= 8)
    {
      const __m128i wanted = _mm_set1_epi32(value);
      auto fourBits = [&wanted](const Index* four) {
        const __m128i x = _mm_load_si128(reinterpret_cast<const __m128i*>(four));
        if constexpr (equal)
        {
          return _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(x, wanted)));
        }
        else
        {
          return _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpgt_epi32(x, wanted)));
        }
      };
      return static_cast<std::uint32_t>(fourBits(lanes) | fourBits(lanes + 4) << 4);
    }
#endif
    std::uint32_t mask = 0;
    for (Index j = 0; j < this->N; ++j)
    {
      mask |= static_cast<std::uint32_t>(equal ? lanes[j] == value : lanes[j] > value) << j;
    }
    return mask;
  }

  // Pads the lanes the 8-wide comparison reads past N.
  void Pad()
  {
    for (Index j = this->N; j < 8; ++j)
    {
      this->Leaving[j] = this->Entering[j] = InvalidIndex;
    }
  }

  // Whether no two corners leave toward, or enter from, the same vertex: then each edge has
  // at most one half-edge each way, and each corner at most one follower and one predecessor.
  bool Distinct() const
  {
    bool distinct = true;
    for (Index k = 0; k < this->N; ++k)
    {
      distinct &= (this->Matching(this->Leaving, this->Leaving[k]) | this->Matching(this->Entering, this->Entering[k])) ==
        1u << k;
    }
    return distinct;
  }
};

// The lowest set bit of a non-zero mask.
inline Index LowestBit(std::uint32_t mask)
{
#if defined(__GNUC__)
  return static_cast<Index>(__builtin_ctz(mask));
#else
  Index bit = 0;
  while (!(mask >> bit & 1u))
  {
    ++bit;
  }
  return bit;
#endif
}

// The chains of followers among a vertex's corners with distinct neighbours: corner j
// follows corner k around the vertex when j leaves it along the edge k enters it by
// (Leaving[j] == Entering[k]).
struct CornerChains
{
  Index Next[CornerNeighbours::MaxCorners];
  std::uint32_t HasPredecessor = 0;

  explicit CornerChains(const CornerNeighbours& corners)
  {
    for (Index k = 0; k < corners.N; ++k)
    {
      const std::uint32_t follower = corners.Matching(corners.Leaving, corners.Entering[k]);
      this->Next[k] = follower ? LowestBit(follower) : InvalidIndex;
      this->HasPredecessor |= follower;
    }
  }

  // The fans are the chains, open (starting at a corner without predecessor) or closed,
  // each walked once.
  Index CountFans(Index n) const
  {
    std::uint32_t visited = 0;
    auto walk = [&](Index corner) {
      while (corner != InvalidIndex && !(visited >> corner & 1u))
      {
        visited |= 1u << corner;
        corner = this->Next[corner];
      }
    };
    Index fans = 0;
    for (Index k = 0; k < n; ++k)
    {
      if (!(this->HasPredecessor >> k & 1u))
      {
        ++fans; // an open fan starts here
        walk(k);
      }
    }
    for (Index k = 0; k < n; ++k)
    {
      if (!(visited >> k & 1u))
      {
        ++fans; // a closed fan
        walk(k);
      }
    }
    return fans;
  }
};
}

namespace
{
// A half-edge h of the vertex pair (lower, upper) as one key, (upper, h, whether h starts at
// the lower vertex): sorted, the keys filed at a lower vertex come in runs of one pair each,
// in increasing half-edge.
inline std::uint64_t HalfEdgeKey(Index upper, Index h, bool upward)
{
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(upper)) << 32) |
    (static_cast<std::uint64_t>(h) << 1) | (upward ? 1u : 0u);
}

inline Index HalfEdgeOfKey(std::uint64_t key)
{
  return static_cast<Index>((key & 0xffffffffu) >> 1);
}

// Calls pair(count, forward, halfEdgeAt) for each run of one vertex pair's keys in the sorted
// [first, last): its `count` half-edges, halfEdgeAt(i) in increasing order, `forward` of them
// running the way the first does.
template <typename Pair>
void ForEachVertexPair(const std::uint64_t* first, const std::uint64_t* last, const Pair& pair)
{
  for (const std::uint64_t* run = first; run != last;)
  {
    const std::uint64_t* runEnd = run + 1;
    while (runEnd != last && (*runEnd >> 32) == (*run >> 32))
    {
      ++runEnd;
    }
    Index forward = 0;
    for (const std::uint64_t* it = run; it != runEnd; ++it)
    {
      forward += (*it & 1u) == (*run & 1u);
    }
    pair(static_cast<Index>(runEnd - run), forward, [run](Index i) { return HalfEdgeOfKey(run[i]); });
    run = runEnd;
  }
}
}

// One edge's group, its `count` half-edges in increasing order (halfEdgeAt(i)), the first in
// the face starting at `firstFaceStart`: each paired with the first, and the edge counted in
// its block.
template <typename HalfEdgeAt>
void MeshTopology::WriteHalfEdgeGroup(HalfEdgePairing& pairing, const EdgeCountsByBlock& counts,
  std::vector<EdgeCounts>& blockCounts, Index count, bool nonManifold, Index firstFaceStart,
  const HalfEdgeAt& halfEdgeAt)
{
  const Index first = halfEdgeAt(0);
  for (Index i = 0; i < count; ++i)
  {
    pairing[halfEdgeAt(i)] = { first, i };
  }
  pairing[first].RankOrGroup = HalfEdgePair::Group(count, nonManifold);
  blockCounts[counts.BlockOf(firstFaceStart)].Add(count, nonManifold);
}

// The edges of one vertex pair, from its `count` half-edges in increasing order (`forward` of
// them running the way the first does): one edge, unless the pair is met again in a face that
// already has it. Then, as OpenSubdiv makes them, that half-edge is an edge of its own, the
// first edge keeps the others, and all of them are non-manifold.
template <typename HalfEdgeAt, typename WriteGroup>
void MeshTopology::WriteVertexPairGroups(
  Index count, Index forward, bool allTriangles, const HalfEdgeAt& halfEdgeAt, const WriteGroup& writeGroup) const
{
  auto faceOf = [&](Index i) { return this->GetFaceStart(halfEdgeAt(i), allTriangles); };
  bool metTwice = false;
  for (Index i = 1; i < count && !metTwice; ++i)
  {
    metTwice = faceOf(i) == faceOf(i - 1);
  }
  if (!metTwice)
  {
    writeGroup(count, EdgeCounts::IsNonManifold(count, forward), faceOf(0), halfEdgeAt);
    return;
  }
  std::vector<Index> first{ halfEdgeAt(0) };
  for (Index i = 1; i < count; ++i)
  {
    const Index h = halfEdgeAt(i);
    if (faceOf(i) == faceOf(i - 1))
    {
      writeGroup(1, true, faceOf(i), [h](Index) { return h; });
    }
    else
    {
      first.push_back(h);
    }
  }
  writeGroup(static_cast<Index>(first.size()), true, faceOf(0), [&first](Index i) { return first[i]; });
}

// The half-edges at v paired from a list sorted by their upper vertex (PairHalfEdges' path
// for many corners and for faces that repeat v, turn back or go from v to v).
template <typename CornerAt, typename WriteGroup>
void MeshTopology::PairBySorting(Index v, Index n, bool allTriangles, std::vector<std::uint64_t>& keys,
  const CornerAt& cornerAt, const WriteGroup& writeGroup) const
{
  if (keys.size() < 2 * static_cast<size_t>(n))
  {
    keys.resize(2 * static_cast<size_t>(n));
  }
  std::uint64_t* first = keys.data();
  std::uint64_t* last = first;
  for (Index k = 0; k < n; ++k)
  {
    Index faceFirst, h, previous, to, from;
    cornerAt(k, faceFirst, h, previous, to, from);
    if (to == v)
    {
      writeGroup(1, true, faceFirst, [h](Index) { return h; }); // from v to v: an edge of its own
    }
    else if (to > v)
    {
      *last++ = HalfEdgeKey(to, h, true);
    }
    if (from > v)
    {
      *last++ = HalfEdgeKey(from, previous, false);
    }
  }
  SortShortList(first, last);
  ForEachVertexPair(first, last, [&](Index count, Index forward, const auto& halfEdgeAt) {
    this->WriteVertexPairGroups(count, forward, allTriangles, halfEdgeAt, writeGroup);
  });
}

// The half-edges of one vertex pair are paired at the pair's lower vertex v, from v's own
// face corners: the half-edge leaving v at a corner, when it goes up (or loops back to v),
// and the one entering it from a higher vertex. At most vertices (up to 32 corners, no
// neighbour met twice the same way) each such pair is one link of the chains of corners
// around v, which also tell v's fans: the edge a corner leaves by is the one another enters
// by exactly when both go to the same vertex, since a vertex pair is one edge; so the fans
// come from the vertex ids read here, not from the edges numbered later. Elsewhere the
// half-edges, sorted by upper vertex and index, come out in their pairs: O(k log k) for a
// vertex of valence k, so even a 100k-valent hub stays fast.
// Each group is also counted in the block of faces its first half-edge lies in (edges, their
// faces, boundary and non-manifold ones), for NumberEdges.
MeshTopology::HalfEdgePairing MeshTopology::PairHalfEdges(
  bool allTriangles, IndexArray& smallFans, EdgeCountsByBlock& counts, const ParallelFor& parallelFor) const
{
  HalfEdgePairing pairing(this->FaceVertices.size());
  smallFans.resize(static_cast<size_t>(this->NumVertices));
  counts = EdgeCountsByBlock(this->FaceVertices.size());
  std::mutex merging;
  parallelFor(0, this->NumVertices, [&](Index begin, Index end) {
    constexpr Index smallValence = CornerNeighbours::MaxCorners;
    std::vector<std::uint64_t> keys;
    std::vector<EdgeCounts> blockCounts(counts.Blocks.size());
    CornerNeighbours neighbours;
    Index leavingEdge[smallValence], enteringEdge[smallValence], faceStart[smallValence];
    auto writeGroup = [&](Index count, bool nonManifold, Index firstFaceStart, const auto& halfEdgeAt) {
      WriteHalfEdgeGroup(pairing, counts, blockCounts, count, nonManifold, firstFaceStart, halfEdgeAt);
    };
    // A group of one half-edge, or of two running opposite ways (b != InvalidIndex), each in
    // the face starting at the corner given after it.
    auto pairUp = [&writeGroup](Index a, Index aFace, Index b, Index bFace) {
      const bool aFirst = b == InvalidIndex || a < b;
      const Index lower = aFirst ? a : b, upper = aFirst ? b : a;
      writeGroup(b == InvalidIndex ? 1 : 2, false, aFirst ? aFace : bFace, [=](Index i) { return i == 0 ? lower : upper; });
    };
    for (Index v = begin; v < end; ++v)
    {
      // A vertex's faces are scattered over the face list: ask for a later vertex's corners
      // ahead of reading them (the reads below are this pass's cost).
      constexpr Index ahead = 8;
      if (v + ahead < end)
      {
        for (Index f : this->GetVertexFaces(v + ahead))
        {
          const Index corner = allTriangles ? 3 * f : this->FaceOffsets[f];
          PrefetchForRead(this->FaceVertices.data() + corner);
          PrefetchForRead(pairing.data() + corner); // written below
        }
      }
      const IndexSpan faces = this->GetVertexFaces(v);
      const IndexSpan corners = this->GetVertexFaceCorners(v);
      const Index n = faces.size();
      const Index kept = std::min(n, smallValence);
      auto cornerAt = [&](Index k, Index& faceFirst, Index& h, Index& previous, Index& to, Index& from) {
        const Index f = faces[k], c = corners[k];
        faceFirst = allTriangles ? 3 * f : this->FaceOffsets[f];
        const Index size = allTriangles ? 3 : this->FaceOffsets[f + 1] - faceFirst;
        h = faceFirst + c;
        previous = faceFirst + (c == 0 ? size - 1 : c - 1);
        to = this->FaceVertices[c + 1 == size ? faceFirst : h + 1];
        from = this->FaceVertices[previous];
      };
      bool repeats = false; // a face through v twice, or back the way it came, or from v to v
      for (Index k = 0; k < kept; ++k)
      {
        cornerAt(k, faceStart[k], leavingEdge[k], enteringEdge[k], neighbours.Leaving[k], neighbours.Entering[k]);
        const Index to = neighbours.Leaving[k], from = neighbours.Entering[k];
        repeats |= to == v || from == v || to == from || (k > 0 && faces[k] == faces[k - 1]);
      }
      neighbours.N = kept;
      neighbours.Pad();
      if (n <= smallValence && !repeats && neighbours.Distinct())
      {
        const CornerChains chains(neighbours);
        smallFans[v] = chains.CountFans(n);
        // The corners entering v from above, and (a boundary: no way back) leaving it
        // upward, as bit masks: whether a neighbour is above v is a coin toss, which a
        // branch per corner would mispredict half the time.
        for (std::uint32_t above = neighbours.Above(neighbours.Entering, v); above; above &= above - 1)
        {
          const Index k = LowestBit(above);
          const Index follower = chains.Next[k];
          if (follower == InvalidIndex)
          {
            pairUp(enteringEdge[k], faceStart[k], InvalidIndex, InvalidIndex);
          }
          else
          {
            pairUp(enteringEdge[k], faceStart[k], leavingEdge[follower], faceStart[follower]);
          }
        }
        for (std::uint32_t boundary = neighbours.Above(neighbours.Leaving, v) & ~chains.HasPredecessor; boundary;
             boundary &= boundary - 1)
        {
          const Index k = LowestBit(boundary);
          pairUp(leavingEdge[k], faceStart[k], InvalidIndex, InvalidIndex);
        }
        continue;
      }
      smallFans[v] = InvalidIndex; // counted by TagVertices (CountFans)
      this->PairBySorting(v, n, allTriangles, keys, cornerAt, writeGroup);
    }
    const std::lock_guard<std::mutex> lock(merging);
    for (size_t b = 0; b < blockCounts.size(); ++b)
    {
      counts.Blocks[b] += blockCounts[b];
    }
  });
  return pairing;
}

Index MeshTopology::EdgeCountsByBlock::FirstFaceOf(Index b, const IndexArray& faceOffsets) const
{
  // faceOffsets ends with the number of corners, which starts no face.
  const std::int64_t corner = static_cast<std::int64_t>(b) << this->Shift;
  return static_cast<Index>(std::lower_bound(faceOffsets.begin(), faceOffsets.end() - 1, corner,
                              [](Index offset, std::int64_t c) { return offset < c; }) -
    faceOffsets.begin());
}

Index MeshTopology::GetFaceStart(Index h, bool allTriangles) const
{
  if (allTriangles)
  {
    return h - h % 3;
  }
  return *(std::upper_bound(this->FaceOffsets.begin(), this->FaceOffsets.end(), h) - 1);
}

// Edges are numbered in the order their first half-edges come walking the faces. The faces
// are cut into blocks (EdgeCountsByBlock: those starting in a fixed range of corners) whose
// edges, and their faces, boundaries and non-manifold ones, PairHalfEdges counted: a prefix
// sum over the blocks gives each block its first edge and first edge-face slot, and each block
// then numbers its own first half-edges (BuildEdgeFaces gives the others their number). Each
// edge's face offsets and tags come from its pairing: one face is a boundary; more than two,
// or two running it the same way, are non-manifold.
void MeshTopology::NumberEdges(const HalfEdgePairing& pairing, const EdgeCountsByBlock& counts, const ParallelFor& parallelFor)
{
  const Index blocks = static_cast<Index>(counts.Blocks.size());
  std::vector<EdgeCounts> firsts(static_cast<size_t>(blocks) + 1);
  std::vector<Index> firstFace(static_cast<size_t>(blocks) + 1);
  for (Index b = 0; b < blocks; ++b)
  {
    firsts[b + 1] = firsts[b];
    firsts[b + 1] += counts.Blocks[b];
    firstFace[b] = counts.FirstFaceOf(b, this->FaceOffsets);
  }
  firstFace[blocks] = this->GetNumFaces();
  const Index numEdges = firsts[blocks].Edges;
  this->NumBoundaryEdges = firsts[blocks].Boundary;
  this->NumNonManifoldEdges = firsts[blocks].NonManifold;
  this->FaceEdges.resize(this->FaceVertices.size());
  this->EdgeVertices.resize(2 * static_cast<size_t>(numEdges));
  this->EdgeFaceOffsets.resize(static_cast<size_t>(numEdges) + 1);
  this->EdgeFaceOffsets[numEdges] = firsts[blocks].EdgeFaces;
  this->EdgeTags.resize(static_cast<size_t>(numEdges));
  ForEachBlock(blocks, parallelFor, [&](Index b) {
    Index e = firsts[b].Edges;
    Index slot = firsts[b].EdgeFaces;
    for (Index f = firstFace[b]; f < firstFace[b + 1]; ++f)
    {
      const Index first = this->FaceOffsets[f], last = this->FaceOffsets[f + 1];
      for (Index h = first; h < last; ++h)
      {
        const HalfEdgePair& group = pairing[h];
        if (group.Representative != h)
        {
          continue;
        }
        this->FaceEdges[h] = e;
        this->EdgeVertices[2 * static_cast<size_t>(e)] = this->FaceVertices[h];
        this->EdgeVertices[2 * static_cast<size_t>(e) + 1] = this->FaceVertices[h + 1 < last ? h + 1 : first];
        this->EdgeFaceOffsets[e] = slot;
        slot += group.GroupSize();
        EdgeTag& tag = this->EdgeTags[e];
        tag.Boundary = group.GroupSize() == 1;
        tag.NonManifold = group.IsNonManifold();
        ++e;
      }
    }
  });
}

// The other half-edges of each edge take its number from the first (NumberEdges wrote only
// the first's), and each edge's faces come in increasing order: its half-edges' ranks in
// their pairing. One pass over the corners for both.
void MeshTopology::BuildEdgeFaces(const HalfEdgePairing& pairing, const ParallelFor& parallelFor)
{
  this->EdgeFaces.resize(this->FaceEdges.size());
  parallelFor(0, this->GetNumFaces(), [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f)
    {
      for (Index h = this->FaceOffsets[f]; h < this->FaceOffsets[f + 1]; ++h)
      {
        const HalfEdgePair& pair = pairing[h];
        const Index e = this->FaceEdges[pair.Representative];
        if (pair.Representative != h) // a group's first entry is read by other threads: not rewritten
        {
          this->FaceEdges[h] = e;
        }
        this->EdgeFaces[this->EdgeFaceOffsets[e] + pair.Rank(h)] = f;
      }
    }
  });
}

// A vertex's edges in increasing order: each edge filed at both its ends.
void MeshTopology::BuildVertexEdges(const ParallelFor& parallelFor)
{
  const Index numEdges = this->GetNumEdges();
  this->VertexEdges.resize(this->EdgeVertices.size());
  auto edgeEnds = [this](Index begin, Index end, const auto& visit) {
    for (Index e = begin; e < end; ++e)
    {
      visit(this->EdgeVertices[2 * static_cast<size_t>(e)], e);
      visit(this->EdgeVertices[2 * static_cast<size_t>(e) + 1], e);
    }
  };
  FileByKey(this->NumVertices, numEdges, edgeEnds, [this](Index slot, Index e) { this->VertexEdges[slot] = e; },
    this->VertexEdgeOffsets, parallelFor);
  this->MaxValence = 0;
  for (Index v = 0; v < this->NumVertices; ++v)
  {
    this->MaxValence = std::max(this->MaxValence, this->VertexEdgeOffsets[v + 1] - this->VertexEdgeOffsets[v]);
  }
}

// A vertex is manifold when its edges are and its faces form one fan: counted while pairing
// the half-edges for up to 32 faces (`smallFans`), by CountFans beyond.
void MeshTopology::TagVertices(const IndexArray& smallFans, const ParallelFor& parallelFor)
{
  this->VertexTags.resize(static_cast<size_t>(this->NumVertices));
  parallelFor(0, this->NumVertices, [this, &smallFans](Index begin, Index end) {
    std::vector<Index> fanScratch;
    for (Index v = begin; v < end; ++v)
    {
      VertexTag tag{ 0, 0 };
      for (Index e : this->GetVertexEdges(v))
      {
        tag.Boundary |= this->EdgeTags[e].Boundary;
        tag.NonManifold |= this->EdgeTags[e].NonManifold;
      }
      if (!tag.NonManifold)
      {
        const Index fans = smallFans[v] != InvalidIndex ? smallFans[v] : this->CountFans(v, fanScratch);
        tag.NonManifold = fans > 1;
      }
      this->VertexTags[v] = tag;
    }
  });
  this->NumNonManifoldVertices = 0;
  for (const VertexTag& tag : this->VertexTags)
  {
    this->NumNonManifoldVertices += tag.NonManifold;
  }
}

// The fans of v's faces (of a vertex with manifold edges), joined across v's edges with two
// faces by a union-find over v's own lists: for vertices of more than 32 faces, where
// PairHalfEdges' chains of followers stop.
Index MeshTopology::CountFans(Index v, std::vector<Index>& parent) const
{
  const IndexSpan faces = this->GetVertexFaces(v);
  if (faces.size() <= 1)
  {
    return faces.size();
  }
  parent.resize(faces.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&parent](Index i) {
    while (parent[i] != i)
    {
      i = parent[i] = parent[parent[i]];
    }
    return i;
  };
  // Faces of a vertex are stored in increasing order: binary search gives local slots.
  auto slot = [&faces](Index f) {
    return static_cast<Index>(std::lower_bound(faces.begin(), faces.end(), f) - faces.begin());
  };
  Index groups = faces.size();
  for (Index e : this->GetVertexEdges(v))
  {
    const IndexSpan ef = this->GetEdgeFaces(e);
    if (ef.size() == 2)
    {
      const Index r0 = root(slot(ef[0])), r1 = root(slot(ef[1]));
      if (r0 != r1)
      {
        parent[r0] = r1;
        --groups;
      }
    }
  }
  return groups;
}

Index MeshTopology::GetTriangleOppositeVertex(Index f, Index e) const
{
  const Index* ev = this->GetEdgeVertices(e);
  return this->GetTriangleThirdVertex(f, ev[0], ev[1]);
}

Index MeshTopology::GetEdgePositionInLargeFace(Index f, Index e) const
{
  // The edge starts or ends at the corner of its first vertex, found through that vertex's
  // faces.
  const IndexSpan fe = this->GetFaceEdges(f);
  const Index i = this->FindCorner(this->GetEdgeVertices(e)[0], f);
  const Index before = i == 0 ? fe.size() - 1 : i - 1;
  if (fe[i] == e || fe[before] == e)
  {
    return fe[i] == e ? i : before;
  }
  return static_cast<Index>(std::find(fe.begin(), fe.end(), e) - fe.begin()); // a vertex f repeats
}

Index MeshTopology::FindCorner(Index v, Index f) const
{
  const IndexSpan faces = this->GetVertexFaces(v);
  const Index* it = std::lower_bound(faces.begin(), faces.end(), f);
  if (it == faces.end() || *it != f)
  {
    return InvalidIndex;
  }
  return this->GetVertexFaceCorners(v)[static_cast<Index>(it - faces.begin())];
}

bool MeshTopology::GetOrderedVertexFaces(
  Index v, std::vector<Index>& faces, std::vector<Index>& corners) const
{
  faces.clear();
  corners.clear();
  const IndexSpan vf = this->GetVertexFaces(v);
  if (vf.empty() || this->VertexTags[v].NonManifold)
  {
    return false;
  }
  // Start: any face for an interior vertex; for a boundary vertex, the face whose edge
  // leaving v (edge at v's corner) is a boundary edge, so the walk covers the whole fan.
  Index face = vf[0];
  Index corner = this->GetVertexFaceCorners(v)[0];
  if (this->VertexTags[v].Boundary)
  {
    for (Index i = 0; i < vf.size(); ++i)
    {
      const Index c = this->GetVertexFaceCorners(v)[i];
      if (this->EdgeTags[this->GetFaceEdges(vf[i])[c]].Boundary)
      {
        face = vf[i];
        corner = c;
        break;
      }
    }
  }
  const IndexSpan vc = this->GetVertexFaceCorners(v);
  const Index K = vf.size();
  constexpr Index chainValence = 64;
  if (K <= chainValence)
  {
    // The next face is the one whose edge leaving v is the edge entering v in this one
    // (the two faces of a manifold edge at a manifold vertex run it in opposite directions):
    // match them among v's faces, whose corners are independent loads, instead of walking
    // across edges, where each step waits on the one before. An edge is a pair of vertices,
    // so the edges match when the vertex one face leaves v toward is the one the other
    // enters v from: the faces' own corners, which callers go on to read, and no edge list.
    Index leaving[chainValence], entering[chainValence];
    Index current = 0;
    for (Index k = 0; k < K; ++k)
    {
      const IndexSpan fv = this->GetFaceVertices(vf[k]);
      leaving[k] = fv[vc[k] + 1 == fv.size() ? 0 : vc[k] + 1];
      entering[k] = fv[vc[k] == 0 ? fv.size() - 1 : vc[k] - 1];
      current = vf[k] == face ? k : current;
    }
    for (Index step = 0; step < K && current != InvalidIndex; ++step)
    {
      faces.push_back(vf[current]);
      corners.push_back(vc[current]);
      current = FollowerOf(current, K, leaving, entering);
    }
    return static_cast<Index>(faces.size()) == K;
  }
  for (Index step = 0; step < K; ++step)
  {
    faces.push_back(face);
    corners.push_back(corner);
    // Cross the edge entering v in this face (edge at the previous corner).
    const Index n = this->GetFaceSize(face);
    const Index entering = this->GetFaceEdges(face)[corner == 0 ? n - 1 : corner - 1];
    const IndexSpan ef = this->GetEdgeFaces(entering);
    if (ef.size() != 2)
    {
      break; // reached the boundary
    }
    face = OtherOfTwo(ef, face);
    corner = this->FindCorner(v, face);
  }
  return static_cast<Index>(faces.size()) == K;
}

Index MeshTopology::FindEdge(Index a, Index b) const
{
  if (a < 0 || a >= this->NumVertices)
  {
    return InvalidIndex;
  }
  for (Index e : this->GetVertexEdges(a))
  {
    if (this->GetOtherEndpoint(e, a) == b)
    {
      return e;
    }
  }
  return InvalidIndex;
}
}
