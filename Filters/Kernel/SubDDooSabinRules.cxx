#include "SubDDooSabinRules.h"

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
bool IsBoundaryLike(const MeshTopology& topo, Index e)
{
  return topo.GetEdgeFaces(e).size() != 2 || topo.GetEdgeTag(e).NonManifold;
}

bool IsCorner(const MeshTopology& topo, Index v)
{
  return topo.GetVertexFaces(v).size() == 1;
}

// The boundary row of corner `j` of face f at vertex v, if one of the face's two edges at v
// is on the boundary: the vertex itself at a corner of the mesh, else Chaikin's 3/4, 1/4 (or
// 1/2, 1/2 next to a corner of the mesh). Returns the number of entries written (0: interior).
Index BoundaryCornerRow(const MeshTopology& topo, Index f, Index j, Index* src, double* wts)
{
  const IndexSpan fv = topo.GetFaceVertices(f);
  const IndexSpan fe = topo.GetFaceEdges(f);
  const Index n = fv.size();
  const Index v = fv[j];
  const bool outgoing = IsBoundaryLike(topo, fe[j]);
  const bool incoming = IsBoundaryLike(topo, fe[(j + n - 1) % n]);
  if (!outgoing && !incoming)
  {
    return 0;
  }
  src[0] = v;
  if ((outgoing && incoming) || IsCorner(topo, v))
  {
    wts[0] = 1.0;
    return 1;
  }
  const Index w = outgoing ? fv[(j + 1) % n] : fv[(j + n - 1) % n];
  const double toward = IsCorner(topo, w) ? 0.5 : 0.25;
  wts[0] = 1.0 - toward;
  src[1] = w;
  wts[1] = toward;
  return 2;
}
}

StencilTable BuildDooSabinStencils(const Level& parent)
{
  const MeshTopology& topo = parent.Topology;
  const Index numFaces = topo.GetNumFaces();
  StencilTable table(topo.GetNumVertices());
  table.ReserveRows(topo.GetNumFaceCorners());
  for (Index f = 0; f < numFaces; ++f)
  {
    const Index n = topo.GetFaceSize(f);
    for (Index j = 0; j < n; ++j)
    {
      Index scratchSource[2];
      double scratchWeight[2];
      const Index boundary = BoundaryCornerRow(topo, f, j, scratchSource, scratchWeight);
      table.SetRowSize(topo.GetFaceOffset(f) + j, boundary > 0 ? boundary : n);
    }
  }
  table.FinalizeSizes();
  std::vector<double> weights;
  for (Index f = 0; f < numFaces; ++f)
  {
    const IndexSpan fv = topo.GetFaceVertices(f);
    const Index n = fv.size();
    // Weights depend on (i - k) mod n only: tabulate once per face.
    weights.resize(static_cast<size_t>(n));
    for (Index d = 0; d < n; ++d)
    {
      weights[d] = DooSabinWeight(n, d);
    }
    for (Index i = 0; i < n; ++i)
    {
      Index* src = table.GetMutableSources(topo.GetFaceOffset(f) + i);
      double* wts = table.GetMutableWeights(topo.GetFaceOffset(f) + i);
      if (BoundaryCornerRow(topo, f, i, src, wts) > 0)
      {
        continue;
      }
      for (Index k = 0; k < n; ++k)
      {
        src[k] = fv[k];
        wts[k] = weights[(i - k + n) % n];
      }
    }
  }
  table.EndBlock(topo.GetNumFaceCorners());
  return table;
}
}
