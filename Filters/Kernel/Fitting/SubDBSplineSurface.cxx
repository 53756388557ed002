#include "SubDBSplineSurface.h"

#include "SubDPatchBasis.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace subd
{
namespace
{
// One line of data (n points, `stride` values apart) to its n + 2 control points: natural
// ends give c_1 = d_0 and c_n = d_{n-1}; the interior unknowns c_2 .. c_{n-1} solve
// c_{k} + 4 c_{k+1} + c_{k+2} = 6 d_k (k = 1 .. n-2), a (1, 4, 1) tridiagonal system whose
// elimination factors `factors` (Thomas algorithm) are shared by every line and component.
void InterpolateLine(
  const double* data, size_t dataStride, Index n, const std::vector<double>& factors, double* control, size_t controlStride)
{
  auto d = [&](Index k) { return data[k * dataStride]; };
  auto c = [&](Index k) -> double& { return control[k * controlStride]; };
  c(1) = d(0);
  c(n) = d(n - 1);
  const Index m = n - 2; // interior unknowns c_2 .. c_{n-1}
  if (m > 0)
  {
    // Forward sweep (right-hand sides into c(2..n-1)), then back substitution.
    for (Index i = 0; i < m; ++i)
    {
      double rhs = 6.0 * d(i + 1);
      if (i == 0)
        rhs -= c(1);
      if (i == m - 1)
        rhs -= c(n);
      c(i + 2) = i == 0 ? rhs / 4.0 : (rhs - c(i + 1)) / (4.0 - factors[i - 1]);
    }
    for (Index i = m - 2; i >= 0; --i)
    {
      c(i + 2) -= factors[i] * c(i + 3);
    }
  }
  c(0) = 2.0 * c(1) - c(2);
  c(n + 1) = 2.0 * c(n) - c(n - 1);
}

std::vector<double> ThomasFactors(Index n)
{
  std::vector<double> factors(static_cast<size_t>(std::max<Index>(n - 2, 0)));
  for (size_t i = 0; i < factors.size(); ++i)
  {
    factors[i] = 1.0 / (4.0 - (i == 0 ? 0.0 : factors[i - 1]));
  }
  return factors;
}
}

void InterpolateGrid(Index P, Index Q, const std::vector<double>& data, int components, std::vector<double>& net)
{
  const size_t K = static_cast<size_t>(components);
  const Index D = P + 2, E = Q + 2;
  // Along i: P x Q data -> D x Q; then along j: D x Q -> D x E.
  std::vector<double> rows(static_cast<size_t>(D) * Q * K);
  const std::vector<double> factorsP = ThomasFactors(P), factorsQ = ThomasFactors(Q);
  for (Index j = 0; j < Q; ++j)
  {
    for (size_t k = 0; k < K; ++k)
    {
      InterpolateLine(&data[(static_cast<size_t>(j) * P) * K + k], K, P, factorsP, &rows[(static_cast<size_t>(j) * D) * K + k], K);
    }
  }
  net.resize(static_cast<size_t>(D) * E * K); // every entry is written below
  for (Index i = 0; i < D; ++i)
  {
    for (size_t k = 0; k < K; ++k)
    {
      InterpolateLine(&rows[static_cast<size_t>(i) * K + k], static_cast<size_t>(D) * K, Q, factorsQ,
        &net[static_cast<size_t>(i) * K + k], static_cast<size_t>(D) * K);
    }
  }
}

namespace
{
// The span of parameter s over `spans` spans and the local parameter in it.
Index SpanOf(double s, Index spans, double& local)
{
  const Index k = std::clamp(static_cast<Index>(std::floor(s)), Index(0), spans - 1);
  local = s - k;
  return k;
}
}

void EvaluateBicubic(const std::vector<double>& net, Index D, Index E, int components, double s, double t,
  double* value, double* ds, double* dt)
{
  double x, y, basis[NumPatchDerivatives][16];
  const Index k = SpanOf(s, D - 3, x), l = SpanOf(t, E - 3, y);
  EvaluatePatchBasis(PatchKind::BSpline, x, y, basis); // basis[d][4 n + m]: control (k + m, l + n)
  for (int c = 0; c < components; ++c)
  {
    double v = 0.0, vs = 0.0, vt = 0.0;
    for (int a = 0; a < 16; ++a)
    {
      const double p = net[(static_cast<size_t>(l + a / 4) * D + (k + a % 4)) * components + c];
      v += basis[PatchValue][a] * p;
      vs += basis[PatchDu][a] * p;
      vt += basis[PatchDv][a] * p;
    }
    value[c] = v;
    if (ds)
      ds[c] = vs;
    if (dt)
      dt[c] = vt;
  }
}

namespace
{
// The normal matrix couples control points at most 3 apart in each direction: a dense 7 x 7
// window per control point accumulates it without a triplet per sample pair.
struct BandedNormalMatrix
{
  Index D, E;
  std::vector<double> Window; // (D E) x 49
  BandedNormalMatrix(Index d, Index e)
    : D(d)
    , E(e)
    , Window(static_cast<size_t>(d) * e * 49, 0.0)
  {
  }
  void Add(Index i0, Index j0, Index i1, Index j1, double w)
  {
    Window[(static_cast<size_t>(j0) * D + i0) * 49 + (j1 - j0 + 3) * 7 + (i1 - i0 + 3)] += w;
  }
  Eigen::SparseMatrix<double> ToSparse() const
  {
    std::vector<Eigen::Triplet<double>> entries;
    for (Index j = 0; j < E; ++j)
      for (Index i = 0; i < D; ++i)
        for (int o = 0; o < 49; ++o)
        {
          const double w = Window[(static_cast<size_t>(j) * D + i) * 49 + o];
          if (w != 0.0)
            entries.emplace_back(j * D + i, (j + o / 7 - 3) * D + (i + o % 7 - 3), w);
        }
    Eigen::SparseMatrix<double> matrix(D * E, D * E);
    matrix.setFromTriplets(entries.begin(), entries.end());
    return matrix;
  }
};
}

bool FitBicubic(Index D, Index E, const std::vector<double>& uv, const std::vector<double>& values, int components,
  double shapeWeight, std::vector<double>& net, BSplineFitReport& report, std::string& error)
{
  net.clear();
  report = BSplineFitReport();
  const size_t numSamples = uv.size() / 2;
  const size_t K = static_cast<size_t>(components);
  BandedNormalMatrix normal(D, E);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(D * E, components);
  std::vector<char> spanUsed(static_cast<size_t>(D - 3) * (E - 3), 0);
  for (size_t p = 0; p < numSamples; ++p)
  {
    const double u = uv[2 * p], v = uv[2 * p + 1];
    if (!(u >= 0.0 && u <= 1.0 && v >= 0.0 && v <= 1.0))
    {
      char text[160];
      std::snprintf(text, sizeof text, "sample %zu has parameters (%g, %g), outside [0, 1] x [0, 1]", p, u, v);
      error = text;
      return false;
    }
    double x, y, basis[NumPatchDerivatives][16];
    const Index k = SpanOf(u * (D - 3), D - 3, x), l = SpanOf(v * (E - 3), E - 3, y);
    spanUsed[static_cast<size_t>(l) * (D - 3) + k] = 1;
    EvaluatePatchBasis(PatchKind::BSpline, x, y, basis);
    const double* w = basis[PatchValue];
    for (int a = 0; a < 16; ++a)
    {
      const double wa = w[a];
      const Index ia = k + a % 4, ja = l + a / 4;
      for (int b = 0; b < 16; ++b)
      {
        normal.Add(ia, ja, k + b % 4, l + b / 4, wa * w[b]);
      }
      for (size_t c = 0; c < K; ++c)
      {
        rhs(ja * D + ia, static_cast<Eigen::Index>(c)) += wa * values[p * K + c];
      }
    }
  }
  report.NumEmptySpans = static_cast<Index>(std::count(spanUsed.begin(), spanUsed.end(), 0));
  // Shape equations: w (c00 - c10 - c01 + c11) = 0 per control quad.
  const double w2 = shapeWeight * shapeWeight;
  if (w2 > 0.0)
  {
    static const int di[4] = { 0, 1, 0, 1 }, dj[4] = { 0, 0, 1, 1 };
    static const double sign[4] = { 1.0, -1.0, -1.0, 1.0 };
    for (Index j = 0; j + 1 < E; ++j)
      for (Index i = 0; i + 1 < D; ++i)
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b < 4; ++b)
            normal.Add(i + di[a], j + dj[a], i + di[b], j + dj[b], w2 * sign[a] * sign[b]);
  }

  const Eigen::SparseMatrix<double> matrix = normal.ToSparse();
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(matrix);
  bool singular = solver.info() != Eigen::Success;
  if (!singular)
  {
    const Eigen::VectorXd pivots = solver.vectorD().cwiseAbs();
    singular = !(pivots.minCoeff() > 1e-12 * pivots.maxCoeff());
  }
  if (singular)
  {
    error = "the samples do not determine every control point (" + std::to_string(report.NumEmptySpans) + " of the " +
      std::to_string((D - 3) * (E - 3)) + " spans have no sample" +
      (w2 > 0.0 ? std::string(")") : std::string("); turn the shape equations on, or use fewer control points"));
    return false;
  }
  const Eigen::MatrixXd solution = solver.solve(rhs);
  net.resize(static_cast<size_t>(D) * E * K);
  for (Index q = 0; q < D * E; ++q)
    for (size_t c = 0; c < K; ++c)
      net[q * K + c] = solution(q, static_cast<Eigen::Index>(c));

  double sum = 0.0;
  std::vector<double> at(K);
  for (size_t p = 0; p < numSamples; ++p)
  {
    EvaluateBicubic(net, D, E, components, uv[2 * p] * (D - 3), uv[2 * p + 1] * (E - 3), at.data());
    double d2 = 0.0;
    for (size_t c = 0; c < std::min<size_t>(K, 3); ++c)
      d2 += (at[c] - values[p * K + c]) * (at[c] - values[p * K + c]);
    sum += d2;
    report.MaxError = std::max(report.MaxError, std::sqrt(d2));
  }
  report.RmsError = numSamples > 0 ? std::sqrt(sum / numSamples) : 0.0;
  return true;
}
}
