#include "SubDPatchBasis.h"

#include "SubDLimitRules.h"
#include "SubDLocalLevel.h"
#include "SubDPatchParam.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>

namespace subd
{
namespace
{
// Cubic B-spline segment basis and its first two derivatives at t.
void CubicBSpline(double t, double b[3][4])
{
  const double s = 1.0 - t;
  b[0][0] = s * s * s / 6.0;
  b[0][1] = (3.0 * t * t * t - 6.0 * t * t + 4.0) / 6.0;
  b[0][2] = (-3.0 * t * t * t + 3.0 * t * t + 3.0 * t + 1.0) / 6.0;
  b[0][3] = t * t * t / 6.0;
  b[1][0] = -0.5 * s * s;
  b[1][1] = 1.5 * t * t - 2.0 * t;
  b[1][2] = -1.5 * t * t + t + 0.5;
  b[1][3] = 0.5 * t * t;
  b[2][0] = s;
  b[2][1] = 3.0 * t - 2.0;
  b[2][2] = -3.0 * t + 1.0;
  b[2][3] = t;
}

// The 15 quartic Bernstein exponents (i, j, k) of barycentrics (w, u, v), w = 1 - u - v.
const std::array<std::array<int, 3>, 15>& QuarticExponents()
{
  static const std::array<std::array<int, 3>, 15> exponents = [] {
    std::array<std::array<int, 3>, 15> e{};
    int n = 0;
    for (int j = 0; j <= 4; ++j)
    {
      for (int k = 0; j + k <= 4; ++k)
      {
        e[n++] = { 4 - j - k, j, k };
      }
    }
    return e;
  }();
  return exponents;
}

// Value and derivatives (PatchDerivative order) in (u, v) of the quartic Bernstein
// polynomials at (u, v).
void QuarticBernstein(double u, double v, double out[NumPatchDerivatives][15])
{
  const double b[3] = { 1.0 - u - v, u, v };
  double powers[3][5]; // b[m]^k, tabulated: this runs once per sample
  for (int m = 0; m < 3; ++m)
  {
    powers[m][0] = 1.0;
    for (int k = 1; k < 5; ++k)
    {
      powers[m][k] = powers[m][k - 1] * b[m];
    }
  }
  auto power = [&powers](int m, int e) { return e < 0 ? 0.0 : powers[m][e]; };
  auto fact = [](int n) { return n <= 1 ? 1.0 : (n == 2 ? 2.0 : (n == 3 ? 6.0 : 24.0)); };
  const auto& exps = QuarticExponents();
  for (int a = 0; a < 15; ++a)
  {
    const int* e = exps[a].data();
    const double c = 24.0 / (fact(e[0]) * fact(e[1]) * fact(e[2]));
    // Partial derivatives in the barycentrics b0, b1, b2 (as independent variables).
    auto partial = [&](int d0, int d1, int d2) {
      const int d[3] = { d0, d1, d2 };
      double value = c;
      for (int m = 0; m < 3; ++m)
      {
        double falling = 1.0;
        for (int q = 0; q < d[m]; ++q)
        {
          falling *= e[m] - q;
        }
        value *= falling * power(m, e[m] - d[m]);
      }
      return value;
    };
    // u moves b1 up and b0 down; v moves b2 up and b0 down.
    out[PatchValue][a] = partial(0, 0, 0);
    out[PatchDu][a] = partial(0, 1, 0) - partial(1, 0, 0);
    out[PatchDv][a] = partial(0, 0, 1) - partial(1, 0, 0);
    out[PatchDuu][a] = partial(0, 2, 0) - 2.0 * partial(1, 1, 0) + partial(2, 0, 0);
    out[PatchDuv][a] = partial(0, 1, 1) - partial(1, 1, 0) - partial(1, 0, 1) + partial(2, 0, 0);
    out[PatchDvv][a] = partial(0, 0, 2) - 2.0 * partial(1, 0, 1) + partial(2, 0, 0);
  }
}

// Bernstein coefficients (15 x 12) of the box-spline basis, derived from Loop's rules.
Eigen::Matrix<double, 15, 12> DeriveBoxSplineCoefficients()
{
  const auto& lattice = BoxSplineLattice();
  auto indexOf = [&lattice](int a, int b) {
    for (int i = 0; i < 12; ++i)
    {
      if (lattice[i][0] == a && lattice[i][1] == b)
      {
        return i;
      }
    }
    return -1;
  };
  // The triangles of the lattice with all corners among the 12 points and one corner on
  // the patch's triangle, the patch's triangle first.
  std::vector<Index> offsets{ 0 }, vertices{ 0, 1, 2 };
  offsets.push_back(3);
  for (int a = -2; a <= 2; ++a)
  {
    for (int b = -2; b <= 2; ++b)
    {
      const int tris[2][3][2] = { { { a, b }, { a + 1, b }, { a, b + 1 } },
        { { a + 1, b }, { a + 1, b + 1 }, { a, b + 1 } } };
      for (const auto& tri : tris)
      {
        int ids[3];
        bool inside = true, touches = false;
        for (int k = 0; k < 3; ++k)
        {
          ids[k] = indexOf(tri[k][0], tri[k][1]);
          inside = inside && ids[k] >= 0;
          touches = touches || (ids[k] >= 0 && ids[k] < 3);
        }
        if (inside && touches && !(ids[0] == 0 && ids[1] == 1 && ids[2] == 2))
        {
          vertices.insert(vertices.end(), { ids[0], ids[1], ids[2] });
          offsets.push_back(static_cast<Index>(vertices.size()));
        }
      }
    }
  }
  Level level;
  level.Topology = MeshTopology::Build(12, offsets, vertices);
  level.EdgeSharpness.assign(static_cast<size_t>(level.Topology.GetNumEdges()), SharpnessSmooth);
  level.VertexSharpness.assign(12, SharpnessSmooth);
  level.FaceIsHole.assign(static_cast<size_t>(level.Topology.GetNumFaces()), 0);
  level.FaceOrigin.assign(static_cast<size_t>(level.Topology.GetNumFaces()), 0);
  std::vector<Index> support;
  const LocalLevel root = ExtractLocalLevel(level, 0, support);
  const LoopScheme loop;

  Eigen::Matrix<double, 15, 12> values;
  Eigen::Matrix<double, 15, 15> bernstein;
  const auto& exps = QuarticExponents();
  for (int s = 0; s < 15; ++s)
  {
    // The sample (i/4, j/4): two levels down it is a corner of a grandchild.
    const double p[2] = { exps[s][1] / 4.0, exps[s][2] / 4.0 };
    double bern[NumPatchDerivatives][15];
    QuarticBernstein(p[0], p[1], bern);
    for (int a = 0; a < 15; ++a)
    {
      bernstein(s, a) = bern[PatchValue][a];
    }
    LocalLevel local = root;
    double q[2] = { p[0], p[1] };
    for (int depth = 0; depth < 2; ++depth)
    {
      const LocalLevel refined = RefineLocalLevel(loop, local);
      for (Index child = 0; child < 4; ++child)
      {
        double inner[2];
        ChildFrame(3, child).Unmap(q, inner);
        if (InsideFace(3, inner, 1e-12))
        {
          local = ExtractLocalLevel(refined, ChildFace(local.Mesh, 0, child, true));
          q[0] = inner[0];
          q[1] = inner[1];
          break;
        }
      }
    }
    Index corner = 0;
    for (Index k = 0; k < 3; ++k)
    {
      double c[2];
      CornerParam(3, k, c);
      if (std::abs(c[0] - q[0]) < 1e-9 && std::abs(c[1] - q[1]) < 1e-9)
      {
        corner = k;
      }
    }
    const StencilTable limit = BuildLoopLimitStencils(local.Mesh);
    const Index vertex = local.Mesh.Topology.GetFaceVertices(0)[corner];
    const IndexSpan sources = limit.GetSources(vertex);
    const double* weights = limit.GetWeights(vertex);
    for (int i = 0; i < 12; ++i)
    {
      double value = 0.0;
      for (Index k = 0; k < sources.size(); ++k)
      {
        value += weights[k] * local.GetWeights(sources[k])[i];
      }
      // Support point i is level point support[i].
      values(s, support[i]) = value;
    }
  }
  return bernstein.fullPivLu().solve(values);
}
}

void EvaluatePatchBasis(PatchKind kind, double u, double v, double weights[NumPatchDerivatives][16])
{
  if (kind == PatchKind::BSpline)
  {
    double bu[3][4], bv[3][4];
    CubicBSpline(u, bu);
    CubicBSpline(v, bv);
    const int orders[NumPatchDerivatives][2] = { { 0, 0 }, { 1, 0 }, { 0, 1 }, { 2, 0 }, { 1, 1 }, { 0, 2 } };
    for (int d = 0; d < NumPatchDerivatives; ++d)
    {
      for (int j = 0; j < 4; ++j)
      {
        for (int i = 0; i < 4; ++i)
        {
          weights[d][4 * j + i] = bu[orders[d][0]][i] * bv[orders[d][1]][j];
        }
      }
    }
    return;
  }
  static const Eigen::Matrix<double, 15, 12> coefficients = DeriveBoxSplineCoefficients();
  // The corners, where filters evaluate every vertex, are tabulated.
  struct CornerTable
  {
    double Weights[3][NumPatchDerivatives][16];
  };
  static const CornerTable corners = [] {
    CornerTable table{};
    const double at[3][2] = { { 0, 0 }, { 1, 0 }, { 0, 1 } };
    for (int c = 0; c < 3; ++c)
    {
      double bern[NumPatchDerivatives][15];
      QuarticBernstein(at[c][0], at[c][1], bern);
      for (int d = 0; d < NumPatchDerivatives; ++d)
        for (int i = 0; i < 12; ++i)
        {
          double sum = 0.0;
          for (int a = 0; a < 15; ++a)
            sum += bern[d][a] * coefficients(a, i);
          table.Weights[c][d][i] = sum;
        }
    }
    return table;
  }();
  const int corner = (u == 0.0 && v == 0.0) ? 0 : (u == 1.0 && v == 0.0) ? 1 : (u == 0.0 && v == 1.0) ? 2 : -1;
  if (corner >= 0)
  {
    std::copy(&corners.Weights[corner][0][0], &corners.Weights[corner][0][0] + NumPatchDerivatives * 16, &weights[0][0]);
    return;
  }
  double bern[NumPatchDerivatives][15];
  QuarticBernstein(u, v, bern);
  for (int d = 0; d < NumPatchDerivatives; ++d)
  {
    for (int i = 0; i < 12; ++i)
    {
      double sum = 0.0;
      for (int a = 0; a < 15; ++a)
      {
        sum += bern[d][a] * coefficients(a, i);
      }
      weights[d][i] = sum;
    }
  }
}
}
