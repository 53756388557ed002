// vtkSubDCurveFilter: pipelines, closed/open lines, corners, point and cell data, polygons
// passed through, limit points and tangents, bad input.
#include "SubDFilterTestSupport.h"
#include "vtkSubDCurveFilter.h"

#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{
const int AllSchemes[] = { vtkSubDCurveFilter::SCHEME_CHAIKIN, vtkSubDCurveFilter::SCHEME_CUBIC_BSPLINE,
  vtkSubDCurveFilter::SCHEME_FOUR_POINT };

// A polydata with the given points and one polyline per id list.
vtkSmartPointer<vtkPolyData> Polylines(
  const std::vector<std::array<double, 3>>& points, const std::vector<std::vector<vtkIdType>>& lines)
{
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  for (const auto& p : points)
    pts->InsertNextPoint(p.data());
  vtkNew<vtkCellArray> cells;
  for (const auto& line : lines)
    cells->InsertNextCell(static_cast<vtkIdType>(line.size()), line.data());
  poly->SetPoints(pts);
  poly->SetLines(cells);
  return poly;
}

std::vector<std::array<double, 3>> Zigzag(int n)
{
  std::vector<std::array<double, 3>> points;
  for (int i = 0; i < n; ++i)
    points.push_back({ double(i), (i % 2) ? 1.0 : -0.5, 0.1 * i * i });
  return points;
}

// Marks point `corner` of `input` infinitely sharp ("CornerSharpness" 10, the others 0).
void AddCorner(vtkPolyData* input, vtkIdType corner)
{
  vtkNew<vtkFloatArray> sharpness;
  sharpness->SetName("CornerSharpness");
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
    sharpness->InsertNextValue(i == corner ? 10.0f : 0.0f);
  input->GetPointData()->AddArray(sharpness);
}

std::vector<vtkIdType> Range(vtkIdType n)
{
  std::vector<vtkIdType> ids;
  for (vtkIdType i = 0; i < n; ++i)
    ids.push_back(i);
  return ids;
}

vtkSmartPointer<vtkPolyData> RunCurveFilter(vtkPolyData* input, int scheme, int levels, subdtest::Messages* messages = nullptr,
  bool limit = false, bool tangents = false)
{
  vtkNew<vtkSubDCurveFilter> filter;
  if (messages)
    messages->Watch(filter);
  filter->SetInputData(input);
  filter->SetScheme(scheme);
  filter->SetNumberOfSubdivisions(levels);
  filter->SetProjectToLimit(limit);
  filter->SetComputeTangents(tangents);
  filter->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(filter->GetOutput());
  return out;
}

std::vector<vtkIdType> CellIds(vtkPolyData* poly, vtkIdType cell)
{
  vtkNew<vtkIdList> ids;
  poly->GetCellPoints(cell, ids);
  return std::vector<vtkIdType>(ids->begin(), ids->end());
}

TEST(CurveFilter, OpenAndClosedPolylineCounts)
{
  for (int scheme : AllSchemes)
  {
    // Open: 5 points; closed: 6 points with the first repeated at the end.
    auto open = RunCurveFilter(Polylines(Zigzag(5), { Range(5) }), scheme, 2);
    const vtkIdType openExpected = scheme == vtkSubDCurveFilter::SCHEME_CHAIKIN ? 3 * 4 + 2 : 4 * 4 + 1;
    ASSERT_EQ(open->GetNumberOfLines(), 1);
    EXPECT_EQ(open->GetNumberOfPoints(), openExpected);
    EXPECT_EQ(CellIds(open, 0).size(), static_cast<size_t>(openExpected));

    std::vector<vtkIdType> ring = Range(6);
    ring.push_back(0);
    auto closed = RunCurveFilter(Polylines(Zigzag(6), { ring }), scheme, 2);
    EXPECT_EQ(closed->GetNumberOfPoints(), 24);
    const std::vector<vtkIdType> ids = CellIds(closed, 0);
    ASSERT_EQ(ids.size(), 25u);
    EXPECT_EQ(ids.front(), ids.back()) << "a closed polyline stays closed";

    // The Closed option closes a polyline that does not repeat its first point.
    vtkNew<vtkSubDCurveFilter> filter;
    filter->SetInputData(Polylines(Zigzag(6), { Range(6) }));
    filter->SetScheme(scheme);
    filter->SetNumberOfSubdivisions(2);
    filter->ClosedOn();
    filter->Update();
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 24);
    EXPECT_LE(subdtest::LargestDistanceToNearestPoint(filter->GetOutput(), closed), 1e-15);
  }
}

TEST(CurveFilter, FourPointInterpolatesAndEndsAreKept)
{
  const auto points = Zigzag(6);
  for (int scheme : AllSchemes)
  {
    auto out = RunCurveFilter(Polylines(points, { Range(6) }), scheme, 3);
    const std::vector<vtkIdType> ids = CellIds(out, 0);
    double first[3], last[3];
    out->GetPoint(ids.front(), first);
    out->GetPoint(ids.back(), last);
    EXPECT_EQ(first[0], points.front()[0]);
    EXPECT_EQ(last[2], points.back()[2]);
    if (scheme == vtkSubDCurveFilter::SCHEME_FOUR_POINT)
      for (const auto& p : points)
        EXPECT_EQ(subdtest::DistanceToNearestPoint(out, p.data()), 0.0);
  }
}

TEST(CurveFilter, PointDataFollowsThePoints)
{
  // A copy of the coordinates as point data comes out equal to the output points, for every
  // scheme, with and without the limit projection; an unsigned char array never wraps.
  for (int scheme : AllSchemes)
    for (bool limit : { false, true })
    {
      auto input = Polylines(Zigzag(7), { Range(7) });
      vtkNew<vtkDoubleArray> copy;
      copy->SetName("Copy");
      copy->SetNumberOfComponents(3);
      vtkNew<vtkUnsignedCharArray> colour;
      colour->SetName("Colour");
      for (vtkIdType i = 0; i < 7; ++i)
      {
        copy->InsertNextTuple(input->GetPoint(i));
        colour->InsertNextValue(i % 2 ? 255 : 0);
      }
      input->GetPointData()->AddArray(copy);
      input->GetPointData()->SetScalars(colour);
      auto out = RunCurveFilter(input, scheme, 3, nullptr, limit);
      vtkDataArray* outCopy = out->GetPointData()->GetArray("Copy");
      ASSERT_NE(outCopy, nullptr);
      ASSERT_EQ(outCopy->GetNumberOfTuples(), out->GetNumberOfPoints());
      for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(outCopy->GetComponent(i, c), out->GetPoint(i)[c], 1e-12);
      vtkDataArray* outColour = out->GetPointData()->GetScalars();
      ASSERT_NE(outColour, nullptr);
      EXPECT_STREQ(outColour->GetName(), "Colour");
      double range[2];
      outColour->GetRange(range);
      EXPECT_GE(range[0], 0.0);
      EXPECT_LE(range[1], 255.0);
      if (scheme == vtkSubDCurveFilter::SCHEME_FOUR_POINT)
      {
        // Negative weights overshoot 255 and 0: clamped, so both extremes are reached.
        EXPECT_EQ(range[0], 0.0);
        EXPECT_EQ(range[1], 255.0);
      }
    }
}

TEST(CurveFilter, PolygonsPassThroughWithTheirData)
{
  // A quad with a crease line along one edge and a free polyline: the quad keeps its ids and
  // points; the lines are refined after them.
  auto input = Polylines({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 2, 0, 0 }, { 3, 1, 0 } },
    { { 0, 1, 2 }, { 4, 5 } });
  vtkNew<vtkCellArray> polys;
  const vtkIdType quad[4] = { 0, 1, 2, 3 };
  polys->InsertNextCell(4, quad);
  input->SetPolys(polys);
  vtkNew<vtkIntArray> label;
  label->SetName("Label");
  for (int v : { 10, 20, 30 })
    label->InsertNextValue(v); // lines 10, 20; quad 30
  input->GetCellData()->AddArray(label);
  for (int scheme : AllSchemes)
  {
    auto out = RunCurveFilter(input, scheme, 2);
    ASSERT_EQ(out->GetNumberOfPolys(), 1);
    ASSERT_EQ(out->GetNumberOfLines(), 2);
    for (vtkIdType i = 0; i < 6; ++i)
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(out->GetPoint(i)[c], input->GetPoint(i)[c]);
    EXPECT_EQ(CellIds(out, 2), (std::vector<vtkIdType>{ 0, 1, 2, 3 }));
    vtkDataArray* outLabel = out->GetCellData()->GetArray("Label");
    ASSERT_NE(outLabel, nullptr);
    EXPECT_EQ(outLabel->GetComponent(0, 0), 10);
    EXPECT_EQ(outLabel->GetComponent(1, 0), 20);
    EXPECT_EQ(outLabel->GetComponent(2, 0), 30);
    for (vtkIdType id : CellIds(out, 0))
      EXPECT_GE(id, 6) << "refined lines use their own points";
  }
}

TEST(CurveFilter, CornersSplitTheCurve)
{
  // Point 3 is a corner: it is kept, and each side is refined on its own, so moving a point
  // on one side does not move the other side's output.
  auto input = Polylines(Zigzag(7), { Range(7) });
  AddCorner(input, 3);
  for (int scheme : AllSchemes)
  {
    auto out = RunCurveFilter(input, scheme, 3);
    const double* corner = input->GetPoint(3);
    EXPECT_EQ(subdtest::DistanceToNearestPoint(out, corner), 0.0);
    ASSERT_EQ(out->GetNumberOfLines(), 1) << "one polyline per input line";

    auto moved = vtkSmartPointer<vtkPolyData>::New();
    moved->DeepCopy(input);
    moved->GetPoints()->SetPoint(5, 5.0, 3.0, 2.0);
    auto outMoved = RunCurveFilter(moved, scheme, 3);
    const std::vector<vtkIdType> ids = CellIds(out, 0), idsMoved = CellIds(outMoved, 0);
    ASSERT_EQ(ids.size(), idsMoved.size());
    size_t cornerAt = ids.size();
    for (size_t k = 0; k < ids.size(); ++k)
    {
      double p[3];
      out->GetPoint(ids[k], p);
      if (p[0] == corner[0] && p[1] == corner[1] && p[2] == corner[2])
        cornerAt = k;
      if (k <= cornerAt)
        for (int c = 0; c < 3; ++c)
          EXPECT_EQ(p[c], outMoved->GetPoint(idsMoved[k])[c]) << "point " << k << " before the corner";
    }
    EXPECT_EQ(cornerAt, ids.size() / 2) << "the corner sits between two equal halves";

    // New points are smooth: one level at a time gives the same curve as all levels at once.
    auto step = RunCurveFilter(RunCurveFilter(RunCurveFilter(input, scheme, 1), scheme, 1), scheme, 1);
    EXPECT_EQ(step->GetNumberOfPoints(), out->GetNumberOfPoints());
    EXPECT_LE(subdtest::LargestDistanceToNearestPoint(step, out), 1e-14);
  }
}

TEST(CurveFilter, ClosedCurveWithACornerStartsThere)
{
  std::vector<vtkIdType> ring = Range(6);
  ring.push_back(0);
  auto input = Polylines(Zigzag(6), { ring });
  AddCorner(input, 2);
  auto out = RunCurveFilter(input, vtkSubDCurveFilter::SCHEME_CUBIC_BSPLINE, 2);
  const std::vector<vtkIdType> ids = CellIds(out, 0);
  ASSERT_EQ(ids.size(), 25u);
  EXPECT_EQ(ids.front(), ids.back());
  for (int c = 0; c < 3; ++c)
    EXPECT_EQ(out->GetPoint(ids.front())[c], input->GetPoint(2)[c]);
}

TEST(CurveFilter, SharedEndPointsStayShared)
{
  auto out = RunCurveFilter(Polylines(Zigzag(5), { { 0, 1, 2 }, { 2, 3, 4 } }), vtkSubDCurveFilter::SCHEME_CUBIC_BSPLINE, 2);
  ASSERT_EQ(out->GetNumberOfLines(), 2);
  EXPECT_EQ(CellIds(out, 0).back(), CellIds(out, 1).front());
  EXPECT_EQ(out->GetNumberOfPoints(), 2 * 9 - 1);
}

TEST(CurveFilter, RepeatedPointsAreControlPointsLikeAnyOther)
{
  // A doubled control point pulls the cubic B-spline towards it; the output stays finite and
  // the doubled point is a limit point of the curve: (p + 4p + p)/6 = p.
  const auto points = Zigzag(5);
  auto out = RunCurveFilter(Polylines(points, { { 0, 1, 2, 2, 2, 3, 4 } }), vtkSubDCurveFilter::SCHEME_CUBIC_BSPLINE, 3, nullptr,
    true);
  EXPECT_EQ(subdtest::DistanceToNearestPoint(out, points[2].data()), 0.0);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_TRUE(std::isfinite(out->GetPoint(i)[c]));
}

TEST(CurveFilter, TangentsAreUnitAndFollowTheCurve)
{
  // A regular polygon: by symmetry every limit tangent is perpendicular to its radius.
  std::vector<std::array<double, 3>> circle;
  for (int i = 0; i < 8; ++i)
    circle.push_back({ std::cos(i * M_PI / 4), std::sin(i * M_PI / 4), 0.0 });
  std::vector<vtkIdType> ring = Range(8);
  ring.push_back(0);
  for (int scheme : AllSchemes)
  {
    auto out = RunCurveFilter(Polylines(circle, { ring }), scheme, 2, nullptr, true, true);
    vtkDataArray* tangents = out->GetPointData()->GetTangents();
    ASSERT_NE(tangents, nullptr);
    EXPECT_STREQ(tangents->GetName(), "Tangents");
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      const double* t = tangents->GetTuple3(i);
      const double* p = out->GetPoint(i);
      EXPECT_NEAR(std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]), 1.0, 1e-12);
      EXPECT_NEAR(t[0] * p[0] + t[1] * p[1], 0.0, 0.05) << "point " << i << ": a near-circle";
      EXPECT_GT(p[0] * t[1] - p[1] * t[0], 0.0) << "counter-clockwise, as the polygon";
    }
  }
}

TEST(CurveFilter, BadInput)
{
  // No lines: a warning, and the input comes through.
  {
    auto quad = subdtest::ToPolyData(subdtest::Grid(1, 1, false, false));
    subdtest::Messages messages;
    auto out = RunCurveFilter(quad, vtkSubDCurveFilter::SCHEME_CHAIKIN, 2, &messages);
    EXPECT_EQ(messages.NumErrors, 0);
    EXPECT_NE(messages.Warnings.find("no lines"), std::string::npos) << messages.Warnings;
    EXPECT_EQ(out->GetNumberOfPolys(), 1);
    EXPECT_EQ(out->GetNumberOfPoints(), quad->GetNumberOfPoints());
  }
  // NaN: an error and an empty output.
  {
    auto points = Zigzag(4);
    points[2][1] = std::numeric_limits<double>::quiet_NaN();
    subdtest::Messages messages;
    auto out = RunCurveFilter(Polylines(points, { Range(4) }), vtkSubDCurveFilter::SCHEME_FOUR_POINT, 1, &messages);
    EXPECT_EQ(messages.NumErrors, 1);
    EXPECT_NE(messages.Errors.find("Point 2"), std::string::npos) << messages.Errors;
    EXPECT_EQ(out->GetNumberOfPoints(), 0);
  }
  // A one-point polyline: kept as a vertex, with a warning; the other line is refined.
  {
    subdtest::Messages messages;
    auto input = Polylines(Zigzag(4), { { 3 }, { 0, 1, 2 } });
    vtkNew<vtkIntArray> label;
    label->SetName("Label");
    label->InsertNextValue(7);
    label->InsertNextValue(8);
    input->GetCellData()->AddArray(label);
    auto out = RunCurveFilter(input, vtkSubDCurveFilter::SCHEME_CUBIC_BSPLINE, 1, &messages);
    EXPECT_EQ(messages.NumErrors, 0);
    EXPECT_NE(messages.Warnings.find("single point"), std::string::npos) << messages.Warnings;
    ASSERT_EQ(out->GetNumberOfVerts(), 1);
    ASSERT_EQ(out->GetNumberOfLines(), 1);
    const std::vector<vtkIdType> single = CellIds(out, 0);
    ASSERT_EQ(single.size(), 1u);
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(out->GetPoint(single[0])[c], Zigzag(4)[3][c]);
    EXPECT_EQ(CellIds(out, 1).size(), 5u);
    EXPECT_EQ(out->GetCellData()->GetArray("Label")->GetComponent(0, 0), 7);
    EXPECT_EQ(out->GetCellData()->GetArray("Label")->GetComponent(1, 0), 8);
  }
  // Out-of-range ids: an error naming the cell.
  {
    subdtest::Messages messages;
    auto out = RunCurveFilter(Polylines(Zigzag(3), { { 0, 1, 7 } }), vtkSubDCurveFilter::SCHEME_CUBIC_BSPLINE, 1, &messages);
    EXPECT_EQ(messages.NumErrors, 1);
    EXPECT_NE(messages.Errors.find("Cell 0"), std::string::npos) << messages.Errors;
    EXPECT_EQ(out->GetNumberOfPoints(), 0);
  }
  // A request far above the memory budget is refused before allocating.
  {
    subdtest::Messages messages;
    vtkNew<vtkSubDCurveFilter> filter;
    messages.Watch(filter);
    filter->SetInputData(Polylines(Zigzag(100), { Range(100) }));
    filter->SetNumberOfSubdivisions(30);
    filter->Update();
    EXPECT_EQ(messages.NumErrors, 1);
    EXPECT_NE(messages.Errors.find("MaximumMemory"), std::string::npos) << messages.Errors;
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
  }
}
}
