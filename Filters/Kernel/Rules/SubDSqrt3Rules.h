// SubD kernel: Kobbelt's sqrt(3) subdivision (L. Kobbelt, "sqrt(3)-Subdivision", SIGGRAPH
// 2000) on triangle meshes. Each step
//   1. inserts the centroid m = (a + b + c) / 3 of every triangle,
//   2. moves every old vertex v of valence n to (1 - alpha_n) v + (alpha_n / n) sum(v_i),
//      alpha_n = (4 - 2 cos(2 pi / n)) / 9,
//   3. joins each centroid to its triangle's corners and flips every old interior edge, so
//      that the edge (a, b) between triangles T1 (running a->b) and T2 becomes the edge
//      (m1, m2) with the triangles (a, m2, m1) and (b, m1, m2).
// Two steps are a triadic refinement (each edge in three); the face count triples per step.
//
// Boundaries follow Kobbelt's rule, which refines them every second step:
// - odd steps (1st, 3rd, ... from the base level): boundary edges are not flipped (their
//   triangle (a, b, m) stays) and boundary vertices keep their position;
// - even steps: the triangle (a, b, m) of each boundary edge gets no centroid; the edge is
//   trisected instead, with the points (p + 16 a + 10 b) / 27 and (10 a + 16 b + q) / 27
//   (p, q the boundary neighbours before a and after b) joined to m, and boundary vertices
//   move to (4 p + 19 a + 4 b) / 27; every old interior edge is still flipped, a trisected
//   triangle offering the trisection point next to the edge instead of a centroid (the
//   connectivity of Kobbelt's paper and of CGAL).
// Two steps therefore refine the boundary polygon ternarily with the masks of the uniform
// cubic B-spline, so the boundary converges to the cubic B-spline of the boundary polygon.
// Non-manifold edges are treated like boundary edges that are never trisected, and
// non-manifold vertices stay in place.
//
// Creases are treated like boundaries (ActsAsBoundary): a crease edge is never flipped, and
// in even steps it is trisected by the boundary masks (p, q its neighbours along the
// crease), the two trisection points shared by the triangles on both sides; a vertex with
// exactly two crease or boundary edges follows the boundary vertex rule along them, a
// vertex with more (or a sharp vertex) stays in place, and a crease end (a dart) takes the
// smooth rule. A triangle can only trisect one of its edges: an edge whose triangle (on
// either side) already trisects another one waits for the next even step, by which time
// its triangles have a single crease edge each. Semi-sharp edges act as creases while their
// sharpness is positive; each step takes one unit off every crease piece and sharp vertex.
//
// Child points: the centroids (of every face in odd steps, of the faces without a trisected
// edge in even steps), then the old vertices, then two points per trisected edge, the first
// next to the edge's first vertex.
// The parity comes from Level::Depth, so a hierarchy refined in one go is consistent; one
// level at a time from a refined mesh restarts at an odd step.
#ifndef SubDSqrt3Rules_h
#define SubDSqrt3Rules_h

#include "SubDFaceBlocks.h"
#include "SubDLevel.h"
#include "SubDStencilTable.h"

#include <functional>
#include <memory>

namespace subd
{
/// Kobbelt's alpha_n.
SUBDKERNEL_EXPORT double Sqrt3Alpha(Index n);

/// A boundary edge, or a crease between two triangles: refined by the boundary curve rule.
SUBDKERNEL_EXPORT bool IsSqrt3CurveEdge(const Level& level, Index e);

/// The other end of v's curve edge that does not lead to `other`, or v itself when v does
/// not have exactly two curve edges.
SUBDKERNEL_EXPORT Index Sqrt3CurveNeighbour(const Level& level, Index v, Index other);

/// The vertex rule of a vertex in one step.
enum class Sqrt3VertexRule : std::uint8_t
{
  Relax, ///< Kobbelt's smoothing, interior smooth or dart vertices
  Curve, ///< the boundary rule along the two curve edges (even steps)
  Fixed  ///< stays in place
};
/// `creasesInside` false promises that no curve edge lies between two triangles
/// (HasSqrt3InteriorCurveEdge): a vertex off the boundary then has no curve edge, and its
/// edges need not be walked.
SUBDKERNEL_EXPORT Sqrt3VertexRule ClassifySqrt3Vertex(
  const Level& level, Index v, bool evenStep, bool creasesInside = true);
/// Whether some curve edge of `level` is a crease between two triangles (not a boundary).
SUBDKERNEL_EXPORT bool HasSqrt3InteriorCurveEdge(const Level& level, const ParallelFor& parallelFor = SerialFor);

/// The child point of the old vertex 0 in the step from `parent` (old vertex v: this + v).
SUBDKERNEL_EXPORT Index Sqrt3FirstVertexPoint(const Level& parent);

/// One step (split and stencils share the point numbering); every face of `parent` must be a
/// triangle.
SUBDKERNEL_EXPORT LevelRefinement RefineSqrt3(
  const Level& parent, ChildTopology depth, const ParallelFor& parallelFor = SerialFor);
/// The split alone (RefineSqrt3's child).
SUBDKERNEL_EXPORT Level SplitSqrt3(const Level& parent, ChildTopology depth, const ParallelFor& parallelFor = SerialFor);
/// RefineSqrt3's rows written as they are applied (SubDRowWriting.h).
SUBDKERNEL_EXPORT std::shared_ptr<const RowSource> MakeSqrt3RowSource(
  std::shared_ptr<const Level> parent, const ParallelFor& parallelFor = SerialFor);
}

#endif
