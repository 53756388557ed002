#include "SubDQuadSplit.h"
#include "SubDCrease.h"
#include "SubDPrimalChildTopology.h"

#include <atomic>

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
  std::atomic<bool> someFaceNotQuad{ false };
  parallelFor(0, numFaces, [&](Index begin, Index end) {
    bool notQuad = false;
    for (Index f = begin; f < end; ++f)
    {
      const Index n = topo.GetFaceSize(f);
      notQuad |= n != 4;
      const Index firstCorner = topo.GetFaceOffset(f);
      Index* out = childVertices.data() + 4 * static_cast<size_t>(firstCorner);
      for (Index j = 0; j < n; ++j, out += 4)
      {
        childOffsets[firstCorner + j] = 4 * (firstCorner + j);
        GetQuadSplitChild(topo, number, f, j, out);
      }
    }
    if (notQuad)
    {
      someFaceNotQuad = true;
    }
  });
  childOffsets[numCorners] = 4 * numCorners;

  Level child;
  // Each face has as many children as corners: four each where all faces are quads.
  InheritPrimalFaceTags(parent, child, depth, !someFaceNotQuad, [&topo](Index f) { return topo.GetFaceOffset(f); }, parallelFor);
  PrimalChildTopology::SetChildLevel(parent, child, PrimalChildTopology::Split::Quads, numFaces + numEdges + numVertices,
    std::move(childOffsets), std::move(childVertices), depth, number.EdgePoint(0), number.VertexPoint(0), parallelFor);
  return child;
}
}
