// SubD kernel: one level of a subdivision hierarchy, i.e. a topology plus the tags the rules
// read (edge and vertex sharpness, holes) and the base face each face descends from.
#ifndef SubDLevel_h
#define SubDLevel_h

#include "SubDMeshTopology.h"
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

  Index GetNumSharpEdges(Index v) const;
  bool HasHoles() const;
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
