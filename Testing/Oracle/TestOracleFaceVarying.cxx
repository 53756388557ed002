// Oracle test: SubD's face-varying channels (SubDFaceVarying.h) against OpenSubdiv's
// Far::PrimvarRefinerReal<double>::InterpolateFaceVarying and LimitFaceVarying.
//
// Seamed fixtures (a UV sphere with triangle poles, a torus with two crossing seams, a cube as
// six islands and as two, an open grid in two islands with semi-sharp and sharp creases and a
// corner, a house of pentagons, quads and triangles, a grid with a hole, a non-manifold mesh)
// are refined three levels by Catmull-Clark, Loop (the fixtures triangulated, their corners'
// values with them) and bilinear, in every interpolation mode, under two boundary rules. Child
// faces are matched through OpenSubdiv's parent-to-child relations (GetFaceChildFaces), the
// corners of each by rotation; every corner's value must agree to 1e-9 of the values' extent,
// and at the last level its limit value to 1e-7 (OpenSubdiv's seam limit weights are floats).
#include "SubDFaceVarying.h"
#include "SubDLimitRules.h"
#include "SubDOpenSubdivOracle.h"
#include "SubDFilterTestSupport.h"
#include "SubDOracleSupport.h"
#include "SubDRefiner.h"
#include "SubDTestMeshes.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticPointLocator.h"
#include "vtkSubDButterflyFilter.h"
#include "vtkSubDCatmullClarkFilter.h"
#include "vtkSubDLinearFilter.h"
#include "vtkSubDLoopFilter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <numeric>
#include <map>
#include <string>
#include <vector>

namespace
{
using namespace OpenSubdiv;
using namespace subdtest;
using subd::FaceVaryingInterpolation;

struct Point2
{
  double P[2];
  void Clear() { P[0] = P[1] = 0.0; }
  void AddWithWeight(const Point2& src, double w)
  {
    P[0] += w * src.P[0];
    P[1] += w * src.P[1];
  }
};

struct SeamedMesh
{
  TestMesh Mesh;
  FaceVaryingChannel UV;
  SharpTags Tags;
};

// Values per (vertex, island): faces of different islands meet at seams. A value is an
// affine function of its point, shifted per island.
SeamedMesh ByIslands(const TestMesh& mesh, const std::vector<int>& islandOfFace, const std::string& name)
{
  SeamedMesh s;
  s.Mesh = mesh;
  s.Mesh.Name = name;
  std::map<std::pair<Index, int>, Index> valueOf;
  for (Index f = 0; f < mesh.NumFaces(); ++f)
    for (Index h = mesh.Offsets[f]; h < mesh.Offsets[f + 1]; ++h)
    {
      const Index v = mesh.Vertices[h];
      const auto inserted = valueOf.emplace(std::make_pair(v, islandOfFace[f]), static_cast<Index>(valueOf.size()));
      if (inserted.second)
      {
        const double* p = &mesh.Points[3 * v];
        const double shift = 5.0 * islandOfFace[f];
        s.UV.Values.insert(s.UV.Values.end(), { p[0] + 0.3 * p[1] + 0.7 * p[2] + shift, 0.2 * p[0] - p[1] + 0.4 * p[2] });
      }
      s.UV.ValueOfCorner.push_back(inserted.first->second);
    }
  return s;
}

// A grid of values (i / nu, j / nv), i in 0..nu, j in 0..nv, for a mesh whose vertices wrap.
Index GridValue(int i, int j, int nu)
{
  return static_cast<Index>(j * (nu + 1) + i);
}

std::vector<double> GridValues(int nu, int nv)
{
  std::vector<double> values;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i)
      values.insert(values.end(), { double(i) / nu, double(j) / nv });
  return values;
}

// A torus of nu x nv quads whose values are cut along i = 0 and j = 0 (the seams cross).
SeamedMesh SeamedTorus(int nu, int nv)
{
  SeamedMesh s;
  s.Mesh = Grid(nu, nv, true, true).Jitter(0.05);
  s.Mesh.Name = "torus-seams";
  s.UV.Values = GridValues(nu, nv);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i)
      s.UV.ValueOfCorner.insert(s.UV.ValueOfCorner.end(),
        { GridValue(i, j, nu), GridValue(i + 1, j, nu), GridValue(i + 1, j + 1, nu), GridValue(i, j + 1, nu) });
  return s;
}

// A UV sphere: rings of quads, triangle fans at the poles, cut along a meridian; every pole
// triangle has its own value at the pole (a vertex where nu regions meet).
SeamedMesh UVSphere(int nu, int nv)
{
  SeamedMesh s;
  TestMesh& m = s.Mesh;
  m.Name = "uv-sphere";
  const double pi = 3.14159265358979323846;
  m.AddPoint(0, 0, 1);
  for (int j = 1; j < nv; ++j)
    for (int i = 0; i < nu; ++i)
      m.AddPoint(std::sin(pi * j / nv) * std::cos(2 * pi * i / nu), std::sin(pi * j / nv) * std::sin(2 * pi * i / nu),
        std::cos(pi * j / nv));
  m.AddPoint(0, 0, -1);
  m.Jitter(0.05);
  const Index south = m.NumVertices() - 1;
  auto ring = [nu](int j, int i) { return static_cast<Index>(1 + (j - 1) * nu + i % nu); };
  s.UV.Values = GridValues(nu, nv);
  const Index numGrid = static_cast<Index>(s.UV.Values.size() / 2);
  for (int i = 0; i < nu; ++i) // pole values: one per triangle
  {
    s.UV.Values.insert(s.UV.Values.end(), { (i + 0.5) / nu, 0.0 });
    s.UV.Values.insert(s.UV.Values.end(), { (i + 0.5) / nu, 1.0 });
  }
  for (int i = 0; i < nu; ++i)
  {
    m.AddFace({ ring(1, i + 1), ring(1, i), 0 });
    s.UV.ValueOfCorner.insert(s.UV.ValueOfCorner.end(), { GridValue(i + 1, 1, nu), GridValue(i, 1, nu), numGrid + 2 * i });
  }
  for (int j = 1; j + 1 < nv; ++j)
    for (int i = 0; i < nu; ++i)
    {
      m.AddFace({ ring(j, i), ring(j, i + 1), ring(j + 1, i + 1), ring(j + 1, i) });
      s.UV.ValueOfCorner.insert(s.UV.ValueOfCorner.end(),
        { GridValue(i, j, nu), GridValue(i + 1, j, nu), GridValue(i + 1, j + 1, nu), GridValue(i, j + 1, nu) });
    }
  for (int i = 0; i < nu; ++i)
  {
    m.AddFace({ ring(nv - 1, i), ring(nv - 1, i + 1), south });
    s.UV.ValueOfCorner.insert(s.UV.ValueOfCorner.end(),
      { GridValue(i, nv - 1, nu), GridValue(i + 1, nv - 1, nu), numGrid + 2 * i + 1 });
  }
  return s;
}

// A 4 x 4 grid, one value per vertex but for a cut from the boundary into the middle along
// x = 2, y in [0, 2]: the seam ends inside the mesh (a dart of the channel) at vertex (2, 2).
SeamedMesh CutGrid()
{
  const TestMesh grid = Grid(4, 4, false, false).Jitter(0.1);
  std::vector<int> islandOfFace(16, 0);
  SeamedMesh s = ByIslands(grid, islandOfFace, "grid-cut");
  const Index cutEnd = 2 * 5 + 2;
  for (Index f = 0; f < grid.NumFaces(); ++f)
  {
    const int i = f % 4, j = f / 4;
    if (i < 2 || j >= 2)
      continue;
    for (Index h = grid.Offsets[f]; h < grid.Offsets[f + 1]; ++h)
    {
      const Index v = grid.Vertices[h];
      if (v % 5 == 2 && v != cutEnd) // on the cut: the right side's own value
      {
        s.UV.ValueOfCorner[h] = static_cast<Index>(s.UV.Values.size() / 2) + v;
      }
    }
  }
  for (Index v = 0; v < grid.NumVertices(); ++v) // room for the right side's values
    s.UV.Values.insert(s.UV.Values.end(), { grid.Points[3 * v] + 0.25, grid.Points[3 * v + 1] });
  return s;
}

std::vector<SeamedMesh> SeamedMeshes()
{
  std::vector<SeamedMesh> meshes{ UVSphere(8, 5), SeamedTorus(6, 4) };
  meshes.push_back(ByIslands(Cube().Jitter(0.1), { 0, 1, 2, 3, 4, 5 }, "cube-6-islands"));
  meshes.push_back(ByIslands(Cube().Jitter(0.1), { 0, 1, 0, 0, 1, 1 }, "cube-2-islands"));
  // An open 4 x 3 grid cut along x = 2; a semi-sharp edge inside the left island ending at the
  // seam, an infinitely sharp one inside the right island, a semi-sharp corner.
  std::vector<int> halves;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i)
      halves.push_back(i >= 2 ? 1 : 0);
  SeamedMesh grid = ByIslands(Grid(4, 3, false, false).Jitter(0.1), halves, "grid-2-islands");
  grid.Tags.Label = "-creased";
  grid.Tags.CreasePairs = { 6, 7, 8, 3 };
  grid.Tags.CreaseSharpness = { 1.5f, 10.0f };
  grid.Tags.Corners = { 0 };
  grid.Tags.CornerSharpness = { 2.0f };
  meshes.push_back(grid);
  SeamedMesh chaikin = grid;
  chaikin.Tags.Method = subd::CreaseMethod::Chaikin;
  chaikin.Tags.Label = "-chaikin";
  meshes.push_back(chaikin);
  meshes.push_back(CutGrid());
  std::vector<int> oneFace(16, 0);
  oneFace[5] = 1; // an island of one face inside another: concave corners around it
  meshes.push_back(ByIslands(Grid(4, 4, false, false).Jitter(0.1), oneFace, "grid-one-face-island"));
  meshes.push_back(ByIslands(House(false).Jitter(0.1), { 1, 0, 0, 0, 0, 0, 0, 0 }, "house-gable-island"));
  std::vector<int> holeHalves;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      holeHalves.push_back(j >= 2 ? 1 : 0);
  SeamedMesh holed = ByIslands(Grid(4, 4, false, false).Jitter(0.1), holeHalves, "grid-hole");
  holed.Tags.Holes = { 5 };
  meshes.push_back(holed);
  meshes.push_back(ByIslands(NonManifold().Jitter(0.05), { 0, 0, 1, 0, 0 }, "non-manifold-islands"));
  return meshes;
}

// The fixture with its faces split into fans, each corner keeping its value.
SeamedMesh Triangulated(const SeamedMesh& s)
{
  SeamedMesh t = s;
  t.Mesh = s.Mesh.Triangulated();
  t.UV.ValueOfCorner.clear();
  for (Index f = 0; f < s.Mesh.NumFaces(); ++f)
  {
    const Index first = s.Mesh.Offsets[f];
    for (Index k = first + 1; k + 1 < s.Mesh.Offsets[f + 1]; ++k)
      t.UV.ValueOfCorner.insert(t.UV.ValueOfCorner.end(),
        { s.UV.ValueOfCorner[first], s.UV.ValueOfCorner[k], s.UV.ValueOfCorner[k + 1] });
  }
  if (!t.Tags.Holes.empty())
    t.Tags.Holes = { 2 * t.Tags.Holes[0] }; // the first triangle of the hole quad
  return t;
}

// The turn of my face's corners `corners` (values `mine`, two each) against OpenSubdiv's
// (`values` into `theirs`) under which the values agree best.
Index TurnOfValues(const Far::ConstIndexArray& values, const subd::IndexSpan& corners, const std::vector<double>& mine,
  const std::vector<Point2>& theirs)
{
  Index best = 0;
  double bestError = 1e300;
  for (Index r = 0; r < values.size(); ++r)
  {
    double error = 0.0;
    for (Index j = 0; j < values.size(); ++j)
      for (int d = 0; d < 2; ++d)
        error = std::max(error, std::abs(mine[2 * corners[(j + r) % corners.size()] + d] - theirs[values[j]].P[d]));
    if (error < bestError)
    {
      bestError = error;
      best = r;
    }
  }
  return best;
}

struct FaceVaryingCase
{
  SeamedMesh Fixture;
  SchemeKind Kind;
  subd::BoundaryRule Rule;
  FaceVaryingInterpolation Mode;
};

void PrintTo(const FaceVaryingCase& c, std::ostream* os)
{
  *os << MakeScheme(c.Kind)->GetName() << " " << c.Fixture.Mesh.Name << c.Fixture.Tags.Label << " "
      << subd::ToString(c.Rule) << " " << subd::ToString(c.Mode);
}

std::string CaseName(const ::testing::TestParamInfo<FaceVaryingCase>& info)
{
  std::string name = ::testing::PrintToString(info.param);
  std::replace_if(name.begin(), name.end(), [](char ch) { return !std::isalnum(static_cast<unsigned char>(ch)); }, '_');
  return name;
}

class FaceVaryingOracle : public ::testing::TestWithParam<FaceVaryingCase>
{
};

TEST_P(FaceVaryingOracle, MatchesOpenSubdiv)
{
  const FaceVaryingCase& c = GetParam();
  SeamedMesh fixture = c.Fixture;
  fixture.UV.Mode = c.Mode;
  const TestMesh& mesh = fixture.Mesh;
  const bool loop = c.Kind == SchemeKind::Loop;
  const int levels = 3;
  const auto refiner = MakeOsdRefiner(mesh, c.Rule, levels, c.Kind, fixture.Tags, &fixture.UV);
  Far::PrimvarRefinerReal<double> primvar(*refiner);

  const std::unique_ptr<subd::Scheme> scheme = MakeScheme(c.Kind);
  subd::MeshTopology topology = subd::MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices);
  const subd::BaseTags tags = ToBaseTags(fixture.Tags, topology);
  const subd::Level base = subd::MakeBaseLevel(std::move(topology), tags, scheme->EffectiveBoundaryRule(c.Rule));
  subd::FaceVaryingBase channel = subd::MakeFaceVaryingBase(base, fixture.UV.ValueOfCorner.data(), c.Mode);
  subd::Level level = std::move(channel.Values);
  std::vector<double> mine;
  for (Index u : channel.UserValue)
    mine.insert(mine.end(), { fixture.UV.Values[2 * u], fixture.UV.Values[2 * u + 1] });
  std::vector<Point2> osd(fixture.UV.Values.size() / 2);
  for (size_t i = 0; i < osd.size(); ++i)
    osd[i] = Point2{ { fixture.UV.Values[2 * i], fixture.UV.Values[2 * i + 1] } };
  double lo[2] = { 1e300, 1e300 }, hi[2] = { -1e300, -1e300 };
  for (size_t i = 0; i < fixture.UV.Values.size(); ++i)
  {
    lo[i % 2] = std::min(lo[i % 2], fixture.UV.Values[i]);
    hi[i % 2] = std::max(hi[i % 2], fixture.UV.Values[i]);
  }
  const double tolerance = 1e-9 * std::hypot(hi[0] - lo[0], hi[1] - lo[1]);

  // OpenSubdiv's face f is my face faceMap[f], its corner j my corner j + turn[f].
  std::vector<Index> faceMap(static_cast<size_t>(mesh.NumFaces())), turn(faceMap.size(), 0);
  std::iota(faceMap.begin(), faceMap.end(), 0);
  // Compares every corner of OpenSubdiv's faces at level l (values `theirs`) with mine.
  auto compareCorners = [&](int l, const std::vector<Point2>& theirs, const std::vector<double>& ours,
                          const std::string& what, double tolerance) {
    const Far::TopologyLevel& osdLevel = refiner->GetLevel(l);
    for (Index f = 0; f < osdLevel.GetNumFaces(); ++f)
    {
      const Far::ConstIndexArray values = osdLevel.GetFaceFVarValues(f, 0);
      const subd::IndexSpan corners = level.Topology.GetFaceVertices(faceMap[f]);
      ASSERT_EQ(values.size(), corners.size()) << what << " face " << f;
      for (Index j = 0; j < values.size(); ++j)
      {
        const Index u = corners[(j + turn[f]) % corners.size()];
        for (int d = 0; d < 2; ++d)
          ASSERT_NEAR(ours[2 * u + d], theirs[values[j]].P[d], tolerance)
            << what << " level " << l << " face " << f << " corner " << j << " component " << d;
      }
    }
  };
  for (int l = 1; l <= levels; ++l)
  {
    const Far::TopologyLevel& parentOsd = refiner->GetLevel(l - 1);
    const Far::TopologyLevel& childOsd = refiner->GetLevel(l);
    std::vector<Point2> osdChild(static_cast<size_t>(childOsd.GetNumFVarValues(0)));
    Point2* src = osd.data();
    Point2* dst = osdChild.data();
    primvar.InterpolateFaceVarying(l, src, dst, 0);
    osd.swap(osdChild);
    const subd::StencilTable rows = scheme->BuildStencils(level);
    std::vector<double> child(static_cast<size_t>(rows.GetNumRows()) * 2);
    rows.Apply(mine.data(), child.data(), 2);
    mine.swap(child);
    const subd::MeshTopology parent = level.Topology;
    level = scheme->Split(level, subd::ChildTopology::Full);
    std::vector<Index> childFaceMap(static_cast<size_t>(childOsd.GetNumFaces()));
    for (Index f = 0; f < parentOsd.GetNumFaces(); ++f)
    {
      const Index g = faceMap[f], n = parent.GetFaceSize(g);
      const Far::ConstIndexArray children = parentOsd.GetFaceChildFaces(f);
      for (Index k = 0; k < children.size(); ++k)
        childFaceMap[children[k]] = MyChildFace(parent, g, turn[f], k, loop);
    }
    faceMap = childFaceMap;
    turn.assign(faceMap.size(), 0);
    for (Index f = 0; f < childOsd.GetNumFaces(); ++f)
      turn[f] = TurnOfValues(childOsd.GetFaceFVarValues(f, 0), level.Topology.GetFaceVertices(faceMap[f]), mine, osd);
    compareCorners(l, osd, mine, "values", tolerance);
  }
  if (c.Kind == SchemeKind::Bilinear)
    return; // OpenSubdiv's bilinear face-varying limit applies a crease mask the refinement does not
  std::vector<Point2> osdLimit(osd.size());
  Point2* limitSrc = osd.data();
  Point2* limitDst = osdLimit.data();
  primvar.LimitFaceVarying(limitSrc, limitDst, 0);
  subd::StencilTable limit;
  std::string error;
  ASSERT_TRUE(scheme->BuildLimitStencils(level, limit, error)) << error;
  std::vector<double> mineLimit(static_cast<size_t>(limit.GetNumRows()) * 2);
  limit.Apply(mine.data(), mineLimit.data(), 2);
  // OpenSubdiv's limit of a value on a seam weighs it and its neighbours by 2/3 and 1/6
  // rounded to float (far/primvarRefiner.h, limitFVar): 3e-8 off, relative.
  compareCorners(levels, osdLimit, mineLimit, "limit", 100 * tolerance);
}

std::vector<FaceVaryingCase> Cases()
{
  std::vector<FaceVaryingCase> cases;
  for (const SeamedMesh& fixture : SeamedMeshes())
    for (const FaceVaryingInterpolation mode :
      { FaceVaryingInterpolation::None, FaceVaryingInterpolation::CornersOnly, FaceVaryingInterpolation::CornersPlus1,
        FaceVaryingInterpolation::CornersPlus2, FaceVaryingInterpolation::Boundaries, FaceVaryingInterpolation::All })
      for (const subd::BoundaryRule rule :
        { subd::BoundaryRule::None, subd::BoundaryRule::EdgeOnly, subd::BoundaryRule::EdgeAndCorner })
      {
        cases.push_back({ fixture, SchemeKind::CatmullClark, rule, mode });
        cases.push_back({ Triangulated(fixture), SchemeKind::Loop, rule, mode });
        cases.push_back({ fixture, SchemeKind::Bilinear, rule, mode });
      }
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Seamed, FaceVaryingOracle, ::testing::ValuesIn(Cases()), CaseName);

// The fixture as VTK's readers deliver a textured mesh: a point per value, at its vertex's
// position, with the value as texture coordinates; faces name those points.
vtkSmartPointer<vtkPolyData> SplitAtSeams(const SeamedMesh& s)
{
  const Index numValues = static_cast<Index>(s.UV.Values.size() / 2);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(numValues);
  vtkNew<vtkDoubleArray> uv;
  uv->SetName("UV");
  uv->SetNumberOfComponents(2);
  uv->SetNumberOfTuples(numValues);
  for (Index value = 0; value < numValues; ++value) // values no corner uses: points of their own
  {
    points->SetPoint(value, 1e6, value, 0.0);
    uv->SetTuple(value, &s.UV.Values[2 * value]);
  }
  vtkNew<vtkCellArray> polys;
  for (Index f = 0; f < s.Mesh.NumFaces(); ++f)
  {
    polys->InsertNextCell(s.Mesh.Offsets[f + 1] - s.Mesh.Offsets[f]);
    for (Index h = s.Mesh.Offsets[f]; h < s.Mesh.Offsets[f + 1]; ++h)
    {
      const Index value = s.UV.ValueOfCorner[h];
      points->SetPoint(value, &s.Mesh.Points[3 * s.Mesh.Vertices[h]]);
      polys->InsertCellPoint(value);
    }
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  mesh->GetPointData()->SetTCoords(uv);
  return mesh;
}

// A mesh split at its seams (as vtkOBJReader gives it) is welded by the surface filters and
// subdivided whole: every corner of OpenSubdiv's refined faces (its position from the vertex
// data, its texture coordinates from the face-varying channel) is a point of the output, the
// output has as many points as OpenSubdiv's channel has values and as many faces, for
// Catmull-Clark, Loop and linear (bilinear) and three interpolation modes, refined and
// projected to the limit (OpenSubdiv's Limit and LimitFaceVarying). (The fixtures' creases and
// holes stay out: the split input does not carry them.)
TEST(FaceVaryingFilters, SplitInputIsWeldedAndRefinedAsOpenSubdivDoes)
{
  const int levels = 2;
  for (const SeamedMesh& fixture : SeamedMeshes())
    for (const SchemeKind kind : { SchemeKind::CatmullClark, SchemeKind::Loop, SchemeKind::Bilinear })
      for (const FaceVaryingInterpolation mode :
        { FaceVaryingInterpolation::None, FaceVaryingInterpolation::CornersPlus1, FaceVaryingInterpolation::Boundaries })
        for (const bool limit : { false, true })
      {
        if (limit && kind == SchemeKind::Bilinear)
          continue; // (OpenSubdiv's bilinear face-varying limit: see MatchesOpenSubdiv)
        SeamedMesh seamed = kind == SchemeKind::Loop ? Triangulated(fixture) : fixture;
        seamed.UV.Mode = mode;
        seamed.Tags = SharpTags(); // (the split input carries no creases or holes)
        const std::string what = std::string(MakeScheme(kind)->GetName()) + " " + seamed.Mesh.Name + " " +
          subd::ToString(mode) + (limit ? " limit" : "");
        vtkSmartPointer<vtkSubDSurfaceFilter> filter;
        if (kind == SchemeKind::CatmullClark)
          filter = vtkSmartPointer<vtkSubDCatmullClarkFilter>::New();
        else if (kind == SchemeKind::Loop)
          filter = vtkSmartPointer<vtkSubDLoopFilter>::New();
        else
          filter = vtkSmartPointer<vtkSubDLinearFilter>::New();
        vtkSmartPointer<vtkPolyData> input = SplitAtSeams(seamed);
        filter->SetInputData(input);
        filter->SetNumberOfSubdivisions(levels);
        filter->SetFaceVaryingInterpolation(static_cast<int>(mode));
        filter->SetBoundaryRuleToEdgeOnly();
        filter->SetProjectToLimit(limit);
        filter->Update();
        vtkPolyData* out = filter->GetOutput();
        vtkDataArray* outUV = out->GetPointData()->GetTCoords();
        ASSERT_NE(outUV, nullptr) << what;

        const auto refiner = MakeOsdRefiner(seamed.Mesh, subd::BoundaryRule::EdgeOnly, levels, kind, seamed.Tags, &seamed.UV);
        Far::PrimvarRefinerReal<double> primvar(*refiner);
        std::vector<Point3> xyz(static_cast<size_t>(refiner->GetNumVerticesTotal()));
        std::vector<Point2> uv(static_cast<size_t>(seamed.UV.Values.size() / 2));
        for (Index v = 0; v < seamed.Mesh.NumVertices(); ++v)
          std::copy(&seamed.Mesh.Points[3 * v], &seamed.Mesh.Points[3 * v] + 3, xyz[v].P);
        for (size_t i = 0; i < uv.size(); ++i)
          uv[i] = Point2{ { seamed.UV.Values[2 * i], seamed.UV.Values[2 * i + 1] } };
        Point3* src = xyz.data();
        for (int l = 1; l <= levels; ++l)
        {
          Point3* dst = src + refiner->GetLevel(l - 1).GetNumVertices();
          primvar.Interpolate(l, src, dst);
          src = dst;
          std::vector<Point2> child(static_cast<size_t>(refiner->GetLevel(l).GetNumFVarValues(0)));
          Point2* from = uv.data();
          Point2* to = child.data();
          primvar.InterpolateFaceVarying(l, from, to, 0);
          uv.swap(child);
        }
        if (limit)
        {
          std::vector<Point3> xyzLimit(static_cast<size_t>(refiner->GetLevel(levels).GetNumVertices()));
          std::vector<Point2> uvLimit(uv.size());
          Point3* limitDst = xyzLimit.data();
          primvar.Limit(src, limitDst);
          Point2* from = uv.data();
          Point2* to = uvLimit.data();
          primvar.LimitFaceVarying(from, to, 0);
          std::copy(xyzLimit.begin(), xyzLimit.end(), src);
          uv.swap(uvLimit);
        }
        const Far::TopologyLevel& finest = refiner->GetLevel(levels);
        ASSERT_EQ(out->GetNumberOfPolys(), finest.GetNumFaces()) << what;
        // (At a non-manifold vertex OpenSubdiv may count one value twice, at one position.)
        if (seamed.Mesh.Name.find("non-manifold") == std::string::npos)
          EXPECT_EQ(out->GetNumberOfPoints(), finest.GetNumFVarValues(0)) << what;
        double extent = 0.0;
        for (double value : seamed.UV.Values)
          extent = std::max(extent, std::abs(value));
        vtkNew<vtkStaticPointLocator> locator;
        locator->SetDataSet(out);
        locator->BuildLocator();
        const double tolerance = 1e-9 * subdtest::Diagonal(seamed.Mesh.Points);
        vtkNew<vtkIdList> near;
        for (Index f = 0; f < finest.GetNumFaces(); ++f)
        {
          const Far::ConstIndexArray corners = finest.GetFaceVertices(f), values = finest.GetFaceFVarValues(f, 0);
          for (Index j = 0; j < corners.size(); ++j)
          {
            locator->FindPointsWithinRadius(tolerance, src[corners[j]].P, near);
            bool found = false;
            for (vtkIdType k = 0; k < near->GetNumberOfIds() && !found; ++k)
            {
              const double* t = outUV->GetTuple2(near->GetId(k));
              // (OpenSubdiv's seam limit weights are floats: 1e-7)
              const double close = (limit ? 1e-7 : 1e-9) * extent;
              found = std::abs(t[0] - uv[values[j]].P[0]) < close && std::abs(t[1] - uv[values[j]].P[1]) < close;
            }
            std::string seen;
            for (vtkIdType k = 0; k < near->GetNumberOfIds(); ++k)
              seen += " (" + std::to_string(outUV->GetTuple2(near->GetId(k))[0]) + ", " +
                std::to_string(outUV->GetTuple2(near->GetId(k))[1]) + ")";
            ASSERT_TRUE(found) << what << ": face " << f << " corner " << j << ": OpenSubdiv's (" << uv[values[j]].P[0]
                               << ", " << uv[values[j]].P[1] << "), the output's there:" << seen;
          }
        }
      }
}

// The points of `mesh`, sorted, to compare surfaces whatever their numbering.
std::vector<std::array<double, 3>> SortedPoints(vtkPolyData* mesh)
{
  std::vector<std::array<double, 3>> points(static_cast<size_t>(mesh->GetNumberOfPoints()));
  for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
    mesh->GetPoint(p, points[p].data());
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  return points;
}

vtkSmartPointer<vtkPolyData> Butterfly(vtkPolyData* input, int levels)
{
  vtkNew<vtkSubDButterflyFilter> filter;
  filter->SetInputData(input);
  filter->SetNumberOfSubdivisions(levels);
  filter->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(filter->GetOutput());
  return out;
}

// Butterfly (no OpenSubdiv counterpart) refines each UV island with its own rules, the seams
// as the island's boundaries, and the surface whole: split at seams, the fixtures give the
// positions of the welded mesh without texture coordinates; on a flat regular grid of two
// islands whose coordinates are a linear map of the position (shifted per island), every
// output point keeps its island's map, since the butterfly's inner and 4-point rules both
// reproduce linear data there.
TEST(FaceVaryingFilters, ButterflyRefinesIslandsAndLeavesPositionsAlone)
{
  const int levels = 2;
  for (const SeamedMesh& fixture : SeamedMeshes())
  {
    if (fixture.Mesh.Name.find("non-manifold") != std::string::npos)
      continue; // (a non-manifold seam vertex is pinned in the channel only)
    const SeamedMesh seamed = Triangulated(fixture);
    vtkSmartPointer<vtkPolyData> split = Butterfly(SplitAtSeams(seamed), levels);
    vtkSmartPointer<vtkPolyData> whole = Butterfly(subdtest::ToPolyData(seamed.Mesh), levels);
    ASSERT_NE(split->GetPointData()->GetTCoords(), nullptr) << seamed.Mesh.Name;
    EXPECT_EQ(split->GetNumberOfPolys(), whole->GetNumberOfPolys()) << seamed.Mesh.Name;
    const auto a = SortedPoints(split), b = SortedPoints(whole);
    ASSERT_EQ(a.size(), b.size()) << seamed.Mesh.Name;
    for (size_t i = 0; i < a.size(); ++i)
      for (int d = 0; d < 3; ++d)
        EXPECT_NEAR(a[i][d], b[i][d], 1e-12) << seamed.Mesh.Name;
  }

  std::vector<int> halves;
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 8; ++i)
      halves.push_back(i >= 4 ? 1 : 0);
  const SeamedMesh flat = Triangulated(ByIslands(Grid(8, 6, false, false), halves, "flat-grid-2-islands"));
  vtkSmartPointer<vtkPolyData> out = Butterfly(SplitAtSeams(flat), 3);
  vtkDataArray* uv = out->GetPointData()->GetTCoords();
  ASSERT_NE(uv, nullptr);
  int checked = 0, onSeam = 0;
  for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
  {
    const double* x = out->GetPoint(p);
    // (Two cage edges from the island's corners, where the 4-point rule meets a turn of the
    // boundary and no rule reproduces linear data.)
    if (x[0] < 2 || x[0] > 6 || x[1] < 2 || x[1] > 4)
      continue;
    double error = 1e300;
    for (int island = 0; island < 2; ++island) // ByIslands' map
      error = std::min(error, std::abs(uv->GetComponent(p, 0) - (x[0] + 0.3 * x[1] + 0.7 * x[2] + 5.0 * island)) +
          std::abs(uv->GetComponent(p, 1) - (0.2 * x[0] - x[1] + 0.4 * x[2])));
    EXPECT_LT(error, 1e-12) << "point " << p;
    ++checked;
    onSeam += x[0] == 4.0;
  }
  EXPECT_GT(checked, 500);
  EXPECT_GT(onSeam, 30); // each side of the seam, split
}
}
