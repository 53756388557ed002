// SubD kernel: the basis functions of the regular patches (SubDRegularPatch.h) and their
// first and second derivatives.
//
// - Uniform bicubic B-spline: the tensor product of the cubic B-spline segment
//   (1-t)^3/6, (3t^3 - 6t^2 + 4)/6, (-3t^3 + 3t^2 + 3t + 1)/6, t^3/6.
// - Quartic three-direction box spline (Loop's regular patch): its 12 basis functions are
//   quartic polynomials on the triangle. They are not typed in from a table: they are
//   derived once from Loop's own rules, by refining the regular 12-point patch twice and
//   taking the limit points (Loop's limit mask) at the 15 points of parameters (i/4, j/4),
//   which determine a quartic; the quartic is kept in Bernstein form.
#ifndef SubDPatchBasis_h
#define SubDPatchBasis_h

#include "SubDRegularPatch.h"

namespace subd
{
/// The derivatives a patch basis evaluates, in this order.
enum PatchDerivative
{
  PatchValue = 0,
  PatchDu,
  PatchDv,
  PatchDuu,
  PatchDuv,
  PatchDvv,
  NumPatchDerivatives
};

/// weights[d][i]: derivative d of basis function i (16 for BSpline, 12 for BoxSpline) at (u, v).
SUBDKERNEL_EXPORT void EvaluatePatchBasis(PatchKind kind, double u, double v, double weights[NumPatchDerivatives][16]);
}

#endif
