// SubD kernel: a control cage whose limit surface passes through given points.
//
// An approximating scheme moves every vertex: the limit point of vertex v is a fixed linear
// combination of the cage's points (its limit mask), row v of a sparse matrix M. Asking the
// limit points of the tagged vertices to be the targets, and the other vertices to stay
// where they are, gives the square system
//     M_v . x = t_v   (v tagged),      x_v = t_v   (v untagged: an identity row),
// one right-hand side per coordinate. The limit masks are local (a vertex's 1-ring), so M
// is as sparse as the mesh; it is not symmetric (a mask's weights depend on the vertex's
// valence). Two solvers, chosen by size (or by the caller):
// - direct, Eigen's SparseLU with a COLAMD ordering, up to kDirectSolverLimit unknowns: exact
//   to round-off, and a singular matrix shows as a failed or round-off-level pivot;
// - iterative, BiCGSTAB with a diagonal (Jacobi) preconditioner, above: limit-mask matrices
//   are well conditioned (condition numbers of 4 to 10 on real meshes), so it converges in a
//   few dozen iterations, in O(non-zeros) memory where LU's fill-in costs hundreds of MiB at
//   100k vertices; a singular matrix shows as no convergence on a random right-hand side.
// Either way the condition is estimated and the residual |M x - t| checked after solving.
//
// Interpolating a surface through points this way goes back to Halstead, Kass and DeRose
// ("Efficient, fair interpolation using Catmull-Clark surfaces", SIGGRAPH 1993), who solved
// the same limit-mask system (with a fairness term for the untagged vertices).
#ifndef SubDInterpolation_h
#define SubDInterpolation_h

#include "SubDLevel.h"
#include "SubDScheme.h"

#include <string>
#include <vector>

namespace subd
{
/// The limit point of one vertex as weights over the level's points (empty: none).
struct SparseRow
{
  std::vector<Index> Points;
  std::vector<double> Weights;
};

/// The limit point of every vertex of `level` that some face uses, as weights over the
/// level's points: the scheme's limit stencils (closed forms; Doo-Sabin: the centroid of the
/// vertex's V-face, SubDDualLimit.h), and for Catmull-Clark and Loop vertices touched by a
/// semi-sharp feature (or where the closed forms do not apply: Catmull-Clark's need quads),
/// the exact LimitEvaluator. A vertex without a limit mask (one only on holes, ...) gets an
/// empty row and its reason in `problems[v]` (else empty). False, with `error`, when the
/// scheme has no limit stencils for this cage at all (a Doo-Sabin dart, ...).
SUBDKERNEL_EXPORT bool BuildVertexLimitRows(const Scheme& scheme, const Level& level, std::vector<SparseRow>& rows,
  std::vector<std::string>& problems, std::string& error);

/// Whether vertex v is on the limit surface: some face of v is not a hole.
SUBDKERNEL_EXPORT bool IsOnLimitSurface(const Level& level, Index v);

struct InterpolationReport
{
  Index NumTagged = 0;   ///< rows that are limit masks
  size_t NumNonZeros = 0; ///< entries of the matrix
  double Residual = 0;   ///< max |M x - t| over rows and coordinates
  /// A lower bound of M's condition number in the max norm, |M| |M^-1 r| / |r| for a
  /// pseudo-random r (one extra solve with the factors): a singular M has a pivot at
  /// round-off level, which makes it huge even when the targets happen to be consistent.
  double Condition = 0;
  bool Iterative = false; ///< solved by BiCGSTAB (else SparseLU)
  int Iterations = 0;     ///< BiCGSTAB: the most iterations any right-hand side took
};

enum class InterpolationSolver
{
  Automatic, ///< direct up to kDirectSolverLimit unknowns, iterative above
  Direct,
  Iterative
};
constexpr Index kDirectSolverLimit = 20000;

/// Condition numbers above this mean the cage is not determined by the targets.
constexpr double kMaximumInterpolationCondition = 1e10;

/// Solves the system above: `targets` and `points` hold 3 coordinates per vertex, `tagged`
/// one flag per vertex, `rows` the limit masks (BuildVertexLimitRows). False, with the
/// reason, when a tagged vertex has no row, when the matrix is singular (the factorisation
/// fails, or the condition estimate exceeds kMaximumInterpolationCondition: then many cages
/// have these limit points, and any one returned would be arbitrary), or when the residual
/// exceeds `tolerance` times the targets' extent: `points` is then left empty.
SUBDKERNEL_EXPORT bool SolveInterpolation(const std::vector<SparseRow>& rows, const std::vector<char>& tagged,
  const std::vector<double>& targets, double tolerance, InterpolationSolver method, std::vector<double>& points,
  InterpolationReport& report, std::string& error);
}

#endif
