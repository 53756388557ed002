// SubD kernel: the fans of a closed manifold triangle mesh, walked without lists around the
// vertices.
//
// Corner h of triangle h / 3 starts the half-edge from it to the next corner of the same
// triangle. Its twin is the corner of the half-edge running back along the same edge, and
// on a closed manifold mesh every vertex's corners form one closed fan: from any corner at
// v, the next corner around v is the one after the twin of the last (the triangle across
// the edge the last leaves v by). Two tables (a twin per corner, a corner per vertex to
// start from: 4 bytes each) then give each vertex's triangles and neighbours, where lists
// of them would take as much again per corner and a prefix per vertex.
#ifndef SubDTriangleFans_h
#define SubDTriangleFans_h

#include "SubDParallel.h"
#include "SubDShortLists.h"
#include "SubDTypes.h"

#include <memory>
#include <vector>

namespace subd
{
class SUBDKERNEL_EXPORT TriangleFans
{
public:
  /// The fans of the triangles `corners` (three per face, `numFaces` faces) over
  /// `numVertices` vertices, or nullptr unless every half-edge has exactly one twin and
  /// every vertex one closed fan (a closed manifold mesh without unused vertices).
  static std::shared_ptr<const TriangleFans> Build(
    const Index* corners, Index numFaces, Index numVertices, const ParallelFor& parallelFor = SerialFor);

  /// The corners after and before corner h in its triangle.
  static Index NextCorner(Index h) { return h % 3 == 2 ? h - 2 : h + 1; }
  static Index PreviousCorner(Index h) { return h % 3 == 0 ? h + 2 : h - 1; }

  Index GetTwin(Index h) const { return this->Twin[h]; }
  Index GetNumVertices() const { return static_cast<Index>(this->FanStart.size()); }
  Index GetMaxValence() const { return this->MaxValence; }

  /// Calls visit(corner) for the corners at v, around its fan.
  template <typename Visit>
  void ForEachCorner(Index v, Visit&& visit) const
  {
    const Index start = this->FanStart[v];
    Index corner = start;
    Index n = 0;
    do
    {
      visit(corner);
      corner = NextCorner(this->Twin[corner]);
    } while (corner != start && ++n < this->MaxValence);
  }

  /// v's neighbours (the ends of the half-edges leaving it), in increasing order, written to
  /// `out` (room for GetMaxValence()); returns how many. `corners` are the triangles the
  /// fans were built from.
  Index SortedNeighbours(const Index* corners, Index v, Index* out) const
  {
    Index n = 0;
    this->ForEachCorner(v, [&](Index h) { out[n++] = corners[NextCorner(h)]; });
    SortShortList(out, out + n);
    return n;
  }

  /// v's triangles in increasing order, written to `out` (room for GetMaxValence()).
  Index SortedFaces(Index v, Index* out) const
  {
    Index n = 0;
    this->ForEachCorner(v, [&](Index h) { out[n++] = h / 3; });
    SortShortList(out, out + n);
    return n;
  }

  /// The bytes the tables hold.
  size_t GetBytes() const { return sizeof(Index) * (this->Twin.size() + this->FanStart.size()); }

private:
  IndexArray Twin;     // per corner
  IndexArray FanStart; // per vertex: a corner at it
  Index MaxValence = 0;
};

/// Room for one fan's entries: on the stack up to 64, else on the heap.
class FanScratch
{
public:
  explicit FanScratch(Index maxValence)
    : Data(this->Stack)
  {
    if (maxValence > OnStack)
    {
      this->Heap.resize(static_cast<size_t>(maxValence));
      this->Data = this->Heap.data();
    }
  }
  FanScratch(const FanScratch&) = delete;
  FanScratch& operator=(const FanScratch&) = delete;
  Index* data() { return this->Data; }

private:
  static constexpr Index OnStack = 64;
  Index Stack[OnStack];
  std::vector<Index> Heap;
  Index* Data;
};
}

#endif
