// Benchmark (a program, not a test): Catmull-Clark of a mesh with texture coordinates on a
// generated atlas (islands of about 256 faces, each projected on a plane of its own, so that
// seams run all over the mesh), the points split at the seams as VTK's readers deliver them.
// Measured in the same run, interleaved, each in a forked child: SubD's filter on the plain
// mesh (no texture coordinates), on the split mesh with its face-varying channel (welded,
// refined, split again), and OpenSubdiv's Far with the same channel (topology, points and
// InterpolateFaceVarying). Prints seconds, peak memory and the ratios: the channel's cost
// (with / without) and OpenSubdiv with its channel over SubD with its channel.
//
//   usage: BenchFaceVarying mesh.off [maxLevel=4] [repeats=3]
#include "vtkSubDCatmullClarkFilter.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include "SubDBenchOpenSubdiv.h"

#include <cstdio>
#include <map>
#include <vector>

namespace
{
using namespace OpenSubdiv;
using subdbench::Result;
using subdbench::Work;

// The atlas: per face corner a value (vertex, island), islands of 256 consecutive faces, each
// value the vertex's position projected on the plane of the island's first face's axes.
struct Atlas
{
  std::vector<int> ValueOfCorner;
  std::vector<int> VertexOfValue;
  std::vector<float> UV; // two per value
};

Atlas MakeAtlas(const subdbench::BenchMesh& mesh)
{
  Atlas atlas;
  std::map<std::pair<int, int>, int> valueOf;
  size_t corner = 0;
  for (size_t f = 0; f < mesh.Sizes.size(); ++f)
  {
    const int island = static_cast<int>(f / 256);
    const int axis = island % 3; // projected along x, y or z
    for (int k = 0; k < mesh.Sizes[f]; ++k, ++corner)
    {
      const int v = mesh.Corners[corner];
      const auto inserted = valueOf.emplace(std::make_pair(v, island), static_cast<int>(atlas.VertexOfValue.size()));
      if (inserted.second)
      {
        atlas.VertexOfValue.push_back(v);
        const double* p = &mesh.Points[3 * static_cast<size_t>(v)];
        atlas.UV.push_back(static_cast<float>(p[(axis + 1) % 3] + 10.0 * island));
        atlas.UV.push_back(static_cast<float>(p[(axis + 2) % 3]));
      }
      atlas.ValueOfCorner.push_back(inserted.first->second);
    }
  }
  return atlas;
}

// The mesh as VTK's OBJ reader gives it: a point per value, with "TCoords".
vtkSmartPointer<vtkPolyData> SplitMesh(const subdbench::BenchMesh& mesh, const Atlas& atlas)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(atlas.VertexOfValue.size()));
  vtkNew<vtkFloatArray> uv;
  uv->SetName("TCoords");
  uv->SetNumberOfComponents(2);
  uv->SetNumberOfTuples(points->GetNumberOfPoints());
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    points->SetPoint(i, &mesh.Points[3 * static_cast<size_t>(atlas.VertexOfValue[i])]);
    uv->SetTuple2(i, atlas.UV[2 * i], atlas.UV[2 * i + 1]);
  }
  vtkNew<vtkCellArray> polys;
  size_t corner = 0;
  for (int size : mesh.Sizes)
  {
    polys->InsertNextCell(size);
    for (int k = 0; k < size; ++k)
      polys->InsertCellPoint(atlas.ValueOfCorner[corner++]);
  }
  auto split = vtkSmartPointer<vtkPolyData>::New();
  split->SetPoints(points);
  split->SetPolys(polys);
  split->GetPointData()->SetTCoords(uv);
  return split;
}

Work RunFilter(vtkPolyData* input, int level, int threads)
{
  subdbench::StartThreads(threads);
  vtkNew<vtkSubDCatmullClarkFilter> filter;
  filter->SetInputData(input);
  filter->SetNumberOfSubdivisions(level);
  const subdbench::Clock::time_point start = subdbench::Clock::now();
  filter->Update();
  return { subdbench::SecondsSince(start), double(filter->GetOutput()->GetNumberOfPolys()),
    subdbench::OutputBytes(filter->GetOutput()) };
}

struct OsdUV
{
  float P[2];
  void Clear() { P[0] = P[1] = 0; }
  void AddWithWeight(const OsdUV& s, float w)
  {
    P[0] += w * s.P[0];
    P[1] += w * s.P[1];
  }
};

// OpenSubdiv's refinement with the channel: topology, points (double) and texture
// coordinates (float, as they come), CORNERS_PLUS1 as SubD's default.
Work RunOpenSubdiv(const subdbench::BenchMesh& mesh, const Atlas& atlas, int level)
{
  const subdbench::Clock::time_point start = subdbench::Clock::now();
  Far::TopologyDescriptor desc;
  desc.numVertices = mesh.NumVertices();
  desc.numFaces = static_cast<int>(mesh.Sizes.size());
  desc.numVertsPerFace = mesh.Sizes.data();
  desc.vertIndicesPerFace = mesh.Corners.data();
  Far::TopologyDescriptor::FVarChannel channel;
  channel.numValues = static_cast<int>(atlas.VertexOfValue.size());
  channel.valueIndices = atlas.ValueOfCorner.data();
  desc.numFVarChannels = 1;
  desc.fvarChannels = &channel;
  Sdc::Options options;
  options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
  options.SetFVarLinearInterpolation(Sdc::Options::FVAR_LINEAR_CORNERS_PLUS1);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(desc, Factory::Options(Sdc::SCHEME_CATMARK, options)));
  refiner->RefineUniform(Far::TopologyRefiner::UniformOptions(level));
  std::vector<subdbench::OsdPoint> points(static_cast<size_t>(refiner->GetNumVerticesTotal()));
  for (int v = 0; v < mesh.NumVertices(); ++v)
    for (int c = 0; c < 3; ++c)
      points[v].P[c] = mesh.Points[3 * v + c];
  std::vector<OsdUV> uv(static_cast<size_t>(refiner->GetNumFVarValuesTotal(0)));
  for (size_t i = 0; i < atlas.VertexOfValue.size(); ++i)
    uv[i] = OsdUV{ { atlas.UV[2 * i], atlas.UV[2 * i + 1] } };
  Far::PrimvarRefinerReal<double> primvar(*refiner);
  Far::PrimvarRefinerReal<float> primvarUV(*refiner);
  subdbench::OsdPoint* src = points.data();
  OsdUV* uvSrc = uv.data();
  for (int l = 1; l <= level; ++l)
  {
    subdbench::OsdPoint* dst = src + refiner->GetLevel(l - 1).GetNumVertices();
    OsdUV* uvDst = uvSrc + refiner->GetLevel(l - 1).GetNumFVarValues(0);
    primvar.Interpolate(l, src, dst);
    primvarUV.InterpolateFaceVarying(l, uvSrc, uvDst, 0);
    src = dst;
    uvSrc = uvDst;
  }
  return { subdbench::SecondsSince(start), double(refiner->GetLevel(level).GetNumFaces()) };
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
  const subdbench::BenchMesh& mesh = args.Mesh;
  const Atlas atlas = MakeAtlas(mesh);
  vtkSmartPointer<vtkPolyData> split = SplitMesh(mesh, atlas);
  std::printf("Catmull-Clark with texture coordinates on %s: %d points, %zu faces, %zu texture coordinates "
              "(islands of 256 faces); best of %d runs each\n",
    argv[1], mesh.NumVertices(), mesh.Sizes.size(), atlas.VertexOfValue.size(), args.Repeats);
  std::printf("%-5s %-36s %10s %9s%s\n", "level", "implementation", "seconds", "OSD/this", subdbench::MemoryHeader);
  for (int level = 1; level <= args.MaxLevel; ++level)
  {
    const std::vector<Result> results = subdbench::MeasureInterleaved(
      { [&] { return RunOpenSubdiv(mesh, atlas, level); }, [&] { return RunFilter(mesh.PolyData, level, 2); },
        [&] { return RunFilter(split, level, 2); }, [&] { return RunFilter(split, level, 1); } },
      args.Repeats);
    const Result &osd = results[0], &plain = results[1], &textured = results[2], &textured1 = results[3];
    auto row = [&](const char* name, const Result& r) {
      std::printf("%-5d %-36s %10.4f %9.2f", level, name, r.Seconds, osd.Seconds / r.Seconds);
      subdbench::PrintMemory(r);
      std::printf("\n");
    };
    row("OpenSubdiv Far + channel (1 thread)", osd);
    row("SubD filter, no channel (2 threads)", plain);
    row("SubD filter + channel (1 thread)", textured1);
    row("SubD filter + channel (2 threads)", textured);
    std::printf("%-5d channel cost (with / without, 2 threads): %.2fx time, %.2fx peak memory\n", level,
      textured.Seconds / plain.Seconds, textured.PeakMiB / plain.PeakMiB);
    if (textured.Faces != osd.Faces || plain.Faces != osd.Faces)
    {
      std::fprintf(stderr, "bench: face counts differ (%g, %g, %g)\n", osd.Faces, plain.Faces, textured.Faces);
      return 1;
    }
  }
  return 0;
}
