// Benchmark (a program, not a test): every SubD surface scheme against every peer from
// Debian that implements it, measured in the same run on the same mesh:
//   OpenSubdiv Far (Loop), CGAL 5.5 (Loop, Doo-Sabin, sqrt(3)), OpenMesh 9 (Loop, modified
//   butterfly, sqrt(3), midpoint) and VTK 9.1 (Loop, butterfly, linear).
// Each timing starts from the mesh as flat arrays and includes building the implementation's
// own mesh structure, refinement and point computation (what a user waits for); each runs in
// a forked child (own peak RSS), best of `repeats`, the implementations' runs interleaved
// (subdbench::MeasureInterleaved). Prints seconds, output faces per second, peak RSS and, per
// scheme, the ratio fastest peer time / SubD time (2 threads).
//
//   usage: BenchSchemes mesh.off [maxLevel=3] [repeats=3] [scheme,scheme,...]
#include "SubDBenchOpenSubdiv.h"

#include "vtkSubDButterflyFilter.h"
#include "vtkSubDDooSabinFilter.h"
#include "vtkSubDLinearFilter.h"
#include "vtkSubDLoopFilter.h"
#include "vtkSubDMidpointFilter.h"
#include "vtkSubDOFFReader.h"
#include "vtkSubDSqrt3Filter.h"

#include "vtkButterflySubdivisionFilter.h"
#include "vtkCellArray.h"
#include "vtkLinearSubdivisionFilter.h"
#include "vtkLoopSubdivisionFilter.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/MidpointT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/ModifiedButterFlyT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/Sqrt3T.hh>


#include <memory>
#include <string>
#include <vector>

namespace
{
using subdbench::Clock;
using subdbench::Result;
using subdbench::SecondsSince;
using subdbench::Work;

using Mesh = subdbench::BenchMesh;

template <typename Filter>
Work RunFilter(const Mesh& mesh, int level)
{
  const Clock::time_point start = Clock::now();
  vtkNew<Filter> filter;
  filter->SetInputData(mesh.PolyData);
  filter->SetNumberOfSubdivisions(level);
  filter->Update();
  return { SecondsSince(start), double(filter->GetOutput()->GetNumberOfPolys()),
    subdbench::OutputBytes(filter->GetOutput()) };
}

template <typename Filter>
Work RunSubD(const Mesh& mesh, int level, int threads)
{
  subdbench::StartThreads(threads);
  return RunFilter<Filter>(mesh, level);
}

using CgalMesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;
template <typename Subdivide>
Work RunCgal(const Mesh& mesh, int level, Subdivide subdivide)
{
  const Clock::time_point start = Clock::now();
  CgalMesh m;
  std::vector<CgalMesh::Vertex_index> vertices;
  for (int v = 0; v < mesh.NumVertices(); ++v)
    vertices.push_back(m.add_vertex({ mesh.Points[3 * v], mesh.Points[3 * v + 1], mesh.Points[3 * v + 2] }));
  std::vector<CgalMesh::Vertex_index> face;
  for (size_t f = 0, k = 0; f < mesh.Sizes.size(); ++f)
  {
    face.clear();
    for (int j = 0; j < mesh.Sizes[f]; ++j)
      face.push_back(vertices[mesh.Corners[k++]]);
    m.add_face(face);
  }
  subdivide(m, CGAL::parameters::number_of_iterations(level));
  return { SecondsSince(start), double(m.number_of_faces()) };
}

struct OMTraits : OpenMesh::DefaultTraits
{
  using Point = OpenMesh::Vec3d;
};
template <typename OMMesh, typename Subdivider>
Work RunOpenMesh(const Mesh& mesh, int level)
{
  const Clock::time_point start = Clock::now();
  OMMesh m;
  std::vector<typename OMMesh::VertexHandle> vertices;
  for (int v = 0; v < mesh.NumVertices(); ++v)
    vertices.push_back(m.add_vertex({ mesh.Points[3 * v], mesh.Points[3 * v + 1], mesh.Points[3 * v + 2] }));
  std::vector<typename OMMesh::VertexHandle> face;
  for (size_t f = 0, k = 0; f < mesh.Sizes.size(); ++f)
  {
    face.clear();
    for (int j = 0; j < mesh.Sizes[f]; ++j)
      face.push_back(vertices[mesh.Corners[k++]]);
    m.add_face(face);
  }
  Subdivider subdivider;
  subdivider.attach(m);
  subdivider(static_cast<size_t>(level));
  subdivider.detach();
  return { SecondsSince(start), double(m.n_faces()) };
}
using OMTri = OpenMesh::TriMesh_ArrayKernelT<OMTraits>;
using OMPoly = OpenMesh::PolyMesh_ArrayKernelT<OMTraits>;

Work RunOpenSubdivLoop(const Mesh& mesh, int level)
{
  return subdbench::RunOpenSubdiv(mesh, level, OpenSubdiv::Sdc::SCHEME_LOOP);
}

struct Peer
{
  std::string Name;
  std::function<Work(const Mesh&, int)> Run;
};

struct SchemeBench
{
  std::string Name;
  std::function<Work(const Mesh&, int, int)> SubD;
  std::vector<Peer> Peers;
};
}

int main(int argc, char* argv[])
{
  subdbench::BenchArguments args;
  int status = 0;
  if (!subdbench::ReadBenchArguments(argc, argv, 3, args, status))
  {
    return status;
  }
  const int maxLevel = args.MaxLevel;
  const int repeats = args.Repeats;
  const Mesh& mesh = args.Mesh;

  const std::vector<SchemeBench> schemes = {
    { "loop", RunSubD<vtkSubDLoopFilter>,
      { { "OpenSubdiv Far", RunOpenSubdivLoop },
        { "CGAL", [](const Mesh& m, int l) { return RunCgal(m, l, [](CgalMesh& x, auto p) { CGAL::Subdivision_method_3::Loop_subdivision(x, p); }); } },
        { "OpenMesh", RunOpenMesh<OMTri, OpenMesh::Subdivider::Uniform::LoopT<OMTri>> },
        { "VTK", RunFilter<vtkLoopSubdivisionFilter> } } },
    { "butterfly", RunSubD<vtkSubDButterflyFilter>,
      { { "OpenMesh", RunOpenMesh<OMTri, OpenMesh::Subdivider::Uniform::ModifiedButterflyT<OMTri>> },
        { "VTK", RunFilter<vtkButterflySubdivisionFilter> } } },
    { "sqrt3", RunSubD<vtkSubDSqrt3Filter>,
      { { "CGAL", [](const Mesh& m, int l) { return RunCgal(m, l, [](CgalMesh& x, auto p) { CGAL::Subdivision_method_3::Sqrt3_subdivision(x, p); }); } },
        { "OpenMesh", RunOpenMesh<OMTri, OpenMesh::Subdivider::Uniform::Sqrt3T<OMTri>> } } },
    { "doo-sabin", RunSubD<vtkSubDDooSabinFilter>,
      { { "CGAL", [](const Mesh& m, int l) { return RunCgal(m, l, [](CgalMesh& x, auto p) { CGAL::Subdivision_method_3::DooSabin_subdivision(x, p); }); } } } },
    { "midpoint", RunSubD<vtkSubDMidpointFilter>,
      { { "OpenMesh", RunOpenMesh<OMPoly, OpenMesh::Subdivider::Uniform::MidpointT<OMPoly>> } } },
    { "linear", RunSubD<vtkSubDLinearFilter>, { { "VTK", RunFilter<vtkLinearSubdivisionFilter> } } },
  };

  std::printf("Surface schemes on %s: %d points, %zu faces; best of %d runs each (%d for runs under %.1f s)\n", argv[1],
    mesh.NumVertices(), mesh.Sizes.size(), repeats, std::max(repeats, subdbench::ShortRunRepeats),
    subdbench::ShortRunSeconds);
  const std::string only = argc > 4 ? "," + std::string(argv[4]) + "," : "";
  std::printf("%-10s %-5s %-22s %10s %12s%s\n", "scheme", "level", "implementation", "seconds", "faces/s",
    subdbench::MemoryHeader);
  for (const SchemeBench& scheme : schemes)
  {
    if (!only.empty() && only.find("," + scheme.Name + ",") == std::string::npos)
    {
      continue;
    }
    for (int level = 1; level <= maxLevel; ++level)
    {
      auto row = [&](const std::string& name, const Result& r) {
        std::printf("%-10s %-5d %-22s %10.4f %12.3g", scheme.Name.c_str(), level, name.c_str(), r.Seconds,
          r.Faces / r.Seconds);
        subdbench::PrintMemory(r);
        std::printf("\n");
      };
      // SubD on 1 and 2 threads and each peer, interleaved.
      std::vector<std::function<Work()>> works = { [&] { return scheme.SubD(mesh, level, 1); },
        [&] { return scheme.SubD(mesh, level, 2); } };
      for (const Peer& peer : scheme.Peers)
      {
        works.push_back([&] { return peer.Run(mesh, level); });
      }
      const std::vector<Result> results = subdbench::MeasureInterleaved(works, repeats);
      const Result& one = results[0];
      const Result& two = results[1];
      row("SubD (1 thread)", one);
      row("SubD (2 threads)", two);
      double fastestPeer = 1e300;
      std::string fastestName;
      for (size_t p = 0; p < scheme.Peers.size(); ++p)
      {
        const Result& r = results[2 + p];
        row(scheme.Peers[p].Name, r);
        if (r.Seconds < fastestPeer)
        {
          fastestPeer = r.Seconds;
          fastestName = scheme.Peers[p].Name;
        }
      }
      std::printf("%-10s %-5d ratio fastest peer (%s) / SubD 2 threads: %.2f, / SubD 1 thread: %.2f\n",
        scheme.Name.c_str(), level, fastestName.c_str(), fastestPeer / two.Seconds, fastestPeer / one.Seconds);
    }
  }
  return 0;
}
