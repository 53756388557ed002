#include "SubDQuadSplit.h"
#include "SubDCrease.h"
#include "SubDPrimalChildTopology.h"

namespace subd
{
Level SplitQuads(const Level& parent, ChildTopology depth, const ParallelFor& parallelFor)
{
  const MeshTopology& topo = parent.Topology;
  const Index numFaces = topo.GetNumFaces();
  const Index numEdges = topo.GetNumEdges();
  const Index numVertices = topo.GetNumVertices();
  const Index numCorners = topo.GetNumFaceCorners();
  const QuadSplitNumbering number{ numFaces, numEdges };

  IndexArray childOffsets(static_cast<size_t>(numCorners) + 1);
  IndexArray childVertices(static_cast<size_t>(numCorners) * 4);
  parallelFor(0, numFaces, [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f)
    {
      const Index n = topo.GetFaceSize(f);
      const Index firstCorner = topo.GetFaceOffset(f);
      Index* out = childVertices.data() + 4 * static_cast<size_t>(firstCorner);
      for (Index j = 0; j < n; ++j, out += 4)
      {
        childOffsets[firstCorner + j] = 4 * (firstCorner + j);
        GetQuadSplitChild(topo, number, f, j, out);
      }
    }
  });
  childOffsets[numCorners] = 4 * numCorners;

  Level child;
  InheritFaceTags(parent, child, [&topo](Index f) { return topo.GetFaceOffset(f); }, parallelFor);
  PrimalChildTopology::SetChildLevel(parent, child, PrimalChildTopology::Split::Quads, numFaces + numEdges + numVertices,
    std::move(childOffsets), std::move(childVertices), depth, number.EdgePoint(0), number.VertexPoint(0), parallelFor);
  return child;
}
}
