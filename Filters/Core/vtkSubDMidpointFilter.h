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
 * boundary polygon's vertices and edge midpoints (a vertex with a single face becomes a
 * corner of that face's F-face instead of getting a sliver V-face). Non-manifold vertices
 * get no V-face. BoundaryRule has no effect.
 *
 * Creases are treated like boundaries: a vertex with two or more crease edges, or a sharp
 * corner, keeps its point, and its fan of faces is cut into sectors at the crease edges,
 * each with its own V-face; the midpoint of a crease edge is shared by both sides. An
 * infinitely sharp crease therefore keeps its polyline exactly. A corner inside smooth
 * surface becomes a corner of every F-face around it. Semi-sharp edges and corners act as
 * sharp while their sharpness is positive (the halves of an edge decay by the crease
 * method, one unit per level with CREASE_UNIFORM); the scheme has no rule to blend with.
 *
 * Attributes, errors, progress and stencil caching: see vtkSubDSurfaceFilter.
 *
 * A polygon that repeats a point has its repeated corners collapsed first (see
 * vtkSubDSurfaceFilter::SetCollapseRepeatedCorners).
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

  /**
   * Ghost levels a piece needs (vtkSubDSurfaceFilter::GetRequiredGhostLevels): 1 for one
   * level, 2 for 2-3, 3 for 4-5 and 4 beyond. Each level reads 1-rings but scales the mesh by
   * only 1/sqrt(2), so the reach in input cells grows like 1 + 1/sqrt(2) + 1/2 + ... < 3.5;
   * the values through 5 levels were measured (TestPieces), the last bounds the series.
   */
  int GetRequiredGhostLevels() override
  {
    const int levels = this->NumberOfSubdivisions;
    return levels <= 1 ? levels : (levels <= 3 ? 2 : (levels <= 5 ? 3 : 4));
  }

protected:
  vtkSubDMidpointFilter() = default;
  ~vtkSubDMidpointFilter() override = default;

  subd::Scheme* NewScheme(bool allTriangles) override;
  bool MakesFacesFromSeveralFaces() override { return true; }

private:
  vtkSubDMidpointFilter(const vtkSubDMidpointFilter&) = delete;
  void operator=(const vtkSubDMidpointFilter&) = delete;
};

#endif
