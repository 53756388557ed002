#include "SubDTriangleFans.h"
#include "SubDFileByKey.h"

#include <algorithm>
#include <atomic>

namespace subd
{
std::shared_ptr<const TriangleFans> TriangleFans::Build(
  const Index* corners, Index numFaces, Index numVertices, const ParallelFor& parallelFor)
{
  const size_t numCorners = 3 * static_cast<size_t>(numFaces);
  // Each vertex's corners, filed by vertex with the vertices before and after them: the
  // twin of the half-edge leaving a corner at v toward w is the one entering v from w at
  // another corner at v (the twin starts at the corner before it), so every twin is found
  // in v's own short list, read in one piece.
  struct Corner
  {
    Index At, To, From;
  };
  IndexArray offsets;
  LevelArray<Corner> around(numCorners); // large blocks: huge pages where the system has them
  FileByKey(
    numVertices, numFaces,
    [corners](Index begin, Index end, const auto& visit) {
      for (Index h = 3 * begin; h < 3 * end; ++h)
      {
        visit(corners[h], Corner{ h, corners[NextCorner(h)], corners[PreviousCorner(h)] });
      }
    },
    [&around](Index slot, const Corner& corner) { around[slot] = corner; }, offsets, parallelFor);
  auto fans = std::make_shared<TriangleFans>();
  fans->Twin.resize(numCorners);
  fans->FanStart.resize(static_cast<size_t>(numVertices));
  std::atomic<bool> valid{ true };
  parallelFor(0, numVertices, [&](Index begin, Index end) {
    std::vector<std::pair<Index, Index>> byFrom; // a long list's corners by the vertex before
    bool here = true;
    for (Index v = begin; v < end && here; ++v)
    {
      const Index first = offsets[v], last = offsets[v + 1];
      here = last > first;
      // The corner at v entered from w, or InvalidIndex unless there is exactly one.
      auto enteringFrom = [&](Index w) {
        if (last - first <= 16)
        {
          Index found = InvalidIndex, count = 0;
          for (Index j = first; j < last; ++j)
          {
            const bool match = around[j].From == w;
            found = match ? around[j].At : found;
            count += match;
          }
          return count == 1 ? found : InvalidIndex;
        }
        const auto it = std::lower_bound(byFrom.begin(), byFrom.end(), std::make_pair(w, Index(0)));
        const bool one = it != byFrom.end() && it->first == w && (it + 1 == byFrom.end() || (it + 1)->first != w);
        return one ? it->second : InvalidIndex;
      };
      if (last - first > 16)
      {
        byFrom.clear();
        for (Index j = first; j < last; ++j)
        {
          byFrom.emplace_back(around[j].From, around[j].At);
        }
        std::sort(byFrom.begin(), byFrom.end());
      }
      for (Index k = first; k < last && here; ++k)
      {
        const Index entering = enteringFrom(around[k].To);
        here = entering != InvalidIndex && entering != around[k].At;
        fans->Twin[around[k].At] = here ? PreviousCorner(entering) : InvalidIndex;
      }
      fans->FanStart[v] = here ? around[first].At : InvalidIndex;
    }
    if (!here)
    {
      valid = false;
    }
  });
  if (!valid)
  {
    return nullptr;
  }
  for (Index v = 0; v < numVertices; ++v)
  {
    fans->MaxValence = std::max(fans->MaxValence, offsets[v + 1] - offsets[v]);
  }
  // Twins in pairs, and one closed fan around each vertex, holding all its corners: the
  // walk from its start comes back to it after exactly as many corners as the vertex has.
  parallelFor(0, numVertices, [&](Index begin, Index end) {
    bool here = true;
    for (Index v = begin; v < end && here; ++v)
    {
      const Index count = offsets[v + 1] - offsets[v];
      const Index start = fans->FanStart[v];
      Index corner = start, n = 0;
      bool paired = true;
      do
      {
        const Index twin = fans->Twin[corner];
        paired = paired && fans->Twin[twin] == corner;
        corner = NextCorner(twin);
      } while (++n < count && corner != start);
      here = paired && n == count && corner == start;
    }
    if (!here)
    {
      valid = false;
    }
  });
  return valid ? fans : nullptr;
}
}
