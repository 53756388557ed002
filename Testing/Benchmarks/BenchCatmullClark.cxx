// Benchmark (a program, not a test): Catmull-Clark levels 1..4 on a real mesh, SubD against
// OpenSubdiv's Far (TopologyRefinerFactory + RefineUniform + PrimvarRefinerReal<double>,
// i.e. topology and interpolation) measured in the same run, their runs interleaved. Each
// measurement runs in a forked child so its peak RSS is its own. Prints seconds, output
// faces per second, peak RSS, the ratio OpenSubdiv time / SubD time, and for the filter the
// peak RSS over the output's bytes and the time over the bandwidth bound (writing the output
// once). The last row of a level re-applies the cached stencils after the points moved (the
// explorer's and an animation's case: the fastest of 5 frames), in output points per second.
//
//   usage: BenchCatmullClark mesh.off [maxLevel=4] [repeats=3]
#include "SubDRefiner.h"
#include "SubDScheme.h"
#include "vtkSubDCatmullClarkFilter.h"
#include "vtkSubDOFFReader.h"

#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkCellArray.h"

#include "SubDBenchOpenSubdiv.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace
{
using subdbench::Clock;
using subdbench::Result;
using subdbench::Work;
using namespace OpenSubdiv;

using Mesh = subdbench::BenchMesh;

Work RunKernel(const Mesh& mesh, int level)
{
  const Clock::time_point start = Clock::now();
  std::vector<subd::Index> offsets{ 0 };
  for (int s : mesh.Sizes)
    offsets.push_back(offsets.back() + s);
  subd::CatmullClarkScheme scheme;
  subd::Hierarchy h;
  subd::Refine(scheme,
    subd::MakeBaseLevel(subd::MeshTopology::Build(mesh.NumVertices(), std::move(offsets),
                          std::vector<subd::Index>(mesh.Corners.begin(), mesh.Corners.end())),
      {}, subd::BoundaryRule::EdgeOnly),
    level, h, nullptr, subd::ChildTopology::FacesOnly, subd::LevelRows::Written);
  std::vector<double> finest(static_cast<size_t>(h.GetNumFinestPoints()) * 3);
  h.Evaluate(mesh.Points.data(), 3, finest.data());
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return { seconds, double(h.Finest.Topology.GetNumFaces()) };
}

Work RunFilter(const Mesh& mesh, int level, int threads)
{
  subdbench::StartThreads(threads);
  vtkNew<vtkSubDCatmullClarkFilter> filter;
  filter->SetInputData(mesh.PolyData);
  filter->SetNumberOfSubdivisions(level);
  const Clock::time_point start = Clock::now();
  filter->Update();
  const double seconds = subdbench::SecondsSince(start);
  return { seconds, double(filter->GetOutput()->GetNumberOfPolys()), subdbench::OutputBytes(filter->GetOutput()) };
}

// Refines once, then moves the input points and times the next updates, which only
// re-apply the cached stencils, as an animation does once per frame: the fastest of
// `frames` frames; "faces" are the output points here.
Work RunReapply(const Mesh& mesh, int level, int threads, int frames = 5)
{
  subdbench::StartThreads(threads);
  vtkNew<vtkPolyData> input;
  input->DeepCopy(mesh.PolyData);
  vtkNew<vtkSubDCatmullClarkFilter> filter;
  filter->SetInputData(input);
  filter->SetNumberOfSubdivisions(level);
  filter->Update();
  vtkPoints* points = input->GetPoints();
  double seconds = 1e300;
  for (int frame = 0; frame < frames; ++frame)
  {
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
    {
      double p[3];
      points->GetPoint(i, p);
      points->SetPoint(i, 1.01 * p[0], p[1], p[2]);
    }
    points->Modified();
    const Clock::time_point start = Clock::now();
    filter->Update();
    seconds = std::min(seconds, subdbench::SecondsSince(start));
  }
  return { seconds, double(filter->GetOutput()->GetNumberOfPoints()), subdbench::OutputBytes(filter->GetOutput()) };
}
}

int main(int argc, char* argv[])
{
  subdbench::BenchArguments args;
  int status = 0;
  if (!subdbench::ReadBenchArguments(argc, argv, 4, args, status))
  {
    return status;
  }
  const int maxLevel = args.MaxLevel;
  const int repeats = args.Repeats;
  const Mesh& mesh = args.Mesh;
  std::printf("Catmull-Clark on %s: %d points, %zu faces; best of %d runs each (%d for runs under %.1f s)\n", argv[1],
    mesh.NumVertices(), mesh.Sizes.size(), repeats, std::max(repeats, subdbench::ShortRunRepeats),
    subdbench::ShortRunSeconds);
  std::printf("%-5s %-28s %10s %12s %9s%s\n", "level", "implementation", "seconds", "faces/s", "OSD/this",
    subdbench::MemoryHeader);
  for (int level = 1; level <= maxLevel; ++level)
  {
    const std::vector<Result> results = subdbench::MeasureInterleaved(
      { [&] { return subdbench::RunOpenSubdiv(mesh, level, Sdc::SCHEME_CATMARK); }, [&] { return RunKernel(mesh, level); },
        [&] { return RunFilter(mesh, level, 1); }, [&] { return RunFilter(mesh, level, 2); },
        [&] { return RunReapply(mesh, level, 2); } },
      repeats);
    const Result &osd = results[0], &kernel = results[1], &filter1 = results[2], &filter2 = results[3],
                 &reapply = results[4];
    auto row = [&](const char* name, const Result& r) {
      std::printf("%-5d %-28s %10.4f %12.3g %9.2f", level, name, r.Seconds, r.Faces / r.Seconds, osd.Seconds / r.Seconds);
      subdbench::PrintMemory(r);
      std::printf("\n");
    };
    row("OpenSubdiv Far (1 thread)", osd);
    row("SubD kernel (1 thread)", kernel);
    row("SubD filter (1 thread)", filter1);
    row("SubD filter (2 threads)", filter2);
    std::printf("%-5d %-28s %10.4f %12.3g points/s (re-applied stencils, points moved)\n", level,
      "SubD re-apply (2 threads)", reapply.Seconds, reapply.Faces / reapply.Seconds);
    if (kernel.Faces != osd.Faces || filter2.Faces != osd.Faces)
    {
      std::fprintf(stderr, "bench: face counts differ (%g, %g, %g)\n", osd.Faces, kernel.Faces, filter2.Faces);
      return 1;
    }
  }
  return 0;
}
