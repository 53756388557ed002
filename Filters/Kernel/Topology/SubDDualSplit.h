// SubD kernel: the dual split (corner cutting) of Doo-Sabin subdivision.
//
// Every face corner gets a new point. Child faces, in three blocks:
//   F-faces  one per face: its corner points, same orientation (faces [0, F));
//   E-faces  one per smooth interior manifold edge: the quad of the four corner points at
//            its ends;
//   V-faces  one per sector of a manifold vertex with at least three faces: the corner
//            points around it, in the order of the faces around it
//            (MeshTopology::GetOrderedVertexFaces). A vertex's fan is cut into sectors at its
//            sharp edges (boundary edges are sharp); at the ends of a sector the face is
//            closed along the crease or boundary.
// Sharp edges (creases, boundaries, non-manifold edges) get no E-face; non-manifold vertices
// no V-face. Creases are treated like boundaries: the corner points on the two sides of a
// crease are the same crease (Chaikin) point, so they are welded into one child point, and
// at a corner vertex (DualCornerVertex) all corner points next to its sharp edges are the
// vertex itself and are welded too (all its corner points, if it has fewer than two sharp
// edges: its V-face vanishes and its E-faces become triangles). Child points are numbered by their first corner
// (DualPoints). With the rows of SubDDooSabinRules.h, boundaries and creases are refined by
// Chaikin's rule.
// F-faces inherit their face's hole flag and origin; an E- or V-face takes the origin of its
// first face. In the child, the crease segments inherit their edge's sharpness less one.
#ifndef SubDDualSplit_h
#define SubDDualSplit_h

#include "SubDFaceBlocks.h"
#include "SubDLevel.h"

namespace subd
{
/// True for a vertex the dual split pins: a single face, a face whose two edges at the vertex
/// are crease edges, three or more crease edges, or a sharp vertex.
SUBDKERNEL_EXPORT bool IsDualCornerVertex(const Level& level, Index v);

/// The child points of the dual split: PointOfCorner[c] for each face corner (faces'
/// corners in order), the first corner of each point, and which vertices are corner
/// vertices (IsDualCornerVertex). Computed once per level, shared by split and stencils.
struct DualPoints
{
  IndexArray PointOfCorner; ///< empty when Unwelded (the identity): use PointOf
  IndexArray CornerOfPoint; ///< empty when Unwelded: use CornerOf
  std::vector<std::uint8_t> IsCornerVertex;
  /// Corner vertices with fewer than two crease edges (a sharp vertex inside smooth
  /// surface, or at the end of a crease): every corner around them is the vertex itself.
  std::vector<std::uint8_t> PinsEveryCorner;
  /// ActsAsBoundary for every edge of the level: split, stencils and numbering each ask it
  /// several times per edge, and a byte is cheaper to read than the sharpness, the edge's
  /// faces and its tags.
  std::vector<std::uint8_t> EdgeActsAsBoundary;
  /// No corner is welded to another: each corner is its own point (no crease, no corner
  /// vertex, which is every level of a smooth closed mesh), and the two numberings are left
  /// empty rather than spelling out the identity (8 bytes per corner of the largest level).
  bool Unwelded = true;
  Index NumPoints = 0;
  Index PointOf(Index corner) const { return this->Unwelded ? corner : this->PointOfCorner[corner]; }
  Index CornerOf(Index point) const { return this->Unwelded ? point : this->CornerOfPoint[point]; }
};
/// `parallelFor` runs the per-edge and per-vertex classification and, when nothing is
/// welded, the numbering.
SUBDKERNEL_EXPORT DualPoints NumberDualPoints(const Level& level, const ParallelFor& parallelFor = SerialFor);

/// Writes the child faces in parallel (in blocks of parent elements, copied to their place
/// in order), so that the result does not depend on the number of threads.
SUBDKERNEL_EXPORT Level SplitDual(const Level& parent, const DualPoints& points, ChildTopology depth,
  const ParallelFor& parallelFor = SerialFor);
}

#endif
