#include "SubDVertexLimit.h"

#include "SubDQuadSplit.h"
#include "SubDRegularPatch.h"
#include "SubDTriangleSplit.h"

#include <Eigen/Dense>

#include <algorithm>
#include <complex>

namespace subd
{
namespace
{
using ComplexMatrix = Eigen::MatrixXcd;

// Indices of the eigenvalues sorted by decreasing magnitude.
std::vector<int> ByMagnitude(const Eigen::VectorXcd& values)
{
  std::vector<int> order(static_cast<size_t>(values.size()));
  for (int i = 0; i < values.size(); ++i)
  {
    order[i] = i;
  }
  std::stable_sort(order.begin(), order.end(), [&values](int a, int b) { return std::abs(values[a]) > std::abs(values[b]); });
  return order;
}

// The spectral projector onto the eigenvalues of `wanted` (indices into the right
// solver's values): R (L^T R)^-1 L^T, L the left eigenvectors with the same eigenvalues.
Eigen::MatrixXd Projector(const Eigen::EigenSolver<Eigen::MatrixXd>& right,
  const Eigen::EigenSolver<Eigen::MatrixXd>& left, const std::vector<int>& wanted, double tol)
{
  const Eigen::Index n = right.eigenvalues().size();
  const Eigen::Index m = static_cast<Eigen::Index>(wanted.size());
  ComplexMatrix R(n, m), L(n, m);
  std::vector<bool> used(static_cast<size_t>(n), false);
  for (Eigen::Index c = 0; c < m; ++c)
  {
    const std::complex<double> value = right.eigenvalues()[wanted[c]];
    R.col(c) = right.eigenvectors().col(wanted[c]);
    Eigen::Index best = -1;
    for (Eigen::Index k = 0; k < n; ++k)
    {
      if (!used[k] && std::abs(left.eigenvalues()[k] - value) < tol &&
        (best < 0 || std::abs(left.eigenvalues()[k] - value) < std::abs(left.eigenvalues()[best] - value)))
      {
        best = k;
      }
    }
    if (best < 0)
    {
      return {};
    }
    used[best] = true;
    L.col(c) = left.eigenvectors().col(best);
  }
  const ComplexMatrix gram = L.transpose() * R;
  return (R * gram.inverse() * L.transpose()).real();
}

// The sector's faces as a level of their own: v (point 0), then the other corners of the
// sector's faces (`points`, in the level's numbering). v keeps its rule there: a corner is
// pinned by vertex sharpness (the sector may hold fewer of its sharp edges).
Level SectorLevel(const Level& level, Index v, const std::vector<Index>& sector, std::vector<Index>& points)
{
  points.assign(1, v);
  std::vector<Index> edges;
  Level mini;
  mini.Topology = level.Topology.ExtractFaces(sector, points, edges);
  const Index n = static_cast<Index>(points.size());
  mini.Creasing = level.Creasing;
  mini.Depth = level.Depth;
  mini.EdgeSharpness.resize(static_cast<size_t>(mini.Topology.GetNumEdges()));
  for (Index e = 0; e < mini.Topology.GetNumEdges(); ++e)
  {
    mini.EdgeSharpness[e] = mini.Topology.GetEdgeFaces(e).size() == 2
      ? level.EdgeSharpness[edges[e]]
      : SharpnessInfinite; // the sector's border: creases, or edges never read
  }
  mini.VertexSharpness.resize(static_cast<size_t>(n));
  for (Index p = 0; p < n; ++p)
  {
    mini.VertexSharpness[p] = level.VertexSharpness[points[p]];
  }
  if (PlanVertexRule(level, v).Rule == VertexRule::Corner)
  {
    mini.VertexSharpness[0] = SharpnessInfinite;
  }
  mini.FaceIsHole.assign(sector.size(), 0);
  mini.FaceOrigin.assign(sector.size(), 0);
  return mini;
}

// S, the subdivision matrix of the sector level: row p is the child of point p (v's vertex
// point, a spoke's edge point, a diagonal corner's face point) in terms of the points. False
// where a point has no child in the sector (not closed under refinement).
bool SubdivisionMatrix(const Scheme& scheme, const Level& mini, bool quads, Eigen::MatrixXd& S)
{
  const StencilTable stencils = scheme.BuildStencils(mini);
  const MeshTopology& mt = mini.Topology;
  const Index n = mt.GetNumVertices();
  Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(n, n);
  Eigen::MatrixXd children(n, stencils.GetNumRows()); // column-major: column c = child c's weights
  stencils.Apply(identity.data(), children.data(), static_cast<int>(n));
  const Index numFaces = mt.GetNumFaces(), numEdges = mt.GetNumEdges();
  const QuadSplitNumbering quadPoints{ numFaces, numEdges };
  const TriangleSplitNumbering trianglePoints{ numEdges };
  auto childOf = [&](Index p) -> Index {
    if (p == 0)
    {
      return quads ? quadPoints.VertexPoint(0) : trianglePoints.VertexPoint(0);
    }
    const Index spoke = mt.FindEdge(0, p);
    if (spoke != InvalidIndex)
    {
      return quads ? quadPoints.EdgePoint(spoke) : trianglePoints.EdgePoint(spoke);
    }
    for (Index g = 0; g < numFaces; ++g) // a diagonal corner: its face's point
    {
      const IndexSpan gv = mt.GetFaceVertices(g);
      if (std::find(gv.begin(), gv.end(), p) != gv.end())
      {
        return quadPoints.FacePoint(g);
      }
    }
    return InvalidIndex;
  };
  S.resize(n, n);
  for (Index p = 0; p < n; ++p)
  {
    const Index c = childOf(p);
    if (c == InvalidIndex)
    {
      return false;
    }
    S.row(p) = children.col(c).transpose();
  }
  return true;
}
}

bool ComputeVertexLimit(const Scheme& scheme, const Level& level, Index face, Index corner, VertexLimit& out,
  std::string& error)
{
  const MeshTopology& topo = level.Topology;
  const Index faceSize = topo.GetFaceSize(face);
  const Index v = topo.GetFaceVertices(face)[corner];
  const std::vector<Index> sector = SectorFaces(level, face, corner);
  if (sector.empty() || !IsStableCorner(level, face, corner, faceSize))
  {
    error = "vertex " + std::to_string(v) + " cannot be analysed (semi-sharp features not decayed)";
    return false;
  }
  std::vector<Index>& points = out.Points;
  const Level mini = SectorLevel(level, v, sector, points);
  const Index n = static_cast<Index>(points.size());
  Eigen::MatrixXd S;
  if (!SubdivisionMatrix(scheme, mini, faceSize == 4, S))
  {
    error = "vertex " + std::to_string(v) + ": its neighbourhood is not closed under refinement";
    return false;
  }
  const Eigen::EigenSolver<Eigen::MatrixXd> right(S), left(S.transpose());
  if (right.info() != Eigen::Success || left.info() != Eigen::Success)
  {
    error = "vertex " + std::to_string(v) + ": eigen-decomposition failed";
    return false;
  }
  const Eigen::VectorXcd& values = right.eigenvalues();
  const std::vector<int> order = ByMagnitude(values);
  const double tol = 1e-9;
  if (std::abs(values[order[0]] - 1.0) > 1e-8 || (n > 1 && std::abs(values[order[1]]) > 1.0 - 1e-8))
  {
    error = "vertex " + std::to_string(v) + ": the subdivision matrix has no single eigenvalue 1";
    return false;
  }
  // The tangent eigenvalues: the next ones by magnitude, whole clusters, at least two.
  std::vector<int> tangent;
  size_t next = 1;
  while (tangent.size() < 2 && next < order.size())
  {
    const double magnitude = std::abs(values[order[next]]);
    while (next < order.size() && std::abs(std::abs(values[order[next]]) - magnitude) < tol)
    {
      tangent.push_back(order[next++]);
    }
  }
  const Eigen::MatrixXd limit = Projector(right, left, { order[0] }, 1e-7);
  const Eigen::MatrixXd tangents = Projector(right, left, tangent, 1e-7);
  if (limit.size() == 0 || tangents.size() == 0)
  {
    error = "vertex " + std::to_string(v) + ": eigenvectors could not be matched";
    return false;
  }
  const IndexSpan fv = topo.GetFaceVertices(face);
  const Index nextPoint = static_cast<Index>(
    std::find(points.begin(), points.end(), fv[(corner + 1) % faceSize]) - points.begin());
  const Index previousPoint = static_cast<Index>(
    std::find(points.begin(), points.end(), fv[(corner + faceSize - 1) % faceSize]) - points.begin());
  out.Position.resize(static_cast<size_t>(n));
  out.TangentNext.resize(static_cast<size_t>(n));
  out.TangentPrevious.resize(static_cast<size_t>(n));
  for (Index p = 0; p < n; ++p)
  {
    out.Position[p] = limit(0, p);
    out.TangentNext[p] = tangents(nextPoint, p);
    out.TangentPrevious[p] = tangents(previousPoint, p);
  }
  return true;
}
}
