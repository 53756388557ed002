#include "SubDButterflyRules.h"
#include "SubDRowWriting.h"
#include "SubDTriangleSplit.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace subd
{
double ButterflyExtraordinaryWeight(Index K, Index j)
{
  j %= K;
  if (K == 3)
  {
    return j == 0 ? 5.0 / 12.0 : -1.0 / 12.0;
  }
  if (K == 4)
  {
    return j == 0 ? 3.0 / 8.0 : (j == 2 ? -1.0 / 8.0 : 0.0);
  }
  const double pi = 3.14159265358979323846;
  return (0.25 + std::cos(2.0 * pi * j / K) + 0.5 * std::cos(4.0 * pi * j / K)) / K;
}

ButterflyWeightTable::ButterflyWeightTable()
  : Weights(32)
{
  for (Index K = 3; K < static_cast<Index>(this->Weights.size()); ++K)
  {
    for (Index j = 0; j < K; ++j)
    {
      this->Weights[K].push_back(ButterflyExtraordinaryWeight(K, j));
    }
  }
}

std::shared_ptr<const IndexArray> MakeTriangleFaceAcross(const MeshTopology& topo, const ParallelFor& parallelFor)
{
  // Filled edge by edge: an edge's first face is mostly the face that numbered it, so only
  // the second face is a scattered read. Each triangle corner's edge is one edge's: every
  // entry is written here, none twice, on threads.
  auto faceAcross = std::make_shared<IndexArray>(topo.GetFaceVertexArray().size());
  Index* across = faceAcross->data();
  parallelFor(0, topo.GetNumEdges(), [&](Index begin, Index end) {
    for (Index e = begin; e < end; ++e)
    {
      const IndexSpan ef = topo.GetEdgeFaces(e);
      if (ef.size() != 2 || ef[0] == ef[1])
      {
        for (Index f : ef) // nothing across a boundary or non-manifold edge
        {
          const Index* fe = topo.GetTriangleEdges(f);
          for (Index i = 0; i < 3; ++i)
          {
            if (fe[i] == e)
            {
              across[MeshTopology::GetFirstTriangleCorner(f) + i] = InvalidIndex;
            }
          }
        }
        continue;
      }
      const Index position[2] = { PlaceInTriangle(topo.GetTriangleEdges(ef[0]), e),
        PlaceInTriangle(topo.GetTriangleEdges(ef[1]), e) };
      across[MeshTopology::GetFirstTriangleCorner(ef[0]) + position[0]] = 4 * ef[1] + position[1];
      across[MeshTopology::GetFirstTriangleCorner(ef[1]) + position[1]] = 4 * ef[0] + position[0];
    }
  });
  return faceAcross;
}

StencilTable BuildButterflyStencils(const Level& parent, double tension, const ParallelFor& parallelFor)
{
  const MeshTopology& topo = parent.Topology;
  // Regular edge rows have 10 entries.
  const size_t expected = 10 * static_cast<size_t>(topo.GetNumEdges()) + static_cast<size_t>(topo.GetNumVertices());
  return WriteStencilTable(ButterflyRowWriter(parent, tension, parallelFor), expected);
}

ButterflyRowWriter::ButterflyRowWriter(const Level& parent, double tension, const ParallelFor& parallelFor)
  : Parent(parent)
  , Topology(parent.Topology)
  , Tension(tension)
{
  const MeshTopology& topo = this->Topology;
  const Index numVertices = topo.GetNumVertices();
  // Vertices that take the interior rules: manifold, not on the boundary, not isolated, on
  // no crease (a dart, one sharp edge, keeps its ring); their faces form one closed fan.
  // Only the rings that RingFrom walks are stored: the extraordinary ones, and all of them
  // when the tips (tension) read the regular rings too.
  this->RingValences.resize(static_cast<size_t>(numVertices));
  this->RingKinds.resize(static_cast<size_t>(numVertices));
  this->RingOffsets.resize(static_cast<size_t>(numVertices) + 1);
  this->RingOffsets[0] = 0;
  const bool hasSharpEdges = std::any_of(
    this->Parent.EdgeSharpness.begin(), this->Parent.EdgeSharpness.end(), [](float s) { return IsSharp(s); });
  std::vector<std::uint8_t> onCrease(hasSharpEdges ? static_cast<size_t>(numVertices) : 0);
  parallelFor(0, numVertices, [&](Index begin, Index end) {
    for (Index v = begin; v < end; ++v)
    {
      const VertexTag tag = topo.GetVertexTag(v);
      const Index sharpEdges = hasSharpEdges ? this->Parent.GetNumSharpEdges(v) : 0;
      if (hasSharpEdges)
      {
        onCrease[v] = sharpEdges == 2;
      }
      const Index valence =
        !tag.Boundary && !tag.NonManifold && sharpEdges < 2 ? topo.GetVertexFaces(v).size() : 0;
      this->RingValences[v] = valence;
      this->RingKinds[v] = valence == 0 || sharpEdges > 0 ? NoSmoothRing
                                                          : (valence == 6 ? SmoothRegularRing : SmoothRing);
      this->RingOffsets[v + 1] = valence != 6 || this->Tension != 0.0 ? valence : 0;
    }
  });
  std::partial_sum(this->RingOffsets.begin(), this->RingOffsets.end(), this->RingOffsets.begin());
  for (Index v = 0; v < static_cast<Index>(onCrease.size()); ++v)
  {
    if (onCrease[v])
    {
      CreaseVertex crease{ v, { InvalidIndex, InvalidIndex } };
      Index k = 0;
      for (Index e : topo.GetVertexEdges(v))
      {
        if (IsSharp(this->Parent.EdgeSharpness[e]))
        {
          crease.Neighbours[k++] = topo.GetOtherEndpoint(e, v);
        }
      }
      this->CreaseVertices.push_back(crease);
    }
  }
  // Each stored ring counter-clockwise: the vertex after v in each face of its ordered fan.
  this->RingNeighbours.resize(static_cast<size_t>(this->RingOffsets.back()));
  parallelFor(0, numVertices, [&](Index begin, Index end) {
    std::vector<Index> faces, corners;
    for (Index v = begin; v < end; ++v)
    {
      Index* ring = this->RingNeighbours.data() + this->RingOffsets[v];
      if (this->RingOffsets[v + 1] == this->RingOffsets[v])
      {
        continue;
      }
      if (!topo.GetOrderedVertexFaces(v, faces, corners)) // not expected of a closed manifold fan
      {
        std::fill(ring, this->RingNeighbours.data() + this->RingOffsets[v + 1], 0);
        continue;
      }
      for (size_t k = 0; k < faces.size(); ++k)
      {
        ring[k] = topo.GetFaceVertices(faces[k])[corners[k] == 2 ? 0 : corners[k] + 1];
      }
    }
  });
  this->FaceAcross = MakeTriangleFaceAcross(topo, parallelFor);
  // A row holds at most the crease rule's 4 sources and the smooth rule's: 10 for the
  // butterfly, K + 1 for each extraordinary end.
  this->RowBound = std::max<Index>(16, 6 + 2 * this->Topology.GetMaxValence());
}

// The vertex across edge (x, b) of triangle `face`, from the other triangle on that edge
// (InvalidIndex when the edge does not have two faces).
Index ButterflyRowWriter::AcrossEdge(Index face, Index x, Index b) const
{
  // Corner j's edge joins corners j and j + 1.
  const Index* fv = this->Topology.GetTriangleVertices(face);
  const Index ix = PlaceInTriangle(fv, x);
  const Index corner = fv[(ix + 1) % 3] == b ? ix : (ix + 2) % 3;
  return this->VertexAcross(MeshTopology::GetFirstTriangleCorner(face) + corner);
}

// Where `first` is in v's ring (K, the valence, when it is not there).
Index ButterflyRowWriter::RingStart(Index v, Index first) const
{
  const Index* ring = this->RingNeighbours.data() + this->RingOffsets[v];
  const Index K = this->RingValence(v);
  Index start = 0;
  while (start < K && ring[start] != first)
  {
    ++start;
  }
  return start;
}

Index ButterflyRowWriter::RingFrom(Index v, Index first, Index j) const
{
  return this->RingNeighbours[this->RingOffsets[v] + (this->RingStart(v, first) + j) % this->RingValence(v)];
}

// The neighbour of v along its crease other than `other`, when v has exactly two sharp
// edges (boundary edges are sharp), or InvalidIndex. Of two such neighbours, the later one
// in v's list of edges.
Index ButterflyRowWriter::OtherCreaseNeighbour(Index v, Index other) const
{
  const auto found = std::lower_bound(this->CreaseVertices.begin(), this->CreaseVertices.end(), v,
    [](const CreaseVertex& c, Index vertex) { return c.Vertex < vertex; });
  if (found == this->CreaseVertices.end() || found->Vertex != v)
  {
    return InvalidIndex;
  }
  const Index* w = found->Neighbours;
  return w[1] != other ? w[1] : (w[0] != other ? w[0] : InvalidIndex);
}

// The vertex across edge (x, b) of triangle `face` = (x, b, y), or its parallelogram
// completion x + b - y when the edge has no second face or is a crease (the other side of
// a crease is as good as missing).
void ButterflyRowWriter::AddWing(Index x, Index b, Index y, Index face, double weight, Row& row) const
{
  if (this->RingKinds[x] != NoSmoothRing)
  {
    // All of x's edges are smooth, manifold and have two faces: the wing is there, even
    // when it is y itself (a tiny closed mesh).
    row.Add(this->AcrossEdge(face, x, b), weight);
    return;
  }
  const MeshTopology& topo = this->Topology;
  // Edge i of a face joins its corners i and i + 1.
  const IndexSpan fv = topo.GetFaceVertices(face);
  const Index ix = PlaceInTriangle(fv.begin(), x);
  const Index e = topo.GetFaceEdges(face)[fv[(ix + 1) % 3] == b ? ix : (ix + 2) % 3];
  const IndexSpan ef = topo.GetEdgeFaces(e);
  if (ef.size() == 2 && !topo.GetEdgeTag(e).NonManifold && !IsSharp(this->Parent.EdgeSharpness[e]))
  {
    const Index other = OtherOfTwo(ef, face);
    const Index opposite = topo.GetTriangleThirdVertex(other, x, b);
    if (opposite != y)
    {
      row.Add(opposite, weight);
      return;
    }
  }
  row.Add(x, weight);
  row.Add(b, weight);
  row.Add(y, -weight);
}

void ButterflyRowWriter::AddTip(Index x, Index y, double weight, Row& row) const
{
  if (weight == 0.0)
  {
    return;
  }
  if (this->HasRing(x) && this->RingValence(x) == 6)
  {
    row.Add(this->RingFrom(x, y, 3), weight);
    return;
  }
  row.Add(x, 2.0 * weight); // reflection of y through x
  row.Add(y, -weight);
}

// The crease rule of edge e: the 4-point rule along the crease (or boundary) when both
// ends continue it, else the midpoint.
void ButterflyRowWriter::AddCreaseRule(Index e, double scale, Row& row) const
{
  const Index a0 = this->Topology.GetEdgeVertices(e)[0], a1 = this->Topology.GetEdgeVertices(e)[1];
  const Index p = this->OtherCreaseNeighbour(a0, a1), q = this->OtherCreaseNeighbour(a1, a0);
  if (p != InvalidIndex && q != InvalidIndex)
  {
    row.Add(a0, scale * 9.0 / 16.0);
    row.Add(a1, scale * 9.0 / 16.0);
    row.Add(p, -scale / 16.0);
    row.Add(q, -scale / 16.0);
    return;
  }
  row.Add(a0, scale * 0.5);
  row.Add(a1, scale * 0.5);
}

// The smooth rule of an edge with two triangles: the (10-point) butterfly, or the
// extraordinary-vertex stencils.
void ButterflyRowWriter::AddSmoothRule(Index e, Row& smooth) const
{
  const MeshTopology& topo = this->Topology;
  const Index a0 = topo.GetEdgeVertices(e)[0], a1 = topo.GetEdgeVertices(e)[1];
  const IndexSpan ef = topo.GetEdgeFaces(e);
  const bool ring0 = this->HasRing(a0), ring1 = this->HasRing(a1);
  const bool regular0 = ring0 && this->RingValence(a0) == 6, regular1 = ring1 && this->RingValence(a1) == 6;
  const bool butterfly = (regular0 && regular1) || (!ring0 && regular1) || (!ring1 && regular0) || (!ring0 && !ring1);
  if (butterfly)
  {
    const ButterflyWeights weight(this->Tension);
    const Index b[2] = { topo.GetTriangleThirdVertex(ef[0], a0, a1), topo.GetTriangleThirdVertex(ef[1], a0, a1) };
    smooth.Add(a0, weight.End);
    smooth.Add(a1, weight.End);
    smooth.Add(b[0], weight.Opposite);
    smooth.Add(b[1], weight.Opposite);
    for (int side = 0; side < 2; ++side)
    {
      this->AddWing(a0, b[side], a1, ef[side], weight.Wing, smooth);
      this->AddWing(a1, b[side], a0, ef[side], weight.Wing, smooth);
    }
    this->AddTip(a0, a1, weight.Tip, smooth);
    this->AddTip(a1, a0, weight.Tip, smooth);
    return;
  }
  int ends = 0;
  for (const auto& end : { std::make_pair(a0, a1), std::make_pair(a1, a0) })
  {
    const Index v = end.first;
    if (!this->HasRing(v) || this->RingValence(v) == 6)
    {
      continue;
    }
    const Index K = this->RingValence(v);
    const Index* ring = this->RingNeighbours.data() + this->RingOffsets[v];
    // The first end's ring and v are distinct points: appended without a search. The table
    // covers Zorin's valences 3..31; a ring of 1 or 2 faces (a degenerate, closed
    // double-sided fan) takes the general formula too.
    const bool append = ends == 0;
    PutButterflyExtraordinaryStencil(
      v, K, this->RingStart(v, end.second), this->ExtraordinaryWeights.Get(K), [ring](Index k) { return ring[k]; },
      [&smooth, append](Index source, double weight) {
        append ? smooth.Append(source, weight) : smooth.Add(source, weight);
      });
    ++ends;
  }
  if (ends == 2) // one end's rule alone is the row as it is
  {
    for (Index k = 0; k < smooth.Size; ++k)
    {
      smooth.Weights[k] *= 0.5;
    }
  }
}

Index ButterflyRowWriter::OneExtraordinaryEnd(Index e) const
{
  const MeshTopology& topo = this->Topology;
  // WriteRow's smooth rule alone: two faces, no sharpness (crease 0).
  if (topo.GetEdgeFaces(e).size() != 2 || topo.GetEdgeTag(e).NonManifold || this->Parent.EdgeSharpness[e] != 0.0f)
  {
    return InvalidIndex;
  }
  const Index* ev = topo.GetEdgeVertices(e);
  auto extraordinary = [this](Index v) { return this->HasRing(v) && this->RingValence(v) != 6; };
  const bool x0 = extraordinary(ev[0]), x1 = extraordinary(ev[1]);
  return x0 == x1 ? InvalidIndex : ev[x0 ? 0 : 1]; // both: AddSmoothRule averages two rules
}

Index ButterflyRowWriter::RegularButterflyRow(Index e, Index* sources, double* weights) const
{
  const MeshTopology& topo = this->Topology;
  const IndexSpan ef = topo.GetEdgeFaces(e);
  if (ef.size() != 2 || topo.GetEdgeTag(e).NonManifold || this->Parent.EdgeSharpness[e] != 0.0f)
  {
    return 0;
  }
  const Index a0 = topo.GetEdgeVertices(e)[0], a1 = topo.GetEdgeVertices(e)[1];
  if (!this->IsSmoothRegular(a0) || !this->IsSmoothRegular(a1))
  {
    return 0;
  }
  // AddSmoothRule's butterfly, entry by entry: with nothing sharp, every wing is across an
  // edge of one of the two triangles (FaceAcross) and every tip in its end's ring.
  Index b[2], wings[2][2];
  for (int side = 0; side < 2; ++side)
  {
    const Index f = ef[side];
    const Index corner = this->TriangleCornerOfEdge(f, e);
    const Index next = corner == 2 ? 0 : corner + 1, previous = corner == 0 ? 2 : corner - 1;
    // Corner `corner` starts e; the triangle's other edges start at `next` (from the end of
    // e) and `previous` (to its start).
    const Index* fv = this->Topology.GetTriangleVertices(f);
    const Index first = MeshTopology::GetFirstTriangleCorner(f);
    const bool startsAtA0 = fv[corner] == a0;
    b[side] = fv[previous];
    wings[side][0] = this->VertexAcross(first + (startsAtA0 ? previous : next)); // across (a0, b)
    wings[side][1] = this->VertexAcross(first + (startsAtA0 ? next : previous)); // across (a1, b)
  }
  Index size = 0;
  auto add = [&](Index source, double weight) {
    sources[size] = source;
    weights[size++] = weight;
  };
  const ButterflyWeights weight(this->Tension);
  add(a0, weight.End);
  add(a1, weight.End);
  add(b[0], weight.Opposite);
  add(b[1], weight.Opposite);
  for (int side = 0; side < 2; ++side)
  {
    add(wings[side][0], weight.Wing);
    add(wings[side][1], weight.Wing);
  }
  if (weight.Tip != 0.0)
  {
    add(this->RingFrom(a0, a1, 3), weight.Tip);
    add(this->RingFrom(a1, a0, 3), weight.Tip);
  }
  // WriteRow merges repeated points (tiny closed meshes): leave those rows to it.
  bool repeated = false;
  for (Index i = 1; i < size; ++i)
  {
    for (Index j = 0; j < i; ++j)
    {
      repeated |= sources[i] == sources[j];
    }
  }
  return repeated ? 0 : size;
}

Index ButterflyRowWriter::WriteRow(Index row, Index* sources, double* weights) const
{
  const MeshTopology& topo = this->Topology;
  const Index numEdges = topo.GetNumEdges();
  if (row >= numEdges)
  {
    sources[0] = row - numEdges;
    weights[0] = 1.0;
    return 1;
  }
  const Index e = row;
  Row out{ sources, weights };
  const bool twoFaces = topo.GetEdgeFaces(e).size() == 2 && !topo.GetEdgeTag(e).NonManifold;
  // Sharpness s >= 1 (boundaries, non-manifold edges: infinite) takes the crease rule;
  // a semi-sharp edge below 1 mixes s of it with 1 - s of the smooth rule.
  const double crease = twoFaces ? std::min(1.0, static_cast<double>(this->Parent.EdgeSharpness[e])) : 1.0;
  if (crease > 0.0)
  {
    this->AddCreaseRule(e, crease, out);
  }
  if (crease == 0.0)
  {
    this->AddSmoothRule(e, out); // the blend below would copy it unchanged
  }
  else if (crease < 1.0)
  {
    Row smooth{ sources + this->RowBound, weights + this->RowBound };
    this->AddSmoothRule(e, smooth);
    for (Index k = 0; k < smooth.Size; ++k)
    {
      out.Add(smooth.Sources[k], (1.0 - crease) * smooth.Weights[k]);
    }
  }
  return out.Size;
}
}
