// Private helper of SubD's interpolation filters (surfaces and curves): which points are
// tagged, and the input with the solved points.
#ifndef vtkSubDInterpolationSupport_h
#define vtkSubDInterpolationSupport_h

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkPolyData;

// One flag per input point: the array `name`'s first component is non-zero; every point when
// the input has no such array of one tuple per point (or `name` is null).
std::vector<char> vtkSubDReadInterpolationTags(vtkPolyData* input, const char* name);

// The input (cells, point, cell and field data) with `coordinates` (3 per point) as its
// points, in double precision.
vtkSmartPointer<vtkPolyData> vtkSubDWithSolvedPoints(vtkPolyData* input, const std::vector<double>& coordinates);

// `message` as a sentence: capitalised, with a full stop.
std::string vtkSubDSentence(std::string message);

#endif
