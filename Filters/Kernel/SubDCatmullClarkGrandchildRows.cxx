#include "SubDCatmullClarkGrandchildRows.h"
#include "SubDCatmullClarkRules.h"
#include "SubDQuadSplit.h"

#include <algorithm>

namespace subd
{
namespace
{
// A point's few edges, in increasing order as the child topology lists them.
void SortShortList(Index* first, Index* last)
{
  for (Index* i = first + 1; i < last; ++i)
  {
    const Index value = *i;
    Index* j = i;
    for (; j > first && *(j - 1) > value; --j)
    {
      *j = *(j - 1);
    }
    *j = value;
  }
}

// The rows of the grandchild (finest) points of grandparent P, in the parent C's numbering
// (QuadSplitNumbering of C; sources below NumParents are C's points), written from P.
struct SmoothRowWriter
{
  const MeshTopology& Topology; // P's
  const ChildEdgeNumbering& ParentEdges;
  Index NumParents;     // C's points
  QuadSplitNumbering Point; // C's points from P's elements
  QuadSplitShape Shape{ Topology };
  Index NumChildFaces = Topology.GetNumFaceCorners(); // C's faces: the finest face points
  Index NumChildEdges = ParentEdges.FirstEdgeOfFace.back();

  Index EdgeOfKey(Index key) const { return this->ParentEdges.EdgeOfKey[key]; }
  Index InsideKey(Index f, Index j) const { return 2 * this->Point.NumEdges + this->Topology.GetFaceOffset(f) + j; }

  // C's face (f, j): the average of its corners.
  Index WriteFaceRow(Index f, Index j, Index* sources, double* weights) const
  {
    GetQuadSplitChild(this->Topology, this->Point, f, j, sources);
    for (int s = 0; s < 4; ++s)
    {
      weights[s] = 1.0 / 4;
    }
    return 4;
  }

  // C's edge first met at `corner` of P's face f's children, with key `key`: its two ends and
  // the face points of its two faces, a quarter each (the smooth edge rule).
  Index WriteEdgeRow(Index f, Index corner, Index key, Index* sources, double* weights) const
  {
    const MeshTopology& topo = this->Topology;
    const Index h = corner / 4, s = corner % 4;
    Index child[4];
    GetQuadSplitChild(topo, this->Point, f, h - topo.GetFaceOffset(f), child);
    sources[0] = child[s];
    sources[1] = child[(s + 1) % 4];
    Index* faces = sources + 2;
    if (key < 2 * this->Point.NumEdges)
    {
      // A half of e: in each face of e, the child at the half's vertex. The first face is f
      // (where the half is first met), whose child h holds it.
      const Index e = key / 2;
      const Index v = topo.GetEdgeVertices(e)[key % 2];
      const Index g = topo.GetEdgeFaces(e)[1];
      const Index i = topo.GetEdgePosition(g, e);
      const Index at = topo.GetFaceVertices(g)[i] == v ? i : (i + 1 == topo.GetFaceSize(g) ? 0 : i + 1);
      faces[0] = h;
      faces[1] = topo.GetFaceOffset(g) + at;
    }
    else
    {
      // Inside f, between the children at its corners j and j + 1.
      const Index first = topo.GetFaceOffset(f);
      const Index inside = key - 2 * this->Point.NumEdges;
      const bool last = inside + 1 == first + topo.GetFaceSize(f);
      faces[0] = last ? first : inside;
      faces[1] = last ? inside : inside + 1;
    }
    faces[0] += this->NumParents;
    faces[1] += this->NumParents;
    std::fill(weights, weights + 4, 0.25);
    return 4;
  }

  // C's point p with a closed fan and nothing sharp: CatmullClarkRowWriter's smooth vertex
  // row, p's edge points and face points listed in increasing order as C lists them.
  Index WriteVertexRow(Index p, Index* sources, double* weights) const
  {
    const MeshTopology& topo = this->Topology;
    Index* edges = sources + 1;
    Index numEdges = 0;
    Index faceList[2 * 64];
    std::vector<Index> longFaceList;
    Index* faces = faceList;
    Index numFaces = 0;
    auto reserveFaces = [&](Index count) {
      if (count > static_cast<Index>(sizeof(faceList) / sizeof(Index)))
      {
        longFaceList.resize(static_cast<size_t>(count));
        faces = longFaceList.data();
      }
    };
    if (p < this->Point.NumFaces)
    {
      const Index f = p, n = topo.GetFaceSize(f), first = topo.GetFaceOffset(f);
      reserveFaces(n);
      for (Index j = 0; j < n; ++j)
      {
        edges[numEdges++] = this->EdgeOfKey(this->InsideKey(f, j));
        faces[numFaces++] = first + j;
      }
    }
    else if (p < this->Point.VertexPoint(0))
    {
      const Index e = p - this->Point.NumFaces;
      edges[numEdges++] = this->EdgeOfKey(2 * e);
      edges[numEdges++] = this->EdgeOfKey(2 * e + 1);
      const IndexSpan edgeFaces = topo.GetEdgeFaces(e);
      reserveFaces(2 * edgeFaces.size());
      for (Index g : edgeFaces)
      {
        const Index i = topo.GetEdgePosition(g, e);
        const Index leaving = topo.GetFaceOffset(g) + i;
        const Index entering = i + 1 == topo.GetFaceSize(g) ? topo.GetFaceOffset(g) : leaving + 1;
        edges[numEdges++] = this->EdgeOfKey(this->InsideKey(g, i));
        faces[numFaces++] = std::min(leaving, entering);
        faces[numFaces++] = std::max(leaving, entering);
      }
    }
    else
    {
      const Index v = p - this->Point.VertexPoint(0);
      for (Index e : topo.GetVertexEdges(v))
      {
        edges[numEdges++] = this->EdgeOfKey(HalfEdgeKey(topo, e, v));
      }
      const IndexSpan vertexFaces = topo.GetVertexFaces(v);
      const IndexSpan corners = topo.GetVertexFaceCorners(v);
      reserveFaces(vertexFaces.size());
      for (Index k = 0; k < vertexFaces.size(); ++k)
      {
        faces[numFaces++] = topo.GetFaceOffset(vertexFaces[k]) + corners[k];
      }
    }
    SortShortList(edges, edges + numEdges);
    const double n = numFaces;
    sources[0] = p;
    weights[0] = (n - 3.0) / n;
    for (Index i = 0; i < numEdges; ++i)
    {
      sources[1 + i] += this->NumParents + this->NumChildFaces;
      weights[1 + i] = 4.0 / (n * n);
    }
    for (Index i = 0; i < numFaces; ++i)
    {
      sources[1 + numEdges + i] = this->NumParents + faces[i];
      weights[1 + numEdges + i] = -1.0 / (n * n);
    }
    return 1 + numEdges + numFaces;
  }
};
}

CatmullClarkGrandchildRows::CatmullClarkGrandchildRows(
  std::shared_ptr<const Level> grandparent, const Level& parent, const ParallelFor& parallelFor)
  : Grandparent(std::move(grandparent))
{
  const MeshTopology& topo = this->Grandparent->Topology;
  this->NumParentFaces = topo.GetNumFaces();
  this->NumParentEdges = topo.GetNumEdges();
  this->ParentEdges = NumberChildEdges(QuadSplitShape{ topo }, parallelFor);
  this->NumParents = parent.Topology.GetNumVertices();
  this->NumRows = parent.Topology.GetNumFaces() + parent.Topology.GetNumEdges() + this->NumParents;

  // The rows without a smooth form (creases, boundaries, corners, non-manifold points), from
  // the parent's own writer, in row order.
  const CatmullClarkRowWriter writer(parent, parallelFor);
  this->MaxRowSize = writer.GetMaxRowSize();
  for (Index row = parent.Topology.GetNumFaces(); row < this->NumRows; ++row)
  {
    if (!writer.IsSmoothRow(row))
    {
      this->StoredRows.push_back(row);
    }
  }
  this->StoredTable = StencilTable(this->NumParents);
  std::vector<Index> sources(static_cast<size_t>(this->MaxRowSize));
  std::vector<double> weights(sources.size());
  for (Index row : this->StoredRows)
  {
    const Index size = writer.WriteRow(row, sources.data(), weights.data());
    this->StoredTable.AppendRow(sources.data(), weights.data(), size);
  }
}

std::vector<Index> CatmullClarkGrandchildRows::GetBlockEnds() const
{
  const Index numChildFaces = this->Grandparent->Topology.GetNumFaceCorners();
  return { numChildFaces, numChildFaces + this->ParentEdges.FirstEdgeOfFace.back(), this->NumRows };
}

// Calls emit(row, sources, weights, size) for rows [begin, end) in increasing order: a stored
// row as stored, any other written from the grandparent into `sources` and `weights`.
template <typename Emit>
void CatmullClarkGrandchildRows::WriteRows(Index begin, Index end, Index* sources, double* weights, Emit&& emit) const
{
  const MeshTopology& topo = this->Grandparent->Topology;
  const SmoothRowWriter writer{ topo, this->ParentEdges, this->NumParents,
    QuadSplitNumbering{ this->NumParentFaces, this->NumParentEdges } };
  size_t stored = static_cast<size_t>(
    std::lower_bound(this->StoredRows.begin(), this->StoredRows.end(), begin) - this->StoredRows.begin());
  auto put = [&](Index row, auto&& write) {
    if (stored < this->StoredRows.size() && this->StoredRows[stored] == row)
    {
      const IndexSpan rowSources = this->StoredTable.GetSources(static_cast<Index>(stored));
      emit(row, rowSources.begin(), this->StoredTable.GetWeights(static_cast<Index>(stored)), rowSources.size());
      ++stored;
      return;
    }
    emit(row, sources, weights, write());
  };

  // Face points: C's faces, the children of P's faces corner by corner.
  const IndexArray& faceOffsets = topo.GetFaceOffsetArray();
  const Index facesEnd = std::min(end, writer.NumChildFaces);
  if (begin < facesEnd)
  {
    Index f = static_cast<Index>(std::upper_bound(faceOffsets.begin(), faceOffsets.end(), begin) - faceOffsets.begin()) - 1;
    for (Index c = begin; c < facesEnd; ++c)
    {
      while (faceOffsets[f + 1] <= c)
      {
        ++f;
      }
      put(c, [&] { return writer.WriteFaceRow(f, c - faceOffsets[f], sources, weights); });
    }
  }

  // Edge points: C's edges, numbered as the walk over P's faces' children first meets them.
  const Index firstEdgeRow = writer.NumChildFaces;
  const Index edgesBegin = std::max(begin, firstEdgeRow) - firstEdgeRow;
  const Index edgesEnd = std::min(end, firstEdgeRow + writer.NumChildEdges) - firstEdgeRow;
  if (edgesBegin < edgesEnd)
  {
    const IndexArray& firstEdge = this->ParentEdges.FirstEdgeOfFace;
    Index f = static_cast<Index>(std::upper_bound(firstEdge.begin(), firstEdge.end(), edgesBegin) - firstEdge.begin()) - 1;
    for (; f < this->NumParentFaces && firstEdge[f] < edgesEnd; ++f)
    {
      Index next = firstEdge[f];
      writer.Shape.VisitCorners(f, [&](Index corner, Index key, bool isNew) {
        if (!isNew)
        {
          return;
        }
        const Index k = next++;
        if (k >= edgesBegin && k < edgesEnd)
        {
          put(firstEdgeRow + k, [&] { return writer.WriteEdgeRow(f, corner, key, sources, weights); });
        }
      });
    }
  }

  // Vertex points: C's points.
  const Index firstVertexRow = firstEdgeRow + writer.NumChildEdges;
  for (Index row = std::max(begin, firstVertexRow); row < end; ++row)
  {
    put(row, [&] { return writer.WriteVertexRow(row - firstVertexRow, sources, weights); });
  }
}

template <typename T>
void CatmullClarkGrandchildRows::Apply(const T* parents, T* children, int components, Index begin, Index end) const
{
  std::vector<Index> sources(static_cast<size_t>(this->MaxRowSize));
  std::vector<double> weights(sources.size());
  std::vector<double> sum(static_cast<size_t>(components));
  this->WriteRows(begin, end, sources.data(), weights.data(),
    [&](Index row, const Index* rowSources, const double* rowWeights, Index size) {
      ApplyRow(rowSources, rowWeights, size, this->NumParents, parents, children, components, sum.data(),
        children + static_cast<size_t>(row) * components);
    });
}

void CatmullClarkGrandchildRows::ApplyRows(
  const double* parents, double* children, int components, Index begin, Index end) const
{
  this->Apply(parents, children, components, begin, end);
}

void CatmullClarkGrandchildRows::ApplyRows(
  const float* parents, float* children, int components, Index begin, Index end) const
{
  this->Apply(parents, children, components, begin, end);
}

StencilTable CatmullClarkGrandchildRows::ToStencilTable() const
{
  StencilTable table(this->NumParents);
  std::vector<Index> sources(static_cast<size_t>(this->MaxRowSize));
  std::vector<double> weights(sources.size());
  this->WriteRows(0, this->NumRows, sources.data(), weights.data(),
    [&](Index, const Index* rowSources, const double* rowWeights, Index size) {
      table.AppendRow(rowSources, rowWeights, size);
    });
  for (Index end : this->GetBlockEnds())
  {
    table.EndBlock(end);
  }
  return table;
}

Level SplitQuadsTwice(const Level& grandparent, const ChildEdgeNumbering& parentEdges, const ParallelFor& parallelFor)
{
  const MeshTopology& topo = grandparent.Topology;
  const QuadSplitShape shape{ topo };
  const QuadSplitNumbering point{ topo.GetNumFaces(), topo.GetNumEdges() };
  const Index numChildFaces = topo.GetNumFaceCorners();
  const QuadSplitNumbering finePoint{ numChildFaces, parentEdges.FirstEdgeOfFace.back() };
  const Index numFineFaces = 4 * numChildFaces;
  IndexArray offsets(static_cast<size_t>(numFineFaces) + 1);
  IndexArray vertices(4 * static_cast<size_t>(numFineFaces));
  parallelFor(0, topo.GetNumFaces(), [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f)
    {
      for (Index j = 0; j < topo.GetFaceSize(f); ++j)
      {
        // C's face h = (f, j) and its edges; its children as SplitQuads makes them.
        const Index h = topo.GetFaceOffset(f) + j;
        Index corners[4], keys[4], edges[4];
        GetQuadSplitChild(topo, point, f, j, corners);
        shape.GetChildEdgeKeys(f, j, keys);
        for (int s = 0; s < 4; ++s)
        {
          edges[s] = parentEdges.EdgeOfKey[keys[s]];
        }
        for (Index s = 0; s < 4; ++s)
        {
          const Index fine = 4 * h + s;
          offsets[fine] = 4 * fine;
          Index* out = vertices.data() + 4 * static_cast<size_t>(fine);
          out[0] = finePoint.VertexPoint(corners[s]);
          out[1] = finePoint.EdgePoint(edges[s]);
          out[2] = finePoint.FacePoint(h);
          out[3] = finePoint.EdgePoint(edges[(s + 3) % 4]);
        }
      }
    }
  });
  offsets[numFineFaces] = 4 * numFineFaces;

  Level fine;
  InheritFaceTags(grandparent, fine, [&topo](Index f) { return 4 * topo.GetFaceOffset(f); }, parallelFor);
  fine.Depth = grandparent.Depth + 2;
  fine.Creasing = grandparent.Creasing;
  const Index numChildPoints = point.VertexPoint(topo.GetNumVertices());
  fine.Topology = MeshTopology::BuildFacesOnly(finePoint.VertexPoint(numChildPoints), std::move(offsets), std::move(vertices));
  return fine;
}
}
