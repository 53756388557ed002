// SubD kernel: one level of a subdivision hierarchy, i.e. a topology plus the tags the rules
// read (edge and vertex sharpness, holes) and the base face each face descends from.
#ifndef SubDLevel_h
#define SubDLevel_h

#include "SubDCrease.h"
#include "SubDMeshTopology.h"
#include "SubDStencilTable.h"
#include <vector>

namespace subd
{
struct SUBDKERNEL_EXPORT Level
{
  MeshTopology Topology;
  std::vector<float> EdgeSharpness;      ///< one per edge, OpenSubdiv's scale
  std::vector<float> VertexSharpness;    ///< one per vertex
  std::vector<std::uint8_t> FaceIsHole;  ///< one per face; holes shape neighbours, aren't emitted
  std::vector<Index> FaceOrigin;         ///< one per face: the base-level face it comes from
  int Depth = 0;                         ///< 0 for the base level, then 1, 2, ...

  Index GetNumSharpEdges(Index v) const;
  bool HasHoles() const;
};

/// The rule of a vertex and, for a crease, the far ends of its two sharp edges.
struct VertexRulePlan
{
  VertexRule Rule;
  Index CreaseEnds[2];
};

/// Classifies vertex v of `level` (SubDCrease.h). A smooth or dart vertex whose faces do not
/// form a closed fan (isolated, or as many edges as faces not met) can only be interpolated,
/// so it is planned as a corner.
SUBDKERNEL_EXPORT VertexRulePlan PlanVertexRule(const Level& level, Index v);

/// The plans of every vertex of `level`.
SUBDKERNEL_EXPORT std::vector<VertexRulePlan> PlanVertexRules(const Level& level);

/// True for an edge that takes a primal scheme's smooth edge rule: not sharp, two faces.
inline bool IsSmoothEdge(const Level& level, Index e)
{
  return !IsSharp(level.EdgeSharpness[e]) && level.Topology.GetEdgeFaces(e).size() == 2;
}

/// The size of a vertex row of a primal scheme (Catmull-Clark, Loop): 1 for a corner, 3 for a
/// crease, `smoothSize` otherwise.
inline Index PrimalVertexRowSize(const VertexRulePlan& plan, Index smoothSize)
{
  return plan.Rule == VertexRule::Corner ? 1 : (plan.Rule == VertexRule::Crease ? 3 : smoothSize);
}

/// Writes the corner (v' = v) or crease (3/4 v + 1/8 (a + b), the cubic B-spline curve rule)
/// row of vertex v, shared by Catmull-Clark and Loop. Returns false for smooth and dart
/// vertices, whose row the scheme writes itself.
inline bool WriteSharpVertexRow(const VertexRulePlan& plan, Index v, Index* src, double* wts)
{
  src[0] = v;
  if (plan.Rule == VertexRule::Corner)
  {
    wts[0] = 1.0;
    return true;
  }
  if (plan.Rule == VertexRule::Crease)
  {
    wts[0] = 0.75;
    src[1] = plan.CreaseEnds[0];
    src[2] = plan.CreaseEnds[1];
    wts[1] = wts[2] = 0.125;
    return true;
  }
  return false;
}

/// Sets the child's topology from its faces: faces only, or the full topology with smooth
/// edge and vertex tags (primal splits then inherit sharpness, InheritPrimalSharpness); and
/// its depth, one more than the parent's.
SUBDKERNEL_EXPORT void SetChildTopology(const Level& parent, Level& child, Index numPoints,
  std::vector<Index> offsets, std::vector<Index> vertices, ChildTopology depth);

/// Gives the child faces of each parent face f, [firstChild(f), firstChild(f + 1)), the hole
/// flag and origin of f. Shared by every split.
template <typename FirstChild>
void InheritFaceTags(const Level& parent, Level& child, FirstChild firstChild)
{
  const Index numFaces = parent.Topology.GetNumFaces();
  const Index numChildFaces = firstChild(numFaces);
  child.FaceIsHole.resize(static_cast<size_t>(numChildFaces));
  child.FaceOrigin.resize(static_cast<size_t>(numChildFaces));
  for (Index f = 0; f < numFaces; ++f)
  {
    for (Index c = firstChild(f); c < firstChild(f + 1); ++c)
    {
      child.FaceIsHole[c] = parent.FaceIsHole[f];
      child.FaceOrigin[c] = parent.FaceOrigin[f];
    }
  }
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
