// Regression images of every scheme on four cages (a cube, a creased cube, an open grid, an
// icosahedron) at levels 1 and 3, with mean-curvature colouring, the cage overlaid and the
// creases highlighted; plus Gaussian and plain colouring and the comparison grid. Rendered
// offscreen with OSMesa (this program links libOSMesa first), DISPLAY unset.
#include "SubDBuiltinCages.h"
#include "SubDImageTestSupport.h"

#include "vtkCellArray.h"
#include "vtkPlatonicSolidSource.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"
#include "vtkSubDButterflyFilter.h"
#include "vtkSubDCatmullClarkFilter.h"
#include "vtkSubDDooSabinFilter.h"
#include "vtkSubDLinearFilter.h"
#include "vtkSubDLoopFilter.h"
#include "vtkSubDMidpointFilter.h"
#include "vtkSubDOffscreenRenderWindow.h"
#include "vtkSubDScene.h"
#include "vtkSubDSqrt3Filter.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <tuple>

namespace
{
struct SchemeCase
{
  const char* Name;
  std::function<vtkSmartPointer<vtkSubDSurfaceFilter>()> Make;
};

template <typename Filter>
SchemeCase Case(const char* name)
{
  return { name, [] { return vtkSmartPointer<vtkSubDSurfaceFilter>(vtkSmartPointer<Filter>::New()); } };
}

const std::vector<SchemeCase>& AllSchemes()
{
  static const std::vector<SchemeCase> schemes = { Case<vtkSubDCatmullClarkFilter>("catmull-clark"),
    Case<vtkSubDLoopFilter>("loop"), Case<vtkSubDButterflyFilter>("butterfly"),
    Case<vtkSubDDooSabinFilter>("doo-sabin"), Case<vtkSubDMidpointFilter>("midpoint"),
    Case<vtkSubDSqrt3Filter>("sqrt3"), Case<vtkSubDLinearFilter>("linear") };
  return schemes;
}

vtkSmartPointer<vtkPolyData> Cage(const std::string& name)
{
  if (name != "icosahedron")
  {
    return subdapp::MakeBuiltinCage(name);
  }
  vtkNew<vtkPlatonicSolidSource> solid;
  solid->SetSolidTypeToIcosahedron();
  solid->Update();
  // VTK's icosahedron faces inward: reverse each triangle so normals point out.
  vtkNew<vtkCellArray> outward;
  vtkIdType n;
  const vtkIdType* ids;
  vtkCellArray* inward = solid->GetOutput()->GetPolys();
  for (inward->InitTraversal(); inward->GetNextCell(n, ids);)
  {
    const vtkIdType reversed[3] = { ids[0], ids[2], ids[1] };
    outward->InsertNextCell(3, reversed);
  }
  auto cage = vtkSmartPointer<vtkPolyData>::New();
  cage->SetPoints(solid->GetOutput()->GetPoints());
  cage->SetPolys(outward);
  return cage;
}

vtkSmartPointer<vtkPolyData> Subdivide(const SchemeCase& scheme, vtkPolyData* cage, int levels)
{
  vtkSmartPointer<vtkSubDSurfaceFilter> filter = scheme.Make();
  filter->SetInputData(cage);
  filter->SetNumberOfSubdivisions(levels);
  filter->GlobalWarningDisplayOff(); // quads into triangle schemes are triangulated, with a warning
  filter->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(filter->GetOutput());
  return out;
}

using ImageCase = std::tuple<int, std::string, int>; // scheme index, cage, level

class SchemeImage : public ::testing::TestWithParam<ImageCase>
{
};

TEST_P(SchemeImage, MatchesBaseline)
{
  ASSERT_EQ(std::getenv("DISPLAY"), nullptr);
  const SchemeCase& scheme = AllSchemes()[std::get<0>(GetParam())];
  const std::string cageName = std::get<1>(GetParam());
  const int level = std::get<2>(GetParam());
  vtkSmartPointer<vtkPolyData> cage = Cage(cageName);
  vtkSmartPointer<vtkPolyData> surface = Subdivide(scheme, cage, level);
  ASSERT_GT(surface->GetNumberOfPolys(), 0);
  vtkNew<vtkSubDScene> scene;
  scene->SetViewSize(240, 240);
  scene->AddView(surface, cage, (std::string(scheme.Name) + " L" + std::to_string(level)).c_str());
  ASSERT_TRUE(scene->Render());
  EXPECT_STREQ(vtkSubDOffscreenRenderWindow::SafeDownCast(scene->GetRenderWindow())->GetBackendInUse(), "osmesa");
  subdtest::CompareWithBaseline(scene->GetRenderWindow(), std::string(scheme.Name) + "_" + cageName + "_L" + std::to_string(level));
}

std::string CaseName(const ::testing::TestParamInfo<ImageCase>& info)
{
  std::string name = std::string(AllSchemes()[std::get<0>(info.param)].Name) + "_" + std::get<1>(info.param) + "_L" +
    std::to_string(std::get<2>(info.param));
  for (char& c : name)
    c = (c == '-') ? '_' : c;
  return name;
}

INSTANTIATE_TEST_SUITE_P(AllSchemes, SchemeImage,
  ::testing::Combine(::testing::Range(0, 7), ::testing::Values("cube", "creased-cube", "open-grid", "icosahedron"),
    ::testing::Values(1, 3)),
  CaseName);

// Gaussian and plain colouring of one surface.
TEST(SceneImage, GaussianAndPlainColouring)
{
  vtkSmartPointer<vtkPolyData> cage = Cage("creased-cube");
  vtkSmartPointer<vtkPolyData> surface = Subdivide(AllSchemes()[0], cage, 3);
  for (int coloring : { vtkSubDScene::COLOR_GAUSSIAN_CURVATURE, vtkSubDScene::COLOR_NONE })
  {
    vtkNew<vtkSubDScene> scene;
    scene->SetViewSize(240, 240);
    scene->SetColoring(coloring);
    scene->AddView(surface, cage, scene->GetColoringAsString());
    ASSERT_TRUE(scene->Render());
    subdtest::CompareWithBaseline(scene->GetRenderWindow(),
      coloring == vtkSubDScene::COLOR_NONE ? "scene_plain" : "scene_gaussian");
  }
}

// Every scheme side by side on the creased cube: one camera, one colour scale.
TEST(SceneImage, ComparisonGrid)
{
  vtkSmartPointer<vtkPolyData> cage = Cage("creased-cube");
  vtkNew<vtkSubDScene> scene;
  scene->SetViewSize(200, 200);
  for (const SchemeCase& scheme : AllSchemes())
    scene->AddView(Subdivide(scheme, cage, 2), cage, scheme.Name);
  ASSERT_TRUE(scene->Render());
  int* size = scene->GetRenderWindow()->GetSize();
  EXPECT_EQ(size[0], 600); // 7 views: 3 x 3 grid
  EXPECT_EQ(size[1], 600);
  subdtest::CompareWithBaseline(scene->GetRenderWindow(), "scene_compare_all");
}

// A scene with no view is an error, not a crash.
TEST(SceneImage, EmptySceneIsAnError)
{
  vtkNew<vtkSubDScene> scene;
  scene->GlobalWarningDisplayOff();
  vtkObject::GlobalWarningDisplayOff();
  EXPECT_FALSE(scene->Render());
  vtkObject::GlobalWarningDisplayOn();
}
}
