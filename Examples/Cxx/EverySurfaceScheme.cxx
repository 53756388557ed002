// Example: a minimal pipeline for each of SubD's seven surface schemes in C++.
// The same octahedron goes through each filter for two levels; each result is written to
// <prefix>-<scheme>.vtp and its face count is checked against the scheme's counting rule.
//
//   EverySurfaceScheme [prefix]
#include "vtkSubDButterflyFilter.h"
#include "vtkSubDCatmullClarkFilter.h"
#include "vtkSubDDooSabinFilter.h"
#include "vtkSubDLinearFilter.h"
#include "vtkSubDLoopFilter.h"
#include "vtkSubDMidpointFilter.h"
#include "vtkSubDSqrt3Filter.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkXMLPolyDataWriter.h"

#include <cstdlib>
#include <iostream>
#include <string>

namespace
{
// The regular octahedron: 6 vertices, 12 edges, 8 triangles.
vtkSmartPointer<vtkPolyData> Octahedron()
{
  vtkNew<vtkPoints> points;
  const double p[6][3] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } };
  for (const auto& q : p)
    points->InsertNextPoint(q);
  vtkNew<vtkCellArray> faces;
  const vtkIdType f[8][3] = { { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 }, { 3, 0, 4 }, { 2, 0, 5 }, { 1, 2, 5 },
    { 3, 1, 5 }, { 0, 3, 5 } };
  for (const auto& t : f)
    faces->InsertNextCell(3, t);
  auto octahedron = vtkSmartPointer<vtkPolyData>::New();
  octahedron->SetPoints(points);
  octahedron->SetPolys(faces);
  return octahedron;
}

// Runs `filter` (two levels) on `cage`, writes the result, and compares the face count.
bool Run(vtkSubDSurfaceFilter* filter, vtkPolyData* cage, vtkIdType expectedFaces, const std::string& path)
{
  filter->SetInputData(cage);
  filter->SetNumberOfSubdivisions(2);
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputConnection(filter->GetOutputPort());
  writer->SetFileName(path.c_str());
  const bool written = writer->Write() == 1;
  const vtkIdType faces = filter->GetOutput()->GetNumberOfPolys();
  std::cout << filter->GetClassName() << ": 8 -> " << faces << " faces (expected " << expectedFaces << ") -> "
            << path << "\n";
  return written && faces == expectedFaces;
}
}

int main(int argc, char* argv[])
{
  const std::string prefix = argc > 1 ? argv[1] : "octahedron";
  vtkSmartPointer<vtkPolyData> cage = Octahedron();
  bool ok = true;

  // Primal triangle schemes: every triangle becomes four per level (8 * 4^2).
  vtkNew<vtkSubDLoopFilter> loop;
  ok = Run(loop, cage, 128, prefix + "-loop.vtp") && ok;
  vtkNew<vtkSubDButterflyFilter> butterfly;
  butterfly->SetTension(0.0); // the classic 8-point butterfly
  ok = Run(butterfly, cage, 128, prefix + "-butterfly.vtp") && ok;
  vtkNew<vtkSubDLinearFilter> linear;
  ok = Run(linear, cage, 128, prefix + "-linear.vtp") && ok;

  // Catmull-Clark: a triangle gives three quads, then each quad four (8 * 3 * 4).
  vtkNew<vtkSubDCatmullClarkFilter> catmullClark;
  ok = Run(catmullClark, cage, 96, prefix + "-catmull-clark.vtp") && ok;

  // sqrt(3): three triangles per triangle and level (8 * 3^2).
  vtkNew<vtkSubDSqrt3Filter> sqrt3;
  ok = Run(sqrt3, cage, 72, prefix + "-sqrt3.vtp") && ok;

  // Dual schemes: one face per face, vertex and (Doo-Sabin) edge of the level above.
  // Doo-Sabin: 8 + 6 + 12 = 26 faces (24 points, 48 edges), then 26 + 24 + 48 = 98.
  vtkNew<vtkSubDDooSabinFilter> dooSabin;
  ok = Run(dooSabin, cage, 98, prefix + "-doo-sabin.vtp") && ok;
  // Midpoint: 8 + 6 = 14 faces (12 points, 24 edges), then 14 + 12 = 26.
  vtkNew<vtkSubDMidpointFilter> midpoint;
  ok = Run(midpoint, cage, 26, prefix + "-midpoint.vtp") && ok;

  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
