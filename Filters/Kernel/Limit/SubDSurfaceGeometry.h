// SubD kernel: normal and curvature of a parametric surface from its first and second
// derivatives (do Carmo, "Differential Geometry of Curves and Surfaces", 3.3): with
// E, F, G the first fundamental form of Du, Dv, the unit normal n = Du x Dv / |Du x Dv|,
// and L, M, N = Duu.n, Duv.n, Dvv.n the second,
//   K = (L N - M^2) / (E G - F^2),   H = -(E N - 2 F M + G L) / (2 (E G - F^2)),
//   k1,2 = H +- sqrt(H^2 - K),
// the principal directions the eigenvectors of the shape operator. The sign convention
// makes a sphere whose faces are ordered counter-clockwise seen from outside have
// H = 1/r, k1 = k2 = 1/r (convex is positive).
#ifndef SubDSurfaceGeometry_h
#define SubDSurfaceGeometry_h

#include "SubDTypes.h"

namespace subd
{
struct SurfaceGeometry
{
  double Normal[3] = { 0, 0, 0 };
  double Mean = 0, Gaussian = 0;
  double Maximum = 0, Minimum = 0;                 ///< k1 >= k2
  double MaximumDirection[3] = { 0, 0, 0 };        ///< unit, tangent
  double MinimumDirection[3] = { 0, 0, 0 };
  bool Regular = false; ///< false where Du x Dv vanishes (no normal, no curvature)
};

/// `d` holds the value and derivatives in PatchDerivative order (SubDPatchBasis.h), xyz each.
/// `curvature` (may be the same as d) gives the second derivatives the curvature is read from
/// with their own first derivatives (at an extraordinary vertex: the nearby point's).
SUBDKERNEL_EXPORT SurfaceGeometry ComputeSurfaceGeometry(const double d[6][3], const double curvature[6][3]);
}

#endif
