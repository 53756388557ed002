// SubD kernel: the dual split (corner cutting) of Doo-Sabin subdivision.
//
// Every face corner gets a new point (two at a crease turn, below). Child faces, in three
// blocks:
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
// at a corner vertex (IsDualCornerVertex) all corner points next to its sharp edges are the
// vertex itself and are welded too (all its corner points, if it has fewer than two sharp
// edges: its V-face vanishes and its E-faces become triangles).
// Where a crease turns around a single face (an interior manifold vertex between exactly two
// crease edges that are both edges of one face, as at each corner of a crease loop around
// one face), Chaikin needs two points, one on each crease edge, and that face's corner gives
// both (DualPoints::TurnCorners): its F-face gets one more corner, and the segment between
// the two points is the crease's cut at the vertex, as between the two sides of any other
// crease vertex. Child points are numbered by their first corner (DualPoints). With the rows
// of SubDDooSabinRules.h, boundaries and creases are refined by Chaikin's rule.
// F-faces inherit their face's hole flag and origin; an E- or V-face takes the origin of its
// first face. In the child, the crease segments inherit their edge's sharpness less one.
#ifndef SubDDualSplit_h
#define SubDDualSplit_h

#include "SubDFaceBlocks.h"
#include "SubDLevel.h"

#include <algorithm>

namespace subd
{
/// True for a vertex the dual split pins: a single face, three or more crease edges, a sharp
/// vertex, or a non-manifold or boundary vertex with a face whose two edges at the vertex are
/// crease edges (at any other vertex such a face is inside a crease turn: TurnCorners).
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
  /// The corners of faces inside a crease turn, ascending: corners at a vertex that is no
  /// corner vertex whose two edges both act as boundaries (the vertex is then interior and
  /// manifold, with exactly these two crease edges). Such a corner gives two points: PointOf,
  /// on its outgoing edge (to the face's next corner), and PointBefore, on its incoming edge.
  /// Each is welded to the point on the same edge of the face across, so every point still
  /// has a first corner (CornerOf) whose PointOf it is, and its row is that corner's (on the
  /// corner's outgoing edge if it is a turn corner).
  IndexArray TurnCorners;
  IndexArray PointBeforeTurnCorner; ///< PointBefore of each of TurnCorners
  /// No corner is welded to another: each corner is its own point (no crease, no corner
  /// vertex, which is every level of a smooth closed mesh), and the two numberings are left
  /// empty rather than spelling out the identity (8 bytes per corner of the largest level).
  bool Unwelded = true;
  Index NumPoints = 0;
  Index PointOf(Index corner) const { return this->Unwelded ? corner : this->PointOfCorner[corner]; }
  Index CornerOf(Index point) const { return this->Unwelded ? point : this->CornerOfPoint[point]; }
  /// The point of `corner` on its incoming edge: PointOf but at TurnCorners.
  Index PointBefore(Index corner) const
  {
    if (this->TurnCorners.empty())
    {
      return this->PointOf(corner);
    }
    const auto at = std::lower_bound(this->TurnCorners.begin(), this->TurnCorners.end(), corner);
    return at != this->TurnCorners.end() && *at == corner
      ? this->PointBeforeTurnCorner[static_cast<size_t>(at - this->TurnCorners.begin())]
      : this->PointOf(corner);
  }
};
/// The point of face f's corner at its vertex v that lies on f's edge e at v (PointOf or
/// PointBefore): the point of a crease edge's end.
SUBDKERNEL_EXPORT Index DualPointOnEdge(const MeshTopology& topo, const DualPoints& points, Index f, Index v, Index e);
/// `parallelFor` runs the per-edge and per-vertex classification and, when nothing is
/// welded, the numbering.
SUBDKERNEL_EXPORT DualPoints NumberDualPoints(const Level& level, const ParallelFor& parallelFor = SerialFor);

/// Writes the child faces in parallel (in blocks of parent elements, copied to their place
/// in order), so that the result does not depend on the number of threads.
SUBDKERNEL_EXPORT Level SplitDual(const Level& parent, const DualPoints& points, ChildTopology depth,
  const ParallelFor& parallelFor = SerialFor);
}

#endif
