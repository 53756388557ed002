#include "SubDRingTangents.h"

namespace subd
{
bool GetOrderedRing(const MeshTopology& topo, Index v, std::vector<Index>& faces, std::vector<Index>& corners,
  std::vector<Index>& ring)
{
  ring.clear();
  const VertexTag tag = topo.GetVertexTag(v);
  if (tag.Boundary || tag.NonManifold || !topo.GetOrderedVertexFaces(v, faces, corners) ||
    faces.size() != static_cast<size_t>(topo.GetVertexEdges(v).size()))
  {
    return false;
  }
  for (size_t j = 0; j < faces.size(); ++j)
  {
    const IndexSpan fv = topo.GetFaceVertices(faces[j]);
    ring.push_back(fv[(corners[j] + 1) % fv.size()]);
  }
  return true;
}
}
