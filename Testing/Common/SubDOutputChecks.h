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
/// Whether `data` holds an array named `name` with a value that is not finite.
inline bool HasNonFiniteValues(vtkDataSetAttributes* data, const char* name)
{
  vtkDataArray* values = data && name ? data->GetArray(name) : nullptr;
  for (vtkIdType i = 0; values && i < values->GetNumberOfValues(); ++i)
  {
    if (!std::isfinite(values->GetVariantValue(i).ToDouble()))
    {
      return true;
    }
  }
  return false;
}

/// What is wrong with `out`, or "" when nothing is: every cell names an existing point, every
/// coordinate is finite, every array has one tuple per point (cell), and every attribute value
/// is finite unless the input's array of that name already held a NaN or infinity (users'
/// arrays may mark missing values so; the filters carry them, they do not make them).
inline std::string OutputProblems(vtkPolyData* out, vtkPolyData* input = nullptr)
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
  const auto checkArrays = [&](vtkDataSetAttributes* data, vtkDataSetAttributes* inputData, vtkIdType tuples,
                              const char* kind) {
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
      vtkDataArray* values =
        HasNonFiniteValues(inputData, array->GetName()) ? nullptr : vtkDataArray::SafeDownCast(array);
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
  checkArrays(out->GetPointData(), input ? input->GetPointData() : nullptr, numPoints, "point-data");
  checkArrays(out->GetCellData(), input ? input->GetCellData() : nullptr, out->GetNumberOfCells(), "cell-data");
  return problems.str();
}
}

#endif
