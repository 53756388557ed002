// Filter tests of sharp features: crease lines with "Sharpness", "CornerSharpness",
// "Hole", automatic creases; the refined crease lines in the output (chaining one-level
// filters equals one N-level filter, sharpness decay per level); the closed form of an
// infinitely sharp crease (the cubic B-spline of its polyline); bad input.
#include "vtkSubDButterflyFilter.h"
#include "vtkSubDCatmullClarkFilter.h"
#include "vtkSubDDooSabinFilter.h"
#include "vtkSubDMidpointFilter.h"
#include "vtkSubDSqrt3Filter.h"
#include "vtkSubDLinearFilter.h"
#include "vtkSubDLoopFilter.h"

#include "SubDFilterTestSupport.h"

#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkPointData.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace
{
using subdtest::AddCornerSharpness;
using subdtest::AddCreases;
using subdtest::Messages;
using subdtest::ToPolyData;

// The 6 x 5 torus fixture: vertex (i, j) is (i mod 6) + 6 (j mod 5).
vtkIdType TorusVertex(int i, int j)
{
  return (i % 6) + 6 * (j % 5);
}

subdtest::TestMesh Torus(bool triangles)
{
  subdtest::TestMesh torus = subdtest::Grid(6, 5, true, true).Jitter(0.05);
  return triangles ? torus.Triangulated() : torus;
}

// A torus with a crease of varying semi-sharp sharpness, a crease loop, a branch, and
// semi-sharp corners.
vtkSmartPointer<vtkPolyData> CreasedTorus(bool triangles)
{
  vtkSmartPointer<vtkPolyData> mesh = ToPolyData(Torus(triangles));
  std::vector<std::array<vtkIdType, 2>> edges;
  std::vector<float> sharpness;
  const float along[] = { 0.5f, 1.5f, 2.5f, 3.7f };
  for (int i = 0; i < 4; ++i)
  {
    edges.push_back({ TorusVertex(i, 1), TorusVertex(i + 1, 1) });
    sharpness.push_back(along[i]);
  }
  const float loop[] = { 0.3f, 1.2f, 2.7f, 0.8f, 4.1f, 10.0f };
  for (int i = 0; i < 6; ++i)
  {
    edges.push_back({ TorusVertex(i, 3), TorusVertex(i + 1, 3) });
    sharpness.push_back(loop[i]);
  }
  edges.push_back({ TorusVertex(2, 3), TorusVertex(2, 4) });
  sharpness.push_back(1.4f);
  AddCreases(mesh, edges, sharpness);
  AddCornerSharpness(mesh, { { TorusVertex(4, 0), 2.6f }, { TorusVertex(1, 1), 0.4f } });
  return mesh;
}

// `weld` off keeps a cut (points duplicated on purpose) as a cut.
template <typename Filter>
vtkSmartPointer<vtkPolyData> Subdivide(
  vtkPolyData* input, int levels, int creaseMethod = 0, Messages* messages = nullptr, bool weld = true)
{
  vtkNew<Filter> filter;
  if (messages)
    messages->Watch(filter);
  filter->SetWeldCoincidentPoints(weld);
  filter->SetInputData(input);
  filter->SetNumberOfSubdivisions(levels);
  filter->SetCreaseMethod(creaseMethod);
  filter->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(filter->GetOutput());
  return out;
}

// The crease lines of a filter output as a map from sorted point pair to sharpness.
std::map<std::pair<vtkIdType, vtkIdType>, float> CreaseLines(vtkPolyData* mesh)
{
  std::map<std::pair<vtkIdType, vtkIdType>, float> lines;
  vtkDataArray* sharpness = mesh->GetCellData()->GetArray("Sharpness");
  vtkCellArray* cells = mesh->GetLines();
  if (!cells)
    return lines;
  vtkIdType n;
  const vtkIdType* pts;
  vtkIdType cell = mesh->GetNumberOfVerts();
  for (cells->InitTraversal(); cells->GetNextCell(n, pts); ++cell)
  {
    EXPECT_EQ(n, 2);
    EXPECT_NE(sharpness, nullptr);
    lines[{ std::min(pts[0], pts[1]), std::max(pts[0], pts[1]) }] =
      sharpness ? static_cast<float>(sharpness->GetComponent(cell, 0)) : -1.0f;
  }
  return lines;
}

template <typename Filter>
class CreaseChaining : public ::testing::Test
{
};
using ChainedFilters = ::testing::Types<vtkSubDCatmullClarkFilter, vtkSubDLoopFilter,
  vtkSubDButterflyFilter, vtkSubDLinearFilter, vtkSubDDooSabinFilter, vtkSubDMidpointFilter, vtkSubDSqrt3Filter>;
TYPED_TEST_SUITE(CreaseChaining, ChainedFilters);

// Three filters of one level each give the same surface, crease lines and corner sharpness
// as one filter of three levels, for both crease methods (sqrt(3) continues the parity of
// its boundary steps through the "SubDDepth" field data).
TYPED_TEST(CreaseChaining, ThreeOneLevelFiltersEqualOneThreeLevelFilter)
{
  const bool triangles = !std::is_same<TypeParam, vtkSubDCatmullClarkFilter>::value &&
    !std::is_same<TypeParam, vtkSubDDooSabinFilter>::value;
  for (int method : { 0, 1 })
  {
    vtkSmartPointer<vtkPolyData> input = CreasedTorus(triangles);
    vtkSmartPointer<vtkPolyData> once = Subdivide<TypeParam>(input, 3, method);
    vtkSmartPointer<vtkPolyData> chained = input;
    for (int l = 0; l < 3; ++l)
      chained = Subdivide<TypeParam>(chained, 1, method);

    ASSERT_GT(once->GetNumberOfPolys(), 0);
    ASSERT_EQ(once->GetNumberOfPoints(), chained->GetNumberOfPoints());
    ASSERT_EQ(once->GetNumberOfPolys(), chained->GetNumberOfPolys());
    double worst = 0.0;
    for (vtkIdType i = 0; i < once->GetNumberOfPoints(); ++i)
    {
      double a[3], b[3];
      once->GetPoint(i, a);
      chained->GetPoint(i, b);
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(a[c] - b[c]));
    }
    EXPECT_LE(worst, 1e-12) << "crease method " << method;
    vtkIdType n1, n2;
    const vtkIdType *p1, *p2;
    once->GetPolys()->InitTraversal();
    chained->GetPolys()->InitTraversal();
    while (once->GetPolys()->GetNextCell(n1, p1))
    {
      ASSERT_TRUE(chained->GetPolys()->GetNextCell(n2, p2));
      ASSERT_EQ(n1, n2);
      EXPECT_TRUE(std::equal(p1, p1 + n1, p2));
    }
    const auto linesOnce = CreaseLines(once);
    EXPECT_FALSE(linesOnce.empty());
    EXPECT_EQ(linesOnce, CreaseLines(chained)) << "crease method " << method;
    vtkDataArray* cornersOnce = once->GetPointData()->GetArray("CornerSharpness");
    vtkDataArray* cornersChained = chained->GetPointData()->GetArray("CornerSharpness");
    ASSERT_NE(cornersOnce, nullptr);
    ASSERT_NE(cornersChained, nullptr);
    for (vtkIdType i = 0; i < once->GetNumberOfPoints(); ++i)
      EXPECT_EQ(cornersOnce->GetComponent(i, 0), cornersChained->GetComponent(i, 0));
  }
}

// Uniform creasing: each level halves every crease edge and takes one unit of sharpness
// off it, and off each corner; what reaches zero disappears.
TEST(CreaseOutput, SharpnessDecaysOneUnitPerLevel)
{
  vtkSmartPointer<vtkPolyData> input = ToPolyData(subdtest::Cube());
  AddCreases(input, { { 0, 1 } }, { 2.5f });
  AddCornerSharpness(input, { { 5, 1.5f } });
  const std::map<int, std::pair<size_t, float>> expected = { { 0, { 1, 2.5f } }, { 1, { 2, 1.5f } },
    { 2, { 4, 0.5f } }, { 3, { 0, 0.0f } } };
  for (const auto& level : expected)
  {
    vtkSmartPointer<vtkPolyData> out = Subdivide<vtkSubDCatmullClarkFilter>(input, level.first);
    const auto lines = CreaseLines(out);
    EXPECT_EQ(lines.size(), level.second.first) << "level " << level.first;
    for (const auto& line : lines)
      EXPECT_FLOAT_EQ(line.second, level.second.second) << "level " << level.first;
    vtkDataArray* corners = out->GetPointData()->GetArray("CornerSharpness");
    ASSERT_NE(corners, nullptr);
    double largest = 0.0;
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
      largest = std::max(largest, corners->GetComponent(i, 0));
    EXPECT_FLOAT_EQ(largest, std::max(0.0, 1.5 - level.first)) << "level " << level.first;
  }
}

// With AutomaticCreases a cube's 12 edges (90 degrees) are creases; a finer feature angle
// than the dihedral angles of a smooth surface tags nothing.
TEST(CreaseOutput, FeatureAngleTagsExactlyTheCubesEdges)
{
  vtkNew<vtkSubDCatmullClarkFilter> filter;
  filter->SetInputData(ToPolyData(subdtest::Cube()));
  filter->AutomaticCreasesOn();
  filter->SetFeatureAngle(30.0);
  filter->SetNumberOfSubdivisions(0);
  filter->Update();
  const auto lines = CreaseLines(filter->GetOutput());
  EXPECT_EQ(lines.size(), 12u);
  for (const auto& line : lines)
    EXPECT_EQ(line.second, 10.0f);
  filter->SetNumberOfSubdivisions(2);
  filter->Update();
  EXPECT_EQ(CreaseLines(filter->GetOutput()).size(), 48u);
  // A sharp cube stays a cube: every output point lies on the cube's surface.
  vtkPolyData* out = filter->GetOutput();
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3];
    out->GetPoint(i, p);
    const double onFace = std::min({ std::abs(p[0]), std::abs(1 - p[0]), std::abs(p[1]), std::abs(1 - p[1]),
      std::abs(p[2]), std::abs(1 - p[2]) });
    EXPECT_LE(onFace, 1e-12) << "point " << i;
  }
  filter->SetFeatureAngle(91.0);
  filter->Update();
  EXPECT_TRUE(CreaseLines(filter->GetOutput()).empty());
}

// The uniform cubic B-spline of a closed control polygon at parameter t (unit knot spacing,
// control point i at t = i).
std::array<double, 3> ClosedCubicBSpline(const std::vector<std::array<double, 3>>& p, double t)
{
  const int n = static_cast<int>(p.size());
  const int i = static_cast<int>(std::floor(t));
  const double u = t - i;
  const double b[4] = { (1 - u) * (1 - u) * (1 - u) / 6, (3 * u * u * u - 6 * u * u + 4) / 6,
    (-3 * u * u * u + 3 * u * u + 3 * u + 1) / 6, u * u * u / 6 };
  std::array<double, 3> c{ 0, 0, 0 };
  for (int k = 0; k < 4; ++k)
    for (int d = 0; d < 3; ++d)
      c[d] += b[k] * p[((i - 1 + k) % n + n) % n][d];
  return c;
}

// The uniform quadratic B-spline of a closed control polygon at t (C(i) is the midpoint of
// control points i and i + 1).
std::array<double, 3> ClosedQuadraticBSpline(const std::vector<std::array<double, 3>>& p, double t)
{
  const int n = static_cast<int>(p.size());
  const int i = static_cast<int>(std::floor(t));
  const double u = t - i;
  const double b[3] = { (1 - u) * (1 - u) / 2, (-2 * u * u + 2 * u + 1) / 2, u * u / 2 };
  std::array<double, 3> c{ 0, 0, 0 };
  for (int k = 0; k < 3; ++k)
    for (int d = 0; d < 3; ++d)
      c[d] += b[k] * p[(i + k) % n][d];
  return c;
}

// Walks the crease lines of `out`, which must form one closed ring of
// control.size() * `pieces` segments, and compares it with `curve` of the control polygon:
// `sample(points, j)` turns the ordered crease polygon into the curve point at
// t = j / pieces (up to the start and direction of the walk).
template <typename Curve, typename Sample>
void CheckCreaseRing(vtkPolyData* out, const std::vector<std::array<double, 3>>& control, size_t pieces,
  Curve&& curve, Sample&& sample)
{
  std::map<vtkIdType, std::vector<vtkIdType>> next;
  for (const auto& line : CreaseLines(out))
  {
    next[line.first.first].push_back(line.first.second);
    next[line.first.second].push_back(line.first.first);
  }
  const size_t count = control.size() * pieces;
  ASSERT_EQ(next.size(), count);
  std::vector<vtkIdType> order{ next.begin()->first };
  while (order.size() < count)
  {
    const auto& around = next[order.back()];
    ASSERT_EQ(around.size(), 2u);
    order.push_back(order.size() > 1 && around[0] == order[order.size() - 2] ? around[1] : around[0]);
  }
  std::vector<std::array<double, 3>> polygon(count), limit(count);
  for (size_t j = 0; j < count; ++j)
    out->GetPoint(order[j], polygon[j].data());
  for (size_t j = 0; j < count; ++j)
    limit[j] = sample(polygon, j);
  double best = std::numeric_limits<double>::max();
  for (size_t start = 0; start < count; ++start)
    for (int direction : { 1, -1 })
    {
      double worst = 0.0;
      for (size_t j = 0; j < count; ++j)
      {
        const std::array<double, 3> exact = curve(control, static_cast<double>(j) / pieces);
        const auto& mine = limit[(start + direction * static_cast<long>(j) + 2 * count) % count];
        for (int d = 0; d < 3; ++d)
          worst = std::max(worst, std::abs(exact[d] - mine[d]));
      }
      best = std::min(best, worst);
    }
  EXPECT_LE(best, 1e-12);
}

// Refines a torus with an infinitely sharp crease ring by `levels` levels and compares the
// crease with `curve` of the ring's polygon (CheckCreaseRing): each ring edge must have
// become `pieces` crease edges.
template <typename Filter, typename Curve, typename Sample>
void CheckCreaseFollowsCurve(bool triangles, int levels, size_t pieces, Curve&& curve, Sample&& sample)
{
  const subdtest::TestMesh torus = Torus(triangles);
  vtkSmartPointer<vtkPolyData> input = ToPolyData(torus);
  std::vector<std::array<vtkIdType, 2>> ring;
  std::vector<std::array<double, 3>> control;
  for (int i = 0; i < 6; ++i)
  {
    ring.push_back({ TorusVertex(i, 2), TorusVertex(i + 1, 2) });
    control.push_back({ torus.Points[3 * TorusVertex(i, 2)], torus.Points[3 * TorusVertex(i, 2) + 1],
      torus.Points[3 * TorusVertex(i, 2) + 2] });
  }
  AddCreases(input, ring, {}); // no Sharpness array: infinitely sharp
  CheckCreaseRing(Subdivide<Filter>(input, levels), control, pieces, curve, sample);
}

// The limit mask (1 4 1)/6 of the level-k polygon of a cubic B-spline.
std::array<double, 3> CubicLimitPoint(const std::vector<std::array<double, 3>>& q, size_t j)
{
  const size_t n = q.size();
  std::array<double, 3> p;
  for (int d = 0; d < 3; ++d)
    p[d] = (q[(j + n - 1) % n][d] + 4 * q[j][d] + q[(j + 1) % n][d]) / 6;
  return p;
}

// Midpoints of Chaikin's polygon lie on the quadratic B-spline.
std::array<double, 3> Midpoint(const std::vector<std::array<double, 3>>& q, size_t j)
{
  std::array<double, 3> p;
  for (int d = 0; d < 3; ++d)
    p[d] = (q[j][d] + q[(j + 1) % q.size()][d]) / 2;
  return p;
}

TEST(CreaseClosedForm, InfinitelySharpCreaseIsTheCubicBSplineOfItsPolylineCatmullClark)
{
  CheckCreaseFollowsCurve<vtkSubDCatmullClarkFilter>(false, 3, 8, ClosedCubicBSpline, CubicLimitPoint);
}

TEST(CreaseClosedForm, InfinitelySharpCreaseIsTheCubicBSplineOfItsPolylineLoop)
{
  CheckCreaseFollowsCurve<vtkSubDLoopFilter>(true, 3, 8, ClosedCubicBSpline, CubicLimitPoint);
}

// Two sqrt(3) steps trisect the crease with the ternary masks of the cubic B-spline.
TEST(CreaseClosedForm, InfinitelySharpCreaseIsTheCubicBSplineOfItsPolylineSqrt3)
{
  CheckCreaseFollowsCurve<vtkSubDSqrt3Filter>(true, 4, 9, ClosedCubicBSpline, CubicLimitPoint);
}

TEST(CreaseClosedForm, InfinitelySharpCreaseIsTheQuadraticBSplineOfItsPolylineDooSabin)
{
  CheckCreaseFollowsCurve<vtkSubDDooSabinFilter>(false, 3, 8, ClosedQuadraticBSpline, Midpoint);
}

// A crease loop around one face of a cube turns at every vertex with that face alone inside
// the turn: the face's corner there gives Chaikin's two points, one on each crease edge, so
// the loop is cut like any other crease and no cage corner of it stays in the output.
TEST(CreaseClosedForm, CreaseLoopAroundOneFaceIsTheQuadraticBSplineOfItsSquareDooSabin)
{
  const subdtest::TestMesh cube = subdtest::Cube();
  vtkSmartPointer<vtkPolyData> input = ToPolyData(cube);
  const vtkIdType top[] = { 4, 5, 6, 7 };
  std::vector<std::array<vtkIdType, 2>> loop;
  std::vector<std::array<double, 3>> control;
  for (int i = 0; i < 4; ++i)
  {
    loop.push_back({ top[i], top[(i + 1) % 4] });
    control.push_back({ cube.Points[3 * top[i]], cube.Points[3 * top[i] + 1], cube.Points[3 * top[i] + 2] });
  }
  AddCreases(input, loop, {}); // infinitely sharp
  for (int levels = 1; levels <= 4; ++levels)
  {
    SCOPED_TRACE("levels " + std::to_string(levels));
    vtkSmartPointer<vtkPolyData> out = Subdivide<vtkSubDDooSabinFilter>(input, levels);
    CheckCreaseRing(out, control, size_t{ 1 } << levels, ClosedQuadraticBSpline, Midpoint);
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      double p[3];
      out->GetPoint(i, p);
      for (const auto& corner : control)
        EXPECT_GT(std::abs(p[0] - corner[0]) + std::abs(p[1] - corner[1]) + std::abs(p[2] - corner[2]), 1e-9)
          << "point " << i << " is a corner of the loop";
    }
  }
}

// The midpoint scheme keeps crease vertices and splits crease edges at their midpoints: the
// crease stays its polyline.
TEST(CreaseClosedForm, InfinitelySharpCreaseKeepsItsPolylineMidpoint)
{
  auto polyline = [](const std::vector<std::array<double, 3>>& p, double t) {
    const size_t i = static_cast<size_t>(std::floor(t));
    const double u = t - i;
    std::array<double, 3> c;
    for (int d = 0; d < 3; ++d)
      c[d] = (1 - u) * p[i % p.size()][d] + u * p[(i + 1) % p.size()][d];
    return c;
  };
  auto vertex = [](const std::vector<std::array<double, 3>>& q, size_t j) { return q[j]; };
  CheckCreaseFollowsCurve<vtkSubDMidpointFilter>(false, 3, 8, polyline, vertex);
}

TEST(CreaseInput, LineThatIsNotAnEdgeIsWarnedAndPassedThrough)
{
  vtkSmartPointer<vtkPolyData> input = ToPolyData(subdtest::Cube());
  AddCreases(input, { { 0, 1 }, { 0, 6 } }, { 10.0f, 3.0f }); // 0-6 crosses the cube
  Messages messages;
  vtkSmartPointer<vtkPolyData> out = Subdivide<vtkSubDCatmullClarkFilter>(input, 1, 0, &messages);
  EXPECT_EQ(messages.NumErrors, 0);
  EXPECT_NE(messages.Warnings.find("not edges of the surface"), std::string::npos) << messages.Warnings;
  EXPECT_NE(messages.Warnings.find("(0, 6)"), std::string::npos) << messages.Warnings;
  const auto lines = CreaseLines(out);
  ASSERT_EQ(lines.size(), 3u); // two halves of 0-1, and 0-6 unchanged
  bool passedThrough = false;
  for (const auto& line : lines)
  {
    double a[3], b[3], p0[3], p6[3];
    out->GetPoint(line.first.first, a);
    out->GetPoint(line.first.second, b);
    input->GetPoint(0, p0);
    input->GetPoint(6, p6);
    if (line.second == 3.0f)
    {
      passedThrough = true;
      EXPECT_TRUE((std::equal(a, a + 3, p0) && std::equal(b, b + 3, p6)) ||
        (std::equal(a, a + 3, p6) && std::equal(b, b + 3, p0)));
    }
  }
  EXPECT_TRUE(passedThrough);
}

TEST(CreaseInput, NegativeOrNaNSharpnessIsAnErrorNamingTheCell)
{
  for (float bad : { -1.0f, std::numeric_limits<float>::quiet_NaN() })
  {
    vtkSmartPointer<vtkPolyData> input = ToPolyData(subdtest::Cube());
    AddCreases(input, { { 0, 1 }, { 1, 2 } }, { 1.0f, bad });
    Messages messages;
    vtkSmartPointer<vtkPolyData> out = Subdivide<vtkSubDCatmullClarkFilter>(input, 1, 0, &messages);
    EXPECT_EQ(messages.NumErrors, 1);
    EXPECT_NE(messages.Errors.find("Line cell 1"), std::string::npos) << messages.Errors;
    EXPECT_EQ(out->GetNumberOfPoints(), 0);
  }
  vtkSmartPointer<vtkPolyData> input = ToPolyData(subdtest::Cube());
  AddCornerSharpness(input, { { 3, -2.0f } });
  Messages messages;
  vtkSmartPointer<vtkPolyData> out = Subdivide<vtkSubDCatmullClarkFilter>(input, 1, 0, &messages);
  EXPECT_NE(messages.Errors.find("Point 3"), std::string::npos) << messages.Errors;
  EXPECT_EQ(out->GetNumberOfPoints(), 0);
}

// Boundary edges are infinitely sharp already: a crease on one changes nothing.
TEST(CreaseInput, SharpnessOnABoundaryEdgeIsANoOp)
{
  vtkSmartPointer<vtkPolyData> plain = ToPolyData(subdtest::Grid(4, 3, false, false).Jitter(0.1));
  vtkSmartPointer<vtkPolyData> tagged = ToPolyData(subdtest::Grid(4, 3, false, false).Jitter(0.1));
  AddCreases(tagged, { { 0, 1 }, { 1, 2 } }, { 0.5f, 2.0f });
  vtkSmartPointer<vtkPolyData> a = Subdivide<vtkSubDCatmullClarkFilter>(plain, 2);
  vtkSmartPointer<vtkPolyData> b = Subdivide<vtkSubDCatmullClarkFilter>(tagged, 2);
  EXPECT_EQ(subdtest::Coordinates(a), subdtest::Coordinates(b));
  EXPECT_TRUE(CreaseLines(b).empty()); // boundary edges are not repeated as crease lines
}

// Hole faces are not output; their neighbours' points are unchanged (holes shape the
// surface, as in OpenSubdiv).
TEST(CreaseInput, HoleFacesAreNotOutput)
{
  vtkSmartPointer<vtkPolyData> plain = ToPolyData(Torus(false));
  vtkSmartPointer<vtkPolyData> holed = ToPolyData(Torus(false));
  vtkNew<vtkIntArray> hole;
  hole->SetName("Hole");
  hole->SetNumberOfTuples(holed->GetNumberOfCells());
  hole->Fill(0);
  hole->SetValue(7, 1);
  holed->GetCellData()->AddArray(hole);
  vtkSmartPointer<vtkPolyData> a = Subdivide<vtkSubDCatmullClarkFilter>(plain, 2);
  vtkSmartPointer<vtkPolyData> b = Subdivide<vtkSubDCatmullClarkFilter>(holed, 2);
  EXPECT_EQ(b->GetNumberOfPolys(), a->GetNumberOfPolys() - 16);
  // Every point of the holed output is a point of the plain output.
  std::set<std::array<double, 3>> plainPoints;
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    std::array<double, 3> p;
    a->GetPoint(i, p.data());
    plainPoints.insert(p);
  }
  for (vtkIdType i = 0; i < b->GetNumberOfPoints(); ++i)
  {
    std::array<double, 3> p;
    b->GetPoint(i, p.data());
    EXPECT_EQ(plainPoints.count(p), 1u) << "point " << i;
  }
}

// The feature arrays can have any names: a torus whose creases, corners and a hole are
// tagged under other names subdivides exactly as with the default names, and its output
// carries the decayed values under those names. An empty name reads no array.
TEST(CreaseInput, FeatureArraysCanHaveOtherNames)
{
  vtkSmartPointer<vtkPolyData> standard = CreasedTorus(false);
  vtkNew<vtkIntArray> hole;
  hole->SetName("Hole");
  hole->SetNumberOfTuples(standard->GetNumberOfCells());
  hole->Fill(0);
  hole->SetValue(standard->GetNumberOfLines() + 9, 1);
  standard->GetCellData()->AddArray(hole);
  vtkNew<vtkPolyData> renamed;
  renamed->DeepCopy(standard);
  renamed->GetCellData()->GetArray("Sharpness")->SetName("EdgeWeight");
  renamed->GetCellData()->GetArray("Hole")->SetName("Cut");
  renamed->GetPointData()->GetArray("CornerSharpness")->SetName("VertexWeight");

  vtkSmartPointer<vtkPolyData> expected = Subdivide<vtkSubDCatmullClarkFilter>(standard, 2);
  vtkNew<vtkSubDCatmullClarkFilter> filter;
  filter->SetInputData(renamed);
  filter->SetNumberOfSubdivisions(2);
  filter->SetSharpnessArrayName("EdgeWeight");
  filter->SetCornerSharpnessArrayName("VertexWeight");
  filter->SetHoleArrayName("Cut");
  filter->Update();
  vtkPolyData* out = filter->GetOutput();
  ASSERT_EQ(out->GetNumberOfPolys(), expected->GetNumberOfPolys());
  EXPECT_EQ(subdtest::Coordinates(out), subdtest::Coordinates(expected));
  const auto lines = CreaseLines(expected);
  ASSERT_FALSE(lines.empty());
  ASSERT_NE(out->GetCellData()->GetArray("EdgeWeight"), nullptr);
  EXPECT_EQ(out->GetCellData()->GetArray("Sharpness"), nullptr);
  for (vtkIdType c = 0; c < out->GetNumberOfLines(); ++c)
    EXPECT_EQ(out->GetCellData()->GetArray("EdgeWeight")->GetComponent(c, 0),
      expected->GetCellData()->GetArray("Sharpness")->GetComponent(c, 0));
  vtkDataArray* corners = out->GetPointData()->GetArray("VertexWeight");
  ASSERT_NE(corners, nullptr);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    EXPECT_EQ(corners->GetComponent(i, 0), expected->GetPointData()->GetArray("CornerSharpness")->GetComponent(i, 0));

  // No hole array: the hole face is output, and the standard names are not read instead.
  filter->SetHoleArrayName("");
  filter->SetInputData(standard);
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPolys(), expected->GetNumberOfPolys() + 16);
}

// Stencils are reused while creases stay the same, rebuilt when a sharpness changes.
TEST(CreaseInput, ChangedSharpnessRebuildsTheStencils)
{
  vtkSmartPointer<vtkPolyData> input = ToPolyData(subdtest::Cube());
  AddCreases(input, { { 0, 1 } }, { 2.0f });
  vtkNew<vtkSubDCatmullClarkFilter> filter;
  filter->SetInputData(input);
  filter->Update();
  double before[3];
  filter->GetOutput()->GetPoint(filter->GetOutput()->GetNumberOfPoints() - 1, before);
  input->Modified();
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfStencilBuilds(), 1);
  vtkFloatArray::SafeDownCast(input->GetCellData()->GetArray("Sharpness"))->SetValue(0, 0.0f);
  input->Modified();
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfStencilBuilds(), 2);
  EXPECT_TRUE(CreaseLines(filter->GetOutput()).empty());
}
}

namespace
{
template <typename Filter>
class CreaseAsBoundary : public ::testing::Test
{
};
using CreaseSchemes = ::testing::Types<vtkSubDCatmullClarkFilter, vtkSubDLoopFilter, vtkSubDButterflyFilter,
  vtkSubDDooSabinFilter, vtkSubDMidpointFilter, vtkSubDSqrt3Filter>;
TYPED_TEST_SUITE(CreaseAsBoundary, CreaseSchemes);

// An infinitely sharp crease loop around a cylinder makes the two sides independent: the
// result is the same as cutting the cylinder along the loop into two open cylinders whose
// boundaries take the scheme's boundary rules.
TYPED_TEST(CreaseAsBoundary, CreaseLoopEqualsACut)
{
  const bool triangles = !std::is_same<TypeParam, vtkSubDCatmullClarkFilter>::value &&
    !std::is_same<TypeParam, vtkSubDDooSabinFilter>::value && !std::is_same<TypeParam, vtkSubDMidpointFilter>::value;
  const bool sqrt3 = std::is_same<TypeParam, vtkSubDSqrt3Filter>::value;
  subdtest::TestMesh cylinder = subdtest::Grid(6, 4, true, false).Jitter(0.1);
  auto id = [](int i, int j) { return static_cast<subd::Index>(6 * j + (i % 6)); };
  subdtest::TestMesh cut;
  cut.Points = cylinder.Points;
  for (int i = 0; i < 6; ++i) // copies of the crease row for the faces above it
    cut.AddPoint(cylinder.Points[3 * id(i, 2)], cylinder.Points[3 * id(i, 2) + 1], cylinder.Points[3 * id(i, 2) + 2]);
  for (subd::Index f = 0; f < cylinder.NumFaces(); ++f)
  {
    std::vector<subd::Index> face(cylinder.Vertices.begin() + cylinder.Offsets[f],
      cylinder.Vertices.begin() + cylinder.Offsets[f + 1]);
    if (f >= 12) // face rows 2 and 3
      for (subd::Index& v : face)
        if (v >= id(0, 2) && v <= id(5, 2))
          v = 30 + v - id(0, 2);
    cut.AddFace(face);
  }
  vtkSmartPointer<vtkPolyData> creased = ToPolyData(triangles ? cylinder.Triangulated() : cylinder);
  std::vector<std::array<vtkIdType, 2>> ring;
  for (int i = 0; i < 6; ++i)
    ring.push_back({ id(i, 2), id(i + 1, 2) });
  AddCreases(creased, ring, {});
  vtkSmartPointer<vtkPolyData> a = Subdivide<TypeParam>(creased, 2);
  vtkSmartPointer<vtkPolyData> b =
    Subdivide<TypeParam>(ToPolyData(triangles ? cut.Triangulated() : cut), 2, 0, nullptr, false);
  ASSERT_GT(a->GetNumberOfPoints(), 0);
  EXPECT_EQ(a->GetNumberOfPolys(), b->GetNumberOfPolys());
  // The cut duplicates the crease's points: 6 * 4 after two levels (primal schemes keep and
  // split the crease row, Doo-Sabin's Chaikin rule doubles it per level too), 6 * 3 after
  // two sqrt(3) steps (one trisection).
  EXPECT_EQ(a->GetNumberOfPoints() + 6 * (sqrt3 ? 3 : 4), b->GetNumberOfPoints());
  // Every point of each result is a point of the other.
  EXPECT_LE(subdtest::LargestDistanceToNearestPoint(a, b), 1e-12);
  EXPECT_LE(subdtest::LargestDistanceToNearestPoint(b, a), 1e-12);
}
}

namespace
{
// A corner (CornerSharpness >= 10) is a point of the refined surface in every scheme that
// keeps vertices (the approximating ones pin it; the interpolating ones keep every vertex).
template <typename Filter>
void CheckCornerStaysPut(bool triangles)
{
  SCOPED_TRACE(vtkNew<Filter>()->GetClassName());
  vtkSmartPointer<vtkPolyData> input = ToPolyData(triangles ? subdtest::Cube().Triangulated() : subdtest::Cube());
  double corner[3];
  input->GetPoint(6, corner);
  auto distanceToCorner = [&corner](vtkPolyData* out) { return subdtest::DistanceToNearestPoint(out, corner); };
  // Untagged, every one of these schemes moves the cube's corner inside.
  EXPECT_GT(distanceToCorner(Subdivide<Filter>(input, 3)), 1e-3);
  AddCornerSharpness(input, { { 6, 10.0f } });
  Messages messages;
  vtkSmartPointer<vtkPolyData> out = Subdivide<Filter>(input, 3, 0, &messages);
  EXPECT_EQ(messages.NumErrors + messages.NumWarnings, 0) << messages.Warnings;
  EXPECT_EQ(distanceToCorner(out), 0.0);
}

TEST(CreaseCorners, SharpCornerIsKeptByEveryScheme)
{
  CheckCornerStaysPut<vtkSubDCatmullClarkFilter>(false);
  CheckCornerStaysPut<vtkSubDLoopFilter>(true);
  CheckCornerStaysPut<vtkSubDDooSabinFilter>(false);
  CheckCornerStaysPut<vtkSubDMidpointFilter>(false);
  CheckCornerStaysPut<vtkSubDSqrt3Filter>(true);
}
}

namespace
{
// The limit of a vertex does not depend on the level it is computed from: the limit points
// of level 2 are among those of level 3 (a vertex's child converges to the same point),
// with an infinitely sharp crease loop and a corner, on a closed and an open mesh. (Not at
// darts: there the smooth limit mask, as in OpenSubdiv, ignores the crease edge's
// midpoint rule, so it is an approximation that changes with the level.)
template <typename Filter>
void CheckLimitIsLevelIndependent(bool triangles)
{
  SCOPED_TRACE(vtkNew<Filter>()->GetClassName());
  std::vector<vtkSmartPointer<vtkPolyData>> inputs;
  vtkSmartPointer<vtkPolyData> torus = ToPolyData(Torus(triangles));
  std::vector<std::array<vtkIdType, 2>> ring;
  for (int i = 0; i < 6; ++i)
    ring.push_back({ TorusVertex(i, 2), TorusVertex(i + 1, 2) });
  AddCreases(torus, ring, {});
  AddCornerSharpness(torus, { { TorusVertex(4, 0), 10.0f } });
  inputs.push_back(torus);
  subdtest::TestMesh grid = subdtest::Grid(5, 4, false, false).Jitter(0.1);
  inputs.push_back(ToPolyData(triangles ? grid.Triangulated() : grid));
  for (vtkPolyData* input : inputs)
  {
    vtkSmartPointer<vtkPolyData> limits[2];
    for (int k = 0; k < 2; ++k)
    {
      vtkNew<Filter> filter;
      filter->SetInputData(input);
      filter->SetNumberOfSubdivisions(2 + k);
      filter->ProjectToLimitOn();
      filter->Update();
      limits[k] = vtkSmartPointer<vtkPolyData>::New();
      limits[k]->ShallowCopy(filter->GetOutput());
      ASSERT_GT(limits[k]->GetNumberOfPolys(), 0);
    }
    EXPECT_LE(subdtest::LargestDistanceToNearestPoint(limits[0], limits[1]), 1e-12);
  }
}

TEST(Limit, LimitPointsDoNotDependOnTheLevel)
{
  CheckLimitIsLevelIndependent<vtkSubDCatmullClarkFilter>(false);
  CheckLimitIsLevelIndependent<vtkSubDLoopFilter>(true);
}

// Regular quads: the limit point of a vertex is the uniform bicubic B-spline at its knot,
// (16 v + 4 sum e + sum f) / 36 of its 3 x 3 neighbourhood, here of a planar grid lifted by
// z = x^2: the uniform B-spline of control values x_i^2 at spacing H is x^2 + H^2 / 3.
TEST(Limit, RegularCatmullClarkVertexIsTheBicubicBSplinePoint)
{
  subdtest::TestMesh grid = subdtest::Grid(6, 6, false, false);
  for (size_t i = 0; i < grid.Points.size(); i += 3)
    grid.Points[i + 2] = grid.Points[i] * grid.Points[i];
  vtkNew<vtkSubDCatmullClarkFilter> filter;
  filter->SetInputData(ToPolyData(grid));
  filter->SetNumberOfSubdivisions(1);
  filter->ProjectToLimitOn();
  filter->Update();
  vtkPolyData* out = filter->GetOutput();
  double a[3], b[3];
  ToPolyData(grid)->GetPoint(0, a);
  ToPolyData(grid)->GetPoint(1, b);
  const double spacing = std::abs(b[0] - a[0]); // of the control net
  int interior = 0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3];
    out->GetPoint(i, p);
    // Away from the boundary (whose crease rule changes the surface) the B-spline's value.
    const double lo = 2 * spacing - 1e-9, hi = 4 * spacing + 1e-9; // two spacings from the boundary
    if (p[0] - a[0] > lo && p[0] - a[0] < hi && p[1] - a[1] > lo && p[1] - a[1] < hi)
    {
      ++interior;
      EXPECT_NEAR(p[2], p[0] * p[0] + spacing * spacing / 3.0, 1e-12) << "point " << i;
    }
  }
  EXPECT_GT(interior, 10);
}

TEST(Limit, ErrorsAreClear)
{
  // Catmull-Clark limit masks need quads: a pyramid at level 0 has triangles.
  subdtest::TestMesh pyramid;
  for (double p : { 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0, 0.0, 0.5, 0.5, 1.0 })
    pyramid.Points.push_back(p);
  pyramid.AddFace({ 0, 3, 2, 1 });
  for (subd::Index i = 0; i < 4; ++i)
    pyramid.AddFace({ i, (i + 1) % 4, 4 });
  {
    vtkNew<vtkSubDCatmullClarkFilter> filter;
    Messages messages;
    messages.Watch(filter);
    filter->SetInputData(ToPolyData(pyramid));
    filter->SetNumberOfSubdivisions(0);
    filter->ProjectToLimitOn();
    filter->Update();
    EXPECT_NE(messages.Errors.find("refine one level first"), std::string::npos) << messages.Errors;
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
    filter->SetNumberOfSubdivisions(1);
    filter->Update();
    EXPECT_GT(filter->GetOutput()->GetNumberOfPolys(), 0);
  }
  vtkNew<vtkSubDButterflyFilter> filter;
  Messages messages;
  messages.Watch(filter);
  filter->SetInputData(ToPolyData(pyramid.Triangulated()));
  filter->ComputeLimitNormalsOn();
  filter->Update();
  EXPECT_NE(messages.Errors.find("no limit tangent masks"), std::string::npos) << messages.Errors;
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
}
}
