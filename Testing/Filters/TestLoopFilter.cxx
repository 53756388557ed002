// Triangle-scheme filter specifics: Loop's triangle counts, polygons triangulated with a
// warning; the butterfly's overshoot clamped in unsigned char arrays.
#include "vtkSubDButterflyFilter.h"
#include "vtkSubDLoopFilter.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkCubeSource.h"
#include "vtkCleanPolyData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkDoubleArray.h"
#include "vtkPointData.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

TEST(LoopFilter, SpherePipelineQuadruplesTriangles)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(12);
  sphere->SetPhiResolution(8);
  vtkNew<vtkSubDLoopFilter> loop;
  loop->SetInputConnection(sphere->GetOutputPort());
  loop->SetNumberOfSubdivisions(3);
  loop->Update();
  sphere->Update();
  vtkPolyData* out = loop->GetOutput();
  EXPECT_EQ(out->GetNumberOfPolys(), sphere->GetOutput()->GetNumberOfPolys() * 64);
  EXPECT_EQ(out->GetPolys()->GetMaxCellSize(), 3);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3];
    out->GetPoint(i, p);
    EXPECT_LE(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), 0.5 + 1e-12);
  }
}

TEST(LoopFilter, QuadsAreSplitIntoFansWithOneWarning)
{
  vtkNew<vtkCubeSource> cube;
  vtkNew<vtkCleanPolyData> weld;
  weld->SetInputConnection(cube->GetOutputPort());
  vtkNew<vtkSubDLoopFilter> loop;
  loop->SetInputConnection(weld->GetOutputPort());
  loop->SetNumberOfSubdivisions(2);
  std::string warnings;
  vtkNew<vtkCallbackCommand> cb;
  cb->SetClientData(&warnings);
  cb->SetCallback([](vtkObject*, unsigned long, void* client, void* data) {
    *static_cast<std::string*>(client) += static_cast<const char*>(data);
  });
  loop->AddObserver(vtkCommand::WarningEvent, cb);
  loop->Update();
  EXPECT_NE(warnings.find("6 polygon(s) with more than 3 corners"), std::string::npos) << warnings;
  EXPECT_EQ(loop->GetOutput()->GetNumberOfPolys(), 12 * 16);
  // Closed triangle mesh: V = F/2 + 2.
  EXPECT_EQ(loop->GetOutput()->GetNumberOfPoints(), 12 * 16 / 2 + 2);
}

TEST(ButterflyFilter, UnsignedCharOvershootIsClampedNotWrapped)
{
  // Values 0 and 255 side by side: the butterfly's negative weights push the refined
  // values below 0 and above 255. Stored as unsigned char they must clamp; the same data
  // as doubles shows where.
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(10);
  sphere->SetPhiResolution(8);
  sphere->Update();
  vtkNew<vtkPolyData> mesh;
  mesh->DeepCopy(sphere->GetOutput());
  vtkNew<vtkUnsignedCharArray> bytes;
  bytes->SetName("Bytes");
  vtkNew<vtkDoubleArray> reals;
  reals->SetName("Reals");
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    const unsigned char value = ((static_cast<unsigned>(i) * 2654435761u) >> 13) & 1u ? 255 : 0;
    bytes->InsertNextValue(value);
    reals->InsertNextValue(value);
  }
  mesh->GetPointData()->AddArray(bytes);
  mesh->GetPointData()->AddArray(reals);
  vtkNew<vtkSubDButterflyFilter> butterfly;
  butterfly->SetInputData(mesh);
  butterfly->SetNumberOfSubdivisions(2);
  butterfly->Update();
  auto* outBytes = vtkUnsignedCharArray::SafeDownCast(butterfly->GetOutput()->GetPointData()->GetArray("Bytes"));
  vtkDataArray* outReals = butterfly->GetOutput()->GetPointData()->GetArray("Reals");
  ASSERT_NE(outBytes, nullptr);
  int below = 0, above = 0;
  for (vtkIdType i = 0; i < outBytes->GetNumberOfTuples(); ++i)
  {
    const double exact = outReals->GetTuple1(i);
    below += exact < -0.5;
    above += exact > 255.5;
    const double expected = exact < 0 ? 0 : (exact > 255 ? 255 : std::round(exact));
    EXPECT_EQ(outBytes->GetValue(i), expected) << "point " << i << " exact " << exact;
  }
  EXPECT_GT(below, 0); // the test did exercise clamping at both ends
  EXPECT_GT(above, 0);
}
