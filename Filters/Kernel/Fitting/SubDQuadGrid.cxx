#include "SubDQuadGrid.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cstdint>
#include <deque>
#include <unordered_map>

namespace subd
{
namespace
{
constexpr Index kUnset = INT_MIN;

std::uint64_t EdgeKey(Index a, Index b)
{
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
}

// The faces as quads with their edges' faces; false, with the reason, for a face that is not
// a quad, repeats a point, or shares an edge with two others.
struct Quads
{
  std::vector<std::array<Index, 4>> Corners;
  std::unordered_map<std::uint64_t, std::array<Index, 3>> EdgeFaces; // up to 2 faces + count
  std::vector<int> FaceCount;                                         // per point
};

bool ReadQuads(Index numPoints, const std::vector<Index>& offsets, const std::vector<Index>& ids, Quads& quads,
  std::string& error)
{
  const Index numFaces = static_cast<Index>(offsets.size()) - 1;
  quads.Corners.resize(static_cast<size_t>(numFaces));
  quads.FaceCount.assign(static_cast<size_t>(numPoints), 0);
  for (Index f = 0; f < numFaces; ++f)
  {
    if (offsets[f + 1] - offsets[f] != 4)
    {
      error = "face " + std::to_string(f) + " has " + std::to_string(offsets[f + 1] - offsets[f]) +
        " points; a grid is made of quads";
      return false;
    }
    std::array<Index, 4>& q = quads.Corners[f];
    for (int k = 0; k < 4; ++k)
    {
      q[k] = ids[offsets[f] + k];
      ++quads.FaceCount[q[k]];
    }
    for (int k = 0; k < 4; ++k)
    {
      if (std::count(q.begin(), q.end(), q[k]) != 1)
      {
        error = "face " + std::to_string(f) + " uses point " + std::to_string(q[k]) + " twice";
        return false;
      }
    }
    for (int k = 0; k < 4; ++k)
    {
      auto& entry =
        quads.EdgeFaces.try_emplace(EdgeKey(q[k], q[(k + 1) % 4]), std::array<Index, 3>{ -1, -1, 0 }).first->second;
      if (entry[2] == 2)
      {
        error = "the edge (" + std::to_string(q[k]) + ", " + std::to_string(q[(k + 1) % 4]) + ") has more than two faces";
        return false;
      }
      entry[entry[2]++] = f;
    }
  }
  return true;
}

// Grid coordinates (I, J) of every point, walked from `start` (face * 4 + corner, a corner of
// a single quad) across shared edges; false, with the reason, where they disagree or some
// quad is not reached.
bool WalkGrid(const Quads& quads, Index start, std::vector<Index>& I, std::vector<Index>& J, std::string& error)
{
  const Index numFaces = static_cast<Index>(quads.Corners.size());
  std::vector<char> visited(static_cast<size_t>(numFaces), 0);
  auto assign = [&](Index v, Index i, Index j) {
    if (I[v] == kUnset)
    {
      I[v] = i;
      J[v] = j;
      return true;
    }
    return I[v] == i && J[v] == j;
  };
  const Index firstFace = start / 4;
  static const Index corner[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
  for (int k = 0; k < 4; ++k)
  {
    assign(quads.Corners[firstFace][(start % 4 + k) % 4], corner[k][0], corner[k][1]);
  }
  std::deque<Index> queue{ firstFace };
  visited[firstFace] = 1;
  while (!queue.empty())
  {
    const Index f = queue.front();
    queue.pop_front();
    const std::array<Index, 4>& q = quads.Corners[f];
    for (int k = 0; k < 4; ++k)
    {
      const Index a = q[k], b = q[(k + 1) % 4], c = q[(k + 2) % 4], d = q[(k + 3) % 4];
      const std::array<Index, 3>& faces = quads.EdgeFaces.at(EdgeKey(a, b));
      const Index g = faces[0] == f ? faces[1] : faces[0];
      if (g < 0 || visited[g])
      {
        continue;
      }
      // In g, the vertex next to a (other than b) continues the grid line d -> a, likewise for b.
      const std::array<Index, 4>& r = quads.Corners[g];
      const int ka = static_cast<int>(std::find(r.begin(), r.end(), a) - r.begin());
      const int kb = static_cast<int>(std::find(r.begin(), r.end(), b) - r.begin());
      const bool forward = (ka + 1) % 4 == kb;
      const Index nextA = r[forward ? (ka + 3) % 4 : (ka + 1) % 4];
      const Index nextB = r[forward ? (kb + 1) % 4 : (kb + 3) % 4];
      if (!assign(nextA, 2 * I[a] - I[d], 2 * J[a] - J[d]) || !assign(nextB, 2 * I[b] - I[c], 2 * J[b] - J[c]))
      {
        error = "the quads do not form a grid (face " + std::to_string(g) + " does not continue the grid lines of face " +
          std::to_string(f) + ")";
        return false;
      }
      visited[g] = 1;
      queue.push_back(g);
    }
  }
  if (std::find(visited.begin(), visited.end(), 0) != visited.end())
  {
    error = "the quads are not connected: a grid is one piece";
    return false;
  }
  return true;
}

// The grid's size and its points in grid order; false, with the reason, unless the
// coordinates fill a P x Q rectangle from (0, 0) once each.
bool PlaceOnGrid(const std::vector<Index>& I, const std::vector<Index>& J, Index numFaces, QuadGrid& grid,
  std::string& error)
{
  const Index numPoints = static_cast<Index>(I.size());
  Index maxI = 0, maxJ = 0, minI = 0, minJ = 0;
  for (Index v = 0; v < numPoints; ++v)
  {
    if (I[v] != kUnset)
    {
      maxI = std::max(maxI, I[v]);
      maxJ = std::max(maxJ, J[v]);
      minI = std::min(minI, I[v]);
      minJ = std::min(minJ, J[v]);
    }
  }
  grid.P = maxI - minI + 1;
  grid.Q = maxJ - minJ + 1;
  if (minI < 0 || minJ < 0 || static_cast<long long>(grid.P - 1) * (grid.Q - 1) != numFaces)
  {
    error = "the quads do not form a rectangular grid (" + std::to_string(numFaces) + " quads span " +
      std::to_string(grid.P) + " x " + std::to_string(grid.Q) + " grid points)";
    return false;
  }
  grid.Points.assign(static_cast<size_t>(grid.P) * grid.Q, -1);
  for (Index v = 0; v < numPoints; ++v)
  {
    if (I[v] == kUnset)
    {
      continue;
    }
    Index& slot = grid.Points[static_cast<size_t>(J[v]) * grid.P + I[v]];
    if (slot >= 0)
    {
      error = "points " + std::to_string(slot) + " and " + std::to_string(v) + " take the same grid position";
      return false;
    }
    slot = v;
  }
  return true;
}
}

bool FindQuadGrid(
  Index numPoints, const std::vector<Index>& offsets, const std::vector<Index>& ids, QuadGrid& grid, std::string& error)
{
  grid = QuadGrid();
  const Index numFaces = static_cast<Index>(offsets.size()) - 1;
  if (numFaces <= 0)
  {
    error = "there are no faces";
    return false;
  }
  Quads quads;
  if (!ReadQuads(numPoints, offsets, ids, quads, error))
  {
    return false;
  }
  // Start at a corner: a vertex of one quad only.
  Index start = -1;
  for (Index f = 0; f < numFaces && start < 0; ++f)
  {
    for (int k = 0; k < 4 && start < 0; ++k)
    {
      start = quads.FaceCount[quads.Corners[f][k]] == 1 ? f * 4 + k : -1;
    }
  }
  if (start < 0)
  {
    error = "no vertex is the corner of a single quad (a closed or periodic surface is not a grid)";
    return false;
  }
  std::vector<Index> I(static_cast<size_t>(numPoints), kUnset), J(static_cast<size_t>(numPoints), kUnset);
  return WalkGrid(quads, start, I, J, error) && PlaceOnGrid(I, J, numFaces, grid, error);
}
}
