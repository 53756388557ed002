#include "SubDDooSabinRules.h"
#include "SubDDualSplit.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace subd
{
double DooSabinWeight(Index n, Index d)
{
  if (d % n == 0)
  {
    return (n + 5.0) / (4.0 * n);
  }
  const double pi = 3.14159265358979323846;
  return (3.0 + 2.0 * std::cos(2.0 * pi * d / n)) / (4.0 * n);
}

namespace
{
// Whether the edge leaving corner `corner` (corner j's edge runs to corner j + 1) acts as a
// boundary (DualPoints::EdgeActsAsBoundary).
bool ActsAsBoundaryAfter(const MeshTopology& topo, const DualPoints& points, Index corner)
{
  return points.EdgeActsAsBoundary[topo.GetFaceEdgeArray()[corner]] != 0;
}

// The boundary row of corner `j` of face f at vertex v, if one of the face's two edges at v
// is a crease (or boundary) edge or v pins every corner: the vertex itself at a corner
// vertex, else Chaikin's 3/4, 1/4 (or 1/2, 1/2 next to a corner vertex) along that edge, the
// outgoing one if both are (a turn corner: the row of its first point, DualPoints::
// TurnCorners; its second point's row is that of the corner across its incoming edge).
// Returns the number of entries written (0: interior).
Index BoundaryCornerRow(const Level& level, const DualPoints& points, Index f, Index j, Index* src, double* wts)
{
  const MeshTopology& topo = level.Topology;
  const std::vector<std::uint8_t>& isCorner = points.IsCornerVertex;
  const IndexSpan fv = topo.GetFaceVertices(f);
  const Index first = topo.GetFaceOffset(f);
  const Index n = fv.size();
  const Index v = fv[j];
  const bool outgoing = ActsAsBoundaryAfter(topo, points, first + j);
  const bool incoming = ActsAsBoundaryAfter(topo, points, first + (j + n - 1) % n);
  if (!outgoing && !incoming && !points.PinsEveryCorner[v])
  {
    return 0;
  }
  src[0] = v;
  if (isCorner[v])
  {
    wts[0] = 1.0;
    return 1;
  }
  const Index w = outgoing ? fv[(j + 1) % n] : fv[(j + n - 1) % n];
  const double toward = isCorner[w] ? 0.5 : 0.25;
  wts[0] = 1.0 - toward;
  src[1] = w;
  wts[1] = toward;
  return 2;
}

// The weights alpha_n(d), d = 0..n-1, of the face sizes most meshes have, tabulated once:
// the cosines would otherwise be most of the cost of writing a row.
class DooSabinWeightTable
{
public:
  DooSabinWeightTable()
  {
    for (Index n = 3; n <= MaxSize; ++n)
    {
      for (Index d = 0; d < n; ++d)
      {
        this->Weights[n][d] = DooSabinWeight(n, d);
      }
    }
  }
  /// alpha_n((i - k) mod n) for k = 0..n-1 into `out`.
  void WriteRow(Index n, Index i, double* out) const
  {
    for (Index k = 0; k < n; ++k)
    {
      const Index d = (i - k + n) % n;
      out[k] = n <= MaxSize ? this->Weights[n][d] : DooSabinWeight(n, d);
    }
  }

private:
  static constexpr Index MaxSize = 8;
  double Weights[MaxSize + 1][MaxSize] = {};
};

// Writes the row of corner i of face f: its boundary row, else the face's vertices with
// alpha_n. Returns the row's size (at most the face's size, and 2 on a boundary).
Index WriteCornerRow(const Level& parent, const DualPoints& points, const DooSabinWeightTable& weights, Index f,
  Index i, Index* src, double* wts)
{
  const Index boundary = BoundaryCornerRow(parent, points, f, i, src, wts);
  if (boundary > 0)
  {
    return boundary;
  }
  const IndexSpan fv = parent.Topology.GetFaceVertices(f);
  std::copy(fv.begin(), fv.end(), src);
  weights.WriteRow(fv.size(), i, wts);
  return fv.size();
}

// The face a corner belongs to (binary search over the faces' offsets).
Index FaceOfCorner(const MeshTopology& topo, Index corner)
{
  const IndexArray& offsets = topo.GetFaceOffsetArray();
  return static_cast<Index>(std::upper_bound(offsets.begin(), offsets.end(), corner) - offsets.begin()) - 1;
}

// BuildDooSabinStencils' rows written as they are applied (WriteCornerRow, the one writer of
// both), from the parent and its dual numbering.
class DooSabinWrittenRows final : public RowSourceWithApply<DooSabinWrittenRows>
{
  friend class RowSourceWithApply<DooSabinWrittenRows>;

public:
  DooSabinWrittenRows(std::shared_ptr<const Level> parent, const ParallelFor& parallelFor)
    : Parent(std::move(parent))
    , Points(NumberDualPoints(*this->Parent, parallelFor))
  {
    const MeshTopology& topo = this->Parent->Topology;
    for (Index f = 0; f < topo.GetNumFaces(); ++f)
    {
      this->MaxRowSize = std::max(this->MaxRowSize, topo.GetFaceSize(f));
    }
  }
  Index GetNumParents() const override { return this->Parent->Topology.GetNumVertices(); }
  Index GetNumRows() const override { return this->Points.NumPoints; }
  std::vector<Index> GetBlockEnds() const override { return { this->Points.NumPoints }; }

private:
  template <typename T>
  void Apply(const T* parents, T* children, int components, Index begin, Index end) const
  {
    if (begin >= end)
    {
      return;
    }
    const MeshTopology& topo = this->Parent->Topology;
    const Index numParents = topo.GetNumVertices();
    std::vector<Index> src(static_cast<size_t>(this->MaxRowSize));
    std::vector<double> wts(src.size()), sum(static_cast<size_t>(components));
    auto applyCorner = [&](Index f, Index corner, Index row) {
      const Index size =
        WriteCornerRow(*this->Parent, this->Points, this->Weights, f, corner - topo.GetFaceOffset(f),
          src.data(), wts.data());
      ApplyRow(src.data(), wts.data(), size, numParents, parents, children, components, sum.data(),
        children + static_cast<size_t>(row) * components);
    };
    if (this->Points.Unwelded)
    {
      // Rows are corners, in the order of the faces: walk the faces from the first row's.
      for (Index f = FaceOfCorner(topo, begin), corner = begin; corner < end; ++f)
      {
        const Index first = topo.GetFaceOffset(f);
        const Index stop = std::min(end, topo.GetFaceOffset(f + 1));
        if (components != 3 || !this->HasInteriorCorners(f))
        {
          for (; corner < stop; ++corner)
          {
            applyCorner(f, corner, corner);
          }
          continue;
        }
        // Every corner's row is alpha_n over the face's vertices: summed straight from them,
        // in the row's order (the same bits as the written row).
        const IndexSpan fv = topo.GetFaceVertices(f);
        for (; corner < stop; ++corner)
        {
          this->Weights.WriteRow(fv.size(), corner - first, wts.data());
          PointSum point;
          for (Index k = 0; k < fv.size(); ++k)
          {
            point.Add(wts[k], parents + 3 * static_cast<size_t>(fv[k]));
          }
          point.Store(children + 3 * static_cast<size_t>(corner));
        }
      }
      return;
    }
    for (Index row = begin; row < end; ++row)
    {
      const Index corner = this->Points.CornerOf(row);
      applyCorner(FaceOfCorner(topo, corner), corner, row);
    }
  }

  // No corner of face f has a boundary row (BoundaryCornerRow): no edge of it acts as a
  // boundary, no vertex of it pins its corners.
  bool HasInteriorCorners(Index f) const
  {
    const MeshTopology& topo = this->Parent->Topology;
    for (Index corner = topo.GetFaceOffset(f); corner < topo.GetFaceOffset(f + 1); ++corner)
    {
      if (ActsAsBoundaryAfter(topo, this->Points, corner))
      {
        return false;
      }
    }
    const IndexSpan fv = topo.GetFaceVertices(f);
    return std::none_of(fv.begin(), fv.end(), [this](Index v) { return this->Points.PinsEveryCorner[v] != 0; });
  }

  std::shared_ptr<const Level> Parent;
  DualPoints Points;
  DooSabinWeightTable Weights;
  Index MaxRowSize = 2; // a boundary row's size, at least
};
}

StencilTable BuildDooSabinStencils(const Level& parent, const DualPoints& points, const ParallelFor& parallelFor)
{
  const MeshTopology& topo = parent.Topology;
  const Index numFaces = topo.GetNumFaces();
  // Welded corners have equal rows; each point takes its first corner's.
  auto ownsRow = [&points](Index corner) { return points.CornerOf(points.PointOf(corner)) == corner; };
  StencilTable table(topo.GetNumVertices());
  table.ReserveRows(points.NumPoints);
  parallelFor(0, numFaces, [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f)
    {
      const Index n = topo.GetFaceSize(f);
      for (Index j = 0; j < n; ++j)
      {
        const Index corner = topo.GetFaceOffset(f) + j;
        if (ownsRow(corner))
        {
          Index scratchSource[2];
          double scratchWeight[2];
          const Index boundary = BoundaryCornerRow(parent, points, f, j, scratchSource, scratchWeight);
          table.SetRowSize(points.PointOf(corner), boundary > 0 ? boundary : n);
        }
      }
    }
  });
  table.FinalizeSizesUnfilled();
  const DooSabinWeightTable weights;
  parallelFor(0, numFaces, [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f)
    {
      for (Index i = 0; i < topo.GetFaceSize(f); ++i)
      {
        const Index corner = topo.GetFaceOffset(f) + i;
        if (ownsRow(corner))
        {
          const Index point = points.PointOf(corner);
          WriteCornerRow(
            parent, points, weights, f, i, table.GetMutableSources(point), table.GetMutableWeights(point));
        }
      }
    }
  });
  table.EndBlock(points.NumPoints);
  return table;
}

std::shared_ptr<const RowSource> MakeDooSabinRowSource(std::shared_ptr<const Level> parent, const ParallelFor& parallelFor)
{
  return std::make_shared<DooSabinWrittenRows>(std::move(parent), parallelFor);
}
}

