// subd and the explorer: editing a cage's sharp features in place, in the form the surface
// filters read (README, "Sharp features"): crease edges are 2-point line cells with float
// cell data "Sharpness", corners point data "CornerSharpness" (OpenSubdiv's scale: 0
// smooth, >= 10 infinitely sharp).
#ifndef SubDCageEditing_h
#define SubDCageEditing_h

#include "vtkType.h"

#include <string>

class vtkPolyData;

namespace subdapp
{
/// Whether (a, b) is an edge of one of the cage's polygons.
bool IsCageEdge(vtkPolyData* cage, vtkIdType a, vtkIdType b);

/// The sharpness of edge (a, b) in the cage's crease lines (0 when no line covers it; a line
/// without a "Sharpness" array is infinitely sharp, 10).
double GetEdgeSharpness(vtkPolyData* cage, vtkIdType a, vtkIdType b);

/// Sets the sharpness of the cage edge (a, b): its crease segment is added, changed, or
/// removed for 0. The cage's lines are rewritten as 2-point segments (each keeping its
/// line's cell data), and every cell gets a "Sharpness" value (0 on the others). Returns
/// false, with the cage untouched and the reason in `error`, when (a, b) is not an edge of
/// one of its polygons or the sharpness is negative or not a number.
bool SetEdgeSharpness(vtkPolyData* cage, vtkIdType a, vtkIdType b, double sharpness, std::string& error);

/// The "CornerSharpness" of vertex v (0 without the array).
double GetVertexSharpness(vtkPolyData* cage, vtkIdType v);

/// Sets the "CornerSharpness" of vertex v (the array is added, zero elsewhere, if missing).
bool SetVertexSharpness(vtkPolyData* cage, vtkIdType v, double sharpness, std::string& error);
}

#endif
