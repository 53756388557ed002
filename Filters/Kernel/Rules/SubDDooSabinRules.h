// SubD kernel: Doo-Sabin masks (D. Doo, M. Sabin, "Behaviour of recursive division surfaces
// near extraordinary points", Computer-Aided Design 10(6), 1978).
//
// The new point of corner i of an n-sided face with vertices v_0..v_{n-1} is
//   sum_k alpha_ik v_k,  alpha_ii = (n + 5) / (4n),
//                        alpha_ik = (3 + 2 cos(2 pi (i - k) / n)) / (4n)  (k != i),
// which for quads is 9/16, 3/16, 1/16, 3/16: the knot insertion of the biquadratic B-spline.
//
// Boundary rule (no peer has one): the corner of a face at a boundary vertex v, next to a
// boundary edge (v, w) of that face, gets 3/4 v + 1/4 w, Chaikin's rule, so the refined
// boundary is the Chaikin refinement of the boundary polygon and converges to its uniform
// quadratic B-spline. Corners of the mesh (vertices with a single face) are interpolated,
// and next to one the weights are 1/2, 1/2, so each side of the boundary between corners is
// the clamped (end-interpolating) quadratic B-spline of its polygon. Non-manifold edges are
// treated like boundary edges.
//
// Creases are treated like boundaries (DeRose et al.'s "boundary rule along sharp edges"):
// the corners next to a sharp edge take Chaikin's rule along it, so an infinitely sharp
// crease converges to the uniform quadratic B-spline of its polyline, where it turns around a
// single face too (that face's corner gives a point on each crease edge, SubDDualSplit.h);
// pinned vertices (corner vertices, SubDDualSplit.h: sharp vertices, three or more sharp
// edges) are interpolated. Semi-sharp edges are creases while their sharpness is positive
// and lose one unit per level (no fractional blend: the dual scheme has no edge point to
// blend).
// Rows are numbered like the child points (SubDDualSplit.h) and read parent points only.
#ifndef SubDDooSabinRules_h
#define SubDDooSabinRules_h

#include "SubDDualSplit.h"
#include "SubDLevel.h"
#include "SubDStencilTable.h"

#include <memory>

namespace subd
{
/// alpha_ik for an n-gon, with d = i - k.
SUBDKERNEL_EXPORT double DooSabinWeight(Index n, Index d);
/// The rows of the child points `points` (NumberDualPoints(parent)), written in parallel by
/// `parallelFor` (each row by one task: the same table for any number of threads).
SUBDKERNEL_EXPORT StencilTable BuildDooSabinStencils(
  const Level& parent, const DualPoints& points, const ParallelFor& parallelFor = SerialFor);
/// The same rows written as they are applied (SubDRowWriting.h), with the numbering of
/// `parent` made here by `parallelFor`.
SUBDKERNEL_EXPORT std::shared_ptr<const RowSource> MakeDooSabinRowSource(
  std::shared_ptr<const Level> parent, const ParallelFor& parallelFor = SerialFor);
}

#endif
