#include "SubDMeshTopology.h"

#include <algorithm>
#include <numeric>
#include <utility>

namespace subd
{
namespace
{
// Turns per-item counts stored at [i+1] into offsets (exclusive prefix sum in place).
void CountsToOffsets(IndexArray& offsets)
{
  for (size_t i = 1; i < offsets.size(); ++i)
  {
    offsets[i] += offsets[i - 1];
  }
}
}

MeshTopology MeshTopology::BuildFacesOnly(Index numVertices, IndexArray faceOffsets, IndexArray faceVertices)
{
  MeshTopology topology;
  topology.NumVertices = numVertices;
  topology.FaceOffsets = std::move(faceOffsets);
  topology.FaceVertices = std::move(faceVertices);
  if (topology.FaceOffsets.empty())
  {
    topology.FaceOffsets.push_back(0);
  }
  return topology;
}

bool MeshTopology::ReleaseFaces(IndexArray& faceOffsets, IndexArray& faceVertices)
{
  if (this->HasEdges())
  {
    return false;
  }
  faceOffsets = std::move(this->FaceOffsets);
  faceVertices = std::move(this->FaceVertices);
  *this = BuildFacesOnly(this->NumVertices, {}, {});
  return true;
}

MeshTopology MeshTopology::Build(Index numVertices, const std::vector<Index>& faceOffsets,
  const std::vector<Index>& faceVertices, const ParallelFor& parallelFor)
{
  return Build(numVertices, IndexArray(faceOffsets.begin(), faceOffsets.end()),
    IndexArray(faceVertices.begin(), faceVertices.end()), parallelFor);
}

MeshTopology MeshTopology::Build(
  Index numVertices, IndexArray faceOffsets, IndexArray faceVertices, const ParallelFor& parallelFor)
{
  MeshTopology topology = BuildFacesOnly(numVertices, std::move(faceOffsets), std::move(faceVertices));
  topology.BuildEdges();
  topology.BuildEdgeFaces();
  topology.BuildVertexRelations();
  topology.TagEdges();
  topology.TagVertices(parallelFor);
  return topology;
}

// Edges are found by bucketing every half-edge under its lower vertex and sorting each
// (small) bucket by the upper vertex: linear in the mesh size for bounded valence, and
// O(k log k) for a vertex of valence k, so even a 100k-valent hub stays fast.
void MeshTopology::BuildEdges()
{
  const Index numFaces = this->GetNumFaces();
  const size_t numHalfEdges = this->FaceVertices.size();

  // Each half-edge h as one key, (upper vertex, h): sorting a bucket compares the keys
  // themselves, not values looked up elsewhere.
  auto key = [](Index upper, Index h) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(upper)) << 32) | static_cast<std::uint32_t>(h);
  };
  IndexArray bucketOffsets(static_cast<size_t>(this->NumVertices) + 1, 0);
  for (Index f = 0; f < numFaces; ++f)
  {
    const Index begin = this->FaceOffsets[f], end = this->FaceOffsets[f + 1];
    for (Index h = begin; h < end; ++h)
    {
      const Index a = this->FaceVertices[h];
      const Index b = this->FaceVertices[h + 1 < end ? h + 1 : begin];
      ++bucketOffsets[std::min(a, b) + 1];
    }
  }
  CountsToOffsets(bucketOffsets);

  LevelArray<std::uint64_t> buckets(numHalfEdges);
  {
    IndexArray fill(bucketOffsets.begin(), bucketOffsets.end() - 1);
    for (Index f = 0; f < numFaces; ++f)
    {
      const Index begin = this->FaceOffsets[f], end = this->FaceOffsets[f + 1];
      for (Index h = begin; h < end; ++h)
      {
        const Index a = this->FaceVertices[h];
        const Index b = this->FaceVertices[h + 1 < end ? h + 1 : begin];
        buckets[fill[std::min(a, b)]++] = key(std::max(a, b), h);
      }
    }
  }

  // representative[h]: the first half-edge (lowest index) with the same vertex pair as h.
  IndexArray representative(numHalfEdges);
  for (Index v = 0; v < this->NumVertices; ++v)
  {
    std::uint64_t* first = buckets.data() + bucketOffsets[v];
    std::uint64_t* last = buckets.data() + bucketOffsets[v + 1];
    std::sort(first, last);
    for (std::uint64_t* it = first; it != last; ++it)
    {
      const Index h = static_cast<Index>(*it & 0xffffffffu);
      const bool startsRun = (it == first) || (*(it - 1) >> 32) != (*it >> 32);
      representative[h] = startsRun ? h : representative[static_cast<Index>(*(it - 1) & 0xffffffffu)];
    }
  }

  this->FaceEdges.resize(numHalfEdges); // every entry written below
  this->EdgeVertices.clear();
  this->EdgeVertices.reserve(numHalfEdges + 8);
  Index numEdges = 0;
  for (Index f = 0; f < numFaces; ++f)
  {
    const Index begin = this->FaceOffsets[f], end = this->FaceOffsets[f + 1];
    for (Index h = begin; h < end; ++h)
    {
      if (representative[h] == h)
      {
        this->FaceEdges[h] = numEdges++;
        this->EdgeVertices.push_back(this->FaceVertices[h]);
        this->EdgeVertices.push_back(this->FaceVertices[h + 1 < end ? h + 1 : begin]);
      }
      else
      {
        this->FaceEdges[h] = this->FaceEdges[representative[h]];
      }
    }
  }
  this->EdgeVertices.shrink_to_fit();
}

void MeshTopology::BuildEdgeFaces()
{
  const Index numFaces = this->GetNumFaces();
  const Index numEdges = this->GetNumEdges();
  this->EdgeFaceOffsets.assign(static_cast<size_t>(numEdges) + 1, 0);
  for (Index e : this->FaceEdges)
  {
    ++this->EdgeFaceOffsets[e + 1];
  }
  CountsToOffsets(this->EdgeFaceOffsets);
  this->EdgeFaces.resize(this->FaceEdges.size());
  IndexArray fill(this->EdgeFaceOffsets.begin(), this->EdgeFaceOffsets.end() - 1);
  for (Index f = 0; f < numFaces; ++f)
  {
    for (Index h = this->FaceOffsets[f]; h < this->FaceOffsets[f + 1]; ++h)
    {
      this->EdgeFaces[fill[this->FaceEdges[h]]++] = f;
    }
  }
}

void MeshTopology::BuildVertexRelations()
{
  const size_t numVertexSlots = static_cast<size_t>(this->NumVertices) + 1;
  this->VertexFaceOffsets.assign(numVertexSlots, 0);
  for (Index v : this->FaceVertices)
  {
    ++this->VertexFaceOffsets[v + 1];
  }
  CountsToOffsets(this->VertexFaceOffsets);
  this->VertexFaces.resize(this->FaceVertices.size());
  this->VertexFaceCorners.resize(this->FaceVertices.size());
  {
    IndexArray fill(this->VertexFaceOffsets.begin(), this->VertexFaceOffsets.end() - 1);
    const Index numFaces = this->GetNumFaces();
    for (Index f = 0; f < numFaces; ++f)
    {
      for (Index h = this->FaceOffsets[f]; h < this->FaceOffsets[f + 1]; ++h)
      {
        const Index slot = fill[this->FaceVertices[h]]++;
        this->VertexFaces[slot] = f;
        this->VertexFaceCorners[slot] = h - this->FaceOffsets[f];
      }
    }
  }

  this->VertexEdgeOffsets.assign(numVertexSlots, 0);
  for (Index v : this->EdgeVertices)
  {
    ++this->VertexEdgeOffsets[v + 1];
  }
  CountsToOffsets(this->VertexEdgeOffsets);
  this->VertexEdges.resize(this->EdgeVertices.size());
  IndexArray fill(this->VertexEdgeOffsets.begin(), this->VertexEdgeOffsets.end() - 1);
  const Index numEdges = this->GetNumEdges();
  for (Index e = 0; e < numEdges; ++e)
  {
    this->VertexEdges[fill[this->EdgeVertices[2 * e]]++] = e;
    this->VertexEdges[fill[this->EdgeVertices[2 * e + 1]]++] = e;
  }
  this->MaxValence = 0;
  for (Index v = 0; v < this->NumVertices; ++v)
  {
    this->MaxValence = std::max(this->MaxValence, this->GetVertexEdges(v).size());
  }
}

void MeshTopology::TagEdges()
{
  const Index numEdges = this->GetNumEdges();
  // How many incident faces run along the edge in its stored direction: a consistently
  // oriented manifold edge with two faces has exactly one.
  std::vector<std::uint8_t> forwardCount(static_cast<size_t>(numEdges), 0);
  const Index numFaces = this->GetNumFaces();
  for (Index f = 0; f < numFaces; ++f)
  {
    for (Index h = this->FaceOffsets[f]; h < this->FaceOffsets[f + 1]; ++h)
    {
      const Index e = this->FaceEdges[h];
      if (this->FaceVertices[h] == this->EdgeVertices[2 * e] && forwardCount[e] < 255)
      {
        ++forwardCount[e];
      }
    }
  }
  this->EdgeTags.assign(static_cast<size_t>(numEdges), EdgeTag{ 0, 0 });
  this->NumNonManifoldEdges = 0;
  this->NumBoundaryEdges = 0;
  for (Index e = 0; e < numEdges; ++e)
  {
    const Index faces = this->GetEdgeFaces(e).size();
    EdgeTag& tag = this->EdgeTags[e];
    tag.Boundary = faces == 1;
    tag.NonManifold = faces > 2 || (faces == 2 && forwardCount[e] != 1);
    this->NumNonManifoldEdges += tag.NonManifold;
    this->NumBoundaryEdges += tag.Boundary;
  }
}

// A vertex is manifold when its faces form one fan: union the faces that share an edge at
// the vertex (manifold edges only) and count the groups.
void MeshTopology::TagVertices(const ParallelFor& parallelFor)
{
  this->VertexTags.resize(static_cast<size_t>(this->NumVertices));
  parallelFor(0, this->NumVertices, [this](Index begin, Index end) {
    std::vector<Index> fanScratch;
    for (Index v = begin; v < end; ++v)
    {
      VertexTag tag{ 0, 0 };
      for (Index e : this->GetVertexEdges(v))
      {
        tag.Boundary |= this->EdgeTags[e].Boundary;
        tag.NonManifold |= this->EdgeTags[e].NonManifold;
      }
      if (!tag.NonManifold)
      {
        tag.NonManifold = this->CountFans(v, fanScratch) > 1;
      }
      this->VertexTags[v] = tag;
    }
  });
  this->NumNonManifoldVertices = 0;
  for (const VertexTag& tag : this->VertexTags)
  {
    this->NumNonManifoldVertices += tag.NonManifold;
  }
}

// Union-find over v's faces, joined across v's edges with two faces. It reads only v's own
// lists and its edges' faces: cheaper than walking from face to face, which reads each
// neighbour face's corners and edges.
Index MeshTopology::CountFans(Index v, std::vector<Index>& parent) const
{
  const IndexSpan faces = this->GetVertexFaces(v);
  if (faces.size() <= 1)
  {
    return faces.size();
  }
  constexpr Index smallValence = 32;
  if (faces.size() <= smallValence)
  {
    // Faces j and k share an edge at v when one leaves v along the edge the other enters
    // by (called for vertices whose edges are manifold and consistently oriented): a
    // union-find over at most 32 local slots, the edges read from the faces' own lists.
    const IndexSpan corners = this->GetVertexFaceCorners(v);
    const Index n = faces.size();
    Index leaving[smallValence], entering[smallValence], group[smallValence];
    for (Index k = 0; k < n; ++k)
    {
      const IndexSpan fe = this->GetFaceEdges(faces[k]);
      leaving[k] = fe[corners[k]];
      entering[k] = fe[corners[k] == 0 ? fe.size() - 1 : corners[k] - 1];
      group[k] = k;
    }
    auto root = [&group](Index i) {
      while (group[i] != i)
      {
        i = group[i] = group[group[i]];
      }
      return i;
    };
    Index groups = n;
    for (Index j = 0; j < n; ++j)
    {
      for (Index k = 0; k < n; ++k)
      {
        if (j != k && leaving[j] == entering[k])
        {
          const Index rj = root(j), rk = root(k);
          groups -= rj != rk;
          group[rj] = rk;
        }
      }
    }
    return groups;
  }
  parent.resize(faces.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&parent](Index i) {
    while (parent[i] != i)
    {
      i = parent[i] = parent[parent[i]];
    }
    return i;
  };
  // Faces of a vertex are stored in increasing order: binary search gives local slots.
  auto slot = [&faces](Index f) {
    return static_cast<Index>(std::lower_bound(faces.begin(), faces.end(), f) - faces.begin());
  };
  Index groups = faces.size();
  for (Index e : this->GetVertexEdges(v))
  {
    const IndexSpan ef = this->GetEdgeFaces(e);
    if (ef.size() == 2)
    {
      const Index r0 = root(slot(ef[0])), r1 = root(slot(ef[1]));
      if (r0 != r1)
      {
        parent[r0] = r1;
        --groups;
      }
    }
  }
  return groups;
}

Index MeshTopology::GetTriangleOppositeVertex(Index f, Index e) const
{
  const Index* ev = this->GetEdgeVertices(e);
  return this->GetTriangleThirdVertex(f, ev[0], ev[1]);
}

Index MeshTopology::GetEdgePosition(Index f, Index e) const
{
  const IndexSpan fe = this->GetFaceEdges(f);
  if (fe.size() <= 16)
  {
    Index i = 0;
    while (fe[i] != e)
    {
      ++i;
    }
    return i;
  }
  // A large polygon (a scan would make its edges quadratic): the edge starts or ends at the
  // corner of its first vertex, found through that vertex's faces.
  const Index i = this->FindCorner(this->GetEdgeVertices(e)[0], f);
  return fe[i] == e ? i : (i == 0 ? fe.size() - 1 : i - 1);
}

Index MeshTopology::FindCorner(Index v, Index f) const
{
  const IndexSpan faces = this->GetVertexFaces(v);
  const Index* it = std::lower_bound(faces.begin(), faces.end(), f);
  if (it == faces.end() || *it != f)
  {
    return InvalidIndex;
  }
  return this->GetVertexFaceCorners(v)[static_cast<Index>(it - faces.begin())];
}

bool MeshTopology::GetOrderedVertexFaces(
  Index v, std::vector<Index>& faces, std::vector<Index>& corners) const
{
  faces.clear();
  corners.clear();
  const IndexSpan vf = this->GetVertexFaces(v);
  if (vf.empty() || this->VertexTags[v].NonManifold)
  {
    return false;
  }
  // Start: any face for an interior vertex; for a boundary vertex, the face whose edge
  // leaving v (edge at v's corner) is a boundary edge, so the walk covers the whole fan.
  Index face = vf[0];
  Index corner = this->GetVertexFaceCorners(v)[0];
  if (this->VertexTags[v].Boundary)
  {
    for (Index i = 0; i < vf.size(); ++i)
    {
      const Index c = this->GetVertexFaceCorners(v)[i];
      if (this->EdgeTags[this->GetFaceEdges(vf[i])[c]].Boundary)
      {
        face = vf[i];
        corner = c;
        break;
      }
    }
  }
  const IndexSpan vc = this->GetVertexFaceCorners(v);
  const Index K = vf.size();
  constexpr Index chainValence = 64;
  if (K <= chainValence)
  {
    // The next face is the one whose edge leaving v is the edge entering v in this one
    // (the two faces of a manifold edge at a manifold vertex run it in opposite directions):
    // match them among v's faces, whose edges are independent loads, instead of walking
    // across edges, where each step waits on the one before.
    Index leaving[chainValence], entering[chainValence];
    Index current = 0;
    for (Index k = 0; k < K; ++k)
    {
      const IndexSpan fe = this->GetFaceEdges(vf[k]);
      leaving[k] = fe[vc[k]];
      entering[k] = fe[vc[k] == 0 ? fe.size() - 1 : vc[k] - 1];
      current = vf[k] == face ? k : current;
    }
    for (Index step = 0; step < K && current != InvalidIndex; ++step)
    {
      faces.push_back(vf[current]);
      corners.push_back(vc[current]);
      Index next = InvalidIndex;
      for (Index j = 0; j < K; ++j)
      {
        next = j != current && leaving[j] == entering[current] ? j : next;
      }
      current = next;
    }
    return static_cast<Index>(faces.size()) == K;
  }
  for (Index step = 0; step < K; ++step)
  {
    faces.push_back(face);
    corners.push_back(corner);
    // Cross the edge entering v in this face (edge at the previous corner).
    const Index n = this->GetFaceSize(face);
    const Index entering = this->GetFaceEdges(face)[corner == 0 ? n - 1 : corner - 1];
    const IndexSpan ef = this->GetEdgeFaces(entering);
    if (ef.size() != 2)
    {
      break; // reached the boundary
    }
    face = ef[0] == face ? ef[1] : ef[0];
    corner = this->FindCorner(v, face);
  }
  return static_cast<Index>(faces.size()) == K;
}

Index MeshTopology::FindEdge(Index a, Index b) const
{
  if (a < 0 || a >= this->NumVertices)
  {
    return InvalidIndex;
  }
  for (Index e : this->GetVertexEdges(a))
  {
    if (this->GetOtherEndpoint(e, a) == b)
    {
      return e;
    }
  }
  return InvalidIndex;
}
}
