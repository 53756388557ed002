#include "SubDLinearRules.h"
#include "SubDQuadSplit.h"
#include "SubDTriangleSplit.h"

namespace subd
{
namespace
{
// Edge points (midpoints) at rows firstEdgeRow + e, vertex points (copies) at
// firstVertexRow + v.
void FillEdgeAndVertexRows(const MeshTopology& topo, StencilTable& table, Index firstEdgeRow, Index firstVertexRow)
{
  for (Index e = 0; e < topo.GetNumEdges(); ++e)
  {
    const Index* ev = topo.GetEdgeVertices(e);
    Index* src = table.GetMutableSources(firstEdgeRow + e);
    double* wts = table.GetMutableWeights(firstEdgeRow + e);
    src[0] = ev[0];
    src[1] = ev[1];
    wts[0] = wts[1] = 0.5;
  }
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    *table.GetMutableSources(firstVertexRow + v) = v;
    *table.GetMutableWeights(firstVertexRow + v) = 1.0;
  }
}

void SizeEdgeAndVertexRows(const MeshTopology& topo, StencilTable& table, Index firstEdgeRow, Index firstVertexRow)
{
  for (Index e = 0; e < topo.GetNumEdges(); ++e)
  {
    table.SetRowSize(firstEdgeRow + e, 2);
  }
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    table.SetRowSize(firstVertexRow + v, 1);
  }
}
}

StencilTable BuildBilinearStencils(const Level& parent)
{
  const MeshTopology& topo = parent.Topology;
  const QuadSplitNumbering number{ topo.GetNumFaces(), topo.GetNumEdges() };
  const Index numRows = topo.GetNumFaces() + topo.GetNumEdges() + topo.GetNumVertices();
  StencilTable table(topo.GetNumVertices());
  table.ReserveRows(numRows);
  for (Index f = 0; f < topo.GetNumFaces(); ++f)
  {
    table.SetRowSize(number.FacePoint(f), topo.GetFaceSize(f));
  }
  SizeEdgeAndVertexRows(topo, table, number.EdgePoint(0), number.VertexPoint(0));
  table.FinalizeSizes();
  for (Index f = 0; f < topo.GetNumFaces(); ++f)
  {
    const IndexSpan fv = topo.GetFaceVertices(f);
    Index* src = table.GetMutableSources(number.FacePoint(f));
    double* wts = table.GetMutableWeights(number.FacePoint(f));
    for (Index j = 0; j < fv.size(); ++j)
    {
      src[j] = fv[j];
      wts[j] = 1.0 / fv.size();
    }
  }
  FillEdgeAndVertexRows(topo, table, number.EdgePoint(0), number.VertexPoint(0));
  table.EndBlock(numRows);
  return table;
}

StencilTable BuildLinearTriangleStencils(const Level& parent)
{
  const MeshTopology& topo = parent.Topology;
  const TriangleSplitNumbering number{ topo.GetNumEdges() };
  const Index numRows = topo.GetNumEdges() + topo.GetNumVertices();
  StencilTable table(topo.GetNumVertices());
  table.ReserveRows(numRows);
  SizeEdgeAndVertexRows(topo, table, number.EdgePoint(0), number.VertexPoint(0));
  table.FinalizeSizes();
  FillEdgeAndVertexRows(topo, table, number.EdgePoint(0), number.VertexPoint(0));
  table.EndBlock(numRows);
  return table;
}
}
