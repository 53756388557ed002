// Filter tests of the limit surface: vtkSubDLimitFilter's tessellation and locations, and
// the ComputeLimitNormals / ComputeCurvature options of the surface filters, against closed
// forms (the periodic bicubic B-spline of a torus-like net), against the surface filters'
// own limit points, and against the refined meshes they converge to.
#include "SubDBSplineNets.h"
#include "SubDFilterTestSupport.h"
#include "vtkSubDButterflyFilter.h"
#include "vtkSubDCatmullClarkFilter.h"
#include "vtkSubDDooSabinFilter.h"
#include "vtkSubDLimitFilter.h"
#include "vtkSubDLinearFilter.h"
#include "vtkSubDLoopFilter.h"
#include "vtkSubDMidpointFilter.h"
#include "vtkSubDSqrt3Filter.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFeatureEdges.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkStripper.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace
{
using subdtest::OpenOrNonManifoldEdges;
using subdtest::ToPolyData;

// Locations (face cell id, u, v, and the sub-face of a polygon) as the second input of
// vtkSubDLimitFilter.
vtkSmartPointer<vtkPolyData> Locations(const std::vector<std::array<double, 4>>& samples)
{
  auto locations = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName("FaceId");
  vtkNew<vtkDoubleArray> uv;
  uv->SetName("FaceUV");
  uv->SetNumberOfComponents(2);
  vtkNew<vtkIdTypeArray> sub;
  sub->SetName("SubFace");
  for (const auto& s : samples)
  {
    points->InsertNextPoint(0, 0, 0);
    ids->InsertNextValue(static_cast<vtkIdType>(s[0]));
    uv->InsertNextTuple2(s[1], s[2]);
    sub->InsertNextValue(static_cast<vtkIdType>(s[3]));
  }
  locations->SetPoints(points);
  locations->GetPointData()->AddArray(ids);
  locations->GetPointData()->AddArray(uv);
  locations->GetPointData()->AddArray(sub);
  return locations;
}

double Norm(const double v[3])
{
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

// Derivatives of the cubic B-spline basis centred at 0.
double CubicBSplineD1(double t)
{
  const double a = std::abs(t), s = t < 0 ? -1.0 : 1.0;
  if (a < 1)
    return s * (-2 * a + 1.5 * a * a);
  if (a < 2)
    return s * (-0.5 * (2 - a) * (2 - a));
  return 0;
}
double CubicBSplineD2(double t)
{
  const double a = std::abs(t);
  if (a < 1)
    return -2 + 3 * a;
  if (a < 2)
    return 2 - a;
  return 0;
}
}

TEST(LimitFilter, TessellationIsWatertightAndMatchesTheLimitPoints)
{
  struct Case
  {
    subdtest::TestMesh Mesh;
    bool Loop;
  };
  const std::vector<Case> cases = { { subdtest::House(false), false }, { subdtest::Star(5), false },
    { subdtest::Cube().Triangulated(), true }, { subdtest::Bipyramid(7), true } };
  for (const Case& c : cases)
  {
    for (int levels : { 1, 2 })
    {
      const int resolution = 1 << levels;
      vtkNew<vtkSubDLimitFilter> limit;
      limit->SetInputData(ToPolyData(c.Mesh));
      limit->SetScheme(c.Loop ? vtkSubDLimitFilter::LOOP : vtkSubDLimitFilter::CATMULL_CLARK);
      limit->SetResolution(resolution);
      limit->Update();
      vtkPolyData* out = limit->GetOutput();
      ASSERT_GT(out->GetNumberOfCells(), 0) << c.Mesh.Name;
      EXPECT_EQ(OpenOrNonManifoldEdges(out), 0) << c.Mesh.Name << ": the tessellation has cracks";
      // Its points are the limit points of the mesh refined `levels` times (Catmull-Clark
      // splits polygons at level 1, so a polygon's quads have half the resolution).
      vtkSmartPointer<vtkPolyDataAlgorithm> refine;
      if (c.Loop)
        refine = vtkSmartPointer<vtkSubDLoopFilter>::New();
      else
        refine = vtkSmartPointer<vtkSubDCatmullClarkFilter>::New();
      auto* surface = vtkSubDSurfaceFilter::SafeDownCast(refine);
      surface->SetInputData(ToPolyData(c.Mesh));
      surface->SetNumberOfSubdivisions(levels);
      surface->ProjectToLimitOn();
      surface->Update();
      vtkPolyData* refined = surface->GetOutput();
      EXPECT_EQ(out->GetNumberOfPoints(), refined->GetNumberOfPoints()) << c.Mesh.Name;
      const double diagonal = subdtest::Diagonal(subdtest::Coordinates(refined));
      EXPECT_LT(subdtest::LargestDistanceToNearestPoint(out, refined), 1e-12 * diagonal) << c.Mesh.Name;
      EXPECT_LT(subdtest::LargestDistanceToNearestPoint(refined, out), 1e-12 * diagonal) << c.Mesh.Name;
      vtkDataArray* normals = out->GetPointData()->GetNormals();
      ASSERT_NE(normals, nullptr);
      for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i)
      {
        EXPECT_NEAR(Norm(normals->GetTuple3(i)), 1.0, 1e-6);
      }
    }
  }
}

// A torus-like closed net of valence-4 quads: Catmull-Clark's limit is the periodic
// bicubic B-spline, evaluated here independently with its analytic curvature.
TEST(LimitFilter, TorusCurvatureIsTheBSplineCurvature)
{
  const int nx = 8, ny = 6;
  subdtest::TestMesh torus = subdtest::Grid(nx, ny, true, true);
  torus.Jitter(0.05);
  std::vector<std::array<double, 4>> samples;
  for (int f = 0; f < nx * ny; f += 5)
    for (double u : { 0.0, 0.3, 0.75 })
      for (double v : { 0.1, 0.5, 1.0 })
        samples.push_back({ static_cast<double>(f), u, v, 0 });
  vtkNew<vtkSubDLimitFilter> limit;
  limit->SetInputData(ToPolyData(torus));
  limit->SetLocationsConnection(nullptr);
  limit->SetInputData(1, Locations(samples));
  limit->ComputeCurvatureOn();
  limit->Update();
  vtkPolyData* out = limit->GetOutput();
  ASSERT_EQ(out->GetNumberOfPoints(), static_cast<vtkIdType>(samples.size()));
  vtkDataArray* mean = out->GetPointData()->GetArray("Mean_Curvature");
  vtkDataArray* gauss = out->GetPointData()->GetArray("Gauss_Curvature");
  vtkDataArray* normals = out->GetPointData()->GetNormals();
  ASSERT_TRUE(mean && gauss && normals);
  for (size_t k = 0; k < samples.size(); ++k)
  {
    const int f = static_cast<int>(samples[k][0]);
    const double s = f % nx + samples[k][1], t = f / nx + samples[k][2];
    double P[3] = {}, Ps[3] = {}, Pt[3] = {}, Pss[3] = {}, Pst[3] = {}, Ptt[3] = {};
    for (int b = -3; b <= ny + 3; ++b)
    {
      for (int a = -3; a <= nx + 3; ++a)
      {
        const double Na = subdtest::CubicBSpline(s - a), Nb = subdtest::CubicBSpline(t - b);
        const double Da = CubicBSplineD1(s - a), Db = CubicBSplineD1(t - b);
        const double DDa = CubicBSplineD2(s - a), DDb = CubicBSplineD2(t - b);
        const double* X = &torus.Points[3 * (((b % ny) + ny) % ny * nx + ((a % nx) + nx) % nx)];
        for (int x = 0; x < 3; ++x)
        {
          P[x] += Na * Nb * X[x];
          Ps[x] += Da * Nb * X[x];
          Pt[x] += Na * Db * X[x];
          Pss[x] += DDa * Nb * X[x];
          Pst[x] += Da * Db * X[x];
          Ptt[x] += Na * DDb * X[x];
        }
      }
    }
    double n[3] = { Ps[1] * Pt[2] - Ps[2] * Pt[1], Ps[2] * Pt[0] - Ps[0] * Pt[2], Ps[0] * Pt[1] - Ps[1] * Pt[0] };
    const double length = Norm(n);
    for (double& x : n)
      x /= length;
    auto dot = [](const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    // First and second fundamental forms; the shape operator I^-1 II; with outward normals a
    // convex surface bends away from n, so its curvature is minus the shape operator's.
    const double I[2][2] = { { dot(Ps, Ps), dot(Ps, Pt) }, { dot(Ps, Pt), dot(Pt, Pt) } };
    const double II[2][2] = { { dot(Pss, n), dot(Pst, n) }, { dot(Pst, n), dot(Ptt, n) } };
    const double detI = I[0][0] * I[1][1] - I[0][1] * I[0][1];
    const double W[2][2] = { { (I[1][1] * II[0][0] - I[0][1] * II[1][0]) / detI, (I[1][1] * II[0][1] - I[0][1] * II[1][1]) / detI },
      { (I[0][0] * II[1][0] - I[0][1] * II[0][0]) / detI, (I[0][0] * II[1][1] - I[0][1] * II[0][1]) / detI } };
    const double expectedMean = -0.5 * (W[0][0] + W[1][1]);
    const double expectedGauss = W[0][0] * W[1][1] - W[0][1] * W[1][0];
    double got[3];
    out->GetPoint(static_cast<vtkIdType>(k), got);
    for (int x = 0; x < 3; ++x)
    {
      EXPECT_NEAR(got[x], P[x], 1e-12) << "sample " << k;
      EXPECT_NEAR(normals->GetComponent(static_cast<vtkIdType>(k), x), n[x], 1e-6) << "sample " << k;
    }
    EXPECT_NEAR(mean->GetTuple1(static_cast<vtkIdType>(k)), expectedMean, 1e-10) << "sample " << k;
    EXPECT_NEAR(gauss->GetTuple1(static_cast<vtkIdType>(k)), expectedGauss, 1e-10) << "sample " << k;
  }
}

// Near an extraordinary vertex curvature stays finite and settles as samples approach it.
TEST(LimitFilter, CurvatureNearExtraordinaryVerticesConverges)
{
  for (const subdtest::TestMesh& mesh : { subdtest::Cube(), subdtest::Star(5), subdtest::Star(7) })
  {
    // Face 0's corner 0 is extraordinary in all three (valence 3, 5, 7 there... or its
    // polygon's corner): approach it along the diagonal of the first quad found there.
    vtkSmartPointer<vtkPolyData> cage = ToPolyData(mesh);
    const vtkIdType face = mesh.Name == "cube" ? 0 : 2; // star: a side quad at the apex ring? no: roof
    std::vector<std::array<double, 4>> samples;
    for (int k = 2; k <= 24; ++k)
      samples.push_back({ static_cast<double>(face), std::ldexp(1.0, -k), std::ldexp(1.0, -k) });
    vtkNew<vtkSubDLimitFilter> limit;
    limit->SetInputData(cage);
    limit->SetInputData(1, Locations(samples));
    limit->ComputeCurvatureOn();
    limit->Update();
    vtkDataArray* gauss = limit->GetOutput()->GetPointData()->GetArray("Gauss_Curvature");
    vtkDataArray* mean = limit->GetOutput()->GetPointData()->GetArray("Mean_Curvature");
    ASSERT_TRUE(gauss && mean) << mesh.Name;
    const vtkIdType n = gauss->GetNumberOfTuples();
    const double atVertex = mean->GetTuple1(n - 1);
    for (vtkIdType i = 0; i < n; ++i)
    {
      const double H = mean->GetTuple1(i), K = gauss->GetTuple1(i);
      ASSERT_TRUE(std::isfinite(H) && std::isfinite(K)) << mesh.Name << " sample " << i;
      EXPECT_LT(std::abs(H), 2.0 * std::abs(atVertex) + 1.0) << mesh.Name << " sample " << i;
      if (i >= 7 && i + 1 < n)
      {
        // From 2^-9 on, the value settles to the vertex's (no blow-up from lost digits).
        EXPECT_LT(std::abs(H - atVertex), 0.05 * std::abs(atVertex)) << mesh.Name << " sample " << i;
      }
    }
  }
}

template <typename T>
vtkSmartPointer<vtkSubDSurfaceFilter> NewSurfaceFilter()
{
  return vtkSmartPointer<T>::New();
}

// Every scheme with tangent masks: exact normals are unit length, and the normals of the
// refined mesh (averaged face normals at the projected points) approach them level by level:
// everywhere, and at the worst point for the schemes whose curvature stays bounded near
// extraordinary points. The midpoint scheme is only C1 there and its worst point, next to an
// extraordinary face, converges too slowly to show it.
TEST(LimitNormals, UnitAndConvergingToTheRefinedMeshNormals)
{
  struct Case
  {
    subdtest::TestMesh Mesh;
    vtkSmartPointer<vtkSubDSurfaceFilter> (*Make)();
    int MaxLevels;
    bool WorstPointConverges;
  };
  const Case cases[] = {
    { subdtest::Star(5).Jitter(0.1), &NewSurfaceFilter<vtkSubDCatmullClarkFilter>, 5, true },
    { subdtest::Bipyramid(7).Jitter(0.1), &NewSurfaceFilter<vtkSubDLoopFilter>, 5, true },
    { subdtest::Bipyramid(7).Jitter(0.1), &NewSurfaceFilter<vtkSubDSqrt3Filter>, 6, true },
    { subdtest::Star(5).Jitter(0.1), &NewSurfaceFilter<vtkSubDDooSabinFilter>, 5, true },
    { subdtest::Star(5).Jitter(0.1), &NewSurfaceFilter<vtkSubDMidpointFilter>, 7, false },
  };
  for (const Case& c : cases)
  {
    double previousWorst = 1e300, previousMean = 1e300;
    std::string name;
    for (int levels = 2; levels <= c.MaxLevels; ++levels)
    {
      vtkSmartPointer<vtkSubDSurfaceFilter> filter = c.Make();
      name = std::string(filter->GetClassName()) + " on " + c.Mesh.Name;
      filter->SetInputData(ToPolyData(c.Mesh));
      filter->SetNumberOfSubdivisions(levels);
      filter->ProjectToLimitOn();
      filter->ComputeLimitNormalsOn();
      filter->Update();
      vtkPolyData* out = filter->GetOutput();
      vtkDataArray* exact = out->GetPointData()->GetNormals();
      ASSERT_NE(exact, nullptr) << name;
      vtkNew<vtkPolyData> plain;
      plain->SetPoints(out->GetPoints());
      plain->SetPolys(out->GetPolys());
      vtkNew<vtkPolyDataNormals> meshNormals;
      meshNormals->SetInputData(plain);
      meshNormals->SplittingOff();
      meshNormals->ConsistencyOff();
      meshNormals->Update();
      vtkDataArray* averaged = meshNormals->GetOutput()->GetPointData()->GetNormals();
      double worst = 0.0, mean = 0.0;
      for (vtkIdType i = 0; i < exact->GetNumberOfTuples(); ++i)
      {
        const double* n = exact->GetTuple3(i);
        EXPECT_NEAR(Norm(n), 1.0, 1e-6) << name;
        double a[3];
        averaged->GetTuple(i, a);
        const double angle = std::acos(std::min(1.0, (n[0] * a[0] + n[1] * a[1] + n[2] * a[2]) / Norm(a)));
        worst = std::max(worst, angle);
        mean += angle / exact->GetNumberOfTuples();
      }
      EXPECT_LT(mean, previousMean) << name << " level " << levels;
      if (c.WorstPointConverges)
      {
        EXPECT_LT(worst, previousWorst) << name << " level " << levels;
      }
      previousWorst = worst;
      previousMean = mean;
    }
    EXPECT_LT(previousMean, 0.01) << name;
    if (c.WorstPointConverges)
    {
      EXPECT_LT(previousWorst, 0.05) << name;
    }
  }
}

TEST(LimitCurvature, ConvexSurfacesHavePositiveCurvature)
{
  vtkNew<vtkSubDCatmullClarkFilter> filter;
  filter->SetInputData(ToPolyData(subdtest::Cube()));
  filter->SetNumberOfSubdivisions(3);
  filter->ComputeCurvatureOn();
  filter->Update();
  vtkDataArray* mean = filter->GetOutput()->GetPointData()->GetArray("Mean_Curvature");
  vtkDataArray* gauss = filter->GetOutput()->GetPointData()->GetArray("Gauss_Curvature");
  ASSERT_TRUE(mean && gauss);
  for (vtkIdType i = 0; i < mean->GetNumberOfTuples(); ++i)
  {
    EXPECT_GT(mean->GetTuple1(i), 0.0) << "point " << i;
    EXPECT_GT(gauss->GetTuple1(i), 0.0) << "point " << i;
  }
}

TEST(LimitFilter, BadInputGivesClearErrors)
{
  auto run = [](vtkPolyData* cage, vtkPolyData* locations, bool loop) {
    vtkNew<vtkSubDLimitFilter> limit;
    subdtest::Messages messages;
    messages.Watch(limit);
    limit->SetInputData(cage);
    if (locations)
      limit->SetInputData(1, locations);
    limit->SetScheme(loop ? vtkSubDLimitFilter::LOOP : vtkSubDLimitFilter::CATMULL_CLARK);
    limit->Update();
    EXPECT_EQ(limit->GetOutput()->GetNumberOfPoints(), 0);
    return messages.Errors;
  };
  vtkSmartPointer<vtkPolyData> cube = ToPolyData(subdtest::Cube());
  // Loop splits the quads into triangles, so that locations cannot name them.
  EXPECT_NE(run(cube, Locations({ { 0, 0.2, 0.2 } }), true).find("not a polygon"), std::string::npos);
  EXPECT_NE(run(cube, Locations({ { 6, 0.5, 0.5 } }), false).find("not a polygon"), std::string::npos);
  EXPECT_NE(run(cube, Locations({ { 1, 1.5, 0.5 } }), false).find("outside face"), std::string::npos);
  vtkNew<vtkPolyData> empty;
  EXPECT_NE(run(empty, nullptr, false).find("no polygons"), std::string::npos);
}

// Interpolating schemes never move their vertices: projecting to the limit changes nothing.
TEST(LimitFilter, InterpolatingSchemesProjectToThemselves)
{
  vtkSmartPointer<vtkPolyData> cube = ToPolyData(subdtest::Cube().Triangulated());
  for (int scheme = 0; scheme < 2; ++scheme)
  {
    vtkSmartPointer<vtkSubDSurfaceFilter> filters[2];
    for (int project = 0; project < 2; ++project)
    {
      if (scheme == 0)
        filters[project] = vtkSmartPointer<vtkSubDButterflyFilter>::New();
      else
        filters[project] = vtkSmartPointer<vtkSubDLinearFilter>::New();
      filters[project]->SetInputData(cube);
      filters[project]->SetNumberOfSubdivisions(2);
      filters[project]->SetProjectToLimit(project == 1);
      filters[project]->Update();
    }
    vtkPolyData* a = filters[0]->GetOutput();
    vtkPolyData* b = filters[1]->GetOutput();
    ASSERT_GT(a->GetNumberOfPoints(), 0);
    EXPECT_EQ(subdtest::Coordinates(a), subdtest::Coordinates(b)); // bit for bit
  }
}

// The cage's point data are evaluated with the limit weights: a linear field follows the
// limit points exactly (the weights are affine), an integer field is rounded to nearest.
TEST(LimitFilter, PointDataFollowTheLimitWeights)
{
  vtkSmartPointer<vtkPolyData> cage = ToPolyData(subdtest::House(false).Jitter(0.1));
  vtkNew<vtkDoubleArray> x;
  x->SetName("X");
  vtkNew<vtkIntArray> hundredX;
  hundredX->SetName("HundredX");
  for (vtkIdType i = 0; i < cage->GetNumberOfPoints(); ++i)
  {
    x->InsertNextValue(cage->GetPoint(i)[0]);
    hundredX->InsertNextValue(static_cast<int>(std::lround(100 * cage->GetPoint(i)[0])));
  }
  cage->GetPointData()->AddArray(x);
  cage->GetPointData()->AddArray(hundredX);
  vtkNew<vtkSubDLimitFilter> limit;
  limit->SetInputData(cage);
  limit->SetResolution(3);
  limit->Update();
  vtkPolyData* out = limit->GetOutput();
  vtkDataArray* outX = out->GetPointData()->GetArray("X");
  vtkDataArray* outHundredX = out->GetPointData()->GetArray("HundredX");
  ASSERT_TRUE(outX && outHundredX);
  EXPECT_EQ(outHundredX->GetDataType(), VTK_INT);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    EXPECT_NEAR(outX->GetTuple1(i), out->GetPoint(i)[0], 1e-12);
    // The control values are rounded 100 x, so the limit is within 0.5 of 100 x, then rounded.
    const double value = outHundredX->GetTuple1(i);
    EXPECT_EQ(value, std::round(value));
    EXPECT_LE(std::abs(value - 100 * out->GetPoint(i)[0]), 1.0);
  }
}

// The cage is read as the surface filters read it: strips are triangles, degenerate polygons
// are dropped with a warning, a quad repeating its points (0 1 1 0) is kept as Catmull-Clark
// keeps it.
TEST(LimitFilter, StripsAndDegeneratePolygonsAreReadLikeTheSurfaceFilters)
{
  vtkSmartPointer<vtkPolyData> triangles = ToPolyData(subdtest::Cube().Triangulated());
  vtkNew<vtkStripper> stripper;
  stripper->SetInputData(triangles);
  stripper->Update();
  ASSERT_GT(stripper->GetOutput()->GetNumberOfStrips(), 0);
  vtkIdType counts[2];
  for (int k = 0; k < 2; ++k)
  {
    vtkNew<vtkSubDLimitFilter> limit;
    limit->SetSchemeToLoop();
    limit->SetResolution(2);
    limit->SetInputData(k == 0 ? triangles.Get() : stripper->GetOutput());
    limit->Update();
    counts[k] = limit->GetOutput()->GetNumberOfPoints();
  }
  EXPECT_GT(counts[0], 0);
  EXPECT_EQ(counts[0], counts[1]);

  vtkSmartPointer<vtkPolyData> cube = ToPolyData(subdtest::Cube());
  const vtkIdType degenerate[3] = { 2, 2, 2 }, repeating[4] = { 0, 1, 1, 0 };
  cube->GetPolys()->InsertNextCell(3, degenerate);
  cube->GetPolys()->InsertNextCell(4, repeating);
  vtkNew<vtkSubDLimitFilter> limit;
  subdtest::Messages messages;
  messages.Watch(limit);
  limit->SetInputData(cube);
  limit->SetResolution(2);
  limit->Update();
  EXPECT_NE(messages.Warnings.find("ignored 1 degenerate"), std::string::npos) << messages.Warnings;
  EXPECT_NE(messages.Warnings.find("2 polygon(s) repeat a point"), std::string::npos) << messages.Warnings;
  EXPECT_NE(messages.Warnings.find("kept as OpenSubdiv"), std::string::npos) << messages.Warnings;
  EXPECT_EQ(messages.NumErrors, 0) << messages.Errors;
  EXPECT_EQ(limit->GetOutput()->GetNumberOfCells(), 7 * 4);
}

namespace
{
// Where the limit surface has no tangent plane (here: a triangle of zero area), the normals
// and curvatures are 0, never NaN, and a warning says how many points.
TEST(LimitGeometry, NoTangentPlaneGivesZerosAndAWarning)
{
  for (bool loop : { false, true })
  {
    SCOPED_TRACE(loop ? "loop" : "catmull-clark");
    vtkSmartPointer<vtkSubDSurfaceFilter> filter;
    if (loop)
    {
      filter = vtkSmartPointer<vtkSubDLoopFilter>::New();
    }
    else
    {
      filter = vtkSmartPointer<vtkSubDCatmullClarkFilter>::New();
    }
    // A cube, and a triangle whose three corners coincide: no tangent plane anywhere on it.
    subdtest::TestMesh mesh = loop ? subdtest::Cube().Triangulated() : subdtest::Cube();
    const subd::Index first = mesh.NumVertices();
    for (int k = 0; k < 3; ++k)
    {
      mesh.AddPoint(5, 5, 5);
    }
    mesh.AddFace({ first, first + 1, first + 2 });
    filter->SetInputData(ToPolyData(mesh));
    filter->WeldCoincidentPointsOff(); // the triangle's points stay three
    filter->SetNumberOfSubdivisions(2);
    filter->ProjectToLimitOn();
    filter->ComputeLimitNormalsOn();
    filter->ComputeCurvatureOn();
    subdtest::Messages messages;
    messages.Watch(filter);
    filter->Update();
    vtkPolyData* out = filter->GetOutput();
    ASSERT_GT(out->GetNumberOfPoints(), 0) << messages.Errors;
    vtkDataArray* normals = out->GetPointData()->GetArray("Normals");
    vtkDataArray* mean = out->GetPointData()->GetArray("Mean_Curvature");
    ASSERT_TRUE(normals && mean);
    vtkIdType undefined = 0;
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      const double* n = normals->GetTuple3(i);
      ASSERT_TRUE(std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2]) &&
        std::isfinite(mean->GetTuple1(i)));
      const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      if (length == 0.0)
      {
        ++undefined;
        EXPECT_EQ(mean->GetTuple1(i), 0.0);
      }
      else
      {
        EXPECT_NEAR(length, 1.0, 1e-6);
      }
    }
    ASSERT_GT(undefined, 0);
    EXPECT_NE(messages.Warnings.find("no tangent plane at " + std::to_string(undefined) + " output point"),
      std::string::npos)
      << messages.Warnings;
  }
}
}
