// Filter tests of vtkSubDLimitFilter's adaptive and selective tessellations: watertight,
// within the tolerance of a dense exact tessellation of the limit surface, economical where
// the surface is flat, equal to the uniform tessellation where a face asks for a level, and
// clear about bad requests.
#include "SubDFilterTestSupport.h"
#include "SubDTempFiles.h"
#include "SubDTexturedCube.h"
#include "vtkSubDCatmullClarkFilter.h"
#include "vtkSubDLimitFilter.h"
#include "vtkSubDOBJReader.h"

#include "vtkCellData.h"
#include "vtkCellLocator.h"
#include "vtkCleanPolyData.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTriangleFilter.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>

namespace
{
using subdtest::OpenOrNonManifoldEdges;
using subdtest::ToPolyData;

struct Cage
{
  std::string Name;
  vtkSmartPointer<vtkPolyData> Mesh;
  bool Loop;
  bool Closed;
};

vtkSmartPointer<vtkPolyData> Tessellate(vtkPolyData* cage, bool loop, int mode, double tolerance = 1e-3,
  int resolution = 4)
{
  vtkNew<vtkSubDLimitFilter> limit;
  limit->SetInputData(cage);
  limit->SetScheme(loop ? vtkSubDLimitFilter::LOOP : vtkSubDLimitFilter::CATMULL_CLARK);
  limit->SetTessellation(mode);
  limit->SetTolerance(tolerance);
  limit->SetResolution(resolution);
  limit->ComputeLocationsOn();
  limit->Update();
  vtkNew<vtkTriangleFilter> triangles; // uniform Catmull-Clark gives quads: count triangles
  triangles->SetInputData(limit->GetOutput());
  triangles->Update();
  return triangles->GetOutput();
}

// The largest distance from a point of a triangle (its corners, edge midpoints, centroid) of
// `mesh` to `reference`, a dense tessellation of the surface.
double LargestDistanceTo(vtkPolyData* mesh, vtkPolyData* reference)
{
  vtkNew<vtkCellLocator> locator;
  locator->SetDataSet(reference);
  locator->BuildLocator();
  double worst = 0.0;
  const std::vector<std::vector<vtkIdType>> faces = subdtest::Faces(mesh);
  for (const std::vector<vtkIdType>& f : faces)
  {
    std::array<std::array<double, 3>, 3> p;
    for (int i = 0; i < 3; ++i)
      mesh->GetPoint(f[i], p[i].data());
    std::vector<std::array<double, 3>> samples(p.begin(), p.end());
    std::array<double, 3> centroid{ 0, 0, 0 };
    for (int i = 0; i < 3; ++i)
    {
      std::array<double, 3> mid;
      for (int j = 0; j < 3; ++j)
      {
        mid[j] = 0.5 * (p[i][j] + p[(i + 1) % 3][j]);
        centroid[j] += p[i][j] / 3.0;
      }
      samples.push_back(mid);
    }
    samples.push_back(centroid);
    for (const auto& s : samples)
    {
      double closest[3], distance2;
      vtkIdType cell;
      int sub;
      locator->FindClosestPoint(s.data(), closest, cell, sub, distance2);
      worst = std::max(worst, std::sqrt(distance2));
    }
  }
  return worst;
}

// A cube with sharp features: a semi-sharp crease loop around one face, an infinitely sharp
// edge, a semi-sharp corner.
vtkSmartPointer<vtkPolyData> CreasedCube(bool triangles)
{
  subdtest::TestMesh cube = subdtest::Cube().Jitter(0.1);
  vtkSmartPointer<vtkPolyData> mesh = ToPolyData(triangles ? cube.Triangulated() : cube);
  const subd::Index* f = &cube.Vertices[cube.Offsets[0]];
  std::vector<std::array<vtkIdType, 2>> edges;
  for (int k = 0; k < 4; ++k)
    edges.push_back({ f[k], f[(k + 1) % 4] });
  const subd::Index* g = &cube.Vertices[cube.Offsets[3]];
  edges.push_back({ g[1], g[2] });
  subdtest::AddCreases(mesh, edges, { 1.5f, 1.5f, 1.5f, 1.5f, 10.0f });
  subdtest::AddCornerSharpness(mesh, { { g[3], 2.2f } });
  return mesh;
}

// A cube with a hole in one face.
vtkSmartPointer<vtkPolyData> HoledCube()
{
  vtkSmartPointer<vtkPolyData> mesh = ToPolyData(subdtest::Cube().Jitter(0.1));
  vtkNew<vtkIntArray> hole;
  hole->SetName("Hole");
  hole->SetNumberOfTuples(mesh->GetNumberOfCells());
  hole->Fill(0);
  hole->SetValue(2, 1);
  mesh->GetCellData()->AddArray(hole);
  return mesh;
}

std::vector<Cage> Cages()
{
  std::vector<Cage> cages;
  for (int n : { 3, 5, 6, 8 })
  {
    const subdtest::TestMesh star = subdtest::Star(n).Jitter(0.05);
    cages.push_back({ star.Name, ToPolyData(star), false, true });
    cages.push_back({ star.Name + "-tri", ToPolyData(star.Triangulated()), true, true });
  }
  cages.push_back({ "cube", ToPolyData(subdtest::Cube()), false, true });
  cages.push_back({ "house", ToPolyData(subdtest::House(false).Jitter(0.05)), false, true });
  cages.push_back({ "open-house", ToPolyData(subdtest::House(true).Jitter(0.05)), false, false });
  cages.push_back({ "open-house-tri", ToPolyData(subdtest::House(true).Jitter(0.05).Triangulated()), true, false });
  cages.push_back({ "creased-cube", CreasedCube(false), false, true });
  cages.push_back({ "creased-cube-tri", CreasedCube(true), true, true });
  cages.push_back({ "holed-cube", HoledCube(), false, false });
  return cages;
}

// A box with rounded rims, as a modeller makes one: each side a grid of quads, `divisions`
// across its flat middle, with support loops at `inset` close to the rims, so that most faces
// are flat.
vtkSmartPointer<vtkPolyData> RoundedBox(double inset, int divisions)
{
  std::vector<double> at{ -1.0 };
  for (int i = 0; i <= divisions; ++i)
    at.push_back(-inset + 2.0 * inset * i / divisions);
  at.push_back(1.0);
  const int n = static_cast<int>(at.size()) - 1;
  subdtest::TestMesh box;
  std::map<std::array<long, 3>, subd::Index> index;
  auto point = [&](std::array<double, 3> p) {
    const std::array<long, 3> key{ std::lround(p[0] * 1e6), std::lround(p[1] * 1e6), std::lround(p[2] * 1e6) };
    auto found = index.emplace(key, box.NumVertices());
    if (found.second)
      box.AddPoint(p[0], p[1], p[2]);
    return found.first->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side : { -1, 1 })
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
        {
          std::vector<subd::Index> quad;
          for (const auto& c : { std::array<int, 2>{ i, j }, { i + 1, j }, { i + 1, j + 1 }, { i, j + 1 } })
          {
            std::array<double, 3> p;
            p[axis] = side;
            p[(axis + 1) % 3] = at[c[0]];
            p[(axis + 2) % 3] = at[c[1]];
            quad.push_back(point(p));
          }
          if (side < 0)
            std::reverse(quad.begin(), quad.end());
          box.AddFace(quad);
        }
  return ToPolyData(box);
}
}

TEST(AdaptiveTessellation, WatertightAndWithinTheToleranceOfTheLimit)
{
  for (const Cage& cage : Cages())
  {
    // The reference: a uniform tessellation fine enough that its own chords are far inside
    // the tolerances below.
    vtkSmartPointer<vtkPolyData> dense = Tessellate(cage.Mesh, cage.Loop, vtkSubDLimitFilter::UNIFORM, 0, 64);
    const double diagonal = cage.Mesh->GetLength();
    for (double tolerance : { 1e-2, 2e-3 })
    {
      vtkSmartPointer<vtkPolyData> out = Tessellate(cage.Mesh, cage.Loop, vtkSubDLimitFilter::ADAPTIVE, tolerance);
      ASSERT_GT(out->GetNumberOfCells(), 0) << cage.Name;
      if (cage.Closed)
      {
        EXPECT_EQ(OpenOrNonManifoldEdges(out), 0) << cage.Name << " " << tolerance << ": cracks";
      }
      EXPECT_LE(LargestDistanceTo(out, dense), tolerance * diagonal) << cage.Name << " " << tolerance;
      // A tighter tolerance takes more triangles.
      if (tolerance < 1e-2)
      {
        EXPECT_GT(out->GetNumberOfCells(),
          Tessellate(cage.Mesh, cage.Loop, vtkSubDLimitFilter::ADAPTIVE, 1e-2)->GetNumberOfCells())
          << cage.Name;
      }
    }
  }
}

// On a cage with large flat regions next to tight rounding, the adaptive tessellation takes
// at most half the triangles of the coarsest uniform tessellation within the same tolerance.
TEST(AdaptiveTessellation, FlatRegionsTakeFewTriangles)
{
  vtkSmartPointer<vtkPolyData> box = RoundedBox(0.9, 4);
  const double diagonal = box->GetLength();
  vtkSmartPointer<vtkPolyData> dense = Tessellate(box, false, vtkSubDLimitFilter::UNIFORM, 0, 64);
  for (double tolerance : { 1e-3, 3e-4 })
  {
    vtkSmartPointer<vtkPolyData> adaptive = Tessellate(box, false, vtkSubDLimitFilter::ADAPTIVE, tolerance);
    EXPECT_EQ(OpenOrNonManifoldEdges(adaptive), 0);
    EXPECT_LE(LargestDistanceTo(adaptive, dense), tolerance * diagonal);
    int resolution = 1;
    vtkSmartPointer<vtkPolyData> uniform;
    for (;; ++resolution)
    {
      uniform = Tessellate(box, false, vtkSubDLimitFilter::UNIFORM, 0, resolution);
      if (LargestDistanceTo(uniform, dense) <= tolerance * diagonal)
        break;
    }
    EXPECT_LE(2 * adaptive->GetNumberOfCells(), uniform->GetNumberOfCells())
      << "tolerance " << tolerance << ": uniform resolution " << resolution;
    std::printf("rounded box, tolerance %g: adaptive %lld triangles, uniform (resolution %d) %lld\n", tolerance,
      static_cast<long long>(adaptive->GetNumberOfCells()), resolution,
      static_cast<long long>(uniform->GetNumberOfCells()));
  }
}

// Faces asking for level L are tessellated as the uniform tessellation at resolution 2^L
// tessellates them; the transitions to coarser faces are crack-free. (The faces asking for a
// level here have no finer neighbour, whose points on their common edge they would take.)
TEST(AdaptiveTessellation, SelectiveEqualsUniformWhereAsked)
{
  struct Case
  {
    vtkSmartPointer<vtkPolyData> Mesh;
    bool Loop;
    std::map<vtkIdType, int> Levels; // cell id -> level; others 0
  };
  const subdtest::TestMesh star = subdtest::Star(5).Jitter(0.05);
  const std::vector<Case> cases = { { ToPolyData(subdtest::Cube().Jitter(0.1)), false, { { 0, 3 }, { 1, 2 } } },
    { ToPolyData(star), false, { { 0, 2 }, { 2, 3 } } }, // the pentagon cap and a roof triangle
    { ToPolyData(star.Triangulated()), true, { { 0, 3 }, { 4, 1 } } } };
  for (const Case& c : cases)
  {
    vtkNew<vtkIntArray> levels;
    levels->SetName("RefineLevel");
    levels->SetNumberOfTuples(c.Mesh->GetNumberOfCells());
    levels->Fill(0);
    for (const auto& l : c.Levels)
      levels->SetValue(l.first, l.second);
    c.Mesh->GetCellData()->AddArray(levels);
    vtkSmartPointer<vtkPolyData> out = Tessellate(c.Mesh, c.Loop, vtkSubDLimitFilter::SELECTIVE);
    EXPECT_EQ(OpenOrNonManifoldEdges(out), 0) << "cracks";
    for (const auto& l : c.Levels)
    {
      vtkSmartPointer<vtkPolyData> uniform = Tessellate(c.Mesh, c.Loop, vtkSubDLimitFilter::UNIFORM, 0, 1 << l.second);
      // The points of the face's cells, in both tessellations.
      auto facePoints = [&l](vtkPolyData* mesh) {
        vtkDataArray* face = mesh->GetCellData()->GetArray("FaceId");
        std::set<vtkIdType> ids;
        const std::vector<std::vector<vtkIdType>> cells = subdtest::Faces(mesh);
        for (size_t i = 0; i < cells.size(); ++i)
          if (face->GetComponent(static_cast<vtkIdType>(i), 0) == l.first)
            ids.insert(cells[i].begin(), cells[i].end());
        vtkNew<vtkPoints> points;
        for (vtkIdType id : ids)
          points->InsertNextPoint(mesh->GetPoint(id));
        auto result = vtkSmartPointer<vtkPolyData>::New();
        result->SetPoints(points);
        return result;
      };
      vtkSmartPointer<vtkPolyData> mine = facePoints(out), theirs = facePoints(uniform);
      EXPECT_EQ(mine->GetNumberOfPoints(), theirs->GetNumberOfPoints()) << "cell " << l.first;
      EXPECT_LT(subdtest::LargestDistanceToNearestPoint(mine, theirs), 1e-12) << "cell " << l.first;
      EXPECT_LT(subdtest::LargestDistanceToNearestPoint(theirs, mine), 1e-12) << "cell " << l.first;
    }
  }
}

// The locations the points were evaluated at give the same points again, with the same point
// data, through the locations input.
TEST(AdaptiveTessellation, LocationsEvaluateToTheSamePoints)
{
  vtkSmartPointer<vtkPolyData> cage = CreasedCube(false);
  vtkNew<vtkDoubleArray> data;
  data->SetName("Data");
  data->SetNumberOfTuples(cage->GetNumberOfPoints());
  for (vtkIdType i = 0; i < cage->GetNumberOfPoints(); ++i)
    data->SetValue(i, std::sin(3.0 * i));
  cage->GetPointData()->AddArray(data);
  vtkNew<vtkSubDLimitFilter> adaptive;
  adaptive->SetInputData(cage);
  adaptive->SetTessellationToAdaptive();
  adaptive->SetTolerance(3e-3);
  adaptive->ComputeLocationsOn();
  adaptive->Update();
  vtkPolyData* out = adaptive->GetOutput();
  ASSERT_GT(out->GetNumberOfPoints(), 0);
  vtkNew<vtkSubDLimitFilter> again;
  again->SetInputData(cage);
  again->SetLocationsConnection(adaptive->GetOutputPort());
  again->Update();
  vtkPolyData* points = again->GetOutput();
  ASSERT_EQ(points->GetNumberOfPoints(), out->GetNumberOfPoints());
  vtkDataArray* before = out->GetPointData()->GetArray("Data");
  vtkDataArray* after = points->GetPointData()->GetArray("Data");
  ASSERT_NE(before, nullptr);
  ASSERT_NE(after, nullptr);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    out->GetPoint(i, p);
    points->GetPoint(i, q);
    for (int j = 0; j < 3; ++j)
      EXPECT_EQ(p[j], q[j]) << "point " << i;
    EXPECT_EQ(before->GetComponent(i, 0), after->GetComponent(i, 0)) << "point " << i;
  }
}

TEST(AdaptiveTessellation, BadRequestsGiveClearErrors)
{
  vtkSmartPointer<vtkPolyData> cage = ToPolyData(subdtest::Cube());
  auto run = [&cage](const std::function<void(vtkSubDLimitFilter*)>& configure, vtkIdType& cells) {
    vtkNew<vtkSubDLimitFilter> limit;
    limit->SetInputData(cage);
    configure(limit);
    subdtest::Messages messages;
    messages.Watch(limit);
    limit->Update();
    cells = limit->GetOutput()->GetNumberOfCells();
    return messages;
  };
  vtkIdType cells = 0;
  for (double bad : { 0.0, -1e-3, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity() })
  {
    subdtest::Messages m = run(
      [bad](vtkSubDLimitFilter* f) {
        f->SetTessellationToAdaptive();
        f->SetTolerance(bad);
      },
      cells);
    EXPECT_NE(m.Errors.find("Tolerance must be a positive number"), std::string::npos) << bad << ": " << m.Errors;
    EXPECT_EQ(cells, 0);
  }
  subdtest::Messages memory = run(
    [](vtkSubDLimitFilter* f) {
      f->SetTessellationToAdaptive();
      f->SetTolerance(1e-9);
      f->SetMaximumLevel(24);
      f->SetMaximumMemory(1.0);
    },
    cells);
  EXPECT_NE(memory.Errors.find("MaximumMemory"), std::string::npos) << memory.Errors;
  EXPECT_EQ(cells, 0);
  subdtest::Messages deep = run(
    [](vtkSubDLimitFilter* f) {
      f->SetTessellationToAdaptive();
      f->SetTolerance(1e-6);
      f->SetMaximumLevel(2);
    },
    cells);
  EXPECT_NE(deep.Warnings.find("farther than the tolerance"), std::string::npos) << deep.Warnings;
  EXPECT_EQ(cells, 6 * 4 * 4 * 2) << "every face at level 2";
  subdtest::Messages selective = run([](vtkSubDLimitFilter* f) { f->SetTessellationToSelective(); }, cells);
  EXPECT_NE(selective.Errors.find("\"RefineLevel\""), std::string::npos) << selective.Errors;
  EXPECT_EQ(cells, 0);
}

// A cube cut along seven edges by its texture unwrap, read split at the seams: the limit
// tessellations weld it (one surface, no cracks) and split their output there again, each
// side with its texture coordinates from the face-varying channel's limit. Checked against
// vtkSubDCatmullClarkFilter at level 2 projected to the limit (its channel through limit masks,
// another evaluation of the same limit): the uniform tessellation at resolution 4 has its
// points, each with its coordinates.
TEST(AdaptiveTessellation, TextureSeamsAreSplitWithTheFaceVaryingLimit)
{
  const std::string path = subdtest::ProcessTempPath("adaptive_", "cross.obj");
  std::ofstream(path) << subdtest::CrossUnwrappedCubeOBJ();
  vtkNew<vtkSubDOBJReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* cage = reader->GetOutput();
  ASSERT_NE(cage->GetPointData()->GetTCoords(), nullptr);
  vtkNew<vtkSubDCatmullClarkFilter> refine;
  refine->SetInputData(cage);
  refine->SetNumberOfSubdivisions(2);
  refine->ProjectToLimitOn();
  refine->Update();
  vtkPolyData* reference = refine->GetOutput();
  vtkSmartPointer<vtkPolyData> uniform = Tessellate(cage, false, vtkSubDLimitFilter::UNIFORM, 0, 4);
  ASSERT_EQ(uniform->GetNumberOfPoints(), reference->GetNumberOfPoints());
  vtkDataArray* uv = uniform->GetPointData()->GetArray("TCoords");
  vtkDataArray* referenceUV = reference->GetPointData()->GetTCoords();
  ASSERT_TRUE(uv && referenceUV);
  for (vtkIdType i = 0; i < uniform->GetNumberOfPoints(); ++i)
  {
    double p[3], t[2], best = 1.0;
    uniform->GetPoint(i, p);
    uv->GetTuple(i, t);
    for (vtkIdType j = 0; j < reference->GetNumberOfPoints(); ++j)
    {
      double q[3], s[2];
      reference->GetPoint(j, q);
      referenceUV->GetTuple(j, s);
      best = std::min(best, std::max({ std::abs(p[0] - q[0]), std::abs(p[1] - q[1]), std::abs(p[2] - q[2]),
                              std::abs(t[0] - s[0]), std::abs(t[1] - s[1]) }));
    }
    EXPECT_LT(best, 1e-12) << "point " << i;
  }
  // Adaptive: split at the seams (more points than places), watertight once the sides are one.
  vtkSmartPointer<vtkPolyData> adaptive = Tessellate(cage, false, vtkSubDLimitFilter::ADAPTIVE, 1e-3);
  ASSERT_NE(adaptive->GetPointData()->GetArray("TCoords"), nullptr);
  vtkNew<vtkCleanPolyData> merged;
  merged->SetInputData(adaptive);
  merged->PointMergingOn();
  merged->SetTolerance(0.0);
  merged->Update();
  EXPECT_GT(adaptive->GetNumberOfPoints(), merged->GetOutput()->GetNumberOfPoints());
  EXPECT_EQ(OpenOrNonManifoldEdges(merged->GetOutput()), 0) << "cracks";
}
