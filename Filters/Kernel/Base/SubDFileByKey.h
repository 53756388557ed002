// SubD kernel: filing items under integer keys in item order (a counting sort) on threads.
#ifndef SubDFileByKey_h
#define SubDFileByKey_h

#include "SubDParallel.h"
#include "SubDTypes.h"

#include <cstdint>
#include <vector>

namespace subd
{
/// Turns per-item counts stored at [i+1] into offsets (exclusive prefix sum in place).
inline void CountsToOffsets(IndexArray& offsets)
{
  for (size_t i = 1; i < offsets.size(); ++i)
  {
    offsets[i] += offsets[i - 1];
  }
}

/// Files items under integer keys (vertices) in item order: a counting sort, on threads
/// without atomics. The items are cut into a few fixed blocks; each block counts its items
/// per key, the file of a key takes the blocks' items in block order, and each block then
/// files its own. `items(begin, end, visit)` calls visit(key, payload) for the items
/// [begin, end) in order; `place(slot, payload)` stores an item at its slot; `offsets`
/// receives where each key's file starts (numKeys + 1 of them).
template <typename Items, typename Place>
void FileByKey(Index numKeys, Index numItems, const Items& items, const Place& place, IndexArray& offsets,
  const ParallelFor& parallelFor)
{
  constexpr Index blocks = 4;
  auto blockBegin = [numItems](Index b) {
    return static_cast<Index>(static_cast<std::int64_t>(numItems) * b / blocks);
  };
  std::vector<IndexArray> cursors(blocks);
  ForEachBlock(blocks, parallelFor, [&](Index b) {
    IndexArray& counts = cursors[b];
    counts.assign(static_cast<size_t>(numKeys), 0);
    items(blockBegin(b), blockBegin(b + 1), [&counts](Index key, const auto&) { ++counts[key]; });
  });
  // Each key's count, its offset (the one serial pass, over keys alone), then each block's
  // first slot in it.
  offsets.resize(static_cast<size_t>(numKeys) + 1);
  offsets[0] = 0;
  parallelFor(0, numKeys, [&](Index begin, Index end) {
    for (Index key = begin; key < end; ++key)
    {
      Index count = 0;
      for (const IndexArray& blockCounts : cursors)
      {
        count += blockCounts[key];
      }
      offsets[key + 1] = count;
    }
  });
  CountsToOffsets(offsets);
  parallelFor(0, numKeys, [&](Index begin, Index end) {
    for (Index key = begin; key < end; ++key)
    {
      Index slot = offsets[key];
      for (IndexArray& cursor : cursors)
      {
        const Index count = cursor[key];
        cursor[key] = slot;
        slot += count;
      }
    }
  });
  ForEachBlock(blocks, parallelFor, [&](Index b) {
    IndexArray& cursor = cursors[b];
    items(blockBegin(b), blockBegin(b + 1), [&](Index key, const auto& payload) { place(cursor[key]++, payload); });
  });
}
}

#endif
