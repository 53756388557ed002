// Kernel tests of exact limit evaluation (SubDLimitEvaluator.h): the evaluator against the
// closed-form limit masks, against itself one level down (limit(P) == limit(subdivide(P))),
// against finite differences of its own positions, across shared edges, and the derived
// box-spline basis against the properties every box spline has.
#include "SubDLimitEvaluator.h"
#include "SubDLimitRules.h"
#include "SubDRefiner.h"
#include "SubDScheme.h"
#include "SubDSurfaceGeometry.h"
#include "SubDTestMeshes.h"
#include "SubDVertexLimit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using subd::Index;

namespace
{
// Value and derivatives (PatchDerivative order) of positions at one sample.
struct Evaluated
{
  double D[6][3];
  double C[6][3];
};

Evaluated Apply(const subd::LimitStencil& s, const std::vector<double>& points)
{
  Evaluated e;
  for (int d = 0; d < 6; ++d)
  {
    s.Apply(s.Weights, d, points.data(), 3, e.D[d]);
    s.Apply(s.CurvatureWeights.empty() ? s.Weights : s.CurvatureWeights, d, points.data(), 3, e.C[d]);
  }
  return e;
}

Evaluated EvaluateAt(const subd::LimitEvaluator& evaluator, const std::vector<double>& points, Index face,
  subd::FaceSample sample)
{
  std::vector<subd::LimitStencil> out;
  std::string error;
  EXPECT_TRUE(evaluator.EvaluateFace(face, { sample }, out, error)) << error;
  return Apply(out.at(0), points);
}

double Distance(const double a[3], const double b[3])
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

double Size(const std::vector<double>& points)
{
  double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
  for (size_t i = 0; i < points.size(); ++i)
  {
    lo[i % 3] = std::min(lo[i % 3], points[i]);
    hi[i % 3] = std::max(hi[i % 3], points[i]);
  }
  return Distance(lo, hi);
}

// A fixture with its base level (full topology) and tags.
struct Case
{
  subdtest::TestMesh Mesh;
  subd::BaseTags Tags;
  subd::BoundaryRule Rule = subd::BoundaryRule::EdgeOnly;
  subd::Level Base() const
  {
    return subd::MakeBaseLevel(
      subd::MeshTopology::Build(Mesh.NumVertices(), Mesh.Offsets, Mesh.Vertices), Tags, Rule);
  }
};

// Sharpness on the edges joining consecutive points of `chain`.
void Crease(Case& c, const std::vector<Index>& chain, float sharpness)
{
  const subd::MeshTopology topo = subd::MeshTopology::Build(c.Mesh.NumVertices(), c.Mesh.Offsets, c.Mesh.Vertices);
  c.Tags.EdgeSharpness.resize(static_cast<size_t>(topo.GetNumEdges()), 0.0f);
  c.Mesh.Name += "-crease" + std::to_string(chain.size()) + "-s" + std::to_string(sharpness).substr(0, 4);
  for (size_t i = 0; i + 1 < chain.size(); ++i)
  {
    c.Tags.EdgeSharpness[topo.FindEdge(chain[i], chain[i + 1])] = sharpness;
  }
}

std::vector<Case> QuadCases()
{
  std::vector<Case> cases;
  auto add = [&cases](subdtest::TestMesh mesh, subd::BoundaryRule rule = subd::BoundaryRule::EdgeOnly) {
    Case c;
    c.Mesh = std::move(mesh.Jitter(0.05));
    c.Rule = rule;
    cases.push_back(c);
    return &cases.back();
  };
  add(subdtest::Cube());
  add(subdtest::Grid(4, 3, false, false));
  add(subdtest::Grid(4, 3, false, false), subd::BoundaryRule::EdgeAndCorner);
  add(subdtest::Grid(6, 5, true, true));
  add(subdtest::House(false));
  add(subdtest::House(true));
  add(subdtest::Star(5));
  Crease(*add(subdtest::Cube()), { 0, 1, 2, 3, 0 }, 10.0f);      // a closed crease loop
  Crease(*add(subdtest::Cube()), { 0, 1, 2 }, 10.0f);             // a crease ending in darts
  Crease(*add(subdtest::Cube()), { 0, 1, 5, 4, 0, 3 }, 2.5f);     // semi-sharp, a corner
  Crease(*add(subdtest::Grid(4, 4, false, false)), { 6, 7, 8, 13 }, 10.0f);
  Case* chaikin = add(subdtest::Grid(6, 5, true, true));
  Crease(*chaikin, { 1, 2, 3, 4, 10 }, 1.7f);
  chaikin->Tags.Creasing = subd::CreaseMethod::Chaikin;
  chaikin->Mesh.Name += "-chaikin";
  add(subdtest::NonManifold());
  // Semi-sharp spokes all around a pole, of increasing sharpness, with Chaikin creasing.
  Case* spokes = add(subdtest::Star(8));
  for (int k = 0; k < 8; ++k)
  {
    Crease(*spokes, { 2 * k + 1, 16 }, 0.2f + 2.5f * k / 8);
  }
  spokes->Tags.Creasing = subd::CreaseMethod::Chaikin;
  return cases;
}

std::vector<Case> TriangleCases()
{
  std::vector<Case> cases;
  for (Case c : QuadCases())
  {
    Case t;
    t.Mesh = c.Mesh.Triangulated();
    t.Rule = c.Rule;
    cases.push_back(t);
  }
  cases.push_back(Case{ subdtest::Bipyramid(7), {}, subd::BoundaryRule::EdgeOnly });
  return cases;
}

// Every face-corner sample of a level.
template <typename Visit>
void ForEachCorner(const subd::Level& level, bool quads, Visit&& visit)
{
  const subd::MeshTopology& topo = level.Topology;
  for (Index f = 0; f < topo.GetNumFaces(); ++f)
  {
    for (Index k = 0; k < topo.GetFaceSize(f); ++k)
    {
      visit(f, k, subd::LimitEvaluator::CornerSample(topo.GetFaceSize(f), k, quads));
    }
  }
}

bool IsDart(const subd::Level& level, Index v)
{
  return subd::PlanVertexRule(level, v).Rule == subd::VertexRule::Dart;
}

// limit(P) at the vertices, evaluator vs the closed-form masks (one level down so that
// Catmull-Clark faces are quads and semi-sharp features have decayed a level).
void CheckCornersAgainstMasks(const subd::Scheme& scheme, const Case& c, bool quads)
{
  subd::Hierarchy h;
  subd::Refine(scheme, c.Base(), 1, h, nullptr, subd::ChildTopology::Full);
  std::vector<double> points(static_cast<size_t>(h.GetNumFinestPoints()) * 3);
  h.Evaluate(c.Mesh.Points.data(), 3, points.data());
  const subd::Level& level = h.Finest;
  subd::StencilTable masks;
  std::string error;
  ASSERT_TRUE(scheme.BuildLimitStencils(level, masks, error)) << error;
  std::vector<double> limit(points.size());
  masks.Apply(points.data(), limit.data(), 3);
  const subd::LimitEvaluator evaluator(scheme, level);
  const double tol = 1e-12 * Size(points);
  ForEachCorner(level, quads, [&](Index f, Index k, subd::FaceSample s) {
    const Index v = level.Topology.GetFaceVertices(f)[k];
    if (IsDart(level, v) || !subd::IsStableCorner(level, f, k, quads ? 4 : 3))
    {
      // The masks are only approximations there (OpenSubdiv's choices too): the smooth mask
      // at a dart, and semi-sharp features treated as sharp although they decay later.
      return;
    }
    const Evaluated e = EvaluateAt(evaluator, points, f, s);
    EXPECT_LT(Distance(e.D[0], &limit[3 * v]), tol) << c.Mesh.Name << " face " << f << " corner " << k;
  });
}

// limit(P) == limit(subdivide(P)): the sample (u, v) of a base face and the same point of its
// child agree in what does not depend on the parametrisation: position, normal, H and K.
void CheckLevelIndependence(const subd::Scheme& scheme, const Case& c, bool quads)
{
  const subd::Level base = c.Base();
  subd::Hierarchy h;
  subd::Refine(scheme, c.Base(), 1, h, nullptr, subd::ChildTopology::Full);
  std::vector<double> fine(static_cast<size_t>(h.GetNumFinestPoints()) * 3);
  h.Evaluate(c.Mesh.Points.data(), 3, fine.data());
  const subd::LimitEvaluator coarse(scheme, base), refined(scheme, h.Finest);
  const double size = Size(c.Mesh.Points);
  const double params[][2] = { { 0.3, 0.2 }, { 0.05, 0.6 }, { 0.25, 0.25 }, { 0.5, 0.1 }, { 0.01, 0.02 }, { 0.0, 0.35 } };
  for (Index f = 0; f < base.Topology.GetNumFaces(); ++f)
  {
    const Index size0 = base.Topology.GetFaceSize(f);
    const bool polygon = quads && size0 != 4;
    for (const auto& p : params)
    {
      for (Index sub = 0; sub < (polygon ? size0 : 1); ++sub)
      {
        subd::FaceSample s;
        s.U = p[0];
        s.V = p[1];
        s.SubFace = sub;
        const Evaluated a = EvaluateAt(coarse, c.Mesh.Points, f, s);
        // The same point one level down.
        Index child = subd::ChildFace(base, f, sub, !quads);
        double q[2] = { p[0], p[1] };
        if (!polygon)
        {
          for (Index j = 0; j < 4; ++j)
          {
            subd::ChildFrame(quads ? 4 : 3, j).Unmap(p, q);
            if (subd::InsideFace(quads ? 4 : 3, q, 1e-12))
            {
              child = subd::ChildFace(base, f, j, !quads);
              break;
            }
          }
        }
        subd::FaceSample t;
        t.U = q[0];
        t.V = q[1];
        const Evaluated b = EvaluateAt(refined, fine, child, t);
        EXPECT_LT(Distance(a.D[0], b.D[0]), 1e-12 * size) << c.Mesh.Name << " face " << f << " at " << p[0] << "," << p[1];
        const subd::SurfaceGeometry ga = subd::ComputeSurfaceGeometry(a.D, a.C);
        const subd::SurfaceGeometry gb = subd::ComputeSurfaceGeometry(b.D, b.C);
        ASSERT_TRUE(ga.Regular && gb.Regular) << c.Mesh.Name << " face " << f;
        EXPECT_LT(Distance(ga.Normal, gb.Normal), 1e-9) << c.Mesh.Name << " face " << f << " at " << p[0] << "," << p[1];
        EXPECT_NEAR(ga.Mean, gb.Mean, 1e-7 * (1 + std::abs(ga.Mean))) << c.Mesh.Name << " face " << f;
        EXPECT_NEAR(ga.Gaussian, gb.Gaussian, 1e-7 * (1 + std::abs(ga.Gaussian))) << c.Mesh.Name << " face " << f;
      }
    }
  }
}
}

TEST(LimitEvaluator, CatmullClarkCornersMatchLimitMasks)
{
  const subd::CatmullClarkScheme scheme;
  for (const Case& c : QuadCases())
  {
    CheckCornersAgainstMasks(scheme, c, true);
  }
}

TEST(LimitEvaluator, LoopCornersMatchLimitMasks)
{
  const subd::LoopScheme scheme;
  for (const Case& c : TriangleCases())
  {
    CheckCornersAgainstMasks(scheme, c, false);
  }
}

TEST(LimitEvaluator, CatmullClarkLevelIndependence)
{
  const subd::CatmullClarkScheme scheme;
  for (const Case& c : QuadCases())
  {
    CheckLevelIndependence(scheme, c, true);
  }
}

TEST(LimitEvaluator, LoopLevelIndependence)
{
  const subd::LoopScheme scheme;
  for (const Case& c : TriangleCases())
  {
    CheckLevelIndependence(scheme, c, false);
  }
}

TEST(LimitEvaluator, BoxSplineBasisReproducesLinearFunctions)
{
  // Any box spline sums to one and reproduces the linear functions on its lattice: with
  // control values equal to the lattice coordinates the patch is the identity (u, v).
  const auto& lattice = subd::BoxSplineLattice();
  for (double u : { 0.0, 0.2, 0.5, 1.0 })
  {
    for (double v : { 0.0, 0.3, 0.5 })
    {
      if (u + v > 1.0)
        continue;
      double w[subd::NumPatchDerivatives][16];
      subd::EvaluatePatchBasis(subd::PatchKind::BoxSpline, u, v, w);
      double sum[6] = {}, a[6] = {}, b[6] = {};
      for (int i = 0; i < 12; ++i)
      {
        for (int d = 0; d < 6; ++d)
        {
          sum[d] += w[d][i];
          a[d] += w[d][i] * lattice[i][0];
          b[d] += w[d][i] * lattice[i][1];
        }
      }
      EXPECT_NEAR(sum[0], 1.0, 1e-13);
      EXPECT_NEAR(a[0], u, 1e-13);
      EXPECT_NEAR(b[0], v, 1e-13);
      EXPECT_NEAR(a[1], 1.0, 1e-12);
      EXPECT_NEAR(b[2], 1.0, 1e-12);
      for (int d = 1; d < 6; ++d)
      {
        EXPECT_NEAR(sum[d], 0.0, 1e-12);
      }
      EXPECT_NEAR(a[2], 0.0, 1e-12);
      EXPECT_NEAR(b[1], 0.0, 1e-12);
    }
  }
}

namespace
{
// Derivatives against central differences of the evaluator's own positions and first
// derivatives, at samples inside faces (irregular ones included).
void CheckAgainstFiniteDifferences(const subd::Scheme& scheme, const Case& c, bool quads)
{
  const subd::Level base = c.Base();
  const subd::LimitEvaluator evaluator(scheme, base);
  const double params[][2] = { { 0.3, 0.2 }, { 0.12, 0.61 }, { 0.05, 0.07 } };
  const double h = 1e-5;
  double worst1 = 0.0, worst2 = 0.0;
  for (Index f = 0; f < base.Topology.GetNumFaces(); ++f)
  {
    if (base.Topology.GetFaceSize(f) != (quads ? 4 : 3))
    {
      continue;
    }
    for (const auto& p : params)
    {
      auto at = [&](double du, double dv) {
        subd::FaceSample s;
        s.U = p[0] + du;
        s.V = p[1] + dv;
        return EvaluateAt(evaluator, c.Mesh.Points, f, s);
      };
      const Evaluated e = at(0, 0), up = at(h, 0), um = at(-h, 0), vp = at(0, h), vm = at(0, -h);
      for (int x = 0; x < 3; ++x)
      {
        const double du = (up.D[0][x] - um.D[0][x]) / (2 * h), dv = (vp.D[0][x] - vm.D[0][x]) / (2 * h);
        const double duu = (up.D[1][x] - um.D[1][x]) / (2 * h), duv = (vp.D[1][x] - vm.D[1][x]) / (2 * h);
        const double dvv = (vp.D[2][x] - vm.D[2][x]) / (2 * h);
        worst1 = std::max({ worst1, std::abs(du - e.D[1][x]), std::abs(dv - e.D[2][x]) });
        worst2 = std::max({ worst2, std::abs(duu - e.D[3][x]), std::abs(duv - e.D[4][x]), std::abs(dvv - e.D[5][x]) });
      }
    }
  }
  const double size = Size(c.Mesh.Points);
  EXPECT_LT(worst1, 1e-6 * size) << c.Mesh.Name;
  EXPECT_LT(worst2, 1e-5 * size) << c.Mesh.Name;
}
}

TEST(LimitEvaluator, CatmullClarkDerivativesMatchFiniteDifferences)
{
  const subd::CatmullClarkScheme scheme;
  for (const Case& c : QuadCases())
  {
    CheckAgainstFiniteDifferences(scheme, c, true);
  }
}

TEST(LimitEvaluator, LoopDerivativesMatchFiniteDifferences)
{
  const subd::LoopScheme scheme;
  for (const Case& c : TriangleCases())
  {
    CheckAgainstFiniteDifferences(scheme, c, false);
  }
}
