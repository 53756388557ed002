// Test helpers: uniform tensor-product B-spline surfaces of control nets whose points carry
// parameter values, for checking that a scheme's refined net of a regular grid is the
// knot-inserted net of the B-spline (both nets then evaluate to the same surface).
#ifndef SubDBSplineNets_h
#define SubDBSplineNets_h

#include "SubDScheme.h"
#include "SubDTestMeshes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace subdtest
{
/// Uniform cubic B-spline basis centred at 0 (support [-2, 2]).
inline double CubicBSpline(double t)
{
  t = std::abs(t);
  if (t < 1)
    return (4 - 6 * t * t + 3 * t * t * t) / 6;
  if (t < 2)
    return (2 - t) * (2 - t) * (2 - t) / 6;
  return 0;
}

/// Uniform quadratic B-spline basis centred at 0 (support [-1.5, 1.5]).
inline double QuadraticBSpline(double t)
{
  t = std::abs(t);
  if (t < 0.5)
    return 0.75 - t * t;
  if (t < 1.5)
    return 0.5 * (t - 1.5) * (t - 1.5);
  return 0;
}

/// An n x n open quad grid whose heights are a smooth wave, sin(a i) cos(b j) + c i j, so a
/// B-spline test sees real surface variation.
inline TestMesh WavyGrid(int n, double a, double b, double c)
{
  TestMesh mesh = Grid(n, n, false, false);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      mesh.Points[3 * (j * (n + 1) + i) + 2] = std::sin(a * i) * std::cos(b * j) + c * i * j;
  return mesh;
}

/// (i, j) parameters of the points of an (n+1) x (n+1) grid, row by row.
inline std::vector<double> GridParameters(int n)
{
  std::vector<double> param;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      param.insert(param.end(), { double(i), double(j) });
  return param;
}

/// sum_k N(scale (u - u_k)) N(scale (v - v_k)) P_k over a net with parameters (u_k, v_k).
template <typename Basis>
std::array<double, 3> EvaluateNet(Basis basis, const std::vector<double>& net,
  const std::vector<double>& param, double scale, double u, double v)
{
  std::array<double, 3> s{ 0, 0, 0 };
  for (size_t k = 0; k < param.size() / 2; ++k)
  {
    const double w = basis(scale * (u - param[2 * k])) * basis(scale * (v - param[2 * k + 1]));
    for (int c = 0; c < 3; ++c)
      s[c] += w * net[3 * k + c];
  }
  return s;
}

/// Largest coordinate difference, over samples of [lo, hi]^2, between the surface of the
/// level-0 net (scale 1) and that of a level-l net (scale 2^l).
template <typename Basis>
double MaxSurfaceDifference(Basis basis, const std::vector<double>& net0, const std::vector<double>& param0,
  const std::vector<double>& net, const std::vector<double>& param, int level, double lo, double hi)
{
  const double scale = double(1 << level);
  double worst = 0;
  for (double u = lo; u <= hi; u += 0.37)
    for (double v = lo; v <= hi; v += 0.41)
    {
      const auto a = EvaluateNet(basis, net0, param0, 1.0, u, v);
      const auto b = EvaluateNet(basis, net, param, scale, u, v);
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(a[c] - b[c]));
    }
  return worst;
}

/**
 * Refines `mesh`, a WavyGrid(n), `levels` times with `scheme`, carrying the points' (u, v)
 * parameters along: `childParameters(topology, param)` gives those of the next level's points
 * from the current level's topology and parameters. Returns, per level, how far the level's
 * net is from describing the level-0 net's B-spline surface (`basis`), over [3, n - 3]^2,
 * away from the boundary, whose rules differ from the infinite grid's.
 */
template <typename Basis, typename ChildParameters>
std::vector<double> GridBSplineDifferences(const subd::Scheme& scheme, const TestMesh& mesh, int n, int levels,
  Basis basis, ChildParameters childParameters)
{
  std::vector<double> param = GridParameters(n);
  const std::vector<double> level0Param = param;
  subd::Level level = BaseLevel(mesh);
  std::vector<double> points = mesh.Points;
  std::vector<double> differences;
  for (int l = 1; l <= levels; ++l)
  {
    std::vector<double> child = ApplyToPoints(scheme.BuildStencils(level), points);
    std::vector<double> childParam = childParameters(level.Topology, param);
    level = scheme.Split(level, subd::ChildTopology::Full);
    points.swap(child);
    param.swap(childParam);
    differences.push_back(MaxSurfaceDifference(basis, mesh.Points, level0Param, points, param, l, 3.0, n - 3.0));
  }
  return differences;
}
}

#endif
