// Helpers shared by the oracle tests that compare with peers numbering points their own way
// (CGAL, OpenMesh): bounding-box diagonal, nearest-point matching, canonical face rotation.
#ifndef SubDOracleSupport_h
#define SubDOracleSupport_h

#include "SubDMeshTopology.h"
#include "SubDTypes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace subdtest
{
inline double Diagonal(const std::vector<double>& xyz)
{
  double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
  for (size_t i = 0; i < xyz.size(); ++i)
  {
    lo[i % 3] = std::min(lo[i % 3], xyz[i]);
    hi[i % 3] = std::max(hi[i % 3], xyz[i]);
  }
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
    (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

/// Points as xyz triples.
inline std::vector<double> Flatten(const std::vector<std::array<double, 3>>& points)
{
  std::vector<double> flat;
  flat.reserve(points.size() * 3);
  for (const auto& p : points)
  {
    flat.insert(flat.end(), p.begin(), p.end());
  }
  return flat;
}

/// The index of the point of `ours` (xyz triples) nearest to p in the max norm, and the
/// distance.
inline subd::Index NearestPoint(const std::vector<double>& ours, const double p[3], double& distance)
{
  subd::Index best = -1;
  distance = 1e300;
  for (size_t i = 0; i < ours.size() / 3; ++i)
  {
    const double d = std::max(
      { std::abs(p[0] - ours[3 * i]), std::abs(p[1] - ours[3 * i + 1]), std::abs(p[2] - ours[3 * i + 2]) });
    if (d < distance)
    {
      distance = d;
      best = static_cast<subd::Index>(i);
    }
  }
  return best;
}

/// A face rotated to start at its smallest vertex, for comparisons that respect orientation.
/// The largest distance from a boundary vertex of `topology` (its point in `xyz`) to the
/// nearest of `candidates`, and how many boundary vertices there are.
inline double FarthestBoundaryPoint(const subd::MeshTopology& topology, const std::vector<double>& xyz,
  const std::vector<double>& candidates, subd::Index& boundaryPoints)
{
  double worst = 0.0;
  boundaryPoints = 0;
  for (subd::Index v = 0; v < topology.GetNumVertices(); ++v)
  {
    if (!topology.GetVertexTag(v).Boundary)
      continue;
    ++boundaryPoints;
    double best;
    NearestPoint(candidates, &xyz[3 * static_cast<size_t>(v)], best);
    worst = std::max(worst, best);
  }
  return worst;
}

inline std::vector<subd::Index> Canonical(std::vector<subd::Index> face)
{
  std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
  return face;
}
}

#endif
