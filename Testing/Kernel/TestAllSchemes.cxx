// Property tests over every scheme x its fixtures, two levels: every stencil row sums to one,
// refinement commutes with affine maps, planar input stays planar, and the refined mesh of a
// closed manifold is a closed manifold with the same Euler characteristic.
#include "SubDButterflyRules.h"
#include "SubDGrandchildRows.h"
#include "SubDMemoryEstimate.h"
#include "SubDMidpointGrandchild.h"
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

// Without faces-only origins (Scheme::SetFacesOnlyOrigins), the same finest faces and hole
// flags: sqrt(3) and Doo-Sabin keep no origin then, and no hole flag where the parent has no
// hole; the other schemes keep theirs (the option is a hint).
TEST_P(AllSchemes, FacesOnlyWithoutOriginsGivesTheSameFacesAndHoles)
{
  const std::string name = GetParam().Name;
  const bool spares = name == "sqrt3" || name == "doo-sabin";
  int withHoles = 0;
  for (const subdtest::TestMesh& mesh : Fixtures())
  {
    for (bool hole : { false, true })
    {
      const auto scheme = GetParam().Make();
      const subd::MeshTopology topology = subd::MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices);
      subd::BaseTags tags;
      if (hole)
        tags.FaceIsHole.assign(static_cast<size_t>(topology.GetNumFaces()), 0), tags.FaceIsHole[0] = 1;
      const subd::Level base =
        subd::MakeBaseLevel(topology, tags, scheme->EffectiveBoundaryRule(subd::BoundaryRule::EdgeOnly));
      subd::Hierarchy kept, spared;
      subd::Refine(*scheme, base, 2, kept);
      scheme->SetFacesOnlyOrigins(false);
      subd::Refine(*scheme, base, 2, spared);
      kept.MakeFinestFaces();
      spared.MakeFinestFaces();
      const subd::MeshTopology &a = kept.Finest.Topology, &b = spared.Finest.Topology;
      ASSERT_EQ(a.GetFaceOffsetArray(), b.GetFaceOffsetArray()) << mesh.Name;
      ASSERT_EQ(a.GetFaceVertexArray(), b.GetFaceVertexArray()) << mesh.Name;
      bool anyHole = false;
      for (Index f = 0; f < a.GetNumFaces(); ++f)
      {
        ASSERT_EQ(kept.Finest.IsFaceHole(f), spared.Finest.IsFaceHole(f)) << mesh.Name << " face " << f;
        anyHole |= kept.Finest.IsFaceHole(f);
      }
      EXPECT_EQ(spared.Finest.FaceOrigin.empty(), spares) << mesh.Name;
      EXPECT_EQ(spared.Finest.FaceIsHole.empty(), spares && !anyHole) << mesh.Name;
      EXPECT_FALSE(kept.Finest.FaceOrigin.empty()) << mesh.Name;
      withHoles += anyHole;
    }
  }
  EXPECT_GT(withHoles, 0);
}

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

// Every level's rows written as they are applied (LevelRows::Written, what the filters use,
// and WrittenFromGrandparent, what they use with LowMemory, at levels 2 and 4 from their
// grandparents, the finest faces then made after the points) give bit for bit the points,
// faces, holes and origins the stored table gives, with semi-sharp and sharp creases and
// corners under both crease methods and with no sharp feature, for 3 double, 3 float and 5
// float components.
namespace
{
// The schemes with rows of their own written from the grandparent (SubDGrandchildRows.h):
// the butterfly only without tension.
bool WritesRowsTwoLevelsDown(const std::string& name)
{
  return name == "catmull-clark" || name == "loop" || name == "butterfly";
}
}

TEST_P(AllSchemes, WrittenLevelRowsEqualStoredRows)
{
  const auto scheme = GetParam().Make();
  const subd::BoundaryRule rule = scheme->EffectiveBoundaryRule(subd::BoundaryRule::EdgeOnly);
  // The creases' methods, and no sharp feature at all (where Catmull-Clark and Loop, with
  // WrittenFromGrandparent or WrittenLean, skip the finest level's parent on closed meshes:
  // EveryGrandchildRowIsSmooth).
  int leanHierarchies = 0, releasedVertexFaceLists = 0, releasedVertexEdgeLists = 0, midpointClosedForms = 0;
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
        subd::Hierarchy stored;
        subd::Refine(*scheme, subd::MakeBaseLevel(topology, tags, rule), levels, stored);
        for (int variant = 0; variant < 4; ++variant)
        {
          // Written rows; written from the grandparent every other level (with the finest
          // level faces only, and with its full topology); written, the finest level from its
          // grandparent where no row needs its parent (WrittenLean).
          const subd::LevelRows rows = variant == 0 ? subd::LevelRows::Written
            : variant == 3                          ? subd::LevelRows::WrittenLean
                                                    : subd::LevelRows::WrittenFromGrandparent;
          const subd::ChildTopology finest = variant == 2 ? subd::ChildTopology::Full : subd::ChildTopology::FacesOnly;
          subd::Hierarchy written;
          subd::Refine(*scheme, subd::MakeBaseLevel(topology, tags, rule), levels, written, nullptr, finest, rows);
          const bool writes = scheme->MakeRowSource(std::make_shared<subd::Level>()) != nullptr;
          for (const subd::StencilTable& table : written.Stencils)
            EXPECT_EQ(table.IsStored(), !writes);
          ASSERT_EQ(written.GetNumFinestPoints(), stored.GetNumFinestPoints());
          // A faces-only finest level written from its grandparent gets its faces when
          // asked, after the points (which need none of them). The linear schemes write it
          // so with any written rows, without building its parent.
          const std::string name = GetParam().Name;
          const bool linear = name == "linear-triangles" || name == "bilinear";
          const bool lean = subd::HasFinestRowsToPromote(*scheme, written);
          // The midpoint scheme's finest level comes from a closed smooth grandparent in
          // closed form with the leaner modes (SubDMidpointGrandchild.h).
          bool midpointClosedForm = false;
          if (name == "midpoint" && levels >= 2 && variant != 0 && variant != 2)
          {
            subd::Hierarchy above;
            subd::Refine(*scheme, subd::MakeBaseLevel(topology, tags, rule), levels - 2, above, nullptr,
              subd::ChildTopology::Full);
            midpointClosedForm = subd::MidpointGrandchildHasClosedForm(above.Finest);
            midpointClosedForms += midpointClosedForm;
          }
          const bool fromGrandparent = levels >= 2 && variant != 2 &&
            (linear || (variant == 1 && WritesRowsTwoLevelsDown(name)) || lean || midpointClosedForm);
          EXPECT_TRUE(!lean || variant != 0) << mesh.Name << " L" << levels;
          leanHierarchies += lean && variant == 3;
          EXPECT_EQ(written.HasFinestFaces(), !fromGrandparent) << mesh.Name << " L" << levels;
          EXPECT_EQ(written.GetNumFinestFaces(), stored.GetNumFinestFaces()) << mesh.Name << " L" << levels;
          EXPECT_EQ(Evaluate(written, mesh.Points), Evaluate(stored, mesh.Points)) << mesh.Name << " L" << levels;
          std::vector<float> a(static_cast<size_t>(stored.GetNumFinestPoints()) * 5), b(a.size());
          stored.Evaluate(values.data(), 5, a.data());
          written.Evaluate(values.data(), 5, b.data());
          EXPECT_EQ(a, b) << mesh.Name << " L" << levels;
          // Three float components: points in single precision (the rows' prefetching path).
          std::vector<float> c(static_cast<size_t>(stored.GetNumFinestPoints()) * 3), d(c.size());
          stored.Evaluate(values.data(), 3, c.data());
          written.Evaluate(values.data(), 3, d.data());
          EXPECT_EQ(c, d) << mesh.Name << " L" << levels;
          const auto* rowsTwoDown = dynamic_cast<const subd::GrandchildRows*>(written.Stencils.back().GetSource());
          if (rowsTwoDown && !linear) // the linear rules' levels between never have them
          {
            // The butterfly's grandparent level has no lists of edges around its vertices
            // once its grandchild's rows are made: its own rows (evaluated above, crease rows
            // included) and its grandchild's read none.
            const bool released = !rowsTwoDown->GetGrandparent().Topology.HasVertexRelations();
            EXPECT_EQ(released, name == "butterfly") << mesh.Name << " L" << levels;
            releasedVertexEdgeLists += released;
          }
          if (lean)
          {
            // Loop's rows read the grandparent's vertex rings through its edges, the butterfly's
            // order them through edges' faces: the lists of faces around its vertices are
            // freed where the parent was skipped, and restored for the promotion's split
            // (below, which must give the same values).
            const auto* grandchildRows = dynamic_cast<const subd::GrandchildRows*>(written.Stencils.back().GetSource());
            ASSERT_NE(grandchildRows, nullptr);
            const bool released = !grandchildRows->GetGrandparent().Topology.HasVertexFaceLists();
            EXPECT_TRUE(!released || name == "loop" || name == "butterfly") << mesh.Name << " L" << levels;
            releasedVertexFaceLists += released;
            // The same rows from the parent's lists, built now (what the filters do when
            // they re-apply them).
            EXPECT_TRUE(subd::PromoteFinestRows(*scheme, written));
            EXPECT_FALSE(subd::HasFinestRowsToPromote(*scheme, written));
            EXPECT_FALSE(subd::PromoteFinestRows(*scheme, written));
            std::vector<float> promoted(c.size());
            written.Evaluate(values.data(), 3, promoted.data());
            EXPECT_EQ(c, promoted) << mesh.Name << " L" << levels;
          }
          written.MakeFinestFaces();
          EXPECT_TRUE(written.HasFinestFaces());
          ASSERT_EQ(written.Finest.Topology.GetFaceVertexArray(), stored.Finest.Topology.GetFaceVertexArray());
          EXPECT_EQ(written.Finest.Topology.GetNumVertices(), stored.Finest.Topology.GetNumVertices());
          EXPECT_EQ(subdtest::FaceTags(written.Finest), subdtest::FaceTags(stored.Finest)) << mesh.Name << " L" << levels;
          if (finest == subd::ChildTopology::Full)
          {
            subd::Hierarchy storedFull;
            subd::Refine(*scheme, subd::MakeBaseLevel(topology, tags, rule), levels, storedFull, nullptr, finest);
            EXPECT_EQ(written.Finest.Topology.GetNumEdges(), storedFull.Finest.Topology.GetNumEdges()) << mesh.Name;
            EXPECT_EQ(written.Finest.EdgeSharpness, storedFull.Finest.EdgeSharpness) << mesh.Name << " L" << levels;
            EXPECT_EQ(written.Finest.VertexSharpness, storedFull.Finest.VertexSharpness) << mesh.Name << " L" << levels;
          }
        }
      }
    }
  }
  // WrittenLean wrote the finest rows of some closed meshes without their parent.
  const std::string name = GetParam().Name;
  EXPECT_EQ(leanHierarchies > 0, WritesRowsTwoLevelsDown(name)) << leanHierarchies;
  EXPECT_EQ(releasedVertexEdgeLists > 0, name == "butterfly") << releasedVertexEdgeLists;
  EXPECT_EQ(releasedVertexFaceLists > 0, name == "loop" || name == "butterfly") << releasedVertexFaceLists;
  EXPECT_EQ(midpointClosedForms > 0, name == "midpoint") << midpointClosedForms;
}

// The size guard's prediction (SubDMemoryEstimate.h) covers what a refinement holds once its
// points are evaluated (every level it keeps, the finest faces, the points and the scratch
// levels: the default path's peak), measured as the heap in use, and is not far above it for
// the schemes that write their rows; LowMemory's is lower from level 2 on, where it applies.
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
    hierarchy.MakeFinestFaces();
    std::vector<double> finest(static_cast<size_t>(hierarchy.GetNumFinestPoints()) * 3);
    subd::EvaluationScratch<double> scratch;
    hierarchy.Evaluate(mesh.Points.data(), 3, finest.data(), subd::SerialFor, nullptr, -1, &scratch);
    held = static_cast<double>(subdtest::HeapInUse() - before);
  }
  EXPECT_GT(held, 1.0e6); // a measurement, not noise
  EXPECT_LE(held, predicted) << GetParam().Name;
  // Not a bound far above, for the schemes whose written rows keep their levels whole (those
  // that keep a part of each level, Doo-Sabin and midpoint, peak while a level is split,
  // which is over when this is measured).
  const bool writesRows = scheme->MakeRowSource(std::make_shared<subd::Level>()) != nullptr;
  subd::MeshTopology::Part part;
  if (writesRows && !scheme->WrittenRowsReadOnly(part))
  {
    EXPECT_GE(held, 0.5 * predicted) << GetParam().Name;
  }
  subd::RefinementRequest lean = request;
  lean.Rows = subd::LevelRows::WrittenFromGrandparent;
  if (scheme->RefinesFromGrandparent() && !scheme->RefinesFromGrandparentAlone())
  {
    EXPECT_LT(subd::EstimatePeakBytes(*scheme, lean) - subd::EstimateLibraryBytes, 0.8 * predicted);
  }
  lean.Levels = request.Levels = 1; // no grandparent: the same path
  EXPECT_EQ(subd::EstimatePeakBytes(*scheme, lean), subd::EstimatePeakBytes(*scheme, request));
}
#endif

// The finest level's rows written from its grandparent (the level between is not kept) are
// the rows the level between writes, entry for entry and bit for bit, in the same blocks;
// applied in small chunks on threads they give the stored table's values; and the faces two
// splits down equal those of splitting twice. Catmull-Clark over meshes with n-gons, Loop
// over triangle meshes, with boundaries, non-manifold edges and pinched fans, semi-sharp and
// sharp creases, a sharp vertex, holes, under both crease methods, from the base level and
// from one level down.
namespace
{
// `rows` are `expected`'s, entry for entry and bit for bit, in the same blocks, and applied
// in small chunks on threads to `components` values they give the table's values.
void ExpectSameRows(
  const subd::GrandchildRows& rows, const subd::StencilTable& expected, int components, const std::string& what)
{
  const subd::StencilTable written = rows.ToStencilTable();
  ASSERT_EQ(written.GetNumRows(), expected.GetNumRows()) << what;
  ASSERT_EQ(written.GetNumBlocks(), expected.GetNumBlocks()) << what;
  for (subd::Index b = 0; b < expected.GetNumBlocks(); ++b)
    EXPECT_EQ(written.GetBlockEnd(b), expected.GetBlockEnd(b)) << what;
  for (subd::Index row = 0; row < expected.GetNumRows(); ++row)
  {
    const subd::IndexSpan a = written.GetSources(row), b = expected.GetSources(row);
    ASSERT_EQ(std::vector<subd::Index>(a.begin(), a.end()), std::vector<subd::Index>(b.begin(), b.end()))
      << what << " row " << row;
    for (subd::Index k = 0; k < a.size(); ++k)
      ASSERT_EQ(written.GetWeights(row)[k], expected.GetWeights(row)[k]) << what << " row " << row;
  }
  std::vector<float> parents(static_cast<size_t>(rows.GetNumParents()) * components);
  for (size_t i = 0; i < parents.size(); ++i)
    parents[i] = static_cast<float>(std::cos(0.3 * i));
  std::vector<float> fromTable(static_cast<size_t>(rows.GetNumRows()) * components), chunked(fromTable.size());
  expected.Apply(parents.data(), fromTable.data(), components);
  const std::vector<subd::Index> ends = rows.GetBlockEnds();
  for (size_t b = 0; b < ends.size(); ++b)
    subdtest::ThreeThreadFor(b == 0 ? 0 : ends[b - 1], ends[b], [&](subd::Index begin, subd::Index end) {
      rows.ApplyRows(parents.data(), chunked.data(), components, begin, end);
    });
  EXPECT_EQ(chunked, fromTable) << what;
}

void ExpectGrandchildRowsEqualTheParentsRows(subd::GrandchildScheme which, const subd::Scheme& scheme,
  const std::vector<subdtest::TestMesh>& meshes)
{
  subd::Index storedRows = 0, writtenRows = 0;
  subd::Index withoutParent = 0; // grandparents whose rows were also written without the parent
  subd::Index sharedTables = 0; // grandparents whose butterfly rows shared their tables
  int tagShifts = 0; // the FaceTagShifts SplitTwice gave, as bits
  for (int creases = 0; creases < 3; ++creases) // two crease methods, then no sharp feature
  {
    const subd::CreaseMethod method = creases == 1 ? subd::CreaseMethod::Chaikin : subd::CreaseMethod::Uniform;
    for (subd::BoundaryRule rule : { subd::BoundaryRule::EdgeOnly, subd::BoundaryRule::None })
    {
      for (const subdtest::TestMesh& mesh : meshes)
      {
        const subd::MeshTopology topology = subd::MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices);
        const subd::BaseTags tags = creases == 2 ? subd::BaseTags() : subdtest::MixedSharpnessTags(topology, method);
        auto grandparent = std::make_shared<subd::Level>(subd::MakeBaseLevel(topology, tags, rule));
        for (int depth = 0; depth < 2; ++depth)
        {
          const std::string what = mesh.Name + " depth " + std::to_string(depth);
          const subd::Level parent = scheme.Split(*grandparent, subd::ChildTopology::Full);
          const subd::GrandchildRows rows(which, grandparent, parent, subdtest::ThreeThreadFor);
          EXPECT_EQ(rows.GetNumParents(), parent.Topology.GetNumVertices()) << what; // counted from the grandparent
          const subd::StencilTable expected = scheme.BuildStencils(parent);
          ExpectSameRows(rows, expected, 5, what);
          // Given the grandparent's own rows, the same rows; the butterfly's share the
          // triangles across the grandparent's edges with them.
          const std::shared_ptr<const subd::RowSource> grandparentRows = scheme.MakeRowSource(grandparent);
          ASSERT_TRUE(grandparentRows) << what;
          const subd::GrandchildRows sharing(which, grandparent, parent, subdtest::ThreeThreadFor, grandparentRows.get());
          ExpectSameRows(sharing, expected, 3, what + " sharing");
          if (const auto* butterfly =
                dynamic_cast<const subd::WrittenRows<subd::ButterflyRowWriter>*>(grandparentRows.get()))
          {
            EXPECT_EQ(butterfly->GetWriter().GetFaceAcross().use_count(), 2) << what;
            ++sharedTables;
          }
          storedRows += rows.GetNumStoredRows();
          writtenRows += rows.GetNumRows() - rows.GetNumStoredRows();
          // Where no row needs the parent, the rows made without it are the same rows.
          if (subd::EveryGrandchildRowIsSmooth(which, *grandparent))
          {
            EXPECT_EQ(rows.GetNumStoredRows(), 0) << what;
            const subd::GrandchildRows alone(which, grandparent, subdtest::ThreeThreadFor);
            ExpectSameRows(alone, expected, 3, what + " without the parent"); // 3: the prefetching path
            ++withoutParent;
          }

          const subd::Level twice =
            subd::SplitTwice(which, *grandparent, rows.GetParentEdgeNumbering(), subdtest::ThreeThreadFor);
          const subd::Level stepwise = scheme.Split(parent, subd::ChildTopology::FacesOnly);
          EXPECT_EQ(twice.Topology.GetNumVertices(), stepwise.Topology.GetNumVertices()) << what;
          EXPECT_EQ(twice.Topology.GetFaceOffsetArray(), stepwise.Topology.GetFaceOffsetArray()) << what;
          EXPECT_EQ(twice.Topology.GetFaceVertexArray(), stepwise.Topology.GetFaceVertexArray()) << what;
          EXPECT_EQ(subdtest::FaceTags(twice), subdtest::FaceTags(stepwise)) << what;
          // Kept per face of the level between, or of the grandparent (four children each); a
          // faces-only split of a level with a tag per face keeps the parent's (four each).
          EXPECT_EQ(twice.FaceOrigin.size() << twice.FaceTagShift, stepwise.FaceOrigin.size() << stepwise.FaceTagShift)
            << what;
          if (!subd::IsQuadSplit(which) && parent.FaceTagShift == 0)
          {
            EXPECT_EQ(stepwise.FaceTagShift, 2) << what;
          }
          EXPECT_TRUE(twice.FaceTagShift == 2 || twice.FaceTagShift == 4) << what;
          tagShifts |= 1 << twice.FaceTagShift;
          EXPECT_EQ(twice.Depth, stepwise.Depth) << what;
          grandparent = std::make_shared<subd::Level>(parent);
        }
      }
    }
  }
  // Triangles always have four children; quads split from n-gons do not (one per corner).
  EXPECT_EQ(tagShifts, subd::IsQuadSplit(which) ? (1 << 2) | (1 << 4) : 1 << 4);
  if (subd::WritesEveryRowFromGrandparent(which))
  {
    EXPECT_EQ(storedRows, 0); // the linear rules need no parent
    EXPECT_GT(writtenRows, 0);
    return;
  }
  // Both kinds of rows were compared: written from the grandparent, and stored; and rows
  // written without the parent, on the closed meshes without sharp features.
  EXPECT_GT(storedRows, 0);
  EXPECT_GT(writtenRows, 2 * storedRows);
  EXPECT_GT(withoutParent, 0);
  EXPECT_EQ(sharedTables > 0, which == subd::GrandchildScheme::Butterfly);
}
}

TEST(GrandchildRows, CatmullClarkEqualsTheParentsRows)
{
  ExpectGrandchildRowsEqualTheParentsRows(
    subd::GrandchildScheme::CatmullClark, subd::CatmullClarkScheme(), subdtest::StandardMeshes());
}

TEST(GrandchildRows, LoopEqualsTheParentsRows)
{
  ExpectGrandchildRowsEqualTheParentsRows(subd::GrandchildScheme::Loop, subd::LoopScheme(), subdtest::TriangleMeshes());
}

// The butterfly without tension: the 8-point butterfly from two rings of the grandparent's
// triangles, Zorin's stencils from its extraordinary vertices' ordered fans; on the tiny
// closed meshes some butterflies meet a point twice (merged as the writer merges them).
TEST(GrandchildRows, ButterflyEqualsTheParentsRows)
{
  ExpectGrandchildRowsEqualTheParentsRows(
    subd::GrandchildScheme::Butterfly, subd::ButterflyScheme(0.0), subdtest::TriangleMeshes());
}

// The linear rules (centroids, midpoints, copies), written from the grandparent alone.
TEST(GrandchildRows, BilinearEqualsTheParentsRows)
{
  ExpectGrandchildRowsEqualTheParentsRows(
    subd::GrandchildScheme::Bilinear, subd::BilinearScheme(), subdtest::StandardMeshes());
}

TEST(GrandchildRows, LinearTrianglesEqualsTheParentsRows)
{
  ExpectGrandchildRowsEqualTheParentsRows(
    subd::GrandchildScheme::LinearTriangles, subd::LinearTriangleScheme(), subdtest::TriangleMeshes());
}

// The finest faces' tags are kept per grandparent face only where every grandparent face has
// four children: not when only the last face has more (a quad, then a pentagon; found by the
// filters' fuzzer: the tags were read past their end).
TEST(GrandchildRows, FaceTagsPerGrandparentFaceOnlyWithFourChildrenEach)
{
  subdtest::TestMesh mesh;
  mesh.Name = "quad-pentagon";
  const double p[7][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 2, 0, 0 }, { 2.5, 0.5, 0 }, { 2, 1, 0 } };
  for (auto& q : p)
    mesh.AddPoint(q[0], q[1], q[2]);
  mesh.AddFace({ 0, 1, 2, 3 });
  mesh.AddFace({ 1, 4, 5, 6, 2 });
  const subd::MeshTopology topology = subd::MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices);
  auto grandparent = std::make_shared<subd::Level>(subd::MakeBaseLevel(topology, {}, subd::BoundaryRule::EdgeOnly));
  const subd::CatmullClarkScheme scheme;
  const subd::Level parent = scheme.Split(*grandparent, subd::ChildTopology::Full);
  const subd::GrandchildRows rows(subd::GrandchildScheme::CatmullClark, grandparent, parent);
  const subd::Level twice = subd::SplitTwice(subd::GrandchildScheme::CatmullClark, *grandparent, rows.GetParentEdgeNumbering());
  const subd::Level stepwise = scheme.Split(parent, subd::ChildTopology::FacesOnly);
  EXPECT_EQ(twice.FaceTagShift, 2);
  EXPECT_EQ(subdtest::FaceTags(twice), subdtest::FaceTags(stepwise));
}

// Which grandparents need no parent for their grandchildren's rows: closed meshes without
// sharp features (any rule); with a boundary, one semi-sharp edge or one sharp vertex, only
// the linear rules (which have no rule for them); with a sharp vertex, the butterfly too.
TEST(GrandchildRows, EveryRowSmoothOnlyOnClosedMeshesWithoutSharpFeatures)
{
  auto level = [](const subdtest::TestMesh& mesh, int sharpEdge, int sharpVertex) {
    const subd::MeshTopology topology = subd::MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices);
    subd::BaseTags tags;
    if (sharpEdge >= 0)
    {
      tags.EdgeSharpness.assign(static_cast<size_t>(topology.GetNumEdges()), 0.0f);
      tags.EdgeSharpness[static_cast<size_t>(sharpEdge)] = 0.5f;
    }
    if (sharpVertex >= 0)
    {
      tags.VertexSharpness.assign(static_cast<size_t>(topology.GetNumVertices()), 0.0f);
      tags.VertexSharpness[static_cast<size_t>(sharpVertex)] = 2.0f;
    }
    return subd::MakeBaseLevel(topology, tags, subd::BoundaryRule::EdgeOnly);
  };
  using subd::EveryGrandchildRowIsSmooth;
  using subd::GrandchildScheme;
  const subdtest::TestMesh cube = subdtest::Cube(), bipyramid = subdtest::Bipyramid(5), house = subdtest::House(true);
  EXPECT_TRUE(EveryGrandchildRowIsSmooth(GrandchildScheme::CatmullClark, level(cube, -1, -1)));
  EXPECT_FALSE(EveryGrandchildRowIsSmooth(GrandchildScheme::CatmullClark, level(cube, 3, -1)));
  EXPECT_FALSE(EveryGrandchildRowIsSmooth(GrandchildScheme::CatmullClark, level(cube, -1, 5)));
  EXPECT_FALSE(EveryGrandchildRowIsSmooth(GrandchildScheme::CatmullClark, level(house, -1, -1)));
  EXPECT_TRUE(EveryGrandchildRowIsSmooth(GrandchildScheme::Bilinear, level(house, 2, 1)));
  EXPECT_TRUE(EveryGrandchildRowIsSmooth(GrandchildScheme::Loop, level(bipyramid, -1, -1)));
  EXPECT_FALSE(EveryGrandchildRowIsSmooth(GrandchildScheme::Loop, level(bipyramid, 0, -1)));
  EXPECT_FALSE(EveryGrandchildRowIsSmooth(GrandchildScheme::Loop, level(bipyramid, -1, 0)));
  EXPECT_TRUE(EveryGrandchildRowIsSmooth(GrandchildScheme::LinearTriangles, level(bipyramid, 0, 0)));
  // The butterfly has no vertex rule: a sharp vertex changes none of its rows.
  EXPECT_TRUE(EveryGrandchildRowIsSmooth(GrandchildScheme::Butterfly, level(bipyramid, -1, -1)));
  EXPECT_FALSE(EveryGrandchildRowIsSmooth(GrandchildScheme::Butterfly, level(bipyramid, 0, -1)));
  EXPECT_TRUE(EveryGrandchildRowIsSmooth(GrandchildScheme::Butterfly, level(bipyramid, -1, 0)));
}

// The linear schemes read faces and edges only: refined from a base of faces and edges
// (MeshTopology::BuildFacesAndEdges, what vtkSubDLinearFilter builds without sharp features),
// their faces-only finest level has the same faces and the same points, bit for bit, as from
// the full base, on every fixture (open, non-manifold edges, pinched vertices), at every
// level, with every way of writing the rows, serially and on threads.
TEST(LinearSchemes, FacesAndEdgesBaseRefinesAsTheFullBase)
{
  const std::vector<subd::LevelRows> allRows = { subd::LevelRows::Stored, subd::LevelRows::Written,
    subd::LevelRows::WrittenLean, subd::LevelRows::WrittenFromGrandparent };
  for (bool triangles : { false, true })
  {
    for (const subd::ParallelFor& parallelFor : { subd::ParallelFor(subd::SerialFor), subd::ParallelFor(subdtest::ThreeThreadFor) })
    {
      std::unique_ptr<subd::Scheme> scheme;
      if (triangles)
        scheme = std::make_unique<subd::LinearTriangleScheme>();
      else
        scheme = std::make_unique<subd::BilinearScheme>();
      scheme->SetParallelFor(parallelFor);
      for (const subdtest::TestMesh& mesh : triangles ? subdtest::TriangleMeshes() : subdtest::StandardMeshes())
      {
        const subd::IndexArray offsets(mesh.Offsets.begin(), mesh.Offsets.end());
        const subd::IndexArray vertices(mesh.Vertices.begin(), mesh.Vertices.end());
        const subd::BoundaryRule rule = scheme->EffectiveBoundaryRule(subd::BoundaryRule::EdgeOnly);
        for (int levels = 0; levels <= 3; ++levels)
        {
          for (subd::LevelRows rows : allRows)
          {
            SCOPED_TRACE(mesh.Name + " level " + std::to_string(levels) + " rows " + std::to_string(static_cast<int>(rows)));
            subd::Hierarchy full, lean;
            ASSERT_TRUE(subd::Refine(*scheme,
              subd::MakeBaseLevel(subd::MeshTopology::Build(mesh.NumVertices(), offsets, vertices, parallelFor), {}, rule),
              levels, full, nullptr, subd::ChildTopology::FacesOnly, rows));
            const subd::MeshTopology base =
              subd::MeshTopology::BuildFacesAndEdges(mesh.NumVertices(), offsets, vertices, parallelFor);
            ASSERT_FALSE(base.HasVertexRelations());
            ASSERT_TRUE(subd::Refine(
              *scheme, subd::MakeBaseLevel(base, {}, rule), levels, lean, nullptr, subd::ChildTopology::FacesOnly, rows));
            full.MakeFinestFaces();
            lean.MakeFinestFaces();
            EXPECT_EQ(lean.Finest.Topology.GetFaceOffsetArray(), full.Finest.Topology.GetFaceOffsetArray());
            EXPECT_EQ(lean.Finest.Topology.GetFaceVertexArray(), full.Finest.Topology.GetFaceVertexArray());
            ASSERT_EQ(lean.GetNumFinestPoints(), full.GetNumFinestPoints());
            std::vector<double> a(static_cast<size_t>(full.GetNumFinestPoints()) * 3), b(a.size());
            ASSERT_TRUE(full.Evaluate(mesh.Points.data(), 3, a.data(), parallelFor));
            ASSERT_TRUE(lean.Evaluate(mesh.Points.data(), 3, b.data(), parallelFor));
            EXPECT_EQ(a, b);
          }
        }
      }
    }
  }
}
