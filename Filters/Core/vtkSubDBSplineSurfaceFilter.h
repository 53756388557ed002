/**
 * @class   vtkSubDBSplineSurfaceFilter
 * @brief   bicubic B-spline surfaces through a grid of points, or fitted to scattered points
 *
 * Uniform bicubic B-spline surfaces are what Catmull-Clark subdivision generalises: on a
 * regular quad grid its limit is exactly this surface (Catmull and Clark, 1978). This filter
 * makes one from data, in either of two modes:
 *
 * - MODE_INTERPOLATE_GRID (default): the input is a P x Q grid of points - a vtkStructuredGrid
 *   with one dimension 1, or a vtkPolyData of quads that form a grid (recognised from its
 *   connectivity: any point numbering, any starting corner; SubDQuadGrid.h). The filter
 *   solves for the (P+2) x (Q+2) control net whose surface passes through every grid point at
 *   the knots: one tridiagonal (1, 4, 1)/6 system per row, then per column (de Boor, "A
 *   Practical Guide to Splines", 1978), with natural end conditions (zero second derivative
 *   across the border, which puts the border control points on the border data).
 * - MODE_APPROXIMATE_SCATTERED: the input is any point set whose point data has parameters
 *   (u, v) in [0, 1]^2 (the 2-component array ParameterArrayName, default "UV"; else the
 *   active texture coordinates). The filter finds the least-squares bicubic B-spline with
 *   NumberOfControlPoints[0] x [1] control points (the normal equations, Eigen's sparse LDLT
 *   factorisation). Where the samples leave control points undetermined (a hole in the data)
 *   the system is singular - an error - unless ShapeWeight > 0 adds the "shape equations":
 *   every control quad should be a parallelogram (c00 - c10 - c01 + c11 = 0), weighted by
 *   ShapeWeight against the data (a planar, evenly spaced net satisfies them exactly; larger
 *   weights smooth more). GetRmsError and GetMaxError report the fit.
 *
 * Output 0 is the control net as a quad mesh: a valid Catmull-Clark cage (with the default
 * boundary rule, its limit over the interior quads is this bicubic surface, and the limit
 * points of its interior vertices are the surface at the knots). Output 1 is the surface
 * evaluated SamplesPerSpan times per span and direction, as quads, with unit "Normals" from
 * the exact derivatives. Every numeric point-data array of the input (except the parameters)
 * is interpolated or fitted with the same equations and comes out on both outputs.
 *
 * Bad input (not a grid, a 3-D structured grid, missing or out-of-range parameters, fewer
 * samples than the net needs, non-finite coordinates) is an error naming the problem, with
 * empty outputs.
 *
 * @sa vtkSubDCatmullClarkFilter vtkSubDInterpolateFilter
 */
#ifndef vtkSubDBSplineSurfaceFilter_h
#define vtkSubDBSplineSurfaceFilter_h

#include "SubDFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class SUBDFILTERS_EXPORT vtkSubDBSplineSurfaceFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkSubDBSplineSurfaceFilter* New();
  vtkTypeMacro(vtkSubDBSplineSurfaceFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Modes
  {
    MODE_INTERPOLATE_GRID = 0,
    MODE_APPROXIMATE_SCATTERED = 1
  };

  ///@{
  /// Interpolate a grid (default) or approximate scattered points with parameters.
  vtkSetClampMacro(Mode, int, MODE_INTERPOLATE_GRID, MODE_APPROXIMATE_SCATTERED);
  vtkGetMacro(Mode, int);
  void SetModeToInterpolateGrid() { this->SetMode(MODE_INTERPOLATE_GRID); }
  void SetModeToApproximateScattered() { this->SetMode(MODE_APPROXIMATE_SCATTERED); }
  ///@}

  ///@{
  /// MODE_APPROXIMATE_SCATTERED: the control net's size in u and v (default 8 x 8; each
  /// clamped to 4..4096).
  void SetNumberOfControlPoints(int u, int v);
  void SetNumberOfControlPoints(const int uv[2]) { this->SetNumberOfControlPoints(uv[0], uv[1]); }
  vtkGetVector2Macro(NumberOfControlPoints, int);
  ///@}

  ///@{
  /// MODE_APPROXIMATE_SCATTERED: the point-data array of (u, v) parameters in [0, 1]^2
  /// (default "UV"; without it, the active texture coordinates).
  vtkSetStringMacro(ParameterArrayName);
  vtkGetStringMacro(ParameterArrayName);
  ///@}

  ///@{
  /// MODE_APPROXIMATE_SCATTERED: weight of the shape equations (0 = off, the default;
  /// 0..1e6). Small values (1e-3 .. 1e-1) fill holes in the data and barely change the fit
  /// elsewhere.
  vtkSetClampMacro(ShapeWeight, double, 0.0, 1.0e6);
  vtkGetMacro(ShapeWeight, double);
  ///@}

  ///@{
  /// Evaluated surface (output 1): samples per span and direction (default 8, 1..256).
  vtkSetClampMacro(SamplesPerSpan, int, 1, 256);
  vtkGetMacro(SamplesPerSpan, int);
  ///@}

  /// After an update in MODE_APPROXIMATE_SCATTERED: root mean square and largest distance
  /// from the samples to the surface (0 when interpolating).
  vtkGetMacro(RmsError, double);
  vtkGetMacro(MaxError, double);

  /// Output 0: the control net; output 1: the evaluated surface.
  vtkPolyData* GetControlNet() { return this->GetOutput(0); }
  vtkPolyData* GetSurface() { return this->GetOutput(1); }

protected:
  vtkSubDBSplineSurfaceFilter();
  ~vtkSubDBSplineSurfaceFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  /// The fit couples every point: asked for one piece of several, the filter asks upstream for
  /// the whole input; piece 0 gets the whole result, the other pieces are empty.
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// RequestData's work; RequestData runs it and turns running out of memory into an error.
  int Execute(vtkInformation*, vtkInformationVector**, vtkInformationVector*);

  int Mode = MODE_INTERPOLATE_GRID;
  int NumberOfControlPoints[2] = { 8, 8 };
  char* ParameterArrayName = nullptr;
  double ShapeWeight = 0.0;
  int SamplesPerSpan = 8;
  double RmsError = 0.0;
  double MaxError = 0.0;

private:
  vtkSubDBSplineSurfaceFilter(const vtkSubDBSplineSurfaceFilter&) = delete;
  void operator=(const vtkSubDBSplineSurfaceFilter&) = delete;
};

#endif
