// Benchmark support: run a measurement in a forked child (so its peak RSS is its own), keep
// the fastest of several runs, and read meshes.
#ifndef SubDBenchSupport_h
#define SubDBenchSupport_h

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkSubDOFFReader.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <utility>
#include <vector>

namespace subdbench
{
using Clock = std::chrono::steady_clock;

inline double SecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// What one run reports: its time, the faces it made and, for SubD's filters, the bytes of
/// the output vtkPolyData (points, cells and arrays; 0 when not measured).
struct Work
{
  double Seconds = 0;
  double Faces = 0;
  double OutputBytes = 0;
  double Extra[2] = { 0, 0 }; ///< anything else a benchmark reports (its meaning is the benchmark's)
};

struct Result
{
  double Seconds = 0;
  double Faces = 0;
  double OutputBytes = 0;
  double Extra[2] = { 0, 0 };
  double PeakMiB = 0;   ///< the child's peak RSS (VmHWM): the forked process, libraries and input included
  double GrowthMiB = 0; ///< that peak less the child's RSS when its work began: what the run itself added
  int Runs = 0;         ///< how many runs the fastest is the fastest of
};

/// A line of /proc/self/status ("VmRSS", "VmHWM") in MiB; 0 where it cannot be read.
inline double StatusMiB(const char* field)
{
  std::FILE* status = std::fopen("/proc/self/status", "r");
  if (!status)
    return 0;
  char line[256];
  double kiB = 0;
  const size_t length = std::strlen(field);
  while (std::fgets(line, sizeof(line), status))
  {
    if (std::strncmp(line, field, length) == 0 && line[length] == ':')
    {
      kiB = std::atof(line + length + 1);
      break;
    }
  }
  std::fclose(status);
  return kiB / 1024.0;
}

/// The bytes of a filter's output, as VTK counts them.
inline double OutputBytes(vtkPolyData* output)
{
  return 1024.0 * static_cast<double>(output->GetActualMemorySize());
}

/// Runs shorter than this are repeated at least ShortRunRepeats times: a few milliseconds of
/// the VM's noise is most of such a run, and the fastest of more runs is what the code costs.
constexpr double ShortRunSeconds = 0.1;
constexpr int ShortRunRepeats = 9;

// One run of `work` in a child process: its report, with the child's own peak RSS and the
// growth of its RSS over the run (what the child starts with is the parent's pages it
// shares: libraries, the mesh read). Library pages the child touches again after the fork
// count as growth, so that errs high, never low.
inline Result RunInChild(const std::function<Work()>& work)
{
  int pipeFd[2];
  if (pipe(pipeFd) != 0)
    std::abort();
  const pid_t pid = fork();
  if (pid == 0)
  {
    close(pipeFd[0]);
    const double startMiB = StatusMiB("VmRSS");
    const Work w = work();
    const double peakMiB = StatusMiB("VmHWM");
    const double message[7] = { w.Seconds, w.Faces, w.OutputBytes, w.Extra[0], w.Extra[1], peakMiB,
      peakMiB - startMiB };
    if (write(pipeFd[1], message, sizeof(message)) != sizeof(message))
      _exit(1);
    _exit(0);
  }
  close(pipeFd[1]);
  double message[7] = { 0, 0, 0, 0, 0, 0, 0 };
  const bool ok = read(pipeFd[0], message, sizeof(message)) == sizeof(message);
  close(pipeFd[0]);
  int status = 0;
  struct rusage usage;
  wait4(pid, &status, 0, &usage);
  if (!ok || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
  {
    std::fprintf(stderr, "bench: a measurement failed\n");
    std::exit(1);
  }
  Result run;
  run.Seconds = message[0];
  run.Faces = message[1];
  run.OutputBytes = message[2];
  run.Extra[0] = message[3];
  run.Extra[1] = message[4];
  run.PeakMiB = message[5] > 0 ? message[5] : usage.ru_maxrss / 1024.0;
  run.GrowthMiB = message[6];
  run.Runs = 1;
  return run;
}

// Runs each of `works` `repeats` times (ShortRunRepeats for one whose first run is short),
// each in its own child process, and keeps each one's fastest run. The runs are interleaved
// (one of each per round) so that the VM slowing down or speeding up for a while (its speed
// drifts by up to 2x over minutes) weighs on all of them alike, not on whichever ran then:
// the ratios between them are what the benchmarks report.
inline std::vector<Result> MeasureInterleaved(const std::vector<std::function<Work()>>& works, int repeats)
{
  std::vector<Result> best(works.size());
  std::vector<int> runs(works.size(), repeats);
  for (int round = 0; round < *std::max_element(runs.begin(), runs.end()); ++round)
  {
    for (size_t i = 0; i < works.size(); ++i)
    {
      if (round >= runs[i])
      {
        continue;
      }
      const Result run = RunInChild(works[i]);
      if (round == 0 && run.Seconds < ShortRunSeconds)
      {
        runs[i] = std::max(repeats, ShortRunRepeats);
      }
      if (round == 0 || run.Seconds < best[i].Seconds)
      {
        best[i] = run;
      }
      best[i].Runs = runs[i];
    }
  }
  return best;
}

// One work measured alone (MeasureInterleaved).
inline Result Measure(const std::function<Work()>& work, int repeats)
{
  return MeasureInterleaved({ work }, repeats)[0];
}

/// Sets vtkSMPTools' thread count and starts its threads. A forked child has no thread pool:
/// its first parallel loop would start one (about 1 ms here), which a process does once, not
/// on every filter run; so runs are timed with the pool up, as in a program that has already
/// run a parallel loop.
inline void StartThreads(int threads)
{
  vtkSMPTools::Initialize(threads);
  vtkSMPTools::For(0, 1024, 1, [](vtkIdType, vtkIdType) {});
}

/// This machine's measured write bandwidth (the figure, bytes/s): writing the output
/// once at this rate is the bound no implementation can beat.
constexpr double WriteBandwidth = 23.0e9;

/// The memory and bound columns every bench row ends with (MemoryHeader names them): peak and
/// growth in MiB and, for SubD's filters (whose output bytes are known), both over the output's
/// bytes and the time over the bandwidth bound.
constexpr const char* MemoryHeader = "  peak MiB  grown MiB  peak/out grown/out   x bound";

inline void PrintMemory(const Result& r)
{
  std::printf(" %9.1f %10.1f", r.PeakMiB, r.GrowthMiB);
  if (r.OutputBytes > 0)
  {
    const double outMiB = r.OutputBytes / 1048576.0;
    std::printf(" %9.2f %9.2f %9.1f", r.PeakMiB / outMiB, r.GrowthMiB / outMiB, r.Seconds / (r.OutputBytes / WriteBandwidth));
  }
}

/// A benchmark mesh as flat arrays (for the peers) and as vtkPolyData (for the filters).
struct BenchMesh
{
  std::vector<double> Points;
  std::vector<int> Sizes, Corners;
  vtkSmartPointer<vtkPolyData> PolyData;
  int NumVertices() const { return static_cast<int>(Points.size() / 3); }
};

/// Reads an OFF file; false (with a message) if it holds no points.
inline bool ReadBenchMesh(const char* path, BenchMesh& mesh)
{
  vtkNew<vtkSubDOFFReader> reader;
  reader->SetFileName(path);
  reader->Update();
  mesh.PolyData = reader->GetOutput();
  if (mesh.PolyData->GetNumberOfPoints() == 0)
  {
    std::fprintf(stderr, "bench: cannot read %s\n", path);
    return false;
  }
  for (vtkIdType i = 0; i < mesh.PolyData->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh.PolyData->GetPoint(i, p);
    mesh.Points.insert(mesh.Points.end(), p, p + 3);
  }
  vtkIdType n;
  const vtkIdType* pts;
  for (mesh.PolyData->GetPolys()->InitTraversal(); mesh.PolyData->GetPolys()->GetNextCell(n, pts);)
  {
    mesh.Sizes.push_back(static_cast<int>(n));
    mesh.Corners.insert(mesh.Corners.end(), pts, pts + n);
  }
  return true;
}
/// A benchmark's command line, `mesh.off [maxLevel] [repeats]`.
struct BenchArguments
{
  BenchMesh Mesh;
  int MaxLevel = 0;
  int Repeats = 3;
};

/// Parses the command line and reads the mesh; false (after a message) when the program
/// should exit with status 2 (usage) or 1 (unreadable mesh), given in `status`.
inline bool ReadBenchArguments(int argc, char* argv[], int defaultMaxLevel, BenchArguments& args, int& status)
{
  if (argc < 2)
  {
    std::fprintf(stderr, "usage: %s mesh.off [maxLevel=%d] [repeats=3]\n", argv[0], defaultMaxLevel);
    status = 2;
    return false;
  }
  args.MaxLevel = argc > 2 ? std::atoi(argv[2]) : defaultMaxLevel;
  args.Repeats = argc > 3 ? std::atoi(argv[3]) : 3;
  status = 1;
  return ReadBenchMesh(argv[1], args.Mesh);
}
}

#endif
