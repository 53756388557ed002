// subd: control cages built into the program, so it runs with no input file.
#ifndef SubDBuiltinCages_h
#define SubDBuiltinCages_h

#include "vtkPolyData.h" // for vtkSmartPointer<vtkPolyData>
#include "vtkSmartPointer.h"
#include <string>
#include <vector>


namespace subdapp
{
/// Names of the built-in cages; the first is the default.
std::vector<std::string> BuiltinCageNames();
/// Names of the built-in curves (polylines, for the curve schemes); the first is the default.
std::vector<std::string> BuiltinCurveNames();
/// The named cage or curve, or nullptr.
vtkSmartPointer<vtkPolyData> MakeBuiltinCage(const std::string& name);
}

#endif
