// Example: an interpolating subdivision curve in C++.
// A coarse helix polyline -> vtkSubDCurveFilter (4-point scheme) -> a .vtp file with the
// limit curve's unit tangents. The 4-point scheme keeps every control point.
//
//   CurvePipeline [output.vtp] [levels]
#include "vtkSubDCurveFilter.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkXMLPolyDataWriter.h"

#include <cmath>
#include <cstdlib>
#include <iostream>

int main(int argc, char* argv[])
{
  const char* output = argc > 1 ? argv[1] : "helix-four-point.vtp";
  const int levels = argc > 2 ? std::atoi(argv[2]) : 4;

  // Eight points on a helix, one open polyline.
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> line;
  line->InsertNextCell(8);
  for (int k = 0; k < 8; ++k)
  {
    points->InsertNextPoint(std::cos(0.9 * k), std::sin(0.9 * k), 0.25 * k);
    line->InsertCellPoint(k);
  }
  vtkNew<vtkPolyData> polygon;
  polygon->SetPoints(points);
  polygon->SetLines(line);

  vtkNew<vtkSubDCurveFilter> curve;
  curve->SetInputData(polygon);
  curve->SetSchemeToFourPoint();
  curve->SetTension(1.0 / 16.0); // the classic value: cubic polynomials are reproduced
  curve->SetNumberOfSubdivisions(levels);
  curve->ComputeTangentsOn();

  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputConnection(curve->GetOutputPort());
  writer->SetFileName(output);
  if (!writer->Write())
  {
    return EXIT_FAILURE;
  }
  vtkPolyData* result = curve->GetOutput();
  std::cout << "wrote " << output << ": " << result->GetNumberOfPoints() << " points on "
            << result->GetNumberOfLines() << " polyline, with \""
            << result->GetPointData()->GetTangents()->GetName() << "\"\n";
  // Open polygon of 8 points: 7 * 2^levels + 1 points.
  return result->GetNumberOfPoints() == 7 * (1 << levels) + 1 ? EXIT_SUCCESS : EXIT_FAILURE;
}
