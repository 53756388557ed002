// The memory of large arrays (AllocateLargeBlock, SubDTypes.h): mapped from the system and
// given back to it when freed, except for a few freed blocks kept while little is in use.
#include "SubDTypes.h"

#include <atomic>
#include <cstdlib>
#include <mutex>
#ifdef __linux__
#include <sys/mman.h>
#include <unistd.h>
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

#if SUBD_MAP_LARGE_BLOCKS
// A few freed blocks, still mapped, for the next requests: a fresh mapping costs a page
// fault per 4 KiB page written (about a third of a small refinement's time on the benchmark
// VM), a kept one none for the pages it already has, so that the scratch a small refinement
// frees holds its next arrays. Blocks are kept only while the large blocks in use stay
// under KeepWhileInUseBelow, and the first request beyond that gives them all back: a large
// refinement's peak never holds a kept block, and a process holds at most KeptBytesAtMost
// it does not use.
class FreedBlocks
{
public:
  static constexpr std::size_t KeepWhileInUseBelow = std::size_t(32) << 20;
  static constexpr std::size_t KeptBytesAtMost = std::size_t(8) << 20;

  // A kept block resized to `bytes` (the smallest that holds them, else the largest, grown:
  // its pages are reused either way), or nullptr.
  void* Take(std::size_t bytes, std::size_t inUse)
  {
    const std::lock_guard<std::mutex> lock(this->Lock);
    if (inUse + bytes >= KeepWhileInUseBelow)
    {
      this->UnmapAll();
      return nullptr;
    }
    if (this->Count == 0)
    {
      return nullptr;
    }
    // A block that holds the bytes beats one that does not; among those that do, the
    // smallest; among those that do not, the largest.
    auto better = [bytes](std::size_t a, std::size_t b) {
      const bool aHolds = a >= bytes, bHolds = b >= bytes;
      if (aHolds != bHolds)
      {
        return aHolds;
      }
      return aHolds ? a < b : a > b;
    };
    int best = 0;
    for (int i = 1; i < this->Count; ++i)
    {
      best = better(this->Blocks[i].Bytes, this->Blocks[best].Bytes) ? i : best;
    }
    const Block block = this->Blocks[best];
    this->Blocks[best] = this->Blocks[--this->Count];
    this->KeptBytes -= block.Bytes;
    void* resized = mremap(block.Address, block.Bytes, bytes, MREMAP_MAYMOVE);
    if (resized == MAP_FAILED)
    {
      munmap(block.Address, block.Bytes);
      return nullptr;
    }
    return resized;
  }

  // Keeps a freed block if there is room, else gives it back.
  void Keep(void* address, std::size_t bytes, std::size_t inUse)
  {
    const std::lock_guard<std::mutex> lock(this->Lock);
    const std::size_t mapped = RoundToPages(bytes);
    if (inUse >= KeepWhileInUseBelow || this->Count == MaxBlocks || this->KeptBytes + mapped > KeptBytesAtMost)
    {
      munmap(address, bytes);
      return;
    }
    this->Blocks[this->Count++] = { address, mapped };
    this->KeptBytes += mapped;
  }

  std::size_t GetKeptBytes()
  {
    const std::lock_guard<std::mutex> lock(this->Lock);
    return this->KeptBytes;
  }

  void Release()
  {
    const std::lock_guard<std::mutex> lock(this->Lock);
    this->UnmapAll();
  }

private:
  static std::size_t RoundToPages(std::size_t bytes)
  {
    static const std::size_t page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
    return (bytes + page - 1) / page * page;
  }
  void UnmapAll()
  {
    for (int i = 0; i < this->Count; ++i)
    {
      munmap(this->Blocks[i].Address, this->Blocks[i].Bytes);
    }
    this->Count = 0;
    this->KeptBytes = 0;
  }

  struct Block
  {
    void* Address;
    std::size_t Bytes; // whole pages
  };
  static constexpr int MaxBlocks = 16;
  std::mutex Lock;
  Block Blocks[MaxBlocks];
  int Count = 0;
  std::size_t KeptBytes = 0;
};

// Never destroyed: blocks may be freed by static destructors after this file's would run.
FreedBlocks& GetFreedBlocks()
{
  static FreedBlocks* blocks = new FreedBlocks;
  return *blocks;
}
#endif
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
    block = GetFreedBlocks().Take(bytes, LargeBlockBytesInUse);
    if (!block)
    {
      block = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
      block = block == MAP_FAILED ? nullptr : block;
    }
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
    GetFreedBlocks().Keep(block, bytes, LargeBlockBytesInUse);
    return;
  }
#endif
  std::free(block);
}

std::size_t GetKeptLargeBlockBytes() noexcept
{
#if SUBD_MAP_LARGE_BLOCKS
  return GetFreedBlocks().GetKeptBytes();
#else
  return 0;
#endif
}

void ReleaseFreeMemory() noexcept
{
#if SUBD_MAP_LARGE_BLOCKS
  GetFreedBlocks().Release();
#endif
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}
}
