#include "SubDCoincidentPoints.h"

#include <cstdint>
#include <cstring>
#include <unordered_map>

namespace subd
{
namespace
{
struct Position
{
  double X[3];
  bool operator==(const Position& other) const
  {
    return this->X[0] == other.X[0] && this->X[1] == other.X[1] && this->X[2] == other.X[2];
  }
};

struct PositionHash
{
  size_t operator()(const Position& p) const
  {
    size_t h = 0;
    for (double x : p.X)
    {
      const double normalized = x + 0.0; // -0 and +0 hash alike, as they compare equal
      std::uint64_t bits;
      std::memcpy(&bits, &normalized, sizeof bits);
      h ^= bits + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    }
    return h;
  }
};
}

std::vector<Index> FirstPointAtSamePosition(const double* xyz, Index numPoints)
{
  std::unordered_map<Position, Index, PositionHash> firstAt(static_cast<size_t>(numPoints));
  std::vector<Index> first(static_cast<size_t>(numPoints));
  for (Index i = 0; i < numPoints; ++i)
  {
    const Position p{ { xyz[3 * static_cast<size_t>(i)], xyz[3 * static_cast<size_t>(i) + 1],
      xyz[3 * static_cast<size_t>(i) + 2] } };
    first[i] = firstAt.emplace(p, i).first->second;
  }
  return first;
}
}
