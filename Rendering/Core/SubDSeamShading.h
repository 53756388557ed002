// SubD's scene: shading a surface split at texture seams as the one surface it is.
//
// A surface with face-varying data (texture coordinates) comes split at its seams: a point
// per side, at one position. Normals and discrete curvature computed on it as it is would see
// each seam as a boundary and draw a crease of light along it. These helpers weld the split
// for the computation and split the result again.
#ifndef SubDSeamShading_h
#define SubDSeamShading_h

#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <vector>

namespace subdrender
{
/// Per point of `mesh`, the first point at exactly its position; empty when no two coincide.
std::vector<vtkIdType> FirstPointAtSamePosition(vtkPolyData* mesh);

/// `mesh`'s points and point data with its polygons naming `weldOf[p]` for every point p.
vtkSmartPointer<vtkPolyData> WeldedPolygons(vtkPolyData* mesh, const std::vector<vtkIdType>& weldOf);

/// `split`'s polygons, as split as both `split` and `shaded` are (`shaded`: the same polygons
/// in the same order, with normals, split at sharp edges by vtkPolyDataNormals): a point per
/// distinct pair of their corner points, with `split`'s point data and `shaded`'s normals.
vtkSmartPointer<vtkPolyData> SplitAsBoth(vtkPolyData* split, vtkPolyData* shaded);
}

#endif
