// Property tests over every scheme x its fixtures, two levels: every stencil row sums to one,
// refinement commutes with affine maps, planar input stays planar, and the refined mesh of a
// closed manifold is a closed manifold with the same Euler characteristic.
#include "SubDButterflyRules.h"
#include "SubDMemoryEstimate.h"
#include "SubDRefiner.h"
#include "SubDRowWriting.h"
#include "SubDScheme.h"
#include "SubDOracleSupport.h"
#include "SubDTestHeap.h"
#include "SubDTestMeshes.h"
#include "SubDTestParallel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <string>

using subd::Index;

namespace
{
struct SchemeCase
{
  std::string Name;
  std::function<std::unique_ptr<subd::Scheme>()> Make;
  bool TrianglesOnly;
};

std::vector<SchemeCase> SchemeCases()
{
  return {
    { "catmull-clark", [] { return std::make_unique<subd::CatmullClarkScheme>(); }, false },
    { "bilinear", [] { return std::make_unique<subd::BilinearScheme>(); }, false },
    { "doo-sabin", [] { return std::make_unique<subd::DooSabinScheme>(); }, false },
    { "midpoint", [] { return std::make_unique<subd::MidpointScheme>(); }, false },
    { "loop", [] { return std::make_unique<subd::LoopScheme>(); }, true },
    { "linear-triangles", [] { return std::make_unique<subd::LinearTriangleScheme>(); }, true },
    { "sqrt3", [] { return std::make_unique<subd::Sqrt3Scheme>(); }, true },
    { "butterfly", [] { return std::make_unique<subd::ButterflyScheme>(0.0); }, true },
    { "butterfly-tension", [] { return std::make_unique<subd::ButterflyScheme>(1.0 / 16.0); }, true },
  };
}

class AllSchemes : public ::testing::TestWithParam<SchemeCase>
{
protected:
  std::vector<subdtest::TestMesh> Fixtures() const
  {
    return GetParam().TrianglesOnly ? subdtest::TriangleMeshes() : subdtest::StandardMeshes();
  }
  subd::Hierarchy Refine(const subdtest::TestMesh& mesh, int levels) const
  {
    const auto scheme = GetParam().Make();
    subd::Hierarchy h;
    subd::Refine(*scheme,
      subdtest::BaseLevel(mesh, scheme->EffectiveBoundaryRule(subd::BoundaryRule::EdgeOnly)),
      levels, h);
    return h;
  }
  static std::vector<double> Evaluate(const subd::Hierarchy& h, const std::vector<double>& points)
  {
    std::vector<double> out(static_cast<size_t>(h.GetNumFinestPoints()) * 3);
    h.Evaluate(points.data(), 3, out.data());
    return out;
  }
};
}

TEST_P(AllSchemes, RowsSumToOne)
{
  for (const subdtest::TestMesh& mesh : Fixtures())
  {
    const subd::Hierarchy h = Refine(mesh, 2);
    for (const subd::StencilTable& table : h.Stencils)
      for (Index r = 0; r < table.GetNumRows(); ++r)
        ASSERT_NEAR(table.GetRowSum(r), 1.0, 1e-14) << mesh.Name << " row " << r;
  }
}

TEST_P(AllSchemes, AffineInvariance)
{
  const double A[3][3] = { { 1.3, 0.2, -0.4 }, { 0.1, 0.9, 0.3 }, { -0.5, 0.25, 1.1 } };
  const double b[3] = { 3.0, -2.0, 0.5 };
  auto apply = [&](std::vector<double> p) {
    for (size_t i = 0; i < p.size(); i += 3)
    {
      const double x = p[i], y = p[i + 1], z = p[i + 2];
      for (int r = 0; r < 3; ++r)
        p[i + r] = A[r][0] * x + A[r][1] * y + A[r][2] * z + b[r];
    }
    return p;
  };
  for (const subdtest::TestMesh& mesh : Fixtures())
  {
    const subd::Hierarchy h = Refine(mesh, 2);
    const std::vector<double> a = apply(Evaluate(h, mesh.Points));
    const std::vector<double> c = Evaluate(h, apply(mesh.Points));
    for (size_t i = 0; i < a.size(); ++i)
      ASSERT_NEAR(a[i], c[i], 1e-12) << mesh.Name;
  }
}

// The size guard relies on PredictChildCounts: never below the real counts, and exact on
// closed manifolds (except the midpoint scheme, whose prediction counts the boundary
// vertices an open mesh may keep).
TEST_P(AllSchemes, PredictedCountsBoundTheRealOnes)
{
  const auto scheme = GetParam().Make();
  for (const subdtest::TestMesh& mesh : Fixtures())
  {
    subd::Level level = subdtest::BaseLevel(mesh, scheme->EffectiveBoundaryRule(subd::BoundaryRule::EdgeOnly));
    for (int l = 1; l <= 2; ++l)
    {
      const subd::MeshTopology& p = level.Topology;
      const bool closed = p.GetNumBoundaryEdges() == 0 && p.GetNumNonManifoldEdges() == 0 &&
        p.GetNumNonManifoldVertices() == 0;
      const subd::MeshCounts predicted = scheme->PredictChildCounts({ double(p.GetNumFaces()),
        double(p.GetNumEdges()), double(p.GetNumVertices()), double(p.GetNumFaceCorners()),
        double(p.GetNumBoundaryEdges() + p.GetNumNonManifoldEdges()) });
      subd::Level child = scheme->Split(level, subd::ChildTopology::Full);
      const subd::MeshTopology& c = child.Topology;
      const double actual[4] = { double(c.GetNumFaces()), double(c.GetNumEdges()), double(c.GetNumVertices()),
        double(c.GetNumFaceCorners()) };
      const double guess[4] = { predicted.Faces, predicted.Edges, predicted.Vertices, predicted.Corners };
      for (int k = 0; k < 4; ++k)
      {
        EXPECT_GE(guess[k], actual[k]) << mesh.Name << " level " << l << " count " << k;
        if (closed && GetParam().Name != "midpoint")
          EXPECT_EQ(guess[k], actual[k]) << mesh.Name << " level " << l << " count " << k;
      }
      level = std::move(child);
    }
  }
}

TEST_P(AllSchemes, PlanarInPlanarOut)
{
  for (const subdtest::TestMesh& mesh : Fixtures())
  {
    std::vector<double> flat = mesh.Points;
    for (size_t i = 2; i < flat.size(); i += 3)
      flat[i] = 0.75; // the plane z = 0.75
    const std::vector<double> out = Evaluate(Refine(mesh, 2), flat);
    for (size_t i = 2; i < out.size(); i += 3)
      ASSERT_NEAR(out[i], 0.75, 1e-15) << mesh.Name;
  }
}

TEST_P(AllSchemes, ClosedManifoldStaysClosedWithSameEuler)
{
  for (const subdtest::TestMesh& mesh : Fixtures())
  {
    const subd::MeshTopology base = subd::MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices);
    if (base.GetNumBoundaryEdges() > 0 || base.GetNumNonManifoldEdges() > 0 || base.GetNumNonManifoldVertices() > 0)
      continue;
    const subd::Hierarchy h = Refine(mesh, 2);
    const subd::MeshTopology finest = subd::MeshTopology::Build(h.GetNumFinestPoints(),
      h.Finest.Topology.GetFaceOffsetArray(), h.Finest.Topology.GetFaceVertexArray());
    EXPECT_EQ(finest.GetNumBoundaryEdges(), 0) << mesh.Name;
    EXPECT_EQ(finest.GetNumNonManifoldEdges(), 0) << mesh.Name << " (orientation)";
    EXPECT_EQ(finest.GetNumNonManifoldVertices(), 0) << mesh.Name;
    EXPECT_EQ(finest.GetNumVertices() - finest.GetNumEdges() + finest.GetNumFaces(),
      base.GetNumVertices() - base.GetNumEdges() + base.GetNumFaces())
      << mesh.Name;
  }
}

INSTANTIATE_TEST_SUITE_P(Schemes, AllSchemes, ::testing::ValuesIn(SchemeCases()),
  [](const ::testing::TestParamInfo<SchemeCase>& info) {
    std::string name = info.param.Name;
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
  });

// A first evaluation into an empty scratch frees the level before the finest's parent before
// the finest level is written (it is not read again: the peak of a refinement is lower by it);
// a scratch reused keeps both levels, and gives the same values, bit for bit.
TEST_P(AllSchemes, FirstEvaluationFreesTheLevelItNoLongerReads)
{
  const subdtest::TestMesh mesh = this->Fixtures().front();
  for (int levels : { 1, 2, 3, 4 })
  {
    SCOPED_TRACE("levels " + std::to_string(levels));
    const subd::Hierarchy h = this->Refine(mesh, levels);
    const std::vector<double> expected = Evaluate(h, mesh.Points);
    subd::EvaluationScratch<double> scratch;
    std::vector<double> first(expected.size()), again(expected.size());
    ASSERT_TRUE(h.Evaluate(mesh.Points.data(), 3, first.data(), subd::SerialFor, nullptr, -1, &scratch));
    // Level l's values (l = 1 .. levels - 1) go to room (l - 1) % 2: the finest's parent's
    // room holds its values, the other one nothing.
    const size_t parentRoom = static_cast<size_t>(levels - 2) % 2;
    for (size_t room = 0; room < 2; ++room)
    {
      const bool holds = levels >= 2 && room == parentRoom;
      EXPECT_EQ(scratch.Levels[room].empty(), !holds) << "room " << room;
    }
    EXPECT_EQ(scratch.IsEmpty(), levels < 2);
    ASSERT_TRUE(h.Evaluate(mesh.Points.data(), 3, again.data(), subd::SerialFor, nullptr, -1, &scratch));
    EXPECT_EQ(scratch.Levels[0].empty(), levels < 2); // reused: both kept for the next one
    EXPECT_EQ(scratch.Levels[1].empty(), levels < 3);
    EXPECT_EQ(first, expected);
    EXPECT_EQ(again, expected);
  }
}

TEST(MidpointScheme, OpenBoundaryKeepsItsShape)
{
  const subdtest::TestMesh mesh = subdtest::Grid(4, 3, false, false).Jitter(0.1);
  const subd::MeshTopology base = subd::MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices);
  subd::MidpointScheme scheme;
  subd::Hierarchy h;
  const std::vector<double> out = subdtest::RefineFixture(scheme, mesh, 3, h);
  const subd::MeshTopology finest = subd::MeshTopology::Build(
    h.GetNumFinestPoints(), h.Finest.Topology.GetFaceOffsetArray(), h.Finest.Topology.GetFaceVertexArray());
  ASSERT_GT(finest.GetNumBoundaryEdges(), 0);
  // Distance from p to the nearest boundary segment of the input.
  auto distanceToBoundary = [&](const double* p) {
    double best = 1e300;
    for (Index e = 0; e < base.GetNumEdges(); ++e)
    {
      if (!base.GetEdgeTag(e).Boundary)
        continue;
      const double* a = &mesh.Points[3 * base.GetEdgeVertices(e)[0]];
      const double* b = &mesh.Points[3 * base.GetEdgeVertices(e)[1]];
      double ab[3], ap[3], t = 0, len2 = 0;
      for (int k = 0; k < 3; ++k)
      {
        ab[k] = b[k] - a[k];
        ap[k] = p[k] - a[k];
        t += ab[k] * ap[k];
        len2 += ab[k] * ab[k];
      }
      t = std::clamp(t / len2, 0.0, 1.0);
      double d2 = 0;
      for (int k = 0; k < 3; ++k)
        d2 += (ap[k] - t * ab[k]) * (ap[k] - t * ab[k]);
      best = std::min(best, std::sqrt(d2));
    }
    return best;
  };
  Index boundaryPoints = 0;
  for (Index v = 0; v < finest.GetNumVertices(); ++v)
  {
    if (finest.GetVertexTag(v).Boundary)
    {
      ++boundaryPoints;
      EXPECT_LT(distanceToBoundary(&out[3 * v]), 1e-12) << "point " << v;
    }
  }
  EXPECT_EQ(boundaryPoints, finest.GetNumBoundaryEdges()); // a closed boundary loop
}

TEST(ButterflyScheme, ExtraordinaryWeightsAndInterpolation)
{
  EXPECT_DOUBLE_EQ(subd::ButterflyExtraordinaryWeight(3, 0), 5.0 / 12.0);
  EXPECT_DOUBLE_EQ(subd::ButterflyExtraordinaryWeight(3, 2), -1.0 / 12.0);
  EXPECT_DOUBLE_EQ(subd::ButterflyExtraordinaryWeight(4, 0), 3.0 / 8.0);
  EXPECT_DOUBLE_EQ(subd::ButterflyExtraordinaryWeight(4, 1), 0.0);
  EXPECT_DOUBLE_EQ(subd::ButterflyExtraordinaryWeight(4, 2), -1.0 / 8.0);
  for (Index K = 3; K <= 64; ++K)
  {
    double sum = 0;
    for (Index j = 0; j < K; ++j)
      sum += subd::ButterflyExtraordinaryWeight(K, j);
    EXPECT_NEAR(sum, 0.25, 1e-14) << "K = " << K; // the vertex itself takes 3/4
  }
  // Valence 6 in the K >= 5 formula gives the regular one-ring weights 7/24, 1/12, -1/12, -1/24.
  EXPECT_NEAR(subd::ButterflyExtraordinaryWeight(6, 0), 7.0 / 24.0, 1e-15);
  EXPECT_NEAR(subd::ButterflyExtraordinaryWeight(6, 3), -1.0 / 24.0, 1e-15);

  // Interpolating: every input point is an output point, bit for bit, at every level.
  for (const subdtest::TestMesh& mesh : subdtest::TriangleMeshes())
  {
    for (double w : { 0.0, 0.05 })
    {
      subd::ButterflyScheme scheme(w);
      subd::Hierarchy h;
      const std::vector<double> out = subdtest::RefineFixture(scheme, mesh, 3, h);
      // Vertex points are numbered last at each level: the input points end the array.
      const size_t first = out.size() - mesh.Points.size();
      for (size_t i = 0; i < mesh.Points.size(); ++i)
        ASSERT_EQ(out[first + i], mesh.Points[i]) << mesh.Name;
    }
  }
}

// Each triangle corner's entry names the other triangle on the corner's edge and the edge's
// place in it (the wing is that triangle's third corner), or nothing where the edge has not
// two distinct faces.
TEST(ButterflyScheme, FaceAcrossNamesTheOtherTriangleOfEachEdge)
{
  Index acrossCount = 0, invalidCount = 0;
  for (const subdtest::TestMesh& mesh : subdtest::TriangleMeshes())
  {
    const subd::MeshTopology topo = subd::MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices);
    const auto across = subd::MakeTriangleFaceAcross(topo, subdtest::ThreeThreadFor);
    ASSERT_EQ(across->size(), topo.GetFaceVertexArray().size()) << mesh.Name;
    for (Index f = 0; f < topo.GetNumFaces(); ++f)
    {
      for (Index i = 0; i < 3; ++i)
      {
        const Index e = topo.GetTriangleEdges(f)[i];
        const subd::IndexSpan ef = topo.GetEdgeFaces(e);
        const Index packed = (*across)[3 * f + i];
        if (ef.size() != 2 || ef[0] == ef[1])
        {
          EXPECT_EQ(packed, subd::InvalidIndex) << mesh.Name << " face " << f;
          ++invalidCount;
          continue;
        }
        ASSERT_NE(packed, subd::InvalidIndex) << mesh.Name << " face " << f;
        const Index h = packed / 4, p = packed % 4;
        EXPECT_EQ(h, ef[0] == f ? ef[1] : ef[0]) << mesh.Name << " face " << f;
        ASSERT_LT(p, 3);
        EXPECT_EQ(topo.GetTriangleEdges(h)[p], e) << mesh.Name << " face " << f;
        const Index* ends = topo.GetEdgeVertices(e);
        const Index wing = subd::TriangleVertexAcross(topo, packed);
        EXPECT_TRUE(wing != ends[0] && wing != ends[1]) << mesh.Name << " face " << f;
        EXPECT_NE(std::find(topo.GetTriangleVertices(h), topo.GetTriangleVertices(h) + 3, wing),
          topo.GetTriangleVertices(h) + 3);
        ++acrossCount;
      }
    }
  }
  EXPECT_GT(acrossCount, 0);
  EXPECT_GT(invalidCount, 0); // the fixtures have boundaries
}

TEST(ButterflyScheme, RegularTenPointStencilWithTension)
{
  // A torus triangulated with all diagonals the same way: every vertex has valence 6.
  subdtest::TestMesh torus = subdtest::Grid(8, 8, true, true).Triangulated();
  const subd::MeshTopology t = subd::MeshTopology::Build(torus.NumVertices(), torus.Offsets, torus.Vertices);
  for (Index v = 0; v < t.GetNumVertices(); ++v)
    ASSERT_EQ(t.GetVertexEdges(v).size(), 6);
  const double w = 0.04;
  const subd::Level base = subd::MakeBaseLevel(t, {}, subd::BoundaryRule::EdgeOnly);
  const subd::StencilTable table = subd::ButterflyScheme(w).BuildStencils(base);
  for (Index e = 0; e < t.GetNumEdges(); ++e)
  {
    // 10 distinct points; weights 1/2-w (x2), 1/8+2w (x2), -1/16-w (x4), w (x2).
    const subd::IndexSpan src = table.GetSources(e);
    ASSERT_EQ(src.size(), 10);
    std::vector<double> weights(table.GetWeights(e), table.GetWeights(e) + 10);
    std::sort(weights.begin(), weights.end());
    const std::vector<double> expected{ -0.0625 - w, -0.0625 - w, -0.0625 - w, -0.0625 - w, w, w, 0.125 + 2 * w,
      0.125 + 2 * w, 0.5 - w, 0.5 - w };
    for (int k = 0; k < 10; ++k)
      EXPECT_NEAR(weights[k], expected[k], 1e-15) << "edge " << e;
    // The edge ends carry 1/2 - w.
    const Index* ev = t.GetEdgeVertices(e);
    for (Index k = 0; k < 10; ++k)
      if (src[k] == ev[0] || src[k] == ev[1])
        EXPECT_NEAR(table.GetWeights(e)[k], 0.5 - w, 1e-15);
  }
}

namespace
{
// Distance from p to triangle (a, b, c) (Ericson, Real-Time Collision Detection, 5.1.5).
double PointTriangleDistance(const double* p, const double* a, const double* b, const double* c)
{
  auto sub = [](const double* x, const double* y, double* r) { r[0] = x[0] - y[0]; r[1] = x[1] - y[1]; r[2] = x[2] - y[2]; };
  auto dot = [](const double* x, const double* y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
  double ab[3], ac[3], ap[3], bp[3], cp[3], q[3];
  sub(b, a, ab);
  sub(c, a, ac);
  sub(p, a, ap);
  auto at = [&](double u, double v) { // a + u ab + v ac
    for (int k = 0; k < 3; ++k)
      q[k] = a[k] + u * ab[k] + v * ac[k];
    double d[3];
    sub(p, q, d);
    return std::sqrt(dot(d, d));
  };
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0)
    return at(0, 0);
  sub(p, b, bp);
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3)
    return at(1, 0);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0)
    return at(d1 / (d1 - d3), 0);
  sub(p, c, cp);
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6)
    return at(0, 1);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0)
    return at(0, d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
  {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return at(1 - w, w);
  }
  const double denom = 1.0 / (va + vb + vc);
  return at(vb * denom, vc * denom);
}

// One-sided Hausdorff distance from the points `fine` to the surface of the polygons of
// `coarse` (fan-triangulated).
double DistanceToSurface(const std::vector<double>& fine, const subd::MeshTopology& coarse,
  const std::vector<double>& coarsePoints)
{
  double worst = 0;
  for (size_t i = 0; i < fine.size() / 3; ++i)
  {
    double best = 1e300;
    for (Index f = 0; f < coarse.GetNumFaces() && best > 0; ++f)
    {
      const subd::IndexSpan fv = coarse.GetFaceVertices(f);
      for (Index k = 1; k + 1 < fv.size(); ++k)
        best = std::min(best, PointTriangleDistance(&fine[3 * i], &coarsePoints[3 * fv[0]], &coarsePoints[3 * fv[k]],
                                &coarsePoints[3 * fv[k + 1]]));
    }
    worst = std::max(worst, best);
  }
  return worst;
}
}

// Successive levels converge: the (vertex-sampled, symmetric) Hausdorff distance between the
// polygon surfaces of levels k and k+1 shrinks by a steady factor, as each scheme converges
// to its limit surface. Linear subdivision of triangles does not move off the surface at all.
TEST_P(AllSchemes, SuccessiveLevelsConverge)
{
  const bool linear = GetParam().Name == "linear-triangles";
  const subdtest::TestMesh mesh =
    GetParam().TrianglesOnly ? subdtest::Bipyramid(5).Jitter(0.1) : subdtest::Star(5).Jitter(0.1);
  const auto scheme = GetParam().Make();
  subd::Level level = subdtest::BaseLevel(mesh);
  std::vector<double> points = mesh.Points;
  std::vector<double> distances;
  for (int l = 1; l <= 4; ++l)
  {
    subd::LevelRefinement r = scheme->RefineLevel(level, subd::ChildTopology::Full);
    std::vector<double> child = subdtest::ApplyToPoints(r.Stencils, points);
    distances.push_back(std::max(DistanceToSurface(child, level.Topology, points),
      DistanceToSurface(points, r.Child.Topology, child)));
    level = std::move(r.Child);
    points.swap(child);
  }
  std::printf("%s: distance of level k+1 to level k:", GetParam().Name.c_str());
  for (double d : distances)
    std::printf(" %.3g", d);
  std::printf("\n");
  for (size_t k = 0; k + 1 < distances.size(); ++k)
  {
    if (linear)
      EXPECT_LT(distances[k + 1], 1e-12);
    else
      EXPECT_LT(distances[k + 1], 0.6 * distances[k]) << "level " << k + 2;
  }
}

namespace
{
// One ternary refinement of a closed polygon with the uniform cubic B-spline masks
// (4, 19, 4)/27 for old points and (1, 16, 10)/27, (10, 16, 1)/27 for the two new points of
// each edge. Written independently of the kernel.
std::vector<std::array<double, 3>> TernaryCubic(const std::vector<std::array<double, 3>>& p)
{
  const size_t n = p.size();
  std::vector<std::array<double, 3>> q;
  auto combine = [](double wa, const std::array<double, 3>& a, double wb, const std::array<double, 3>& b, double wc,
                   const std::array<double, 3>& c) {
    std::array<double, 3> r;
    for (int k = 0; k < 3; ++k)
      r[k] = (wa * a[k] + wb * b[k] + wc * c[k]) / 27.0;
    return r;
  };
  for (size_t i = 0; i < n; ++i)
  {
    const auto& prev = p[(i + n - 1) % n];
    const auto& cur = p[i];
    const auto& next = p[(i + 1) % n];
    const auto& after = p[(i + 2) % n];
    q.push_back(combine(4, prev, 19, cur, 4, next));
    q.push_back(combine(1, prev, 16, cur, 10, next));
    q.push_back(combine(10, cur, 16, next, 1, after));
  }
  return q;
}
}

TEST(Sqrt3Scheme, KobbeltBoundaryIsTheTernaryCubicBSplineEveryTwoSteps)
{
  // A 4x3 grid: its boundary is a closed polygon of 14 points, in order around the grid.
  const int nx = 4, ny = 3;
  const subdtest::TestMesh mesh = subdtest::Grid(nx, ny, false, false).Jitter(0.2).Triangulated();
  std::vector<std::array<double, 3>> loop;
  auto add = [&](int i, int j) {
    const Index v = j * (nx + 1) + i;
    loop.push_back({ mesh.Points[3 * v], mesh.Points[3 * v + 1], mesh.Points[3 * v + 2] });
  };
  for (int i = 0; i < nx; ++i)
    add(i, 0);
  for (int j = 0; j < ny; ++j)
    add(nx, j);
  for (int i = nx; i > 0; --i)
    add(i, ny);
  for (int j = ny; j > 0; --j)
    add(0, j);

  subd::Sqrt3Scheme scheme;
  for (int levels : { 1, 2, 4 })
  {
    subd::Hierarchy h;
    const std::vector<double> out = subdtest::RefineFixture(scheme, mesh, levels, h);
    const subd::MeshTopology finest = subd::MeshTopology::Build(
      h.GetNumFinestPoints(), h.Finest.Topology.GetFaceOffsetArray(), h.Finest.Topology.GetFaceVertexArray());
    EXPECT_EQ(finest.GetNumNonManifoldEdges(), 0) << "level " << levels;
    EXPECT_EQ(finest.GetNumNonManifoldVertices(), 0) << "level " << levels;
    // Every used point is used (no orphan centroids).
    std::vector<int> used(static_cast<size_t>(finest.GetNumVertices()), 0);
    for (Index v : finest.GetFaceVertexArray())
      used[v] = 1;
    EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0) << "level " << levels;

    std::vector<std::array<double, 3>> expected = loop;
    for (int step = 2; step <= levels; step += 2)
      expected = TernaryCubic(expected);
    const std::vector<double> expectedPoints = subdtest::Flatten(expected);
    Index boundaryPoints = 0;
    EXPECT_LT(subdtest::FarthestBoundaryPoint(finest, out, expectedPoints, boundaryPoints), 1e-12)
      << "level " << levels;
    EXPECT_EQ(static_cast<size_t>(boundaryPoints), expected.size()) << "level " << levels;
  }
}

TEST(Sqrt3Scheme, CentroidAndRelaxationMasksForValences3To64)
{
  for (int n = 3; n <= 64; ++n)
  {
    // The apexes of a bipyramid have valence n; its equator vertices valence 4.
    const subdtest::TestMesh mesh = subdtest::Bipyramid(n).Jitter(0.2);
    const subd::Level base = subdtest::BaseLevel(mesh);
    const subd::LevelRefinement r = subd::Sqrt3Scheme().RefineLevel(base, subd::ChildTopology::Full);
    const std::vector<double> child = subdtest::ApplyToPoints(r.Stencils, mesh.Points);
    const Index numFaces = base.Topology.GetNumFaces();
    auto P = [&](Index v, int k) { return mesh.Points[3 * v + k]; };
    // Centroids first (closed mesh: one per face), then the old vertices.
    for (Index f = 0; f < numFaces; ++f)
      for (int k = 0; k < 3; ++k)
      {
        double c = 0;
        for (Index v : base.Topology.GetFaceVertices(f))
          c += P(v, k) / 3.0;
        EXPECT_NEAR(child[3 * f + k], c, 1e-15);
      }
    // Apex: (1 - a) v + a/n sum, a = (4 - 2 cos(2 pi / n)) / 9 (Kobbelt 2000).
    const Index apex = n;
    const double a = (4.0 - 2.0 * std::cos(2.0 * 3.14159265358979323846 / n)) / 9.0;
    for (int k = 0; k < 3; ++k)
    {
      double ring = 0;
      for (int i = 0; i < n; ++i)
        ring += P(i, k);
      EXPECT_NEAR(child[3 * (numFaces + apex) + k], (1 - a) * P(apex, k) + a / n * ring, 1e-14) << "n = " << n;
    }
  }
}

// The per-level flags the Catmull-Clark and Loop writers read (one pass over the edges)
// agree with the per-vertex test, with sharp and semi-sharp edges, a sharp vertex and
// boundaries, on the base level and after the creases decayed one level.
TEST(Level, SmoothClosedVerticesAgreeWithThePerVertexTest)
{
  int smooth = 0, tested = 0;
  for (const subdtest::TestMesh& mesh : subdtest::StandardMeshes())
  {
    const subd::MeshTopology topology = subd::MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices);
    subd::BaseTags tags;
    tags.EdgeSharpness.resize(static_cast<size_t>(topology.GetNumEdges()));
    for (size_t e = 0; e < tags.EdgeSharpness.size(); ++e)
      tags.EdgeSharpness[e] = e % 5 == 0 ? 0.6f : (e % 7 == 0 ? subd::SharpnessInfinite : 0.0f);
    tags.VertexSharpness.assign(static_cast<size_t>(topology.GetNumVertices()), 0.0f);
    tags.VertexSharpness[0] = 2.3f;
    subd::Level level = subd::MakeBaseLevel(topology, tags, subd::BoundaryRule::EdgeOnly);
    for (int l = 0; l < 2; ++l)
    {
      const std::vector<std::uint8_t> flags = subd::FindSmoothClosedVertices(level);
      ASSERT_EQ(flags.size(), static_cast<size_t>(level.Topology.GetNumVertices()));
      for (Index v = 0; v < level.Topology.GetNumVertices(); ++v)
      {
        EXPECT_EQ(flags[v] != 0, subd::IsSmoothClosedVertex(level, v)) << mesh.Name << " level " << l << " vertex " << v;
        smooth += flags[v];
        ++tested;
      }
      level = subd::CatmullClarkScheme().Split(level, subd::ChildTopology::Full);
    }
  }
  EXPECT_GT(smooth, 0);
  EXPECT_LT(smooth, tested);
}

// Every level's rows written as they are applied (LevelRows::Written, what the filters use)
// give bit for bit the points, faces, holes and origins the stored table gives, with
// semi-sharp and sharp creases and corners under both crease methods and with no sharp
// feature, a faces-only or full finest level, for 3 double, 3 float and 5 float components.
TEST_P(AllSchemes, WrittenLevelRowsEqualStoredRows)
{
  const auto scheme = GetParam().Make();
  const subd::BoundaryRule rule = scheme->EffectiveBoundaryRule(subd::BoundaryRule::EdgeOnly);
  const bool writes = scheme->MakeRowSource(std::make_shared<subd::Level>()) != nullptr;
  for (int creases = 0; creases < 3; ++creases)
  {
    const subd::CreaseMethod method = creases == 1 ? subd::CreaseMethod::Chaikin : subd::CreaseMethod::Uniform;
    for (const subdtest::TestMesh& mesh : Fixtures())
    {
      const subd::MeshTopology topology = subd::MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices);
      const subd::BaseTags tags = creases == 2 ? subd::BaseTags() : subdtest::MixedSharpnessTags(topology, method);
      std::vector<float> values(static_cast<size_t>(mesh.NumVertices()) * 5);
      for (size_t i = 0; i < values.size(); ++i)
        values[i] = static_cast<float>(std::sin(0.7 * i));
      for (int levels = 1; levels <= 4; ++levels)
      {
        for (const subd::ChildTopology finest : { subd::ChildTopology::FacesOnly, subd::ChildTopology::Full })
        {
          const std::string what = mesh.Name + " L" + std::to_string(levels);
          subd::Hierarchy stored, written;
          subd::Refine(*scheme, subd::MakeBaseLevel(topology, tags, rule), levels, stored, nullptr, finest);
          subd::Refine(*scheme, subd::MakeBaseLevel(topology, tags, rule), levels, written, nullptr, finest,
            subd::LevelRows::Written);
          for (const subd::StencilTable& table : written.Stencils)
            EXPECT_EQ(table.IsStored(), !writes);
          ASSERT_EQ(written.GetNumFinestPoints(), stored.GetNumFinestPoints());
          EXPECT_EQ(Evaluate(written, mesh.Points), Evaluate(stored, mesh.Points)) << what;
          std::vector<float> a(static_cast<size_t>(stored.GetNumFinestPoints()) * 5), b(a.size());
          stored.Evaluate(values.data(), 5, a.data());
          written.Evaluate(values.data(), 5, b.data());
          EXPECT_EQ(a, b) << what;
          // Three float components: points in single precision (the rows' prefetching path).
          std::vector<float> c(static_cast<size_t>(stored.GetNumFinestPoints()) * 3), d(c.size());
          stored.Evaluate(values.data(), 3, c.data());
          written.Evaluate(values.data(), 3, d.data());
          EXPECT_EQ(c, d) << what;
          ASSERT_EQ(written.Finest.Topology.GetFaceVertexArray(), stored.Finest.Topology.GetFaceVertexArray());
          EXPECT_EQ(written.Finest.Topology.GetNumVertices(), stored.Finest.Topology.GetNumVertices());
          EXPECT_EQ(subdtest::FaceTags(written.Finest), subdtest::FaceTags(stored.Finest)) << what;
          EXPECT_EQ(written.Finest.Topology.GetNumEdges(), stored.Finest.Topology.GetNumEdges()) << what;
          EXPECT_EQ(written.Finest.EdgeSharpness, stored.Finest.EdgeSharpness) << what;
          EXPECT_EQ(written.Finest.VertexSharpness, stored.Finest.VertexSharpness) << what;
        }
      }
    }
  }
}

// The size guard's prediction (SubDMemoryEstimate.h) covers what a refinement holds once its
// points are evaluated (every level it keeps, the finest faces, the points and the scratch
// levels: the default path's peak), measured as the heap in use, and is not far above it for
// the schemes that write their rows.
// (Not in the AddressSanitizer build, whose allocator mallinfo2 does not see.)
#if defined(SUBD_HEAP_MEASURABLE)
TEST_P(AllSchemes, PeakMemoryEstimateCoversTheHeldMemory)
{
  const auto scheme = GetParam().Make();
  const subdtest::TestMesh mesh = GetParam().TrianglesOnly ? subdtest::Grid(40, 40, true, false).Triangulated()
                                                       : subdtest::Grid(40, 40, true, false);
  const subd::MeshTopology topology = subd::MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices);
  subd::RefinementRequest request;
  request.Base = { double(topology.GetNumFaces()), double(topology.GetNumEdges()), double(topology.GetNumVertices()),
    double(topology.GetNumFaceCorners()), double(topology.GetNumBoundaryEdges()) };
  request.Levels = 3;
  const double predicted = (subd::EstimatePeakBytes(*scheme, request) - subd::EstimateLibraryBytes);
  const size_t before = subdtest::HeapInUse();
  double held = 0.0;
  {
    subd::Hierarchy hierarchy;
    subd::Refine(*scheme, subd::MakeBaseLevel(topology, {}, scheme->EffectiveBoundaryRule(subd::BoundaryRule::EdgeOnly)),
      request.Levels, hierarchy, nullptr, request.Finest, request.Rows);
    std::vector<double> finest(static_cast<size_t>(hierarchy.GetNumFinestPoints()) * 3);
    subd::EvaluationScratch<double> scratch;
    hierarchy.Evaluate(mesh.Points.data(), 3, finest.data(), subd::SerialFor, nullptr, -1, &scratch);
    held = static_cast<double>(subdtest::HeapInUse() - before);
  }
  EXPECT_GT(held, 1.0e6); // a measurement, not noise
  EXPECT_LE(held, predicted) << GetParam().Name;
  // Not a bound far above, for the schemes whose written rows keep their levels and whose
  // predicted counts are exact (the midpoint's bound its kept boundary vertices by all).
  if (scheme->MakeRowSource(std::make_shared<subd::Level>()) != nullptr && GetParam().Name != "midpoint")
  {
    EXPECT_GE(held, 0.5 * predicted) << GetParam().Name;
  }
}
#endif


// The third consumer of a scheme's rows, its limit masks, agrees with them: the limit of a
// point does not change when the mesh is refined. Primal schemes and sqrt(3) keep every
// vertex v as a child point (its vertex point), whose limit at the next level must be v's:
// checked at smooth and extraordinary vertices, on boundaries, creases, corners and darts.
// The dual schemes replace v by its V-face, whose centroid is v's limit point (SubDDualLimit.h)
// and, a level further down, the centroid of that face's own F-face: checked on closed meshes.
TEST_P(AllSchemes, LimitMasksAgreeWithTheRows)
{
  const auto scheme = GetParam().Make();
  const std::string name = GetParam().Name;
  const bool dual = name == "doo-sabin" || name == "midpoint";
  const subdtest::TestMesh cube = subdtest::Cube().Jitter(0.1), grid = subdtest::Grid(5, 4, false, false).Jitter(0.1);
  std::vector<subdtest::TestMesh> meshes{ cube, grid, subdtest::Grid(6, 5, true, true).Jitter(0.05) };
  if (GetParam().TrianglesOnly)
  {
    meshes = { cube.Triangulated(), grid.Triangulated(), subdtest::Bipyramid(5).Jitter(0.1) };
  }
  int compared = 0;
  for (const subdtest::TestMesh& mesh : meshes)
  {
    const subd::MeshTopology topology = subd::MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices);
    if (dual && topology.GetNumBoundaryEdges() > 0)
      continue; // boundaries of the dual schemes: their curves' own limit rule, not a V-face
    subd::BaseTags tags;
    if (!dual && name != "sqrt3") // sqrt(3) has no limit point at a dart (SubDSqrt3Limit.h)
    {
      // Infinitely sharp edges: creases, corners where three meet, darts where one ends.
      tags.EdgeSharpness.assign(static_cast<size_t>(topology.GetNumEdges()), 0.0f);
      for (size_t e = 0; e < tags.EdgeSharpness.size(); e += 7)
        tags.EdgeSharpness[e] = subd::SharpnessInfinite;
    }
    const subd::Level base = subd::MakeBaseLevel(topology, tags, subd::BoundaryRule::EdgeAndCorner);
    const subd::LevelRefinement one = scheme->RefineLevel(base, subd::ChildTopology::Full);
    const std::vector<double> points1 = subdtest::ApplyToPoints(one.Stencils, mesh.Points);
    subd::StencilTable limit0, limit1;
    std::string error;
    ASSERT_TRUE(scheme->BuildLimitStencils(base, limit0, error)) << mesh.Name << ": " << error;
    const std::vector<double> limits0 = subdtest::ApplyToPoints(limit0, mesh.Points);
    const subd::MeshTopology& child = one.Child.Topology;
    if (!dual)
    {
      ASSERT_TRUE(scheme->BuildLimitStencils(one.Child, limit1, error)) << mesh.Name << ": " << error;
      const std::vector<double> limits1 = subdtest::ApplyToPoints(limit1, points1);
      // The vertex points follow the face points (quad split, sqrt(3)'s first step) or the
      // edge points (triangle split).
      const Index firstVertexPoint = name == "sqrt3" ? topology.GetNumFaces()
        : GetParam().TrianglesOnly                  ? topology.GetNumEdges()
                                                    : topology.GetNumFaces() + topology.GetNumEdges();
      for (Index v = 0; v < topology.GetNumVertices(); ++v)
      {
        // Not at a dart (one sharp edge inside): its limit mask, OpenSubdiv's too, is the
        // smooth one, which the crease beside it makes an approximation.
        const Index sharpEdges = base.GetNumSharpEdges(v);
        if (sharpEdges == 1 && !topology.GetVertexTag(v).Boundary)
          continue;
        for (int k = 0; k < 3; ++k)
          ASSERT_NEAR(limits1[3 * (firstVertexPoint + v) + k], limits0[3 * v + k], 1e-12)
            << mesh.Name << " vertex " << v << " with " << sharpEdges << " sharp edges";
        ++compared;
      }
      continue;
    }
    // A closed mesh: F-faces, then (Doo-Sabin) one E-face per edge, then one V-face per vertex.
    const subd::LevelRefinement two = scheme->RefineLevel(one.Child, subd::ChildTopology::Full);
    const std::vector<double> points2 = subdtest::ApplyToPoints(two.Stencils, points1);
    auto centroid = [](const subd::MeshTopology& t, Index f, const std::vector<double>& p, int k) {
      double sum = 0.0;
      for (Index v : t.GetFaceVertices(f))
        sum += p[3 * v + k];
      return sum / t.GetFaceSize(f);
    };
    const Index firstVFace = topology.GetNumFaces() + (name == "doo-sabin" ? topology.GetNumEdges() : 0);
    ASSERT_EQ(child.GetNumFaces(), firstVFace + topology.GetNumVertices()) << mesh.Name;
    for (Index v = 0; v < topology.GetNumVertices(); ++v, ++compared)
      for (int k = 0; k < 3; ++k)
      {
        ASSERT_NEAR(centroid(child, firstVFace + v, points1, k), limits0[3 * v + k], 1e-12) << mesh.Name << " " << v;
        ASSERT_NEAR(centroid(two.Child.Topology, firstVFace + v, points2, k), limits0[3 * v + k], 1e-12)
          << mesh.Name << " vertex " << v;
      }
  }
  EXPECT_GT(compared, 30);
}
