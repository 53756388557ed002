// Private helper of vtkSubDLimitFilter: a crack-free triangulation of the limit surface, refined
// where the surface needs it to stay within a tolerance, or to the level each face asks for.
//
// Method. Each face of the cage is one parameter domain (a quad, a Loop triangle, or for a
// Catmull-Clark polygon that is not a quad, the quad at each of its corners, as the limit
// evaluator parametrizes it). A domain is a tree of cells with integer (dyadic) corners: a quad
// cell is cut across u, across v or both, a triangle into four, while
// - adaptive: a cell's chords stray from the limit surface by more than the tolerance,
//   measured along the limit's normal (a side along u: cut across u; likewise v; only the
//   diagonal or the centroids of its two triangles: both ways), or
// - selective: the cell is coarser than the level its face asks for,
// up to a deepest level. Cells are triangulated with every point of a finer neighbour on
// their sides (in the same domain or across a cage edge) as a vertex, the polygon cut corner by
// corner, so that each side of the mesh is made of the same segments from both sides: no cracks
// and no T-junctions. Points at one place (a cage vertex, a point of a cage edge at a dyadic
// parameter, ...) have one key and become one output point (on a seam of the cage's
// face-varying channel, one per side). Adaptive: the triangles of cells with such points are
// then checked at their edge midpoints and centroids, and a cell with a triangle off by more
// than the tolerance is cut again, until every triangle holds (or its cell is at the deepest
// level). The surface is evaluated in one batch per face and level.
#ifndef vtkSubDAdaptiveTessellation_h
#define vtkSubDAdaptiveTessellation_h

#include "vtkSubDCage.h"
#include "vtkSubDLimitSamples.h"

#include <string>
#include <vector>

struct vtkSubDAdaptiveSettings
{
  /// Adaptive: the largest distance (in the cage's units) allowed between a triangle and the
  /// limit surface, measured at its edge midpoints and centroid.
  double Tolerance = 0.0;
  /// Selective (when not empty): the level each face of the cage asks for, 2^level segments
  /// along its edges as a uniform tessellation of that level has.
  std::vector<int> FaceLevels;
  /// The deepest level any face is refined to.
  int MaximumLevel = 10;
  /// The most cells the trees may hold before the request is refused.
  double MaximumCells = 1e8;
};

/// What the refinement left undone: triangles farther than the tolerance whose cell was at the
/// deepest level.
struct vtkSubDAdaptiveResult
{
  long long NumTrianglesOffTolerance = 0;
};

/// Tessellates `faces` of the cage (Catmull-Clark when `quads`, else Loop) into triangles as
/// `settings` ask. False, with the reason, when the evaluator fails or the cells would exceed
/// settings.MaximumCells.
bool vtkSubDTessellateAdaptive(const vtkSubDCage& cage, const subd::LimitEvaluator& evaluator, bool quads,
  const std::vector<subd::Index>& faces, const vtkSubDAdaptiveSettings& settings, vtkSubDLimitSamples& samples,
  vtkSubDAdaptiveResult& result, std::string& error);

#endif
