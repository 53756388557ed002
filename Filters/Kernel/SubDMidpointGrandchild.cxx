#include "SubDMidpointGrandchild.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace subd
{
namespace
{
// The arrays of a level the closed form reads (MeshTopology::Part::FacesWithEdges): its
// faces' offsets and edges and its edges' ends. A corner's vertex is the end its edge shares
// with the edge before it (no face repeats a vertex, so they share one end only).
struct FacesWithEdges
{
  explicit FacesWithEdges(const MeshTopology& topology)
    : Offsets(topology.GetFaceOffsetArray().data())
    , Edges(topology.GetFaceEdgeArray().data())
    , Topology(topology)
  {
  }
  // The vertex at corner h, whose previous corner in its face is `previous`.
  Index VertexAt(Index h, Index previous) const
  {
    const Index* ends = this->Topology.GetEdgeVertices(this->Edges[h]);
    const Index* before = this->Topology.GetEdgeVertices(this->Edges[previous]);
    return ends[0] == before[0] || ends[0] == before[1] ? ends[0] : ends[1];
  }
  // Whether corner h holds its edge's first half-edge: the one that starts at the edge's
  // first end (the two half-edges of a manifold edge start at its two ends).
  bool IsFirstHalfEdge(Index h, Index previous) const
  {
    return this->VertexAt(h, previous) == this->Topology.GetEdgeVertices(this->Edges[h])[0];
  }
  // Calls visit(f, h, previous corner) for the corners of the faces [begin, end).
  template <typename Visit>
  void ForEachCorner(Index begin, Index end, Visit&& visit) const
  {
    for (Index f = begin; f < end; ++f)
    {
      const Index first = this->Offsets[f], last = this->Offsets[f + 1];
      for (Index h = first, previous = last - 1; h < last; previous = h++)
      {
        visit(f, h, previous);
      }
    }
  }

  const Index* Offsets;
  const Index* Edges;
  const MeshTopology& Topology;
};

class MidpointGrandchildRows final : public RowSourceWithApply<MidpointGrandchildRows>
{
  friend class RowSourceWithApply<MidpointGrandchildRows>;

public:
  explicit MidpointGrandchildRows(std::shared_ptr<const Level> grandparent)
    : Grandparent(std::move(grandparent))
  {
  }
  Index GetNumParents() const override { return this->Grandparent->Topology.GetNumEdges(); }
  Index GetNumRows() const override { return this->Grandparent->Topology.GetNumFaceCorners(); }
  std::vector<Index> GetBlockEnds() const override { return { this->GetNumRows() }; }

private:
  template <typename T>
  void Apply(const T* parents, T* children, int components, Index begin, Index end) const
  {
    if (begin >= end)
    {
      return;
    }
    const MeshTopology& topology = this->Grandparent->Topology;
    const IndexArray& offsets = topology.GetFaceOffsetArray();
    const Index* edges = topology.GetFaceEdgeArray().data();
    const Index numParents = this->GetNumParents();
    const double halves[2] = { 0.5, 0.5 };
    std::vector<double> sum(static_cast<size_t>(components));
    // The face holding row `begin`, then face after face.
    Index f = static_cast<Index>(std::upper_bound(offsets.begin(), offsets.end(), begin) - offsets.begin()) - 1;
    for (Index row = begin; row < end; ++f)
    {
      const Index first = offsets[f], last = offsets[f + 1];
      for (; row < last && row < end; ++row)
      {
        const Index ends[2] = { edges[row], edges[row + 1 < last ? row + 1 : first] };
        ApplyRow(ends, halves, 2, numParents, parents, children, components, sum.data(),
          children + static_cast<size_t>(row) * components);
      }
    }
  }

  std::shared_ptr<const Level> Grandparent;
};
}

bool MidpointGrandchildHasClosedForm(const Level& grandparent)
{
  const MeshTopology& topology = grandparent.Topology;
  if (topology.GetNumFaces() == 0 || topology.GetNumBoundaryEdges() != 0 || topology.GetNumNonManifoldEdges() != 0 ||
    topology.GetNumNonManifoldVertices() != 0 || grandparent.FaceTagShift != 0 || grandparent.HasHoles() ||
    grandparent.HasSharpFeatures())
  {
    return false;
  }
  if (!topology.HasVertexRelations())
  {
    // Split for a grandchild alone (MidpointChildWithEdges) from a level with the closed
    // form: four faces at each vertex. (A level trimmed otherwise keeps no faces' edges.)
    return topology.GetFaceVertexArray().empty() && !topology.GetFaceEdgeArray().empty();
  }
  if (!topology.HasEdges())
  {
    return false;
  }
  for (Index v = 0; v < topology.GetNumVertices(); ++v)
  {
    if (topology.GetNumVertexFaces(v) < 3) // a vertex of two faces gets no V-face
    {
      return false;
    }
  }
  return true;
}

std::shared_ptr<const RowSource> MakeMidpointGrandchildRowSource(std::shared_ptr<const Level> grandparent)
{
  return std::make_shared<MidpointGrandchildRows>(std::move(grandparent));
}

namespace
{
// The origins of the faces of one split of a closed smooth level into `out` (as many as the
// level's faces and vertices): its faces' own (the F-faces) then, per vertex, the lowest of
// its faces' (the V-faces).
void WriteSplitOrigins(const FacesWithEdges& faces, const Index* origin, Index* out)
{
  const Index numFaces = faces.Topology.GetNumFaces(), numVertices = faces.Topology.GetNumVertices();
  std::copy(origin, origin + numFaces, out);
  Index* vertexFaces = out + numFaces;
  std::fill(vertexFaces, vertexFaces + numVertices, std::numeric_limits<Index>::max());
  faces.ForEachCorner(0, numFaces, [&](Index f, Index h, Index previous) {
    Index& lowest = vertexFaces[faces.VertexAt(h, previous)];
    lowest = std::min(lowest, origin[f]);
  });
}
}

namespace
{
// One split of a closed smooth level along the child's edges, which are numbered by the
// level's corners: `offsets` (as many as the level's faces and vertices, plus one) and
// `edges` (two per corner) get the F-faces' then the V-faces' edges; `quads` (four per edge
// of the level) each edge's half-edges (corners: the first one's, then the second one's),
// each with the corner before it in its face, from which the fans are walked.
void WriteSplitFaceEdges(
  const FacesWithEdges& faces, Index* offsets, Index* edges, Index* quads, const ParallelFor& parallelFor)
{
  const Index numFaces = faces.Topology.GetNumFaces(), numVertices = faces.Topology.GetNumVertices();
  const Index numCorners = faces.Topology.GetNumFaceCorners();
  // F-faces: along the edges of their corners (written last: until then the first entries
  // hold each vertex's first corner, where its fan starts, in its lowest face; every vertex
  // has three corners or more, so there is room).
  std::copy(faces.Offsets, faces.Offsets + numFaces + 1, offsets);
  // V-faces: as many edges as the vertex has faces.
  Index* vertexEnds = offsets + numFaces + 1;
  Index* fanStart = edges;
  std::fill(vertexEnds, vertexEnds + numVertices, 0);
  std::fill(fanStart, fanStart + numVertices, InvalidIndex);
  faces.ForEachCorner(0, numFaces, [&](Index, Index h, Index previous) {
    const Index v = faces.VertexAt(h, previous);
    ++vertexEnds[v];
    fanStart[v] = fanStart[v] == InvalidIndex ? h : fanStart[v];
  });
  for (Index v = 0; v < numVertices; ++v)
  {
    vertexEnds[v] += offsets[numFaces + v];
  }
  parallelFor(0, numFaces, [&](Index begin, Index end) {
    faces.ForEachCorner(begin, end, [&](Index, Index h, Index previous) {
      Index* quad = quads + 4 * static_cast<size_t>(faces.Edges[h]) + (faces.IsFirstHalfEdge(h, previous) ? 0 : 2);
      quad[0] = h;
      quad[1] = previous;
    });
  });
  // The corner before h ends at h's start vertex v, and the other half-edge of its edge
  // starts at v in the next face of v's fan: the V-face runs along the edges of the corners
  // before v's, in fan order.
  auto previousOf = [quads, &faces](Index h) {
    const Index* quad = quads + 4 * static_cast<size_t>(faces.Edges[h]);
    return quad[0] == h ? quad[1] : quad[3];
  };
  auto otherHalfOf = [quads, &faces](Index h) {
    const Index* quad = quads + 4 * static_cast<size_t>(faces.Edges[h]);
    return quad[0] == h ? quad[2] : quad[0];
  };
  parallelFor(0, numVertices, [&](Index begin, Index end) {
    for (Index v = begin; v < end; ++v)
    {
      Index h = fanStart[v];
      for (Index k = offsets[numFaces + v]; k < offsets[numFaces + v + 1]; ++k)
      {
        const Index previous = previousOf(h);
        edges[k] = previous;
        h = otherHalfOf(previous);
      }
    }
  });
  parallelFor(0, numCorners, [&](Index begin, Index end) {
    for (Index h = begin; h < end; ++h)
    {
      edges[h] = h;
    }
  });
}
}

Level MidpointChildWithEdges(const Level& parent, bool keepOrigins, const ParallelFor& parallelFor)
{
  const MeshTopology& topology = parent.Topology;
  const FacesWithEdges faces(topology);
  const Index numFaces = topology.GetNumFaces(), numVertices = topology.GetNumVertices();
  const Index numCorners = topology.GetNumFaceCorners();
  IndexArray offsets(static_cast<size_t>(numFaces) + numVertices + 1);
  IndexArray edges(2 * static_cast<size_t>(numCorners));
  {
    IndexArray quads(4 * static_cast<size_t>(topology.GetNumEdges()));
    WriteSplitFaceEdges(faces, offsets.data(), edges.data(), quads.data(), parallelFor);
  }
  // The child's edge h joins the points of the parent's edges at h and after it.
  IndexArray edgeEnds(2 * static_cast<size_t>(numCorners));
  parallelFor(0, numFaces, [&](Index begin, Index end) {
    faces.ForEachCorner(begin, end, [&](Index, Index h, Index previous) {
      edgeEnds[2 * static_cast<size_t>(previous)] = faces.Edges[previous];
      edgeEnds[2 * static_cast<size_t>(previous) + 1] = faces.Edges[h];
    });
  });
  Level child;
  child.Depth = parent.Depth + 1;
  child.Creasing = parent.Creasing;
  if (keepOrigins)
  {
    child.FaceOrigin.resize(static_cast<size_t>(numFaces) + numVertices);
    WriteSplitOrigins(faces, parent.FaceOrigin.data(), child.FaceOrigin.data());
  }
  child.Topology =
    MeshTopology::BuildFacesWithEdges(topology.GetNumEdges(), std::move(offsets), std::move(edges), std::move(edgeEnds));
  return child;
}

Level MidpointGrandchildTags(const Level& grandparent, bool keepOrigins, const ParallelFor& parallelFor)
{
  Level fine;
  fine.Depth = grandparent.Depth + 2;
  fine.Creasing = grandparent.Creasing;
  if (!keepOrigins)
  {
    return fine;
  }
  const MeshTopology& topology = grandparent.Topology;
  const FacesWithEdges faces(topology);
  const Index numFaces = topology.GetNumFaces(), numVertices = topology.GetNumVertices();
  const Index* origin = grandparent.FaceOrigin.data();
  fine.FaceOrigin.resize(static_cast<size_t>(numFaces) + numVertices + topology.GetNumEdges());
  WriteSplitOrigins(faces, origin, fine.FaceOrigin.data());
  const Index* vertexFaces = fine.FaceOrigin.data() + numFaces;
  Index* edgeFaces = fine.FaceOrigin.data() + numFaces + numVertices;
  // An edge's V-face comes from its two faces and its ends' V-faces: each half-edge brings
  // its face and the end it starts at; the first half-edges write, then the second ones
  // (one writer per edge in each pass).
  for (const bool firstHalves : { true, false })
  {
    parallelFor(0, numFaces, [&](Index begin, Index end) {
      faces.ForEachCorner(begin, end, [&](Index f, Index h, Index previous) {
        const Index v = faces.VertexAt(h, previous);
        if ((v == topology.GetEdgeVertices(faces.Edges[h])[0]) == firstHalves) // IsFirstHalfEdge
        {
          const Index lowest = std::min(origin[f], vertexFaces[v]);
          Index& edgeFace = edgeFaces[faces.Edges[h]];
          edgeFace = firstHalves ? lowest : std::min(edgeFace, lowest);
        }
      });
    });
  }
  return fine;
}

MeshTopology MidpointGrandchildFaces(const MeshTopology& grandparent, const ParallelFor& parallelFor)
{
  // The faces of the split of the level between are those of the grandparent's split along
  // its edges (F-faces of F- and V-faces), then its V-faces: the quads.
  const FacesWithEdges faces(grandparent);
  const Index numFaces = grandparent.GetNumFaces(), numVertices = grandparent.GetNumVertices();
  const Index numEdges = grandparent.GetNumEdges(), numCorners = grandparent.GetNumFaceCorners();
  IndexArray offsets(static_cast<size_t>(numFaces) + numVertices + numEdges + 1);
  IndexArray vertices(2 * static_cast<size_t>(numCorners) + 4 * static_cast<size_t>(numEdges));
  const Index quadsBegin = 2 * numCorners;
  WriteSplitFaceEdges(faces, offsets.data(), vertices.data(), vertices.data() + quadsBegin, parallelFor);
  Index* quadEnds = offsets.data() + numFaces + numVertices + 1;
  parallelFor(0, numEdges, [&](Index begin, Index end) {
    for (Index e = begin; e < end; ++e)
    {
      quadEnds[e] = quadsBegin + 4 * (e + 1);
    }
  });
  return MeshTopology::BuildFacesOnly(numCorners, std::move(offsets), std::move(vertices));
}

Index CountMidpointGrandchildFaces(const MeshTopology& grandparent)
{
  return grandparent.GetNumFaces() + grandparent.GetNumVertices() + grandparent.GetNumEdges();
}
}
