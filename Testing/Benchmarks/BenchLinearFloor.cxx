// How fast can a linear level-1 split of a triangle mesh be on this machine? The issue's
// target asks SubD's linear filter for 10x VTK's (vtkLinearSubdivisionFilter) at every level;
// at level 1 VTK takes about 55 ms on the bunny, so 10x leaves 5.5 ms for the whole run. This
// program measures, in the same interleaved forked runs as the other benchmarks (fresh pages
// in each child, as a filter's first update meets them), what any implementation must at
// least do:
//   - "writing alone": the output's points (vertices copied, edge midpoints) and its four
//     triangles per face written straight into VTK's arrays on the benchmark's threads, the
//     edges given (numbered in the parent process);
//   - "minimal split": the same after numbering the edges with the least work known here (the
//     half-edges filed under their lower vertex, matched within each file), with no input
//     screening, no topology beyond the edges, no caching for re-application; numbered on one
//     thread, then ("... 2 threads") on two;
// next to SubD's filter and VTK's, and prints VTK's time over each. What the minimal split
// leaves of the 10x budget is what the filter's checks, topology and caches must fit in.
//
//   BenchLinearFloor mesh.off [repeats] [threads]
#include "SubDBenchSupport.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkLinearSubdivisionFilter.h"
#include "vtkPoints.h"
#include "vtkSubDLinearFilter.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <vector>

namespace
{
using subdbench::Clock;
using subdbench::SecondsSince;
using subdbench::Work;

// A triangle mesh's edges: each corner's edge (the one to the next corner) and each edge's ends.
struct Edges
{
  std::vector<int> OfCorner;
  std::vector<int> Ends;
};

// Half-edge h of a triangle mesh: its lower vertex, and its key (upper vertex, h).
int LowerVertex(const vtkTypeInt64* corners, int h, std::uint64_t& key)
{
  const int a = static_cast<int>(corners[h]), b = static_cast<int>(corners[h % 3 == 2 ? h - 2 : h + 1]);
  key = static_cast<std::uint64_t>(a < b ? b : a) << 32 | static_cast<std::uint32_t>(h);
  return a < b ? a : b;
}

// The edges of the files of vertices [begin, end) (each vertex's half-edges, filed under it as
// their lower vertex, in increasing order), numbered from 0 in that order: within a file, a
// half-edge takes the edge of an earlier one to the same upper vertex, or a new edge.
void NumberFiledEdges(int begin, int end, const std::vector<int>& offsets, const std::vector<std::uint64_t>& filed,
  std::vector<int>& ofCorner, std::vector<int>& ends)
{
  for (int v = begin; v < end; ++v)
  {
    for (int i = offsets[v]; i < offsets[v + 1]; ++i)
    {
      const std::uint64_t upper = filed[i] >> 32;
      int edge = -1;
      for (int j = offsets[v]; j < i && edge < 0; ++j)
      {
        edge = (filed[j] >> 32) == upper ? ofCorner[filed[j] & 0xffffffffu] : -1;
      }
      if (edge < 0)
      {
        edge = static_cast<int>(ends.size() / 2);
        ends.push_back(v);
        ends.push_back(static_cast<int>(upper));
      }
      ofCorner[filed[i] & 0xffffffffu] = edge;
    }
  }
}

// The edges numbered by lower vertex: each half-edge filed under its lower vertex (a counting
// sort), then the files matched in vertex order.
Edges NumberEdges(int numVertices, int numCorners, const vtkTypeInt64* corners)
{
  std::vector<int> offsets(static_cast<size_t>(numVertices) + 1, 0);
  std::uint64_t key;
  for (int h = 0; h < numCorners; ++h)
  {
    ++offsets[LowerVertex(corners, h, key) + 1];
  }
  for (int v = 0; v < numVertices; ++v)
  {
    offsets[v + 1] += offsets[v];
  }
  std::vector<std::uint64_t> filed(static_cast<size_t>(numCorners));
  std::vector<int> cursor(offsets.begin(), offsets.end() - 1);
  for (int h = 0; h < numCorners; ++h)
  {
    const int lower = LowerVertex(corners, h, key);
    filed[cursor[lower]++] = key;
  }
  Edges edges;
  edges.OfCorner.resize(static_cast<size_t>(numCorners));
  edges.Ends.reserve(static_cast<size_t>(numCorners)); // about half the corners are edges
  NumberFiledEdges(0, numVertices, offsets, filed, edges.OfCorner, edges.Ends);
  return edges;
}

// NumberEdges on two threads: each half of the half-edges counted and filed with its own
// cursors (the second half after the first in every file, so the files are the same), then
// each half of the vertices' files matched on its own, the second half's edges numbered after
// the first's.
Edges NumberEdgesOnTwoThreads(int numVertices, int numCorners, const vtkTypeInt64* corners)
{
  auto onTwoThreads = [](const std::function<void(int)>& task) {
    vtkSMPTools::For(0, 2, 1, [&task](vtkIdType begin, vtkIdType end) {
      for (vtkIdType t = begin; t < end; ++t)
      {
        task(static_cast<int>(t));
      }
    });
  };
  const int cornerHalf[3] = { 0, numCorners / 6 * 3, numCorners };
  std::vector<int> counts[2];
  onTwoThreads([&](int t) {
    counts[t].assign(static_cast<size_t>(numVertices), 0);
    std::uint64_t key;
    for (int h = cornerHalf[t]; h < cornerHalf[t + 1]; ++h)
    {
      ++counts[t][LowerVertex(corners, h, key)];
    }
  });
  std::vector<int> offsets(static_cast<size_t>(numVertices) + 1);
  offsets[0] = 0;
  for (int v = 0; v < numVertices; ++v)
  {
    offsets[v + 1] = offsets[v] + counts[0][v] + counts[1][v];
    counts[1][v] = offsets[v] + counts[0][v]; // the cursors
    counts[0][v] = offsets[v];
  }
  std::vector<std::uint64_t> filed(static_cast<size_t>(numCorners));
  onTwoThreads([&](int t) {
    std::vector<int>& cursor = counts[t];
    std::uint64_t key;
    for (int h = cornerHalf[t]; h < cornerHalf[t + 1]; ++h)
    {
      const int lower = LowerVertex(corners, h, key);
      filed[cursor[lower]++] = key;
    }
  });
  Edges edges;
  edges.OfCorner.resize(static_cast<size_t>(numCorners));
  const int vertexHalf[3] = { 0, numVertices / 2, numVertices };
  std::vector<int> ends[2];
  onTwoThreads([&](int t) {
    ends[t].reserve(static_cast<size_t>(offsets[vertexHalf[t + 1]] - offsets[vertexHalf[t]]));
    NumberFiledEdges(vertexHalf[t], vertexHalf[t + 1], offsets, filed, edges.OfCorner, ends[t]);
  });
  const int firstHalfEdges = static_cast<int>(ends[0].size() / 2);
  for (int i = offsets[vertexHalf[1]]; i < numCorners; ++i)
  {
    edges.OfCorner[filed[i] & 0xffffffffu] += firstHalfEdges;
  }
  edges.Ends = std::move(ends[0]);
  edges.Ends.insert(edges.Ends.end(), ends[1].begin(), ends[1].end());
  return edges;
}

// The level-1 output from the edges: vertices, then edge midpoints; four triangles per face.
vtkSmartPointer<vtkPolyData> WriteLevelOne(vtkPolyData* input, const Edges& edges)
{
  const vtkIdType numVertices = input->GetNumberOfPoints();
  const vtkIdType numEdges = static_cast<vtkIdType>(edges.Ends.size() / 2);
  const vtkIdType numFaces = input->GetPolys()->GetNumberOfCells();
  const vtkTypeInt64* corners = input->GetPolys()->GetConnectivityArray64()->GetPointer(0);
  const double* p = vtkDoubleArray::SafeDownCast(input->GetPoints()->GetData())->GetPointer(0);

  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(numVertices + numEdges);
  double* q = coordinates->GetPointer(0);
  vtkSMPTools::For(0, numVertices + numEdges, 4096, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        q[3 * i + c] = i < numVertices ? p[3 * i + c]
                                       : 0.5 * (p[3 * edges.Ends[2 * (i - numVertices)] + c] +
                                                 p[3 * edges.Ends[2 * (i - numVertices) + 1] + c]);
      }
    }
  });
  vtkNew<vtkTypeInt32Array> offsets, connectivity;
  offsets->SetNumberOfValues(4 * numFaces + 1);
  connectivity->SetNumberOfValues(12 * numFaces);
  std::int32_t* o = offsets->GetPointer(0);
  std::int32_t* t = connectivity->GetPointer(0);
  vtkSMPTools::For(0, numFaces, 2048, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType f = begin; f < end; ++f)
    {
      const std::int32_t v0 = static_cast<std::int32_t>(corners[3 * f]),
                         v1 = static_cast<std::int32_t>(corners[3 * f + 1]),
                         v2 = static_cast<std::int32_t>(corners[3 * f + 2]);
      const std::int32_t m0 = static_cast<std::int32_t>(numVertices + edges.OfCorner[3 * f]),
                         m1 = static_cast<std::int32_t>(numVertices + edges.OfCorner[3 * f + 1]),
                         m2 = static_cast<std::int32_t>(numVertices + edges.OfCorner[3 * f + 2]);
      const std::int32_t children[12] = { v0, m0, m2, m0, v1, m1, m2, m1, v2, m0, m1, m2 };
      std::copy(children, children + 12, t + 12 * f);
      for (int k = 0; k < 4; ++k)
      {
        o[4 * f + k] = static_cast<std::int32_t>(12 * f + 3 * k);
      }
    }
  });
  o[4 * numFaces] = static_cast<std::int32_t>(12 * numFaces);
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  auto output = vtkSmartPointer<vtkPolyData>::New();
  output->SetPoints(points);
  output->SetPolys(polys);
  return output;
}

Work Report(Clock::time_point start, vtkPolyData* output)
{
  Work work{ SecondsSince(start), static_cast<double>(output->GetNumberOfPolys()), subdbench::OutputBytes(output) };
  work.Extra[0] = static_cast<double>(output->GetNumberOfPoints());
  return work;
}

// A filter's level 1, timed from its construction.
template <typename Filter>
Work FilterLevelOne(vtkPolyData* input)
{
  const Clock::time_point start = Clock::now();
  vtkNew<Filter> filter;
  filter->SetInputData(input);
  filter->SetNumberOfSubdivisions(1);
  filter->Update();
  return Report(start, filter->GetOutput());
}
}

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::fprintf(stderr, "usage: BenchLinearFloor mesh.off [repeats] [threads]\n");
    return 2;
  }
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 3;
  const int threads = argc > 3 ? std::atoi(argv[3]) : 2;
  subdbench::BenchMesh mesh;
  if (!subdbench::ReadBenchMesh(argv[1], mesh))
  {
    return 1;
  }
  vtkPolyData* input = mesh.PolyData;
  vtkCellArray* polys = input->GetPolys();
  if (!polys->IsStorage64Bit() || polys->GetNumberOfConnectivityIds() != 3 * polys->GetNumberOfCells() ||
    !vtkDoubleArray::SafeDownCast(input->GetPoints()->GetData()))
  {
    std::fprintf(stderr, "BenchLinearFloor: needs triangles only, 64-bit cells and double points\n");
    return 1;
  }
  const int numCorners = static_cast<int>(polys->GetNumberOfConnectivityIds());
  const vtkTypeInt64* corners = polys->GetConnectivityArray64()->GetPointer(0);
  const int numVertices = static_cast<int>(input->GetNumberOfPoints());
  const Edges given = NumberEdges(numVertices, numCorners, corners);
  // The two numberings agree (checked in a child: threads started here would not be there
  // in the children forked later, whose own pools the measurements start).
  const pid_t checker = fork();
  if (checker == 0)
  {
    subdbench::StartThreads(threads);
    const Edges onThreads = NumberEdgesOnTwoThreads(numVertices, numCorners, corners);
    _exit(onThreads.OfCorner == given.OfCorner && onThreads.Ends == given.Ends ? 0 : 1);
  }
  int status = 0;
  waitpid(checker, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
  {
    std::fprintf(stderr, "BenchLinearFloor: the two edge numberings differ\n");
    return 1;
  }

  // A minimal split whose edges `number` numbers.
  auto minimalSplit = [&](Edges (*number)(int, int, const vtkTypeInt64*)) {
    return [&, number] {
      subdbench::StartThreads(threads);
      const Clock::time_point start = Clock::now();
      return Report(start, WriteLevelOne(input, number(numVertices, numCorners, corners)));
    };
  };
  const char* names[] = { "writing alone", "minimal split", "... 2 threads", "SubD filter", "VTK" };
  const std::vector<std::function<Work()>> works = {
    [&] {
      subdbench::StartThreads(threads);
      const Clock::time_point start = Clock::now();
      return Report(start, WriteLevelOne(input, given));
    },
    minimalSplit(&NumberEdges),
    minimalSplit(&NumberEdgesOnTwoThreads),
    [&] {
      subdbench::StartThreads(threads);
      return FilterLevelOne<vtkSubDLinearFilter>(input);
    },
    [&] { return FilterLevelOne<vtkLinearSubdivisionFilter>(input); }, // serial
  };
  const std::vector<subdbench::Result> results = subdbench::MeasureInterleaved(works, repeats);
  std::printf("Linear level 1 on %s (%d faces), %d threads, best of %d forked runs each\n", argv[1],
    static_cast<int>(polys->GetNumberOfCells()), threads, results[0].Runs);
  std::printf("%-16s %9s %12s %12s\n", "implementation", "ms", "output faces", "VTK / this");
  for (size_t i = 0; i < results.size(); ++i)
  {
    std::printf("%-16s %9.2f %12.0f %12.2f\n", names[i], 1e3 * results[i].Seconds, results[i].Faces,
      results.back().Seconds / results[i].Seconds);
  }
  for (size_t i = 0; i + 1 < results.size(); ++i)
  {
    if (results[i].Faces != results.back().Faces || results[i].Extra[0] != results.back().Extra[0])
    {
      std::fprintf(stderr, "BenchLinearFloor: %s made %.0f faces and %.0f points, VTK %.0f and %.0f\n", names[i],
        results[i].Faces, results[i].Extra[0], results.back().Faces, results.back().Extra[0]);
      return 1;
    }
  }
  return 0;
}
