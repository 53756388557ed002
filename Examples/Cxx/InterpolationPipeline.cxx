// Example: smooth surfaces and curves that pass through given points, in C++.
// - A wavy 5 x 4 grid of measured heights -> vtkSubDInterpolateFilter -> the Catmull-Clark
//   cage whose limit surface passes through every measurement -> vtkSubDCatmullClarkFilter.
// - The same measurements, as a grid -> vtkSubDBSplineSurfaceFilter -> the bicubic B-spline
//   through them, and its control net.
// - A closed polygon -> vtkSubDCurveInterpolateFilter -> a cubic B-spline through its points.
// Each result is written to <prefix>-*.vtp, and the program checks that the limit (evaluated
// by vtkSubDCatmullClarkFilter's ProjectToLimit) really meets the measurements.
//
//   InterpolationPipeline [prefix]
#include "vtkSubDBSplineSurfaceFilter.h"
#include "vtkSubDCatmullClarkFilter.h"
#include "vtkSubDCurveInterpolateFilter.h"
#include "vtkSubDInterpolateFilter.h"

#include "vtkCellArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkXMLPolyDataWriter.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

namespace
{
bool Write(vtkPolyData* data, const std::string& path)
{
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(data);
  writer->SetFileName(path.c_str());
  return writer->Write() == 1;
}
}

int main(int argc, char* argv[])
{
  const std::string prefix = argc > 1 ? argv[1] : "interpolation";

  // Measurements on a 5 x 4 grid, as quads.
  const int P = 5, Q = 4;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int j = 0; j < Q; ++j)
    for (int i = 0; i < P; ++i)
      points->InsertNextPoint(i, j, 0.4 * std::sin(1.3 * i) * std::cos(0.9 * j));
  vtkNew<vtkCellArray> quads;
  for (int j = 0; j + 1 < Q; ++j)
    for (int i = 0; i + 1 < P; ++i)
    {
      const vtkIdType quad[4] = { i + j * P, i + 1 + j * P, i + 1 + (j + 1) * P, i + (j + 1) * P };
      quads->InsertNextCell(4, quad);
    }
  vtkNew<vtkPolyData> measurements;
  measurements->SetPoints(points);
  measurements->SetPolys(quads);

  // 1. The Catmull-Clark cage through the measurements, and its refined surface.
  vtkNew<vtkSubDInterpolateFilter> solve;
  solve->SetInputData(measurements);
  solve->SetSchemeToCatmullClark();
  vtkNew<vtkSubDCatmullClarkFilter> refine;
  refine->SetInputConnection(solve->GetOutputPort());
  refine->SetNumberOfSubdivisions(4);
  refine->Update();
  std::cout << "Catmull-Clark cage through " << solve->GetNumberOfTaggedPoints()
            << " points, residual " << solve->GetResidual() << "\n";

  // Check: the limit points of the cage's vertices are the measurements.
  vtkNew<vtkSubDCatmullClarkFilter> limit;
  limit->SetInputConnection(solve->GetOutputPort());
  limit->SetNumberOfSubdivisions(0);
  limit->ProjectToLimitOn();
  limit->Update();
  double worst = 0.0;
  for (vtkIdType v = 0; v < measurements->GetNumberOfPoints(); ++v)
  {
    double a[3], b[3];
    measurements->GetPoint(v, a);
    limit->GetOutput()->GetPoint(v, b);
    worst = std::max(worst, std::sqrt(vtkMath::Distance2BetweenPoints(a, b)));
  }
  std::cout << "  largest distance from a measurement to the limit surface: " << worst << "\n";

  // 2. The bicubic B-spline through the same grid.
  vtkNew<vtkSubDBSplineSurfaceFilter> bspline;
  bspline->SetInputData(measurements);
  bspline->SetSamplesPerSpan(8);
  bspline->Update();
  std::cout << "B-spline: " << bspline->GetControlNet()->GetNumberOfPoints() << " control points, surface of "
            << bspline->GetSurface()->GetNumberOfPolys() << " quads\n";

  // 3. A closed cubic B-spline curve through six points.
  vtkNew<vtkPoints> curvePoints;
  vtkNew<vtkCellArray> polygon;
  polygon->InsertNextCell(7);
  for (int k = 0; k < 6; ++k)
  {
    curvePoints->InsertNextPoint(std::cos(k * M_PI / 3), std::sin(k * M_PI / 3), 0.2 * (k % 2));
    polygon->InsertCellPoint(k);
  }
  polygon->InsertCellPoint(0); // closed
  vtkNew<vtkPolyData> curveTargets;
  curveTargets->SetPoints(curvePoints);
  curveTargets->SetLines(polygon);
  vtkNew<vtkSubDCurveInterpolateFilter> curve;
  curve->SetInputData(curveTargets);
  curve->SetSchemeToCubicBSpline();
  curve->OutputRefinedCurveOn();
  curve->SetNumberOfSubdivisions(5);
  curve->Update();
  std::cout << "closed cubic B-spline through 6 points: " << curve->GetOutput()->GetNumberOfPoints()
            << " points\n";

  const bool written = Write(refine->GetOutput(), prefix + "-catmull-clark.vtp") &&
    Write(bspline->GetSurface(), prefix + "-bspline.vtp") && Write(bspline->GetControlNet(), prefix + "-bspline-net.vtp") &&
    Write(curve->GetOutput(), prefix + "-curve.vtp");
  return written && worst < 1e-9 && curve->GetOutput()->GetNumberOfPoints() == 6 * 32 ? EXIT_SUCCESS : EXIT_FAILURE;
}
