// The properties every SubD output has, whatever the scheme and the input: checked by the
// corpus test and the fuzz targets.
#ifndef SubDOutputChecks_h
#define SubDOutputChecks_h

#include "vtkAbstractArray.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <cmath>
#include <sstream>
#include <string>

namespace subdtest
{
/// What is wrong with `out`, or "" when nothing is: every cell names an existing point, every
/// coordinate and attribute value is finite, every array has one tuple per point (cell).
inline std::string OutputProblems(vtkPolyData* out)
{
  std::ostringstream problems;
  const vtkIdType numPoints = out->GetNumberOfPoints();
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    double p[3];
    out->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      problems << "point " << i << " is not finite; ";
      break;
    }
  }
  for (vtkCellArray* cells : { out->GetVerts(), out->GetLines(), out->GetPolys(), out->GetStrips() })
  {
    vtkIdType n;
    const vtkIdType* ids;
    for (cells->InitTraversal(); cells->GetNextCell(n, ids);)
    {
      for (vtkIdType k = 0; k < n; ++k)
      {
        if (ids[k] < 0 || ids[k] >= numPoints)
        {
          problems << "a cell names point " << ids[k] << " of " << numPoints << "; ";
          return problems.str();
        }
      }
    }
  }
  const auto checkArrays = [&](vtkDataSetAttributes* data, vtkIdType tuples, const char* kind) {
    for (int a = 0; a < data->GetNumberOfArrays(); ++a)
    {
      vtkAbstractArray* array = data->GetAbstractArray(a);
      const char* name = array->GetName() ? array->GetName() : "(unnamed)";
      if (array->GetNumberOfTuples() != tuples)
      {
        problems << kind << " array '" << name << "' has " << array->GetNumberOfTuples() << " tuples, not "
                 << tuples << "; ";
        continue;
      }
      vtkDataArray* values = vtkDataArray::SafeDownCast(array);
      for (vtkIdType i = 0; values && i < values->GetNumberOfValues(); ++i)
      {
        if (!std::isfinite(values->GetVariantValue(i).ToDouble()))
        {
          problems << kind << " array '" << name << "' value " << i << " is not finite; ";
          break;
        }
      }
    }
  };
  checkArrays(out->GetPointData(), numPoints, "point-data");
  checkArrays(out->GetCellData(), out->GetNumberOfCells(), "cell-data");
  return problems.str();
}
}

#endif
