// vtkSubDLoopFilter specifics: triangle counts, polygons triangulated with a warning.
#include "vtkSubDLoopFilter.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkCubeSource.h"
#include "vtkCleanPolyData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"

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
