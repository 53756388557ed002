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
 * The polygons of a mesh, the polygon across each of their edges, and whether each point lies
 * on the boundary (an edge from it with a polygon on one side only, or a non-manifold edge).
 */
struct PolygonAdjacency
{
  std::vector<vtkIdType> Offsets; ///< polygon f's corners: [Offsets[f], Offsets[f + 1])
  std::vector<vtkIdType> Corners; ///< point ids
  /// Per corner c (the edge from c to the next corner of its polygon): the polygon with the
  /// opposite edge, or -1 on the boundary and at non-manifold edges.
  std::vector<vtkIdType> Across;
  std::vector<bool> Boundary; ///< per point

  explicit PolygonAdjacency(vtkPolyData* mesh);
  vtkIdType GetNumberOfPolygons() const { return static_cast<vtkIdType>(Offsets.size()) - 1; }
  /// The corner after c in its polygon f.
  vtkIdType Next(vtkIdType f, vtkIdType c) const { return c + 1 < Offsets[f + 1] ? c + 1 : Offsets[f]; }
};

/**
 * The discrete curvature `coloring` (vtkSubDScene::Colorings, not COLOR_NONE) at every point
 * of `mesh`, as an array named as vtkCurvatures names it, on its polygons as they are (no
 * triangulation, whose diagonals would add a chequered pattern to a quad mesh). A polygon's
 * normal and area are Newell's; a point's share of the area around it is, per polygon, the
 * polygon's area over its number of corners (A / 3 for triangles):
 * - Gaussian: the angle deficit, K = (2 pi - sum of the corner angles at the point) / share;
 * - mean: the dihedral angles b_e of the edges e at the point, H = (sum |e| b_e / 4) / share,
 *   positive where the surface is convex (its normals diverge);
 * - principal: k1,2 = H +- sqrt(max(0, H^2 - K)).
 * (N. Dyn, K. Hormann, S.-J. Kim, D. Levin, "Optimizing 3D triangulations using discrete
 * curvature analysis", 2001; on triangles, the definitions of vtkCurvatures.) Points without area get 0.
 * Boundary values are computed with what is there and mean little.
 */
vtkSmartPointer<vtkDoubleArray> DiscreteCurvature(
  vtkPolyData* mesh, const PolygonAdjacency& adjacency, int coloring);
}

#endif
