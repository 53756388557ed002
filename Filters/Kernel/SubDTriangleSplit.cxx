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
      const IndexSpan fv = topo.GetFaceVertices(f);
      const IndexSpan fe = topo.GetFaceEdges(f);
      Index* out = childVertices.data() + 12 * static_cast<size_t>(f);
      for (Index j = 0; j < 3; ++j, out += 3)
      {
        out[0] = number.VertexPoint(fv[j]);
        out[1] = number.EdgePoint(fe[j]);
        out[2] = number.EdgePoint(fe[j == 0 ? 2 : j - 1]);
      }
      out[0] = number.EdgePoint(fe[0]);
      out[1] = number.EdgePoint(fe[1]);
      out[2] = number.EdgePoint(fe[2]);
      for (Index c = 4 * f; c < 4 * f + 4; ++c)
      {
        childOffsets[c] = 3 * c;
      }
    }
  });
  childOffsets[4 * static_cast<size_t>(numFaces)] = 12 * numFaces;

  Level child;
  InheritFaceTags(parent, child, [](Index f) { return 4 * f; }, parallelFor);
  PrimalChildTopology::SetChildLevel(parent, child, PrimalChildTopology::Split::Triangles, numEdges + topo.GetNumVertices(),
    std::move(childOffsets), std::move(childVertices), depth, number.EdgePoint(0), number.VertexPoint(0), parallelFor);
  return child;
}
}
