// Example: sharp and semi-sharp creases and a corner on a Catmull-Clark surface, in C++.
// Creases are line cells of the input with the cell array "Sharpness" (0 smooth .. 10
// infinitely sharp, OpenSubdiv's scale); corners are points with "CornerSharpness". The
// refined creases come out as lines again, with their decayed sharpness.
//
//   CreasePipeline [output.vtp] [levels]
#include "vtkSubDCatmullClarkFilter.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkXMLPolyDataWriter.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>

int main(int argc, char* argv[])
{
  const char* output = argc > 1 ? argv[1] : "creased-cube.vtp";
  const int levels = argc > 2 ? std::atoi(argv[2]) : 3;

  // A cube with corners at +-1.
  vtkNew<vtkPoints> points;
  for (int k = 0; k < 8; ++k)
    points->InsertNextPoint(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
  vtkNew<vtkCellArray> quads;
  const vtkIdType faces[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 }, { 0, 4, 6, 2 },
    { 1, 3, 7, 5 } };
  for (const auto& face : faces)
    quads->InsertNextCell(4, face);

  // The top face's rim is an infinitely sharp crease; one bottom edge is semi-sharp (2:
  // sharp for two levels, then smooth); the bottom corner 0 is pinned.
  vtkNew<vtkCellArray> creases;
  const vtkIdType rim[5] = { 4, 5, 7, 6, 4 }, bottom[2] = { 0, 1 };
  creases->InsertNextCell(5, rim);
  creases->InsertNextCell(2, bottom);
  vtkNew<vtkFloatArray> sharpness; // one value per cell: the lines first, then the polygons
  sharpness->SetName("Sharpness");
  sharpness->InsertNextValue(10.0f);
  sharpness->InsertNextValue(2.0f);
  for (int f = 0; f < 6; ++f)
    sharpness->InsertNextValue(0.0f);
  vtkNew<vtkFloatArray> corners;
  corners->SetName("CornerSharpness");
  for (int k = 0; k < 8; ++k)
    corners->InsertNextValue(k == 0 ? 10.0f : 0.0f);

  vtkNew<vtkPolyData> cage;
  cage->SetPoints(points);
  cage->SetLines(creases);
  cage->SetPolys(quads);
  cage->GetCellData()->AddArray(sharpness);
  cage->GetPointData()->AddArray(corners);

  vtkNew<vtkSubDCatmullClarkFilter> smooth;
  smooth->SetInputData(cage);
  smooth->SetNumberOfSubdivisions(levels);
  smooth->ProjectToLimitOn(); // the limit surface: the crease is the cubic B-spline of the rim
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputConnection(smooth->GetOutputPort());
  writer->SetFileName(output);
  if (!writer->Write())
    return EXIT_FAILURE;

  vtkPolyData* result = smooth->GetOutput();
  // The pinned corner keeps its position (some output point is exactly at (-1, -1, -1));
  // the rim's points stay in the plane z = 1.
  double worst = 0.0, cornerMiss = HUGE_VAL;
  for (vtkIdType p = 0; p < result->GetNumberOfPoints(); ++p)
  {
    const double* x = result->GetPoint(p);
    cornerMiss = std::min(cornerMiss, std::abs(x[0] + 1) + std::abs(x[1] + 1) + std::abs(x[2] + 1));
  }
  vtkIdType n;
  const vtkIdType* ids;
  vtkCellArray* lines = result->GetLines();
  vtkIdType rimPoints = 0;
  vtkDataArray* lineSharpness = result->GetCellData()->GetArray("Sharpness");
  vtkIdType cell = 0;
  for (lines->InitTraversal(); lines->GetNextCell(n, ids); ++cell)
  {
    if (lineSharpness->GetComponent(cell, 0) < 10.0)
      continue;
    for (vtkIdType k = 0; k < n; ++k, ++rimPoints)
      worst = std::max(worst, std::abs(result->GetPoint(ids[k])[2] - 1.0));
  }
  std::cout << "wrote " << output << ": " << result->GetNumberOfPolys() << " quads, " << result->GetNumberOfLines()
            << " crease lines; nearest point to the pinned corner " << cornerMiss
            << " away; rim points off z = 1 by at most " << worst << "\n";
  return cornerMiss == 0.0 && rimPoints > 0 && worst < 1e-12 ? EXIT_SUCCESS : EXIT_FAILURE;
}
