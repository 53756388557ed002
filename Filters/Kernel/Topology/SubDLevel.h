// SubD kernel: one level of a subdivision hierarchy, i.e. a topology plus the tags the rules
// read (edge and vertex sharpness, holes) and the base face each face descends from.
#ifndef SubDLevel_h
#define SubDLevel_h

#include "SubDCrease.h"
#include "SubDMeshTopology.h"
#include "SubDParallel.h"
#include "SubDStencilTable.h"
#include <algorithm>
#include <vector>

namespace subd
{
/// The part of a face-varying channel's mesh that stays linear at every level (OpenSubdiv's
/// FVarLinearInterpolation Boundaries and All, SubDFaceVarying.h).
enum class LinearPart : std::uint8_t
{
  None,       ///< none (a mesh's level)
  Boundaries, ///< every point made on a boundary edge is a corner, so boundaries stay polylines
  All         ///< every point and edge is infinitely sharp: linear refinement
};

struct SUBDKERNEL_EXPORT Level
{
  MeshTopology Topology;
  LevelArray<float> EdgeSharpness;        ///< one per edge, OpenSubdiv's scale
  LevelArray<float> VertexSharpness;      ///< one per vertex
  LevelArray<std::uint8_t> FaceIsHole;    ///< per face (or none: no hole); holes shape neighbours, aren't emitted
  LevelArray<Index> FaceOrigin;           ///< per face: the base-level face it comes from
  /// Face f's hole flag and origin are at f >> FaceTagShift: 0, one per face, except for a
  /// faces-only primal split whose parent's faces have four children each, which keeps its
  /// parent's tags (InheritPrimalFaceTags: 2).
  int FaceTagShift = 0;
  int Depth = 0;                         ///< 0 for the base level, then 1, 2, ...
  LinearPart Linear = LinearPart::None;  ///< inherited by every level below

  bool IsFaceHole(Index f) const
  {
    return !this->FaceIsHole.empty() && this->FaceIsHole[static_cast<size_t>(f) >> this->FaceTagShift] != 0;
  }
  Index GetFaceOrigin(Index f) const { return this->FaceOrigin[static_cast<size_t>(f) >> this->FaceTagShift]; }
  CreaseMethod Creasing = CreaseMethod::Uniform; ///< how semi-sharp edges decay

  Index GetNumSharpEdges(Index v) const;
  bool HasHoles() const;
  /// Some edge or vertex is sharp (semi-sharp included).
  bool HasSharpFeatures() const;
};

/// True for an edge that schemes without a crease rule of their own (Doo-Sabin, midpoint,
/// sqrt(3)) treat like a boundary: sharp at this level, or without exactly two faces, or
/// non-manifold.
SUBDKERNEL_EXPORT bool ActsAsBoundary(const Level& level, Index e);

/// The number of edges at vertex v for which isCounted(level, e) holds.
template <typename Predicate>
Index CountVertexEdges(const Level& level, Index v, Predicate&& isCounted)
{
  Index count = 0;
  for (Index e : level.Topology.GetVertexEdges(v))
  {
    count += isCounted(level, e) ? 1 : 0;
  }
  return count;
}

/// Sharpness of the half of edge e that ends at its end vertex `end` (0 or 1), one level
/// down, by the level's crease method (SubdivideEdgeSharpnessAtVertex).
SUBDKERNEL_EXPORT float ChildEdgeSharpness(const Level& level, Index e, int end);

/// The rule of a vertex at this level and of its child point at the next level, and how
/// the two masks mix when they differ (a semi-sharp feature decays to smooth at this level,
/// OpenSubdiv's "transitional" rule).
struct VertexRulePlan
{
  VertexRule Rule;           ///< at this level
  VertexRule ChildRule;      ///< of the vertex's child point, after the sharpness decays
  Index CreaseEdges[2];      ///< Rule == Crease: positions in GetVertexEdges(v) of the sharp edges
  Index ChildCreaseEdges[2]; ///< the same for ChildRule == Crease
  float ParentWeight;        ///< weight of the Rule's mask when ChildRule differs, else 1
};

/// Classifies vertex v of `level` and its child point (SubDCrease.h). A smooth or dart
/// vertex whose faces do not form a closed fan (isolated, or as many edges as faces not
/// met) can only be interpolated, so it is planned as a corner.
SUBDKERNEL_EXPORT VertexRulePlan PlanVertexRule(const Level& level, Index v);

/// The plans of every vertex of `level`.
SUBDKERNEL_EXPORT std::vector<VertexRulePlan> PlanVertexRules(const Level& level);

/// The weight of the crease rule (the midpoint) in the edge point of e, against the scheme's
/// smooth edge rule (OpenSubdiv's edge-vertex rule): 0 for a smooth edge, 1 when the edge
/// is sharp and both its halves stay sharp (or it cannot be smooth: not two faces), and the
/// edge's sharpness when a semi-sharp edge becomes smooth at this level. As in OpenSubdiv
/// the sharpness is not clamped: with Chaikin creasing a half can vanish under an edge of
/// sharpness above 1, which then extrapolates past the crease rule.
SUBDKERNEL_EXPORT float EdgeCreaseWeight(const Level& level, Index e);

/// True for an edge with two faces and no sharpness: the smooth edge rule applies.
inline bool IsSmoothEdge(const Level& level, Index e)
{
  return !IsSharp(level.EdgeSharpness[e]) && level.Topology.GetEdgeFaces(e).size() == 2;
}

/// True when neither v nor any of its edges is sharp.
inline bool NothingSharpAt(const Level& level, Index v)
{
  if (IsSharp(level.VertexSharpness[v]))
  {
    return false;
  }
  for (Index e : level.Topology.GetVertexEdges(v))
  {
    if (IsSharp(level.EdgeSharpness[e]))
    {
      return false;
    }
  }
  return true;
}

/// True when v has faces, they close around it (as many faces as edges) and nothing is
/// sharp at or around it: the smooth vertex rule applies at this level and the next (the
/// common case of PlanVertexRule).
inline bool IsSmoothClosedVertex(const Level& level, Index v)
{
  const Index numEdges = level.Topology.GetVertexEdges(v).size();
  return numEdges > 0 && level.Topology.GetVertexFaces(v).size() == numEdges && NothingSharpAt(level, v);
}

/// IsSmoothClosedVertex for every vertex of `level`, one byte each. A pass over the edges
/// marks the ends of the sharp ones, where the per-vertex test reads the sharpness of every
/// edge around the vertex: scattered reads that were most of a smooth vertex row's cost.
SUBDKERNEL_EXPORT std::vector<std::uint8_t> FindSmoothClosedVertices(
  const Level& level, const ParallelFor& parallelFor = SerialFor);

/// The crease weight of every edge of `level`.
SUBDKERNEL_EXPORT std::vector<float> EdgeCreaseWeights(const Level& level);

/// Sets the child's topology from its faces: faces only, or the full topology with smooth
/// edge and vertex tags; and its depth, one more than the parent's.
SUBDKERNEL_EXPORT void SetChildTopology(const Level& parent, Level& child, Index numPoints,
  IndexArray offsets, IndexArray vertices, ChildTopology depth, const ParallelFor& parallelFor = SerialFor);

/// The edge key of the half of parent edge e that ends at its vertex v (0 .. 2E-1): keys
/// that primal splits give the two halves of every parent edge.
inline Index HalfEdgeKey(const MeshTopology& parent, Index e, Index v)
{
  return 2 * e + (parent.GetEdgeVertices(e)[0] == v ? 0 : 1);
}

/// The keys of the halves of edge e of a face where e starts at the face's corner `start`:
/// the half at that corner, and the half at the next one. Told by corner rather than by
/// vertex, so that an edge from a vertex to itself (a face that repeats it) has two halves.
inline Index StartHalfKey(const MeshTopology& parent, Index e, Index start)
{
  return HalfEdgeKey(parent, e, start);
}
inline Index EndHalfKey(const MeshTopology& parent, Index e, Index start)
{
  return 2 * e + (parent.GetEdgeVertices(e)[0] == start ? 1 : 0);
}

/// Gives the child faces of each parent face f, [firstChild(f), firstChild(f + 1)), the hole
/// flag and origin of f. Shared by every split.
template <typename FirstChild>
void InheritFaceTags(const Level& parent, Level& child, FirstChild firstChild, const ParallelFor& parallelFor = SerialFor)
{
  const Index numFaces = parent.Topology.GetNumFaces();
  const Index numChildFaces = firstChild(numFaces);
  child.FaceIsHole.resize(static_cast<size_t>(numChildFaces));
  child.FaceOrigin.resize(static_cast<size_t>(numChildFaces));
  parallelFor(0, numFaces, [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f)
    {
      for (Index c = firstChild(f); c < firstChild(f + 1); ++c)
      {
        child.FaceIsHole[c] = parent.FaceIsHole[f];
        child.FaceOrigin[c] = parent.FaceOrigin[f];
      }
    }
  });
}

/// InheritFaceTags, or with `share` (the parent has a tag per face, and each of its faces
/// has 2^shift children, in order) the parent's tags themselves, one per parent face, with
/// FaceTagShift `shift`: no copy per child face. Returns whether it shared them.
template <typename FirstChild>
bool ShareOrInheritFaceTags(const Level& parent, Level& child, bool share, int shift, FirstChild firstChild,
  const ParallelFor& parallelFor = SerialFor)
{
  if (share)
  {
    child.FaceIsHole = parent.FaceIsHole;
    child.FaceOrigin = parent.FaceOrigin;
    child.FaceTagShift = shift;
    return true;
  }
  InheritFaceTags(parent, child, firstChild, parallelFor);
  return false;
}

/// InheritFaceTags for a primal split's child: a faces-only child (a finest level, only
/// output) whose faces come four from each parent face in order (`fourEach`: child faces
/// 4f .. 4f + 3 of face f) keeps the parent's tags, one per parent face (FaceTagShift 2),
/// instead of a copy per child face: 5 bytes per output face less.
template <typename FirstChild>
void InheritPrimalFaceTags(const Level& parent, Level& child, ChildTopology depth, bool fourEach,
  FirstChild firstChild, const ParallelFor& parallelFor = SerialFor)
{
  const bool share = depth == ChildTopology::FacesOnly && fourEach && parent.FaceTagShift == 0;
  ShareOrInheritFaceTags(parent, child, share, 2, firstChild, parallelFor);
}

/// For primal splits (each edge gets an edge point, each vertex a vertex point): the two
/// halves of a sharp edge inherit its sharpness decayed by one level, a vertex point its
/// vertex's decayed sharpness; everything new is smooth. `child.Topology` must be complete.
SUBDKERNEL_EXPORT void InheritPrimalSharpness(const Level& parent, Level& child,
  Index firstEdgePoint, Index firstVertexPoint);

/// One level's refinement: the stencils of the child points and the child level.
struct LevelRefinement
{
  StencilTable Stencils;
  Level Child;
};

/// Tags supplied with the base mesh. Empty vectors mean "none".
struct BaseTags
{
  std::vector<float> EdgeSharpness;   ///< per edge of the base topology
  std::vector<float> VertexSharpness; ///< per vertex
  std::vector<std::uint8_t> FaceIsHole;
  CreaseMethod Creasing = CreaseMethod::Uniform;
};

/// Makes the base level: applies the explicit tags, then the boundary rule and the treatment
/// of non-manifold features exactly as OpenSubdiv prepares its base level
/// (Far::TopologyRefinerFactoryBase): boundary and non-manifold edges become infinitely
/// sharp; EdgeAndCorner sharpens vertices with one face and two edges; non-manifold vertices
/// are sharpened, except those inside a non-manifold crease (two non-manifold edges, no
/// boundary, more faces than edges); with BoundaryRule::None the faces around every vertex
/// that has a boundary edge not explicitly infinitely sharp become holes. Those tags are
/// inherited by later levels, never re-derived from their topology.
SUBDKERNEL_EXPORT Level MakeBaseLevel(MeshTopology topology, const BaseTags& tags, BoundaryRule rule);

}

#endif
