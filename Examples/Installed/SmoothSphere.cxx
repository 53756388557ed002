// Example: SubD from its install tree, found with find_package(SubD). A coarse sphere is
// refined twice by Loop's scheme and projected to the limit surface with exact normals.
#include "vtkSubDLoopFilter.h"

#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"

#include <cstdlib>
#include <iostream>

int main()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(8);
  sphere->SetPhiResolution(6);

  vtkNew<vtkSubDLoopFilter> loop;
  loop->SetInputConnection(sphere->GetOutputPort());
  loop->SetNumberOfSubdivisions(2);
  loop->ProjectToLimitOn();
  loop->ComputeLimitNormalsOn();
  loop->Update();

  vtkPolyData* smooth = loop->GetOutput();
  std::cout << "Loop, 2 levels: " << sphere->GetOutput()->GetNumberOfPolys() << " -> " << smooth->GetNumberOfPolys()
            << " triangles, normals: " << (smooth->GetPointData()->GetNormals() ? "yes" : "no") << "\n";
  return smooth->GetNumberOfPolys() == 16 * sphere->GetOutput()->GetNumberOfPolys() &&
      smooth->GetPointData()->GetNormals()
    ? EXIT_SUCCESS
    : EXIT_FAILURE;
}
