// SubD kernel: how the kernel runs its loops in parallel without depending on a threading
// library. Loops are written as tasks over index ranges; the caller supplies the ParallelFor
// that splits a range among threads (the VTK layer passes one backed by vtkSMPTools).
// Every parallel loop of the kernel writes disjoint outputs, so results do not depend on
// the number of threads.
#ifndef SubDParallel_h
#define SubDParallel_h

#include "SubDTypes.h"
#include <algorithm>
#include <functional>
#include <limits>

namespace subd
{
/// Runs task(begin, end) over [begin, end), possibly split among threads.
using RangeTask = std::function<void(Index, Index)>;
using ParallelFor = std::function<void(Index, Index, const RangeTask&)>;

/// offsets[i] = stride * i for i = 0..count (count + 1 entries): the offsets of lists that all
/// have `stride` entries, written in parallel.
inline void FillStrided(IndexArray& offsets, Index count, Index stride, const ParallelFor& parallelFor)
{
  offsets.resize(static_cast<size_t>(count) + 1);
  parallelFor(0, count + 1, [&](Index begin, Index end) {
    for (Index i = begin; i < end; ++i)
    {
      offsets[i] = stride * i;
    }
  });
}

/// A copy of [first, last) as an IndexArray, made on `parallelFor`'s threads: the first write
/// to each page is most of the cost of copying a large array, and a serial copy takes those
/// faults one after another.
template <typename Iterator>
IndexArray CopyOnThreads(Iterator first, Iterator last, const ParallelFor& parallelFor)
{
  IndexArray to(static_cast<size_t>(last - first));
  parallelFor(0, static_cast<Index>(to.size()), [&](Index begin, Index end) {
    std::copy(first + begin, first + end, to.begin() + begin);
  });
  return to;
}

/// Runs task(b) for the blocks b = 0..numBlocks-1 through `parallelFor`, each block standing
/// for `stride` indices of a longer range: a ParallelFor that will not split a short range
/// (vtkSMPTools' grain is 2048) still hands a few blocks (64 ranges of faces, 1024 ranges of
/// elements) to different threads.
template <typename Task>
void ForEachBlock(Index numBlocks, const ParallelFor& parallelFor, const Task& task)
{
  constexpr Index stride = 4096;
  if (numBlocks > std::numeric_limits<Index>::max() / stride)
  {
    parallelFor(0, numBlocks, [&](Index begin, Index end) {
      for (Index b = begin; b < end; ++b)
      {
        task(b);
      }
    });
    return;
  }
  parallelFor(0, numBlocks * stride, [&](Index begin, Index end) {
    for (Index b = (begin + stride - 1) / stride; b * stride < end; ++b)
    {
      task(b);
    }
  });
}

/// The ParallelFor of a single thread: runs the whole range at once.
inline void SerialFor(Index begin, Index end, const RangeTask& task)
{
  if (begin < end)
  {
    task(begin, end);
  }
}
}

#endif
