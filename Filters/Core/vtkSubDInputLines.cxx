#include "vtkSubDInputLines.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

vtkSubDInputLines vtkSubDReadInputLines(vtkPolyData* input, bool allClosed)
{
  vtkSubDInputLines lines;
  const vtkIdType numPoints = input->GetNumberOfPoints();
  const vtkIdType firstLineCell = input->GetNumberOfVerts();
  auto it = vtk::TakeSmartPointer(input->GetLines()->NewIterator());
  vtkIdType index = 0;
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++index)
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    if (n == 0)
    {
      ++lines.Empty;
      continue;
    }
    for (vtkIdType k = 0; k < n; ++k)
    {
      if (ids[k] < 0 || ids[k] >= numPoints)
      {
        lines.FirstBadCell = firstLineCell + index;
        return lines;
      }
    }
    bool closed = allClosed;
    if (n >= 4 && ids[0] == ids[n - 1])
    {
      closed = true;
      --n; // the repeated point is listed once
    }
    lines.SinglePoint += n == 1 ? 1 : 0;
    lines.Ids.insert(lines.Ids.end(), ids, ids + n);
    lines.Offsets.push_back(static_cast<subd::Index>(lines.Ids.size()));
    lines.Closed.push_back(closed ? 1 : 0);
    lines.CellIds.push_back(firstLineCell + index);
  }
  return lines;
}

std::vector<unsigned char> vtkSubDReadCurveCorners(vtkPolyData* input)
{
  std::vector<unsigned char> corners;
  vtkDataArray* sharpness = input->GetPointData()->GetArray("CornerSharpness");
  if (!sharpness || sharpness->GetNumberOfTuples() != input->GetNumberOfPoints())
  {
    return corners;
  }
  corners.resize(static_cast<size_t>(input->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    corners[i] = sharpness->GetComponent(i, 0) >= 10.0 ? 1 : 0;
  }
  return corners;
}
