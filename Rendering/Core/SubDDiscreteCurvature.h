// vtkSubDScene's discrete curvature of a refined mesh (when it carries no exact limit
// curvature), on flat arrays: several times faster than vtkCurvatures, which matters when the
// explorer redraws a large surface after every crease edit. Internal to SubD::Rendering.
#ifndef SubDDiscreteCurvature_h
#define SubDDiscreteCurvature_h

#include "vtkSmartPointer.h"

#include <vector>

class vtkDoubleArray;
class vtkPolyData;

namespace subdrender
{
/**
 * The triangles of a polygon mesh (each polygon fanned from its first corner), the triangle
 * across each of their edges, and whether each point lies on the boundary (an edge from it
 * with a triangle on one side only, or a non-manifold edge).
 */
struct TriangleAdjacency
{
  std::vector<vtkIdType> Corners; ///< 3 per triangle
  /// Per half edge 3 t + k (corner k to corner k + 1 of triangle t): the triangle with the
  /// opposite half edge, or -1 on the boundary and at non-manifold edges.
  std::vector<vtkIdType> Across;
  std::vector<bool> Boundary; ///< per point

  explicit TriangleAdjacency(vtkPolyData* mesh);
};

/**
 * The discrete curvature `coloring` (vtkSubDScene::Colorings, not COLOR_NONE) at every point
 * of `mesh`, as an array named as vtkCurvatures names it. With A the area of the triangles
 * around a point (a third of it is the point's share):
 * - Gaussian: the angle deficit, K = (2 pi - sum of the angles at the point) / (A / 3);
 * - mean: the dihedral angles b_e of the edges e at the point, H = (sum |e| b_e / 4) / (A / 3),
 *   positive where the surface is convex (its normals diverge);
 * - principal: k1,2 = H +- sqrt(max(0, H^2 - K)).
 * (N. Dyn, K. Hormann, S.-J. Kim, D. Levin, "Optimizing 3D triangulations using discrete
 * curvature analysis", 2001; the same definitions as vtkCurvatures.) Points without area get 0.
 * Boundary values are computed with what is there and mean little.
 */
vtkSmartPointer<vtkDoubleArray> DiscreteCurvature(
  vtkPolyData* mesh, const TriangleAdjacency& adjacency, int coloring);
}

#endif
