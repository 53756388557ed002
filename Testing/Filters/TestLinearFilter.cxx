// vtkSubDLinearFilter: linear data is reproduced exactly, shapes are kept, split modes.
#include "vtkSubDLinearFilter.h"

#include "vtkCellArray.h"
#include "vtkCleanPolyData.h"
#include "vtkCubeSource.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace
{
double LinearField(const double p[3])
{
  return 2.0 * p[0] - 3.0 * p[1] + p[2] + 1.0;
}

// Adds the point-data array "Field" = LinearField(point).
void AddLinearField(vtkPolyData* mesh)
{
  vtkNew<vtkDoubleArray> field;
  field->SetName("Field");
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    field->InsertNextValue(LinearField(p));
  }
  mesh->GetPointData()->AddArray(field);
}

void ExpectFieldIsLinear(vtkPolyData* out)
{
  vtkDataArray* field = out->GetPointData()->GetArray("Field");
  ASSERT_NE(field, nullptr);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3];
    out->GetPoint(i, p);
    EXPECT_NEAR(field->GetTuple1(i), LinearField(p), 1e-12);
  }
}
}

TEST(LinearFilter, TrianglesSplitInFourAndLinearDataIsExact)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  vtkNew<vtkPolyData> mesh;
  mesh->DeepCopy(sphere->GetOutput());
  AddLinearField(mesh);
  vtkNew<vtkSubDLinearFilter> linear;
  linear->SetInputData(mesh);
  linear->SetNumberOfSubdivisions(3);
  // The sphere's points are float; ask for double output so the comparison is exact.
  linear->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  linear->Update();
  EXPECT_EQ(linear->GetOutput()->GetPoints()->GetDataType(), VTK_DOUBLE);
  EXPECT_EQ(linear->GetOutput()->GetNumberOfPolys(), mesh->GetNumberOfPolys() * 64);
  EXPECT_EQ(linear->GetOutput()->GetPolys()->GetMaxCellSize(), 3);
  ExpectFieldIsLinear(linear->GetOutput());
}

TEST(LinearFilter, PolygonsSplitIntoQuadsKeepTheShape)
{
  vtkNew<vtkCubeSource> cube;
  vtkNew<vtkCleanPolyData> weld;
  weld->SetInputConnection(cube->GetOutputPort());
  weld->Update();
  vtkNew<vtkPolyData> mesh;
  mesh->DeepCopy(weld->GetOutput());
  AddLinearField(mesh);
  vtkNew<vtkSubDLinearFilter> linear;
  linear->SetInputData(mesh);
  linear->SetNumberOfSubdivisions(2);
  linear->SetBoundaryRuleToNone(); // no effect on a linear scheme
  linear->Update();
  vtkPolyData* out = linear->GetOutput();
  EXPECT_EQ(out->GetNumberOfPolys(), 6 * 16);
  ExpectFieldIsLinear(out);
  // Every point stays on the cube's surface: one coordinate at +-0.5.
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3];
    out->GetPoint(i, p);
    const double m = std::max({ std::abs(p[0]), std::abs(p[1]), std::abs(p[2]) });
    EXPECT_DOUBLE_EQ(m, 0.5);
  }
}

TEST(LinearFilter, SplitModes)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  const vtkIdType triangles = sphere->GetOutput()->GetNumberOfPolys();
  vtkNew<vtkSubDLinearFilter> linear;
  linear->SetInputConnection(sphere->GetOutputPort());
  linear->SetSplitToQuads();
  EXPECT_STREQ(linear->GetSplitAsString(), "Quads");
  linear->Update();
  EXPECT_EQ(linear->GetOutput()->GetNumberOfPolys(), 3 * triangles);
  EXPECT_EQ(linear->GetOutput()->GetPolys()->GetMaxCellSize(), 4);

  vtkNew<vtkCubeSource> cube;
  vtkNew<vtkSubDLinearFilter> toTriangles;
  toTriangles->SetInputConnection(cube->GetOutputPort());
  toTriangles->SetSplitToTriangles();
  toTriangles->SetGlobalWarningDisplay(0);
  toTriangles->Update();
  EXPECT_EQ(toTriangles->GetOutput()->GetNumberOfPolys(), 6 * 2 * 4);
}
