// vtkSubDScene's colouring: which curvature it reads and the range its colours span, checked
// against closed forms (planted exact curvature arrays, the curvature of a sphere).
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkMath.h"
#include "vtkPoints.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkSubDScene.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <string>

namespace
{
constexpr double Radius = 2.0;

vtkSmartPointer<vtkPolyData> Sphere()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(Radius);
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(64);
  sphere->Update();
  vtkSmartPointer<vtkPolyData> mesh = sphere->GetOutput();
  mesh->GetPointData()->SetNormals(nullptr);
  return mesh;
}

// An open cylinder of radius r around z (quads, outward normals): k1 = 1/r, k2 = 0,
// H = 1/(2r), K = 0 inside; its two rims are boundary.
vtkSmartPointer<vtkPolyData> Cylinder()
{
  constexpr int around = 64, along = 24;
  vtkNew<vtkPoints> points;
  for (int j = 0; j <= along; ++j)
  {
    for (int i = 0; i < around; ++i)
    {
      const double angle = 2.0 * vtkMath::Pi() * i / around;
      points->InsertNextPoint(Radius * std::cos(angle), Radius * std::sin(angle), 0.25 * j);
    }
  }
  vtkNew<vtkCellArray> quads;
  for (int j = 0; j < along; ++j)
  {
    for (int i = 0; i < around; ++i)
    {
      const vtkIdType next = (i + 1) % around;
      const vtkIdType quad[4] = { j * around + i, j * around + next, (j + 1) * around + next, (j + 1) * around + i };
      quads->InsertNextCell(4, quad);
    }
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(quads);
  return mesh;
}

void Plant(vtkPolyData* mesh, const char* name, double (*value)(vtkIdType, vtkIdType))
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  const vtkIdType n = mesh->GetNumberOfPoints();
  array->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    array->SetValue(i, value(i, n));
  }
  mesh->GetPointData()->AddArray(array);
}

// The colour range after rendering `mesh` alone with `coloring`.
std::array<double, 2> RangeOf(vtkPolyData* mesh, int coloring, int mode = vtkSubDScene::RANGE_SYMMETRIC,
  double percentile = 95.0)
{
  vtkNew<vtkSubDScene> scene;
  scene->SetViewSize(64, 64);
  scene->SetColoring(coloring);
  scene->SetRangeMode(mode);
  scene->SetRangePercentile(percentile);
  scene->AddView(mesh, nullptr, nullptr);
  EXPECT_TRUE(scene->Render());
  return { scene->GetColorRange()[0], scene->GetColorRange()[1] };
}
}

TEST(SceneColoring, NamesRoundTrip)
{
  for (int c = vtkSubDScene::COLOR_NONE; c <= vtkSubDScene::COLOR_MINIMUM_CURVATURE; ++c)
  {
    EXPECT_EQ(vtkSubDScene::ColoringFromName(vtkSubDScene::GetColoringName(c)), c);
  }
  for (int m = vtkSubDScene::COLORMAP_COOL_TO_WARM; m <= vtkSubDScene::COLORMAP_GRAYSCALE; ++m)
  {
    EXPECT_EQ(vtkSubDScene::ColorMapFromName(vtkSubDScene::GetColorMapName(m)), m);
  }
  EXPECT_EQ(vtkSubDScene::ColoringFromName("curvy"), -1);
  EXPECT_EQ(vtkSubDScene::ColorMapFromName(nullptr), -1);
}

// A surface that carries its limit curvature (as the filters' ComputeCurvature makes it) is
// coloured by it, each colouring by its own array: constant planted values give the range.
TEST(SceneColoring, ExactCurvatureArraysAreUsed)
{
  vtkSmartPointer<vtkPolyData> mesh = Sphere();
  Plant(mesh, "Mean_Curvature", [](vtkIdType, vtkIdType) { return 0.7; });
  Plant(mesh, "Gauss_Curvature", [](vtkIdType, vtkIdType) { return -6.0; });
  Plant(mesh, "Maximum_Curvature", [](vtkIdType, vtkIdType) { return 3.0; });
  Plant(mesh, "Minimum_Curvature", [](vtkIdType, vtkIdType) { return -2.0; });
  EXPECT_DOUBLE_EQ(RangeOf(mesh, vtkSubDScene::COLOR_MEAN_CURVATURE)[1], 0.7);
  EXPECT_DOUBLE_EQ(RangeOf(mesh, vtkSubDScene::COLOR_GAUSSIAN_CURVATURE)[1], 6.0);
  EXPECT_DOUBLE_EQ(RangeOf(mesh, vtkSubDScene::COLOR_MAXIMUM_CURVATURE)[1], 3.0);
  const std::array<double, 2> k2 = RangeOf(mesh, vtkSubDScene::COLOR_MINIMUM_CURVATURE);
  EXPECT_DOUBLE_EQ(k2[0], -2.0);
  EXPECT_DOUBLE_EQ(k2[1], 2.0);
  // One value only: the percentile range is widened around it, not empty.
  const std::array<double, 2> flat =
    RangeOf(mesh, vtkSubDScene::COLOR_MAXIMUM_CURVATURE, vtkSubDScene::RANGE_PERCENTILE);
  EXPECT_DOUBLE_EQ(flat[0], 2.0);
  EXPECT_DOUBLE_EQ(flat[1], 4.0);
}

// Without the arrays, the discrete curvature of a sphere of radius r: H = k1 = k2 = 1/r,
// K = 1/r^2 (vtkCurvatures' convention: convex is positive).
TEST(SceneColoring, DiscreteCurvatureOfASphere)
{
  vtkSmartPointer<vtkPolyData> mesh = Sphere();
  const double k = 1.0 / Radius;
  EXPECT_NEAR(RangeOf(mesh, vtkSubDScene::COLOR_MEAN_CURVATURE)[1], k, 0.05 * k);
  EXPECT_NEAR(RangeOf(mesh, vtkSubDScene::COLOR_GAUSSIAN_CURVATURE)[1], k * k, 0.05 * k * k);
  EXPECT_NEAR(RangeOf(mesh, vtkSubDScene::COLOR_MAXIMUM_CURVATURE)[1], k, 0.1 * k);
  EXPECT_NEAR(RangeOf(mesh, vtkSubDScene::COLOR_MINIMUM_CURVATURE)[1], k, 0.1 * k);
  const std::array<double, 2> mean =
    RangeOf(mesh, vtkSubDScene::COLOR_MEAN_CURVATURE, vtkSubDScene::RANGE_PERCENTILE, 90.0);
  EXPECT_GT(mean[0], 0.9 * k); // both ends near 1/r: not symmetric about zero
  EXPECT_LT(mean[1], 1.1 * k);
}

// A surface with a boundary: the rims (where the angle deficit is about pi) stay out of the
// range, and the principal curvatures come apart with the right signs.
TEST(SceneColoring, DiscreteCurvatureOfACylinder)
{
  vtkSmartPointer<vtkPolyData> mesh = Cylinder();
  const double k = 1.0 / Radius;
  const int percentile = vtkSubDScene::RANGE_PERCENTILE;
  const std::array<double, 2> k1 = RangeOf(mesh, vtkSubDScene::COLOR_MAXIMUM_CURVATURE, percentile, 100.0);
  EXPECT_NEAR(k1[0], k, 0.02 * k);
  EXPECT_NEAR(k1[1], k, 0.02 * k);
  // k2 and K are zero everywhere inside: a range of one value, widened by 1 around it.
  const std::array<double, 2> k2 = RangeOf(mesh, vtkSubDScene::COLOR_MINIMUM_CURVATURE, percentile, 100.0);
  EXPECT_NEAR(0.5 * (k2[0] + k2[1]), 0.0, 0.02 * k);
  const std::array<double, 2> mean = RangeOf(mesh, vtkSubDScene::COLOR_MEAN_CURVATURE, percentile, 100.0);
  EXPECT_NEAR(mean[0], 0.5 * k, 0.01 * k);
  EXPECT_NEAR(mean[1], 0.5 * k, 0.01 * k);
  const std::array<double, 2> gauss = RangeOf(mesh, vtkSubDScene::COLOR_GAUSSIAN_CURVATURE, percentile, 100.0);
  EXPECT_NEAR(0.5 * (gauss[0] + gauss[1]), 0.0, 1e-3 * k * k);
}

// The sphere split along a seam, as a textured surface comes (a point per side, at one
// position): its curvature is the sphere's, the seam no boundary. The Gaussian curvature's
// range over all of it (the extremes) is the unsplit sphere's; seen as a boundary, the seam's
// angle deficits (about pi) would widen it a hundredfold.
TEST(SceneColoring, SeamsAreNoBoundary)
{
  vtkSmartPointer<vtkPolyData> sphere = Sphere();
  vtkNew<vtkPoints> points;
  points->DeepCopy(sphere->GetPoints());
  vtkNew<vtkCellArray> polys;
  vtkIdType n;
  const vtkIdType* ids;
  std::map<vtkIdType, vtkIdType> copyOf;
  for (vtkIdType f = 0; f < sphere->GetPolys()->GetNumberOfCells(); ++f)
  {
    sphere->GetPolys()->GetCellAtId(f, n, ids);
    double c[3] = { 0, 0, 0 }, p[3];
    for (vtkIdType k = 0; k < n; ++k)
    {
      sphere->GetPoint(ids[k], p);
      c[0] += p[0];
      c[1] += p[1];
    }
    const bool quarter = c[0] > 0 && c[1] > 0; // its faces get points of their own
    polys->InsertNextCell(n);
    for (vtkIdType k = 0; k < n; ++k)
    {
      vtkIdType id = ids[k];
      if (quarter)
      {
        const auto inserted = copyOf.emplace(id, points->GetNumberOfPoints());
        if (inserted.second)
          points->InsertNextPoint(sphere->GetPoint(id));
        id = inserted.first->second;
      }
      polys->InsertCellPoint(id);
    }
  }
  vtkNew<vtkPolyData> split;
  split->SetPoints(points);
  split->SetPolys(polys);
  ASSERT_GT(split->GetNumberOfPoints(), sphere->GetNumberOfPoints() + 100);
  const int percentile = vtkSubDScene::RANGE_PERCENTILE;
  const std::array<double, 2> whole = RangeOf(sphere, vtkSubDScene::COLOR_GAUSSIAN_CURVATURE, percentile, 100.0);
  const std::array<double, 2> seamed = RangeOf(split, vtkSubDScene::COLOR_GAUSSIAN_CURVATURE, percentile, 100.0);
  EXPECT_NEAR(seamed[0], whole[0], 1e-12);
  EXPECT_NEAR(seamed[1], whole[1], 1e-12);
}

// Values spread evenly over [0, 1) with 1% of spikes at 1000: the percentile range is the
// central part of the spread and ignores the spikes.
TEST(SceneColoring, PercentileRangeClipsTheTails)
{
  vtkSmartPointer<vtkPolyData> mesh = Sphere();
  Plant(mesh, "Mean_Curvature", [](vtkIdType i, vtkIdType n) {
    return i % 100 == 0 ? 1000.0 : static_cast<double>((i * 7919) % n) / static_cast<double>(n);
  });
  const std::array<double, 2> central =
    RangeOf(mesh, vtkSubDScene::COLOR_MEAN_CURVATURE, vtkSubDScene::RANGE_PERCENTILE, 90.0);
  EXPECT_NEAR(central[0], 0.05, 0.02);
  EXPECT_NEAR(central[1], 0.95, 0.02);
  const std::array<double, 2> symmetric = RangeOf(mesh, vtkSubDScene::COLOR_MEAN_CURVATURE);
  EXPECT_NEAR(symmetric[1], 0.96, 0.02);
  EXPECT_DOUBLE_EQ(symmetric[0], -symmetric[1]);
  // 100 takes the extremes: the spikes.
  EXPECT_DOUBLE_EQ(
    RangeOf(mesh, vtkSubDScene::COLOR_MEAN_CURVATURE, vtkSubDScene::RANGE_PERCENTILE, 100.0)[1], 1000.0);
}
