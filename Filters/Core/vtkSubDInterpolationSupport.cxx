#include "vtkSubDInterpolationSupport.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cctype>

std::vector<char> vtkSubDReadInterpolationTags(vtkPolyData* input, const char* name)
{
  const vtkIdType numPoints = input->GetNumberOfPoints();
  std::vector<char> tagged(static_cast<size_t>(numPoints), 1);
  vtkDataArray* tags = name ? input->GetPointData()->GetArray(name) : nullptr;
  if (tags && tags->GetNumberOfTuples() == numPoints)
  {
    for (vtkIdType v = 0; v < numPoints; ++v)
    {
      tagged[v] = tags->GetComponent(v, 0) != 0.0;
    }
  }
  return tagged;
}

vtkSmartPointer<vtkPolyData> vtkSubDWithSolvedPoints(vtkPolyData* input, const std::vector<double>& coordinates)
{
  vtkNew<vtkDoubleArray> values;
  values->SetNumberOfComponents(3);
  values->SetNumberOfTuples(static_cast<vtkIdType>(coordinates.size() / 3));
  std::copy(coordinates.begin(), coordinates.end(), values->GetPointer(0));
  vtkNew<vtkPoints> points;
  points->SetData(values);
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->ShallowCopy(input);
  result->SetPoints(points);
  return result;
}

std::string vtkSubDSentence(std::string message)
{
  if (!message.empty())
  {
    message[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(message[0])));
    if (message.back() != '.')
    {
      message += '.';
    }
  }
  return message;
}
