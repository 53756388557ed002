/**
 * @class   vtkSubDDooSabinFilter
 * @brief   Doo-Sabin subdivision (corner cutting) of polygon meshes of any face sizes
 *
 * Each level cuts every corner of every face: the point of corner i of an n-sided face is
 * sum_k alpha_ik v_k with alpha_ii = (n+5)/(4n) and alpha_ik = (3 + 2cos(2 pi (i-k)/n))/(4n)
 * (D. Doo and M. Sabin, "Behaviour of recursive division surfaces near extraordinary
 * points", Computer-Aided Design 10(6), 1978). The new faces are an F-face inside each face,
 * a quad E-face across each edge and a V-face around each vertex. On a regular quad mesh the
 * limit surface is the uniform biquadratic B-spline (C1), and the refined net is its
 * knot-inserted net.
 *
 * Open meshes (a boundary rule no peer has): the corners of faces next to a boundary edge
 * (v, w) are cut with Chaikin's 3/4, 1/4 along that edge, so the refined boundary is the
 * Chaikin refinement of the boundary polygon and converges to its quadratic B-spline;
 * vertices with a single face (corners of the mesh) are interpolated and the sides between
 * them follow the clamped quadratic B-spline. CGAL, without a boundary rule, lets the surface
 * shrink back from the boundary instead. Non-manifold edges are treated like boundaries. Point data are carried by the same weights (each output point belongs to
 * one input face corner); cell data: F-faces inherit their face's, E- and V-faces those of an
 * adjacent face. BoundaryRule has no effect.
 *
 * Creases are treated like boundaries: corners next to a sharp edge take Chaikin's rule
 * along it, so an infinitely sharp crease converges to the quadratic B-spline of its
 * polyline; the corner points on both sides of a crease are one point (the surface stays
 * closed); sharp vertices and vertices with three or more creases are interpolated.
 * Semi-sharp edges are creases while their sharpness is positive (one unit less per level;
 * the dual scheme has no edge point to blend, so there is no fractional transition).
 *
 * Attributes, errors, progress and stencil caching: see vtkSubDSurfaceFilter.
 *
 * A polygon that repeats a point has its repeated corners collapsed first (its corner
 * points need distinct corners; see vtkSubDSurfaceFilter::SetCollapseRepeatedCorners).
 */
#ifndef vtkSubDDooSabinFilter_h
#define vtkSubDDooSabinFilter_h

#include "SubDFiltersModule.h" // for export macro
#include "vtkSubDSurfaceFilter.h"

class SUBDFILTERS_EXPORT vtkSubDDooSabinFilter : public vtkSubDSurfaceFilter
{
public:
  static vtkSubDDooSabinFilter* New();
  vtkTypeMacro(vtkSubDDooSabinFilter, vtkSubDSurfaceFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Ghost levels a piece needs (vtkSubDSurfaceFilter::GetRequiredGhostLevels): 2. A corner
   * point reads its whole face, and next to a boundary or crease edge its weights depend on
   * whether the edge's far end is a corner of the mesh (a vertex of one face), which takes
   * that vertex's faces, a second ring; each level halves the reach in input cells. Checked
   * through 5 levels (TestPieces).
   */
  int GetRequiredGhostLevels() override { return this->NumberOfSubdivisions > 0 ? 2 : 0; }

protected:
  vtkSubDDooSabinFilter() = default;
  ~vtkSubDDooSabinFilter() override = default;

  subd::Scheme* NewScheme(bool allTriangles) override;
  bool MakesFacesFromSeveralFaces() override { return true; }

private:
  vtkSubDDooSabinFilter(const vtkSubDDooSabinFilter&) = delete;
  void operator=(const vtkSubDDooSabinFilter&) = delete;
};

#endif
