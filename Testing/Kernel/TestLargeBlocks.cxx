// The memory of large arrays (subd::AllocateLargeBlock, SubDTypes.h): blocks handed out are
// whole and distinct, freed ones are kept for reuse only within their bounds, and a kept
// block's pages need no new page fault.
#include "SubDTypes.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>
#ifdef __linux__
#include <sys/resource.h>
#endif

// Blocks are mapped from the system on Linux, except under AddressSanitizer (malloc's).
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SUBD_TEST_BLOCKS_FROM_MALLOC
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || !defined(__linux__)
#define SUBD_TEST_BLOCKS_FROM_MALLOC
#endif

namespace
{
constexpr std::size_t MiB = std::size_t(1) << 20;

// Writes `value` over every byte of a block and checks they all read back.
bool FillAndCheck(void* block, std::size_t bytes, unsigned char value)
{
  auto* bytesOf = static_cast<unsigned char*>(block);
  std::memset(bytesOf, value, bytes);
  for (std::size_t i = 0; i < bytes; i += 997)
  {
    if (bytesOf[i] != value)
    {
      return false;
    }
  }
  return bytesOf[bytes - 1] == value;
}
}

TEST(LargeBlocks, ReusedBlocksAreWholeAndDistinct)
{
  subd::ReleaseFreeMemory();
  // Freed blocks of several sizes, then requests smaller and larger than each: every block
  // handed out holds its bytes, and live blocks never share one.
  std::vector<std::size_t> sizes = { MiB, 3 * MiB + 12345, 300 << 10, 2 * MiB };
  std::vector<void*> freed;
  for (std::size_t bytes : sizes)
  {
    void* block = subd::AllocateLargeBlock(bytes);
    ASSERT_TRUE(FillAndCheck(block, bytes, 0x5a));
    freed.push_back(block);
  }
  for (size_t i = 0; i < sizes.size(); ++i)
  {
    subd::FreeLargeBlock(freed[i], sizes[i]);
  }
  const std::vector<std::size_t> requests = { 5 * MiB, 700 << 10, MiB + 1, 2 * MiB, 260 << 10 };
  std::vector<void*> live;
  for (size_t i = 0; i < requests.size(); ++i)
  {
    live.push_back(subd::AllocateLargeBlock(requests[i]));
    ASSERT_TRUE(FillAndCheck(live.back(), requests[i], static_cast<unsigned char>(i + 1)));
  }
  for (size_t i = 0; i < requests.size(); ++i)
  {
    const auto* bytesOf = static_cast<const unsigned char*>(live[i]);
    for (std::size_t k = 0; k < requests[i]; k += 4093)
    {
      ASSERT_EQ(bytesOf[k], i + 1) << "block " << i << " was overwritten at byte " << k;
    }
    subd::FreeLargeBlock(live[i], requests[i]);
  }
  EXPECT_LE(subd::GetKeptLargeBlockBytes(), 8 * MiB);
  subd::ReleaseFreeMemory();
  EXPECT_EQ(subd::GetKeptLargeBlockBytes(), 0u);
}

TEST(LargeBlocks, KeptBlocksStayBoundedAndGoWhenMuchIsInUse)
{
  subd::ReleaseFreeMemory();
  const std::size_t inUseBefore = subd::GetLargeBlockBytesInUse();
  std::vector<void*> blocks;
  for (int i = 0; i < 20; ++i)
  {
    blocks.push_back(subd::AllocateLargeBlock(MiB));
    std::memset(blocks.back(), 1, MiB);
  }
  for (void* block : blocks)
  {
    subd::FreeLargeBlock(block, MiB);
  }
  EXPECT_EQ(subd::GetLargeBlockBytesInUse(), inUseBefore);
  EXPECT_LE(subd::GetKeptLargeBlockBytes(), 8 * MiB);
#ifndef SUBD_TEST_BLOCKS_FROM_MALLOC
  EXPECT_GE(subd::GetKeptLargeBlockBytes(), MiB);
#else
  EXPECT_EQ(subd::GetKeptLargeBlockBytes(), 0u); // malloc's blocks: none kept here
#endif
  // A request that takes the blocks in use past 32 MiB gives the kept ones back, and a block
  // larger than what may be kept is never kept.
  void* large = subd::AllocateLargeBlock(40 * MiB);
  EXPECT_EQ(subd::GetKeptLargeBlockBytes(), 0u);
  subd::FreeLargeBlock(large, 40 * MiB);
  EXPECT_EQ(subd::GetKeptLargeBlockBytes(), 0u);
}

#if defined(__linux__) && !defined(SUBD_TEST_BLOCKS_FROM_MALLOC)
namespace
{
long MinorFaults()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

// The page faults taken writing a block of `bytes` just allocated.
long FaultsToFill(std::size_t bytes, void*& block)
{
  block = subd::AllocateLargeBlock(bytes);
  const long before = MinorFaults();
  std::memset(block, 7, bytes);
  return MinorFaults() - before;
}
}

TEST(LargeBlocks, AReusedBlockTakesNoNewPageFaults)
{
  subd::ReleaseFreeMemory();
  const std::size_t bytes = 4 * MiB;
  void* block = nullptr;
  const long fresh = FaultsToFill(bytes, block); // about one per 4 KiB page
  subd::FreeLargeBlock(block, bytes);
  const long reused = FaultsToFill(bytes / 2, block); // the same pages, shrunk
  subd::FreeLargeBlock(block, bytes / 2);
  const long grown = FaultsToFill(bytes, block); // half of them new again
  subd::FreeLargeBlock(block, bytes);
  subd::ReleaseFreeMemory();
  EXPECT_GT(fresh, 256) << "a fresh block should fault its pages in";
  EXPECT_LT(reused, fresh / 8);
  EXPECT_LT(grown, 3 * fresh / 4);
}
#endif
