#include "SubDMeshValidation.h"

#include <algorithm>

namespace subd
{
bool HasRepeatedVertex(const Index* corners, Index n, std::vector<Index>& scratch)
{
  constexpr Index PairwiseLimit = 16;
  if (n <= PairwiseLimit)
  {
    for (Index i = 0; i < n; ++i)
    {
      for (Index j = i + 1; j < n; ++j)
      {
        if (corners[i] == corners[j])
        {
          return true;
        }
      }
    }
    return false;
  }
  scratch.assign(corners, corners + n);
  std::sort(scratch.begin(), scratch.end());
  return std::adjacent_find(scratch.begin(), scratch.end()) != scratch.end();
}
}
