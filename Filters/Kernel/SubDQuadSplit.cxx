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
  // Child edges, keyed for MeshTopology: the halves of parent edge e (HalfEdgeKey), then
  // the edge from the edge point of corner c's leaving edge to the face point (2E + c).
  const bool full = depth == ChildTopology::Full;
  KnownAdjacency known;
  if (full)
  {
    known = PrimalChildTags(topo, numFaces);
    known.CornerEdgeKeys.resize(childVertices.size());
    known.NumEdgeKeys = 2 * numEdges + numCorners;
  }
  for (Index f = 0; f < numFaces; ++f)
  {
    const IndexSpan fv = topo.GetFaceVertices(f);
    const IndexSpan fe = topo.GetFaceEdges(f);
    const Index n = fv.size();
    const Index firstCorner = topo.GetFaceOffset(f);
    Index* out = childVertices.data() + 4 * static_cast<size_t>(firstCorner);
    for (Index j = 0; j < n; ++j, out += 4)
    {
      const Index previous = j == 0 ? n - 1 : j - 1;
      out[0] = number.VertexPoint(fv[j]);
      out[1] = number.EdgePoint(fe[j]);
      out[2] = number.FacePoint(f);
      out[3] = number.EdgePoint(fe[previous]);
      if (full)
      {
        Index* keys = known.CornerEdgeKeys.data() + (out - childVertices.data());
        keys[0] = HalfEdgeKey(topo, fe[j], fv[j]);
        keys[1] = 2 * numEdges + firstCorner + j;
        keys[2] = 2 * numEdges + firstCorner + previous;
        keys[3] = HalfEdgeKey(topo, fe[previous], fv[j]);
      }
    }
  }

  Level child;
  InheritFaceTags(parent, child, [&topo](Index f) { return topo.GetFaceOffset(f); });
  const Index numChildVertices = numFaces + numEdges + numVertices;
  SetChildTopology(
    parent, child, numChildVertices, std::move(childOffsets), std::move(childVertices), depth, &known);
  if (depth == ChildTopology::Full)
  {
    InheritPrimalSharpness(parent, child, number.EdgePoint(0), number.VertexPoint(0));
  }
  return child;
}
}
