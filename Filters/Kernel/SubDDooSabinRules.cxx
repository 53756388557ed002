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
      table.SetRowSize(topo.GetFaceOffset(f) + j, n);
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
