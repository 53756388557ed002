// vtkSubDCurveInterpolateFilter: the solved polygons' limit curves pass through the targets.
// Two independent checks: the closed forms of the uniform B-splines at their knots (closed
// curves) and, for every case, the distance from each target to the curve that
// vtkSubDCurveFilter's refinement rules converge to (10 levels: within 1e-6 of the limit).
#include "vtkSubDCurveFilter.h"
#include "vtkSubDCurveInterpolateFilter.h"

#include "SubDFilterTestSupport.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkIntArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace
{
using subdtest::Coordinates;

// A wavy polygon of n points, open or closed (first id repeated).
vtkSmartPointer<vtkPolyData> WavyPolyline(int n, bool closed)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkIdList> ids;
  for (int i = 0; i < n; ++i)
  {
    const double t = 2.0 * M_PI * i / n;
    const double r = 1.0 + 0.3 * std::sin(3.0 * t) + 0.05 * ((i * 7) % 5);
    points->InsertNextPoint(r * std::cos(t), r * std::sin(t), 0.2 * std::cos(2.0 * t));
    ids->InsertNextId(i);
  }
  if (closed)
  {
    ids->InsertNextId(0);
  }
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell(ids);
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetLines(lines);
  return mesh;
}

vtkSmartPointer<vtkPolyData> Solve(vtkPolyData* input, int scheme, bool closed = false)
{
  vtkNew<vtkSubDCurveInterpolateFilter> filter;
  filter->SetInputData(input);
  filter->SetScheme(scheme);
  filter->SetClosed(closed);
  filter->Update();
  EXPECT_EQ(filter->GetErrorCode(), 0UL);
  EXPECT_LE(filter->GetResidual(), 1e-12);
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->ShallowCopy(filter->GetOutput());
  return result;
}

double DistanceToSegment(const double* p, const double* a, const double* b)
{
  double ab[3], ap[3];
  double len2 = 0.0, dot = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    ab[c] = b[c] - a[c];
    ap[c] = p[c] - a[c];
    len2 += ab[c] * ab[c];
    dot += ab[c] * ap[c];
  }
  const double t = len2 > 0.0 ? std::clamp(dot / len2, 0.0, 1.0) : 0.0;
  double d2 = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    d2 += (ap[c] - t * ab[c]) * (ap[c] - t * ab[c]);
  }
  return std::sqrt(d2);
}

// The largest distance from a tagged target to the curve that 10 levels of `scheme` make of
// the polygons (every segment of every output line).
double LargestDistanceToRefinedCurve(
  vtkPolyData* polygons, const std::vector<double>& targets, const std::vector<char>& tagged, int scheme, bool closed)
{
  vtkNew<vtkSubDCurveFilter> refine;
  refine->SetInputData(polygons);
  refine->SetScheme(scheme);
  refine->SetClosed(closed);
  refine->SetNumberOfSubdivisions(10);
  refine->Update();
  vtkPolyData* curve = refine->GetOutput();
  double largest = 0.0;
  for (size_t v = 0; v < tagged.size(); ++v)
  {
    if (!tagged[v])
    {
      continue;
    }
    double nearest = std::numeric_limits<double>::infinity();
    auto it = vtk::TakeSmartPointer(curve->GetLines()->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      for (vtkIdType k = 0; k + 1 < n; ++k)
      {
        double a[3], b[3];
        curve->GetPoint(ids[k], a);
        curve->GetPoint(ids[k + 1], b);
        nearest = std::min(nearest, DistanceToSegment(&targets[3 * v], a, b));
      }
    }
    largest = std::max(largest, nearest);
  }
  return largest;
}

// The uniform B-spline at the knot where p_i's basis function peaks: (1, m, 1) / (m + 2);
// on an open polygon (cubic B-spline's end rule) the ends are the end points themselves.
double LargestClosedFormMiss(vtkPolyData* polygon, const std::vector<double>& targets, double middle, bool open = false)
{
  const std::vector<double> p = Coordinates(polygon);
  const size_t n = p.size() / 3;
  double largest = 0.0;
  for (size_t i = 0; i < n; ++i)
  {
    if (open && (i == 0 || i + 1 == n))
    {
      for (int c = 0; c < 3; ++c)
        largest = std::max(largest, std::abs(p[3 * i + c] - targets[3 * i + c]));
      continue;
    }
    const size_t prev = (i + n - 1) % n, next = (i + 1) % n;
    for (int c = 0; c < 3; ++c)
    {
      const double limit = (p[3 * prev + c] + middle * p[3 * i + c] + p[3 * next + c]) / (middle + 2.0);
      largest = std::max(largest, std::abs(limit - targets[3 * i + c]));
    }
  }
  return largest;
}
}

TEST(CurveInterpolateFilter, ClosedCurvesMatchTheBSplineClosedForms)
{
  for (const bool repeatedId : { true, false })
  {
    vtkSmartPointer<vtkPolyData> input = WavyPolyline(11, repeatedId);
    const std::vector<double> targets = Coordinates(input);
    const std::vector<char> all(11, 1);
    vtkSmartPointer<vtkPolyData> cubic = Solve(input, vtkSubDCurveFilter::SCHEME_CUBIC_BSPLINE, !repeatedId);
    EXPECT_LT(LargestClosedFormMiss(cubic, targets, 4.0), 1e-12);
    EXPECT_LT(LargestDistanceToRefinedCurve(cubic, targets, all, vtkSubDCurveFilter::SCHEME_CUBIC_BSPLINE, !repeatedId),
      1e-6);
    vtkSmartPointer<vtkPolyData> chaikin = Solve(input, vtkSubDCurveFilter::SCHEME_CHAIKIN, !repeatedId);
    EXPECT_LT(LargestClosedFormMiss(chaikin, targets, 6.0), 1e-12);
    EXPECT_LT(LargestDistanceToRefinedCurve(chaikin, targets, all, vtkSubDCurveFilter::SCHEME_CHAIKIN, !repeatedId),
      1e-6);
    // The approximating schemes must move the points to pass through them.
    EXPECT_GT(subdtest::LargestDistanceToNearestPoint(input, cubic), 1e-3);
  }
}

TEST(CurveInterpolateFilter, OpenCurvesPassThroughEveryPointAndKeepTheirEnds)
{
  for (int scheme : { vtkSubDCurveFilter::SCHEME_CHAIKIN, vtkSubDCurveFilter::SCHEME_CUBIC_BSPLINE })
  {
    for (int n : { 3, 4, 5, 9 })
    {
      vtkSmartPointer<vtkPolyData> input = WavyPolyline(n, false);
      const std::vector<double> targets = Coordinates(input);
      vtkSmartPointer<vtkPolyData> solved = Solve(input, scheme);
      if (scheme == vtkSubDCurveFilter::SCHEME_CUBIC_BSPLINE)
      {
        EXPECT_LT(LargestClosedFormMiss(solved, targets, 4.0, true), 1e-12) << n << " points";
      }
      const std::vector<double> p = Coordinates(solved);
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_EQ(p[c], targets[c]);
        EXPECT_EQ(p[3 * (n - 1) + c], targets[3 * (n - 1) + c]);
      }
      EXPECT_LT(LargestDistanceToRefinedCurve(solved, targets, std::vector<char>(n, 1), scheme, false), 1e-6)
        << "scheme " << scheme << ", " << n << " points";
    }
  }
}

TEST(CurveInterpolateFilter, FourPointInterpolatesAlready)
{
  vtkSmartPointer<vtkPolyData> input = WavyPolyline(8, true);
  vtkSmartPointer<vtkPolyData> solved = Solve(input, vtkSubDCurveFilter::SCHEME_FOUR_POINT);
  EXPECT_EQ(Coordinates(solved), Coordinates(input));
}

TEST(CurveInterpolateFilter, UniformPointsOnALineAreAFixedPoint)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkIdList> ids;
  for (int i = 0; i < 7; ++i)
  {
    points->InsertNextPoint(0.5 * i, 1.0 - 0.25 * i, 2.0);
    ids->InsertNextId(i);
  }
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell(ids);
  vtkNew<vtkPolyData> input;
  input->SetPoints(points);
  input->SetLines(lines);
  const std::vector<double> before = Coordinates(input);
  const std::vector<double> after = Coordinates(Solve(input, vtkSubDCurveFilter::SCHEME_CUBIC_BSPLINE));
  for (size_t k = 0; k < before.size(); ++k)
  {
    EXPECT_NEAR(after[k], before[k], 1e-12);
  }
}

TEST(CurveInterpolateFilter, UntaggedPointsKeepTheirPositionsAndCornersSplitTheCurve)
{
  vtkSmartPointer<vtkPolyData> input = WavyPolyline(12, true);
  vtkNew<vtkIntArray> tags;
  tags->SetName("Interpolate");
  vtkNew<vtkDoubleArray> corners;
  corners->SetName("CornerSharpness");
  std::vector<char> tagged(12);
  for (int i = 0; i < 12; ++i)
  {
    tagged[i] = i % 3 != 1;
    tags->InsertNextValue(tagged[i]);
    corners->InsertNextValue(i == 4 || i == 9 ? 10.0 : 0.0);
  }
  input->GetPointData()->AddArray(tags);
  input->GetPointData()->AddArray(corners);
  const std::vector<double> targets = Coordinates(input);
  vtkNew<vtkSubDCurveInterpolateFilter> filter;
  filter->SetInputData(input);
  filter->Update();
  ASSERT_EQ(filter->GetErrorCode(), 0UL);
  EXPECT_EQ(filter->GetNumberOfTaggedPoints(), 8);
  const std::vector<double> solved = Coordinates(filter->GetOutput());
  for (int i = 0; i < 12; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      if (!tagged[i] || i == 4 || i == 9)
      {
        EXPECT_EQ(solved[3 * i + c], targets[3 * i + c]) << "point " << i;
      }
    }
  }
  EXPECT_LT(LargestDistanceToRefinedCurve(filter->GetOutput(), targets, tagged, vtkSubDCurveFilter::SCHEME_CUBIC_BSPLINE,
              false),
    1e-6);
  EXPECT_TRUE(filter->GetOutput()->GetPointData()->GetArray("CornerSharpness")); // point data kept
}

TEST(CurveInterpolateFilter, RefinedOutputIsTheCurveFilterOfTheSolvedPolygons)
{
  vtkSmartPointer<vtkPolyData> input = WavyPolyline(9, false);
  vtkNew<vtkSubDCurveInterpolateFilter> filter;
  filter->SetInputData(input);
  filter->SetSchemeToChaikin();
  filter->Update();
  vtkNew<vtkSubDCurveFilter> refine;
  refine->SetInputConnection(filter->GetOutputPort());
  refine->SetSchemeToChaikin();
  refine->SetNumberOfSubdivisions(3);
  refine->Update();
  vtkNew<vtkSubDCurveInterpolateFilter> direct;
  direct->SetInputData(input);
  direct->SetSchemeToChaikin();
  direct->SetOutputRefinedCurve(true);
  direct->SetNumberOfSubdivisions(3);
  direct->Update();
  EXPECT_EQ(Coordinates(direct->GetOutput()), Coordinates(refine->GetOutput()));
  EXPECT_EQ(direct->GetOutput()->GetNumberOfLines(), 1);
}

TEST(CurveInterpolateFilter, APointInsideTwoCurvesCannotBeTagged)
{
  // Two polylines crossing at point 2, which is inside both.
  vtkNew<vtkPoints> points;
  for (double x : { -2.0, -1.0, 0.0, 1.0, 2.0 })
  {
    points->InsertNextPoint(x, 0.1 * x * x, 0);
  }
  points->InsertNextPoint(0, -1, 0);
  points->InsertNextPoint(0, 1, 0);
  vtkNew<vtkCellArray> lines;
  const vtkIdType a[] = { 0, 1, 2, 3, 4 }, b[] = { 5, 2, 6 };
  lines->InsertNextCell(5, a);
  lines->InsertNextCell(3, b);
  vtkNew<vtkPolyData> input;
  input->SetPoints(points);
  input->SetLines(lines);
  subdtest::Messages messages;
  vtkNew<vtkSubDCurveInterpolateFilter> filter;
  messages.Watch(filter);
  filter->SetInputData(input);
  filter->Update();
  EXPECT_NE(filter->GetErrorCode(), 0UL);
  EXPECT_NE(messages.Errors.find("Point 2 is tagged but it is on several curves"), std::string::npos)
    << messages.Errors;
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);

  // Untagged, it stays where it is and the rest is solved.
  vtkNew<vtkIntArray> tags;
  tags->SetName("Interpolate");
  for (int i = 0; i < 7; ++i)
  {
    tags->InsertNextValue(i != 2);
  }
  input->GetPointData()->AddArray(tags);
  filter->Modified();
  filter->Update();
  EXPECT_EQ(filter->GetErrorCode(), 0UL);
  double p[3];
  filter->GetOutput()->GetPoint(2, p);
  EXPECT_EQ(p[0], 0.0);
  EXPECT_EQ(p[1], 0.0);
}

TEST(CurveInterpolateFilter, NoLinesIsAnError)
{
  vtkNew<vtkPolyData> input;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  input->SetPoints(points);
  subdtest::Messages messages;
  vtkNew<vtkSubDCurveInterpolateFilter> filter;
  messages.Watch(filter);
  filter->SetInputData(input);
  filter->Update();
  EXPECT_NE(filter->GetErrorCode(), 0UL);
  EXPECT_NE(messages.Errors.find("no lines"), std::string::npos) << messages.Errors;
}

// A tag array without one value per point cannot say which points are meant: it is ignored
// (every point tagged), never read past its end.
TEST(CurveInterpolateFilter, ATagArrayOfTheWrongLengthIsIgnored)
{
  vtkSmartPointer<vtkPolyData> input = WavyPolyline(9, true);
  vtkNew<vtkIntArray> tags;
  tags->SetName("Interpolate");
  tags->InsertNextValue(0);
  input->GetPointData()->AddArray(tags);
  vtkNew<vtkSubDCurveInterpolateFilter> filter;
  filter->SetInputData(input);
  filter->Update();
  ASSERT_EQ(filter->GetErrorCode(), 0UL);
  EXPECT_EQ(filter->GetNumberOfTaggedPoints(), 9);
}
