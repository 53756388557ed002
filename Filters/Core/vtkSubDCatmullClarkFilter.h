/**
 * @class   vtkSubDCatmullClarkFilter
 * @brief   Catmull-Clark subdivision of polygon meshes of any face sizes
 *
 * Each level splits every n-sided face into n quads and places the new points with the
 * Catmull-Clark rules (E. Catmull and J. Clark, "Recursively generated B-spline surfaces on
 * arbitrary topological meshes", Computer-Aided Design 10(6), 1978):
 *
 * - face point: the centroid of the face;
 * - edge point: (v0 + v1 + f0 + f1) / 4 for an interior edge with face points f0, f1, and
 *   the midpoint (v0 + v1) / 2 on boundary, sharp and non-manifold edges;
 * - vertex point of a vertex v with n faces: (n-2)/n v + (1/n^2) sum e_i + (1/n^2) sum f_i
 *   (e_i the neighbours across the n edges, f_i the new face points); on a boundary or
 *   crease, 3/4 v + 1/8 (a + b) with a, b its neighbours along the crease (the cubic B-spline
 *   curve rule, Hoppe et al., SIGGRAPH 1994); a corner stays where it is.
 *
 * On a regular quad grid the refined net is the knot-inserted net of the uniform bicubic
 * B-spline surface, so the limit surface is that B-spline away from extraordinary vertices.
 * Boundary rules, non-manifold handling and vertex classification follow OpenSubdiv
 * (DeRose, Kass, Truong, "Subdivision Surfaces in Character Animation", SIGGRAPH 1998), and
 * the output matches OpenSubdiv's Far::TopologyRefiner + PrimvarRefiner to round-off.
 *
 * Creases (infinitely sharp and semi-sharp, with the Uniform or Chaikin crease method),
 * darts, corners and holes follow OpenSubdiv's rules exactly, including the transitional
 * blend at the level where a fractional sharpness reaches zero; see vtkSubDSurfaceFilter for
 * how they are given.
 *
 * Everything else (attributes, cell data, errors, progress, stencil caching) is described
 * in vtkSubDSurfaceFilter.
 *
 * A polygon that repeats a point (a quad 4 3 5 5) keeps its corners, as in OpenSubdiv: see
 * vtkSubDSurfaceFilter::SetCollapseRepeatedCorners.
 */
#ifndef vtkSubDCatmullClarkFilter_h
#define vtkSubDCatmullClarkFilter_h

#include "SubDFiltersModule.h" // for export macro
#include "vtkSubDSurfaceFilter.h"

class SUBDFILTERS_EXPORT vtkSubDCatmullClarkFilter : public vtkSubDSurfaceFilter
{
public:
  static vtkSubDCatmullClarkFilter* New();
  vtkTypeMacro(vtkSubDCatmullClarkFilter, vtkSubDSurfaceFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * OpenSubdiv's smooth triangle rule (Sdc::Options::TRI_SUB_SMOOTH; default off): the smooth
   * edge point of an edge of a triangle weighs each face point by the mean of 0.47 for a
   * triangle and 1/4 for another face, its ends by what remains, which rounds the surface
   * over triangles where Catmull-Clark's rule leaves it flat and dimpled. Only the input's
   * triangles are affected (after one level every face is a quad), face-varying data alike.
   */
  vtkSetMacro(SmoothTriangles, bool);
  vtkGetMacro(SmoothTriangles, bool);
  vtkBooleanMacro(SmoothTriangles, bool);
  ///@}

protected:
  vtkSubDCatmullClarkFilter() = default;
  ~vtkSubDCatmullClarkFilter() override = default;

  subd::Scheme* NewScheme(bool allTriangles) override;
  bool KeepsRepeatedCorners() override { return true; }
  bool RefinesFaceVaryingData() override { return true; }

private:
  bool SmoothTriangles = false;

private:
  vtkSubDCatmullClarkFilter(const vtkSubDCatmullClarkFilter&) = delete;
  void operator=(const vtkSubDCatmullClarkFilter&) = delete;
};

#endif
