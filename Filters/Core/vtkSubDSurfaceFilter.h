/**
 * @class   vtkSubDSurfaceFilter
 * @brief   base class of SubD's subdivision surface filters
 *
 * vtkSubDSurfaceFilter does everything a subdivision surface filter needs except choosing
 * the rules: a subclass names its scheme (CreateScheme) and exposes the scheme's own
 * options; this class
 *
 * - reads the input's polygons (any size; triangle strips are split into triangles) straight
 *   from its offsets/connectivity arrays, screens them (faces with fewer than three distinct
 *   corners are dropped with one warning; out-of-range point ids are an error), and for
 *   triangle-only schemes splits larger polygons into triangles by ear clipping, which is
 *   correct for concave polygons too (one warning),
 * - builds the kernel topology, tagging non-manifold edges and vertices, which are then
 *   subdivided as infinitely sharp (OpenSubdiv's behaviour) after one warning,
 * - refines NumberOfSubdivisions levels, or reuses the stencils of the previous execution when
 *   the connectivity and options did not change (only the points are re-evaluated),
 * - applies the stencils, in parallel with vtkSMPTools, to the points and to every point-data
 *   array (integer arrays are rounded and clamped to their type's range, so negative weights
 *   can never wrap a colour; arrays flagged as normals are re-normalized),
 * - gives every output face the cell data of the input cell it comes from, and optionally a
 *   vtkIdTypeArray "ParentCellId" naming that cell,
 * - writes the output faces directly into offsets/connectivity arrays,
 * - reports progress per level and inside long loops, and honours AbortExecute.
 *
 * Bad input never crashes: an empty input, input without polygons, NaN or infinite
 * coordinates and out-of-range point ids each give an error message naming the problem and
 * an empty output. A request whose predicted output exceeds MaximumMemory (MiB) is refused
 * with a message before anything large is allocated.
 *
 * BoundaryRule has OpenSubdiv's meanings (Sdc::Options::VtxBoundaryInterpolation):
 * None (faces at the boundary become holes that shape the surface but are not output),
 * EdgeOnly (default: boundary edges are sharp creases) and EdgeAndCorner (also pins corners,
 * the vertices with a single face).
 *
 * @sa vtkSubDCatmullClarkFilter
 */
#ifndef vtkSubDSurfaceFilter_h
#define vtkSubDSurfaceFilter_h

#include "SubDFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

namespace subd
{
class Scheme;
}

class SUBDFILTERS_EXPORT vtkSubDSurfaceFilter : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkSubDSurfaceFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum BoundaryRules
  {
    BOUNDARY_NONE = 0,
    BOUNDARY_EDGE_ONLY = 1,
    BOUNDARY_EDGE_AND_CORNER = 2
  };

  ///@{
  /**
   * Number of subdivision levels applied (default 1). 0 copies the cleaned input polygons.
   */
  vtkSetClampMacro(NumberOfSubdivisions, int, 0, 30);
  vtkGetMacro(NumberOfSubdivisions, int);
  ///@}

  ///@{
  /**
   * Boundary interpolation (default BOUNDARY_EDGE_ONLY), with OpenSubdiv's meanings.
   */
  vtkSetClampMacro(BoundaryRule, int, BOUNDARY_NONE, BOUNDARY_EDGE_AND_CORNER);
  vtkGetMacro(BoundaryRule, int);
  void SetBoundaryRuleToNone() { this->SetBoundaryRule(BOUNDARY_NONE); }
  void SetBoundaryRuleToEdgeOnly() { this->SetBoundaryRule(BOUNDARY_EDGE_ONLY); }
  void SetBoundaryRuleToEdgeAndCorner() { this->SetBoundaryRule(BOUNDARY_EDGE_AND_CORNER); }
  const char* GetBoundaryRuleAsString();
  ///@}

  ///@{
  /**
   * Precision of the output points: vtkAlgorithm::DEFAULT_PRECISION (that of the input
   * points), SINGLE_PRECISION or DOUBLE_PRECISION. Computation is always in double.
   */
  vtkSetClampMacro(OutputPointsPrecision, int, SINGLE_PRECISION, DEFAULT_PRECISION);
  vtkGetMacro(OutputPointsPrecision, int);
  ///@}

  ///@{
  /**
   * Add a vtkIdTypeArray "ParentCellId" to the output cell data, naming for each output face
   * the input cell it descends from (default off).
   */
  vtkSetMacro(GenerateParentCellIds, bool);
  vtkGetMacro(GenerateParentCellIds, bool);
  vtkBooleanMacro(GenerateParentCellIds, bool);
  ///@}

  ///@{
  /**
   * Refuse requests whose predicted output needs more than this many MiB (default 16384).
   */
  vtkSetClampMacro(MaximumMemory, double, 1.0, 1.0e9);
  vtkGetMacro(MaximumMemory, double);
  ///@}

  /**
   * Number of times the stencils were rebuilt (not reused from the previous execution).
   * Lets applications and tests verify that point-only changes are cheap.
   */
  vtkGetMacro(NumberOfStencilBuilds, int);

protected:
  vtkSubDSurfaceFilter();
  ~vtkSubDSurfaceFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /// The subclass's scheme; called when the stencils must be (re)built. `allTriangles` tells
  /// whether every (screened) input face is a triangle.
  virtual subd::Scheme* NewScheme(bool allTriangles) = 0;

  /// True for schemes defined on triangles only; polygons are then triangulated first (ear
  /// clipping, correct for concave polygons), with one warning, instead of being refused.
  virtual bool RequiresTriangles() { return false; }

  int NumberOfSubdivisions = 1;
  int BoundaryRule = BOUNDARY_EDGE_ONLY;
  int OutputPointsPrecision = DEFAULT_PRECISION;
  bool GenerateParentCellIds = false;
  double MaximumMemory = 16384.0;
  int NumberOfStencilBuilds = 0;

private:
  vtkSubDSurfaceFilter(const vtkSubDSurfaceFilter&) = delete;
  void operator=(const vtkSubDSurfaceFilter&) = delete;

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
