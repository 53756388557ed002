// SubD kernel: the midpoint scheme's finest level written from its grandparent, in closed
// form, so that the level between is never built.
//
// Peters and Reif's split (SubDMidpointSplit.h) makes a point per edge, an F-face per face
// and a V-face per vertex. On a grandparent G that is closed, manifold and without sharp
// features, holes or vertices of fewer than three faces, nothing is kept and the level
// between P is known in closed form from G:
// - P's points are G's edges; each is a vertex of four faces of P (the F-faces of its two
//   faces, the V-faces of its two ends);
// - P's faces are G's faces (F-faces, the same sizes) then one per vertex of G (V-faces);
// - every edge of P joins an F-face and a V-face, and MeshTopology numbers edges in the order
//   their first half-edge is met: P's edge at corner j of F-face f is P's edge number
//   offset(f) + j, the number of G's corner at j in f. So P's edges, the finest level's
//   points, are G's corners: P's edge (f, j) joins the points of G's edges j and j + 1 of f,
//   which meet at G's corner j + 1.
// Naming the finest points by G's corners h (point h is the midpoint of P's edge h), the
// finest level's faces are, in the order the split of P gives them:
// - the F-face of P's F-face f: the corners of f, h = offset(f) .. offset(f + 1) - 1;
// - the F-face of P's V-face v: prev(h) for the corners h of v in the order of v's fan
//   (MeshTopology::GetOrderedVertexFaces: from v's first face, each next face across the edge
//   entering v in the one before), prev(h) being the corner before h in its face;
// - the V-face of P's point e (G's edge e, in edge order): h0, prev(h0), h1, prev(h1), where
//   h0 < h1 are e's two half-edges (corners) in G: P's fan around e starts at the F-face of
//   h0's face (the lowest of the four) and alternates F- and V-faces.
// The finest level's rows read P's points (G's edges): point h is the mean of the points of
// G's edges at h and after it in h's face, the two ends of P's edge h in P's order, so that
// the rows give the bits of P's own (MakeMidpointRowSource). The faces' origins are the
// lowest of the faces each comes from, as the split gives them.
//
// The finest faces need G's faces' edges and its edges' ends, which G's own rows keep anyway
// (the ends): G is kept with MeshTopology::Part::FacesWithEdges, without its faces' corners,
// since a corner's vertex is the end its edge shares with the edge before it (which tells an
// edge's first half-edge, starting at its first end, from its second). The fans are walked
// from the V-faces' quads once they are written (each quad holds both half-edges of an edge
// and the corners before them).
// Where a level above G has the closed form too, each level from it down to G is split with
// that part alone (MidpointChildWithEdges): its faces' edges and edges' ends follow from its
// parent's the same way (the F-faces of F- and V-faces above), and its lists and tags around
// the vertices, most of a level's topology, are never made.
#ifndef SubDMidpointGrandchild_h
#define SubDMidpointGrandchild_h

#include "SubDLevel.h"
#include "SubDStencilTable.h"

#include <memory>

namespace subd
{
/// Whether the finest level two midpoint splits below `grandparent` (a full-topology level,
/// or one split by MidpointChildWithEdges) has the closed form above: no boundary,
/// non-manifold edge or vertex, sharp edge or vertex, hole, and every vertex of at least three
/// faces.
SUBDKERNEL_EXPORT bool MidpointGrandchildHasClosedForm(const Level& grandparent);

/// The split of a level with that closed form (its child has it too), with what its
/// grandchild written from it and its own rows read alone: its faces' offsets and edges and
/// its edges' ends (MeshTopology::BuildFacesWithEdges), and its faces' origins if
/// `keepOrigins`; no corners, relation, tag or sharpness (nothing is sharp). It reads the
/// parent's faces' edges, edges' ends and origins only, so `parent` may be such a split
/// itself. The same faces' edges, edges' ends and origins as SplitMidpoint's, for about a
/// fifth of its memory: the child's F-faces run along its edges numbered by the face's
/// corners, its V-faces along those of the corners before the vertex's in fan order; its
/// edge h joins the points of the parent's edges at and after corner h.
SUBDKERNEL_EXPORT Level MidpointChildWithEdges(
  const Level& parent, bool keepOrigins, const ParallelFor& parallelFor = SerialFor);

/// The rows of the finest level's points (one per corner of `grandparent`) from the points
/// of the level between (one per edge of `grandparent`), written as they are applied. They
/// read the grandparent's faces' offsets and edges only.
SUBDKERNEL_EXPORT std::shared_ptr<const RowSource> MakeMidpointGrandchildRowSource(
  std::shared_ptr<const Level> grandparent);

/// The finest level's tags, without its faces: depth, crease method and, if `keepOrigins`,
/// each face's origin. Reads the grandparent's faces' edges, its edges' ends and its faces'
/// origins.
SUBDKERNEL_EXPORT Level MidpointGrandchildTags(
  const Level& grandparent, bool keepOrigins, const ParallelFor& parallelFor = SerialFor);

/// The finest level's faces (faces only, one point per corner of `grandparent`).
SUBDKERNEL_EXPORT MeshTopology MidpointGrandchildFaces(
  const MeshTopology& grandparent, const ParallelFor& parallelFor = SerialFor);

/// Their number: a face per face, vertex and edge of `grandparent`.
SUBDKERNEL_EXPORT Index CountMidpointGrandchildFaces(const MeshTopology& grandparent);
}

#endif
