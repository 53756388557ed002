/**
 * @class   vtkSubDInterpolateFilter
 * @brief   a control cage whose Catmull-Clark, Loop or Doo-Sabin limit surface passes through the input's vertices
 *
 * Approximating schemes do not pass through their control points. Given a mesh whose
 * vertices are targets, this filter solves for a new cage with the same topology whose limit
 * surface passes through them: the limit point of each tagged vertex (Catmull-Clark, Loop:
 * the vertex's limit point; Doo-Sabin: the centroid of its V-face, a limit point too) equals
 * the vertex's input position, and untagged vertices keep their positions. Vertices are
 * tagged by the point-data array named InterpolationArrayName (default "Interpolate":
 * non-zero means tagged); without that array every vertex is tagged.
 *
 * Method (SubDInterpolation.h; Halstead, Kass, DeRose, "Efficient, fair interpolation using
 * Catmull-Clark surfaces", SIGGRAPH 1993): each limit point is a sparse linear combination of
 * the cage points, its limit mask; the masks of the tagged vertices and identity rows for the
 * others form a square sparse system M x = t, solved for the three coordinates at once
 * (Solver: Eigen's SparseLU with a COLAMD ordering up to 20000 points - M is not symmetric -,
 * BiCGSTAB with a Jacobi preconditioner above; limit-mask matrices are well conditioned). The
 * masks are the schemes' closed forms, and for Catmull-Clark and Loop the exact limit
 * evaluator of vtkSubDLimitFilter next to semi-sharp creases; for Doo-Sabin a semi-sharp
 * feature counts as sharp. Sharp features are
 * read as vtkSubDSurfaceFilter reads them ("Sharpness", "CornerSharpness", "Hole"), with the
 * same BoundaryRule and CreaseMethod.
 *
 * The condition number is estimated (GetConditionEstimate) and the residual max |M x - t|
 * checked against Tolerance times the targets' extent (GetResidual). A tagged vertex without
 * a limit point (only on holes, a Doo-Sabin dart), a singular system (a closed cube's
 * Catmull-Clark masks are singular, even for targets that happen to be consistent: many cages
 * would do) or one whose residual exceeds the tolerance is an error naming the cause, with an
 * empty output - never a silent wrong or arbitrary cage.
 *
 * The output is the new cage (the input's cells and point, cell and field data with the
 * solved points, in double precision); feed it to the scheme's filter to see the
 * interpolating surface, or set OutputRefinedSurface to get that surface directly
 * (NumberOfSubdivisions levels of the scheme, with the same boundary rule and creases).
 *
 * @sa vtkSubDCatmullClarkFilter vtkSubDLoopFilter vtkSubDDooSabinFilter vtkSubDLimitFilter
 *
 * Polygons that repeat a point are read as the scheme's surface filter reads them: kept by
 * Catmull-Clark and Loop (triangles), collapsed by Doo-Sabin.
 */
#ifndef vtkSubDInterpolateFilter_h
#define vtkSubDInterpolateFilter_h

#include "SubDFiltersModule.h" // for export macro
#include "vtkSubDInterpolationAlgorithm.h"

class SUBDFILTERS_EXPORT vtkSubDInterpolateFilter : public vtkSubDInterpolationAlgorithm
{
public:
  static vtkSubDInterpolateFilter* New();
  vtkTypeMacro(vtkSubDInterpolateFilter, vtkSubDInterpolationAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Schemes
  {
    CATMULL_CLARK = 0,
    LOOP = 1,
    DOO_SABIN = 2
  };

  ///@{
  /// The scheme whose limit surface must pass through the targets (default CATMULL_CLARK).
  vtkSetClampMacro(Scheme, int, CATMULL_CLARK, DOO_SABIN);
  vtkGetMacro(Scheme, int);
  void SetSchemeToCatmullClark() { this->SetScheme(CATMULL_CLARK); }
  void SetSchemeToLoop() { this->SetScheme(LOOP); }
  void SetSchemeToDooSabin() { this->SetScheme(DOO_SABIN); }
  const char* GetSchemeAsString();
  ///@}

  ///@{
  /// As vtkSubDSurfaceFilter: 0 none, 1 edge only (default), 2 edge and corner.
  vtkSetClampMacro(BoundaryRule, int, 0, 2);
  vtkGetMacro(BoundaryRule, int);
  /// As vtkSubDSurfaceFilter: 0 uniform (default), 1 Chaikin.
  vtkSetClampMacro(CreaseMethod, int, 0, 1);
  vtkGetMacro(CreaseMethod, int);
  ///@}

  ///@{
  /// Output the refined interpolating surface (NumberOfSubdivisions levels, default 3,
  /// 1..8) instead of the cage (default off).
  vtkSetMacro(OutputRefinedSurface, bool);
  vtkGetMacro(OutputRefinedSurface, bool);
  vtkBooleanMacro(OutputRefinedSurface, bool);
  vtkSetClampMacro(NumberOfSubdivisions, int, 1, 8);
  vtkGetMacro(NumberOfSubdivisions, int);
  ///@}

protected:
  vtkSubDInterpolateFilter() = default;
  ~vtkSubDInterpolateFilter() override = default;

  int Execute(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Scheme = CATMULL_CLARK;
  int BoundaryRule = 1;
  int CreaseMethod = 0;
  bool OutputRefinedSurface = false;
  int NumberOfSubdivisions = 3;

private:
  vtkSubDInterpolateFilter(const vtkSubDInterpolateFilter&) = delete;
  void operator=(const vtkSubDInterpolateFilter&) = delete;
};

#endif
