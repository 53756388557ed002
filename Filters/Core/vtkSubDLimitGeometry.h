// Private helper of SubD's filters: point-data arrays of the limit surface's differential
// geometry (SubDSurfaceGeometry.h), filled point by point from limit stencils.
//
// Arrays (names as vtkCurvatures uses where it has one): "Normals" (float, unit),
// "Mean_Curvature", "Gauss_Curvature", "Maximum_Curvature", "Minimum_Curvature" (double),
// "Maximum_Curvature_Direction", "Minimum_Curvature_Direction" (float, unit, tangent), and
// with derivatives "dPdu", "dPdv" (double). Curvature is positive where the surface is
// convex seen from the side its faces are counter-clockwise from (a closed surface's outside).
// Where the limit surface has no tangent plane (a non-manifold vertex, degenerate geometry),
// the normal, the curvatures and their directions are 0, never NaN, and the points are
// counted (GetNumberOfUndefinedPoints) for the filter's warning.
#ifndef vtkSubDLimitGeometry_h
#define vtkSubDLimitGeometry_h

#include "SubDLimitEvaluator.h"
#include "SubDSurfaceGeometry.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"

#include <atomic>
#include <string>

class vtkObject;
class vtkPointData;

class vtkSubDLimitGeometry
{
public:
  vtkSubDLimitGeometry(vtkIdType numPoints, bool normals, bool curvature, bool derivatives);

  /// Point i from the values and derivatives `d` (PatchDerivative order) and the frame the
  /// curvature is read in (`c`, see SubDLimitEvaluator.h); returns false where the surface
  /// has no normal there.
  bool Set(vtkIdType i, const double d[6][3], const double c[6][3]);
  /// Point i as the mean of several evaluations (the sides of a crease): unit mean normal,
  /// mean curvature values, the first one's directions and derivatives.
  bool SetMean(vtkIdType i, const std::vector<subd::SurfaceGeometry>& sides, const double d[6][3]);
  /// Point `to` as point `from` (the same place evaluated twice: one value for both).
  void Copy(vtkIdType to, vtkIdType from);

  /// Adds the arrays to `pd` (replacing arrays of the same names; the normals become the
  /// active normals), and gives `filter`'s warning for the undefined points.
  void AddTo(vtkPointData* pd, vtkObject* filter) const;

  /// How many points had no tangent plane (their normal and curvature were set to 0).
  vtkIdType GetNumberOfUndefinedPoints() const { return this->NumUndefined; }

  /// Applies a stencil's rows to xyz points: d = derivatives, c = the curvature frame.
  static void Apply(const subd::LimitStencil& stencil, const double* points, double d[6][3], double c[6][3]);

private:
  vtkNew<vtkFloatArray> Normals, MaximumDirection, MinimumDirection;
  vtkNew<vtkDoubleArray> Mean, Gauss, Maximum, Minimum, Du, Dv;
  bool WithNormals, WithCurvature, WithDerivatives;
  std::atomic<vtkIdType> NumUndefined{ 0 }; // Set and SetMean run on several threads
};

#endif
