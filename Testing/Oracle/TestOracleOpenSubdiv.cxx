// Oracle test: SubD's Catmull-Clark and Loop against OpenSubdiv's Far::TopologyRefiner and
// PrimvarRefinerReal<double> (Debian's libosd-dev), an independent implementation.
//
// Both refine the same fixtures for each boundary rule, levels 1..3. Child points are
// matched through the parent they come from (OpenSubdiv orders child points from faces
// first, then edges, then vertices; faces are matched by their vertex sets, edges by their
// end points), never by assuming equal numbering. Positions must agree to 1e-9 of the
// bounding-box diagonal; faces and holes must agree exactly.
#include "SubDRefiner.h"
#include "SubDQuadSplit.h"
#include "SubDScheme.h"
#include "SubDTestMeshes.h"
#include "SubDTriangleSplit.h"

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <ostream>
#include <map>
#include <memory>
#include <numeric>

namespace
{
using namespace OpenSubdiv;
using subd::Index;

struct Point3
{
  double P[3];
  void Clear() { P[0] = P[1] = P[2] = 0.0; }
  void AddWithWeight(const Point3& src, double w)
  {
    for (int c = 0; c < 3; ++c)
    {
      P[c] += w * src.P[c];
    }
  }
};

Sdc::Options::VtxBoundaryInterpolation ToOsd(subd::BoundaryRule rule)
{
  switch (rule)
  {
    case subd::BoundaryRule::None:
      return Sdc::Options::VTX_BOUNDARY_NONE;
    case subd::BoundaryRule::EdgeOnly:
      return Sdc::Options::VTX_BOUNDARY_EDGE_ONLY;
    default:
      return Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER;
  }
}

enum class SchemeKind
{
  CatmullClark,
  Loop,
  Bilinear
};

std::unique_ptr<subd::Scheme> MakeScheme(SchemeKind kind)
{
  if (kind == SchemeKind::Loop)
    return std::make_unique<subd::LoopScheme>();
  if (kind == SchemeKind::Bilinear)
    return std::make_unique<subd::BilinearScheme>();
  return std::make_unique<subd::CatmullClarkScheme>();
}

std::unique_ptr<Far::TopologyRefiner> MakeOsdRefiner(
  const subdtest::TestMesh& mesh, subd::BoundaryRule rule, int levels, SchemeKind kind)
{
  std::vector<int> sizes(static_cast<size_t>(mesh.NumFaces()));
  for (Index f = 0; f < mesh.NumFaces(); ++f)
  {
    sizes[f] = mesh.Offsets[f + 1] - mesh.Offsets[f];
  }
  Far::TopologyDescriptor desc;
  desc.numVertices = mesh.NumVertices();
  desc.numFaces = mesh.NumFaces();
  desc.numVertsPerFace = sizes.data();
  desc.vertIndicesPerFace = mesh.Vertices.data();
  Sdc::Options options;
  options.SetVtxBoundaryInterpolation(ToOsd(rule));
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(
    Factory::Create(desc,
      Factory::Options(kind == SchemeKind::Loop
          ? Sdc::SCHEME_LOOP
          : (kind == SchemeKind::Bilinear ? Sdc::SCHEME_BILINEAR : Sdc::SCHEME_CATMARK),
        options)));
  Far::TopologyRefiner::UniformOptions uniform(levels);
  uniform.orderVerticesFromFacesFirst = true;
  uniform.fullTopologyInLastLevel = true;
  refiner->RefineUniform(uniform);
  return refiner;
}

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

double Diagonal(const std::vector<double>& p)
{
  double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
  for (size_t i = 0; i < p.size(); ++i)
  {
    lo[i % 3] = std::min(lo[i % 3], p[i]);
    hi[i % 3] = std::max(hi[i % 3], p[i]);
  }
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
    (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

struct OracleCase
{
  subdtest::TestMesh Mesh;
  subd::BoundaryRule Rule;
  SchemeKind Kind;
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
  *os << MakeScheme(c.Kind)->GetName() << " " << c.Mesh.Name << " " << subd::ToString(c.Rule);
}

class SchemeOracle : public ::testing::TestWithParam<OracleCase>
{
};

TEST_P(SchemeOracle, MatchesOpenSubdivLevels1To3)
{
  const OracleCase& c = GetParam();
  const int maxLevel = 3;
  auto refiner = MakeOsdRefiner(c.Mesh, c.Rule, maxLevel, c.Kind);
  ASSERT_TRUE(refiner);
  Far::PrimvarRefinerReal<double> primvar(*refiner);

  const std::unique_ptr<subd::Scheme> schemePointer = MakeScheme(c.Kind);
  const subd::Scheme& scheme = *schemePointer;
  subd::Level level = subd::MakeBaseLevel(
    subd::MeshTopology::Build(c.Mesh.NumVertices(), c.Mesh.Offsets, c.Mesh.Vertices), {},
    scheme.EffectiveBoundaryRule(c.Rule));
  std::vector<double> mine = c.Mesh.Points;
  std::vector<Point3> osd(static_cast<size_t>(c.Mesh.NumVertices()));
  for (Index v = 0; v < c.Mesh.NumVertices(); ++v)
  {
    std::copy(&c.Mesh.Points[3 * v], &c.Mesh.Points[3 * v] + 3, osd[v].P);
  }
  const double tolerance = 1e-9 * Diagonal(c.Mesh.Points);

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
    std::vector<double> mineChild(static_cast<size_t>(stencils.GetNumRows()) * 3);
    stencils.Apply(mine.data(), mineChild.data(), 3);
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
    std::printf("%s %s %s level %d: largest difference %.3g of the bounding-box diagonal\n",
      scheme.GetName(), c.Mesh.Name.c_str(), subd::ToString(c.Rule), l, worst / (tolerance * 1e9));
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
}

std::string CaseName(const ::testing::TestParamInfo<OracleCase>& info)
{
  std::string name = std::string(MakeScheme(info.param.Kind)->GetName()) + "_" +
    info.param.Mesh.Name + "_" + subd::ToString(info.param.Rule);
  std::replace_if(name.begin(), name.end(), [](char ch) { return !std::isalnum(static_cast<unsigned char>(ch)); }, '_');
  return name;
}

INSTANTIATE_TEST_SUITE_P(Fixtures, SchemeOracle, ::testing::ValuesIn(Cases()), CaseName);
}
