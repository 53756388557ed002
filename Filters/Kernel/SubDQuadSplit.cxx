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
  child.FaceIsHole.resize(static_cast<size_t>(numCorners));
  child.FaceOrigin.resize(static_cast<size_t>(numCorners));
  for (Index f = 0; f < numFaces; ++f)
  {
    for (Index c = topo.GetFaceOffset(f); c < topo.GetFaceOffset(f + 1); ++c)
    {
      child.FaceIsHole[c] = parent.FaceIsHole[f];
      child.FaceOrigin[c] = parent.FaceOrigin[f];
    }
  }
  const Index numChildVertices = numFaces + numEdges + numVertices;
  if (depth == ChildTopology::FacesOnly)
  {
    child.Topology = MeshTopology::BuildFacesOnly(
      numChildVertices, std::move(childOffsets), std::move(childVertices));
    return child;
  }
  child.Topology =
    MeshTopology::Build(numChildVertices, std::move(childOffsets), std::move(childVertices));
  const MeshTopology& childTopo = child.Topology;

  child.EdgeSharpness.assign(static_cast<size_t>(childTopo.GetNumEdges()), SharpnessSmooth);
  for (Index e = 0; e < numEdges; ++e)
  {
    const float sharpness = parent.EdgeSharpness[e];
    if (!IsSharp(sharpness))
    {
      continue;
    }
    const float decayed = DecaySharpness(sharpness);
    const Index* ev = topo.GetEdgeVertices(e);
    for (int k = 0; k < 2; ++k)
    {
      const Index half = childTopo.FindEdge(number.EdgePoint(e), number.VertexPoint(ev[k]));
      child.EdgeSharpness[half] = decayed;
    }
  }

  child.VertexSharpness.assign(static_cast<size_t>(childTopo.GetNumVertices()), SharpnessSmooth);
  for (Index v = 0; v < numVertices; ++v)
  {
    child.VertexSharpness[number.VertexPoint(v)] = DecaySharpness(parent.VertexSharpness[v]);
  }
  return child;
}
}
