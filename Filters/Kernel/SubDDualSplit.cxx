#include "SubDDualSplit.h"

namespace subd
{
Level SplitDual(const Level& parent, ChildTopology depth)
{
  const MeshTopology& topo = parent.Topology;
  const Index numFaces = topo.GetNumFaces();
  const Index numCorners = topo.GetNumFaceCorners();
  // The child point of corner `corner` of face f.
  auto cornerPoint = [&topo](Index f, Index corner) { return topo.GetFaceOffset(f) + corner; };

  Level child;
  std::vector<Index> offsets{ 0 }, vertices, origins, holes;
  auto addFace = [&](Index origin, std::uint8_t hole) {
    offsets.push_back(static_cast<Index>(vertices.size()));
    origins.push_back(origin);
    holes.push_back(hole);
  };
  // F-faces: the corner points of each face.
  vertices.reserve(static_cast<size_t>(numCorners) * 3);
  for (Index f = 0; f < numFaces; ++f)
  {
    for (Index j = 0; j < topo.GetFaceSize(f); ++j)
    {
      vertices.push_back(cornerPoint(f, j));
    }
    addFace(parent.FaceOrigin[f], parent.FaceIsHole[f]);
  }
  // E-faces: edge (a, b) runs a->b in face f0 and b->a in f1; the quad runs against f0's
  // side of the edge and then along f1's, so that it is oriented like its neighbours.
  for (Index e = 0; e < topo.GetNumEdges(); ++e)
  {
    const IndexSpan ef = topo.GetEdgeFaces(e);
    if (ef.size() != 2 || topo.GetEdgeTag(e).NonManifold)
    {
      continue;
    }
    const Index* ev = topo.GetEdgeVertices(e);
    Index f0 = ef[0], f1 = ef[1];
    Index a = ev[0], b = ev[1];
    Index ca = topo.FindCorner(a, f0);
    if (topo.GetFaceVertices(f0)[(ca + 1) % topo.GetFaceSize(f0)] != b)
    {
      std::swap(f0, f1); // make f0 the face that runs a->b
      ca = topo.FindCorner(a, f0);
    }
    vertices.insert(vertices.end(), { cornerPoint(f0, topo.FindCorner(b, f0)), cornerPoint(f0, ca),
                                      cornerPoint(f1, topo.FindCorner(a, f1)),
                                      cornerPoint(f1, topo.FindCorner(b, f1)) });
    addFace(parent.FaceOrigin[f0], parent.FaceIsHole[f0] && parent.FaceIsHole[f1]);
  }
  // V-faces around manifold vertices with at least three faces (with two, the E-face between
  // them already joins their corner points; with one there is nothing to join).
  std::vector<Index> fan, fanCorners;
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    if (!topo.GetOrderedVertexFaces(v, fan, fanCorners) || (topo.GetVertexTag(v).Boundary && fan.size() < 3))
    {
      continue;
    }
    std::uint8_t allHoles = 1;
    for (size_t i = 0; i < fan.size(); ++i)
    {
      vertices.push_back(cornerPoint(fan[i], fanCorners[i]));
      allHoles &= parent.FaceIsHole[fan[i]];
    }
    addFace(parent.FaceOrigin[fan[0]], allHoles);
  }

  child.FaceOrigin.assign(origins.begin(), origins.end());
  child.FaceIsHole.assign(holes.begin(), holes.end());
  SetChildTopology(parent, child, numCorners, std::move(offsets), std::move(vertices), depth);
  return child;
}
}
