// vtkSubDScene's overlays: the control cage (edges, vertices, its creases and corners by
// sharpness), a selected cage element, crease lines and the refined mesh's wireframe.
// Internal to SubD::Rendering.
#ifndef SubDSceneOverlays_h
#define SubDSceneOverlays_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

class vtkActor;
class vtkPolyData;
class vtkRenderer;

namespace subdrender
{
/// The points and polygons of a mesh (its lines and vertices left out).
vtkSmartPointer<vtkPolyData> PolygonsOf(vtkPolyData* mesh);

/// The points of a mesh with its lines only.
vtkSmartPointer<vtkPolyData> LinesOf(vtkPolyData* mesh);

/// Lines drawn as tubes of one colour.
vtkSmartPointer<vtkActor> TubeActor(vtkPolyData* lines, double radius, const double color[3]);

/**
 * The line cells of `mesh` as tubes coloured by their sharpness (cell data "Sharpness" on
 * OpenSubdiv's scale; lines without it are infinitely sharp): from orange for a barely
 * semi-sharp crease to magenta for an infinitely sharp one, on a logarithmic scale so that
 * the common values 1..3 stay apart. Lines of sharpness 0 are left out. Null when none is
 * left.
 */
vtkSmartPointer<vtkActor> SharpLinesActor(vtkPolyData* mesh, double radius);

struct CageStyle
{
  double Size = 1.0;    ///< the scene's diagonal: tube and sphere sizes are fractions of it
  double Opacity = 1.0; ///< of the cage's edges and vertices (its creases stay opaque)
};

/// Adds the cage: the edges of its polygons (or, for a curve's control polygon, its lines) as
/// gold tubes, its vertices as spheres, its crease lines by sharpness (SharpLinesActor) and
/// its corners ("CornerSharpness" > 0) as larger spheres in the same colours.
void AddCage(vtkRenderer* renderer, vtkPolyData* cage, const CageStyle& style);

/// Adds a marker on the cage's edge (a, b), or on its vertex a when b < 0 (the explorer's
/// selection). Ids out of range add nothing.
void AddCageSelection(vtkRenderer* renderer, vtkPolyData* cage, vtkIdType a, vtkIdType b, double size);

/// The edges of the surface's polygons as thin dark lines (drawn over the shaded surface).
vtkSmartPointer<vtkActor> WireframeActor(vtkPolyData* surface);
}

#endif
