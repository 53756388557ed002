#include "SubDGrandchildRows.h"
#include "SubDButterflyRules.h"
#include "SubDCatmullClarkRules.h"
#include "SubDLoopRules.h"
#include "SubDRowWriting.h" // PrefetchDistance

#include <algorithm>
#include <type_traits>

namespace subd
{
namespace
{
// What the smooth rows of both schemes read of the parent C, written from the grandparent P:
// a C edge's ends and faces, a C point's edges and faces (SubDPrimalSplitShape.h).
template <typename SplitShape>
struct ParentFromGrandparent
{
  using Shape = SplitShape;
  const MeshTopology& Topology; // P's
  const ChildEdgeNumbering& ParentEdges;
  Index NumParents; // C's points
  Shape Split{ Topology };

  // The C edge first met at `corner` of P's face f's children, with key `key`: its ends in
  // the order C lists them (from that corner to the next), and its two faces in increasing
  // order. Only for edges with two faces.
  void GetEdge(Index f, Index corner, Index key, Index* ends, Index* faces) const
  {
    const MeshTopology& topo = this->Topology;
    const Index size = Shape::ChildFaceSize;
    const Index child = corner / size;
    this->GetEdgeEnds(f, corner, ends);
    if (key >= 2 * this->Split.NumEdges)
    {
      this->Split.GetInteriorEdgeFaces(f, key, faces);
      return;
    }
    // A half of e: in each face of e, the child at the half's vertex. The first face is f
    // (where the half is first met), whose child holds it.
    const Index e = key / 2;
    const Index v = topo.GetEdgeVertices(e)[key % 2];
    const Index g = topo.GetEdgeFaces(e)[1];
    const Index i = topo.GetEdgePosition(g, e);
    faces[0] = child;
    faces[1] = this->Split.CornerChild(g, topo.GetFaceVertices(g)[i] == v ? i : (i + 1 == topo.GetFaceSize(g) ? 0 : i + 1));
  }

  // The ends of the C edge first met at `corner` of P's face f's children, in the order C
  // lists them (from that corner to the next).
  void GetEdgeEnds(Index f, Index corner, Index* ends) const
  {
    const Index size = Shape::ChildFaceSize;
    const Index child = corner / size, slot = corner % size;
    Index corners[4];
    this->Split.GetChildCorners(f, child - this->Split.CornerChild(f, 0), corners);
    ends[0] = corners[slot];
    ends[1] = corners[slot + 1 == size ? 0 : slot + 1];
  }

  // The face point of C's face j of P's face f (quad split): the centroid of its corners.
  Index WriteCentroidRow(Index f, Index j, Index* sources, double* weights) const
  {
    this->Split.GetChildCorners(f, j, sources);
    std::fill(weights, weights + 4, 1.0 / 4);
    return 4;
  }

  // C's point p: its faces and edges as C lists them; `scratch` holds three lists.
  void GetPoint(Index p, Index* scratch, Index listSize, Index*& faces, Index& numFaces, Index*& edges, Index& numEdges) const
  {
    faces = scratch;
    edges = scratch + 2 * listSize;
    WriteChildPointRelations(this->Split, this->ParentEdges, p, faces, scratch + listSize, edges, numFaces, numEdges);
  }
  // C's point p: its edges only (for rules that read no faces; P's lists of faces around its
  // vertices may then be freed: Scheme::GrandchildReadsVertexFaceLists).
  void GetPointEdges(Index p, Index* scratch, Index*& edges, Index& numEdges) const
  {
    Index numFaces;
    edges = scratch;
    WriteChildPointRelations(this->Split, this->ParentEdges, p, nullptr, nullptr, edges, numFaces, numEdges);
  }
};

// Catmull-Clark's smooth rows (CatmullClarkRowWriter's, in its order and weights).
struct CatmullClarkSmoothRows : ParentFromGrandparent<QuadSplitShape>
{
  static constexpr bool HasFaceRows = true;
  Index NumChildFaces = Topology.GetNumFaceCorners(); // the finest face points come first

  Index WriteFaceRow(Index f, Index j, Index* sources, double* weights) const
  {
    return this->WriteCentroidRow(f, j, sources, weights);
  }
  Index WriteEdgeRow(Index f, Index corner, Index key, Index* sources, double* weights) const
  {
    Index ends[2], faces[2];
    this->GetEdge(f, corner, key, ends, faces);
    WritePrimalEdgeRow(ends, 0.0f, 0.25, 0.25, sources, weights, [&](Index* sides) {
      sides[0] = this->NumParents + faces[0];
      sides[1] = this->NumParents + faces[1];
    });
    return 4;
  }
  Index WriteVertexRow(Index p, Index* sources, double* weights, Index* scratch, Index listSize) const
  {
    Index *faces, *edges, numFaces, numEdges;
    this->GetPoint(p, scratch, listSize, faces, numFaces, edges, numEdges);
    return WriteCatmullClarkSmoothVertexRow(
      p, numEdges, numFaces, [&](Index i) { return this->NumParents + this->NumChildFaces + edges[i]; },
      [&](Index i) { return this->NumParents + faces[i]; }, sources, weights);
  }
};

// Loop's smooth rows (LoopRowWriter's, in its order and weights).
struct LoopSmoothRows : ParentFromGrandparent<TriangleSplitShape>
{
  static constexpr bool HasFaceRows = false;
  LoopBetas Beta;

  Index WriteFaceRow(Index, Index, Index*, double*) const { return 0; }
  Index WriteEdgeRow(Index f, Index corner, Index key, Index* sources, double* weights) const
  {
    Index ends[2], faces[2];
    this->GetEdge(f, corner, key, ends, faces);
    WritePrimalEdgeRow(ends, 0.0f, 0.375, 0.125, sources, weights, [&](Index* sides) {
      for (int k = 0; k < 2; ++k)
      {
        // The corner of the C triangle across from the edge.
        Index corners[3];
        this->Split.GetChildCorners(faces[k] / 4, faces[k] % 4, corners);
        sides[k] = *std::find_if(corners, corners + 3, [&](Index c) { return c != ends[0] && c != ends[1]; });
      }
    });
    return 4;
  }
  Index WriteVertexRow(Index p, Index* sources, double* weights, Index* scratch, Index listSize) const
  {
    Index* edges;
    Index numEdges;
    this->GetPointEdges(p, scratch, edges, numEdges);
    return WriteLoopSmoothVertexRow(
      p, numEdges, this->Beta(numEdges), [&](Index i) { return this->NumParents + edges[i]; }, sources, weights);
  }
};

// The modified butterfly's smooth rows without tension (ButterflyRowWriter's, in its order
// and weights): the 8-point butterfly of a C edge between two regular points, or Zorin's
// stencil of its end at an extraordinary vertex of P. C's triangles are P's triangles'
// children (SubDTriangleSplit.h): the triangle across an edge of a child is another child of
// the same face, or the child at the same vertex of the face across P's edge, which P's
// faces store (ButterflyGrandparentTables::FaceAcross); the rings of P's extraordinary
// vertices are stored too.
struct ButterflySmoothRows : ParentFromGrandparent<TriangleSplitShape>
{
  static constexpr bool HasFaceRows = false;
  const ButterflyGrandparentTables* Tables = nullptr;

  // Child j of P's face g (j = 3: the middle one) and its corners, C's points.
  struct ChildTriangle
  {
    Index Face, Child;
    Index Corners[3];
  };

  Index WriteFaceRow(Index, Index, Index*, double*) const { return 0; }
  Index WriteEdgeRow(Index f, Index corner, Index, Index* sources, double* weights) const
  {
    const MeshTopology& topo = this->Topology;
    ButterflyRowWriter::Row row{ sources, weights };
    // The edge leaves corner s of f's child j (SubDPrimalSplitShape.h, VisitCorners).
    const Index j = (corner / 3) % 4, s = corner % 3;
    if (j < 3 && s != 1)
    {
      // A half of P's edge e at f's corner v: Zorin's stencil when v is extraordinary.
      const Index v = topo.GetTriangleVertices(f)[j];
      const Index first = this->Tables->RingOffsets[v], K = this->Tables->RingOffsets[v + 1] - first;
      if (K > 0)
      {
        const Index e = topo.GetTriangleEdges(f)[s == 0 ? j : Previous(j)];
        const Index* ring = this->Tables->RingEdges.data() + first; // an edge's point is numbered as the edge
        PutButterflyExtraordinaryStencil(
          TriangleSplitNumbering{ this->Split.NumEdges }.VertexPoint(v), K,
          static_cast<Index>(std::find(ring, ring + K, e) - ring), this->Tables->Weights.Get(K),
          [ring](Index k) { return ring[k]; }, [&row](Index source, double weight) { row.Append(source, weight); });
        return row.Size;
      }
    }
    // The butterfly: the edge's ends a0, a1 (C lists them from the triangle it is first met
    // in, the lower-numbered of its two), the third corners b0, b1 of its triangles and the
    // corners across those triangles' other edges.
    ChildTriangle t0;
    this->GetChild(f, j, t0);
    Index s1;
    ChildTriangle t1;
    this->GetTriangleAcross(t0, s, t1, s1); // the edge leaves its corner s1 the other way
    const Index points[8] = { t0.Corners[s], t0.Corners[Next(s)], t0.Corners[Previous(s)],
      t1.Corners[Previous(s1)], this->GetCornerAcross(t0, Previous(s)), this->GetCornerAcross(t0, Next(s)),
      this->GetCornerAcross(t1, Next(s1)), this->GetCornerAcross(t1, Previous(s1)) };
    constexpr double pointWeights[8] = { 0.5, 0.5, 0.125, 0.125, -0.0625, -0.0625, -0.0625, -0.0625 };
    bool repeated = false;
    for (int i = 1; i < 8; ++i)
    {
      for (int k = 0; k < i; ++k)
      {
        repeated |= points[i] == points[k];
      }
    }
    for (int i = 0; i < 8; ++i)
    {
      // Added as WriteRow adds them: a point met twice (tiny closed meshes) merged.
      repeated ? row.Add(points[i], pointWeights[i]) : row.Append(points[i], pointWeights[i]);
    }
    return row.Size;
  }
  Index WriteVertexRow(Index p, Index* sources, double* weights, Index*, Index) const
  {
    sources[0] = p;
    weights[0] = 1.0;
    return 1;
  }

  static Index Next(Index i) { return i == 2 ? 0 : i + 1; }
  static Index Previous(Index i) { return i == 0 ? 2 : i - 1; }
  void GetChild(Index g, Index j, ChildTriangle& t) const
  {
    t.Face = g;
    t.Child = j;
    this->Split.GetChildCorners(g, j, t.Corners);
  }
  // The triangle across the edge leaving corner s of t, and the corner that edge leaves in
  // it. A corner child's corners are (v_j, m_j, m_{j-1}), m_i the point of edge i (from v_i
  // to v_{i+1}), the middle child's (m_0, m_1, m_2).
  void GetTriangleAcross(const ChildTriangle& t, Index s, ChildTriangle& across, Index& slot) const
  {
    const Index g = t.Face, j = t.Child;
    if (j == 3) // (m_s, m_{s+1}): in the corner child at v_{s+1}, from its corner 1
    {
      this->GetChild(g, Next(s), across);
      slot = 1;
      return;
    }
    if (s == 1) // (m_j, m_{j-1}): in the middle child, from its corner j - 1
    {
      this->GetChild(g, 3, across);
      slot = Previous(j);
      return;
    }
    // A half of edge j (s = 0) or j - 1 (s = 2) at v_j: in the child at v_j of the face h
    // across, where the edge is h's edge p, run the other way: v_j is h's corner p + 1
    // (s = 0), or p (s = 2).
    const Index packed = (*this->Tables->FaceAcross)[MeshTopology::GetFirstTriangleCorner(g) + (s == 0 ? j : Previous(j))];
    const Index h = packed / 4, p = packed % 4;
    this->GetChild(h, s == 0 ? Next(p) : p, across);
    slot = s == 0 ? 2 : 0;
  }
  // The corner of the triangle across the edge leaving corner s of t that is not on that
  // edge (GetTriangleAcross's, without its other corners).
  Index GetCornerAcross(const ChildTriangle& t, Index s) const
  {
    const MeshTopology& topo = this->Topology;
    const Index g = t.Face, j = t.Child;
    if (j == 3)
    {
      return TriangleSplitNumbering{ this->Split.NumEdges }.VertexPoint(topo.GetTriangleVertices(g)[Next(s)]);
    }
    if (s == 1)
    {
      return topo.GetTriangleEdges(g)[Next(j)]; // m_{j+1}
    }
    const Index packed = (*this->Tables->FaceAcross)[MeshTopology::GetFirstTriangleCorner(g) + (s == 0 ? j : Previous(j))];
    const Index* he = topo.GetTriangleEdges(packed / 4);
    const Index p = packed % 4;
    return he[s == 0 ? Next(p) : Previous(p)]; // h's other edge at v_j
  }
};

// The rings of P's extraordinary interior vertices and the faces across its triangles'
// edges (see ButterflyGrandparentTables).
ButterflyGrandparentTables MakeButterflyGrandparentTables(
  const MeshTopology& topo, const ParallelFor& parallelFor, const RowSource* grandparentRows)
{
  ButterflyGrandparentTables tables;
  const Index numVertices = topo.GetNumVertices();
  tables.RingOffsets.resize(static_cast<size_t>(numVertices) + 1);
  tables.RingOffsets[0] = 0;
  parallelFor(0, numVertices, [&](Index begin, Index end) {
    for (Index v = begin; v < end; ++v)
    {
      const VertexTag tag = topo.GetVertexTag(v);
      const Index K = topo.GetVertexFaces(v).size();
      const bool closedFan = !tag.Boundary && !tag.NonManifold && K == topo.GetVertexEdges(v).size();
      tables.RingOffsets[v + 1] = closedFan && K != 6 ? K : 0;
    }
  });
  std::partial_sum(tables.RingOffsets.begin(), tables.RingOffsets.end(), tables.RingOffsets.begin());
  tables.RingEdges.resize(static_cast<size_t>(tables.RingOffsets.back()));
  parallelFor(0, numVertices, [&](Index begin, Index end) {
    for (Index v = begin; v < end; ++v)
    {
      Index* ring = tables.RingEdges.data() + tables.RingOffsets[v];
      const Index K = tables.RingOffsets[v + 1] - tables.RingOffsets[v];
      if (K == 0)
      {
        continue;
      }
      // In C, v's ring is the vertex after v in each of its triangles: the point of the edge
      // leaving v in the face of P that triangle is the child of, face after face around v
      // (each next one across the edge entering v in the one before, as
      // MeshTopology::GetOrderedVertexFaces orders them). Walked through edges' faces: the
      // lists of faces around vertices may be released by now
      // (Scheme::GrandchildReadsVertexFaceLists).
      const Index start = topo.GetVertexEdges(v)[0];
      const IndexSpan startFaces = topo.GetEdgeFaces(start);
      bool closed = startFaces.size() == 2;
      Index e = start;
      Index g = closed && topo.GetTriangleVertices(startFaces[0])[topo.GetEdgePosition(startFaces[0], e)] != v
        ? startFaces[1]
        : startFaces[0];
      for (Index k = 0; k < K && closed; ++k)
      {
        ring[k] = e;
        const Index p = topo.GetEdgePosition(g, e); // e leaves v at g's corner p
        e = topo.GetTriangleEdges(g)[p == 0 ? 2 : p - 1];
        const IndexSpan ef = topo.GetEdgeFaces(e);
        closed = ef.size() == 2;
        g = closed ? OtherOfTwo(ef, g) : g;
      }
      if (!closed || e != start) // not expected of a closed manifold fan
      {
        std::fill(ring, ring + K, 0);
      }
    }
  });
  // P's own rows, when they are the butterfly's, have the triangles across P's edges.
  const auto* writtenRows = dynamic_cast<const WrittenRows<ButterflyRowWriter>*>(grandparentRows);
  tables.FaceAcross = writtenRows && &writtenRows->GetParent().Topology == &topo
    ? writtenRows->GetWriter().GetFaceAcross()
    : MakeTriangleFaceAcross(topo, parallelFor);
  return tables;
}

// The linear rules (LinearRowWriter's, in its order and weights): centroids (bilinear),
// midpoints and copies, each row from the grandparent alone.
template <typename SplitShape>
struct LinearRows : ParentFromGrandparent<SplitShape>
{
  static constexpr bool HasFaceRows = SplitShape::ChildFaceSize == 4;

  Index WriteFaceRow(Index f, Index j, Index* sources, double* weights) const
  {
    return this->WriteCentroidRow(f, j, sources, weights);
  }
  Index WriteEdgeRow(Index f, Index corner, Index, Index* sources, double* weights) const
  {
    this->GetEdgeEnds(f, corner, sources);
    weights[0] = weights[1] = 0.5;
    return 2;
  }
  Index WriteVertexRow(Index p, Index* sources, double* weights, Index*, Index) const
  {
    sources[0] = p;
    weights[0] = 1.0;
    return 1;
  }
};

// C's faces c in [begin, end) on the quad split, c being child j of P's face f:
// visit(c, f, j).
template <typename Visit>
void ForEachQuadSplitChild(const IndexArray& faceOffsets, Index begin, Index end, Visit&& visit)
{
  if (begin >= end)
  {
    return;
  }
  Index f = static_cast<Index>(std::upper_bound(faceOffsets.begin(), faceOffsets.end(), begin) - faceOffsets.begin()) - 1;
  for (Index c = begin; c < end; ++c)
  {
    while (faceOffsets[f + 1] <= c)
    {
      ++f;
    }
    visit(c, f, c - faceOffsets[f]);
  }
}

// C's edges k in [begin, end), numbered as the walk over P's faces' children first meets
// them: visit(k, f, corner, key) for the edge first met at `corner` of P's face f's children,
// with key `key`; startFace(f) before each face of P the walk reads.
template <typename Shape, typename StartFace, typename Visit>
void ForEachChildEdge(const Shape& split, const IndexArray& firstEdge, Index begin, Index end, StartFace&& startFace,
  Visit&& visit)
{
  if (begin >= end)
  {
    return;
  }
  Index f = static_cast<Index>(std::upper_bound(firstEdge.begin(), firstEdge.end(), begin) - firstEdge.begin()) - 1;
  for (; f < split.Parent.GetNumFaces() && firstEdge[f] < end; ++f)
  {
    startFace(f);
    Index next = firstEdge[f];
    split.VisitCorners(f, [&](Index corner, Index key, bool isNew) {
      if (!isNew)
      {
        return;
      }
      const Index k = next++;
      if (k >= begin && k < end)
      {
        visit(k, f, corner, key);
      }
    });
  }
}

// The rows `writer` (over the parent C) has no smooth form for, from row `first` on.
template <typename Writer>
void StoreRowsWithoutSmoothForm(const Writer& writer, Index first, std::vector<Index>& rows, StencilTable& table)
{
  for (Index row = first; row < writer.GetNumRows(); ++row)
  {
    if (!writer.IsSmoothRow(row))
    {
      rows.push_back(row);
    }
  }
  table = StencilTable(writer.GetNumParents());
  std::vector<Index> sources(static_cast<size_t>(writer.GetMaxRowSize()));
  std::vector<double> weights(sources.size());
  for (Index row : rows)
  {
    const Index size = writer.WriteRow(row, sources.data(), weights.data());
    table.AppendRow(sources.data(), weights.data(), size);
  }
}
}

GrandchildRows::GrandchildRows(GrandchildScheme scheme, std::shared_ptr<const Level> grandparent,
  const ParallelFor& parallelFor, const RowSource* grandparentRows)
  : Scheme(scheme)
  , Grandparent(std::move(grandparent))
{
  // C's counts, from P: C's faces are the children of P's corners (quads) or four per
  // triangle; its points stand for P's faces (quads), edges and vertices.
  const MeshTopology& topo = this->Grandparent->Topology;
  const bool quads = IsQuadSplit(scheme);
  // The triangle split's edges inside faces are numbered in closed form (kept with the
  // rows: 3 indices per triangle of P less).
  this->ParentEdges = quads ? NumberChildEdges(QuadSplitShape{ topo }, parallelFor)
                            : NumberChildEdges(TriangleSplitShape{ topo }, parallelFor, false);
  this->NumFaceRows = quads ? topo.GetNumFaceCorners() : 0;
  this->NumParents = (quads ? topo.GetNumFaces() : 0) + topo.GetNumEdges() + topo.GetNumVertices();
  this->NumRows = this->NumFaceRows + this->ParentEdges.FirstEdgeOfFace.back() + this->NumParents;
  if (!WritesEveryRowFromGrandparent(scheme))
  {
    // Every row smooth (EveryGrandchildRowIsSmooth): the longest is a vertex row of the point
    // of C with the most faces and edges, as many as the vertex, face or edge of P it stands
    // for has. The same size as C's own writer finds (two-argument constructor, below).
    Index mostFaces = std::max<Index>(topo.GetMaxValence(), quads ? 4 : 6);
    for (Index f = 0; quads && f < topo.GetNumFaces(); ++f)
    {
      mostFaces = std::max(mostFaces, topo.GetFaceSize(f));
    }
    this->MaxRowSize = std::max<Index>(4, 1 + (quads ? 2 * mostFaces : mostFaces));
  }
  if (scheme == GrandchildScheme::Butterfly)
  {
    this->ButterflyTables = MakeButterflyGrandparentTables(topo, parallelFor, grandparentRows);
    this->MaxRowSize = std::max<Index>(8, 1 + topo.GetMaxValence()); // the butterfly, or Zorin's stencil
  }
}

bool EveryGrandchildRowIsSmooth(GrandchildScheme scheme, const Level& grandparent)
{
  if (WritesEveryRowFromGrandparent(scheme))
  {
    return true;
  }
  const MeshTopology& topo = grandparent.Topology;
  const bool butterfly = scheme == GrandchildScheme::Butterfly;
  for (Index e = 0; e < topo.GetNumEdges(); ++e)
  {
    if (!IsSmoothEdge(grandparent, e) || (butterfly && topo.GetEdgeTag(e).NonManifold))
    {
      return false;
    }
  }
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    const Index numEdges = topo.GetVertexEdges(v).size();
    // A sharp vertex changes Catmull-Clark's and Loop's vertex rows; a non-manifold one has
    // no ring for the butterfly.
    const bool ruledOut = butterfly ? topo.GetVertexTag(v).NonManifold : IsSharp(grandparent.VertexSharpness[v]);
    if (numEdges == 0 || topo.GetVertexFaces(v).size() != numEdges || ruledOut)
    {
      return false;
    }
  }
  return true;
}

GrandchildRows::GrandchildRows(GrandchildScheme scheme, std::shared_ptr<const Level> grandparent,
  const Level& parent, const ParallelFor& parallelFor, const RowSource* grandparentRows)
  : GrandchildRows(scheme, std::move(grandparent), parallelFor, grandparentRows)
{
  // The rows without a smooth form (creases, boundaries, corners, non-manifold points), from
  // the parent's own writer, in row order.
  if (scheme == GrandchildScheme::CatmullClark)
  {
    const CatmullClarkRowWriter writer(parent, parallelFor);
    this->MaxRowSize = writer.GetMaxRowSize();
    StoreRowsWithoutSmoothForm(writer, this->NumFaceRows, this->StoredRows, this->StoredTable);
  }
  else if (scheme == GrandchildScheme::Loop)
  {
    const LoopRowWriter writer(parent, parallelFor);
    this->MaxRowSize = writer.GetMaxRowSize();
    StoreRowsWithoutSmoothForm(writer, 0, this->StoredRows, this->StoredTable);
  }
  else if (scheme == GrandchildScheme::Butterfly)
  {
    const ButterflyRowWriter writer(parent, 0.0, parallelFor);
    this->MaxRowSize = writer.GetMaxRowSize();
    StoreRowsWithoutSmoothForm(writer, 0, this->StoredRows, this->StoredTable);
  }
}

std::vector<Index> GrandchildRows::GetBlockEnds() const
{
  if (ReadsParentPointsOnly(this->Scheme))
  {
    return { this->NumRows }; // no row reads another
  }
  const Index vertexRows = this->NumFaceRows + this->ParentEdges.FirstEdgeOfFace.back();
  if (this->NumFaceRows > 0)
  {
    return { this->NumFaceRows, vertexRows, this->NumRows };
  }
  return { vertexRows, this->NumRows };
}

// Calls emit(row, sources, weights, size) for rows [begin, end) in increasing order: a stored
// row as stored, any other written from the grandparent into `buffers` (sources, then room
// for a point's lists) and `weights`.
template <typename Emit>
void GrandchildRows::WriteRows(Index begin, Index end, Index* buffers, double* weights, Emit&& emit) const
{
  switch (this->Scheme)
  {
    case GrandchildScheme::CatmullClark:
      this->WriteRowsWith<CatmullClarkSmoothRows>(begin, end, buffers, weights, emit);
      break;
    case GrandchildScheme::Loop:
      this->WriteRowsWith<LoopSmoothRows>(begin, end, buffers, weights, emit);
      break;
    case GrandchildScheme::Butterfly:
      this->WriteRowsWith<ButterflySmoothRows>(begin, end, buffers, weights, emit);
      break;
    case GrandchildScheme::Bilinear:
      this->WriteRowsWith<LinearRows<QuadSplitShape>>(begin, end, buffers, weights, emit);
      break;
    case GrandchildScheme::LinearTriangles:
      this->WriteRowsWith<LinearRows<TriangleSplitShape>>(begin, end, buffers, weights, emit);
      break;
  }
}

template <typename Rules, typename Emit>
void GrandchildRows::WriteRowsWith(Index begin, Index end, Index* buffers, double* weights, Emit&& emit) const
{
  const MeshTopology& topo = this->Grandparent->Topology;
  Rules rules{ { topo, this->ParentEdges, this->NumParents } };
  if constexpr (std::is_same_v<Rules, ButterflySmoothRows>)
  {
    rules.Tables = &this->ButterflyTables;
  }
  Index* sources = buffers;
  Index* scratch = buffers + this->MaxRowSize;
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

  // Face points (Catmull-Clark): C's faces, the children of P's faces corner by corner.
  if constexpr (Rules::HasFaceRows)
  {
    ForEachQuadSplitChild(topo.GetFaceOffsetArray(), begin, std::min(end, this->NumFaceRows),
      [&](Index c, Index f, Index j) { put(c, [&] { return rules.WriteFaceRow(f, j, sources, weights); }); });
  }

  // Edge points: C's edges, numbered as the walk over P's faces' children first meets them.
  const Index firstEdgeRow = this->NumFaceRows;
  const Index numChildEdges = this->ParentEdges.FirstEdgeOfFace.back();
  ForEachChildEdge(rules.Split, this->ParentEdges.FirstEdgeOfFace, std::max(begin, firstEdgeRow) - firstEdgeRow,
    std::min(end, firstEdgeRow + numChildEdges) - firstEdgeRow, [](Index) {},
    [&](Index k, Index f, Index corner, Index key) {
      put(firstEdgeRow + k, [&] { return rules.WriteEdgeRow(f, corner, key, sources, weights); });
    });

  // Vertex points: C's points.
  const Index firstVertexRow = firstEdgeRow + numChildEdges;
  for (Index row = std::max(begin, firstVertexRow); row < end; ++row)
  {
    put(row, [&] { return rules.WriteVertexRow(row - firstVertexRow, sources, weights, scratch, this->MaxRowSize); });
  }
}

namespace
{
// Points' rows applied a few rows after they are written, each row's points asked for
// (PrefetchPoint) when it is written: the rows written meanwhile, whose neighbourhoods are
// worked out from the grandparent, hide the time those points take to arrive (Catmull-Clark
// armadillo L3 re-applied with LowMemory, one thread: 0.25 s against 0.32 s; Loop bunny L3,
// two threads: 0.17 against 0.19 s). A waiting row is a copy (a few entries, in L1). Rows
// of one block never read each other's points, so the delay is safe within a block; Drain
// applies what is left at a block's end.
template <typename T>
class DelayedPointRows
{
public:
  /// How many rows a row waits: as far as rows written from the parent look ahead
  /// (PrefetchDistance; 16 measured a few per cent slower here).
  static constexpr Index Depth = PrefetchDistance;

  DelayedPointRows(Index maxRowSize, Index numParents, const T* parents, T* children)
    : MaxRowSize(maxRowSize)
    , NumParents(numParents)
    , Parents(parents)
    , Children(children)
    , Sources(static_cast<size_t>(Depth * maxRowSize))
    , Weights(Sources.size())
  {
  }

  void Add(Index row, const Index* sources, const double* weights, Index size)
  {
    for (Index k = 0; k < size; ++k)
    {
      PrefetchPoint(this->ValuesOf(sources[k]));
    }
    if (this->Count == Depth)
    {
      this->ApplyOldest();
    }
    const Index slot = (this->First + this->Count) % Depth;
    Index* rowSources = this->Sources.data() + slot * this->MaxRowSize;
    double* rowWeights = this->Weights.data() + slot * this->MaxRowSize;
    for (Index k = 0; k < size; ++k) // a few entries: a loop, not a call to memmove
    {
      rowSources[k] = sources[k];
      rowWeights[k] = weights[k];
    }
    this->Rows[slot] = row;
    this->Sizes[slot] = size;
    ++this->Count;
  }

  void Drain()
  {
    while (this->Count > 0)
    {
      this->ApplyOldest();
    }
  }

private:
  const T* ValuesOf(Index source) const
  {
    return source < this->NumParents ? this->Parents + 3 * static_cast<size_t>(source)
                                     : this->Children + 3 * static_cast<size_t>(source - this->NumParents);
  }
  void ApplyOldest()
  {
    const Index slot = this->First;
    ApplyRow(this->Sources.data() + slot * this->MaxRowSize, this->Weights.data() + slot * this->MaxRowSize,
      this->Sizes[slot], this->NumParents, this->Parents, this->Children, 3, nullptr,
      this->Children + 3 * static_cast<size_t>(this->Rows[slot]));
    this->First = (this->First + 1) % Depth;
    --this->Count;
  }

  const Index MaxRowSize, NumParents;
  const T* Parents;
  T* Children;
  std::vector<Index> Sources;
  std::vector<double> Weights;
  Index Rows[Depth], Sizes[Depth];
  Index First = 0, Count = 0;
};
}

namespace
{
// Weighted sums of the level between's points (sources below NumParents), as ApplyRow sums
// them: each component from 0 over the sources in order, so the bits are ApplyRow's.
template <typename T>
struct ParentSums
{
  const T* Parents;
  T* Children;
  int Components;

  void Average(Index row, const Index* sources, Index size, double weight) const
  {
    T* dst = this->Children + static_cast<size_t>(row) * this->Components;
    if (this->Components == 3)
    {
      PointSum point;
      for (Index k = 0; k < size; ++k)
      {
        point.Add(weight, this->Parents + 3 * static_cast<size_t>(sources[k]));
      }
      point.Store(dst);
      return;
    }
    for (int c = 0; c < this->Components; ++c)
    {
      double sum = 0.0;
      for (Index k = 0; k < size; ++k)
      {
        sum += weight * static_cast<double>(this->Parents[static_cast<size_t>(sources[k]) * this->Components + c]);
      }
      dst[c] = static_cast<T>(sum);
    }
  }
};

// The linear rules' rows [begin, end) summed where WriteRowsWith would write them
// (LinearRows: centroids, midpoints and copies, whose writing costs more than their sums):
// a child's corners are worked out once for all the edges first met in it, not once per
// edge, and the vertex rows, C's points in order, are one sweep. Each row is summed as
// ApplyRow sums LinearRows' row, so the values are the same bits.
template <typename Shape, typename T>
void ApplyLinearRows(const MeshTopology& topo, const ChildEdgeNumbering& parentEdges, Index numFaceRows,
  const ParentSums<T>& sums, Index begin, Index end)
{
  const Shape split{ topo };
  constexpr Index size = Shape::ChildFaceSize;
  Index corners[4];
  if constexpr (size == 4) // face points (bilinear): the centroids of C's faces
  {
    ForEachQuadSplitChild(topo.GetFaceOffsetArray(), begin, std::min(end, numFaceRows), [&](Index c, Index f, Index j) {
      split.GetChildCorners(f, j, corners);
      sums.Average(c, corners, 4, 1.0 / 4);
    });
  }

  // Edge points: the midpoints of C's edges, in the order the walk over P's faces' children
  // first meets them.
  const Index numChildEdges = parentEdges.FirstEdgeOfFace.back();
  Index cornersOf = InvalidIndex; // the child whose corners `corners` holds
  auto askForLaterPoints = [&](Index f) {
    // The sums wait on their points (C's points of a face are scattered): ask for a later
    // face's ahead of summing them. The children at a face's corners hold all its points.
    constexpr Index ahead = 8;
    if (f + ahead < topo.GetNumFaces())
    {
      Index later[4];
      for (Index c = 0; c < topo.GetFaceSize(f + ahead); ++c)
      {
        split.GetChildCorners(f + ahead, c, later);
        for (Index k = 0; k < size; ++k)
        {
          PrefetchPoint(sums.Parents + static_cast<size_t>(later[k]) * sums.Components);
        }
      }
    }
  };
  ForEachChildEdge(split, parentEdges.FirstEdgeOfFace, std::max(begin, numFaceRows) - numFaceRows,
    std::min(end, numFaceRows + numChildEdges) - numFaceRows, askForLaterPoints,
    [&](Index k, Index f, Index corner, Index) {
      const Index child = corner / size, slot = corner % size;
      if (child != cornersOf)
      {
        split.GetChildCorners(f, child - split.CornerChild(f, 0), corners);
        cornersOf = child;
      }
      const Index ends[2] = { corners[slot], corners[slot + 1 == size ? 0 : slot + 1] };
      sums.Average(numFaceRows + k, ends, 2, 0.5);
    });

  // Vertex points: C's points, each summed as a row of one entry of weight 1 (0 + x: a
  // negative zero comes out positive, as from ApplyRow).
  const Index firstVertexRow = numFaceRows + numChildEdges;
  const Index rowsBegin = std::max(begin, firstVertexRow);
  if (rowsBegin < end)
  {
    const size_t components = static_cast<size_t>(sums.Components);
    const T* src = sums.Parents + static_cast<size_t>(rowsBegin - firstVertexRow) * components;
    T* dst = sums.Children + static_cast<size_t>(rowsBegin) * components;
    const size_t count = static_cast<size_t>(end - rowsBegin) * components;
    for (size_t i = 0; i < count; ++i)
    {
      dst[i] = static_cast<T>(0.0 + static_cast<double>(src[i]));
    }
  }
}
}

template <typename T>
void GrandchildRows::Apply(const T* parents, T* children, int components, Index begin, Index end) const
{
  if (WritesEveryRowFromGrandparent(this->Scheme))
  {
    const MeshTopology& topo = this->Grandparent->Topology;
    const ParentSums<T> sums{ parents, children, components };
    if (IsQuadSplit(this->Scheme))
    {
      ApplyLinearRows<QuadSplitShape>(topo, this->ParentEdges, this->NumFaceRows, sums, begin, end);
    }
    else
    {
      ApplyLinearRows<TriangleSplitShape>(topo, this->ParentEdges, this->NumFaceRows, sums, begin, end);
    }
    return;
  }
  std::vector<Index> buffers(4 * static_cast<size_t>(this->MaxRowSize)); // sources, a point's lists
  std::vector<double> weights(static_cast<size_t>(this->MaxRowSize));
  // Other values than points are applied as written.
  if (components != 3)
  {
    std::vector<double> sum(static_cast<size_t>(components));
    this->WriteRows(begin, end, buffers.data(), weights.data(),
      [&](Index row, const Index* rowSources, const double* rowWeights, Index size) {
        ApplyRow(rowSources, rowWeights, size, this->NumParents, parents, children, components, sum.data(),
          children + static_cast<size_t>(row) * components);
      });
    return;
  }
  DelayedPointRows<T> delayed(this->MaxRowSize, this->NumParents, parents, children);
  for (Index blockEnd : this->GetBlockEnds())
  {
    const Index last = std::min(end, blockEnd);
    if (begin < last)
    {
      this->WriteRows(begin, last, buffers.data(), weights.data(),
        [&](Index row, const Index* rowSources, const double* rowWeights, Index size) {
          delayed.Add(row, rowSources, rowWeights, size);
        });
      delayed.Drain();
      begin = last;
    }
  }
}

void GrandchildRows::ApplyRows(const double* parents, double* children, int components, Index begin, Index end) const
{
  this->Apply(parents, children, components, begin, end);
}

void GrandchildRows::ApplyRows(const float* parents, float* children, int components, Index begin, Index end) const
{
  this->Apply(parents, children, components, begin, end);
}

StencilTable GrandchildRows::ToStencilTable() const
{
  StencilTable table(this->NumParents);
  std::vector<Index> buffers(4 * static_cast<size_t>(this->MaxRowSize));
  std::vector<double> weights(static_cast<size_t>(this->MaxRowSize));
  this->WriteRows(0, this->NumRows, buffers.data(), weights.data(),
    [&](Index, const Index* rowSources, const double* rowWeights, Index size) {
      table.AppendRow(rowSources, rowWeights, size);
    });
  for (Index end : this->GetBlockEnds())
  {
    table.EndBlock(end);
  }
  return table;
}

namespace
{
// The faces of the split of every C face, from the C face's corners and edges (as
// SplitQuads and SplitTriangles make them from C's topology).
template <typename Shape>
MeshTopology SplitTwiceFacesWith(const Shape& shape, const MeshTopology& topo, const ChildEdgeNumbering& parentEdges,
  const ParallelFor& parallelFor)
{
  constexpr bool quads = Shape::ChildFaceSize == 4;
  constexpr Index size = Shape::ChildFaceSize;
  const Index numChildFaces = shape.CornerChild(topo.GetNumFaces(), 0);
  const Index numChildEdges = parentEdges.FirstEdgeOfFace.back();
  const Index numChildPoints = shape.GetNumFacePoints() + topo.GetNumEdges() + topo.GetNumVertices();
  const QuadSplitNumbering quadPoint{ numChildFaces, numChildEdges };
  const TriangleSplitNumbering trianglePoint{ numChildEdges };
  const Index numFineFaces = 4 * numChildFaces;
  IndexArray offsets(static_cast<size_t>(numFineFaces) + 1);
  IndexArray vertices(size * static_cast<size_t>(numFineFaces));
  parallelFor(0, topo.GetNumFaces(), [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f)
    {
      // A face's edges are read out of order (their ends, their halves' numbers): asked for
      // a few faces ahead.
      constexpr Index ahead = 8;
      if (f + ahead < end)
      {
        for (Index e : topo.GetFaceEdges(f + ahead))
        {
          PrefetchForRead(topo.GetEdgeVertices(e));
          PrefetchForRead(parentEdges.EdgeOfKey.data() + 2 * static_cast<size_t>(e));
        }
      }
      for (Index j = 0; j < shape.GetNumChildren(f); ++j)
      {
        const Index c = shape.CornerChild(f, j);
        Index corners[4], keys[4], edges[4];
        shape.GetChildCorners(f, j, corners);
        shape.GetChildEdgeKeys(f, j, keys);
        for (Index s = 0; s < size; ++s)
        {
          edges[s] = parentEdges.GetEdge(keys[s]);
        }
        for (Index s = 0; s < 4; ++s)
        {
          const Index fine = 4 * c + s;
          offsets[fine] = size * fine;
          Index* out = vertices.data() + size * static_cast<size_t>(fine);
          const Index previous = s == 0 ? size - 1 : s - 1;
          if (quads)
          {
            out[0] = quadPoint.VertexPoint(corners[s]);
            out[1] = quadPoint.EdgePoint(edges[s]);
            out[2] = quadPoint.FacePoint(c);
            out[3] = quadPoint.EdgePoint(edges[previous]);
          }
          else if (s < 3)
          {
            out[0] = trianglePoint.VertexPoint(corners[s]);
            out[1] = trianglePoint.EdgePoint(edges[s]);
            out[2] = trianglePoint.EdgePoint(edges[previous]);
          }
          else
          {
            out[0] = trianglePoint.EdgePoint(edges[0]);
            out[1] = trianglePoint.EdgePoint(edges[1]);
            out[2] = trianglePoint.EdgePoint(edges[2]);
          }
        }
      }
    }
  });
  offsets[numFineFaces] = size * numFineFaces;
  const Index numFinePoints = quads ? quadPoint.VertexPoint(numChildPoints) : trianglePoint.VertexPoint(numChildPoints);
  return MeshTopology::BuildFacesOnly(numFinePoints, std::move(offsets), std::move(vertices));
}

template <typename Shape>
Level SplitTwiceTagsWith(const Shape& shape, const Level& grandparent, const ParallelFor& parallelFor)
{
  // The tags stay with the faces of the level between (four finest faces each) or, where
  // every face of the grandparent has four children (quads split into quads, triangles into
  // triangles), with the grandparent's own faces (sixteen each): a copy of its tags, a
  // sixteenth of the finest level's faces.
  Level fine;
  bool fourChildren = grandparent.FaceTagShift == 0;
  for (Index f = 0; f <= grandparent.Topology.GetNumFaces() && fourChildren; ++f) // the last face's end too
  {
    fourChildren = shape.CornerChild(f, 0) == 4 * f;
  }
  if (!ShareOrInheritFaceTags(grandparent, fine, fourChildren, 4, [&shape](Index f) { return shape.CornerChild(f, 0); },
        parallelFor))
  {
    fine.FaceTagShift = 2; // a tag per face of the level between
  }
  fine.Depth = grandparent.Depth + 2;
  fine.Creasing = grandparent.Creasing;
  return fine;
}
}

Level SplitTwiceTags(GrandchildScheme scheme, const Level& grandparent, const ParallelFor& parallelFor)
{
  if (IsQuadSplit(scheme))
  {
    return SplitTwiceTagsWith(QuadSplitShape{ grandparent.Topology }, grandparent, parallelFor);
  }
  return SplitTwiceTagsWith(TriangleSplitShape{ grandparent.Topology }, grandparent, parallelFor);
}

MeshTopology SplitTwiceFaces(GrandchildScheme scheme, const MeshTopology& grandparent,
  const ChildEdgeNumbering& parentEdges, const ParallelFor& parallelFor)
{
  if (IsQuadSplit(scheme))
  {
    return SplitTwiceFacesWith(QuadSplitShape{ grandparent }, grandparent, parentEdges, parallelFor);
  }
  return SplitTwiceFacesWith(TriangleSplitShape{ grandparent }, grandparent, parentEdges, parallelFor);
}

Index CountSplitTwiceFaces(GrandchildScheme scheme, const MeshTopology& grandparent)
{
  const Index numChildFaces = IsQuadSplit(scheme)
    ? QuadSplitShape{ grandparent }.CornerChild(grandparent.GetNumFaces(), 0)
    : TriangleSplitShape{ grandparent }.CornerChild(grandparent.GetNumFaces(), 0);
  return 4 * numChildFaces;
}

Level SplitTwice(GrandchildScheme scheme, const Level& grandparent, const ChildEdgeNumbering& parentEdges,
  const ParallelFor& parallelFor)
{
  Level fine = SplitTwiceTags(scheme, grandparent, parallelFor);
  fine.Topology = SplitTwiceFaces(scheme, grandparent.Topology, parentEdges, parallelFor);
  return fine;
}
}
