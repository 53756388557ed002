// The explorer's crease editing without its GUI: picking a cage element from screen
// positions, and the cage edits keeping every other cell and its data in place. (That the
// edited cage refines as OpenSubdiv does is checked in TestOracleOpenSubdiv.)
#include "SubDBuiltinCages.h"
#include "SubDCageEditing.h"
#include "SubDCagePicking.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <array>

#include <gtest/gtest.h>

TEST(CagePicking, NearestVertexFirstThenNearestEdge)
{
  // A unit square seen from above, 100 px per unit.
  vtkSmartPointer<vtkPolyData> cage = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  for (const std::array<double, 2>& xy : { std::array<double, 2>{ 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } })
    points->InsertNextPoint(xy[0], xy[1], 0.0);
  cage->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  const vtkIdType square[4] = { 0, 1, 2, 3 };
  polys->InsertNextCell(4, square);
  cage->SetPolys(polys);
  const std::vector<double> screen = { 0, 0, 100, 0, 100, 100, 0, 100 };
  auto picked = subdapp::PickCageElement(cage, screen, 103, 96);
  EXPECT_EQ(picked.A, 2);
  EXPECT_EQ(picked.B, -1);
  picked = subdapp::PickCageElement(cage, screen, 50, 97);
  EXPECT_EQ(picked.A, 2);
  EXPECT_EQ(picked.B, 3);
  picked = subdapp::PickCageElement(cage, screen, 50, 50);
  EXPECT_EQ(picked.A, -1);
}

TEST(CageEditing, EditsKeepTheOtherCellsAndTheirData)
{
  vtkSmartPointer<vtkPolyData> cage = subdapp::MakeBuiltinCage("creased-cube");
  ASSERT_GT(cage->GetNumberOfLines(), 0);
  const vtkIdType polys = cage->GetNumberOfPolys();
  vtkNew<vtkIdList> firstLine;
  cage->GetLines()->GetCellAtId(0, firstLine);
  const vtkIdType segments = [&]() {
    vtkIdType count = 0;
    vtkNew<vtkIdList> cell;
    for (cage->GetLines()->InitTraversal(); cage->GetLines()->GetNextCell(cell);)
      count += cell->GetNumberOfIds() - 1;
    return count;
  }();
  const double before = subdapp::GetEdgeSharpness(cage, firstLine->GetId(0), firstLine->GetId(1));
  EXPECT_GT(before, 0.0);
  // A new crease on a cube edge that has none: find one through the first face.
  vtkNew<vtkIdList> face;
  cage->GetPolys()->GetCellAtId(0, face);
  vtkIdType a = -1, b = -1;
  for (vtkIdType k = 0; k < face->GetNumberOfIds() && a < 0; ++k)
  {
    const vtkIdType p = face->GetId(k), q = face->GetId((k + 1) % face->GetNumberOfIds());
    if (subdapp::GetEdgeSharpness(cage, p, q) == 0.0)
    {
      a = p;
      b = q;
    }
  }
  ASSERT_GE(a, 0);
  std::string error;
  ASSERT_TRUE(subdapp::SetEdgeSharpness(cage, a, b, 1.5, error)) << error;
  EXPECT_EQ(subdapp::GetEdgeSharpness(cage, b, a), 1.5);
  EXPECT_EQ(cage->GetNumberOfLines(), segments + 1); // lines become 2-point segments
  EXPECT_EQ(cage->GetNumberOfPolys(), polys);
  EXPECT_EQ(subdapp::GetEdgeSharpness(cage, firstLine->GetId(0), firstLine->GetId(1)), before);
  vtkDataArray* sharpness = cage->GetCellData()->GetArray("Sharpness");
  ASSERT_NE(sharpness, nullptr);
  EXPECT_EQ(sharpness->GetNumberOfTuples(), cage->GetNumberOfCells());
  ASSERT_TRUE(subdapp::SetEdgeSharpness(cage, a, b, 0.0, error)) << error;
  EXPECT_EQ(cage->GetNumberOfLines(), segments);
  EXPECT_FALSE(subdapp::SetEdgeSharpness(cage, a, b, -1.0, error));
  EXPECT_FALSE(subdapp::SetVertexSharpness(cage, cage->GetNumberOfPoints(), 1.0, error));
  EXPECT_NE(error.find("no vertex"), std::string::npos) << error;
  ASSERT_TRUE(subdapp::SetVertexSharpness(cage, 3, 2.0, error)) << error;
  EXPECT_EQ(subdapp::GetVertexSharpness(cage, 3), 2.0);
  EXPECT_EQ(subdapp::GetVertexSharpness(cage, 4), 0.0);
}
