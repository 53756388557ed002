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

// What every part of the child is written from: the parent, the child's faces, and each
// parent corner's face; child edge c (c < corners) is the F-face edge from corner c to the
// next, the edges across parent edge e follow (see the header).
struct DualChildTopology::Split
{
  const MeshTopology& Parent;
  const IndexArray& ChildOffsets;
  const IndexArray& ChildVertices;
  const ParallelFor& Parallel;
  Index NumCorners, NumFaces, NumEdges, NumVertices;
  Index FirstEFace, FirstVFace;
  IndexArray FaceOfCorner;

  Split(const MeshTopology& parent, const MeshTopology& child, const ParallelFor& parallelFor)
    : Parent(parent)
    , ChildOffsets(child.GetFaceOffsetArray())
    , ChildVertices(child.GetFaceVertexArray())
    , Parallel(parallelFor)
    , NumCorners(parent.GetNumFaceCorners())
    , NumFaces(parent.GetNumFaces())
    , NumEdges(parent.GetNumEdges())
    , NumVertices(parent.GetNumVertices())
    , FirstEFace(NumFaces)
    , FirstVFace(NumFaces + NumEdges)
    , FaceOfCorner(static_cast<size_t>(NumCorners))
  {
    const IndexArray& offsets = parent.GetFaceOffsetArray();
    parallelFor(0, this->NumFaces, [&](Index begin, Index end) {
      for (Index f = begin; f < end; ++f)
      {
        std::fill(this->FaceOfCorner.begin() + offsets[f], this->FaceOfCorner.begin() + offsets[f + 1], f);
      }
    });
  }
  Index Next(Index c) const
  {
    const Index f = this->FaceOfCorner[c];
    return c + 1 == this->Parent.GetFaceOffset(f + 1) ? this->Parent.GetFaceOffset(f) : c + 1;
  }
  Index Previous(Index c) const
  {
    const Index f = this->FaceOfCorner[c];
    return c == this->Parent.GetFaceOffset(f) ? this->Parent.GetFaceOffset(f + 1) - 1 : c - 1;
  }
  // The child edge across parent edge e at its end v.
  Index Across(Index e, Index v) const
  {
    return this->NumCorners + 2 * e + (this->Parent.GetEdgeVertices(e)[0] == v ? 0 : 1);
  }
  // The corner of child face `face` at point c.
  Index CornerIn(Index face, Index c) const
  {
    Index k = 0;
    while (this->ChildVertices[this->ChildOffsets[face] + k] != c)
    {
      ++k;
    }
    return k;
  }
};

void DualChildTopology::WriteFaceEdges(const Split& split, MeshTopology& child)
{
  const IndexArray& parentEdges = split.Parent.GetFaceEdgeArray();
  child.FaceEdges.resize(split.ChildVertices.size());
  IndexArray& faceEdges = child.FaceEdges;
  split.Parallel(0, split.NumCorners, [&](Index begin, Index end) {
    for (Index c = begin; c < end; ++c)
    {
      faceEdges[c] = c; // F-face corners are numbered like the parent's corners
    }
  });
  split.Parallel(0, split.NumEdges, [&](Index begin, Index end) {
    for (Index e = begin; e < end; ++e)
    {
      const Index* q = split.ChildVertices.data() + split.ChildOffsets[split.FirstEFace + e];
      Index* edges = faceEdges.data() + split.ChildOffsets[split.FirstEFace + e];
      // (q0, q1) and (q2, q3) are F-face edges of the parent corners q1 and q3.
      edges[0] = q[1];
      edges[1] = split.NumCorners + 2 * e;
      edges[2] = q[3];
      edges[3] = split.NumCorners + 2 * e + 1;
    }
  });
  split.Parallel(0, split.NumVertices, [&](Index begin, Index end) {
    for (Index v = begin; v < end; ++v)
    {
      // A V-face's corner c is followed by the corner across the edge entering v at c.
      for (Index h = split.ChildOffsets[split.FirstVFace + v]; h < split.ChildOffsets[split.FirstVFace + v + 1]; ++h)
      {
        faceEdges[h] = split.Across(parentEdges[split.Previous(split.ChildVertices[h])], v);
      }
    }
  });
}

void DualChildTopology::WriteEdges(const Split& split, MeshTopology& child)
{
  const IndexArray& parentEdges = split.Parent.GetFaceEdgeArray();
  const Index numChildEdges = split.NumCorners + 2 * split.NumEdges;
  child.EdgeVertices.resize(2 * static_cast<size_t>(numChildEdges));
  child.EdgeFaces.resize(2 * static_cast<size_t>(numChildEdges));
  split.Parallel(0, split.NumCorners, [&](Index begin, Index end) {
    for (Index c = begin; c < end; ++c)
    {
      child.EdgeVertices[2 * c] = c;
      child.EdgeVertices[2 * c + 1] = split.Next(c);
      child.EdgeFaces[2 * c] = split.FaceOfCorner[c];
      child.EdgeFaces[2 * c + 1] = split.FirstEFace + parentEdges[c];
    }
  });
  split.Parallel(0, split.NumEdges, [&](Index begin, Index end) {
    for (Index e = begin; e < end; ++e)
    {
      const Index* q = split.ChildVertices.data() + split.ChildOffsets[split.FirstEFace + e];
      const Index* ev = split.Parent.GetEdgeVertices(e);
      Index* ends = child.EdgeVertices.data() + 2 * static_cast<size_t>(split.NumCorners + 2 * e);
      Index* faces = child.EdgeFaces.data() + 2 * static_cast<size_t>(split.NumCorners + 2 * e);
      ends[0] = q[1];
      ends[1] = q[2];
      ends[2] = q[3];
      ends[3] = q[0];
      faces[0] = split.FirstEFace + e;
      faces[1] = split.FirstVFace + ev[0];
      faces[2] = split.FirstEFace + e;
      faces[3] = split.FirstVFace + ev[1];
    }
  });
  FillStrided(child.EdgeFaceOffsets, numChildEdges, 2, split.Parallel);
}

void DualChildTopology::WritePointRelations(const Split& split, MeshTopology& child)
{
  // Four faces (F-face, two E-faces, V-face: already in increasing order by block) with the
  // point's corner in each, and four edges.
  const IndexArray& parentVertices = split.Parent.GetFaceVertexArray();
  const IndexArray& parentEdges = split.Parent.GetFaceEdgeArray();
  child.VertexFaces.resize(4 * static_cast<size_t>(split.NumCorners));
  child.VertexFaceCorners.resize(child.VertexFaces.size());
  child.VertexEdges.resize(child.VertexFaces.size());
  split.Parallel(0, split.NumCorners, [&](Index begin, Index end) {
    for (Index c = begin; c < end; ++c)
    {
      const Index f = split.FaceOfCorner[c], v = parentVertices[c];
      Index leaving = parentEdges[c], entering = parentEdges[split.Previous(c)];
      if (leaving > entering)
      {
        std::swap(leaving, entering);
      }
      Index* faces = child.VertexFaces.data() + 4 * static_cast<size_t>(c);
      Index* corners = child.VertexFaceCorners.data() + 4 * static_cast<size_t>(c);
      faces[0] = f;
      faces[1] = split.FirstEFace + leaving;
      faces[2] = split.FirstEFace + entering;
      faces[3] = split.FirstVFace + v;
      corners[0] = c - split.Parent.GetFaceOffset(f);
      for (int k = 1; k < 4; ++k)
      {
        corners[k] = split.CornerIn(faces[k], c);
      }
      Index* edges = child.VertexEdges.data() + 4 * static_cast<size_t>(c);
      edges[0] = std::min(split.Previous(c), c);
      edges[1] = std::max(split.Previous(c), c);
      edges[2] = std::min(split.Across(leaving, v), split.Across(entering, v));
      edges[3] = std::max(split.Across(leaving, v), split.Across(entering, v));
    }
  });
  FillStrided(child.VertexFaceOffsets, split.NumCorners, 4, split.Parallel);
  FillStrided(child.VertexEdgeOffsets, split.NumCorners, 4, split.Parallel);
}

MeshTopology DualChildTopology::OfDualSplit(
  const MeshTopology& parent, IndexArray offsets, IndexArray vertices, const ParallelFor& parallelFor)
{
  const Index numCorners = parent.GetNumFaceCorners(); // child points, and F-face edges
  MeshTopology child = MeshTopology::BuildFacesOnly(numCorners, std::move(offsets), std::move(vertices));
  const Split split(parent, child, parallelFor);
  WriteFaceEdges(split, child);
  WriteEdges(split, child);
  WritePointRelations(split, child);
  child.EdgeTags.assign(static_cast<size_t>(child.GetNumEdges()), EdgeTag{ 0, 0 });
  child.VertexTags.assign(static_cast<size_t>(numCorners), VertexTag{ 0, 0 });
  child.NumNonManifoldEdges = 0;
  child.NumNonManifoldVertices = 0;
  child.NumBoundaryEdges = 0;
  child.MaxValence = numCorners > 0 ? 4 : 0;
  return child;
}
}
