/**
 * @class   vtkSubDCurveFilter
 * @brief   subdivision curves: Chaikin, cubic B-spline and the 4-point scheme
 *
 * vtkSubDCurveFilter refines the Lines of its input (lines and polylines, open or closed)
 * NumberOfSubdivisions times with one of three curve schemes:
 *
 * - SCHEME_CHAIKIN (Chaikin, "An algorithm for high-speed curve generation", 1974): every edge
 *   is cut at 1/4 and 3/4; the polygons converge to the uniform quadratic B-spline of the
 *   control polygon (Riesenfeld 1975). C1, approximating.
 * - SCHEME_CUBIC_BSPLINE (Lane and Riesenfeld, 1980): vertex (1/8, 6/8, 1/8), edge (1/2, 1/2);
 *   the limit is the uniform cubic B-spline. C2, approximating. This is also the rule of
 *   infinitely sharp creases of Catmull-Clark and Loop surfaces.
 * - SCHEME_FOUR_POINT (Dyn, Levin and Gregory, "A 4-point interpolatory subdivision scheme
 *   for curve design", CAGD 4, 1987): points are kept, each edge gains
 *   -w p_{i-1} + (1/2 + w)(p_i + p_{i+1}) - w p_{i+2} with Tension w (default 1/16, which
 *   reproduces cubic polynomials). C1 for 0 < w < 1/8, interpolating.
 *
 * A polyline is closed when its first and last point ids are equal (and it has at least three
 * other points), or when Closed is on. Open curves keep their end points with each scheme's
 * end rule (SubDCurveRules.h): Chaikin's polygon is treated as a quadratic B-spline with clamped
 * end knots (knot insertion keeps the ends and gives (p_0 + p_1)/2 next to them); the cubic
 * B-spline keeps the end point (the boundary-curve rule, i.e. a phantom point 2 p_0 - p_1); the
 * 4-point scheme extrapolates the missing neighbour of an end segment with the cubic through
 * the four end points (quadratic or linear for shorter polygons), so w = 1/16 reproduces
 * cubics up to the ends. A 2-point polyline stays a straight segment.
 *
 * A point whose point-data "CornerSharpness" is 10 or more (OpenSubdiv's "infinitely sharp")
 * is a sharp corner: the curve is cut there, both sides are refined as open curves ending at
 * the corner, and the corner keeps its position. Each input line gives one output polyline
 * (its pieces joined at their corners), with the line's cell data. Points shared by several
 * polylines at their ends stay shared; points shared elsewhere are refined once per polyline.
 *
 * Every point-data array is refined with the same weights as the points (integer arrays
 * rounded and clamped; normals re-normalized). "CornerSharpness" keeps its value on corners
 * and curve ends and is zero on the new points, so running the filter N times with one level
 * equals running it once with N levels.
 *
 * Pieces of a distributed mesh: each line is refined by itself, so a piece needs no ghost
 * cells, and the pieces' outputs together are the serial output. Ghost levels asked of the
 * output are asked of the input: its ghost lines are refined too and keep their cells'
 * "vtkGhostType" marks; points on no own cell are marked DUPLICATEPOINT.
 *
 * Polygons, triangle strips and vertices of the input pass through untouched, with their cell
 * data: a surface with crease lines can go through this filter. The output points are then
 * the input points followed by the curves' points; without such cells, only the curves'
 * points.
 *
 * ProjectToLimit moves the output points (and point data) to the limit curve; ComputeTangents
 * adds unit limit tangents as point data "Tangents" (SubDCurveLimit.h states the masks: the
 * B-spline's own for Chaikin and the cubic B-spline, the subdivision matrix's eigenvector for
 * the 4-point scheme). At a corner the tangent is the normalized mean of both sides.
 *
 * Bad input: no lines gives a warning and the input passed through; NaN or infinite
 * coordinates and out-of-range point ids give an error and an empty output; a polyline of a
 * single point is kept as a vertex cell (with its cell data; VTK refuses one-point lines, and
 * vtkCleanPolyData makes the same change), with a warning; empty line cells are dropped, with a warning.
 * A request whose predicted output exceeds MaximumMemory (MiB) is refused before allocation.
 *
 * @sa vtkSubDSurfaceFilter
 */
#ifndef vtkSubDCurveFilter_h
#define vtkSubDCurveFilter_h

#include "SubDFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <cstdint>    // InterpolatePointData
#include <functional> // Progress
#include <vector>     // WritePoints

namespace subd
{
struct CurveRules;
struct CurvePieces;
struct Hierarchy;
}

class SUBDFILTERS_EXPORT vtkSubDCurveFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkSubDCurveFilter* New();
  vtkTypeMacro(vtkSubDCurveFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Schemes
  {
    SCHEME_CHAIKIN = 0,
    SCHEME_CUBIC_BSPLINE = 1,
    SCHEME_FOUR_POINT = 2
  };

  ///@{
  /**
   * The scheme (default SCHEME_CUBIC_BSPLINE).
   */
  vtkSetClampMacro(Scheme, int, SCHEME_CHAIKIN, SCHEME_FOUR_POINT);
  vtkGetMacro(Scheme, int);
  void SetSchemeToChaikin() { this->SetScheme(SCHEME_CHAIKIN); }
  void SetSchemeToCubicBSpline() { this->SetScheme(SCHEME_CUBIC_BSPLINE); }
  void SetSchemeToFourPoint() { this->SetScheme(SCHEME_FOUR_POINT); }
  const char* GetSchemeAsString();
  ///@}

  ///@{
  /**
   * Number of subdivision levels (default 1; 0 copies the curves, or projects them to the
   * limit with ProjectToLimit).
   */
  vtkSetClampMacro(NumberOfSubdivisions, int, 0, 30);
  vtkGetMacro(NumberOfSubdivisions, int);
  ///@}

  ///@{
  /**
   * The 4-point scheme's tension w, in [0, 1/8] (default 1/16). 0 gives the polygon itself.
   */
  vtkSetClampMacro(Tension, double, 0.0, 0.125);
  vtkGetMacro(Tension, double);
  ///@}

  ///@{
  /**
   * Treat every polyline as closed (its last point joins its first), default off.
   */
  vtkSetMacro(Closed, bool);
  vtkGetMacro(Closed, bool);
  vtkBooleanMacro(Closed, bool);
  ///@}

  ///@{
  /**
   * Move the output points and point data to the limit curve (default off).
   */
  vtkSetMacro(ProjectToLimit, bool);
  vtkGetMacro(ProjectToLimit, bool);
  vtkBooleanMacro(ProjectToLimit, bool);
  ///@}

  ///@{
  /**
   * Add unit tangents of the limit curve as point data "Tangents" (default off).
   */
  vtkSetMacro(ComputeTangents, bool);
  vtkGetMacro(ComputeTangents, bool);
  vtkBooleanMacro(ComputeTangents, bool);
  ///@}

  ///@{
  /**
   * Precision of the output points: DEFAULT_PRECISION (that of the input points),
   * SINGLE_PRECISION or DOUBLE_PRECISION. Computation is always in double.
   */
  vtkSetClampMacro(OutputPointsPrecision, int, SINGLE_PRECISION, DEFAULT_PRECISION);
  vtkGetMacro(OutputPointsPrecision, int);
  ///@}

  ///@{
  /**
   * Refuse requests whose predicted output needs more than this many MiB (default: half the
   * physical memory), with an error naming the estimate, before allocating anything.
   */
  vtkSetClampMacro(MaximumMemory, double, 1.0, 1.0e9);
  vtkGetMacro(MaximumMemory, double);
  ///@}

protected:
  vtkSubDCurveFilter();
  ~vtkSubDCurveFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// RequestData's work; RequestData runs it and turns running out of memory into an error.
  int Execute(vtkInformation*, vtkInformationVector**, vtkInformationVector*);

  int Scheme = SCHEME_CUBIC_BSPLINE;
  int NumberOfSubdivisions = 1;
  double Tension = 1.0 / 16.0;
  bool Closed = false;
  bool ProjectToLimit = false;
  bool ComputeTangents = false;
  int OutputPointsPrecision = DEFAULT_PRECISION;
  double MaximumMemory; // half the physical memory (vtkSubDMemoryBudget.h)

private:
  /// Non-finite points, cells past the points, too many points: an error, false.
  bool CheckInput(vtkPolyData* input);
  /// The size guard: false, with an error, when the output would not fit MaximumMemory.
  bool FitsTheMemoryBudget(double predictedPoints, vtkPolyData* input);
  /// Progress from `first` over `span` of the whole; false asks the work to stop.
  std::function<bool(double)> Progress(double first, double span);
  /// The output points (the input's first, where other cells use them, then the curves',
  /// projected to the limit where asked); returns the curves' points before the projection.
  std::vector<double> WritePoints(vtkPolyData* input, const subd::CurveRules& rules, const subd::CurvePieces& finest,
    subd::Hierarchy& hierarchy, vtkIdType shift, vtkPolyData* output);
  /// Every point-data array with the same stencils; false if aborted.
  bool InterpolatePointData(vtkPolyData* input, const subd::Hierarchy& hierarchy, std::int32_t numAnchors,
    vtkIdType shift, vtkPolyData* output);
  vtkSubDCurveFilter(const vtkSubDCurveFilter&) = delete;
  void operator=(const vtkSubDCurveFilter&) = delete;
};

#endif
