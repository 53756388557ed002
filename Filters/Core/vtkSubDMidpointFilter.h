/**
 * @class   vtkSubDMidpointFilter
 * @brief   Peters-Reif midpoint ("simplest") subdivision of polygon meshes
 *
 * Each level cuts every vertex off: the new points are the edge midpoints; every face
 * becomes the polygon of its edge midpoints (an F-face), and every vertex is replaced by the
 * polygon of the midpoints of its edges (a V-face). The limit surface is C1; on regular
 * quad meshes it is the four-direction quadratic box spline (Zwart-Powell element)
 * (J. Peters and U. Reif, "The simplest subdivision scheme for smoothing polyhedra", ACM
 * Transactions on Graphics 16(4), 1997). Output faces are quads around regular vertices and n-gons elsewhere.
 *
 * Boundaries are kept: a boundary vertex keeps its own point and its V-face runs from it
 * through the midpoints of its edges, so the refined boundary passes through the original
 * boundary polygon's vertices and edge midpoints. Non-manifold vertices get no V-face.
 * BoundaryRule has no effect.
 *
 * Crease and corner sharpness are not honoured yet (a warning says so; holes are).
 *
 * Attributes, errors, progress and stencil caching: see vtkSubDSurfaceFilter.
 */
#ifndef vtkSubDMidpointFilter_h
#define vtkSubDMidpointFilter_h

#include "SubDFiltersModule.h" // for export macro
#include "vtkSubDSurfaceFilter.h"

class SUBDFILTERS_EXPORT vtkSubDMidpointFilter : public vtkSubDSurfaceFilter
{
public:
  static vtkSubDMidpointFilter* New();
  vtkTypeMacro(vtkSubDMidpointFilter, vtkSubDSurfaceFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkSubDMidpointFilter() = default;
  ~vtkSubDMidpointFilter() override = default;

  subd::Scheme* NewScheme(bool allTriangles) override;

private:
  vtkSubDMidpointFilter(const vtkSubDMidpointFilter&) = delete;
  void operator=(const vtkSubDMidpointFilter&) = delete;
};

#endif
