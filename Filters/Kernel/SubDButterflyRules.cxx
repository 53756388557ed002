#include "SubDButterflyRules.h"
#include "SubDTriangleSplit.h"

#include <algorithm>
#include <cmath>

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

namespace
{
// A stencil row under construction: weights accumulated per source.
class RowBuilder
{
public:
  void Add(Index source, double weight)
  {
    for (auto& entry : this->Entries)
    {
      if (entry.first == source)
      {
        entry.second += weight;
        return;
      }
    }
    this->Entries.emplace_back(source, weight);
  }
  void Scale(double factor)
  {
    for (auto& entry : this->Entries)
    {
      entry.second *= factor;
    }
  }
  std::vector<std::pair<Index, double>> Entries;
};

// Rings of the vertices that take the butterfly's interior rules: manifold, not on the
// boundary, and on no crease (fewer than two sharp edges: a dart keeps its ring).
// Neighbours in counter-clockwise order.
class Rings
{
public:
  explicit Rings(const Level& level)
    : Offsets(static_cast<size_t>(level.Topology.GetNumVertices()) + 1, 0)
  {
    const MeshTopology& topo = level.Topology;
    std::vector<Index> faces, corners;
    for (Index v = 0; v < topo.GetNumVertices(); ++v)
    {
      if (!topo.GetVertexTag(v).Boundary && level.GetNumSharpEdges(v) < 2 &&
        topo.GetOrderedVertexFaces(v, faces, corners))
      {
        for (size_t i = 0; i < faces.size(); ++i)
        {
          this->Neighbours.push_back(topo.GetFaceVertices(faces[i])[(corners[i] + 1) % 3]);
        }
      }
      this->Offsets[v + 1] = static_cast<Index>(this->Neighbours.size());
    }
  }
  bool Has(Index v) const { return this->Offsets[v + 1] > this->Offsets[v]; }
  Index Valence(Index v) const { return this->Offsets[v + 1] - this->Offsets[v]; }
  /// Neighbour j of v counted from `first` (which must be a neighbour).
  Index From(Index v, Index first, Index j) const
  {
    const Index* ring = this->Neighbours.data() + this->Offsets[v];
    const Index K = this->Valence(v);
    Index start = 0;
    while (start < K && ring[start] != first)
    {
      ++start;
    }
    return ring[(start + j) % K];
  }

private:
  std::vector<Index> Offsets;
  std::vector<Index> Neighbours;
};

// The neighbour of v along its crease other than `other`, when v has exactly two sharp
// edges (boundary edges are sharp), or InvalidIndex.
Index OtherCreaseNeighbour(const Level& level, Index v, Index other)
{
  const MeshTopology& topo = level.Topology;
  Index found = InvalidIndex;
  Index count = 0;
  for (Index e : topo.GetVertexEdges(v))
  {
    if (IsSharp(level.EdgeSharpness[e]))
    {
      ++count;
      const Index w = topo.GetOtherEndpoint(e, v);
      if (w != other)
      {
        found = w;
      }
    }
  }
  return count == 2 ? found : InvalidIndex;
}

// The vertex across edge (x, b) from the triangle (x, b, y), or its parallelogram
// completion x + b - y when the edge has no second face or is a crease (the other side of
// a crease is as good as missing).
void AddWing(const Level& level, Index x, Index b, Index y, double weight, RowBuilder& row)
{
  const MeshTopology& topo = level.Topology;
  const Index e = topo.FindEdge(x, b);
  const IndexSpan ef = topo.GetEdgeFaces(e);
  if (ef.size() == 2 && !topo.GetEdgeTag(e).NonManifold && !IsSharp(level.EdgeSharpness[e]))
  {
    for (Index f : ef)
    {
      const Index opposite = topo.GetTriangleOppositeVertex(f, e);
      if (opposite != y)
      {
        row.Add(opposite, weight);
        return;
      }
    }
  }
  row.Add(x, weight);
  row.Add(b, weight);
  row.Add(y, -weight);
}

void AddTip(const Rings& rings, Index x, Index y, double weight, RowBuilder& row)
{
  if (weight == 0.0)
  {
    return;
  }
  if (rings.Has(x) && rings.Valence(x) == 6)
  {
    row.Add(rings.From(x, y, 3), weight);
    return;
  }
  row.Add(x, 2.0 * weight); // reflection of y through x
  row.Add(y, -weight);
}

// The crease rule of edge e: the 4-point rule along the crease (or boundary) when both
// ends continue it, else the midpoint.
void AddCreaseRule(const Level& level, Index e, double scale, RowBuilder& row)
{
  const Index a0 = level.Topology.GetEdgeVertices(e)[0], a1 = level.Topology.GetEdgeVertices(e)[1];
  const Index p = OtherCreaseNeighbour(level, a0, a1), q = OtherCreaseNeighbour(level, a1, a0);
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
void AddSmoothRule(const Level& level, const Rings& rings, Index e, double w, double scale, RowBuilder& row)
{
  const MeshTopology& topo = level.Topology;
  const Index a0 = topo.GetEdgeVertices(e)[0], a1 = topo.GetEdgeVertices(e)[1];
  const IndexSpan ef = topo.GetEdgeFaces(e);
  const bool ring0 = rings.Has(a0), ring1 = rings.Has(a1);
  const bool regular0 = ring0 && rings.Valence(a0) == 6, regular1 = ring1 && rings.Valence(a1) == 6;
  const bool butterfly = (regular0 && regular1) || (!ring0 && regular1) || (!ring1 && regular0) || (!ring0 && !ring1);
  RowBuilder smooth;
  if (butterfly)
  {
    const Index b0 = topo.GetTriangleOppositeVertex(ef[0], e);
    const Index b1 = topo.GetTriangleOppositeVertex(ef[1], e);
    smooth.Add(a0, 0.5 - w);
    smooth.Add(a1, 0.5 - w);
    smooth.Add(b0, 0.125 + 2.0 * w);
    smooth.Add(b1, 0.125 + 2.0 * w);
    for (Index b : { b0, b1 })
    {
      AddWing(level, a0, b, a1, -0.0625 - w, smooth);
      AddWing(level, a1, b, a0, -0.0625 - w, smooth);
    }
    AddTip(rings, a0, a1, w, smooth);
    AddTip(rings, a1, a0, w, smooth);
  }
  else
  {
    int ends = 0;
    for (const auto& end : { std::make_pair(a0, a1), std::make_pair(a1, a0) })
    {
      const Index v = end.first;
      if (!rings.Has(v) || rings.Valence(v) == 6)
      {
        continue;
      }
      const Index K = rings.Valence(v);
      double sum = 0.0;
      for (Index j = 0; j < K; ++j)
      {
        const double s = ButterflyExtraordinaryWeight(K, j);
        smooth.Add(rings.From(v, end.second, j), s);
        sum += s;
      }
      smooth.Add(v, 1.0 - sum);
      ++ends;
    }
    smooth.Scale(1.0 / ends);
  }
  for (const auto& entry : smooth.Entries)
  {
    row.Add(entry.first, scale * entry.second);
  }
}
}

StencilTable BuildButterflyStencils(const Level& parent, double tension)
{
  const MeshTopology& topo = parent.Topology;
  const Index numEdges = topo.GetNumEdges();
  const Index numVertices = topo.GetNumVertices();
  const TriangleSplitNumbering number{ numEdges };
  const Rings rings(parent);

  std::vector<RowBuilder> rows(static_cast<size_t>(numEdges));
  for (Index e = 0; e < numEdges; ++e)
  {
    RowBuilder& row = rows[e];
    const bool twoFaces = topo.GetEdgeFaces(e).size() == 2 && !topo.GetEdgeTag(e).NonManifold;
    // Sharpness s >= 1 (boundaries, non-manifold edges: infinite) takes the crease rule;
    // a semi-sharp edge below 1 mixes s of it with 1 - s of the smooth rule.
    const double crease = twoFaces ? std::min(1.0, static_cast<double>(parent.EdgeSharpness[e])) : 1.0;
    if (crease > 0.0)
    {
      AddCreaseRule(parent, e, crease, row);
    }
    if (crease < 1.0)
    {
      AddSmoothRule(parent, rings, e, tension, 1.0 - crease, row);
    }
  }

  StencilTable table(numVertices);
  table.ReserveRows(numEdges + numVertices);
  for (Index e = 0; e < numEdges; ++e)
  {
    table.SetRowSize(number.EdgePoint(e), static_cast<Index>(rows[e].Entries.size()));
  }
  for (Index v = 0; v < numVertices; ++v)
  {
    table.SetRowSize(number.VertexPoint(v), 1);
  }
  table.FinalizeSizes();
  for (Index e = 0; e < numEdges; ++e)
  {
    Index* src = table.GetMutableSources(number.EdgePoint(e));
    double* wts = table.GetMutableWeights(number.EdgePoint(e));
    for (const auto& entry : rows[e].Entries)
    {
      *src++ = entry.first;
      *wts++ = entry.second;
    }
  }
  for (Index v = 0; v < numVertices; ++v)
  {
    *table.GetMutableSources(number.VertexPoint(v)) = v;
    *table.GetMutableWeights(number.VertexPoint(v)) = 1.0;
  }
  table.EndBlock(numEdges + numVertices);
  return table;
}
}
