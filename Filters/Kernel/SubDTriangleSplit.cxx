#include "SubDTriangleSplit.h"

namespace subd
{
Level SplitTriangles(const Level& parent, ChildTopology depth)
{
  const MeshTopology& topo = parent.Topology;
  const Index numFaces = topo.GetNumFaces();
  const Index numEdges = topo.GetNumEdges();
  const TriangleSplitNumbering number{ numEdges };

  std::vector<Index> childOffsets(4 * static_cast<size_t>(numFaces) + 1);
  for (size_t i = 0; i < childOffsets.size(); ++i)
  {
    childOffsets[i] = static_cast<Index>(3 * i);
  }
  std::vector<Index> childVertices(12 * static_cast<size_t>(numFaces));
  for (Index f = 0; f < numFaces; ++f)
  {
    const IndexSpan fv = topo.GetFaceVertices(f);
    const IndexSpan fe = topo.GetFaceEdges(f);
    Index* out = childVertices.data() + 12 * static_cast<size_t>(f);
    for (Index j = 0; j < 3; ++j, out += 3)
    {
      out[0] = number.VertexPoint(fv[j]);
      out[1] = number.EdgePoint(fe[j]);
      out[2] = number.EdgePoint(fe[(j + 2) % 3]);
    }
    out[0] = number.EdgePoint(fe[0]);
    out[1] = number.EdgePoint(fe[1]);
    out[2] = number.EdgePoint(fe[2]);
  }

  Level child;
  InheritFaceTags(parent, child, [](Index f) { return 4 * f; });
  const Index numChildVertices = numEdges + topo.GetNumVertices();
  SetChildTopology(parent, child, numChildVertices, std::move(childOffsets), std::move(childVertices), depth);
  if (depth == ChildTopology::Full)
  {
    InheritPrimalSharpness(parent, child, number.EdgePoint(0), number.VertexPoint(0));
  }
  return child;
}
}
