#include "SubDTypes.h"

#include <cstdlib>
#ifdef __linux__
#include <sys/mman.h>
#endif
#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace subd
{
namespace
{
// SUBD_HUGE_PAGES=1 in the environment (read once).
bool HugePagesRequested()
{
  static const bool requested = [] {
    const char* value = std::getenv("SUBD_HUGE_PAGES");
    return value && value[0] == '1';
  }();
  return requested;
}
}

void* AllocateLargeBlock(std::size_t bytes)
{
  void* block = nullptr;
#ifdef __linux__
  if (HugePagesRequested())
  {
    // Whole 2 MiB pages: aligned, and rounded up to a multiple.
    constexpr std::size_t hugePage = std::size_t(2) << 20;
    const std::size_t rounded = (bytes + hugePage - 1) / hugePage * hugePage;
    block = rounded >= bytes ? std::aligned_alloc(hugePage, rounded) : nullptr;
    if (block)
    {
      madvise(block, rounded, MADV_HUGEPAGE); // a hint: without huge pages nothing changes
    }
  }
  else
#endif
  {
    block = std::malloc(bytes);
  }
  if (!block)
  {
    throw std::bad_alloc();
  }
  return block;
}

void FreeLargeBlock(void* block) noexcept
{
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
