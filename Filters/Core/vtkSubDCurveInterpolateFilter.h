/**
 * @class   vtkSubDCurveInterpolateFilter
 * @brief   control polygons whose Chaikin or cubic B-spline limit curves pass through the input's points
 *
 * The curve counterpart of vtkSubDInterpolateFilter. Chaikin's scheme and the cubic B-spline
 * approximate: their limit curves do not pass through the control points. Given polylines
 * whose points are targets, this filter solves for new control polygons (same cells, same
 * point ids) whose limit curves, as vtkSubDCurveFilter refines them, pass through the tagged
 * points; untagged points keep their positions. Points are tagged by the point-data array
 * InterpolationArrayName (default "Interpolate", non-zero means tagged); without it every
 * point is tagged. The 4-point scheme interpolates already: its solve is the identity.
 *
 * The limit point of a control point is a fixed mask over its neighbours (SubDCurveLimit.h):
 * (p_{i-1} + 6 p_i + p_{i+1}) / 8 for Chaikin (the uniform quadratic B-spline where p_i's
 * basis function peaks; clamped-end masks near the ends of open curves), and
 * (p_{i-1} + 4 p_i + p_{i+1}) / 6 for the cubic B-spline; the end points of open curves and
 * sharp corners ("CornerSharpness" >= 10) are kept by every scheme, so their rows are the
 * identity. This is the classical B-spline interpolation system (de Boor, "A Practical Guide
 * to Splines", 1978; for closed curves the cyclic tridiagonal system), here assembled for any
 * set of polylines at once and solved with Eigen's SparseLU (SubDInterpolation.h). The
 * matrices are strictly diagonally dominant, so the solve always succeeds; the residual is
 * still checked and reported.
 *
 * A polyline is closed as vtkSubDCurveFilter decides (first id repeated last, or Closed on).
 * A point used inside two polylines has one limit point per polyline and cannot be tagged
 * (an error naming it); points on no line keep their positions.
 *
 * The output is the input (all cells and point, cell and field data) with the solved points
 * in double precision; with OutputRefinedCurve on, it is vtkSubDCurveFilter's refinement of
 * those polygons (NumberOfSubdivisions levels) instead.
 *
 * @sa vtkSubDCurveFilter vtkSubDInterpolateFilter
 */
#ifndef vtkSubDCurveInterpolateFilter_h
#define vtkSubDCurveInterpolateFilter_h

#include "SubDFiltersModule.h" // for export macro
#include "vtkSubDInterpolationAlgorithm.h"

class SUBDFILTERS_EXPORT vtkSubDCurveInterpolateFilter : public vtkSubDInterpolationAlgorithm
{
public:
  static vtkSubDCurveInterpolateFilter* New();
  vtkTypeMacro(vtkSubDCurveInterpolateFilter, vtkSubDInterpolationAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The curve scheme, vtkSubDCurveFilter's values: 0 Chaikin, 1 cubic B-spline (default),
  /// 2 the 4-point scheme.
  vtkSetClampMacro(Scheme, int, 0, 2);
  vtkGetMacro(Scheme, int);
  void SetSchemeToChaikin() { this->SetScheme(0); }
  void SetSchemeToCubicBSpline() { this->SetScheme(1); }
  void SetSchemeToFourPoint() { this->SetScheme(2); }
  const char* GetSchemeAsString();
  ///@}

  ///@{
  /// The 4-point scheme's tension, for the refined output (default 1/16, 0..1/8).
  vtkSetClampMacro(Tension, double, 0.0, 0.125);
  vtkGetMacro(Tension, double);
  ///@}

  ///@{
  /// Treat every polyline as closed (default off).
  vtkSetMacro(Closed, bool);
  vtkGetMacro(Closed, bool);
  vtkBooleanMacro(Closed, bool);
  ///@}

  ///@{
  /// Output the refined interpolating curves (NumberOfSubdivisions levels of the scheme,
  /// default 4, 1..20) instead of the control polygons (default off).
  vtkSetMacro(OutputRefinedCurve, bool);
  vtkGetMacro(OutputRefinedCurve, bool);
  vtkBooleanMacro(OutputRefinedCurve, bool);
  vtkSetClampMacro(NumberOfSubdivisions, int, 1, 20);
  vtkGetMacro(NumberOfSubdivisions, int);
  ///@}

protected:
  vtkSubDCurveInterpolateFilter() = default;
  ~vtkSubDCurveInterpolateFilter() override = default;

  int Execute(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Scheme = 1;
  double Tension = 1.0 / 16.0;
  bool Closed = false;
  bool OutputRefinedCurve = false;
  int NumberOfSubdivisions = 4;

private:
  vtkSubDCurveInterpolateFilter(const vtkSubDCurveInterpolateFilter&) = delete;
  void operator=(const vtkSubDCurveInterpolateFilter&) = delete;
};

#endif
