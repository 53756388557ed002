// Oracle test: SubD's Catmull-Clark and Loop against OpenSubdiv's Far::TopologyRefiner and
// PrimvarRefinerReal<double> (Debian's libosd-dev), an independent implementation.
//
// Both refine the same fixtures for each boundary rule, levels 1..3, and a corpus of sharp
// features (creases, semi-sharp with fractional sharpness, darts, corners, holes, Chaikin
// and Uniform crease methods, poles of valence 8 and 64), levels 1..4. Child points are
// matched through the parent they come from (OpenSubdiv orders child points from faces
// first, then edges, then vertices; faces are matched by their vertex sets, edges by their
// end points), never by assuming equal numbering. Positions must agree to 1e-9 of the
// bounding-box diagonal; faces and holes must agree exactly.
#include "SubDLimitRules.h"
#include "SubDOpenSubdivOracle.h"
#include "SubDFilterTestSupport.h"
#include "SubDOracleSupport.h"
#include "SubDRefiner.h"
#include "SubDQuadSplit.h"
#include "SubDScheme.h"
#include "SubDTestMeshes.h"
#include "SubDTestParallel.h"
#include "SubDTriangleSplit.h"

#include "SubDLimitEvaluator.h"

#include <opensubdiv/far/patchMap.h>
#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/ptexIndices.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include "SubDBuiltinCages.h"
#include "SubDCageEditing.h"
#include "SubDMessageCollector.h"
#include "SubDSchemeRegistry.h"

#include "vtkCellArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkStaticPointLocator.h"
#include "vtkSubDCatmullClarkFilter.h"
#include "vtkSubDLimitFilter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <map>
#include <memory>
#include <numeric>

namespace
{
using namespace OpenSubdiv;
using namespace subdtest;
using subd::Index;

std::vector<Index> SortedCorners(const Index* begin, Index n, const std::vector<Index>& map)
{
  std::vector<Index> key(static_cast<size_t>(n));
  for (Index k = 0; k < n; ++k)
  {
    key[k] = map[begin[k]];
  }
  std::sort(key.begin(), key.end());
  return key;
}

struct OracleCase
{
  subdtest::TestMesh Mesh;
  subd::BoundaryRule Rule;
  SchemeKind Kind;
  SharpTags Tags = {};
  int Levels = 3;
};

std::vector<OracleCase> Cases()
{
  std::vector<OracleCase> cases;
  const auto rules = { subd::BoundaryRule::None, subd::BoundaryRule::EdgeOnly,
    subd::BoundaryRule::EdgeAndCorner };
  for (const subdtest::TestMesh& mesh : subdtest::StandardMeshes())
    for (auto rule : rules)
      cases.push_back({ mesh, rule, SchemeKind::CatmullClark });
  for (const subdtest::TestMesh& mesh : subdtest::TriangleMeshes())
    for (auto rule : rules)
      cases.push_back({ mesh, rule, SchemeKind::Loop });
  for (const subdtest::TestMesh& mesh : subdtest::StandardMeshes())
    for (auto rule : rules)
      cases.push_back({ mesh, rule, SchemeKind::Bilinear });
  return cases;
}

void PrintTo(const OracleCase& c, std::ostream* os)
{
  *os << MakeScheme(c.Kind)->GetName() << " " << c.Mesh.Name << c.Tags.Label << " "
      << subd::ToString(c.Rule);
}

/// 1e-9, or 1e-6 with Chaikin creasing: there a half edge's sharpness is a mean of its
/// neighbours' rounded to float, and OpenSubdiv sums them in float in its own order of a
/// vertex's edges, SubD in double (so that the result does not depend on the order, which
/// differs between a mesh and the pieces of it that limit evaluation refines). The two
/// means can differ in the last bit of a float (1e-7), the points by about 1e-8 of the
/// diagonal and second derivatives, which amplify sharp changes, by 1e-7.
double ChaikinTolerance(const OracleCase& c)
{
  return c.Tags.Method == subd::CreaseMethod::Chaikin ? 1e-6 : 1e-9;
}

class SchemeOracle : public ::testing::TestWithParam<OracleCase>
{
};

TEST_P(SchemeOracle, MatchesOpenSubdiv)
{
  const OracleCase& c = GetParam();
  const int maxLevel = c.Levels;
  auto refiner = MakeOsdRefiner(c.Mesh, c.Rule, maxLevel, c.Kind, c.Tags);
  ASSERT_TRUE(refiner);
  Far::PrimvarRefinerReal<double> primvar(*refiner);

  const std::unique_ptr<subd::Scheme> schemePointer = MakeScheme(c.Kind);
  const subd::Scheme& scheme = *schemePointer;
  subd::MeshTopology baseTopology =
    subd::MeshTopology::Build(c.Mesh.NumVertices(), c.Mesh.Offsets, c.Mesh.Vertices);
  const subd::BaseTags baseTags = ToBaseTags(c.Tags, baseTopology);
  subd::Level level =
    subd::MakeBaseLevel(std::move(baseTopology), baseTags, scheme.EffectiveBoundaryRule(c.Rule));
  std::vector<double> mine = c.Mesh.Points;
  std::vector<Point3> osd(static_cast<size_t>(c.Mesh.NumVertices()));
  for (Index v = 0; v < c.Mesh.NumVertices(); ++v)
  {
    std::copy(&c.Mesh.Points[3 * v], &c.Mesh.Points[3 * v] + 3, osd[v].P);
  }
  const double tolerance = ChaikinTolerance(c) * subdtest::Diagonal(c.Mesh.Points);

  // osdToMine[i]: my index of OpenSubdiv's vertex i at the current level.
  std::vector<Index> osdToMine(static_cast<size_t>(c.Mesh.NumVertices()));
  std::iota(osdToMine.begin(), osdToMine.end(), 0);

  for (int l = 1; l <= maxLevel; ++l)
  {
    const Far::TopologyLevel& parentOsd = refiner->GetLevel(l - 1);
    const subd::MeshTopology& parentMine = level.Topology;
    ASSERT_EQ(parentOsd.GetNumFaces(), parentMine.GetNumFaces());
    ASSERT_EQ(parentOsd.GetNumEdges(), parentMine.GetNumEdges());
    ASSERT_EQ(parentOsd.GetNumVertices(), parentMine.GetNumVertices());

    // Match parent faces by vertex set, parent edges by end points.
    std::map<std::vector<Index>, Index> myFaceByCorners;
    for (Index f = 0; f < parentMine.GetNumFaces(); ++f)
    {
      std::vector<Index> key(parentMine.GetFaceVertices(f).begin(), parentMine.GetFaceVertices(f).end());
      std::sort(key.begin(), key.end());
      myFaceByCorners[key] = f;
    }
    const Index numFacesOsd = parentOsd.GetNumFaces(), numEdgesOsd = parentOsd.GetNumEdges();
    std::vector<Index> childMap(static_cast<size_t>(refiner->GetLevel(l).GetNumVertices()));
    // Child point numbering: OpenSubdiv (faces first) puts face points, edge points, then
    // vertex points; Loop has no face points.
    const bool loop = c.Kind == SchemeKind::Loop;
    const subd::QuadSplitNumbering quadNumber{ parentMine.GetNumFaces(), parentMine.GetNumEdges() };
    const subd::TriangleSplitNumbering triNumber{ parentMine.GetNumEdges() };
    auto myEdgePoint = [&](Index e) { return loop ? triNumber.EdgePoint(e) : quadNumber.EdgePoint(e); };
    auto myVertexPoint = [&](Index v) { return loop ? triNumber.VertexPoint(v) : quadNumber.VertexPoint(v); };
    const Index osdFacePoints = loop ? 0 : numFacesOsd;
    for (Index f = 0; f < numFacesOsd; ++f)
    {
      Far::ConstIndexArray fv = parentOsd.GetFaceVertices(f);
      auto it = myFaceByCorners.find(SortedCorners(&fv[0], fv.size(), osdToMine));
      ASSERT_NE(it, myFaceByCorners.end()) << "level " << l - 1 << " face " << f << " unmatched";
      if (!loop)
        childMap[f] = quadNumber.FacePoint(it->second);
      EXPECT_EQ(parentOsd.IsFaceHole(f), level.FaceIsHole[it->second] != 0) << "face " << f;
    }
    for (Index e = 0; e < numEdgesOsd; ++e)
    {
      Far::ConstIndexArray ev = parentOsd.GetEdgeVertices(e);
      const Index mineEdge = parentMine.FindEdge(osdToMine[ev[0]], osdToMine[ev[1]]);
      ASSERT_NE(mineEdge, subd::InvalidIndex) << "level " << l - 1 << " edge " << e << " unmatched";
      childMap[osdFacePoints + e] = myEdgePoint(mineEdge);
    }
    for (Index v = 0; v < parentOsd.GetNumVertices(); ++v)
    {
      childMap[osdFacePoints + numEdgesOsd + v] = myVertexPoint(osdToMine[v]);
    }

    // Refine both.
    std::vector<Point3> osdChild(childMap.size());
    Point3* osdSrc = osd.data();
    Point3* osdDst = osdChild.data();
    primvar.Interpolate(l, osdSrc, osdDst);
    subd::StencilTable stencils = scheme.BuildStencils(level);
    std::vector<double> mineChild = subdtest::ApplyToPoints(stencils, mine);
    level = scheme.Split(level, subd::ChildTopology::Full);

    double worst = 0.0;
    Index worstVertex = -1;
    for (size_t i = 0; i < childMap.size(); ++i)
    {
      const double* a = osdChild[i].P;
      const double* b = &mineChild[3 * static_cast<size_t>(childMap[i])];
      const double d = std::max({ std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2]) });
      if (d > worst)
      {
        worst = d;
        worstVertex = static_cast<Index>(i);
      }
    }
    std::printf("%s %s%s %s level %d: largest difference %.3g of the bounding-box diagonal\n",
      scheme.GetName(), c.Mesh.Name.c_str(), c.Tags.Label.c_str(), subd::ToString(c.Rule), l, worst / (tolerance * 1e9));
    EXPECT_LE(worst, tolerance) << c.Mesh.Name << " " << subd::ToString(c.Rule) << " level " << l
                                << ": worst OpenSubdiv vertex " << worstVertex;

    // Child faces: same corner sets (in the same cyclic order) and the same holes.
    const Far::TopologyLevel& childOsd = refiner->GetLevel(l);
    ASSERT_EQ(childOsd.GetNumFaces(), level.Topology.GetNumFaces());
    std::map<std::vector<Index>, Index> childFaces;
    for (Index f = 0; f < level.Topology.GetNumFaces(); ++f)
    {
      std::vector<Index> key(level.Topology.GetFaceVertices(f).begin(), level.Topology.GetFaceVertices(f).end());
      std::sort(key.begin(), key.end());
      childFaces[key] = f;
    }
    for (Index f = 0; f < childOsd.GetNumFaces(); ++f)
    {
      Far::ConstIndexArray fv = childOsd.GetFaceVertices(f);
      auto it = childFaces.find(SortedCorners(&fv[0], fv.size(), childMap));
      ASSERT_NE(it, childFaces.end()) << "level " << l << " face " << f << " unmatched";
      const subd::IndexSpan corners = level.Topology.GetFaceVertices(it->second);
      const Index start = static_cast<Index>(std::find(corners.begin(), corners.end(), childMap[fv[0]]) - corners.begin());
      for (int k = 0; k < fv.size(); ++k)
      {
        EXPECT_EQ(corners[(start + k) % corners.size()], childMap[fv[k]]) << "orientation of face " << f;
      }
      EXPECT_EQ(childOsd.IsFaceHole(f), level.FaceIsHole[it->second] != 0) << "hole " << f;
    }

    osd.swap(osdChild);
    mine.swap(mineChild);
    osdToMine = childMap;
  }

  // Limit positions of the finest vertices (Far::PrimvarRefiner::Limit).
  if (c.Kind == SchemeKind::Bilinear)
    return;
  std::vector<Point3> osdLimit(osd.size());
  Point3* limitSrc = osd.data();
  Point3* limitDst = osdLimit.data();
  primvar.Limit(limitSrc, limitDst);
  subd::StencilTable limit;
  if (c.Kind == SchemeKind::Loop)
    limit = subd::BuildLoopLimitStencils(level);
  else
  {
    std::string error;
    ASSERT_TRUE(subd::BuildCatmullClarkLimitStencils(level, limit, error)) << error;
  }
  const std::vector<double> mineLimit = subdtest::ApplyToPoints(limit, mine);
  double worst = 0.0;
  for (size_t i = 0; i < osdLimit.size(); ++i)
  {
    const double* a = osdLimit[i].P;
    const double* b = &mineLimit[3 * static_cast<size_t>(osdToMine[i])];
    worst = std::max({ worst, std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2]) });
  }
  std::printf("%s %s%s %s limit: largest difference %.3g of the bounding-box diagonal\n", scheme.GetName(),
    c.Mesh.Name.c_str(), c.Tags.Label.c_str(), subd::ToString(c.Rule), worst / (tolerance * 1e9));
  EXPECT_LE(worst, tolerance) << "limit positions";
}

std::string CaseName(const ::testing::TestParamInfo<OracleCase>& info)
{
  std::string name = std::string(MakeScheme(info.param.Kind)->GetName()) + "_" +
    info.param.Mesh.Name + info.param.Tags.Label + "_" + subd::ToString(info.param.Rule);
  std::replace_if(name.begin(), name.end(), [](char ch) { return !std::isalnum(static_cast<unsigned char>(ch)); }, '_');
  return name;
}

INSTANTIATE_TEST_SUITE_P(Fixtures, SchemeOracle, ::testing::ValuesIn(Cases()), CaseName);

// The sharp-feature corpus. Each entry is refined by Catmull-Clark on the quad mesh and by
// Loop on its triangulation (which keeps every quad edge, so the same creases apply).
struct SharpFixture
{
  subdtest::TestMesh Mesh;
  SharpTags Tags;
  int LoopHole = -1; // a hole face of the triangulation, if the fixture has holes
};

SharpTags Creases(std::string label, std::vector<int> pairs, std::vector<float> sharpness,
  subd::CreaseMethod method = subd::CreaseMethod::Uniform)
{
  SharpTags t;
  t.Label = "-" + label;
  t.CreasePairs = std::move(pairs);
  t.CreaseSharpness = std::move(sharpness);
  t.Method = method;
  return t;
}

std::vector<SharpFixture> SharpCorpus()
{
  std::vector<SharpFixture> corpus;
  const subdtest::TestMesh cube = subdtest::Cube().Jitter(0.1);
  // One closed crease loop: the four edges around one face (vertices 0..3 of the cube's
  // first face).
  {
    std::vector<int> pairs;
    const subd::IndexSpan fv{ &cube.Vertices[cube.Offsets[0]], cube.Offsets[1] - cube.Offsets[0] };
    for (Index k = 0; k < fv.size(); ++k)
      pairs.insert(pairs.end(), { fv[k], fv[(k + 1) % fv.size()] });
    corpus.push_back({ cube, Creases("loop2.5", pairs, std::vector<float>(pairs.size() / 2, 2.5f)) });
  }
  // Every edge at one sharpness.
  {
    const subd::MeshTopology topo = subd::MeshTopology::Build(cube.NumVertices(), cube.Offsets, cube.Vertices);
    std::vector<int> pairs;
    for (Index e = 0; e < topo.GetNumEdges(); ++e)
      pairs.insert(pairs.end(), { topo.GetEdgeVertices(e)[0], topo.GetEdgeVertices(e)[1] });
    for (float s : { 0.5f, 1.0f, 2.5f, 10.0f })
    {
      std::string label = "all" + std::to_string(s).substr(0, 4);
      corpus.push_back({ cube, Creases(label, pairs, std::vector<float>(pairs.size() / 2, s)) });
    }
  }
  // A torus (6 x 5 quads, all valence 4): vertex (i, j) is i + 6 j.
  const subdtest::TestMesh torus = subdtest::Grid(6, 5, true, true).Jitter(0.05);
  auto tv = [](int i, int j) { return (i % 6) + 6 * (j % 5); };
  corpus.push_back({ torus, Creases("dart", { tv(1, 1), tv(2, 1) }, { 10.0f }) });
  corpus.push_back({ torus, Creases("end-inside", { tv(1, 2), tv(2, 2), tv(2, 2), tv(3, 2), tv(3, 2), tv(4, 2) },
                              { 3.3f, 3.3f, 3.3f }) });
  for (auto method : { subd::CreaseMethod::Uniform, subd::CreaseMethod::Chaikin })
  {
    // A crease whose sharpness varies along it, and a closed loop around the torus.
    std::vector<int> pairs;
    std::vector<float> sharpness;
    const float along[] = { 0.5f, 1.5f, 2.5f, 3.7f };
    for (int i = 0; i < 4; ++i)
    {
      pairs.insert(pairs.end(), { tv(i, 1), tv(i + 1, 1) });
      sharpness.push_back(along[i]);
    }
    const float loop[] = { 0.3f, 1.2f, 2.7f, 0.8f, 4.1f, 1.9f };
    for (int i = 0; i < 6; ++i)
    {
      pairs.insert(pairs.end(), { tv(i, 3), tv(i + 1, 3) });
      sharpness.push_back(loop[i]);
    }
    // A branch (three semi-sharp edges meet: a semi-sharp corner).
    pairs.insert(pairs.end(), { tv(2, 3), tv(2, 4) });
    sharpness.push_back(1.4f);
    corpus.push_back({ torus, Creases(std::string("varying-") + subd::ToString(method), pairs, sharpness, method) });
  }
  // Corner sharpness on boundary and interior vertices of an open grid (vertex (i, j) is
  // i + 5 j on the 4 x 3 grid), with a semi-sharp crease ending at a boundary.
  {
    SharpTags t = Creases("corners", { 6, 7, 7, 8 }, { 1.6f, 0.4f });
    t.Corners = { 1, 2, 4, 7, 15 };
    t.CornerSharpness = { 0.5f, 3.0f, 10.0f, 1.7f, 0.25f };
    corpus.push_back({ subdtest::Grid(4, 3, false, false).Jitter(0.1), t });
  }
  // Holes: in the torus and at the boundary of the open grid.
  {
    SharpTags t = Creases("hole", { tv(1, 1), tv(2, 1) }, { 2.0f });
    t.Holes = { 7, 8 };
    corpus.push_back({ torus, t, 14 });
    SharpTags g;
    g.Label = "-hole";
    g.Holes = { 0 };
    corpus.push_back({ subdtest::Grid(4, 3, false, false).Jitter(0.1), g, 0 });
  }
  // A semi-sharp crease touching a non-manifold edge (vertices 0 and 1 are its ends).
  corpus.push_back({ subdtest::NonManifold().Jitter(0.05), Creases("crease", { 0, 2, 2, 3 }, { 1.5f, 0.7f }) });
  // Poles of valence 8 and 64 (the apex 2n of the star): a semi-sharp crease through the
  // pole, a semi-sharp pole, and (with Chaikin) semi-sharp edges all around it.
  for (int n : { 8, 64 })
  {
    const subdtest::TestMesh star = subdtest::Star(n).Jitter(0.1);
    SharpTags t = Creases("pole", { 1, 2 * n, 2 * n, n + 1 }, { 1.5f, 2.25f });
    t.Corners = { 2 * n };
    t.CornerSharpness = { 0.7f };
    corpus.push_back({ star, t });
    std::vector<int> pairs;
    std::vector<float> sharpness;
    for (int k = 0; k < n; ++k)
    {
      pairs.insert(pairs.end(), { 2 * k + 1, 2 * n });
      sharpness.push_back(0.2f + 2.5f * k / n);
    }
    corpus.push_back({ star, Creases("spokes", pairs, sharpness, subd::CreaseMethod::Chaikin) });
  }
  return corpus;
}

std::vector<OracleCase> SharpCases()
{
  std::vector<OracleCase> cases;
  for (const SharpFixture& fixture : SharpCorpus())
  {
    for (auto rule : { subd::BoundaryRule::EdgeOnly, subd::BoundaryRule::EdgeAndCorner })
    {
      cases.push_back({ fixture.Mesh, rule, SchemeKind::CatmullClark, fixture.Tags, 4 });
      OracleCase loop{ fixture.Mesh.Triangulated(), rule, SchemeKind::Loop, fixture.Tags, 4 };
      if (!loop.Tags.Holes.empty())
        loop.Tags.Holes = { fixture.LoopHole };
      cases.push_back(loop);
    }
  }
  return cases;
}

INSTANTIATE_TEST_SUITE_P(SharpFeatures, SchemeOracle, ::testing::ValuesIn(SharpCases()), CaseName);

// OpenSubdiv's limit surface of a fixture: its adaptive patches (Far::PatchTable, isolation
// level 10, infinitely sharp patches, Gregory end caps, double precision) over the refined
// and local points.
class OsdLimitPatches
{
public:
  explicit OsdLimitPatches(const OracleCase& c)
    : Quads(c.Kind == SchemeKind::CatmullClark)
  {
    std::unique_ptr<Far::TopologyRefiner> refiner = CreateOsdRefiner(c.Mesh, c.Rule, c.Kind, c.Tags);
    Far::PatchTableFactory::Options options(10);
    options.SetEndCapType(Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
    options.useInfSharpPatch = true;
    options.SetPatchPrecision<double>();
    refiner->RefineAdaptive(options.GetRefineAdaptiveOptions());
    this->Table.reset(Far::PatchTableFactory::Create(*refiner, options));
    const int numRefined = refiner->GetNumVerticesTotal();
    this->Values.resize(static_cast<size_t>(numRefined + this->Table->GetNumLocalPoints()));
    for (Index v = 0; v < c.Mesh.NumVertices(); ++v)
    {
      std::copy(&c.Mesh.Points[3 * v], &c.Mesh.Points[3 * v] + 3, this->Values[v].P);
    }
    Far::PrimvarRefinerReal<double> primvar(*refiner);
    Point3* src = this->Values.data();
    for (int l = 1; l <= refiner->GetMaxLevel(); ++l)
    {
      Point3* dst = src + refiner->GetLevel(l - 1).GetNumVertices();
      primvar.Interpolate(l, src, dst);
      src = dst;
    }
    // The local points (Gregory end caps) from the double-precision stencils the options
    // asked for (PatchTable::ComputeLocalPointValues reads the float table only).
    if (const Far::StencilTableReal<double>* local = this->Table->GetLocalPointStencilTable<double>())
    {
      local->UpdateValues(this->Values.data(), this->Values.data() + numRefined);
    }
    this->Map.reset(new Far::PatchMap(*this->Table));
    this->Ptex.reset(new Far::PtexIndices(*refiner));
  }

  /// The value and derivatives (PatchDerivative order) at (u, v) of face f, a quad
  /// (Catmull-Clark) or triangle (Loop) of the fixture; false where no patch holds it.
  bool Evaluate(Index f, double u, double v, double out[6][3]) const
  {
    const Far::PatchTable::PatchHandle* handle = this->Map->FindPatch(this->Ptex->GetFaceId(f), u, v);
    if (!handle)
    {
      return false;
    }
    double w[6][20];
    this->Table->EvaluateBasis(*handle, u, v, w[0], w[1], w[2], w[3], w[4], w[5]);
    const Far::ConstIndexArray cvs = this->Table->GetPatchVertices(*handle);
    // OpenSubdiv 3.5 negates all derivatives of a sub-triangle that is rotated by 180 degrees
    // in its parent's parameters; that is right for the first derivatives and wrong for the
    // second (two sign changes cancel). Undo it for the second.
    const bool rotated = !this->Quads && this->Table->GetPatchParam(*handle).IsTriangleRotated();
    for (int d = 0; d < 6; ++d)
    {
      const double sign = rotated && d >= 3 ? -1.0 : 1.0;
      for (int x = 0; x < 3; ++x)
      {
        out[d][x] = 0.0;
        for (int k = 0; k < cvs.size(); ++k)
        {
          out[d][x] += sign * w[d][k] * this->Values[cvs[k]].P[x];
        }
      }
    }
    return true;
  }

private:
  bool Quads;
  std::unique_ptr<Far::PatchTable> Table;
  std::vector<Point3> Values;
  std::unique_ptr<Far::PatchMap> Map;
  std::unique_ptr<Far::PtexIndices> Ptex;
};

// Exact limit evaluation (SubDLimitEvaluator) against OpenSubdiv's adaptive patches
// (Far::PatchTable, isolation level 10, infinitely sharp patches, double precision): on
// regular, boundary and crease patches and their feature-adaptive refinements OpenSubdiv
// is exact too, so positions and first and second derivatives must agree. Samples keep
// away from face corners, where OpenSubdiv's end caps (Gregory patches, 2^-10 across)
// only approximate extraordinary vertices. Catmull-Clark polygons other than quads are
// skipped (OpenSubdiv's sub-face parameters are its own), and so are the non-manifold
// fixtures: OpenSubdiv isolates non-manifold edges to the last level and closes them with
// end caps, so it is only accurate to about 1e-10 there (SubD's level-independence tests
// cover them).
class LimitOracle : public ::testing::TestWithParam<OracleCase>
{
};

TEST_P(LimitOracle, MatchesOpenSubdivPatches)
{
  const OracleCase& c = GetParam();
  const bool quads = c.Kind == SchemeKind::CatmullClark;
  const OsdLimitPatches osdPatches(c);
  const std::unique_ptr<subd::Scheme> scheme = MakeScheme(c.Kind);
  subd::MeshTopology topology = subd::MeshTopology::Build(c.Mesh.NumVertices(), c.Mesh.Offsets, c.Mesh.Vertices);
  const subd::BaseTags tags = ToBaseTags(c.Tags, topology);
  const subd::Level level = subd::MakeBaseLevel(std::move(topology), tags, scheme->EffectiveBoundaryRule(c.Rule));
  const subd::LimitEvaluator evaluator(*scheme, level);
  const double size = subdtest::Diagonal(c.Mesh.Points);

  const double params[][2] = { { 0.3, 0.2 }, { 0.5, 0.5 }, { 0.1, 0.7 }, { 0.0, 0.4 }, { 0.45, 0.0 },
    { 0.2, 0.05 }, { 0.9, 0.6 } };
  double worst[6] = {};
  int compared = 0;
  for (Index f = 0; f < level.Topology.GetNumFaces(); ++f)
  {
    if (level.FaceIsHole[f] || level.Topology.GetFaceSize(f) != (quads ? 4 : 3))
    {
      continue;
    }
    std::vector<subd::FaceSample> samples;
    for (const auto& p : params)
    {
      if (quads || p[0] + p[1] <= 1.0)
      {
        subd::FaceSample s;
        s.U = p[0];
        s.V = p[1];
        samples.push_back(s);
      }
    }
    std::vector<subd::LimitStencil> mine;
    std::string error;
    ASSERT_TRUE(evaluator.EvaluateFace(f, samples, mine, error)) << error;
    for (size_t i = 0; i < samples.size(); ++i)
    {
      double osdValues[6][3];
      ASSERT_TRUE(osdPatches.Evaluate(f, samples[i].U, samples[i].V, osdValues)) << "face " << f;
      for (int d = 0; d < 6; ++d)
      {
        const double* osd = osdValues[d];
        double ours[3];
        mine[i].Apply(mine[i].Weights, d, c.Mesh.Points.data(), 3, ours);
        const double scale = std::max(size, std::sqrt(osd[0] * osd[0] + osd[1] * osd[1] + osd[2] * osd[2]));
        const double error = std::sqrt((osd[0] - ours[0]) * (osd[0] - ours[0]) + (osd[1] - ours[1]) * (osd[1] - ours[1]) +
          (osd[2] - ours[2]) * (osd[2] - ours[2])) / scale;
        worst[d] = std::max(worst[d], error);
        EXPECT_LT(error, ChaikinTolerance(c)) << "face " << f << " at (" << samples[i].U << ", " << samples[i].V << ") derivative " << d;
      }
      ++compared;
    }
  }
  EXPECT_GT(compared, 0);
  std::printf("limit patches: %-40s %4d samples, relative error P %.1e Du %.1e Dv %.1e Duu %.1e Duv %.1e Dvv %.1e\n",
    ::testing::PrintToString(c).c_str(), compared, worst[0], worst[1], worst[2], worst[3], worst[4], worst[5]);
}

std::vector<OracleCase> LimitCases()
{
  std::vector<OracleCase> cases;
  auto manifold = [](const OracleCase& c) { return c.Mesh.Name.find("non-manifold") == std::string::npos; };
  for (const OracleCase& c : Cases())
  {
    if (c.Kind != SchemeKind::Bilinear && manifold(c))
      cases.push_back(c);
  }
  for (const OracleCase& c : SharpCases())
  {
    if (manifold(c))
      cases.push_back(c);
  }
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Limit, LimitOracle, ::testing::ValuesIn(LimitCases()), CaseName);

// A fixture with its sharp features as the filters read them: crease lines with "Sharpness",
// "CornerSharpness", "Hole".
vtkSmartPointer<vtkPolyData> TaggedPolyData(const subdtest::TestMesh& mesh, const SharpTags& tags)
{
  vtkSmartPointer<vtkPolyData> poly = subdtest::ToPolyData(mesh);
  std::vector<std::array<vtkIdType, 2>> creases;
  for (size_t k = 0; k + 1 < tags.CreasePairs.size(); k += 2)
    creases.push_back({ tags.CreasePairs[k], tags.CreasePairs[k + 1] });
  if (!creases.empty())
    subdtest::AddCreases(poly, creases, tags.CreaseSharpness);
  std::map<vtkIdType, float> corners;
  for (size_t k = 0; k < tags.Corners.size(); ++k)
    corners[tags.Corners[k]] = tags.CornerSharpness[k];
  if (!corners.empty())
    subdtest::AddCornerSharpness(poly, corners);
  if (!tags.Holes.empty())
  {
    vtkNew<vtkIntArray> holes;
    holes->SetName("Hole");
    holes->SetNumberOfTuples(poly->GetNumberOfCells());
    holes->Fill(0);
    for (int f : tags.Holes)
      holes->SetValue(poly->GetNumberOfLines() + f, 1); // lines come before polygons
    poly->GetCellData()->AddArray(holes);
  }
  return poly;
}

// vtkSubDLimitFilter's adaptive tessellation, and its selective one with every face at level 2:
// each point against OpenSubdiv's patches at the (face, u, v) it was evaluated at
// (ComputeLocations), to 1e-12 of the diagonal (Chaikin creasing: 1e-6, as LimitOracle). The
// fixtures of LimitOracle whose faces are all quads (Catmull-Clark) or all triangles (Loop):
// OpenSubdiv's sub-face parameters of other polygons are its own. Points within 2^-10 of a face
// corner are not compared: there OpenSubdiv's end caps only approximate an extraordinary vertex
// (the limit points at vertices have their own oracle test).
class AdaptiveTessellationOracle : public ::testing::TestWithParam<OracleCase>
{
};

TEST_P(AdaptiveTessellationOracle, PointsAreOpenSubdivsLimit)
{
  const OracleCase& c = GetParam();
  const bool quads = c.Kind == SchemeKind::CatmullClark;
  const OsdLimitPatches osdPatches(c);
  vtkSmartPointer<vtkPolyData> cage = TaggedPolyData(c.Mesh, c.Tags);
  vtkNew<vtkIntArray> levels;
  levels->SetName("RefineLevel");
  levels->SetNumberOfTuples(cage->GetNumberOfCells());
  levels->Fill(2);
  cage->GetCellData()->AddArray(levels);
  const double size = subdtest::Diagonal(c.Mesh.Points), nearCorner = std::ldexp(1.0, -10);
  // Positions agree to round-off, but for Chaikin creasing (see ChaikinTolerance).
  const double tolerance = c.Tags.Method == subd::CreaseMethod::Chaikin ? ChaikinTolerance(c) : 1e-12;
  for (int mode : { vtkSubDLimitFilter::ADAPTIVE, vtkSubDLimitFilter::SELECTIVE })
  {
    vtkNew<vtkSubDLimitFilter> limit;
    limit->SetInputData(cage);
    limit->SetScheme(quads ? vtkSubDLimitFilter::CATMULL_CLARK : vtkSubDLimitFilter::LOOP);
    limit->SetBoundaryRule(static_cast<int>(c.Rule));
    limit->SetCreaseMethod(c.Tags.Method == subd::CreaseMethod::Chaikin ? 1 : 0);
    limit->SetTessellation(mode);
    limit->SetTolerance(3e-3);
    limit->ComputeNormalsOff();
    limit->ComputeLocationsOn();
    limit->Update();
    vtkPolyData* out = limit->GetOutput();
    ASSERT_GT(out->GetNumberOfPolys(), 0);
    vtkDataArray* faceIds = out->GetPointData()->GetArray("FaceId");
    vtkDataArray* uv = out->GetPointData()->GetArray("FaceUV");
    ASSERT_TRUE(faceIds && uv);
    double worst = 0.0;
    int compared = 0;
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      const Index f = static_cast<Index>(faceIds->GetComponent(i, 0) - cage->GetNumberOfLines());
      const double u = uv->GetComponent(i, 0), v = uv->GetComponent(i, 1);
      const bool diagonal = !quads && u + v > 1.0 - nearCorner;
      if ((std::min(u, 1.0 - u) < nearCorner || diagonal) && (std::min(v, 1.0 - v) < nearCorner || diagonal))
        continue;
      double osd[6][3], p[3];
      ASSERT_TRUE(osdPatches.Evaluate(f, u, v, osd)) << "face " << f;
      out->GetPoint(i, p);
      const double error = std::sqrt((osd[0][0] - p[0]) * (osd[0][0] - p[0]) + (osd[0][1] - p[1]) * (osd[0][1] - p[1]) +
                             (osd[0][2] - p[2]) * (osd[0][2] - p[2])) / size;
      worst = std::max(worst, error);
      EXPECT_LT(error, tolerance) << "point " << i << " of face " << f << " at (" << u << ", " << v << ")";
      ++compared;
    }
    // Level 2 puts points inside every face; a flat fixture's adaptive tessellation has none.
    EXPECT_TRUE(compared > 0 || mode == vtkSubDLimitFilter::ADAPTIVE);
    std::printf("%s tessellation: %-40s %5d points, relative error %.1e\n",
      mode == vtkSubDLimitFilter::ADAPTIVE ? "adaptive" : "selective", ::testing::PrintToString(c).c_str(), compared,
      worst);
  }
}

std::vector<OracleCase> AdaptiveTessellationCases()
{
  std::vector<OracleCase> cases;
  for (const OracleCase& c : LimitCases())
  {
    const Index size = c.Kind == SchemeKind::CatmullClark ? 4 : 3;
    bool uniform = true;
    for (Index f = 0; f < c.Mesh.NumFaces(); ++f)
      uniform = uniform && c.Mesh.Offsets[f + 1] - c.Mesh.Offsets[f] == size;
    if (uniform)
      cases.push_back(c);
  }
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Adaptive, AdaptiveTessellationOracle, ::testing::ValuesIn(AdaptiveTessellationCases()), CaseName);

// The explorer's crease editing: the functions its sharpness spin box calls
// (SubDCageEditing.h) edit a built-in cage, the scheme registry runs the filter as the
// explorer's update job does, and the refined surface must move from the unedited one to
// exactly what OpenSubdiv computes for the cage with that crease and corner.
TEST(ExplorerCreaseEditing, TheEditedSurfaceIsOpenSubdivs)
{
  vtkSmartPointer<vtkPolyData> cage = subdapp::MakeBuiltinCage("cube");
  subdtest::TestMesh mesh;
  for (vtkIdType i = 0; i < cage->GetNumberOfPoints(); ++i)
  {
    const double* p = cage->GetPoint(i);
    mesh.AddPoint(p[0], p[1], p[2]);
  }
  vtkCellArray* polys = cage->GetPolys();
  vtkNew<vtkIdList> cell;
  for (polys->InitTraversal(); polys->GetNextCell(cell);)
  {
    std::vector<Index> face;
    for (vtkIdType k = 0; k < cell->GetNumberOfIds(); ++k)
      face.push_back(static_cast<Index>(cell->GetId(k)));
    mesh.AddFace(face);
  }
  const Index a = mesh.Vertices[0], b = mesh.Vertices[1], corner = mesh.Vertices[2];
  const int levels = 3;
  subdapp::SchemeOptions options;
  options.Levels = levels;
  const subdapp::SchemeEntry& catmullClark = *subdapp::FindScheme("catmull-clark");
  auto run = [&]() {
    subdapp::MessageCollector messages;
    vtkSmartPointer<vtkPolyData> out = subdapp::RunScheme(catmullClark, options, cage, messages);
    EXPECT_NE(out, nullptr) << messages.Errors;
    std::vector<double> xyz;
    for (vtkIdType i = 0; out && i < out->GetNumberOfPoints(); ++i)
      xyz.insert(xyz.end(), out->GetPoint(i), out->GetPoint(i) + 3);
    return xyz;
  };
  const std::vector<double> before = run();
  std::string error;
  ASSERT_TRUE(subdapp::SetEdgeSharpness(cage, a, b, 2.5, error)) << error;
  ASSERT_TRUE(subdapp::SetVertexSharpness(cage, corner, 3.0, error)) << error;
  EXPECT_EQ(subdapp::GetEdgeSharpness(cage, b, a), 2.5);
  EXPECT_EQ(subdapp::GetVertexSharpness(cage, corner), 3.0);
  const std::vector<double> after = run();

  SharpTags tags;
  tags.CreasePairs = { a, b };
  tags.CreaseSharpness = { 2.5f };
  tags.Corners = { corner };
  tags.CornerSharpness = { 3.0f };
  auto refiner = MakeOsdRefiner(mesh, subd::BoundaryRule::EdgeOnly, levels, SchemeKind::CatmullClark, tags);
  Far::PrimvarRefinerReal<double> primvar(*refiner);
  std::vector<Point3> points(static_cast<size_t>(mesh.NumVertices()));
  for (Index v = 0; v < mesh.NumVertices(); ++v)
    std::copy(&mesh.Points[3 * v], &mesh.Points[3 * v] + 3, points[v].P);
  for (int l = 1; l <= levels; ++l)
  {
    std::vector<Point3> child(static_cast<size_t>(refiner->GetLevel(l).GetNumVertices()));
    Point3* childPoints = child.data();
    primvar.Interpolate(l, points.data(), childPoints);
    points = std::move(child);
  }
  ASSERT_EQ(after.size(), 3 * points.size());
  const double scale = subdtest::Diagonal(mesh.Points);
  double editedToOsd = 0.0, uneditedToOsd = 0.0;
  for (const Point3& p : points)
  {
    double d;
    subdtest::NearestPoint(after, p.P, d);
    editedToOsd = std::max(editedToOsd, d);
    subdtest::NearestPoint(before, p.P, d);
    uneditedToOsd = std::max(uneditedToOsd, d);
  }
  EXPECT_LT(editedToOsd, 1e-9 * scale);
  EXPECT_GT(uneditedToOsd, 1e-2 * scale); // the edit changed the surface
  // Sharpness 0 removes the crease again.
  ASSERT_TRUE(subdapp::SetEdgeSharpness(cage, a, b, 0.0, error)) << error;
  EXPECT_EQ(cage->GetNumberOfLines(), 0);
  EXPECT_FALSE(subdapp::SetEdgeSharpness(cage, a, a, 1.0, error));
  EXPECT_NE(error.find("not an edge"), std::string::npos) << error;
}
}

// Faces that repeat a vertex are read as OpenSubdiv reads them (Vtr::Level): each half-edge
// from a vertex to itself is an edge of its own, a vertex pair met twice in one face is two
// edges, all non-manifold; edges numbered in the order they are met. The base topology's
// edges, their ends, faces and tags, and the vertices' tags equal OpenSubdiv's.
TEST(RepeatedCorners, BaseTopologyIsOpenSubdivs)
{
  std::vector<subdtest::TestMesh> meshes{ subdtest::RepeatedCornerMix() };
  for (int n : { 3, 8, 64, 360 })
    meshes.push_back(subdtest::RepeatedCornerPole(n));
  for (const subdtest::TestMesh& mesh : meshes)
  {
    const std::unique_ptr<Far::TopologyRefiner> refiner =
      CreateOsdRefiner(mesh, subd::BoundaryRule::EdgeOnly, SchemeKind::CatmullClark, {});
    const Far::TopologyLevel& osd = refiner->GetLevel(0);
    for (const subd::ParallelFor& parallelFor : { subd::ParallelFor(subd::SerialFor), subd::ParallelFor(subdtest::ThreeThreadFor) })
    {
      const subd::MeshTopology topo =
        subd::MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices, parallelFor);
      ASSERT_EQ(topo.GetNumEdges(), osd.GetNumEdges()) << mesh.Name;
      for (Index f = 0; f < topo.GetNumFaces(); ++f)
      {
        const Far::ConstIndexArray edges = osd.GetFaceEdges(f);
        ASSERT_EQ(topo.GetFaceSize(f), edges.size()) << mesh.Name;
        for (Index i = 0; i < edges.size(); ++i)
          ASSERT_EQ(topo.GetFaceEdges(f)[i], edges[i]) << mesh.Name << " face " << f << " edge " << i;
      }
      for (Index e = 0; e < topo.GetNumEdges(); ++e)
      {
        const std::string what = mesh.Name + " edge " + std::to_string(e);
        EXPECT_EQ(topo.GetEdgeVertices(e)[0], osd.GetEdgeVertices(e)[0]) << what;
        EXPECT_EQ(topo.GetEdgeVertices(e)[1], osd.GetEdgeVertices(e)[1]) << what;
        const Far::ConstIndexArray faces = osd.GetEdgeFaces(e);
        ASSERT_EQ(topo.GetEdgeFaces(e).size(), faces.size()) << what;
        for (Index k = 0; k < faces.size(); ++k)
          EXPECT_EQ(topo.GetEdgeFaces(e)[k], faces[k]) << what;
        EXPECT_EQ(topo.GetEdgeTag(e).NonManifold != 0, osd.IsEdgeNonManifold(e)) << what;
        EXPECT_EQ(topo.GetEdgeTag(e).Boundary != 0, osd.IsEdgeBoundary(e)) << what;
      }
      Index degenerate = 0;
      for (Index e = 0; e < topo.GetNumEdges(); ++e)
        degenerate += topo.GetEdgeVertices(e)[0] == topo.GetEdgeVertices(e)[1];
      EXPECT_GT(degenerate, 0) << mesh.Name;
      for (Index v = 0; v < topo.GetNumVertices(); ++v)
      {
        EXPECT_EQ(topo.GetVertexTag(v).NonManifold != 0, osd.IsVertexNonManifold(v)) << mesh.Name << " vertex " << v;
        EXPECT_EQ(topo.GetVertexEdges(v).size(), osd.GetVertexEdges(v).size()) << mesh.Name << " vertex " << v;
        EXPECT_EQ(topo.GetVertexFaces(v).size(), osd.GetVertexFaces(v).size()) << mesh.Name << " vertex " << v;
      }
    }
  }
}

// Semi-sharp creases and a corner on the repeated-corner fixtures (RepeatedCornerPole: a side
// edge, a ring edge and a spoke to the pole, a bottom corner; RepeatedCornerMix: two grid
// edges and a corner), edges of their triangulations too.
SharpTags RepeatedCornerCreases(const subdtest::TestMesh& mesh)
{
  SharpTags tags;
  tags.Label = "-creased";
  if (mesh.Name.rfind("pole", 0) == 0)
  {
    const int pole = mesh.NumVertices() - 1;
    tags.CreasePairs = { 0, 1, 1, 3, 3, pole };
    tags.CreaseSharpness = { 2.5f, 1.0f, 1.5f };
    tags.Corners = { 2 };
    tags.CornerSharpness = { 3.0f };
  }
  else
  {
    tags.CreasePairs = { 4, 5, 5, 6 };
    tags.CreaseSharpness = { 2.0f, 1.5f };
    tags.Corners = { 15 };
    tags.CornerSharpness = { 2.0f };
  }
  return tags;
}

// Refined, such faces give OpenSubdiv's faces (each keeps its size: a quad still has four
// children), points and holes, level by level, and its limit positions, for Catmull-Clark,
// Loop (on the meshes triangulated: triangles with a repeated corner) and bilinear, under the
// three boundary rules, with and without creases and a corner. Matched through OpenSubdiv's parent-to-child relations: a face's,
// edge's and vertex's child point, a face's children by corner (the base levels are numbered
// alike; a child face may start at another corner, found from its points).
TEST(RepeatedCorners, RefinementIsOpenSubdivs)
{
  std::vector<subdtest::TestMesh> meshes{ subdtest::RepeatedCornerMix() };
  for (int n : { 3, 8, 64, 360 })
    meshes.push_back(subdtest::RepeatedCornerPole(n));
  for (const SchemeKind kind : { SchemeKind::CatmullClark, SchemeKind::Loop, SchemeKind::Bilinear })
    for (const subd::BoundaryRule rule :
      { subd::BoundaryRule::None, subd::BoundaryRule::EdgeOnly, subd::BoundaryRule::EdgeAndCorner })
      for (const subdtest::TestMesh& input : meshes)
        for (const SharpTags& tags : { SharpTags{}, RepeatedCornerCreases(input) })
      {
        const bool loop = kind == SchemeKind::Loop;
        const subdtest::TestMesh mesh = loop ? input.Triangulated() : input;
        const int levels = 4;
        const std::unique_ptr<subd::Scheme> scheme = MakeScheme(kind);
        const std::string what =
          std::string(scheme->GetName()) + " " + mesh.Name + tags.Label + " " + subd::ToString(rule);
        auto refiner = MakeOsdRefiner(mesh, rule, levels, kind, tags);
        Far::PrimvarRefinerReal<double> primvar(*refiner);
        subd::MeshTopology base = subd::MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices);
        const subd::BaseTags baseTags = ToBaseTags(tags, base);
        subd::Level level = subd::MakeBaseLevel(std::move(base), baseTags, scheme->EffectiveBoundaryRule(rule));
        std::vector<double> mine = mesh.Points;
        std::vector<Point3> osd(static_cast<size_t>(mesh.NumVertices()));
        for (Index v = 0; v < mesh.NumVertices(); ++v)
          std::copy(&mesh.Points[3 * v], &mesh.Points[3 * v] + 3, osd[v].P);
        const double tolerance = 1e-9 * subdtest::Diagonal(mesh.Points);
        // OpenSubdiv's face f is my face FaceMap[f], its corner j my corner j + Turn[f].
        std::vector<Index> faceMap(static_cast<size_t>(mesh.NumFaces())), turn(faceMap.size(), 0);
        std::vector<Index> vertexMap(static_cast<size_t>(mesh.NumVertices()));
        std::iota(faceMap.begin(), faceMap.end(), 0);
        std::iota(vertexMap.begin(), vertexMap.end(), 0);
        for (int l = 1; l <= levels; ++l)
        {
          const std::string at = what + " level " + std::to_string(l);
          const Far::TopologyLevel& parentOsd = refiner->GetLevel(l - 1);
          const Far::TopologyLevel& childOsd = refiner->GetLevel(l);
          const subd::MeshTopology parent = level.Topology;
          const subd::QuadSplitNumbering quads{ parent.GetNumFaces(), parent.GetNumEdges() };
          const subd::TriangleSplitNumbering triangles{ parent.GetNumEdges() };
          std::vector<Index> childVertexMap(static_cast<size_t>(childOsd.GetNumVertices()), subd::InvalidIndex);
          std::vector<Index> childFaceMap(static_cast<size_t>(childOsd.GetNumFaces()), subd::InvalidIndex);
          for (Index f = 0; f < parentOsd.GetNumFaces(); ++f)
          {
            const Index g = faceMap[f], n = parent.GetFaceSize(g);
            const Far::ConstIndexArray edges = parentOsd.GetFaceEdges(f), children = parentOsd.GetFaceChildFaces(f);
            for (Index j = 0; j < n; ++j)
            {
              const Index e = parent.GetFaceEdges(g)[(j + turn[f]) % n];
              childVertexMap[parentOsd.GetEdgeChildVertex(edges[j])] = loop ? triangles.EdgePoint(e) : quads.EdgePoint(e);
            }
            if (!loop)
              childVertexMap[parentOsd.GetFaceChildVertex(f)] = quads.FacePoint(g);
            for (Index k = 0; k < children.size(); ++k)
              childFaceMap[children[k]] = MyChildFace(parent, g, turn[f], k, loop);
          }
          for (Index v = 0; v < parentOsd.GetNumVertices(); ++v)
            childVertexMap[parentOsd.GetVertexChildVertex(v)] = loop ? triangles.VertexPoint(vertexMap[v]) : quads.VertexPoint(vertexMap[v]);

          std::vector<Point3> osdChild(childVertexMap.size());
          Point3* src = osd.data();
          Point3* dst = osdChild.data();
          primvar.Interpolate(l, src, dst);
          osd.swap(osdChild);
          mine = subdtest::ApplyToPoints(scheme->BuildStencils(level), mine);
          level = scheme->Split(level, subd::ChildTopology::Full);
          ASSERT_EQ(level.Topology.GetNumFaces(), childOsd.GetNumFaces()) << at;
          ASSERT_EQ(level.Topology.GetNumVertices(), childOsd.GetNumVertices()) << at;
          std::vector<Index> childTurn(childFaceMap.size(), subd::InvalidIndex);
          for (Index f = 0; f < childOsd.GetNumFaces(); ++f)
          {
            const Far::ConstIndexArray fv = childOsd.GetFaceVertices(f);
            const subd::IndexSpan corners = level.Topology.GetFaceVertices(childFaceMap[f]);
            ASSERT_EQ(corners.size(), fv.size()) << at << " face " << f;
            for (Index r = 0; r < fv.size() && childTurn[f] == subd::InvalidIndex; ++r)
            {
              bool agrees = true;
              for (Index j = 0; j < fv.size(); ++j)
                agrees &= childVertexMap[fv[j]] == corners[(j + r) % fv.size()];
              childTurn[f] = agrees ? r : subd::InvalidIndex;
            }
            ASSERT_NE(childTurn[f], subd::InvalidIndex) << at << " face " << f << ": other corners";
            EXPECT_EQ(level.IsFaceHole(childFaceMap[f]), childOsd.IsFaceHole(f)) << at << " face " << f;
          }
          for (Index v = 0; v < static_cast<Index>(osd.size()); ++v)
            for (int k = 0; k < 3; ++k)
              ASSERT_NEAR(mine[3 * childVertexMap[v] + k], osd[v].P[k], tolerance) << at << " point " << v;
          faceMap = childFaceMap;
          turn = childTurn;
          vertexMap = childVertexMap;
        }
        if (kind == SchemeKind::Bilinear)
          continue;
        std::vector<Point3> osdLimit(osd.size());
        Point3* limitSrc = osd.data();
        Point3* limitDst = osdLimit.data();
        primvar.Limit(limitSrc, limitDst);
        subd::StencilTable limit;
        std::string error;
        if (loop)
          limit = subd::BuildLoopLimitStencils(level);
        else
          ASSERT_TRUE(subd::BuildCatmullClarkLimitStencils(level, limit, error)) << what << ": " << error;
        const std::vector<double> mineLimit = subdtest::ApplyToPoints(limit, mine);
        for (Index v = 0; v < static_cast<Index>(osd.size()); ++v)
          for (int k = 0; k < 3; ++k)
            ASSERT_NEAR(mineLimit[3 * vertexMap[v] + k], osdLimit[v].P[k], tolerance) << what << " limit " << v;
      }
}

// What a user gets from subd's filters on the repeated-corner fixtures: OpenSubdiv's face
// count (Catmull-Clark level 1 on pole fans of 8, 64 and 360 quads: 64, 512 and 2880 faces,
// not the 56, 448 and 2520 of collapsed poles) and its points, found among the output's (the
// two number them differently), at two levels, for Catmull-Clark, Loop (triangulated input)
// and linear (bilinear on quads), with one warning counting the polygons.
TEST(RepeatedCorners, FiltersGiveOpenSubdivsOutput)
{
  std::vector<subdtest::TestMesh> meshes{ subdtest::RepeatedCornerMix() };
  for (int n : { 8, 64, 360 })
    meshes.push_back(subdtest::RepeatedCornerPole(n));
  const std::pair<const char*, SchemeKind> schemes[] = { { "catmull-clark", SchemeKind::CatmullClark },
    { "loop", SchemeKind::Loop }, { "linear", SchemeKind::Bilinear } };
  for (const auto& scheme : schemes)
    for (const subdtest::TestMesh& input : meshes)
      for (int levels : { 1, 2 })
      {
        const subdtest::TestMesh mesh = scheme.second == SchemeKind::Loop ? input.Triangulated() : input;
        const std::string what = std::string(scheme.first) + " " + mesh.Name + " level " + std::to_string(levels);
        subdapp::SchemeOptions options;
        options.Levels = levels;
        subdapp::MessageCollector messages;
        const vtkSmartPointer<vtkPolyData> out =
          subdapp::RunScheme(*subdapp::FindScheme(scheme.first), options, subdtest::ToPolyData(mesh), messages);
        ASSERT_NE(out, nullptr) << what << ": " << messages.Errors;
        EXPECT_NE(messages.Warnings.find("polygon(s) repeat a point"), std::string::npos) << what;
        // The mix has a non-manifold edge of its own (three faces); the poles only what their
        // repeated corners make non-manifold, which that warning tells.
        EXPECT_EQ(messages.Warnings.find("Input is non-manifold") != std::string::npos, mesh.Name.rfind("repeat-mix", 0) == 0)
          << what << ": " << messages.Warnings;

        auto refiner = MakeOsdRefiner(mesh, subd::BoundaryRule::EdgeOnly, levels, scheme.second, {});
        const std::vector<Point3> finestPoints = OsdFinestPoints(*refiner, mesh);
        const Point3* src = finestPoints.data();
        const Far::TopologyLevel& finest = refiner->GetLevel(levels);
        ASSERT_EQ(out->GetNumberOfPolys(), finest.GetNumFaces()) << what;
        ASSERT_EQ(out->GetNumberOfPoints(), finest.GetNumVertices()) << what;
        if (scheme.second == SchemeKind::CatmullClark && levels == 1 && mesh.Name != "repeat-mix")
          EXPECT_EQ(finest.GetNumFaces(), 8 * (mesh.NumVertices() - 1) / 2) << what; // 8 children per pole quad pair
        vtkNew<vtkStaticPointLocator> locator;
        locator->SetDataSet(out);
        locator->BuildLocator();
        const double tolerance = 1e-9 * subdtest::Diagonal(mesh.Points);
        for (Index v = 0; v < finest.GetNumVertices(); ++v)
        {
          const double* p = src[v].P;
          const double* q = out->GetPoint(locator->FindClosestPoint(p));
          ASSERT_LT(std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]), tolerance) << what << " point " << v;
        }
      }
}

// OpenSubdiv's smooth triangle rule (Sdc::Options::TRI_SUB_SMOOTH) in Catmull-Clark: on meshes
// with triangles (the house's floor, the stars' roofs, the triangulated grid and cube), under
// the three boundary rules, with and without a semi-sharp edge between a triangle and a quad,
// levels 1..3: every refined point is one of OpenSubdiv's at 1e-9 of the diagonal, and as many;
// without the rule some point is not (the fixtures test it).
TEST(SmoothTriangles, CatmullClarkIsOpenSubdivs)
{
  std::vector<subdtest::TestMesh> meshes{ subdtest::House(false).Jitter(0.1),
    subdtest::Grid(4, 3, false, false).Jitter(0.1).Triangulated(), subdtest::Cube().Jitter(0.1).Triangulated() };
  for (int n : { 3, 5, 8 })
    meshes.push_back(subdtest::Star(n).Jitter(0.1));
  const int levels = 3;
  for (const subdtest::TestMesh& mesh : meshes)
    for (const subd::BoundaryRule rule :
      { subd::BoundaryRule::None, subd::BoundaryRule::EdgeOnly, subd::BoundaryRule::EdgeAndCorner })
      for (const bool creased : { false, true })
      {
        SharpTags tags;
        if (creased) // an edge of the first face, a triangle or next to one
        {
          tags.CreasePairs = { mesh.Vertices[mesh.Offsets[0]], mesh.Vertices[mesh.Offsets[0] + 1] };
          tags.CreaseSharpness = { 0.6f };
        }
        const std::string what = mesh.Name + " " + subd::ToString(rule) + (creased ? " creased" : "");
        auto refiner = MakeOsdRefiner(mesh, rule, levels, SchemeKind::CatmullClark, tags, nullptr, true);
        const std::vector<Point3> finestPoints = OsdFinestPoints(*refiner, mesh);
        const Point3* src = finestPoints.data();
        const Index numFinest = refiner->GetLevel(levels).GetNumVertices();
        const double tolerance = 1e-9 * subdtest::Diagonal(mesh.Points);
        Index unmatched[2] = { 0, 0 };
        for (const bool smooth : { true, false })
        {
          const subd::CatmullClarkScheme scheme(smooth);
          subd::MeshTopology topology = subd::MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices);
          const subd::BaseTags baseTags = ToBaseTags(tags, topology);
          subd::Level level = subd::MakeBaseLevel(std::move(topology), baseTags, scheme.EffectiveBoundaryRule(rule));
          std::vector<double> mine = mesh.Points;
          for (int l = 0; l < levels; ++l)
          {
            mine = subdtest::ApplyToPoints(scheme.BuildStencils(level), mine);
            level = scheme.Split(level, subd::ChildTopology::Full);
          }
          ASSERT_EQ(static_cast<Index>(mine.size() / 3), numFinest) << what;
          for (Index v = 0; v < numFinest; ++v)
          {
            double distance;
            subdtest::NearestPoint(mine, src[v].P, distance);
            unmatched[smooth ? 0 : 1] += distance > tolerance;
          }
        }
        EXPECT_EQ(unmatched[0], 0) << what << ": points not OpenSubdiv's";
        EXPECT_GT(unmatched[1], 0) << what << ": the rule changes nothing here";
      }
}

// The filter's SmoothTriangles option is that rule: the house (its floor two triangles)
// through vtkSubDCatmullClarkFilter gives OpenSubdiv's points.
TEST(SmoothTriangles, TheFilterOptionIsTheRule)
{
  const subdtest::TestMesh mesh = subdtest::House(false).Jitter(0.1);
  const int levels = 2;
  vtkNew<vtkSubDCatmullClarkFilter> filter;
  filter->SetInputData(subdtest::ToPolyData(mesh));
  filter->SetNumberOfSubdivisions(levels);
  filter->SmoothTrianglesOn();
  filter->Update();
  auto refiner = MakeOsdRefiner(mesh, subd::BoundaryRule::EdgeOnly, levels, SchemeKind::CatmullClark, {}, nullptr, true);
  const std::vector<Point3> finestPoints = OsdFinestPoints(*refiner, mesh);
  const Point3* src = finestPoints.data();
  vtkPolyData* out = filter->GetOutput();
  ASSERT_EQ(out->GetNumberOfPoints(), refiner->GetLevel(levels).GetNumVertices());
  std::vector<double> ours;
  for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
    ours.insert(ours.end(), out->GetPoint(p), out->GetPoint(p) + 3);
  for (Index v = 0; v < refiner->GetLevel(levels).GetNumVertices(); ++v)
  {
    double distance;
    subdtest::NearestPoint(ours, src[v].P, distance);
    EXPECT_LT(distance, 1e-9 * subdtest::Diagonal(mesh.Points)) << "point " << v;
  }
}

// Limit evaluation next to faces that repeat a vertex: the pieces it refines keep the two
// edges that a degenerate edge leaves between the same two points (MeshTopology::ExtractFaces),
// so positions and derivatives are OpenSubdiv's patches' (LimitOracle), with and without
// creases.
std::vector<OracleCase> RepeatedCornerLimitCases()
{
  std::vector<OracleCase> cases;
  for (const subdtest::TestMesh& mesh : { subdtest::RepeatedCornerMix(), subdtest::RepeatedCornerPole(3),
         subdtest::RepeatedCornerPole(8) })
    for (const SharpTags& tags : { SharpTags{}, RepeatedCornerCreases(mesh) })
      for (auto rule : { subd::BoundaryRule::EdgeOnly, subd::BoundaryRule::EdgeAndCorner })
      {
        cases.push_back({ mesh, rule, SchemeKind::CatmullClark, tags });
        cases.push_back({ mesh.Triangulated(), rule, SchemeKind::Loop, tags });
      }
  return cases;
}

INSTANTIATE_TEST_SUITE_P(RepeatedCorners, LimitOracle, ::testing::ValuesIn(RepeatedCornerLimitCases()), CaseName);

