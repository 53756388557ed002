#include "SubDTriangleSplit.h"
#include "SubDPrimalChildTopology.h"

namespace subd
{
Level SplitTriangles(const Level& parent, ChildTopology depth, const ParallelFor& parallelFor)
{
  const MeshTopology& topo = parent.Topology;
  const Index numFaces = topo.GetNumFaces();
  const Index numEdges = topo.GetNumEdges();
  const TriangleSplitNumbering number{ numEdges };

  IndexArray childOffsets(4 * static_cast<size_t>(numFaces) + 1);
  IndexArray childVertices(12 * static_cast<size_t>(numFaces));
  parallelFor(0, numFaces, [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f)
    {
      Index* out = childVertices.data() + 12 * static_cast<size_t>(f);
      for (Index j = 0; j < 4; ++j, out += 3)
      {
        GetTriangleSplitChild(topo, number, f, j, out);
      }
      for (Index c = 4 * f; c < 4 * f + 4; ++c)
      {
        childOffsets[c] = 3 * c;
      }
    }
  });
  childOffsets[4 * static_cast<size_t>(numFaces)] = 12 * numFaces;

  Level child;
  InheritPrimalFaceTags(parent, child, depth, true, [](Index f) { return 4 * f; }, parallelFor);
  PrimalChildTopology::SetChildLevel(parent, child, PrimalChildTopology::Split::Triangles, numEdges + topo.GetNumVertices(),
    std::move(childOffsets), std::move(childVertices), depth, number.EdgePoint(0), number.VertexPoint(0), parallelFor);
  return child;
}
}
