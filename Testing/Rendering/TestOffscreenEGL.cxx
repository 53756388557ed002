// The EGL backend (this program does not link libOSMesa, so BACKEND_AUTO takes EGL) renders
// the same pixels as the OSMesa backend: it is compared with a baseline that the OSMesa
// image test also checks.
#include "SubDBuiltinCages.h"
#include "SubDImageTestSupport.h"

#include "vtkPolyData.h"
#include "vtkSubDCatmullClarkFilter.h"
#include "vtkSubDOffscreenRenderWindow.h"
#include "vtkSubDScene.h"

#include <gtest/gtest.h>

TEST(OffscreenEGL, SameImageAsOSMesa)
{
  ASSERT_EQ(std::getenv("DISPLAY"), nullptr);
  EXPECT_FALSE(vtkSubDOffscreenRenderWindow::ProcessUsesOSMesa());
  vtkSmartPointer<vtkPolyData> cage = subdapp::MakeBuiltinCage("creased-cube");
  vtkNew<vtkSubDCatmullClarkFilter> filter;
  filter->SetInputData(cage);
  filter->SetNumberOfSubdivisions(3);
  filter->Update();
  vtkNew<vtkSubDScene> scene;
  scene->SetViewSize(240, 240);
  scene->AddView(filter->GetOutput(), cage, "catmull-clark L3");
  ASSERT_TRUE(scene->Render());
  EXPECT_STREQ(vtkSubDOffscreenRenderWindow::SafeDownCast(scene->GetRenderWindow())->GetBackendInUse(), "egl");
  if (!std::getenv("SUBD_REGENERATE_BASELINES")) // the OSMesa test owns this baseline
    subdtest::CompareWithBaseline(scene->GetRenderWindow(), "catmull-clark_creased-cube_L3");
}

TEST(OffscreenEGL, OSMesaRequestedWithoutOSMesaIsAClearError)
{
  vtkNew<vtkSubDOffscreenRenderWindow> window;
  window->SetBackendToOSMesa();
  window->GlobalWarningDisplayOff();
  vtkObject::GlobalWarningDisplayOff();
  EXPECT_FALSE(window->CreateContext());
  vtkObject::GlobalWarningDisplayOn();
  EXPECT_STREQ(window->GetBackendInUse(), "none");
}

TEST(OffscreenEGL, SizeIsFixedAfterTheFirstRender)
{
  vtkNew<vtkSubDOffscreenRenderWindow> window;
  window->SetSize(64, 48);
  ASSERT_TRUE(window->CreateContext());
  vtkObject::GlobalWarningDisplayOff();
  window->SetSize(100, 100);
  vtkObject::GlobalWarningDisplayOn();
  EXPECT_EQ(window->GetSize()[0], 64);
  EXPECT_EQ(window->GetSize()[1], 48);
}
