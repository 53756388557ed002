#include "SubDLinearRules.h"
#include "SubDRowWriting.h"

#include <algorithm>

namespace subd
{
StencilTable BuildBilinearStencils(const Level& parent)
{
  const MeshTopology& topo = parent.Topology;
  const size_t expected = static_cast<size_t>(topo.GetNumFaceCorners()) + 2 * static_cast<size_t>(topo.GetNumEdges()) +
    static_cast<size_t>(topo.GetNumVertices());
  return WriteStencilTable(LinearRowWriter(parent, true), expected);
}

StencilTable BuildLinearTriangleStencils(const Level& parent)
{
  const MeshTopology& topo = parent.Topology;
  const size_t expected = 2 * static_cast<size_t>(topo.GetNumEdges()) + static_cast<size_t>(topo.GetNumVertices());
  return WriteStencilTable(LinearRowWriter(parent, false), expected);
}

LinearRowWriter::LinearRowWriter(const Level& parent, bool facePoints)
  : Topology(parent.Topology)
  , FirstEdgeRow(facePoints ? parent.Topology.GetNumFaces() : 0)
  , FirstVertexRow(FirstEdgeRow + parent.Topology.GetNumEdges())
{
  for (Index f = 0; f < this->FirstEdgeRow; ++f)
  {
    this->MaxRowSize = std::max(this->MaxRowSize, this->Topology.GetFaceSize(f));
  }
}

Index LinearRowWriter::WriteRow(Index row, Index* sources, double* weights) const
{
  if (row < this->FirstEdgeRow)
  {
    const IndexSpan fv = this->Topology.GetFaceVertices(row);
    for (Index j = 0; j < fv.size(); ++j)
    {
      sources[j] = fv[j];
      weights[j] = 1.0 / fv.size();
    }
    return fv.size();
  }
  if (row < this->FirstVertexRow)
  {
    const Index* ev = this->Topology.GetEdgeVertices(row - this->FirstEdgeRow);
    sources[0] = ev[0];
    sources[1] = ev[1];
    weights[0] = weights[1] = 0.5;
    return 2;
  }
  sources[0] = row - this->FirstVertexRow;
  weights[0] = 1.0;
  return 1;
}
}
