// Property tests over every scheme x its fixtures, two levels: every stencil row sums to one,
// refinement commutes with affine maps, planar input stays planar, and the refined mesh of a
// closed manifold is a closed manifold with the same Euler characteristic.
#include "SubDButterflyRules.h"
#include "SubDRefiner.h"
#include "SubDScheme.h"
#include "SubDTestMeshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <memory>

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
      subd::MakeBaseLevel(subd::MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices), {},
        scheme->EffectiveBoundaryRule(subd::BoundaryRule::EdgeOnly)),
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

TEST(MidpointScheme, OpenBoundaryKeepsItsShape)
{
  const subdtest::TestMesh mesh = subdtest::Grid(4, 3, false, false).Jitter(0.1);
  const subd::MeshTopology base = subd::MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices);
  subd::MidpointScheme scheme;
  subd::Hierarchy h;
  subd::Refine(scheme, subd::MakeBaseLevel(base, {}, subd::BoundaryRule::EdgeOnly), 3, h);
  std::vector<double> out(static_cast<size_t>(h.GetNumFinestPoints()) * 3);
  h.Evaluate(mesh.Points.data(), 3, out.data());
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
      subd::Refine(scheme,
        subd::MakeBaseLevel(subd::MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices), {},
          subd::BoundaryRule::EdgeOnly),
        3, h);
      std::vector<double> out(static_cast<size_t>(h.GetNumFinestPoints()) * 3);
      h.Evaluate(mesh.Points.data(), 3, out.data());
      // Vertex points are numbered last at each level: the input points end the array.
      const size_t first = out.size() - mesh.Points.size();
      for (size_t i = 0; i < mesh.Points.size(); ++i)
        ASSERT_EQ(out[first + i], mesh.Points[i]) << mesh.Name;
    }
  }
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
