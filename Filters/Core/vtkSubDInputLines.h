// Private helper of SubD's curve filters: the line cells of an input vtkPolyData as
// polylines of kernel indices, and its sharp corners.
#ifndef vtkSubDInputLines_h
#define vtkSubDInputLines_h

#include "SubDTypes.h"
#include "vtkType.h"

#include <vector>

class vtkPolyData;

// A closed polyline (first id == last with at least three other points, or every line when
// read with allClosed) lists its points once.
struct vtkSubDInputLines
{
  std::vector<subd::Index> Offsets{ 0 };
  std::vector<subd::Index> Ids;
  std::vector<unsigned char> Closed;
  std::vector<vtkIdType> CellIds; // input cell id of each kept line
  vtkIdType Empty = 0;           // line cells without points (dropped)
  vtkIdType SinglePoint = 0;     // one-point polylines (kept)
  vtkIdType FirstBadCell = -1;   // first line with an out-of-range point id
};

vtkSubDInputLines vtkSubDReadInputLines(vtkPolyData* input, bool allClosed);

// Per point, whether its "CornerSharpness" is infinitely sharp (OpenSubdiv's 10); empty when
// the input has no such array.
std::vector<unsigned char> vtkSubDReadCurveCorners(vtkPolyData* input);

#endif
