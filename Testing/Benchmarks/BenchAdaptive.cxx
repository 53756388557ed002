// Benchmark of the adaptive tessellation of the limit surface (vtkSubDLimitFilter, ADAPTIVE)
// against the uniform tessellation that meets the same tolerance. No peer offers an adaptive
// limit tessellation with a bound on the error, so the ratios are against SubD's own uniform
// one: the triangles it needs for the same accuracy, and its time.
//
//   BenchAdaptive MESH.off|builtin:NAME [catmull-clark|loop]
//
// For each tolerance (1e-2, 1e-3, 1e-4 of the cage's diagonal): the adaptive triangles and
// time; the coarsest uniform resolution within the same tolerance, its triangles and time; and
// the time to tessellate again after the cage's points move (the explorer's and animation's
// case). The uniform error is measured as the adaptive one is: at every cell's side
// midpoints, centre and the centroids of its triangles (the better diagonal), the distance
// along the limit's normal from the chord to the surface. It is searched for on the faces the
// adaptive tessellation refined deepest (they bind the uniform resolution), between the
// resolutions of that level and the one below.
#include "SubDBenchSupport.h"
#include "SubDBuiltinCages.h"
#include "vtkSubDLimitFilter.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"

#include <array>
#include <cmath>
#include <set>
#include <string>

namespace
{
using subdbench::Clock;
using subdbench::SecondsSince;

struct Location
{
  vtkIdType Cell;
  double U, V;
  int SubFace;
};

vtkSmartPointer<vtkPolyData> Run(vtkPolyData* cage, int scheme, int tessellation, double tolerance, int resolution,
  vtkPolyData* locations = nullptr)
{
  vtkNew<vtkSubDLimitFilter> limit;
  limit->SetInputData(cage);
  if (locations)
  {
    limit->SetInputData(1, locations);
  }
  limit->SetScheme(scheme);
  limit->SetTessellation(tessellation);
  limit->SetTolerance(tolerance);
  limit->SetResolution(resolution);
  limit->Update();
  return limit->GetOutput();
}

// The limit's points and normals at `at`.
vtkSmartPointer<vtkPolyData> Evaluate(vtkPolyData* cage, int scheme, const std::vector<Location>& at)
{
  vtkNew<vtkPolyData> locations;
  vtkNew<vtkPoints> points;
  points->SetNumberOfPoints(static_cast<vtkIdType>(at.size()));
  vtkNew<vtkIdTypeArray> ids, sub;
  vtkNew<vtkDoubleArray> uv;
  ids->SetName("FaceId");
  sub->SetName("SubFace");
  uv->SetName("FaceUV");
  uv->SetNumberOfComponents(2);
  for (const Location& l : at)
  {
    ids->InsertNextValue(l.Cell);
    sub->InsertNextValue(l.SubFace);
    uv->InsertNextTuple2(l.U, l.V);
  }
  locations->SetPoints(points);
  locations->GetPointData()->AddArray(ids);
  locations->GetPointData()->AddArray(uv);
  locations->GetPointData()->AddArray(sub);
  vtkSmartPointer<vtkPolyData> out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(Run(cage, scheme, vtkSubDLimitFilter::UNIFORM, 0, 1, locations));
  return out;
}

using Vec = std::array<double, 3>;
Vec At(vtkPolyData* p, vtkIdType i)
{
  Vec v;
  p->GetPoint(i, v.data());
  return v;
}
// The distance along the normal at sample s from the chord point q to the surface.
double Off(vtkPolyData* p, vtkIdType s, const Vec& q)
{
  const Vec x = At(p, s);
  double n[3];
  p->GetPointData()->GetNormals()->GetTuple(s, n);
  return std::abs((q[0] - x[0]) * n[0] + (q[1] - x[1]) * n[1] + (q[2] - x[2]) * n[2]);
}
Vec Mean(std::initializer_list<Vec> points)
{
  Vec m{ 0, 0, 0 };
  for (const Vec& p : points)
    for (int j = 0; j < 3; ++j)
      m[j] += p[j] / points.size();
  return m;
}

// The largest error of the uniform tessellation at `resolution` over the cells `cells` of the
// cage (quads and Catmull-Clark polygons: a grid of quads per face or corner; Loop triangles:
// the triangle grid).
double UniformError(vtkPolyData* cage, int scheme, const std::set<vtkIdType>& cells, int resolution)
{
  std::vector<Location> at;
  std::vector<int> kinds; // per cell: 4 a quad grid cell, 3 an upward and 5 a downward triangle
  for (vtkIdType cell : cells)
  {
    const vtkIdType size = cage->GetCell(cell)->GetNumberOfPoints();
    const bool triangles = scheme == vtkSubDLimitFilter::LOOP;
    const int subFaces = triangles || size == 4 ? 1 : static_cast<int>(size);
    const int n = subFaces == 1 ? resolution : (resolution + 1) / 2;
    for (int k = 0; k < subFaces; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
        {
          auto add = [&](double u, double v) { at.push_back({ cell, u / n, v / n, k }); };
          if (!triangles)
          {
            kinds.push_back(4); // corners, side midpoints, centre, four centroids
            for (const auto& p : { Vec{ 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 }, { .5, 0 }, { 1, .5 }, { .5, 1 }, { 0, .5 },
                   { .5, .5 }, { 2. / 3, 1. / 3 }, { 1. / 3, 2. / 3 }, { 2. / 3, 2. / 3 }, { 1. / 3, 1. / 3 } })
              add(i + p[0], j + p[1]);
            continue;
          }
          for (int down = 0; down < 2 && i + j + down < n; ++down)
          {
            kinds.push_back(down ? 5 : 3); // corners, side midpoints, centroid
            const double s = down ? -1 : 1, u0 = down ? i + 1 : i, v0 = down ? j + 1 : j;
            for (const auto& p : { Vec{ 0, 0 }, { s, 0 }, { 0, s }, { s / 2, 0 }, { s / 2, s / 2 }, { 0, s / 2 },
                   { s / 3, s / 3 } })
              add(u0 + p[0], v0 + p[1]);
          }
        }
  }
  vtkSmartPointer<vtkPolyData> p = Evaluate(cage, scheme, at);
  double worst = 0;
  vtkIdType s = 0;
  for (int kind : kinds)
  {
    if (kind == 4)
    {
      const Vec c[4] = { At(p, s), At(p, s + 1), At(p, s + 2), At(p, s + 3) };
      double sides = 0;
      for (int k = 0; k < 4; ++k)
        sides = std::max(sides, Off(p, s + 4 + k, Mean({ c[k], c[(k + 1) % 4] })));
      const double first = std::max({ Off(p, s + 8, Mean({ c[0], c[2] })), Off(p, s + 9, Mean({ c[0], c[1], c[2] })),
        Off(p, s + 10, Mean({ c[0], c[2], c[3] })) });
      const double second = std::max({ Off(p, s + 8, Mean({ c[1], c[3] })), Off(p, s + 11, Mean({ c[1], c[2], c[3] })),
        Off(p, s + 12, Mean({ c[1], c[3], c[0] })) });
      worst = std::max({ worst, sides, std::min(first, second) });
      s += 13;
      continue;
    }
    const Vec c[3] = { At(p, s), At(p, s + 1), At(p, s + 2) };
    for (int k = 0; k < 3; ++k)
      worst = std::max(worst, Off(p, s + 3 + k, Mean({ c[k], c[(k + 1) % 3] })));
    worst = std::max(worst, Off(p, s + 6, Mean({ c[0], c[1], c[2] })));
    s += 7;
  }
  return worst;
}

// The triangles of the uniform tessellation at `resolution` (Catmull-Clark: two per quad; a
// cage with other polygons than quads takes an even resolution, half of it per corner).
double UniformTriangles(vtkPolyData* cage, int scheme, int resolution)
{
  bool polygons = false;
  for (vtkIdType c = 0; c < cage->GetNumberOfCells() && scheme == vtkSubDLimitFilter::CATMULL_CLARK; ++c)
    polygons = polygons || (cage->GetCellType(c) != VTK_VERTEX && cage->GetCellType(c) != VTK_LINE &&
      cage->GetCell(c)->GetNumberOfPoints() != 4);
  const double r = polygons ? 2 * ((resolution + 1) / 2) : resolution;
  double triangles = 0;
  for (vtkIdType c = 0; c < cage->GetNumberOfCells(); ++c)
  {
    const vtkIdType size = cage->GetCell(c)->GetNumberOfPoints();
    if (size < 3)
      continue;
    triangles += scheme == vtkSubDLimitFilter::LOOP ? r * r : (size == 4 ? 2 * r * r : size * 2 * (r / 2) * (r / 2));
  }
  return triangles;
}

// Moves every cage point a little (a deterministic wave), as an animation or an edit would.
void Move(vtkPolyData* cage, double amount)
{
  vtkPoints* points = cage->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    points->SetPoint(i, p[0] + amount * std::sin(3 * p[1]), p[1], p[2] + amount * std::cos(2 * p[0]));
  }
  points->Modified();
}
}

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::fprintf(stderr, "usage: BenchAdaptive MESH.off|builtin:NAME [catmull-clark|loop]\n");
    return 2;
  }
  const std::string name = argv[1];
  const int scheme = argc > 2 && std::string(argv[2]) == "loop" ? vtkSubDLimitFilter::LOOP : vtkSubDLimitFilter::CATMULL_CLARK;
  vtkSmartPointer<vtkPolyData> cage;
  if (name.rfind("builtin:", 0) == 0)
  {
    cage = subdapp::MakeBuiltinCage(name.substr(8));
  }
  else
  {
    subdbench::BenchMesh mesh;
    if (!subdbench::ReadBenchMesh(name.c_str(), mesh))
      return 1;
    cage = mesh.PolyData;
  }
  if (!cage)
  {
    std::fprintf(stderr, "BenchAdaptive: no cage '%s'\n", name.c_str());
    return 1;
  }
  subdbench::StartThreads(0);
  const double diagonal = cage->GetLength();
  std::printf("%s, %s limit, %lld faces, %d threads\n", name.c_str(), scheme == vtkSubDLimitFilter::LOOP ? "loop" : "catmull-clark",
    static_cast<long long>(cage->GetNumberOfPolys()), vtkSMPTools::GetEstimatedNumberOfThreads());
  std::printf("%-9s %12s %9s %11s %12s %9s %9s %12s\n", "tolerance", "adaptive", "time s", "uniform R", "uniform",
    "time s", "tri ratio", "re-tessel. s");
  for (double tolerance : { 1e-2, 1e-3, 1e-4 })
  {
    Clock::time_point start = Clock::now();
    vtkSmartPointer<vtkPolyData> adaptive = Run(cage, scheme, vtkSubDLimitFilter::ADAPTIVE, tolerance, 1);
    const double adaptiveSeconds = SecondsSince(start);
    // The cells refined deepest bind the uniform resolution.
    vtkDataArray* levels = adaptive->GetCellData()->GetArray("RefineLevel");
    vtkDataArray* faces = adaptive->GetCellData()->GetArray("FaceId");
    const int deepest = static_cast<int>(levels->GetRange()[1]);
    std::set<vtkIdType> binding;
    for (vtkIdType c = 0; c < adaptive->GetNumberOfCells(); ++c)
      if (levels->GetComponent(c, 0) == deepest)
        binding.insert(static_cast<vtkIdType>(faces->GetComponent(c, 0)));
    int low = deepest > 0 ? (1 << (deepest - 1)) : 1, high = 1 << deepest; // low fails (or is 1), high holds
    while (low + 1 < high)
    {
      const int mid = (low + high) / 2;
      (UniformError(cage, scheme, binding, mid) <= tolerance * diagonal ? high : low) = mid;
    }
    const int resolution = low == 1 && UniformError(cage, scheme, binding, 1) <= tolerance * diagonal ? 1 : high;
    const double uniformTriangles = UniformTriangles(cage, scheme, resolution);
    double uniformSeconds = -1; // not run: too large for this machine's memory
    if (uniformTriangles < 2e7)
    {
      start = Clock::now();
      Run(cage, scheme, vtkSubDLimitFilter::UNIFORM, 0, resolution);
      uniformSeconds = SecondsSince(start);
    }
    vtkNew<vtkPolyData> moved;
    moved->DeepCopy(cage);
    Move(moved, 1e-3 * diagonal);
    start = Clock::now();
    Run(moved, scheme, vtkSubDLimitFilter::ADAPTIVE, tolerance, 1);
    const double again = SecondsSince(start);
    std::printf("%-9g %12lld %9.2f %11d %12.0f %9.2f %9.2f %12.2f\n", tolerance,
      static_cast<long long>(adaptive->GetNumberOfCells()), adaptiveSeconds, resolution, uniformTriangles,
      uniformSeconds, uniformTriangles / adaptive->GetNumberOfCells(), again);
  }
  return 0;
}
