#include "SubDFaceBlocks.h"

#include <algorithm>
#include <atomic>
#include <numeric>

namespace subd
{
void FaceBlock::EndFaceWithoutRepeats(size_t first, Index origin, std::uint8_t hole)
{
  auto end = std::unique(this->Vertices.begin() + static_cast<std::ptrdiff_t>(first), this->Vertices.end());
  if (end - this->Vertices.begin() > static_cast<std::ptrdiff_t>(first) + 1 && *(end - 1) == this->Vertices[first])
  {
    --end;
  }
  this->Vertices.erase(end, this->Vertices.end());
  if (this->Vertices.size() - first < 3)
  {
    this->Vertices.resize(first);
    return;
  }
  this->EndFace(origin, hole);
}

namespace
{
// [0, numElements) cut into at most maxRanges fixed ranges (not a ParallelFor's, which may
// cut differently each call and, under its grain, into many small ones).
struct FixedRanges
{
  FixedRanges(Index numElements, Index maxRanges)
    : NumElements(numElements)
    , NumRanges(std::max<Index>(1, std::min<Index>(numElements, maxRanges)))
  {
  }
  Index Begin(Index r) const
  {
    return static_cast<Index>(static_cast<std::int64_t>(this->NumElements) * r / this->NumRanges);
  }
  Index NumElements;
  Index NumRanges;
};

std::ptrdiff_t Offset(size_t i)
{
  return static_cast<std::ptrdiff_t>(i);
}

// Calls copy(block, localBegin, localEnd, globalBegin) for every part of the concatenation
// [0, firsts.back()) of blocks (block b starting at firsts[b]), in parallel ranges, and
// release(block) once all of a block is copied (by whichever range copied its last part),
// so that the blocks' memory goes back as the concatenation's is filled: the faces are not
// held twice at the end of the copy.
template <typename Copy, typename Release>
void ForEachBlockPart(const ParallelFor& parallelFor, const std::vector<size_t>& firsts, Copy&& copy, Release&& release)
{
  std::vector<std::atomic<size_t>> uncopied(firsts.size() - 1);
  for (size_t b = 0; b + 1 < firsts.size(); ++b)
  {
    uncopied[b] = firsts[b + 1] - firsts[b];
  }
  parallelFor(0, static_cast<Index>(firsts.back()), [&](Index begin, Index end) {
    // The block holding `begin`: the last one starting at or before it.
    size_t b = static_cast<size_t>(std::upper_bound(firsts.begin(), firsts.end(), static_cast<size_t>(begin)) - firsts.begin()) - 1;
    for (size_t at = static_cast<size_t>(begin); at < static_cast<size_t>(end); ++b)
    {
      const size_t stop = std::min(firsts[b + 1], static_cast<size_t>(end));
      if (stop > at)
      {
        copy(b, at - firsts[b], stop - firsts[b], at);
        if (uncopied[b].fetch_sub(stop - at) == stop - at)
        {
          release(b);
        }
      }
      at = std::max(at, stop);
    }
  });
}
}

EmittedFaces EmitFacesInParallel(Index numElements, const ParallelFor& parallelFor,
  const std::function<void(Index begin, Index end, FaceBlock& block)>& write)
{
  // Fixed ranges, not the ParallelFor's: its ranges are many small ones (its grain), and the
  // result must not depend on how the work was cut.
  const FixedRanges ranges(numElements, 64);
  std::vector<FaceBlock> written(static_cast<size_t>(ranges.NumRanges));
  ForEachBlock(ranges.NumRanges, parallelFor,
    [&](Index r) { write(ranges.Begin(r), ranges.Begin(r + 1), written[static_cast<size_t>(r)]); });

  std::vector<size_t> firstFace(written.size() + 1, 0), firstCorner(written.size() + 1, 0);
  for (size_t b = 0; b < written.size(); ++b)
  {
    firstFace[b + 1] = firstFace[b] + written[b].Ends.size();
    firstCorner[b + 1] = firstCorner[b] + written[b].Vertices.size();
  }
  EmittedFaces faces;
  faces.Offsets.resize(firstFace.back() + 1);
  faces.Offsets[0] = 0;
  faces.Vertices.resize(firstCorner.back());
  faces.Origins.resize(firstFace.back());
  faces.Holes.resize(firstFace.back());
  ForEachBlockPart(parallelFor, firstFace, [&](size_t b, size_t from, size_t to, size_t at) {
    const FaceBlock& block = written[b];
    const Index base = static_cast<Index>(firstCorner[b]);
    for (size_t i = from; i < to; ++i)
    {
      faces.Offsets[at + (i - from) + 1] = base + block.Ends[i];
    }
    std::copy(block.Origins.begin() + Offset(from), block.Origins.begin() + Offset(to), faces.Origins.begin() + Offset(at));
    std::copy(block.Holes.begin() + Offset(from), block.Holes.begin() + Offset(to), faces.Holes.begin() + Offset(at));
  }, [&written](size_t b) {
    FaceBlock& block = written[b];
    IndexArray().swap(block.Ends);
    IndexArray().swap(block.Origins);
    LevelArray<std::uint8_t>().swap(block.Holes);
  });
  ForEachBlockPart(parallelFor, firstCorner, [&](size_t b, size_t from, size_t to, size_t at) {
    const IndexArray& vertices = written[b].Vertices;
    std::copy(vertices.begin() + Offset(from), vertices.begin() + Offset(to), faces.Vertices.begin() + Offset(at));
  }, [&written](size_t b) { IndexArray().swap(written[b].Vertices); });
  return faces;
}
}
