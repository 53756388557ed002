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
  // Child edges, keyed for MeshTopology: the halves of parent edge e (HalfEdgeKey), then
  // the edge inside face f opposite its corner j (2E + 3f + j).
  const bool full = depth == ChildTopology::Full;
  KnownAdjacency known;
  if (full)
  {
    known = PrimalChildTags(topo, 0);
    known.CornerEdgeKeys.resize(childVertices.size());
    known.NumEdgeKeys = 2 * numEdges + 3 * numFaces;
  }
  for (Index f = 0; f < numFaces; ++f)
  {
    const IndexSpan fv = topo.GetFaceVertices(f);
    const IndexSpan fe = topo.GetFaceEdges(f);
    Index* out = childVertices.data() + 12 * static_cast<size_t>(f);
    Index* keys = full ? known.CornerEdgeKeys.data() + 12 * static_cast<size_t>(f) : nullptr;
    const Index inner = 2 * numEdges + 3 * f;
    for (Index j = 0; j < 3; ++j, out += 3)
    {
      const Index previous = (j + 2) % 3;
      out[0] = number.VertexPoint(fv[j]);
      out[1] = number.EdgePoint(fe[j]);
      out[2] = number.EdgePoint(fe[previous]);
      if (keys)
      {
        keys[0] = HalfEdgeKey(topo, fe[j], fv[j]);
        keys[1] = inner + j;
        keys[2] = HalfEdgeKey(topo, fe[previous], fv[j]);
        keys += 3;
      }
    }
    out[0] = number.EdgePoint(fe[0]);
    out[1] = number.EdgePoint(fe[1]);
    out[2] = number.EdgePoint(fe[2]);
    if (keys)
    {
      keys[0] = inner + 1;
      keys[1] = inner + 2;
      keys[2] = inner + 0;
    }
  }

  Level child;
  InheritFaceTags(parent, child, [](Index f) { return 4 * f; });
  const Index numChildVertices = numEdges + topo.GetNumVertices();
  SetChildTopology(
    parent, child, numChildVertices, std::move(childOffsets), std::move(childVertices), depth, &known);
  if (depth == ChildTopology::Full)
  {
    InheritPrimalSharpness(parent, child, number.EdgePoint(0), number.VertexPoint(0));
  }
  return child;
}
}
