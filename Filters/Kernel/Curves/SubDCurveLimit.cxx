#include "SubDCurveLimit.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>

namespace subd
{
namespace
{
void AddCyclic(Index k, Index n, double w, StencilRows& rows)
{
  rows.Add(((k % n) + n) % n, w);
}

// Clamped quadratic B-spline with n >= 3 control points, knots t_i = clamp(i - 2, 0, n - 2),
// i = 0 .. n + 2 (triple end knots, unit spacing): the three basis functions that are not zero
// at x (controls first .. first + 2) and their derivatives, by the Cox-de Boor recursion.
struct QuadraticBasis
{
  Index First = 0;
  double Value[3] = { 0, 0, 0 };
  double Derivative[3] = { 0, 0, 0 };
};

QuadraticBasis ClampedQuadraticAt(Index n, double x)
{
  auto t = [n](Index i) { return static_cast<double>(std::clamp<Index>(i - 2, 0, n - 2)); };
  const Index s = std::clamp<Index>(static_cast<Index>(std::floor(x)) + 2, 2, n - 1); // t_s <= x < t_{s+1}
  const double linearLeft = (t(s + 1) - x) / (t(s + 1) - t(s));                   // N_{s-1,1}
  const double linearRight = (x - t(s)) / (t(s + 1) - t(s));                      // N_{s,1}
  const double spanLeft = t(s + 1) - t(s - 1), spanRight = t(s + 2) - t(s);
  QuadraticBasis basis;
  basis.First = s - 2;
  basis.Value[0] = (t(s + 1) - x) / spanLeft * linearLeft;
  basis.Value[1] = (x - t(s - 1)) / spanLeft * linearLeft + (t(s + 2) - x) / spanRight * linearRight;
  basis.Value[2] = (x - t(s)) / spanRight * linearRight;
  basis.Derivative[0] = -2.0 / spanLeft * linearLeft;
  basis.Derivative[1] = 2.0 / spanLeft * linearLeft - 2.0 / spanRight * linearRight;
  basis.Derivative[2] = 2.0 / spanRight * linearRight;
  return basis;
}

// The Greville abscissa of control point j of the clamped quadratic above.
double ClampedQuadraticGreville(Index n, Index j)
{
  auto t = [n](Index i) { return static_cast<double>(std::clamp<Index>(i - 2, 0, n - 2)); };
  return 0.5 * (t(j + 1) + t(j + 2));
}

// A left eigenvector l of `S` for the eigenvalue 1/2, scaled so that l . x = 1 (x: the
// parameters of the points), or false when that eigenvalue is not simple.
bool HalfEigenvector(const Eigen::MatrixXd& S, const Eigen::VectorXd& x, Eigen::VectorXd& l)
{
  const Eigen::Index size = S.rows();
  Eigen::FullPivLU<Eigen::MatrixXd> lu(S.transpose() - 0.5 * Eigen::MatrixXd::Identity(size, size));
  lu.setThreshold(1e-10);
  if (lu.dimensionOfKernel() != 1)
  {
    return false;
  }
  l = lu.kernel().col(0);
  const double scale = l.dot(x);
  if (std::abs(scale) < 1e-12)
  {
    return false;
  }
  l /= scale;
  return true;
}

// The child rows of an open polygon of `n` points as a dense matrix (children x n).
Eigen::MatrixXd ChildMatrix(const CurveRules& rules, Index n)
{
  StencilRows rows;
  AppendCurveChildRows(rules, n, false, rows);
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(rows.GetNumRows(), n);
  for (Index r = 0; r < rows.GetNumRows(); ++r)
  {
    for (Index k = rows.Offsets[r]; k < rows.Offsets[r + 1]; ++k)
    {
      S(r, rows.Sources[k]) += rows.Weights[k];
    }
  }
  return S;
}

// The 4-point scheme's tangent masks (see the header).
struct FourPointTangents
{
  bool Valid = false;
  std::array<double, 7> Interior{}; // points i-3 .. i+3
  std::array<double, 6> End{};      // points 0 .. 5 of an open end

  explicit FourPointTangents(const CurveRules& rules)
  {
    if (rules.Tension <= 0.0)
    {
      return;
    }
    // Interior: children -3 .. 3 of parents -3 .. 3, read from a long closed polygon.
    const Index n = 16, centre = 8;
    StencilRows rows;
    AppendCurveChildRows(rules, n, true, rows);
    Eigen::MatrixXd S = Eigen::MatrixXd::Zero(7, 7);
    for (Index c = -3; c <= 3; ++c)
    {
      const Index row = 2 * centre + c;
      for (Index k = rows.Offsets[row]; k < rows.Offsets[row + 1]; ++k)
      {
        S(c + 3, rows.Sources[k] - centre + 3) += rows.Weights[k];
      }
    }
    Eigen::VectorXd x(7), l;
    for (int k = 0; k < 7; ++k)
    {
      x(k) = k - 3;
    }
    if (!HalfEigenvector(S, x, l))
    {
      return;
    }
    std::copy(l.data(), l.data() + 7, this->Interior.begin());
    // Open end: the first six children of the first six points (stationary once n >= 5).
    const Eigen::MatrixXd E = ChildMatrix(rules, 12).topLeftCorner(6, 6);
    Eigen::VectorXd xe(6), le;
    for (int k = 0; k < 6; ++k)
    {
      xe(k) = k;
    }
    if (!HalfEigenvector(E, xe, le))
    {
      return;
    }
    std::copy(le.data(), le.data() + 6, this->End.begin());
    this->Valid = true;
  }
};

// Tangent of point j <= (n - 1) / 2 of an open 4-point polygon near its start or in a short
// polygon: refine a window of the first points (all of them when the polygon is short) as a
// matrix until the descendant of j is the end point of a long enough polygon or an interior
// point, then apply the stationary mask there (scaled by 2^K for K levels).
void FourPointNearEndTangent(
  const CurveRules& rules, const FourPointTangents& masks, Index n, Index j, double sign, bool mirrored, StencilRows& rows)
{
  const Index m = std::min<Index>(n, 12);
  Eigen::MatrixXd R = Eigen::MatrixXd::Identity(m, m);
  double scale = 1.0;
  Index c = j;
  Eigen::RowVectorXd tangent;
  for (int level = 0; level < 8; ++level)
  {
    const Index size = static_cast<Index>(R.rows());
    if (c == 0 && size >= 6)
    {
      tangent = Eigen::Map<const Eigen::RowVectorXd>(masks.End.data(), 6) * R.topRows(6);
      break;
    }
    if (c >= 3 && c + 3 < size)
    {
      tangent = Eigen::Map<const Eigen::RowVectorXd>(masks.Interior.data(), 7) * R.middleRows(c - 3, 7);
      break;
    }
    R = ChildMatrix(rules, size) * R;
    c *= 2;
    scale *= 2.0;
  }
  for (Index k = 0; k < m; ++k)
  {
    if (tangent(k) != 0.0)
    {
      rows.Add(mirrored ? n - 1 - k : k, sign * scale * tangent(k));
    }
  }
}

void AppendFourPointTangent(
  const CurveRules& rules, const FourPointTangents& masks, Index n, bool closed, Index j, StencilRows& rows)
{
  if (!masks.Valid)
  {
    // w = 0: the polygon itself; the mean of its two one-sided tangents.
    const bool first = !closed && j == 0, last = !closed && j == n - 1;
    if (closed || (!first && !last))
    {
      AddCyclic(j - 1, n, -0.5, rows);
      AddCyclic(j + 1, n, 0.5, rows);
    }
    else
    {
      rows.Add(first ? 0 : n - 2, -1.0);
      rows.Add(first ? 1 : n - 1, 1.0);
    }
    return;
  }
  if (closed || (j >= 3 && j + 3 < n))
  {
    for (Index d = -3; d <= 3; ++d)
    {
      AddCyclic(j + d, n, masks.Interior[d + 3], rows);
    }
    return;
  }
  // Near an end: work from the nearer end (the rules are symmetric under reversal).
  if (2 * j <= n - 1)
  {
    FourPointNearEndTangent(rules, masks, n, j, 1.0, false, rows);
  }
  else
  {
    FourPointNearEndTangent(rules, masks, n, n - 1 - j, -1.0, true, rows);
  }
}

void AppendTangent(const CurveRules& rules, const FourPointTangents* masks, Index n, bool closed, Index j, StencilRows& rows)
{
  if (n < 2)
  {
    return; // a single point has no tangent: an empty row
  }
  closed = IsClosedPolygon(n, closed);
  if (rules.Scheme == CurveScheme::FourPoint)
  {
    AppendFourPointTangent(rules, *masks, n, closed, j, rows);
    return;
  }
  if (!closed && rules.Scheme == CurveScheme::Chaikin && n > 2)
  {
    const QuadraticBasis basis = ClampedQuadraticAt(n, ClampedQuadraticGreville(n, j));
    for (int k = 0; k < 3; ++k)
    {
      rows.Add(basis.First + k, basis.Derivative[k]);
    }
    return;
  }
  if (!closed && (j == 0 || j == n - 1))
  {
    rows.Add(j == 0 ? 0 : n - 2, -1.0);
    rows.Add(j == 0 ? 1 : n - 1, 1.0);
    return;
  }
  AddCyclic(j - 1, n, -0.5, rows);
  AddCyclic(j + 1, n, 0.5, rows);
}
}

void AppendCurveLimitMask(const CurveRules& rules, Index n, bool closed, Index j, StencilRows& rows)
{
  closed = IsClosedPolygon(n, closed);
  const bool end = !closed && (j == 0 || j == n - 1);
  if (rules.Scheme == CurveScheme::FourPoint || n < 3 || end)
  {
    rows.Add(j, 1.0);
  }
  else if (rules.Scheme == CurveScheme::Chaikin && !closed)
  {
    const QuadraticBasis basis = ClampedQuadraticAt(n, ClampedQuadraticGreville(n, j));
    for (int k = 0; k < 3; ++k)
    {
      rows.Add(basis.First + k, basis.Value[k]);
    }
  }
  else
  {
    const double side = rules.Scheme == CurveScheme::Chaikin ? 1.0 / 8.0 : 1.0 / 6.0;
    AddCyclic(j - 1, n, side, rows);
    rows.Add(j, 1.0 - 2.0 * side);
    AddCyclic(j + 1, n, side, rows);
  }
  rows.EndRow();
}

void AppendCurveTangentMask(const CurveRules& rules, Index n, bool closed, Index j, StencilRows& rows)
{
  const FourPointTangents masks(rules);
  AppendTangent(rules, &masks, n, closed, j, rows);
  rows.EndRow();
}

StencilTable CurveLimitStencils(const CurveRules& rules, const CurvePieces& pieces, Index numPoints)
{
  // Anchors are end points: every scheme interpolates them. Interior points are numbered
  // piece after piece (SubDCurveRefiner.h), so their rows come in point order.
  StencilRows rows, local;
  for (Index a = 0; a < pieces.NumAnchors; ++a)
  {
    rows.Add(a, 1.0);
    rows.EndRow();
  }
  for (Index p = 0; p < pieces.GetNumPieces(); ++p)
  {
    const IndexSpan piece = pieces.GetPiece(p);
    const bool closed = pieces.IsClosed(p);
    local.Clear();
    for (Index j = 0; j < piece.size(); ++j)
    {
      if (closed || (j > 0 && j + 1 < piece.size()))
      {
        AppendCurveLimitMask(rules, piece.size(), closed, j, local);
      }
    }
    rows.AppendRenumbered(local, 0, local.GetNumRows(), piece.Data);
  }
  return rows.ToStencilTable(numPoints);
}

StencilTable CurveTangentStencils(const CurveRules& rules, const CurvePieces& pieces, Index numPoints)
{
  const FourPointTangents masks(rules);
  StencilRows rows, local;
  for (Index p = 0; p < pieces.GetNumPieces(); ++p)
  {
    const IndexSpan piece = pieces.GetPiece(p);
    local.Clear();
    for (Index j = 0; j < piece.size(); ++j)
    {
      AppendTangent(rules, &masks, piece.size(), pieces.IsClosed(p), j, local);
      local.EndRow();
    }
    rows.AppendRenumbered(local, 0, local.GetNumRows(), piece.Data);
  }
  return rows.ToStencilTable(numPoints);
}
}
