#include "SubDFaceVarying.h"

#include <algorithm>
#include <cmath>

namespace subd
{
const char* ToString(FaceVaryingInterpolation mode)
{
  switch (mode)
  {
    case FaceVaryingInterpolation::None:
      return "none";
    case FaceVaryingInterpolation::CornersOnly:
      return "corners-only";
    case FaceVaryingInterpolation::CornersPlus1:
      return "corners-plus1";
    case FaceVaryingInterpolation::CornersPlus2:
      return "corners-plus2";
    case FaceVaryingInterpolation::Boundaries:
      return "boundaries";
    default:
      return "all";
  }
}

namespace
{
// The channel's vertices: per mesh vertex, its distinct values in the order its corners come
// (GetVertexFaces), numbered vertex after vertex. Returns each corner's channel vertex;
// `firstOf` gets each mesh vertex's first channel vertex (numVertices + 1 entries).
IndexArray NumberChannelVertices(const MeshTopology& mesh, const Index* valueOfCorner, IndexArray& userValue,
  IndexArray& firstOf)
{
  IndexArray channelVertexOfCorner(static_cast<size_t>(mesh.GetNumFaceCorners()));
  firstOf.assign(static_cast<size_t>(mesh.GetNumVertices()) + 1, 0);
  userValue.clear();
  for (Index v = 0; v < mesh.GetNumVertices(); ++v)
  {
    const Index first = static_cast<Index>(userValue.size());
    firstOf[v] = first;
    const IndexSpan faces = mesh.GetVertexFaces(v), corners = mesh.GetVertexFaceCorners(v);
    for (Index i = 0; i < faces.size(); ++i)
    {
      const Index h = mesh.GetFaceOffset(faces[i]) + corners[i];
      const auto known = std::find(userValue.begin() + first, userValue.end(), valueOfCorner[h]);
      channelVertexOfCorner[h] = static_cast<Index>(known - userValue.begin());
      if (known == userValue.end())
      {
        userValue.push_back(valueOfCorner[h]);
      }
    }
  }
  firstOf[mesh.GetNumVertices()] = static_cast<Index>(userValue.size());
  return channelVertexOfCorner;
}

// What the mode needs to know of one value u (a channel vertex) at its mesh vertex.
struct ValueSpan
{
  Index Faces = 0;           ///< faces using u at its vertex
  bool OnSeam = false;       ///< an edge at u has fewer faces in the channel than in the mesh
  bool InfSharpEdge = false; ///< an edge at u inside its region is infinitely sharp
  bool Disjoint = false;     ///< u's faces form several fans
  std::vector<float> SemiSharpEdges; ///< sharpness of the semi-sharp edges inside its region
};

ValueSpan DescribeSpan(const Level& channel, const MeshTopology& mesh, const IndexArray& meshEdgeOf, Index u)
{
  const MeshTopology& topo = channel.Topology;
  ValueSpan span;
  span.Faces = topo.GetVertexFaces(u).size();
  span.Disjoint = topo.GetVertexTag(u).NonManifold != 0;
  for (Index e : topo.GetVertexEdges(u))
  {
    const Index faces = topo.GetEdgeFaces(e).size();
    span.OnSeam |= faces < mesh.GetEdgeFaces(meshEdgeOf[e]).size();
    if (faces >= 2)
    {
      const float s = channel.EdgeSharpness[e];
      span.InfSharpEdge |= IsInfinitelySharp(s);
      if (IsSemiSharp(s))
      {
        span.SemiSharpEdges.push_back(s);
      }
    }
  }
  return span;
}

// The vertex sharpness that makes a value without semi-sharp edges follow the corner-to-crease
// transition of a partner whose region has these (OpenSubdiv's "dependent sharpness"): under
// uniform creasing the partner stays a corner until its sharpest edge decays, and then blends
// with the mean sharpness left on the edges decaying that level; a vertex sharpness of that
// level plus that mean does the same.
float DependentSharpness(const std::vector<float>& semiSharp)
{
  const float most = *std::max_element(semiSharp.begin(), semiSharp.end());
  const float level = std::ceil(most) - 1.0f;
  float sum = 0.0f;
  int count = 0;
  for (float s : semiSharp)
  {
    if (s > level)
    {
      sum += s - level;
      ++count;
    }
  }
  return level + std::min(1.0f, sum / static_cast<float>(count));
}

// The two values of a vertex under CornersPlus1 and CornersPlus2: true if both are corners (a
// region holds an infinitely sharp edge or touches itself; with Plus2 one of a single face),
// else gives the value whose region has no semi-sharp edge its partner's decay.
bool PinTwoValues(const std::vector<ValueSpan>& spans, Index first, FaceVaryingInterpolation mode, Level& channel)
{
  const auto sharpened = [mode](const ValueSpan& s) {
    return s.InfSharpEdge || s.Disjoint || (mode == FaceVaryingInterpolation::CornersPlus2 && s.Faces == 1);
  };
  if (sharpened(spans[0]) || sharpened(spans[1]))
  {
    return true;
  }
  const bool semi0 = !spans[0].SemiSharpEdges.empty(), semi1 = !spans[1].SemiSharpEdges.empty();
  if (semi0 != semi1)
  {
    float& dependent = channel.VertexSharpness[first + (semi0 ? 1 : 0)];
    dependent = std::max(dependent, DependentSharpness(spans[semi0 ? 0 : 1].SemiSharpEdges));
  }
  return false;
}

// Pins the values of mesh vertex v that the mode makes corners (OpenSubdiv's
// FVarLevel::completeTopologyFromFaceValues); the channel's own rules do the rest.
void PinValues(const Level& mesh, Index v, const std::vector<ValueSpan>& spans, Index first,
  FaceVaryingInterpolation mode, Level& channel)
{
  using Mode = FaceVaryingInterpolation;
  const Index count = static_cast<Index>(spans.size());
  const bool mismatched = count > 1 || std::any_of(spans.begin(), spans.end(), [](const ValueSpan& s) { return s.OnSeam; });
  const VertexTag tag = mesh.Topology.GetVertexTag(v);
  const bool plus = mode == Mode::CornersPlus1 || mode == Mode::CornersPlus2;
  const bool all = (tag.NonManifold && mismatched) || (mode == Mode::Boundaries && (mismatched || tag.Boundary)) ||
    (plus && count > 2) || (mode == Mode::CornersPlus2 && mismatched && count == 1 && !tag.Boundary) ||
    (plus && count == 2 && PinTwoValues(spans, first, mode, channel));
  for (Index k = 0; k < count; ++k)
  {
    if (all || (mode != Mode::None && spans[k].Faces == 1))
    {
      channel.VertexSharpness[first + k] = SharpnessInfinite;
    }
  }
}
}

FaceVaryingBase MakeFaceVaryingBase(const Level& mesh, const Index* valueOfCorner, FaceVaryingInterpolation mode)
{
  const MeshTopology& topo = mesh.Topology;
  FaceVaryingBase base;
  IndexArray firstOf;
  IndexArray corners = NumberChannelVertices(topo, valueOfCorner, base.UserValue, firstOf);
  const Index numValues = static_cast<Index>(base.UserValue.size());
  IndexArray offsets(static_cast<size_t>(topo.GetNumFaces()) + 1);
  for (Index f = 0; f <= topo.GetNumFaces(); ++f)
  {
    offsets[f] = f < topo.GetNumFaces() ? topo.GetFaceOffset(f) : topo.GetNumFaceCorners();
  }
  MeshTopology channelTopology = MeshTopology::Build(numValues, std::move(offsets), std::move(corners));

  // Each channel edge is the mesh edge at the same corner, with its sharpness; a seam is a
  // boundary of the channel, made infinitely sharp by MakeBaseLevel.
  IndexArray meshEdgeOf(static_cast<size_t>(channelTopology.GetNumEdges()), InvalidIndex);
  BaseTags tags;
  tags.Creasing = mesh.Creasing;
  tags.EdgeSharpness.assign(static_cast<size_t>(channelTopology.GetNumEdges()), 0.0f);
  for (Index f = 0; f < topo.GetNumFaces(); ++f)
  {
    const IndexSpan channelEdges = channelTopology.GetFaceEdges(f), meshEdges = topo.GetFaceEdges(f);
    for (Index k = 0; k < meshEdges.size(); ++k)
    {
      meshEdgeOf[channelEdges[k]] = meshEdges[k];
      tags.EdgeSharpness[channelEdges[k]] = mesh.EdgeSharpness[meshEdges[k]];
    }
  }
  tags.VertexSharpness.resize(static_cast<size_t>(numValues));
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    std::fill(tags.VertexSharpness.begin() + firstOf[v], tags.VertexSharpness.begin() + firstOf[v + 1],
      mesh.VertexSharpness[v]);
  }
  tags.FaceIsHole.assign(mesh.FaceIsHole.begin(), mesh.FaceIsHole.end());
  base.Values = MakeBaseLevel(std::move(channelTopology), tags, BoundaryRule::EdgeOnly);
  Level& channel = base.Values;
  if (mode == FaceVaryingInterpolation::All)
  {
    channel.Linear = LinearPart::All;
    std::fill(channel.EdgeSharpness.begin(), channel.EdgeSharpness.end(), SharpnessInfinite);
    std::fill(channel.VertexSharpness.begin(), channel.VertexSharpness.end(), SharpnessInfinite);
    return base;
  }
  channel.Linear = mode == FaceVaryingInterpolation::Boundaries ? LinearPart::Boundaries : LinearPart::None;
  std::vector<ValueSpan> spans;
  for (Index v = 0; v < topo.GetNumVertices(); ++v)
  {
    spans.clear();
    for (Index u = firstOf[v]; u < firstOf[v + 1]; ++u)
    {
      spans.push_back(DescribeSpan(channel, topo, meshEdgeOf, u));
    }
    if (!spans.empty())
    {
      PinValues(mesh, v, spans, firstOf[v], mode, channel);
    }
  }
  return base;
}
}
