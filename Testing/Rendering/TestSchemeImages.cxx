// Regression images of every scheme on four cages (a cube, a creased cube, an open grid, an
// icosahedron) at levels 1 and 3, with mean-curvature colouring, the cage overlaid and the
// creases highlighted; plus Gaussian and plain colouring, the comparison grid, and the size of
// the faces behind one of the pictures (Doo-Sabin's creased cube). Rendered offscreen with
// OSMesa (this program links libOSMesa first), DISPLAY unset.
#include "SubDBuiltinCages.h"
#include "SubDImageTestSupport.h"
#include "SubDMeshIO.h"
#include "SubDTexturedCube.h"

#include "vtkCellArray.h"
#include "vtkMath.h"
#include "vtkPlatonicSolidSource.h"
#include "vtkPointData.h"
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

#include <algorithm>
#include <cmath>
#include <fstream>
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

// The largest distance between two corners of a polygon of `mesh`, over its polygons.
double LargestFaceDiameter(vtkPolyData* mesh)
{
  double largest = 0.0;
  vtkIdType n;
  const vtkIdType* ids;
  vtkCellArray* polys = mesh->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
    for (vtkIdType i = 0; i < n; ++i)
      for (vtkIdType j = i + 1; j < n; ++j)
      {
        double p[3], q[3];
        mesh->GetPoint(ids[i], p);
        mesh->GetPoint(ids[j], q);
        largest = std::max(largest, std::sqrt(vtkMath::Distance2BetweenPoints(p, q)));
      }
  return largest;
}

// What doo-sabin_creased-cube_L3.png shows: the crease loop around the top face is cut at its
// corners like the rest of the crease, so none of them stays an output point, and no face is
// left as large as a cage face (the top face and the two side faces at the sharp corner were,
// the loop's corners pinned: the cage face's diagonal across). The largest faces left run
// from the sharp corner (every corner point there is the corner itself) up to the crease,
// whose Chaikin points barely move: they shrink only once the loop's sharpness is used up.
TEST(SceneImage, DooSabinCreasedCubeKeepsNoCageFace)
{
  vtkSmartPointer<vtkPolyData> cage = Cage("creased-cube");
  double p[3], q[3]; // the cage's edge length: every edge of the cube is as long
  vtkIdType n;
  const vtkIdType* ids;
  cage->GetPolys()->GetCellAtId(0, n, ids);
  cage->GetPoint(ids[0], p);
  cage->GetPoint(ids[1], q);
  const double edge = std::sqrt(vtkMath::Distance2BetweenPoints(p, q));
  vtkSmartPointer<vtkPolyData> surface = Subdivide(AllSchemes()[3], cage, 3);
  EXPECT_LE(LargestFaceDiameter(surface), 0.85 * std::sqrt(2.0) * edge);
  for (vtkIdType loopCorner : { 4, 5, 6, 7 })
  {
    cage->GetPoint(loopCorner, p);
    for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
    {
      surface->GetPoint(i, q);
      EXPECT_GT(vtkMath::Distance2BetweenPoints(p, q), 1e-18) << "loop corner " << loopCorner << " is point " << i;
    }
  }
}

// A cube with a cross unwrap, split at its seams as VTK's readers deliver textured meshes,
// checkered: subdivided as it is (no welding), it falls apart along the seams; welded, it is
// the smooth cube with its texture seams intact. The welded surface is the one of the cube
// without texture coordinates.
TEST(SceneImage, CheckerTexturedSeamedCubeBeforeAndAfterWelding)
{
  const std::string path = std::string(SUBD_IMAGE_TEMP_DIR) + "/cross-unwrapped-cube.obj";
  std::ofstream(path) << subdtest::CrossUnwrappedCubeOBJ();
  std::string error;
  vtkSmartPointer<vtkPolyData> cage = subdapp::ReadMesh(path, error);
  ASSERT_TRUE(cage) << error;
  ASSERT_NE(cage->GetPointData()->GetTCoords(), nullptr);
  vtkNew<vtkSubDScene> scene;
  scene->SetViewSize(300, 300);
  scene->ShowTextureOn();
  scene->ShowCageOff();
  scene->SetViewAzimuth(-60.0);
  vtkSmartPointer<vtkPolyData> welded;
  for (const bool weld : { false, true })
  {
    vtkNew<vtkSubDCatmullClarkFilter> filter;
    filter->SetInputData(cage);
    filter->SetNumberOfSubdivisions(3);
    filter->SetWeldCoincidentPoints(weld);
    filter->Update();
    auto surface = vtkSmartPointer<vtkPolyData>::New();
    surface->ShallowCopy(filter->GetOutput());
    ASSERT_NE(surface->GetPointData()->GetTCoords(), nullptr);
    scene->AddView(surface, cage, weld ? "welded" : "split at seams");
    welded = surface;
  }
  ASSERT_TRUE(scene->Render());
  subdtest::CompareWithBaseline(scene->GetRenderWindow(), "scene_texture_seams");

  // (Cage("cube") is the same unit cube, its faces in another order: round-off apart.)
  vtkSmartPointer<vtkPolyData> plain = Subdivide(AllSchemes()[0], Cage("cube"), 3);
  for (vtkIdType i = 0; i < welded->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3], nearest = 1e300;
    welded->GetPoint(i, p);
    for (vtkIdType j = 0; j < plain->GetNumberOfPoints(); ++j)
    {
      plain->GetPoint(j, q);
      nearest = std::min(nearest, vtkMath::Distance2BetweenPoints(p, q));
    }
    EXPECT_LT(nearest, 1e-24) << "point " << i;
  }
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
