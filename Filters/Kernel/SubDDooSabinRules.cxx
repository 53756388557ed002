#include "SubDDooSabinRules.h"
#include "SubDDualSplit.h"

#include <algorithm>
#include <cmath>

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
// The boundary row of corner `j` of face f at vertex v, if one of the face's two edges at v
// is a crease (or boundary) edge or v pins every corner: the vertex itself at a corner
// vertex, else Chaikin's 3/4, 1/4 (or 1/2, 1/2 next to a corner vertex). Returns the number
// of entries written (0: interior).
Index BoundaryCornerRow(const Level& level, const DualPoints& points, Index f, Index j, Index* src, double* wts)
{
  const MeshTopology& topo = level.Topology;
  const std::vector<std::uint8_t>& isCorner = points.IsCornerVertex;
  const IndexSpan fv = topo.GetFaceVertices(f);
  const IndexSpan fe = topo.GetFaceEdges(f);
  const Index n = fv.size();
  const Index v = fv[j];
  const bool outgoing = points.EdgeActsAsBoundary[fe[j]];
  const bool incoming = points.EdgeActsAsBoundary[fe[(j + n - 1) % n]];
  if (!outgoing && !incoming && !points.PinsEveryCorner[v])
  {
    return 0;
  }
  src[0] = v;
  if ((outgoing && incoming) || isCorner[v])
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
}

StencilTable BuildDooSabinStencils(const Level& parent, const DualPoints& points, const ParallelFor& parallelFor)
{
  const MeshTopology& topo = parent.Topology;
  const Index numFaces = topo.GetNumFaces();
  // Welded corners have equal rows; each point takes its first corner's.
  auto ownsRow = [&points](Index corner) {
    return points.Unwelded || points.CornerOfPoint[points.PointOfCorner[corner]] == corner;
  };
  StencilTable table(topo.GetNumVertices());
  table.ReserveRows(static_cast<Index>(points.CornerOfPoint.size()));
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
          table.SetRowSize(points.PointOfCorner[corner], boundary > 0 ? boundary : n);
        }
      }
    }
  });
  table.FinalizeSizesUnfilled();
  const DooSabinWeightTable weights;
  parallelFor(0, numFaces, [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f)
    {
      const IndexSpan fv = topo.GetFaceVertices(f);
      const Index n = fv.size();
      for (Index i = 0; i < n; ++i)
      {
        const Index corner = topo.GetFaceOffset(f) + i;
        if (!ownsRow(corner))
        {
          continue;
        }
        Index* src = table.GetMutableSources(points.PointOfCorner[corner]);
        double* wts = table.GetMutableWeights(points.PointOfCorner[corner]);
        if (BoundaryCornerRow(parent, points, f, i, src, wts) == 0)
        {
          std::copy(fv.begin(), fv.end(), src);
          weights.WriteRow(n, i, wts);
        }
      }
    }
  });
  table.EndBlock(static_cast<Index>(points.CornerOfPoint.size()));
  return table;
}
}
