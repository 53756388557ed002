// vtkSubDScene's colouring: which curvature array a colouring reads, the range its colours
// span, and the colour maps. Internal to SubD::Rendering.
#ifndef SubDSceneColoring_h
#define SubDSceneColoring_h

#include "vtkSmartPointer.h"

#include <array>
#include <vector>

class vtkDataArray;
class vtkLookupTable;
class vtkPolyData;

namespace subdrender
{
/// The point-data array holding a colouring's curvature, as SubD's filters (ComputeCurvature)
/// and vtkCurvatures both name it; nullptr for COLOR_NONE.
const char* CurvatureArrayName(int coloring);

/// Appends the finite values of `curvature` at the points not on the boundary (`boundary`,
/// per point): discrete curvature is meaningless there (the angle deficit at a boundary point
/// is about pi), and the exact one should not dominate the range either.
void AppendInteriorValues(const std::vector<bool>& boundary, vtkDataArray* curvature, std::vector<double>& values);

/**
 * The range colours span for `values` (which are reordered):
 * - symmetric: [-m, m] with m the `percentile`-th percentile of |value| (zero in the middle of
 *   a diverging map, so convex and saddle regions read at a glance);
 * - percentile-clipped: the central `percentile` percent of the values, [lo, hi].
 * Percentiles, not extremes, so that the spikes curvature has at corners and creases do not
 * wash out the picture. A degenerate range becomes [-1, 1] (or [v - 1, v + 1]).
 */
std::array<double, 2> ColorRange(std::vector<double>& values, bool symmetric, double percentile);

/// A 256-entry table of colour map `map` (vtkSubDScene::ColorMaps) over [lo, hi].
vtkSmartPointer<vtkLookupTable> MakeColorTable(int map, double lo, double hi);
}

#endif
