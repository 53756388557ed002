#include "SubDSqrt3GrandparentRows.h"
#include "SubDRowWriting.h"
#include "SubDShortLists.h"
#include "SubDSqrt3Rules.h"
#include "SubDTriangleFans.h"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <vector>

namespace subd
{
namespace
{
constexpr auto NextCorner = TriangleFans::NextCorner;

// The half-edges of the grandparent P's pair of triangles 2e, 2e + 1 of the parent C, if
// they have the closed form (F + a, f2, f1), (F + b, f1, f2): a->b in f1 (first), b->a in f2.
bool FlippedPair(const Index* pv, Index numFaces, const Index* t0, const Index* t1, Index& first, Index& second)
{
  const Index f1 = t0[2], f2 = t0[1];
  if (t0[0] < numFaces || t1[0] < numFaces || f1 >= numFaces || f2 >= numFaces || f1 == f2 || t1[1] != f1 ||
    t1[2] != f2)
  {
    return false;
  }
  const Index a = t0[0] - numFaces, b = t1[0] - numFaces;
  const Index i = PlaceInTriangle(pv + 3 * static_cast<size_t>(f1), a);
  const Index j = PlaceInTriangle(pv + 3 * static_cast<size_t>(f2), b);
  if (i > 2 || j > 2)
  {
    return false; // a triangle with a repeated corner
  }
  first = 3 * f1 + i;
  second = 3 * f2 + j;
  return pv[first] == a && pv[second] == b && pv[NextCorner(first)] == b && pv[NextCorner(second)] == a &&
    first < second;
}

// The rows of the grandchild's points from the grandparent's triangles (see the header),
// as a row writer (SubDRowWriting.h).
class Sqrt3GrandparentRowWriter
{
public:
  Sqrt3GrandparentRowWriter(
    const Level& grandparent, const ParallelFor& parallelFor, std::shared_ptr<const TriangleFans> fans)
    : Corners(grandparent.Topology.GetFaceVertexArray().data())
    , NumFaces(grandparent.Topology.GetNumFaces())
    , NumVertices(grandparent.Topology.GetNumVertices())
    , Fans(fans ? std::move(fans) : TriangleFans::Build(this->Corners, this->NumFaces, this->NumVertices, parallelFor))
  {
    if (!this->Fans)
    {
      throw std::logic_error("sqrt(3) rows from the grandparent: the grandparent is not a closed manifold");
    }
    const size_t numCorners = 3 * static_cast<size_t>(this->NumFaces);
    this->FirstHalf.reserve(numCorners / 2); // closed: two half-edges per edge
    for (size_t h = 0; h < numCorners; ++h)
    {
      if (static_cast<Index>(h) < this->Fans->GetTwin(static_cast<Index>(h)))
      {
        this->FirstHalf.push_back(static_cast<Index>(h));
      }
    }
    for (Index n = 1; n < MaxTabulatedValence; ++n)
    {
      this->Alphas[n] = Sqrt3Alpha(n);
    }
  }

  Index GetNumParents() const { return this->NumFaces + this->NumVertices; }
  Index GetNumRows() const { return 4 * this->NumFaces + this->NumVertices; }
  std::vector<Index> GetBlockEnds() const { return { this->GetNumRows() }; }
  Index GetMaxRowSize() const { return 1 + std::max<Index>(6, this->Fans->GetMaxValence()); }

  Index WriteRow(Index row, Index* src, double* wts) const
  {
    Index size = 0;
    this->VisitRow(row, [&](Index s, double w) {
      src[size] = s;
      wts[size++] = w;
    });
    return size;
  }

  template <typename T>
  bool ApplySmoothRow(Index row, const T* parents, const T*, T* dst) const
  {
    PointSum sum;
    this->VisitRow(row, [&](Index s, double w) { sum.Add(w, parents + 3 * static_cast<size_t>(s)); });
    sum.Store(dst);
    return true;
  }

  template <typename T>
  void PrefetchRow(Index row, const T* parents, const T*) const
  {
    this->VisitRow(row, [parents](Index s, double) { PrefetchPoint(parents + 3 * static_cast<size_t>(s)); });
  }

private:
  // Calls visit(source, weight) for the entries of the row, in the order Sqrt3's row writer
  // writes the parent's: a triangle's centroid (its corners), else a relaxed point (itself,
  // then its ring in increasing order).
  template <typename Visit>
  void VisitRow(Index row, Visit&& visit) const
  {
    const Index numTriangles = 3 * this->NumFaces; // two per edge of P
    if (row < numTriangles)
    {
      const Index h = this->FirstHalf[row / 2];
      const Index f1 = h / 3, f2 = this->Fans->GetTwin(h) / 3;
      const Index end = this->NumFaces + this->Corners[row % 2 == 0 ? h : NextCorner(h)];
      visit(end, 1.0 / 3.0);
      visit(row % 2 == 0 ? f2 : f1, 1.0 / 3.0);
      visit(row % 2 == 0 ? f1 : f2, 1.0 / 3.0);
      return;
    }
    const Index point = row - numTriangles;
    if (point < this->NumFaces)
    {
      // A centroid: the three across its edges, then its corners (all above the centroids).
      const size_t first = 3 * static_cast<size_t>(point);
      const TriangleFans& fans = *this->Fans;
      Index across[3] = { fans.GetTwin(first) / 3, fans.GetTwin(first + 1) / 3, fans.GetTwin(first + 2) / 3 };
      Index ends[3] = { this->Corners[first], this->Corners[first + 1], this->Corners[first + 2] };
      SortShortList(across, across + 3);
      SortShortList(ends, ends + 3);
      const double alpha = this->Alpha(6);
      visit(point, 1.0 - alpha);
      for (Index f : across)
      {
        visit(f, alpha / 6);
      }
      for (Index v : ends)
      {
        visit(this->NumFaces + v, alpha / 6);
      }
      return;
    }
    // An old vertex: the centroids of its faces, walked around it and sorted. Walking costs
    // the memory of no list.
    FanScratch faces(this->Fans->GetMaxValence());
    const Index n = this->Fans->SortedFaces(point - this->NumFaces, faces.data());
    const double alpha = this->Alpha(n);
    visit(point, 1.0 - alpha);
    for (Index k = 0; k < n; ++k)
    {
      visit(faces.data()[k], alpha / n);
    }
  }

  double Alpha(Index n) const { return n < MaxTabulatedValence ? this->Alphas[n] : Sqrt3Alpha(n); }

  static constexpr Index MaxTabulatedValence = 16;
  const Index* Corners; // the grandparent's triangles (kept by WrittenRows)
  Index NumFaces, NumVertices;
  std::shared_ptr<const TriangleFans> Fans; // P's, maybe shared with P's own rows
  IndexArray FirstHalf;                     // per edge of P: its first half-edge
  double Alphas[MaxTabulatedValence] = {};
};

using Sqrt3GrandparentRows = WrittenRows<Sqrt3GrandparentRowWriter>;
}

bool Sqrt3RowsFromGrandparentApply(const Level& grandparent, const Level& parent, const ParallelFor& parallelFor)
{
  const MeshTopology& p = grandparent.Topology;
  const MeshTopology& c = parent.Topology;
  const Index numFaces = p.GetNumFaces();
  if (numFaces == 0 || p.GetNumFaceCorners() != 3 * numFaces || c.GetNumFaces() != 3 * numFaces ||
    c.GetNumFaceCorners() != 3 * c.GetNumFaces() || c.GetNumVertices() != numFaces + p.GetNumVertices() ||
    !c.HasVertexFaceCounts() || c.GetNumBoundaryEdges() > 0 || c.GetNumNonManifoldEdges() > 0 ||
    c.GetNumNonManifoldVertices() > 0 || parent.HasSharpFeatures())
  {
    return false;
  }
  std::atomic<bool> fits{ true };
  parallelFor(0, c.GetNumVertices(), [&](Index begin, Index end) {
    bool here = true;
    for (Index x = begin; x < end && here; ++x)
    {
      here = c.GetNumVertexFaces(x) > 0; // no vertex without faces (it would stay put)
    }
    fits = fits && here;
  });
  // Every triangle pair in the closed form, the first half-edges increasing, and every
  // half-edge of P met once (a bit each): then each edge of P has two half-edges, its
  // triangles' pair.
  const size_t numCorners = 3 * static_cast<size_t>(numFaces);
  std::vector<std::atomic<std::uint64_t>> met((numCorners + 63) / 64);
  for (auto& word : met)
  {
    word.store(0, std::memory_order_relaxed);
  }
  const Index* pv = p.GetFaceVertexArray().data();
  const Index* cv = c.GetFaceVertexArray().data();
  auto meetOnce = [&met](Index h) {
    const std::uint64_t bit = std::uint64_t(1) << (h % 64);
    return (met[static_cast<size_t>(h) / 64].fetch_or(bit, std::memory_order_relaxed) & bit) == 0;
  };
  parallelFor(0, c.GetNumFaces() / 2, [&](Index begin, Index end) {
    bool here = fits;
    Index previous = -1;
    if (here && begin > 0)
    {
      Index unused;
      const size_t t = 6 * static_cast<size_t>(begin - 1);
      here = FlippedPair(pv, numFaces, cv + t, cv + t + 3, previous, unused);
    }
    for (Index e = begin; e < end && here; ++e)
    {
      Index first, second;
      const size_t t = 6 * static_cast<size_t>(e);
      here = FlippedPair(pv, numFaces, cv + t, cv + t + 3, first, second) && first > previous && meetOnce(first) &&
        meetOnce(second);
      previous = first;
    }
    fits = fits && here;
  });
  return fits;
}

std::shared_ptr<const RowSource> MakeSqrt3RowSourceFromGrandparent(
  std::shared_ptr<const Level> grandparent, const ParallelFor& parallelFor, std::shared_ptr<const TriangleFans> fans)
{
  return std::make_shared<Sqrt3GrandparentRows>(std::move(grandparent), parallelFor, std::move(fans));
}

bool IsSqrt3RowSourceFromGrandparent(const RowSource* rows)
{
  return dynamic_cast<const Sqrt3GrandparentRows*>(rows) != nullptr;
}
}
