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

Index CollapseRepeatedCorners(Index* corners, Index n)
{
  Index left = 0;
  for (Index k = 0; k < n; ++k)
  {
    if (left == 0 || corners[left - 1] != corners[k])
    {
      corners[left++] = corners[k];
    }
  }
  while (left > 1 && corners[left - 1] == corners[0])
  {
    --left;
  }
  return left;
}
}
