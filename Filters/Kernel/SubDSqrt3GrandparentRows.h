// SubD kernel: the rows of a sqrt(3) step's points written from the level two above, so that
// the level above the finest need not be kept for them.
//
// Rows written as they are applied keep the level they read (SubDRowWriting.h). For the
// finest level that is its parent C, whose faces and rings (MeshTopology::Part::FacesAndRings)
// are about a third of the peak memory of a deep refinement. But where C's own parent P is a
// closed manifold triangle mesh whose every edge was flipped (no sharp edge, nothing
// trisected: Sqrt3ChildTopology's case), C follows from P's triangles in closed form:
//   - C's points are P's centroids (point f for face f) and P's vertices (F + v);
//   - C's triangles are 2e = (F + a, f2, f1) and 2e + 1 = (F + b, f1, f2) for P's edge e,
//     numbered by its first half-edge, running a->b in its face f1, with f2 across;
//   - the ring of centroid f is the three centroids across f's edges and f's three vertices;
//     the ring of vertex F + v the centroids of v's faces.
// With C closed and smooth as well (no sharp vertex), every point of the next level is a
// centroid of one of C's triangles or a relaxed point of C, and its row is written here from
// P's triangles and three small tables (each half-edge's twin and a corner at each vertex to
// walk its fan from: SubDTriangleFans.h, shared with P's own rows where those read them; each
// edge's first half-edge), in the order Sqrt3's own row writer writes C's rows (rings in
// increasing order: MeshTopology::ForEachRingVertex): the same bits. C is then only split
// (its faces), and freed.
//
// The tables take about 20 bytes per face of P against C's 88 for its faces, face offsets
// and rings (bunny, level 5: 39 MiB instead of 179).
#ifndef SubDSqrt3GrandparentRows_h
#define SubDSqrt3GrandparentRows_h

#include "SubDLevel.h"
#include "SubDStencilTable.h"
#include "SubDTriangleFans.h"

#include <functional>
#include <memory>

namespace subd
{
/// Whether `parent` is the closed, smooth child of `grandparent` in the form above, every one
/// of whose rows has that form: `parent` closed manifold triangles without sharp edges or
/// vertices; its triangles those of `grandparent`'s flipped edges, each edge once, in the
/// order of their first half-edges. Reads `grandparent`'s triangles only (the rest of it may
/// have been freed: MeshTopology::KeepOnly) and `parent`'s triangles, counts and tags (its
/// lists around vertices and its sharpness arrays may have been freed: LeanChild::SplitAlone).
SUBDKERNEL_EXPORT bool Sqrt3RowsFromGrandparentApply(
  const Level& grandparent, const Level& parent, const ParallelFor& parallelFor = SerialFor);

/// The rows of the points of `grandparent`'s grandchild, numbered like its parent's row
/// writer's (MakeSqrt3RowSource of the parent), written as they are applied from
/// `grandparent`'s triangles and fans: `fans` where the grandparent's own rows have them
/// (Sqrt3RowFans), else built here. Requires Sqrt3RowsFromGrandparentApply. Keeps
/// `grandparent`.
SUBDKERNEL_EXPORT std::shared_ptr<const RowSource> MakeSqrt3RowSourceFromGrandparent(std::shared_ptr<const Level> grandparent,
  const ParallelFor& parallelFor = SerialFor, std::shared_ptr<const TriangleFans> fans = nullptr);

/// Whether `rows` were made by MakeSqrt3RowSourceFromGrandparent (to inspect a hierarchy).
SUBDKERNEL_EXPORT bool IsSqrt3RowSourceFromGrandparent(const RowSource* rows);
}

#endif
