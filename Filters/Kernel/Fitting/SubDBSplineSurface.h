// SubD kernel: uniform bicubic B-spline surfaces - the tensor-product surfaces that
// Catmull-Clark subdivision generalises (on a regular quad grid, Catmull-Clark's limit is
// exactly this surface; Catmull and Clark 1978).
//
// A net of D x E control points c_{i,j} (point (i, j) at index i + j D) defines the surface
//     S(s, t) = sum_{m,n=0..3} B_m(s - k) B_n(t - l) c_{k+m, l+n},  k = floor(s), l = floor(t),
// over s in [0, D - 3], t in [0, E - 3], with the uniform cubic B-spline basis
//     B_0 = (1 - x)^3 / 6,  B_1 = (3x^3 - 6x^2 + 4) / 6,  B_2 = (-3x^3 + 3x^2 + 3x + 1) / 6,  B_3 = x^3 / 6
// (the regular Catmull-Clark patch's basis, SubDPatchBasis.h, which evaluates it).
// At integer parameters (the knots) a span's point is (c_{k} + 4 c_{k+1} + c_{k+2}) / 6 per
// direction, the regular Catmull-Clark limit mask.
//
// Every function handles `components` values per point (coordinates, then any point data):
// the systems are linear, so all of them share one matrix.
#ifndef SubDBSplineSurface_h
#define SubDBSplineSurface_h

#include "SubDTypes.h"

#include <string>
#include <vector>

namespace subd
{
/// The control net (P+2) x (Q+2) of the bicubic B-spline that interpolates a P x Q grid of
/// points (data (i, j) at index i + j P) at its knots: S(i, j) = data(i, j). The end
/// conditions are natural (zero second derivative across the border: c_0 - 2 c_1 + c_2 = 0),
/// which makes the border control points equal the border data; each row, then each
/// column, is a tridiagonal system (1, 4, 1) / 6 solved by elimination (strictly diagonally
/// dominant: no pivoting needed, always solvable). P, Q >= 2.
SUBDKERNEL_EXPORT void InterpolateGrid(
  Index P, Index Q, const std::vector<double>& data, int components, std::vector<double>& net);

/// The surface of a D x E net at (s, t), s in [0, D-3], t in [0, E-3]: `value` gets the
/// components; `ds` and `dt` (may be null) the derivatives.
SUBDKERNEL_EXPORT void EvaluateBicubic(const std::vector<double>& net, Index D, Index E, int components, double s,
  double t, double* value, double* ds = nullptr, double* dt = nullptr);

struct BSplineFitReport
{
  double RmsError = 0;      ///< root mean square distance between the samples and the surface
  double MaxError = 0;      ///< the largest one
  Index NumEmptySpans = 0;  ///< spans (of (D-3) x (E-3)) without samples
};

/// Least-squares bicubic B-spline with a D x E net (D, E >= 4) through scattered samples with
/// parameters (u, v) in [0, 1]^2 (s = u (D-3), t = v (E-3)): minimises
///     sum_samples |S(u, v) - value|^2 + shapeWeight^2 sum_quads |c00 - c10 - c01 + c11|^2,
/// the second term (the "shape equations") asking every control quad to be a parallelogram,
/// so that control points no sample reaches (holes in the data) are still determined. The
/// normal equations are sparse, symmetric positive (semi-)definite: Eigen's SimplicialLDLT.
/// Returns false with the reason when the system is singular (samples do not determine the
/// net and the shape equations are off) or a parameter is outside [0, 1].
SUBDKERNEL_EXPORT bool FitBicubic(Index D, Index E, const std::vector<double>& uv, const std::vector<double>& values,
  int components, double shapeWeight, std::vector<double>& net, BSplineFitReport& report, std::string& error);
}

#endif
