// Example: the smallest useful SubD pipeline in C++.
// A VTK source -> vtkSubDCatmullClarkFilter -> a .vtp file.
//
//   CatmullClarkPipeline [output.vtp] [levels]
#include "vtkSubDCatmullClarkFilter.h"

#include "vtkCubeSource.h"
#include "vtkCleanPolyData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkXMLPolyDataWriter.h"

#include <cstdlib>
#include <iostream>

int main(int argc, char* argv[])
{
  const char* output = argc > 1 ? argv[1] : "cube-smooth.vtp";
  const int levels = argc > 2 ? std::atoi(argv[2]) : 3;

  // vtkCubeSource gives each face its own four points (for flat normals); merge them so the
  // six quads form one closed surface.
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(2.0);
  vtkNew<vtkCleanPolyData> merge;
  merge->SetInputConnection(cube->GetOutputPort());
  merge->PointMergingOn();

  vtkNew<vtkSubDCatmullClarkFilter> subdivide;
  subdivide->SetInputConnection(merge->GetOutputPort());
  subdivide->SetNumberOfSubdivisions(levels);
  subdivide->GenerateParentCellIdsOn(); // which input face each output quad comes from

  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputConnection(subdivide->GetOutputPort());
  writer->SetFileName(output);
  if (!writer->Write())
  {
    return EXIT_FAILURE;
  }
  vtkPolyData* result = subdivide->GetOutput();
  std::cout << "wrote " << output << ": " << result->GetNumberOfPolys() << " quads, "
            << result->GetNumberOfPoints() << " points\n";
  return result->GetNumberOfPolys() == 6 * (1 << (2 * levels)) ? EXIT_SUCCESS : EXIT_FAILURE;
}
