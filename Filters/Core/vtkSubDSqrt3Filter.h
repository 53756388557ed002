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
 * polygon. The parity counts from the level the input was made at: the output records its
 * depth in the field data array "SubDDepth" (one integer), and an input carrying it
 * continues from there, so N chained one-level filters equal one N-level filter. The
 * output matches CGAL's sqrt(3) to round-off on closed and open meshes, and OpenMesh's on
 * closed ones. Polygons are triangulated first (ear clipping), with a warning.
 * BoundaryRule has no effect.
 *
 * Creases are treated like boundaries: crease edges are never flipped, every second step
 * they are trisected by the boundary masks (both sides sharing the trisection points), a
 * vertex on a crease moves by the boundary vertex rule along it, and corners (sharp
 * vertices, three or more crease edges) stay put: an infinitely sharp crease converges to
 * the cubic B-spline of its polyline. A triangle trisects only one edge per step; a second
 * crease edge of the same triangle waits for the next trisecting step. Semi-sharp edges and
 * corners act as sharp while their sharpness is positive, losing one unit per step.
 *
 * Attributes, errors, progress and stencil caching: see vtkSubDSurfaceFilter.
 *
 * A polygon that repeats a point has its repeated corners collapsed first (see
 * vtkSubDSurfaceFilter::SetCollapseRepeatedCorners).
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

  /**
   * Ghost levels a piece needs (vtkSubDSurfaceFilter::GetRequiredGhostLevels): 1 for one
   * level, 2 for two, 3 for 3-5 and 4 beyond. A level reads 1-rings (creases: two edges along
   * the crease), and each level scales the mesh by 1/sqrt(3), so the reach in input cells
   * is bounded by a geometric series; the values through 5 levels were measured (TestPieces,
   * where creases need the third layer), the last bounds the series.
   */
  int GetRequiredGhostLevels() override
  {
    const int levels = this->NumberOfSubdivisions;
    return levels <= 2 ? levels : (levels <= 5 ? 3 : 4);
  }

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
