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
}
