#include "SubDQuadSplit.h"
#include "SubDCrease.h"

namespace subd
{
Level SplitQuads(const Level& parent, ChildTopology depth)
{
  const MeshTopology& topo = parent.Topology;
  const Index numFaces = topo.GetNumFaces();
  const Index numEdges = topo.GetNumEdges();
  const Index numVertices = topo.GetNumVertices();
  const Index numCorners = topo.GetNumFaceCorners();
  const QuadSplitNumbering number{ numFaces, numEdges };

  std::vector<Index> childOffsets(static_cast<size_t>(numCorners) + 1);
  std::vector<Index> childVertices(static_cast<size_t>(numCorners) * 4);
  for (Index i = 0; i <= numCorners; ++i)
  {
    childOffsets[i] = 4 * i;
  }
  for (Index f = 0; f < numFaces; ++f)
  {
    const IndexSpan fv = topo.GetFaceVertices(f);
    const IndexSpan fe = topo.GetFaceEdges(f);
    const Index n = fv.size();
    Index* out = childVertices.data() + 4 * static_cast<size_t>(topo.GetFaceOffset(f));
    for (Index j = 0; j < n; ++j, out += 4)
    {
      out[0] = number.VertexPoint(fv[j]);
      out[1] = number.EdgePoint(fe[j]);
      out[2] = number.FacePoint(f);
      out[3] = number.EdgePoint(fe[j == 0 ? n - 1 : j - 1]);
    }
  }

  Level child;
  InheritFaceTags(parent, child, [&topo](Index f) { return topo.GetFaceOffset(f); });
  const Index numChildVertices = numFaces + numEdges + numVertices;
  SetChildTopology(parent, child, numChildVertices, std::move(childOffsets), std::move(childVertices), depth);
  if (depth == ChildTopology::Full)
  {
    InheritPrimalSharpness(parent, child, number.EdgePoint(0), number.VertexPoint(0));
  }
  return child;
}
}
