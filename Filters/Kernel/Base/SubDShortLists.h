// SubD kernel: sorting the short index lists of a vertex's neighbourhood.
#ifndef SubDShortLists_h
#define SubDShortLists_h

#include <algorithm>
#include <cstddef>

namespace subd
{
/// Sorts the few values of a typical vertex's list by insertion (std::sort's set-up costs
/// more than the sort itself there), a longer list with std::sort.
template <typename T>
inline void SortShortList(T* first, T* last)
{
  constexpr std::ptrdiff_t shortList = 32;
  if (last - first > shortList)
  {
    std::sort(first, last);
    return;
  }
  for (T* i = first + (first != last); i < last; ++i)
  {
    const T value = *i;
    T* j = i;
    for (; j > first && *(j - 1) > value; --j)
    {
      *j = *(j - 1);
    }
    *j = value;
  }
}
}

#endif
