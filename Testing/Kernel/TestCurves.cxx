// Curve schemes against closed forms: the uniform cubic and quadratic B-splines (and their
// clamped / phantom-extended forms at open ends), and the 4-point scheme's interpolation and
// cubic reproduction.
#include "SubDBSplineNets.h"
#include "SubDCurveLimit.h"
#include "SubDCurveRefiner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace
{
using subd::CurveRules;
using subd::CurveScheme;
using subd::Index;
using Vec = std::array<double, 3>;

CurveRules Rules(CurveScheme scheme, double tension = 1.0 / 16.0)
{
  CurveRules rules;
  rules.Scheme = scheme;
  rules.Tension = tension;
  return rules;
}

std::vector<Vec> RandomPolygon(int n, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec> p(static_cast<size_t>(n));
  for (Vec& q : p)
    q = { u(rng), u(rng), u(rng) };
  return p;
}

// One polygon refined `levels` times: its points in order, their limit points and tangents.
struct RefinedPolygon
{
  std::vector<Vec> Points, Limit, Tangents;
};

RefinedPolygon Refine(const CurveRules& rules, const std::vector<Vec>& polygon, bool closed, int levels)
{
  const Index n = static_cast<Index>(polygon.size());
  subd::CurvePieces base;
  std::vector<Index> ids(polygon.size());
  for (Index i = 0; i < n; ++i)
    ids[i] = i;
  base.AddPiece(ids.data(), ids.data() + n, closed);
  subd::Hierarchy hierarchy;
  subd::CurvePieces finest;
  EXPECT_TRUE(subd::RefineCurves(rules, n, base, levels, hierarchy, finest));
  const Index numPoints = hierarchy.GetNumFinestPoints();
  std::vector<double> all(static_cast<size_t>(numPoints) * 3), limit(all.size());
  hierarchy.Evaluate(polygon.front().data(), 3, all.data());
  subd::CurveLimitStencils(rules, finest, numPoints).Apply(all.data(), limit.data(), 3);
  const subd::StencilTable tangentRows = subd::CurveTangentStencils(rules, finest, numPoints);
  const std::vector<double> tangents = subdtest::ApplyToPoints(tangentRows, all);
  RefinedPolygon out;
  const subd::IndexSpan piece = finest.GetPiece(0);
  for (Index k = 0; k < piece.size(); ++k)
  {
    const size_t id = static_cast<size_t>(piece[k]);
    out.Points.push_back({ all[3 * id], all[3 * id + 1], all[3 * id + 2] });
    out.Limit.push_back({ limit[3 * id], limit[3 * id + 1], limit[3 * id + 2] });
    out.Tangents.push_back({ tangents[3 * k], tangents[3 * k + 1], tangents[3 * k + 2] });
  }
  return out;
}

double Distance(const Vec& a, const Vec& b)
{
  return std::max({ std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2]) });
}

// sum_j P_j N(t - j) over a periodic polygon (N centred at 0), and its derivative.
template <typename Basis>
Vec PeriodicSpline(const std::vector<Vec>& P, double t, Basis basis)
{
  const int n = static_cast<int>(P.size());
  Vec c{ 0, 0, 0 };
  for (int j = -2 * n; j < 3 * n; ++j)
  {
    const double w = basis(t - j);
    for (int d = 0; d < 3; ++d)
      c[d] += w * P[static_cast<size_t>(((j % n) + n) % n)][d];
  }
  return c;
}

double CubicBSplineDerivative(double t)
{
  const double a = std::abs(t), s = t < 0 ? -1.0 : 1.0;
  if (a < 1)
    return s * (-2 * a + 1.5 * a * a);
  if (a < 2)
    return -s * 0.5 * (2 - a) * (2 - a);
  return 0;
}

// The parameter of point m of a closed Chaikin polygon after k levels: the centre of its
// quadratic basis function (each level moves the centres by a quarter of the spacing).
double ChaikinCentre(int m, int k)
{
  const double h = std::ldexp(1.0, -k);
  return m * h + 0.5 * (1.0 - h);
}

TEST(CurveCubicBSpline, LimitMaskGivesTheCubicBSplineAtEveryLevel)
{
  const std::vector<Vec> P = RandomPolygon(7, 11);
  for (int k = 0; k <= 6; ++k)
  {
    const RefinedPolygon r = Refine(Rules(CurveScheme::CubicBSpline), P, true, k);
    ASSERT_EQ(r.Points.size(), P.size() << k);
    double worst = 0.0, worstTangent = 0.0;
    for (size_t i = 0; i < r.Points.size(); ++i)
    {
      const double t = std::ldexp(static_cast<double>(i), -k);
      worst = std::max(worst, Distance(r.Limit[i], PeriodicSpline(P, t, subdtest::CubicBSpline)));
      Vec d = PeriodicSpline(P, t, CubicBSplineDerivative);
      for (double& x : d)
        x = std::ldexp(x, -k); // per unit of the level's parameter
      worstTangent = std::max(worstTangent, Distance(r.Tangents[i], d));
    }
    EXPECT_LE(worst, 1e-12) << "level " << k;
    EXPECT_LE(worstTangent, 1e-12) << "level " << k;
  }
}

// Error of the level-k polygon against the curve at its points' parameters; returns the
// ratios of successive errors.
template <typename Curve>
std::vector<double> ConvergenceRatios(CurveScheme scheme, const std::vector<Vec>& P, Curve curveAtPoint)
{
  std::vector<double> errors;
  for (int k = 2; k <= 8; ++k)
  {
    const RefinedPolygon r = Refine(Rules(scheme), P, true, k);
    double worst = 0.0;
    for (size_t i = 0; i < r.Points.size(); ++i)
      worst = std::max(worst, Distance(r.Points[i], curveAtPoint(static_cast<int>(i), k)));
    errors.push_back(worst);
  }
  std::vector<double> ratios;
  for (size_t k = 1; k < errors.size(); ++k)
    ratios.push_back(errors[k - 1] / errors[k]);
  return ratios;
}

TEST(CurveCubicBSpline, PolygonConvergesQuadratically)
{
  const std::vector<Vec> P = RandomPolygon(6, 5);
  for (double ratio : ConvergenceRatios(CurveScheme::CubicBSpline, P, [&](int i, int k) {
         return PeriodicSpline(P, std::ldexp(double(i), -k), subdtest::CubicBSpline);
       }))
    EXPECT_NEAR(ratio, 4.0, 0.3);
}

TEST(CurveChaikin, MidpointsLieOnTheQuadraticBSpline)
{
  const std::vector<Vec> P = RandomPolygon(5, 3);
  for (int k = 0; k <= 6; ++k)
  {
    const RefinedPolygon r = Refine(Rules(CurveScheme::Chaikin), P, true, k);
    ASSERT_EQ(r.Points.size(), P.size() << k);
    const size_t m = r.Points.size();
    double worst = 0.0, worstLimit = 0.0;
    for (size_t i = 0; i < m; ++i)
    {
      const Vec& a = r.Points[i];
      const Vec& b = r.Points[(i + 1) % m];
      const Vec mid{ 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2]) };
      const double knot = 0.5 * (ChaikinCentre(int(i), k) + ChaikinCentre(int(i) + 1, k));
      worst = std::max(worst, Distance(mid, PeriodicSpline(P, knot, subdtest::QuadraticBSpline)));
      worstLimit = std::max(
        worstLimit, Distance(r.Limit[i], PeriodicSpline(P, ChaikinCentre(int(i), k), subdtest::QuadraticBSpline)));
    }
    EXPECT_LE(worst, 1e-12) << "level " << k;
    EXPECT_LE(worstLimit, 1e-12) << "level " << k;
  }
}

TEST(CurveChaikin, PolygonConvergesQuadratically)
{
  const std::vector<Vec> P = RandomPolygon(6, 8);
  for (double ratio : ConvergenceRatios(CurveScheme::Chaikin, P, [&](int i, int k) {
         return PeriodicSpline(P, ChaikinCentre(i, k), subdtest::QuadraticBSpline);
       }))
    EXPECT_NEAR(ratio, 4.0, 0.3);
}

// The clamped quadratic B-spline of an open polygon (triple end knots, unit spacing), by its
// Bezier spans: span s runs from the midpoint of edge s to that of edge s + 1, except that the
// first starts at p_0 and the last ends at p_{n-1}. u in [0, n - 2].
Vec ClampedQuadratic(const std::vector<Vec>& P, double u)
{
  const int n = static_cast<int>(P.size());
  const int s = std::min(static_cast<int>(std::floor(u)), n - 3);
  const double t = u - s;
  Vec b0, b2;
  for (int d = 0; d < 3; ++d)
  {
    b0[d] = s == 0 ? P[0][d] : 0.5 * (P[s][d] + P[s + 1][d]);
    b2[d] = s == n - 3 ? P[n - 1][d] : 0.5 * (P[s + 1][d] + P[s + 2][d]);
  }
  Vec c;
  for (int d = 0; d < 3; ++d)
    c[d] = (1 - t) * (1 - t) * b0[d] + 2 * t * (1 - t) * P[s + 1][d] + t * t * b2[d];
  return c;
}

TEST(CurveChaikin, OpenEndRuleIsClampedKnotInsertion)
{
  // Every level's polygon describes the same clamped quadratic: knot insertion.
  for (int n : { 3, 4, 5, 9 })
  {
    const std::vector<Vec> P = RandomPolygon(n, 20 + n);
    for (int k = 1; k <= 4; ++k)
    {
      const RefinedPolygon r = Refine(Rules(CurveScheme::Chaikin), P, false, k);
      ASSERT_EQ(r.Points.size(), static_cast<size_t>(((n - 2) << k) + 2));
      EXPECT_EQ(Distance(r.Points.front(), P.front()), 0.0);
      EXPECT_EQ(Distance(r.Points.back(), P.back()), 0.0);
      double worst = 0.0;
      for (int s = 0; s <= 50; ++s)
      {
        const double u = (n - 2) * s / 50.0;
        worst = std::max(worst, Distance(ClampedQuadratic(P, u), ClampedQuadratic(r.Points, std::ldexp(u, k))));
      }
      EXPECT_LE(worst, 1e-12) << n << " points, level " << k;
      // A limit point is the curve at its point's Greville abscissa (t_{j+1} + t_{j+2}) / 2,
      // knots t_i = clamp(i - 2, 0, m - 2) in the level's units.
      const int m = static_cast<int>(r.Points.size());
      auto knot = [m](int i) { return static_cast<double>(std::clamp(i - 2, 0, m - 2)); };
      for (int j = 0; j < m; ++j)
      {
        const double greville = 0.5 * (knot(j + 1) + knot(j + 2));
        EXPECT_LE(Distance(r.Limit[j], ClampedQuadratic(P, std::ldexp(greville, -k))), 1e-12) << "point " << j;
      }
    }
  }
}

// The uniform cubic B-spline of the polygon extended by 2 p_0 - p_1 and 2 p_{n-1} - p_{n-2}:
// the limit of the open cubic B-spline scheme; u in [0, n - 1].
Vec ExtendedCubic(const std::vector<Vec>& P, double u)
{
  const int n = static_cast<int>(P.size());
  auto point = [&](int j) {
    if (j < 0)
      return Vec{ 2 * P[0][0] - P[1][0], 2 * P[0][1] - P[1][1], 2 * P[0][2] - P[1][2] };
    if (j >= n)
      return Vec{ 2 * P[n - 1][0] - P[n - 2][0], 2 * P[n - 1][1] - P[n - 2][1], 2 * P[n - 1][2] - P[n - 2][2] };
    return P[static_cast<size_t>(j)];
  };
  Vec c{ 0, 0, 0 };
  for (int j = -1; j <= n; ++j)
  {
    const double w = subdtest::CubicBSpline(u - j);
    const Vec p = point(j);
    for (int d = 0; d < 3; ++d)
      c[d] += w * p[d];
  }
  return c;
}

TEST(CurveCubicBSpline, OpenEndsFollowThePhantomExtendedSpline)
{
  for (int n : { 2, 3, 4, 8 })
  {
    const std::vector<Vec> P = RandomPolygon(n, 40 + n);
    for (int k = 0; k <= 4; ++k)
    {
      const RefinedPolygon r = Refine(Rules(CurveScheme::CubicBSpline), P, false, k);
      ASSERT_EQ(r.Points.size(), static_cast<size_t>(((n - 1) << k) + 1));
      double worst = 0.0;
      for (size_t i = 0; i < r.Limit.size(); ++i)
        worst = std::max(worst, Distance(r.Limit[i], ExtendedCubic(P, std::ldexp(double(i), -k))));
      EXPECT_LE(worst, 1e-12) << n << " points, level " << k;
      EXPECT_EQ(Distance(r.Limit.front(), P.front()), 0.0);
      EXPECT_EQ(Distance(r.Limit.back(), P.back()), 0.0);
    }
  }
}

TEST(CurveFourPoint, KeepsEveryOriginalPoint)
{
  for (bool closed : { true, false })
  {
    const std::vector<Vec> P = RandomPolygon(6, closed ? 1 : 2);
    for (double w : { 0.0, 0.03, 1.0 / 16.0, 0.1 })
    {
      const RefinedPolygon r = Refine(Rules(CurveScheme::FourPoint, w), P, closed, 4);
      for (size_t i = 0; i < P.size(); ++i)
      {
        EXPECT_EQ(Distance(r.Points[i << 4], P[i]), 0.0);
        EXPECT_EQ(Distance(r.Limit[i << 4], P[i]), 0.0);
      }
    }
  }
}

double Cubic(double x)
{
  return 0.3 * x * x * x - 1.2 * x * x + 0.5 * x - 2.0;
}
double CubicSlope(double x)
{
  return 0.9 * x * x - 2.4 * x + 0.5;
}

TEST(CurveFourPoint, ReproducesCubicsUpToTheEnds)
{
  // Points (x, f(x)) at integers: with w = 1/16 every refined point is on the cubic, with its
  // parameter spacing kept, and the limit tangent is (1, f'(x)) up to scale.
  for (int n : { 4, 5, 9 })
  {
    std::vector<Vec> P;
    for (int i = 0; i < n; ++i)
      P.push_back({ double(i), Cubic(i), 0.0 });
    const int k = 4;
    const RefinedPolygon r = Refine(Rules(CurveScheme::FourPoint), P, false, k);
    ASSERT_EQ(r.Points.size(), static_cast<size_t>(((n - 1) << k) + 1));
    for (size_t i = 0; i < r.Points.size(); ++i)
    {
      const double x = std::ldexp(double(i), -k);
      EXPECT_NEAR(r.Points[i][0], x, 1e-12);
      EXPECT_NEAR(r.Points[i][1], Cubic(x), 1e-12);
      const Vec& t = r.Tangents[i];
      ASSERT_GT(std::abs(t[0]), 0.0) << "point " << i;
      EXPECT_NEAR(t[1] / t[0], CubicSlope(x), 1e-9) << n << " points, point " << i;
      EXPECT_NEAR(t[0], std::ldexp(1.0, -k), 1e-12) << "tangent per unit of the level's parameter";
    }
  }
}

TEST(CurveFourPoint, ShortPolygonsReproduceLowerDegrees)
{
  // 3 points: quadratic extrapolation at both ends, so parabolas are reproduced; 2 points: the
  // segment.
  const std::vector<Vec> parabola{ { 0, 1, 0 }, { 1, -0.5, 0 }, { 2, 2, 0 } };
  auto f = [](double x) { return 1.0 + x * (-3.5 + 2.0 * x); };
  const RefinedPolygon r = Refine(Rules(CurveScheme::FourPoint), parabola, false, 3);
  ASSERT_EQ(r.Points.size(), 17u);
  for (size_t i = 0; i < r.Points.size(); ++i)
    EXPECT_NEAR(r.Points[i][1], f(r.Points[i][0]), 1e-12);
  const std::vector<Vec> segment{ { 0, 0, 0 }, { 2, 4, 6 } };
  for (CurveScheme scheme : { CurveScheme::Chaikin, CurveScheme::CubicBSpline, CurveScheme::FourPoint })
  {
    const RefinedPolygon s = Refine(Rules(scheme), segment, false, 3);
    // Chaikin: 2 -> 3 (the midpoint) -> 4 -> 6 points; the others 2^3 + 1, evenly spaced.
    const bool chaikin = scheme == CurveScheme::Chaikin;
    ASSERT_EQ(s.Points.size(), chaikin ? 6u : 9u) << subd::ToString(scheme);
    EXPECT_EQ(Distance(s.Points.front(), segment.front()), 0.0);
    EXPECT_EQ(Distance(s.Points.back(), segment.back()), 0.0);
    for (size_t i = 0; i < s.Points.size(); ++i)
    {
      const double t = s.Points[i][0] / 2;
      EXPECT_LE(Distance(s.Points[i], Vec{ 2 * t, 4 * t, 6 * t }), 1e-15);
      EXPECT_TRUE(t >= 0.0 && t <= 1.0);
      if (!chaikin)
        EXPECT_NEAR(t, i / 8.0, 1e-15);
      EXPECT_LE(Distance(s.Limit[i], Vec{ 2 * s.Limit[i][0] / 2, 4 * s.Limit[i][0] / 2, 6 * s.Limit[i][0] / 2 }), 1e-15);
      EXPECT_NEAR(s.Tangents[i][1], 2 * s.Tangents[i][0], 1e-15);
      EXPECT_GT(s.Tangents[i][0], 0.0);
    }
  }
}

TEST(CurveRules, RowsSumToOneAndCountsMatch)
{
  for (CurveScheme scheme : { CurveScheme::Chaikin, CurveScheme::CubicBSpline, CurveScheme::FourPoint })
    for (bool closed : { false, true })
      for (Index n = 1; n <= 9; ++n)
      {
        subd::StencilRows rows;
        subd::AppendCurveChildRows(Rules(scheme), n, closed, rows);
        ASSERT_EQ(rows.GetNumRows(), subd::CurveChildCount(Rules(scheme), n, closed));
        for (Index r = 0; r < rows.GetNumRows(); ++r)
        {
          double sum = 0.0;
          for (Index k = rows.Offsets[r]; k < rows.Offsets[r + 1]; ++k)
          {
            sum += rows.Weights[k];
            EXPECT_GE(rows.Sources[k], 0);
            EXPECT_LT(rows.Sources[k], n);
          }
          EXPECT_NEAR(sum, 1.0, 1e-15);
        }
      }
}

TEST(CurveRefiner, CornersCutTheCurveAndAnchorsAreShared)
{
  // Two polylines sharing point 3; point 2 is a corner of the first; a closed square with a
  // corner at 7.
  const std::vector<Index> offsets{ 0, 4, 7, 11 };
  const std::vector<Index> ids{ 0, 1, 2, 3, 3, 4, 5, 6, 7, 8, 9 };
  const std::vector<unsigned char> closed{ 0, 0, 1 };
  std::vector<unsigned char> corner(10, 0);
  corner[2] = corner[7] = 1;
  subd::CurvePieces pieces;
  std::vector<Index> firstPiece;
  subd::SplitAtCorners(subd::CurveLines{ &offsets, &ids, &closed, &corner }, pieces, firstPiece);
  ASSERT_EQ(firstPiece, (std::vector<Index>{ 0, 2, 3, 4 }));
  EXPECT_EQ(std::vector<Index>(pieces.GetPiece(0).begin(), pieces.GetPiece(0).end()), (std::vector<Index>{ 0, 1, 2 }));
  EXPECT_EQ(std::vector<Index>(pieces.GetPiece(1).begin(), pieces.GetPiece(1).end()), (std::vector<Index>{ 2, 3 }));
  EXPECT_EQ(std::vector<Index>(pieces.GetPiece(3).begin(), pieces.GetPiece(3).end()),
    (std::vector<Index>{ 7, 8, 9, 6, 7 }));
  EXPECT_FALSE(pieces.IsClosed(3));

  subd::Hierarchy hierarchy;
  subd::CurvePieces finest;
  ASSERT_TRUE(subd::RefineCurves(Rules(CurveScheme::CubicBSpline), 10, pieces, 2, hierarchy, finest));
  // Anchors: 0, 2, 3, 5 and 7, once each.
  EXPECT_EQ(finest.NumAnchors, 5);
  EXPECT_EQ(finest.GetPiece(0)[finest.GetPiece(0).size() - 1], finest.GetPiece(1)[0]);
  EXPECT_EQ(finest.GetPiece(1)[finest.GetPiece(1).size() - 1], finest.GetPiece(2)[0]);
  EXPECT_EQ(finest.GetPiece(3)[0], finest.GetPiece(3)[finest.GetPiece(3).size() - 1]);
  EXPECT_EQ(hierarchy.GetNumFinestPoints(), 5 + 7 + 3 + 7 + 15);
}
}
