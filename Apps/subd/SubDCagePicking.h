// The explorer's picking of cage elements: given where each cage point lands on the screen,
// which vertex or polygon edge a click means. In SubDAppSupport, apart from the GUI, so that
// tests can call it.
#ifndef SubDCagePicking_h
#define SubDCagePicking_h

#include "vtkType.h"

#include <vector>

class vtkPolyData;

namespace subdapp
{
struct PickedElement
{
  vtkIdType A = -1; ///< a vertex, or an edge's first end; -1: nothing picked
  vtkIdType B = -1; ///< an edge's other end; -1 for a vertex
};

/// `screen` holds the display position (x, y) of each cage point. A vertex within
/// `vertexRadius` pixels of (x, y) wins (the nearest); else the polygon edge nearest to
/// (x, y) within `edgeRadius` pixels of its projected segment; else nothing.
PickedElement PickCageElement(vtkPolyData* cage, const std::vector<double>& screen, double x, double y,
  double vertexRadius = 8.0, double edgeRadius = 6.0);
}

#endif
