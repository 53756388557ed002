#include "SubDMidpointSplit.h"

namespace subd
{
namespace
{
bool KeepsBoundaryVertex(const MeshTopology& topo, Index v)
{
  const VertexTag tag = topo.GetVertexTag(v);
  return tag.Boundary && !tag.NonManifold && !topo.GetVertexFaces(v).empty();
}
}

LevelRefinement RefineMidpoint(const Level& parent, ChildTopology depth)
{
  const MeshTopology& topo = parent.Topology;
  const Index numEdges = topo.GetNumEdges();

  // Child points: midpoints, then kept boundary vertices.
  std::vector<Index> keptPoint(static_cast<size_t>(topo.GetNumVertices()), InvalidIndex);
  Index numChildPoints = numEdges;
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    if (KeepsBoundaryVertex(topo, v))
    {
      keptPoint[v] = numChildPoints++;
    }
  }

  LevelRefinement result;
  StencilTable& table = result.Stencils;
  table = StencilTable(topo.GetNumVertices());
  table.ReserveRows(numChildPoints);
  for (Index e = 0; e < numEdges; ++e)
  {
    table.SetRowSize(e, 2);
  }
  for (Index r = numEdges; r < numChildPoints; ++r)
  {
    table.SetRowSize(r, 1);
  }
  table.FinalizeSizes();
  for (Index e = 0; e < numEdges; ++e)
  {
    const Index* ev = topo.GetEdgeVertices(e);
    table.GetMutableSources(e)[0] = ev[0];
    table.GetMutableSources(e)[1] = ev[1];
    table.GetMutableWeights(e)[0] = table.GetMutableWeights(e)[1] = 0.5;
  }
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    if (keptPoint[v] != InvalidIndex)
    {
      *table.GetMutableSources(keptPoint[v]) = v;
      *table.GetMutableWeights(keptPoint[v]) = 1.0;
    }
  }
  table.EndBlock(numChildPoints);

  std::vector<Index> offsets{ 0 }, vertices;
  Level& child = result.Child;
  auto endFace = [&](Index origin, std::uint8_t hole) {
    offsets.push_back(static_cast<Index>(vertices.size()));
    child.FaceOrigin.push_back(origin);
    child.FaceIsHole.push_back(hole);
  };
  for (Index f = 0; f < topo.GetNumFaces(); ++f)
  {
    for (Index e : topo.GetFaceEdges(f))
    {
      vertices.push_back(e);
    }
    endFace(parent.FaceOrigin[f], parent.FaceIsHole[f]);
  }
  // V-faces: in fan order each face contributes the midpoint of the edge leaving v, which
  // is the edge entering v in the next face; a boundary fan starts at the kept vertex and
  // ends with the boundary edge entering v.
  std::vector<Index> fan, corners;
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    if (!topo.GetOrderedVertexFaces(v, fan, corners))
    {
      continue;
    }
    const bool boundary = keptPoint[v] != InvalidIndex;
    if (boundary)
    {
      vertices.push_back(keptPoint[v]);
    }
    std::uint8_t allHoles = 1;
    for (size_t i = 0; i < fan.size(); ++i)
    {
      vertices.push_back(topo.GetFaceEdges(fan[i])[corners[i]]);
      allHoles &= parent.FaceIsHole[fan[i]];
    }
    if (boundary)
    {
      const Index n = topo.GetFaceSize(fan.back());
      const Index last = corners.back();
      vertices.push_back(topo.GetFaceEdges(fan.back())[last == 0 ? n - 1 : last - 1]);
    }
    endFace(parent.FaceOrigin[fan[0]], allHoles);
  }

  SetChildTopology(parent, child, numChildPoints, std::move(offsets), std::move(vertices), depth);
  return result;
}
}
