/**
 * @class   vtkSubDButterflyFilter
 * @brief   modified butterfly subdivision (interpolating) of triangle meshes, with tension
 *
 * An interpolating scheme: the input points stay where they are and every edge gets a new
 * point (D. Zorin, P. Schroeder, W. Sweldens, "Interpolating Subdivision for Meshes with
 * Arbitrary Topology", SIGGRAPH 1996; N. Dyn, D. Levin, J. Gregory, "A butterfly
 * subdivision scheme for surface interpolation with tension control", ACM TOG 9(2), 1990):
 *
 * - between regular vertices (valence 6), the 10-point stencil with tension w: 1/2 - w on the
 *   edge ends, 1/8 + 2w on the two opposite vertices, -1/16 - w on the four wings, w on the
 *   two tips straight across from the edge. w = 0 (default) is the 8-point butterfly of VTK
 *   and OpenMesh; small positive w gives a tighter surface.
 * - next to an extraordinary interior vertex of valence K: 3/4 on it and
 *   s_j = (1/4 + cos(2 pi j/K) + 1/2 cos(4 pi j/K))/K on its neighbours (K = 3: 5/12,
 *   -1/12, -1/12; K = 4: 3/8, 0, -1/8, 0), averaged when both ends are extraordinary;
 * - on the boundary, the 4-point rule -1/16, 9/16, 9/16, -1/16, so boundaries interpolate
 *   their polygon; near a boundary, missing wings are replaced by their parallelogram
 *   reflection (as OpenMesh does). Non-manifold edges get their midpoint.
 *
 * The limit surface is C1 (for small |w|). It matches OpenMesh's ModifiedButterflyT for
 * w = 0 to round-off. Polygons are triangulated first (ear clipping), with a warning.
 * BoundaryRule has no effect.
 *
 * Creases are treated like boundaries: a sharp edge takes the 4-point rule along its
 * crease, vertices on a crease (two or more sharp edges) take the boundary vertex's place in
 * their neighbours' butterflies, and wings across a crease are reflected. A semi-sharp edge
 * of sharpness s < 1 blends s of the crease rule with 1 - s of the smooth one; sharpness
 * decays one unit per level. Vertices never move (the scheme interpolates), so corner
 * sharpness has nothing to change.
 *
 * Attributes, crease input/output, errors, progress and stencil caching: see
 * vtkSubDSurfaceFilter.
 *
 * Face-varying data (texture coordinates split at seams, see vtkSubDSurfaceFilter's
 * WeldCoincidentPoints): the surface is refined whole; each UV island is refined by the same
 * rules, its seams acting as its boundaries (4-point rule), so values inside an island are
 * interpolated as positions are, and a linear map on a flat island stays linear.
 *
 * A polygon that repeats a point has its repeated corners collapsed first (its stencils
 * need distinct corners; see vtkSubDSurfaceFilter::SetCollapseRepeatedCorners).
 */
#ifndef vtkSubDButterflyFilter_h
#define vtkSubDButterflyFilter_h

#include "SubDFiltersModule.h" // for export macro
#include "vtkSubDSurfaceFilter.h"

class SUBDFILTERS_EXPORT vtkSubDButterflyFilter : public vtkSubDSurfaceFilter
{
public:
  static vtkSubDButterflyFilter* New();
  vtkTypeMacro(vtkSubDButterflyFilter, vtkSubDSurfaceFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Ghost levels a piece needs (vtkSubDSurfaceFilter::GetRequiredGhostLevels): 1 for one
   * level; 2 for more, since an edge point reads the butterfly's wings two rings out, which
   * at the next level lie in cells that touch the piece only through other ghost cells. Each
   * level halves the reach in cells of the input, so 2 is enough for any number of levels
   * (checked by TestPieces and the MPI tests).
   */
  int GetRequiredGhostLevels() override { return this->NumberOfSubdivisions > 1 ? 2 : this->NumberOfSubdivisions; }

  ///@{
  /**
   * Tension w of the regular 10-point stencil (default 0, the 8-point butterfly), clamped to
   * [-0.0625, 0.0625]; the scheme is C1 for small |w|.
   */
  vtkSetClampMacro(Tension, double, -0.0625, 0.0625);
  vtkGetMacro(Tension, double);
  ///@}

protected:
  vtkSubDButterflyFilter() = default;
  ~vtkSubDButterflyFilter() override = default;

  subd::Scheme* NewScheme(bool allTriangles) override;
  bool RequiresTriangles() override { return true; }
  bool RefinesFaceVaryingData() override { return true; }

  double Tension = 0.0;

private:
  vtkSubDButterflyFilter(const vtkSubDButterflyFilter&) = delete;
  void operator=(const vtkSubDButterflyFilter&) = delete;
};

#endif
