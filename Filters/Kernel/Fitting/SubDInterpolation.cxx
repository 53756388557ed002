#include "SubDInterpolation.h"

#include "SubDCrease.h"
#include "SubDLimitEvaluator.h"
#include "SubDStencilTable.h"

#include <Eigen/SparseCore>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>

namespace subd
{
namespace
{
bool IsExactlyEvaluated(const Scheme& scheme)
{
  return std::strcmp(scheme.GetName(), "catmull-clark") == 0 || std::strcmp(scheme.GetName(), "loop") == 0;
}

// Rows from LimitEvaluator: the limit at a corner of one of the vertex's faces that is not
// a hole (any of them: the limit point is the same from every side).
void RowsFromLimitEvaluator(const Scheme& scheme, const Level& level, const std::vector<Index>& vertices,
  std::vector<SparseRow>& rows, std::vector<std::string>& problems)
{
  if (vertices.empty())
  {
    return;
  }
  const LimitEvaluator evaluator(scheme, level);
  std::string error;
  if (!evaluator.IsValid(error))
  {
    for (Index v : vertices)
    {
      problems[v] = error;
      rows[v] = SparseRow();
    }
    return;
  }
  const bool quads = std::strcmp(scheme.GetName(), "catmull-clark") == 0;
  std::vector<LimitStencil> out;
  for (Index v : vertices)
  {
    rows[v] = SparseRow();
    const IndexSpan faces = level.Topology.GetVertexFaces(v);
    const IndexSpan corners = level.Topology.GetVertexFaceCorners(v);
    problems[v] = faces.size() == 0 ? "it is on no face" : "it is only on holes";
    for (Index k = 0; k < faces.size(); ++k)
    {
      const Index f = faces[k];
      if (level.FaceIsHole[f])
      {
        continue;
      }
      const FaceSample sample = LimitEvaluator::CornerSample(level.Topology.GetFaceSize(f), corners[k], quads);
      if (!evaluator.EvaluateFace(f, { sample }, out, error))
      {
        problems[v] = error;
        break;
      }
      rows[v].Points = out[0].Points;
      rows[v].Weights.assign(out[0].Row(0), out[0].Row(0) + out[0].Points.size());
      problems[v].clear();
      break;
    }
  }
}

// Rows from the scheme's limit stencils (entries naming earlier rows expanded by AddRow).
bool RowsFromLimitStencils(const Scheme& scheme, const Level& level, std::vector<SparseRow>& rows, std::string& error)
{
  StencilTable stencils;
  if (!scheme.BuildLimitStencils(level, stencils, error))
  {
    return false;
  }
  StencilRows row;
  for (Index v = 0; v < level.Topology.GetNumVertices() && v < stencils.GetNumRows(); ++v)
  {
    row.Clear();
    row.AddRow(stencils, v, 1.0);
    rows[v].Points.assign(row.Sources.begin(), row.Sources.end());
    rows[v].Weights.assign(row.Weights.begin(), row.Weights.end());
  }
  return true;
}

// Whether the vertex or one of its edges is semi-sharp (sharp for a finite number of levels):
// only those change a vertex's limit mask away from the closed forms of the limit stencils.
bool TouchesSemiSharpFeature(const Level& level, Index v)
{
  if (!level.VertexSharpness.empty() && IsSemiSharp(level.VertexSharpness[v]))
  {
    return true;
  }
  if (level.EdgeSharpness.empty())
  {
    return false;
  }
  const IndexSpan edges = level.Topology.GetVertexEdges(v);
  return std::any_of(edges.begin(), edges.end(), [&](Index e) { return IsSemiSharp(level.EdgeSharpness[e]); });
}
}

bool IsOnLimitSurface(const Level& level, Index v)
{
  const IndexSpan faces = level.Topology.GetVertexFaces(v);
  return std::any_of(faces.begin(), faces.end(), [&](Index f) { return !level.FaceIsHole[f]; });
}

bool BuildVertexLimitRows(const Scheme& scheme, const Level& level, std::vector<SparseRow>& rows,
  std::vector<std::string>& problems, std::string& error)
{
  const Index numVertices = level.Topology.GetNumVertices();
  rows.assign(static_cast<size_t>(numVertices), SparseRow());
  problems.assign(static_cast<size_t>(numVertices), std::string());
  const bool stencilsBuilt = RowsFromLimitStencils(scheme, level, rows, error);
  if (!stencilsBuilt && !IsExactlyEvaluated(scheme))
  {
    rows.assign(static_cast<size_t>(numVertices), SparseRow());
    return false;
  }
  if (IsExactlyEvaluated(scheme))
  {
    // The limit stencils are exact (and far cheaper: a closed form per vertex) except where
    // a semi-sharp feature touches the vertex; there the limit evaluator refines the
    // neighbourhood as often as the sharpness lasts.
    std::vector<Index> evaluated;
    for (Index v = 0; v < numVertices; ++v)
    {
      if (!stencilsBuilt || rows[v].Points.empty() || TouchesSemiSharpFeature(level, v))
      {
        evaluated.push_back(v);
      }
    }
    RowsFromLimitEvaluator(scheme, level, evaluated, rows, problems);
  }
  // A vertex whose faces are all holes (or that has none) is not on the limit surface.
  for (Index v = 0; v < numVertices; ++v)
  {
    if (!IsOnLimitSurface(level, v))
    {
      rows[v] = SparseRow();
      problems[v] = level.Topology.GetVertexFaces(v).empty() ? "it is on no face" : "it is only on holes";
    }
  }
  return true;
}

namespace
{
using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
using Solve = std::function<bool(const Eigen::MatrixXd&, const Eigen::MatrixXd*, Eigen::MatrixXd&)>;

// The system: a tagged vertex's limit row equals its target, an untagged vertex stays.
bool AssembleSystem(const std::vector<SparseRow>& rows, const std::vector<char>& tagged,
  const std::vector<double>& targets, InterpolationReport& report, RowMatrix& matrix, Eigen::MatrixXd& rhs,
  std::string& error)
{
  const Index n = static_cast<Index>(tagged.size());
  std::vector<Eigen::Triplet<double>> entries;
  for (Index v = 0; v < n; ++v)
  {
    if (!tagged[v])
    {
      entries.emplace_back(v, v, 1.0);
      continue;
    }
    if (rows[v].Points.empty())
    {
      error = "vertex " + std::to_string(v) + " is tagged but has no limit point to interpolate with";
      return false;
    }
    ++report.NumTagged;
    for (size_t k = 0; k < rows[v].Points.size(); ++k)
    {
      entries.emplace_back(v, rows[v].Points[k], rows[v].Weights[k]);
    }
  }
  matrix.resize(n, n);
  matrix.setFromTriplets(entries.begin(), entries.end());
  matrix.makeCompressed();
  report.NumNonZeros = static_cast<size_t>(matrix.nonZeros());
  rhs.resize(n, 3);
  for (Index v = 0; v < n; ++v)
  {
    rhs.row(v) << targets[3 * v], targets[3 * v + 1], targets[3 * v + 2];
  }
  return true;
}

// A lower bound of the condition number, from a solve with a pseudo-random right-hand side:
// round-off hides an exactly singular matrix from the factorisation (a closed cube's
// Catmull-Clark limit masks annihilate the alternating +1/-1 vertex pattern), and consistent
// targets (the cube's own corners) even give a tiny residual, with an arbitrary multiple of
// that pattern added; the random solve exposes the tiny pivot. Infinite where the solve fails
// (`probed` false: the iterative solver does not converge).
double EstimateCondition(const RowMatrix& matrix, const Solve& solve, bool& probed)
{
  const Index n = static_cast<Index>(matrix.rows());
  Eigen::MatrixXd probe(n, 1);
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  for (Index v = 0; v < n; ++v)
  {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    probe(v, 0) = static_cast<double>(state >> 11) * 0x1.0p-52 - 1.0; // in [-1, 1)
  }
  Eigen::MatrixXd response;
  probed = solve(probe, nullptr, response);
  double matrixNorm = 0.0;
  for (Index v = 0; v < n; ++v)
  {
    matrixNorm = std::max(matrixNorm, matrix.row(v).cwiseAbs().sum());
  }
  return probed && response.allFinite()
    ? matrixNorm * response.cwiseAbs().maxCoeff() / std::max(probe.cwiseAbs().maxCoeff(), 1e-300)
    : HUGE_VAL;
}
}

bool SolveInterpolation(const std::vector<SparseRow>& rows, const std::vector<char>& tagged,
  const std::vector<double>& targets, double tolerance, InterpolationSolver method, std::vector<double>& points,
  InterpolationReport& report, std::string& error)
{
  points.clear();
  report = InterpolationReport();
  const Index n = static_cast<Index>(tagged.size());
  RowMatrix matrix;
  Eigen::MatrixXd rhs;
  if (!AssembleSystem(rows, tagged, targets, report, matrix, rhs, error))
  {
    return false;
  }
  // solve(b, guess, x): false when the solver failed on b. The iterative solver starts from
  // `guess` when there is one (the targets: a cage is near its limit surface).
  Solve solve;
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> direct;
  Eigen::BiCGSTAB<RowMatrix, Eigen::DiagonalPreconditioner<double>> iterative;
  report.Iterative = method == InterpolationSolver::Iterative ||
    (method == InterpolationSolver::Automatic && n > kDirectSolverLimit);
  if (!report.Iterative)
  {
    direct.compute(Eigen::SparseMatrix<double>(matrix));
    if (direct.info() != Eigen::Success)
    {
      error = "the interpolation system is singular (" + direct.lastErrorMessage() +
        "): no cage of this topology has these limit points; tag fewer vertices";
      return false;
    }
    solve = [&](const Eigen::MatrixXd& b, const Eigen::MatrixXd*, Eigen::MatrixXd& x) {
      x = direct.solve(b);
      return true;
    };
  }
  else
  {
    iterative.setTolerance(1e-14);
    iterative.setMaxIterations(1000);
    iterative.compute(matrix);
    solve = [&](const Eigen::MatrixXd& b, const Eigen::MatrixXd* guess, Eigen::MatrixXd& x) {
      x.resize(b.rows(), b.cols());
      for (Eigen::Index c = 0; c < b.cols(); ++c)
      {
        if (guess)
          x.col(c) = iterative.solveWithGuess(b.col(c), guess->col(c));
        else
          x.col(c) = iterative.solve(b.col(c));
        report.Iterations = std::max(report.Iterations, static_cast<int>(iterative.iterations()));
        if (iterative.info() != Eigen::Success)
        {
          return false;
        }
      }
      return true;
    };
  }
  bool probed = false;
  report.Condition = EstimateCondition(matrix, solve, probed);
  if (!(report.Condition <= kMaximumInterpolationCondition))
  {
    char number[64];
    std::snprintf(number, sizeof number, "%.3g", report.Condition);
    error = std::string("the interpolation system is singular or ill-conditioned (") +
      (probed ? std::string("condition number at least ") + number
              : "the iterative solver does not converge on a random right-hand side in " +
            std::to_string(report.Iterations) + " iterations") +
      "): many cages have these limit points, so none is returned; tag fewer vertices";
    return false;
  }
  Eigen::MatrixXd solution;
  const bool solved = solve(rhs, &rhs, solution);
  const double residual = solved && solution.allFinite() ? (matrix * solution - rhs).cwiseAbs().maxCoeff() : HUGE_VAL;
  const double extent = std::max(1.0, rhs.cwiseAbs().maxCoeff());
  report.Residual = residual;
  if (!(residual <= tolerance * extent))
  {
    // Inconsistent targets for a nearly singular matrix that passed the estimate above.
    char numbers[160];
    std::snprintf(numbers, sizeof numbers, "%.3g (tolerance %.3g)", residual, tolerance * extent);
    error = std::string("the interpolation system is singular or ill-conditioned: the solution misses the targets "
                        "by ") + numbers + "; no cage of this topology has these limit points, tag fewer vertices";
    return false;
  }
  points.resize(static_cast<size_t>(n) * 3);
  for (Index v = 0; v < n; ++v)
  {
    for (int c = 0; c < 3; ++c)
    {
      points[3 * v + c] = solution(v, c);
    }
  }
  return true;
}
}
