// SubD kernel: recognises a quad mesh that is a P x Q grid and numbers its points.
//
// A polydata "grid" carries no dimensions: its structure is in its connectivity. Starting at
// a corner (a vertex of a single quad), the quads are walked across shared edges and every
// vertex gets grid coordinates: the first quad (a, b, c, d) gives a = (0, 0), b = (1, 0),
// c = (1, 1), d = (0, 1) (so the grid keeps the faces' orientation), and the quad across an
// edge (x, y) continues each of the edge's two grid lines one step further. The mesh is a
// grid when this assignment is consistent and covers a full P x Q rectangle exactly once.
#ifndef SubDQuadGrid_h
#define SubDQuadGrid_h

#include "SubDTypes.h"

#include <string>
#include <vector>

namespace subd
{
struct QuadGrid
{
  Index P = 0, Q = 0;
  std::vector<Index> Points; ///< P x Q point ids, (i, j) at i + j P
};

/// Faces given as offsets + point ids over numPoints points. False, with the reason, when
/// they are not all quads of one P x Q grid (P, Q >= 2); points on no face are ignored.
SUBDKERNEL_EXPORT bool FindQuadGrid(Index numPoints, const std::vector<Index>& offsets,
  const std::vector<Index>& ids, QuadGrid& grid, std::string& error);
}

#endif
