// Example: the exact limit surface of a Catmull-Clark cage, with its curvature, in C++.
// vtkSubDLimitFilter evaluates the limit surface of a torus-like cage on a grid of 8 x 8
// samples per face, with exact normals and mean / Gaussian curvature from the second
// derivatives, and writes it to a .vtp file. A torus has positive Gaussian curvature on its
// outer side and negative on its inner side; the program checks both appear.
//
//   LimitSurface [output.vtp]
#include "vtkSubDLimitFilter.h"

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
  const char* output = argc > 1 ? argv[1] : "torus-limit.vtp";

  // An 8 x 6 quad torus (major radius 2, minor radius 0.7).
  const int nu = 8, nv = 6;
  vtkNew<vtkPoints> points;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i)
    {
      const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
      const double r = 2.0 + 0.7 * std::cos(v);
      points->InsertNextPoint(r * std::cos(u), r * std::sin(u), 0.7 * std::sin(v));
    }
  vtkNew<vtkCellArray> quads;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i)
    {
      const vtkIdType quad[4] = { i + nu * j, (i + 1) % nu + nu * j, (i + 1) % nu + nu * ((j + 1) % nv),
        i + nu * ((j + 1) % nv) };
      quads->InsertNextCell(4, quad);
    }
  vtkNew<vtkPolyData> cage;
  cage->SetPoints(points);
  cage->SetPolys(quads);

  vtkNew<vtkSubDLimitFilter> limit;
  limit->SetInputData(cage);
  limit->SetSchemeToCatmullClark();
  limit->SetResolution(8);
  limit->ComputeNormalsOn();
  limit->ComputeCurvatureOn();
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputConnection(limit->GetOutputPort());
  writer->SetFileName(output);
  if (!writer->Write())
    return EXIT_FAILURE;

  vtkPolyData* surface = limit->GetOutput();
  vtkDataArray* gauss = surface->GetPointData()->GetArray("Gauss_Curvature");
  double range[2];
  gauss->GetRange(range);
  std::cout << "wrote " << output << ": " << surface->GetNumberOfPoints() << " limit points, Gaussian curvature in ["
            << range[0] << ", " << range[1] << "]\n";
  return range[0] < 0.0 && range[1] > 0.0 && surface->GetPointData()->GetNormals() ? EXIT_SUCCESS : EXIT_FAILURE;
}
