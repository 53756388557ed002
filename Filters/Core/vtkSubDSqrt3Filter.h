/**
 * @class   vtkSubDSqrt3Filter
 * @brief   Kobbelt's sqrt(3) subdivision of triangle meshes
 *
 * Each step inserts the centroid of every triangle, relaxes every old vertex of valence n to
 * (1 - alpha_n) v + (alpha_n / n) sum v_i with alpha_n = (4 - 2 cos(2 pi / n)) / 9, joins the
 * centroids to the corners and flips every old edge (L. Kobbelt, "sqrt(3)-Subdivision",
 * SIGGRAPH 2000). The face count triples per step (a slower, finer-grained growth than the
 * four-fold split of Loop); two steps refine every edge into three. The limit surface is
 * C2 except at extraordinary vertices (C1).
 *
 * Boundaries follow Kobbelt's rule: every second step the boundary edges are trisected with
 * the masks (1, 16, 10)/27 and (10, 16, 1)/27 and boundary vertices move by (4, 19, 4)/27 (in
 * between they stay), so the boundary converges to the cubic B-spline of the boundary
 * polygon. The parity counts from the filter's input: one filter with N levels is not the
 * same as N chained one-level filters on an open mesh. The output matches CGAL's sqrt(3) to
 * round-off on closed and open meshes, and OpenMesh's on closed ones. Polygons are triangulated first (ear clipping),
 * with a warning. BoundaryRule has no effect.
 *
 * Crease and corner sharpness are not honoured yet (a warning says so; holes are).
 *
 * Attributes, errors, progress and stencil caching: see vtkSubDSurfaceFilter.
 */
#ifndef vtkSubDSqrt3Filter_h
#define vtkSubDSqrt3Filter_h

#include "SubDFiltersModule.h" // for export macro
#include "vtkSubDSurfaceFilter.h"

class SUBDFILTERS_EXPORT vtkSubDSqrt3Filter : public vtkSubDSurfaceFilter
{
public:
  static vtkSubDSqrt3Filter* New();
  vtkTypeMacro(vtkSubDSqrt3Filter, vtkSubDSurfaceFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkSubDSqrt3Filter() = default;
  ~vtkSubDSqrt3Filter() override = default;

  subd::Scheme* NewScheme(bool allTriangles) override;
  bool RequiresTriangles() override { return true; }

private:
  vtkSubDSqrt3Filter(const vtkSubDSqrt3Filter&) = delete;
  void operator=(const vtkSubDSqrt3Filter&) = delete;
};

#endif
