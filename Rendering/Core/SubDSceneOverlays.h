// vtkSubDScene's overlays: the control cage (edges, vertices, its creases and corners by
// sharpness), a selected cage element, crease lines and the refined mesh's wireframe.
// Internal to SubD::Rendering.
#ifndef SubDSceneOverlays_h
#define SubDSceneOverlays_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

class vtkActor;
class vtkPolyDataMapper;
class vtkPolyData;
class vtkRenderer;

namespace subdrender
{
/// The points, point data and polygons of a mesh (its lines and vertices left out).
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

/**
 * Draws control cages: the edges of its polygons (or, for a curve's control polygon, its
 * lines) as gold tubes, its vertices as spheres, its crease lines by sharpness
 * (SharpLinesActor) and its corners ("CornerSharpness" > 0) as larger spheres in the same
 * colours. The edges and vertices, the costly part on a large cage, are built once per cage
 * geometry (points and polygons) and size: a sharpness edit rebuilds only the creases. Above
 * LargeCageEdges edges they are drawn as lines and points shaded as tubes and spheres on the
 * GPU, not as geometry.
 */
class CageOverlayCache
{
public:
  static constexpr vtkIdType LargeCageEdges = 4000;
  void AddCage(vtkRenderer* renderer, vtkPolyData* cage, const CageStyle& style);

private:
  struct Key
  {
    vtkSmartPointer<vtkPolyData> Cage; // held, so that its address is not reused
    vtkMTimeType Points = 0, Polys = 0, Lines = 0;
    double Size = 0.0;
    bool operator==(const Key& other) const
    {
      return this->Cage == other.Cage && this->Points == other.Points && this->Polys == other.Polys &&
        this->Lines == other.Lines && this->Size == other.Size;
    }
  };
  Key Built;
  bool Large = false;
  vtkSmartPointer<vtkPolyDataMapper> Edges, Vertices;
};

/// Adds a marker on the cage's edge (a, b), or on its vertex a when b < 0 (the explorer's
/// selection). Ids out of range add nothing.
void AddCageSelection(vtkRenderer* renderer, vtkPolyData* cage, vtkIdType a, vtkIdType b, double size);

/// The edges of the surface's polygons as thin dark lines (drawn over the shaded surface).
vtkSmartPointer<vtkActor> WireframeActor(vtkPolyData* surface);
}

#endif
