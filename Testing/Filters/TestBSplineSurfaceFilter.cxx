// vtkSubDBSplineSurfaceFilter against independent oracles: the cardinal cubic B-spline by its
// recursive definition (not the filter's basis polynomials), closed forms (a natural spline
// reproduces bilinear data exactly), and Catmull-Clark's limit points of the control net
// (vtkSubDCatmullClarkFilter, itself checked against OpenSubdiv).
#include "vtkSubDBSplineSurfaceFilter.h"
#include "vtkSubDCatmullClarkFilter.h"

#include "SubDFilterTestSupport.h"
#include "SubDOutputChecks.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStructuredGrid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numeric>
#include <vector>

namespace
{
using subdtest::Coordinates;

// The cardinal cubic B-spline on [0, 4], by the recursion N_k(x) = (x N_{k-1}(x) +
// (k + 1 - x) N_{k-1}(x - 1)) / k from the box N_0 = 1 on [0, 1).
double Cardinal(int k, double x)
{
  if (k == 0)
    return x >= 0.0 && x < 1.0 ? 1.0 : 0.0;
  return (x * Cardinal(k - 1, x) + (k + 1 - x) * Cardinal(k - 1, x - 1.0)) / k;
}

// The surface of a D x E net (3 values per point, (i, j) at i + j D) at (s, t): control
// (i, j) weighs N(s - i + 3) N(t - j + 3). At the far end (s = D - 3) the half-open box
// needs the limit from the left, so the parameters are nudged inwards by 1e-13.
std::array<double, 3> ReferenceSurface(const std::vector<double>& net, int D, int E, double s, double t)
{
  s = std::min(s, D - 3 - 1e-13);
  t = std::min(t, E - 3 - 1e-13);
  std::array<double, 3> p{ 0, 0, 0 };
  for (int j = 0; j < E; ++j)
    for (int i = 0; i < D; ++i)
    {
      const double w = Cardinal(3, s - i + 3) * Cardinal(3, t - j + 3);
      for (int c = 0; c < 3; ++c)
        p[c] += w * net[3 * (i + j * D) + c];
    }
  return p;
}

struct Lcg
{
  std::uint64_t State;
  double Next() // in [0, 1)
  {
    State = State * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(State >> 11) * 0x1.0p-53;
  }
};

// A P x Q structured grid of points f(i, j), with a scalar "Temperature" = i + 2 j.
vtkSmartPointer<vtkStructuredGrid> MakeGrid(int P, int Q, const std::function<std::array<double, 3>(int, int)>& f)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> temperature;
  temperature->SetName("Temperature");
  for (int j = 0; j < Q; ++j)
    for (int i = 0; i < P; ++i)
    {
      const std::array<double, 3> p = f(i, j);
      points->InsertNextPoint(p.data());
      temperature->InsertNextValue(i + 2.0 * j);
    }
  auto grid = vtkSmartPointer<vtkStructuredGrid>::New();
  grid->SetDimensions(P, Q, 1);
  grid->SetPoints(points);
  grid->GetPointData()->AddArray(temperature);
  return grid;
}

std::array<double, 3> Wavy(int i, int j)
{
  return { 0.7 * i + 0.1 * j, 0.6 * j, std::sin(0.9 * i) * std::cos(0.7 * j) + 0.05 * i * j };
}

// The same grid as quads of a polydata, its point ids shuffled, its faces in another order,
// each starting at another corner.
vtkSmartPointer<vtkPolyData> AsShuffledQuads(vtkStructuredGrid* grid, int P, int Q)
{
  const vtkIdType n = grid->GetNumberOfPoints();
  std::vector<vtkIdType> newId(n);
  std::iota(newId.begin(), newId.end(), 0);
  Lcg random{ 7 };
  for (vtkIdType k = n - 1; k > 0; --k)
    std::swap(newId[k], newId[static_cast<vtkIdType>(random.Next() * (k + 1))]);
  vtkNew<vtkPoints> points;
  points->SetNumberOfPoints(n);
  vtkNew<vtkDoubleArray> temperature;
  temperature->SetName("Temperature");
  temperature->SetNumberOfTuples(n);
  for (vtkIdType p = 0; p < n; ++p)
  {
    points->SetPoint(newId[p], grid->GetPoint(p));
    temperature->SetValue(newId[p], grid->GetPointData()->GetArray("Temperature")->GetComponent(p, 0));
  }
  std::vector<std::array<vtkIdType, 4>> quads;
  for (int j = 0; j + 1 < Q; ++j)
    for (int i = 0; i + 1 < P; ++i)
    {
      const vtkIdType ids[4] = { i + j * P, i + 1 + j * P, i + 1 + (j + 1) * P, i + (j + 1) * P };
      const int rotation = (i + 2 * j) % 4;
      std::array<vtkIdType, 4> quad;
      for (int k = 0; k < 4; ++k)
        quad[k] = newId[ids[(k + rotation) % 4]];
      quads.push_back(quad);
    }
  std::reverse(quads.begin(), quads.end());
  vtkNew<vtkCellArray> cells;
  for (const auto& quad : quads)
    cells->InsertNextCell(4, quad.data());
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(cells);
  mesh->GetPointData()->AddArray(temperature);
  return mesh;
}

void ExpectSameSets(vtkPolyData* a, vtkPolyData* b, double tolerance)
{
  EXPECT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
  EXPECT_LT(subdtest::LargestDistanceToNearestPoint(a, b), tolerance);
  EXPECT_LT(subdtest::LargestDistanceToNearestPoint(b, a), tolerance);
}
}

TEST(BSplineSurfaceFilter, InterpolatesEveryGridPointAndIsACatmullClarkCage)
{
  const int P = 7, Q = 5, samples = 4;
  vtkSmartPointer<vtkStructuredGrid> grid = MakeGrid(P, Q, Wavy);
  vtkNew<vtkSubDBSplineSurfaceFilter> filter;
  filter->SetInputData(grid);
  filter->SetSamplesPerSpan(samples);
  filter->Update();
  ASSERT_EQ(filter->GetErrorCode(), 0UL);
  vtkPolyData* net = filter->GetControlNet();
  vtkPolyData* surface = filter->GetSurface();
  ASSERT_EQ(net->GetNumberOfPoints(), (P + 2) * (Q + 2));
  EXPECT_EQ(net->GetNumberOfPolys(), (P + 1) * (Q + 1));
  const vtkIdType Ns = (P - 1) * samples + 1;
  ASSERT_EQ(surface->GetNumberOfPoints(), Ns * ((Q - 1) * samples + 1));
  EXPECT_EQ(surface->GetNumberOfPolys(), (P - 1) * samples * (Q - 1) * samples);

  // Through every grid point (and its scalar) at the knots.
  vtkDataArray* temperature = surface->GetPointData()->GetArray("Temperature");
  ASSERT_NE(temperature, nullptr);
  for (int j = 0; j < Q; ++j)
    for (int i = 0; i < P; ++i)
    {
      double on[3], target[3];
      surface->GetPoint(i * samples + j * samples * Ns, on);
      grid->GetPoint(i + j * P, target);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(on[c], target[c], 1e-12) << i << ", " << j;
      EXPECT_NEAR(temperature->GetComponent(i * samples + j * samples * Ns, 0), i + 2.0 * j, 1e-12);
    }

  // Everywhere: the cardinal B-spline's recursive definition over the net.
  const std::vector<double> control = Coordinates(net);
  for (vtkIdType p = 0; p < surface->GetNumberOfPoints(); p += 3)
  {
    const double s = static_cast<double>(p % Ns) / samples, t = static_cast<double>(p / Ns) / samples;
    const std::array<double, 3> reference = ReferenceSurface(control, P + 2, Q + 2, s, t);
    double on[3];
    surface->GetPoint(p, on);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(on[c], reference[c], 1e-12) << "sample " << p;
  }

  // The net is a Catmull-Clark cage whose interior vertices' limit points are the data.
  vtkNew<vtkSubDCatmullClarkFilter> limit;
  limit->SetInputData(net);
  limit->SetNumberOfSubdivisions(0);
  limit->SetProjectToLimit(true);
  limit->Update();
  for (int j = 0; j < Q; ++j)
    for (int i = 0; i < P; ++i)
    {
      double on[3], target[3];
      limit->GetOutput()->GetPoint((i + 1) + (j + 1) * (P + 2), on);
      grid->GetPoint(i + j * P, target);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(on[c], target[c], 1e-12) << i << ", " << j;
    }
}

TEST(BSplineSurfaceFilter, NaturalSplinesReproduceBilinearData)
{
  const int P = 5, Q = 4, samples = 3;
  vtkNew<vtkSubDBSplineSurfaceFilter> filter;
  filter->SetInputData(MakeGrid(P, Q, [](int i, int j) { return std::array<double, 3>{ 1.0 * i, 1.0 * j, 1.0 * i * j }; }));
  filter->SetSamplesPerSpan(samples);
  filter->Update();
  vtkPolyData* surface = filter->GetSurface();
  const vtkIdType Ns = (P - 1) * samples + 1;
  for (vtkIdType p = 0; p < surface->GetNumberOfPoints(); ++p)
  {
    const double s = static_cast<double>(p % Ns) / samples, t = static_cast<double>(p / Ns) / samples;
    double on[3];
    surface->GetPoint(p, on);
    EXPECT_NEAR(on[0], s, 1e-12);
    EXPECT_NEAR(on[1], t, 1e-12);
    EXPECT_NEAR(on[2], s * t, 1e-12);
    // The normal of z = s t is (-t, -s, 1), normalised.
    double n[3];
    surface->GetPointData()->GetNormals()->GetTuple(p, n);
    const double length = std::sqrt(s * s + t * t + 1.0);
    EXPECT_NEAR(n[0], -t / length, 1e-12);
    EXPECT_NEAR(n[1], -s / length, 1e-12);
    EXPECT_NEAR(n[2], 1.0 / length, 1e-12);
  }
}

TEST(BSplineSurfaceFilter, AQuadGridInAnyNumberingGivesTheSameSurface)
{
  const int P = 6, Q = 4;
  vtkSmartPointer<vtkStructuredGrid> grid = MakeGrid(P, Q, Wavy);
  vtkNew<vtkSubDBSplineSurfaceFilter> structured;
  structured->SetInputData(grid);
  structured->Update();
  vtkNew<vtkSubDBSplineSurfaceFilter> shuffled;
  shuffled->SetInputData(AsShuffledQuads(grid, P, Q));
  shuffled->Update();
  ASSERT_EQ(shuffled->GetErrorCode(), 0UL);
  ExpectSameSets(structured->GetControlNet(), shuffled->GetControlNet(), 1e-12);
  ExpectSameSets(structured->GetSurface(), shuffled->GetSurface(), 1e-12);
}

TEST(BSplineSurfaceFilter, WhatIsNotAGridIsAClearError)
{
  auto expectError = [](vtkPointSet* input, const std::string& expected) {
    subdtest::Messages messages;
    vtkNew<vtkSubDBSplineSurfaceFilter> filter;
    messages.Watch(filter);
    filter->SetInputData(input);
    filter->Update();
    EXPECT_NE(filter->GetErrorCode(), 0UL) << expected;
    EXPECT_NE(messages.Errors.find(expected), std::string::npos) << messages.Errors;
    EXPECT_EQ(filter->GetControlNet()->GetNumberOfPoints(), 0);
    EXPECT_EQ(filter->GetSurface()->GetNumberOfPoints(), 0);
  };
  // A closed cube of quads.
  vtkNew<vtkPoints> cubePoints;
  for (int k = 0; k < 8; ++k)
    cubePoints->InsertNextPoint(k & 1, (k >> 1) & 1, (k >> 2) & 1);
  vtkNew<vtkCellArray> cubeFaces;
  const vtkIdType faces[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 }, { 0, 4, 6, 2 },
    { 1, 3, 7, 5 } };
  for (const auto& face : faces)
    cubeFaces->InsertNextCell(4, face);
  vtkNew<vtkPolyData> cube;
  cube->SetPoints(cubePoints);
  cube->SetPolys(cubeFaces);
  expectError(cube, "no vertex is the corner of a single quad");

  // An L of three quads: a corner, but not a rectangle.
  vtkNew<vtkPoints> lPoints;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      lPoints->InsertNextPoint(i, j, 0);
  vtkNew<vtkCellArray> lFaces;
  const vtkIdType l[3][4] = { { 0, 1, 4, 3 }, { 1, 2, 5, 4 }, { 3, 4, 7, 6 } };
  for (const auto& face : l)
    lFaces->InsertNextCell(4, face);
  vtkNew<vtkPolyData> shapeL;
  shapeL->SetPoints(lPoints);
  shapeL->SetPolys(lFaces);
  expectError(shapeL, "do not form a rectangular grid");

  // Triangles.
  vtkNew<vtkCellArray> triangles;
  const vtkIdType triangle[3] = { 0, 1, 4 };
  triangles->InsertNextCell(3, triangle);
  vtkNew<vtkPolyData> tri;
  tri->SetPoints(lPoints);
  tri->SetPolys(triangles);
  expectError(tri, "a grid is made of quads");

  // A 3-D structured grid.
  vtkNew<vtkStructuredGrid> block;
  vtkNew<vtkPoints> blockPoints;
  for (int k = 0; k < 8; ++k)
    blockPoints->InsertNextPoint(k & 1, (k >> 1) & 1, (k >> 2) & 1);
  block->SetDimensions(2, 2, 2);
  block->SetPoints(blockPoints);
  expectError(block, "a surface grid has exactly two dimensions above 1");
}

namespace
{
// Samples of the surface of `net` (D x E) at pseudo-random parameters, skipping those for
// which `skip(u, v)` holds, as points with a "UV" array.
vtkSmartPointer<vtkPolyData> SampleSurface(const std::vector<double>& net, int D, int E, int count,
  const std::function<bool(double, double)>& skip = nullptr)
{
  Lcg random{ 42 };
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> uv;
  uv->SetName("UV");
  uv->SetNumberOfComponents(2);
  while (points->GetNumberOfPoints() < count)
  {
    const double u = random.Next(), v = random.Next();
    if (skip && skip(u, v))
      continue;
    const std::array<double, 3> p = ReferenceSurface(net, D, E, u * (D - 3), v * (E - 3));
    points->InsertNextPoint(p.data());
    uv->InsertNextTuple2(u, v);
  }
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  cloud->SetPoints(points);
  cloud->GetPointData()->AddArray(uv);
  return cloud;
}

std::vector<double> RandomNet(int D, int E)
{
  Lcg random{ 3 };
  std::vector<double> net;
  for (int j = 0; j < E; ++j)
    for (int i = 0; i < D; ++i)
    {
      net.push_back(i + 0.3 * random.Next());
      net.push_back(j + 0.3 * random.Next());
      net.push_back(random.Next());
    }
  return net;
}

std::vector<double> AffineNet(int D, int E)
{
  std::vector<double> net;
  for (int j = 0; j < E; ++j)
    for (int i = 0; i < D; ++i)
    {
      net.push_back(1.0 + 0.8 * i + 0.1 * j);
      net.push_back(-0.2 * i + 0.9 * j);
      net.push_back(0.3 * i - 0.5 * j);
    }
  return net;
}

void ExpectNetNear(vtkPolyData* net, const std::vector<double>& expected, double tolerance)
{
  EXPECT_LT(subdtest::LargestPointwiseDifference(Coordinates(net), expected), tolerance);
}
}

TEST(BSplineSurfaceFilter, LeastSquaresRecoversTheNetThatMadeTheSamples)
{
  const int D = 7, E = 6;
  const std::vector<double> truth = RandomNet(D, E);
  vtkNew<vtkSubDBSplineSurfaceFilter> filter;
  filter->SetInputData(SampleSurface(truth, D, E, 2000));
  filter->SetModeToApproximateScattered();
  filter->SetNumberOfControlPoints(D, E);
  filter->Update();
  ASSERT_EQ(filter->GetErrorCode(), 0UL);
  ExpectNetNear(filter->GetControlNet(), truth, 1e-9);
  EXPECT_LT(filter->GetRmsError(), 1e-10);
  EXPECT_LT(filter->GetMaxError(), 1e-10);
  EXPECT_EQ(filter->GetSurface()->GetNumberOfPoints(), (4 * 8 + 1) * (3 * 8 + 1));
}

TEST(BSplineSurfaceFilter, AHoleInTheDataNeedsTheShapeEquations)
{
  const int D = 16, E = 16; // the 13 x 13 spans' middle control points see no sample
  auto hole = [](double u, double v) { return (u - 0.5) * (u - 0.5) + (v - 0.5) * (v - 0.5) < 0.3 * 0.3; };
  for (const bool affine : { true, false })
  {
    const std::vector<double> truth = affine ? AffineNet(D, E) : RandomNet(D, E);
    vtkSmartPointer<vtkPolyData> samples = SampleSurface(truth, D, E, 3000, hole);
    subdtest::Messages messages;
    vtkNew<vtkSubDBSplineSurfaceFilter> filter;
    messages.Watch(filter);
    filter->SetInputData(samples);
    filter->SetModeToApproximateScattered();
    filter->SetNumberOfControlPoints(D, E);
    filter->Update();
    EXPECT_NE(filter->GetErrorCode(), 0UL);
    EXPECT_NE(messages.Errors.find("do not determine every control point"), std::string::npos) << messages.Errors;
    EXPECT_NE(messages.Errors.find("turn the shape equations on"), std::string::npos) << messages.Errors;

    filter->SetShapeWeight(1e-2);
    filter->Update();
    ASSERT_EQ(filter->GetErrorCode(), 0UL);
    if (affine)
    {
      // An evenly spaced planar net satisfies the shape equations: recovered exactly.
      ExpectNetNear(filter->GetControlNet(), truth, 1e-9);
    }
    else
    {
      EXPECT_LT(filter->GetRmsError(), 2e-3); // measured 4.3e-4: the shape equations bias a twisted net a little
    }
    EXPECT_EQ(subdtest::OutputProblems(filter->GetControlNet()), "");
    EXPECT_EQ(subdtest::OutputProblems(filter->GetSurface()), "");
  }
}

TEST(BSplineSurfaceFilter, ScatteredInputErrorsAndTextureCoordinates)
{
  const int D = 5, E = 5;
  vtkSmartPointer<vtkPolyData> samples = SampleSurface(AffineNet(D, E), D, E, 400);
  // Texture coordinates instead of "UV".
  samples->GetPointData()->GetArray("UV")->SetName("st");
  samples->GetPointData()->SetTCoords(samples->GetPointData()->GetArray("st"));
  vtkNew<vtkSubDBSplineSurfaceFilter> filter;
  filter->SetInputData(samples);
  filter->SetModeToApproximateScattered();
  filter->SetNumberOfControlPoints(D, E);
  filter->Update();
  ASSERT_EQ(filter->GetErrorCode(), 0UL);
  ExpectNetNear(filter->GetControlNet(), AffineNet(D, E), 1e-9);
  EXPECT_EQ(filter->GetControlNet()->GetPointData()->GetArray("st"), nullptr); // parameters are not fitted

  subdtest::Messages messages;
  messages.Watch(filter);
  samples->GetPointData()->GetTCoords()->SetComponent(17, 0, 1.5);
  filter->Modified();
  filter->Update();
  EXPECT_NE(messages.Errors.find("Sample 17 has parameters (1.5,"), std::string::npos) << messages.Errors;

  // Far too large a request is refused before anything is allocated.
  samples->GetPointData()->GetTCoords()->SetComponent(17, 0, 0.5);
  filter->SetNumberOfControlPoints(4096, 4096);
  filter->SetSamplesPerSpan(256);
  filter->Update();
  EXPECT_NE(messages.Errors.find("above half the physical memory"), std::string::npos) << messages.Errors;
  EXPECT_EQ(filter->GetControlNet()->GetNumberOfPoints(), 0);

  samples->GetPointData()->Initialize();
  filter->Modified();
  filter->Update();
  EXPECT_NE(messages.Errors.find("scattered points need (u, v) parameters"), std::string::npos) << messages.Errors;
}
