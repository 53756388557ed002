/**
 * @class   vtkSubDLoopFilter
 * @brief   Loop subdivision of triangle meshes
 *
 * Each level splits every triangle into four and places the points with Loop's rules
 * (C. Loop, "Smooth Subdivision Surfaces Based on Triangles", M.S. thesis, University of
 * Utah, 1987):
 *
 * - edge point: 3/8 (v0 + v1) + 1/8 (a + b) for an interior edge, a and b the vertices
 *   opposite it; the midpoint on boundary, sharp and non-manifold edges;
 * - vertex point of a vertex with n neighbours v_i: (1 - n beta) v + beta sum v_i with
 *   beta = (1/n)(5/8 - (3/8 + 1/4 cos(2 pi/n))^2) (1/16 for the regular valence 6); on a
 *   boundary or crease 3/4 v + 1/8 (a + b) (Hoppe et al., SIGGRAPH 1994); corners stay.
 *
 * On a regular triangulation the limit surface is the quartic box spline. Boundary rules,
 * non-manifold handling and vertex classification follow OpenSubdiv, and the output matches
 * OpenSubdiv's Far with Sdc::SCHEME_LOOP to round-off. Unlike VTK's vtkLoopSubdivisionFilter
 * and OpenSubdiv, polygons with more than three corners are accepted: they are split into
 * triangles first (ear clipping, correct for concave polygons), with a warning.
 *
 * Creases, corners, holes, semi-sharp (fractional) sharpness and both crease methods follow
 * OpenSubdiv exactly (see vtkSubDSurfaceFilter): the output matches OpenSubdiv's Loop to
 * round-off with the same tags.
 *
 * Attributes, cell data, errors, progress and stencil caching: see vtkSubDSurfaceFilter.
 *
 * A triangle that repeats a point (a b b) is kept as OpenSubdiv keeps it, larger polygons
 * that do are collapsed before they are triangulated (see
 * vtkSubDSurfaceFilter::SetCollapseRepeatedCorners).
 */
#ifndef vtkSubDLoopFilter_h
#define vtkSubDLoopFilter_h

#include "SubDFiltersModule.h" // for export macro
#include "vtkSubDSurfaceFilter.h"

class SUBDFILTERS_EXPORT vtkSubDLoopFilter : public vtkSubDSurfaceFilter
{
public:
  static vtkSubDLoopFilter* New();
  vtkTypeMacro(vtkSubDLoopFilter, vtkSubDSurfaceFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkSubDLoopFilter() = default;
  ~vtkSubDLoopFilter() override = default;

  subd::Scheme* NewScheme(bool allTriangles) override;
  bool RequiresTriangles() override { return true; }
  bool KeepsRepeatedCorners() override { return true; }
  bool RefinesFaceVaryingData() override { return true; }

private:
  vtkSubDLoopFilter(const vtkSubDLoopFilter&) = delete;
  void operator=(const vtkSubDLoopFilter&) = delete;
};

#endif
