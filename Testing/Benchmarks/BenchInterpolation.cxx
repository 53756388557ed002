// Benchmark: vtkSubDInterpolateFilter at scale. A real mesh is refined until it has at least
// `minVertices` vertices (Loop: linear levels, triangles stay triangles; Catmull-Clark:
// Catmull-Clark levels, which make the all-quad cages that scheme is used with); the Catmull-Clark (quads) or Loop (triangles)
// cage whose limit passes through all of them is then solved. No peer offers this, so the
// program prints absolute figures: time, peak memory (RSS of the child process that solves; it
// is forked after the refinement, so this includes the refined mesh), residual and condition
// estimate.
//
//   BenchInterpolation mesh.off [catmull-clark|loop] [minVertices=100000] [repeats=3]
#include "SubDBenchSupport.h"

#include "vtkSubDCatmullClarkFilter.h"
#include "vtkSubDInterpolateFilter.h"
#include "vtkSubDLinearFilter.h"

#include <cstring>
#include <string>

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::fprintf(stderr, "usage: %s mesh.off [catmull-clark|loop] [minVertices=100000] [repeats=3]\n", argv[0]);
    return 2;
  }
  const std::string scheme = argc > 2 ? argv[2] : "catmull-clark";
  const vtkIdType minVertices = argc > 3 ? std::atol(argv[3]) : 100000;
  const int repeats = argc > 4 ? std::atoi(argv[4]) : 3;
  if (scheme != "catmull-clark" && scheme != "loop")
  {
    std::fprintf(stderr, "bench: scheme must be catmull-clark or loop\n");
    return 2;
  }
  subdbench::BenchMesh mesh;
  if (!subdbench::ReadBenchMesh(argv[1], mesh))
  {
    return 1;
  }
  vtkSmartPointer<vtkPolyData> targets = mesh.PolyData;
  int levels = 0;
  while (targets->GetNumberOfPoints() < minVertices)
  {
    vtkSmartPointer<vtkSubDSurfaceFilter> refine;
    if (scheme == "loop")
      refine = vtkSmartPointer<vtkSubDLinearFilter>::New();
    else
      refine = vtkSmartPointer<vtkSubDCatmullClarkFilter>::New();
    refine->SetInputData(targets);
    refine->SetNumberOfSubdivisions(1);
    refine->Update();
    targets = refine->GetOutput();
    ++levels;
  }
  targets->SetLines(nullptr); // crease edges the linear filter wrote; the targets are smooth

  double residual = 0, condition = 0;
  const subdbench::Result result = subdbench::Measure(
    [&]() {
      vtkNew<vtkSubDInterpolateFilter> solve;
      solve->SetInputData(targets);
      solve->SetScheme(scheme == "loop" ? vtkSubDInterpolateFilter::LOOP : vtkSubDInterpolateFilter::CATMULL_CLARK);
      const subdbench::Clock::time_point start = subdbench::Clock::now();
      solve->Update();
      subdbench::Work work;
      work.Seconds = subdbench::SecondsSince(start);
      work.Extra[0] = solve->GetErrorCode() == 0 ? solve->GetResidual() : -1.0;
      work.Extra[1] = solve->GetConditionEstimate();
      return work;
    },
    repeats);
  residual = result.Extra[0];
  condition = result.Extra[1];
  if (residual < 0)
  {
    std::fprintf(stderr, "bench: the solve failed\n");
    return 1;
  }
  const double inputMiB = subdbench::OutputBytes(targets) / (1024.0 * 1024.0);
  std::printf("interpolation, %s: %s after %d level(s) of refinement: %lld vertices, %lld faces\n", scheme.c_str(), argv[1],
    levels, static_cast<long long>(targets->GetNumberOfPoints()), static_cast<long long>(targets->GetNumberOfPolys()));
  std::printf("  solve %.2f s (best of %d), peak RSS %.0f MiB (input mesh %.0f MiB), residual %.2g, condition >= %.3g\n",
    result.Seconds, result.Runs, result.PeakMiB, inputMiB, residual, condition);
  return 0;
}
