#include "SubDDualChildTopology.h"

#include <algorithm>

namespace subd
{
bool DualChildTopology::Applies(const Level& parent, const DualPoints& points)
{
  const MeshTopology& topo = parent.Topology;
  if (!points.Unwelded || topo.GetNumBoundaryEdges() > 0 || topo.GetNumNonManifoldEdges() > 0 ||
    topo.GetNumNonManifoldVertices() > 0)
  {
    return false;
  }
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    if (topo.GetVertexFaces(v).size() < 3)
    {
      return false; // its V-face would vanish (or it has no faces at all)
    }
  }
  // Unwelded with two faces at every edge already rules out sharp edges and sharp vertices
  // (both weld corners); asked again so that this test stands on its own.
  return !parent.HasSharpFeatures();
}

MeshTopology DualChildTopology::OfDualSplit(
  const MeshTopology& parent, IndexArray offsets, IndexArray vertices, const ParallelFor& parallelFor)
{
  const Index numCorners = parent.GetNumFaceCorners(); // child points, and F-face edges
  const Index numFaces = parent.GetNumFaces();
  const Index numEdges = parent.GetNumEdges();
  const Index numVertices = parent.GetNumVertices();
  const Index firstEFace = numFaces, firstVFace = numFaces + numEdges;
  const IndexArray& parentOffsets = parent.GetFaceOffsetArray();
  const IndexArray& parentVertices = parent.GetFaceVertexArray();
  const IndexArray& parentEdges = parent.GetFaceEdgeArray();

  MeshTopology child = MeshTopology::BuildFacesOnly(numCorners, std::move(offsets), std::move(vertices));
  const IndexArray& childOffsets = child.FaceOffsets;
  const IndexArray& childVertices = child.FaceVertices;
  // The parent face of each corner, and the corner before it in that face.
  IndexArray faceOfCorner(static_cast<size_t>(numCorners));
  parallelFor(0, numFaces, [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f)
    {
      std::fill(faceOfCorner.begin() + parentOffsets[f], faceOfCorner.begin() + parentOffsets[f + 1], f);
    }
  });
  auto next = [&](Index c) {
    const Index f = faceOfCorner[c];
    return c + 1 == parentOffsets[f + 1] ? parentOffsets[f] : c + 1;
  };
  auto previous = [&](Index c) {
    const Index f = faceOfCorner[c];
    return c == parentOffsets[f] ? parentOffsets[f + 1] - 1 : c - 1;
  };
  // The child edge across parent edge e at its end v (see the header).
  auto across = [&](Index e, Index v) { return numCorners + 2 * e + (parent.GetEdgeVertices(e)[0] == v ? 0 : 1); };

  // Face edges.
  child.FaceEdges.resize(childVertices.size());
  IndexArray& faceEdges = child.FaceEdges;
  parallelFor(0, numCorners, [&](Index begin, Index end) {
    for (Index c = begin; c < end; ++c)
    {
      faceEdges[c] = c; // F-face corners are numbered like the parent's corners
    }
  });
  parallelFor(0, numEdges, [&](Index begin, Index end) {
    for (Index e = begin; e < end; ++e)
    {
      const Index* q = childVertices.data() + childOffsets[firstEFace + e];
      Index* edges = faceEdges.data() + childOffsets[firstEFace + e];
      // (q0, q1) and (q2, q3) are F-face edges of the parent corners q1 and q3.
      edges[0] = q[1];
      edges[1] = numCorners + 2 * e;
      edges[2] = q[3];
      edges[3] = numCorners + 2 * e + 1;
    }
  });
  parallelFor(0, numVertices, [&](Index begin, Index end) {
    for (Index v = begin; v < end; ++v)
    {
      // A V-face's corner c is followed by the corner across the edge entering v at c.
      for (Index h = childOffsets[firstVFace + v]; h < childOffsets[firstVFace + v + 1]; ++h)
      {
        faceEdges[h] = across(parentEdges[previous(childVertices[h])], v);
      }
    }
  });

  // Edges: their ends and their two faces (in increasing order).
  const Index numChildEdges = numCorners + 2 * numEdges;
  child.EdgeVertices.resize(2 * static_cast<size_t>(numChildEdges));
  child.EdgeFaces.resize(2 * static_cast<size_t>(numChildEdges));
  parallelFor(0, numCorners, [&](Index begin, Index end) {
    for (Index c = begin; c < end; ++c)
    {
      child.EdgeVertices[2 * c] = c;
      child.EdgeVertices[2 * c + 1] = next(c);
      child.EdgeFaces[2 * c] = faceOfCorner[c];
      child.EdgeFaces[2 * c + 1] = firstEFace + parentEdges[c];
    }
  });
  parallelFor(0, numEdges, [&](Index begin, Index end) {
    for (Index e = begin; e < end; ++e)
    {
      const Index* q = childVertices.data() + childOffsets[firstEFace + e];
      const Index* ev = parent.GetEdgeVertices(e);
      Index* ends = child.EdgeVertices.data() + 2 * static_cast<size_t>(numCorners + 2 * e);
      Index* faces = child.EdgeFaces.data() + 2 * static_cast<size_t>(numCorners + 2 * e);
      ends[0] = q[1];
      ends[1] = q[2];
      ends[2] = q[3];
      ends[3] = q[0];
      faces[0] = firstEFace + e;
      faces[1] = firstVFace + ev[0];
      faces[2] = firstEFace + e;
      faces[3] = firstVFace + ev[1];
    }
  });
  FillStrided(child.EdgeFaceOffsets, numChildEdges, 2, parallelFor);

  // Points: four faces (F-face, two E-faces, V-face: already in increasing order by block)
  // with the point's corner in each, and four edges.
  child.VertexFaces.resize(4 * static_cast<size_t>(numCorners));
  child.VertexFaceCorners.resize(child.VertexFaces.size());
  child.VertexEdges.resize(child.VertexFaces.size());
  auto cornerIn = [&](Index face, Index c) {
    Index k = 0;
    while (childVertices[childOffsets[face] + k] != c)
    {
      ++k;
    }
    return k;
  };
  parallelFor(0, numCorners, [&](Index begin, Index end) {
    for (Index c = begin; c < end; ++c)
    {
      const Index f = faceOfCorner[c], v = parentVertices[c];
      Index leaving = parentEdges[c], entering = parentEdges[previous(c)];
      if (leaving > entering)
      {
        std::swap(leaving, entering);
      }
      Index* faces = child.VertexFaces.data() + 4 * static_cast<size_t>(c);
      Index* corners = child.VertexFaceCorners.data() + 4 * static_cast<size_t>(c);
      faces[0] = f;
      faces[1] = firstEFace + leaving;
      faces[2] = firstEFace + entering;
      faces[3] = firstVFace + v;
      corners[0] = c - parentOffsets[f];
      for (int k = 1; k < 4; ++k)
      {
        corners[k] = cornerIn(faces[k], c);
      }
      Index* edges = child.VertexEdges.data() + 4 * static_cast<size_t>(c);
      edges[0] = std::min(previous(c), c);
      edges[1] = std::max(previous(c), c);
      edges[2] = std::min(across(leaving, v), across(entering, v));
      edges[3] = std::max(across(leaving, v), across(entering, v));
    }
  });
  FillStrided(child.VertexFaceOffsets, numCorners, 4, parallelFor);
  FillStrided(child.VertexEdgeOffsets, numCorners, 4, parallelFor);

  child.EdgeTags.assign(static_cast<size_t>(numChildEdges), EdgeTag{ 0, 0 });
  child.VertexTags.assign(static_cast<size_t>(numCorners), VertexTag{ 0, 0 });
  child.NumNonManifoldEdges = 0;
  child.NumNonManifoldVertices = 0;
  child.NumBoundaryEdges = 0;
  child.MaxValence = numCorners > 0 ? 4 : 0;
  return child;
}
}
