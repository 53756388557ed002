#include "SubDTypes.h"

#include <atomic>
#include <cstdlib>
#ifdef __linux__
#include <sys/mman.h>
#endif
#ifdef __GLIBC__
#include <malloc.h>
#endif

// Under AddressSanitizer large blocks come from malloc, which it watches; mapped memory it
// would not check.
#if defined(__SANITIZE_ADDRESS__)
#define SUBD_MAP_LARGE_BLOCKS 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SUBD_MAP_LARGE_BLOCKS 0
#endif
#endif
#if !defined(SUBD_MAP_LARGE_BLOCKS) && defined(__linux__)
#define SUBD_MAP_LARGE_BLOCKS 1
#elif !defined(SUBD_MAP_LARGE_BLOCKS)
#define SUBD_MAP_LARGE_BLOCKS 0
#endif

namespace subd
{
namespace
{
// Bytes of the blocks AllocateLargeBlock handed out and FreeLargeBlock has not taken back.
std::atomic<std::size_t> LargeBlockBytesInUse{ 0 };

// SUBD_HUGE_PAGES=1 in the environment (read once).
bool HugePagesRequested()
{
  static const bool requested = [] {
    const char* value = std::getenv("SUBD_HUGE_PAGES");
    return value && value[0] == '1';
  }();
  return requested;
}

// Blocks backed by huge pages (when asked, on Linux): from 4 MiB up, since each is rounded
// up to whole 2 MiB pages.
bool UsesHugePages(std::size_t bytes)
{
#ifdef __linux__
  return HugePagesRequested() && bytes >= (std::size_t(4) << 20);
#else
  (void)bytes;
  return false;
#endif
}
}

void* AllocateLargeBlock(std::size_t bytes)
{
  void* block = nullptr;
  if (UsesHugePages(bytes))
  {
#ifdef __linux__
    // Whole 2 MiB pages: aligned, and rounded up to a multiple.
    constexpr std::size_t hugePage = std::size_t(2) << 20;
    const std::size_t rounded = (bytes + hugePage - 1) / hugePage * hugePage;
    block = rounded >= bytes ? std::aligned_alloc(hugePage, rounded) : nullptr;
    if (block)
    {
      madvise(block, rounded, MADV_HUGEPAGE); // a hint: without huge pages nothing changes
    }
#endif
  }
  else if (SUBD_MAP_LARGE_BLOCKS)
  {
#if SUBD_MAP_LARGE_BLOCKS
    // Straight from the system, so that FreeLargeBlock gives it straight back: malloc keeps
    // freed blocks below its moving threshold (up to 32 MiB) for reuse, and those count in
    // the peak of every later phase that allocates larger ones.
    block = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    block = block == MAP_FAILED ? nullptr : block;
#endif
  }
  else
  {
    block = std::malloc(bytes);
  }
  if (!block)
  {
    throw std::bad_alloc();
  }
  LargeBlockBytesInUse += bytes;
  return block;
}

std::size_t GetLargeBlockBytesInUse() noexcept
{
  return LargeBlockBytesInUse;
}

void FreeLargeBlock(void* block, std::size_t bytes) noexcept
{
  LargeBlockBytesInUse -= bytes;
#if SUBD_MAP_LARGE_BLOCKS
  if (!UsesHugePages(bytes))
  {
    munmap(block, bytes);
    return;
  }
#endif
  std::free(block);
}

void ReleaseFreeMemory() noexcept
{
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}

const char* ToString(BoundaryRule rule)
{
  switch (rule)
  {
    case BoundaryRule::None:
      return "None";
    case BoundaryRule::EdgeOnly:
      return "EdgeOnly";
    case BoundaryRule::EdgeAndCorner:
      return "EdgeAndCorner";
  }
  return "Unknown";
}
}
