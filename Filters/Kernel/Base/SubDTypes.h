// SubD kernel: basic types shared by every kernel component.
//
// The kernel stores meshes in flat arrays indexed by 32-bit integers (no per-element
// allocation), so a level with tens of millions of faces stays compact and cache friendly.
#ifndef SubDTypes_h
#define SubDTypes_h

#include "SubDKernelModule.h" // export macro
#include <cstdint>
#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace subd
{
using Index = std::int32_t;
constexpr Index InvalidIndex = -1;

/// Inlines a function the compiler would call: the row writers' per-row masks
/// (VisitSmoothRow), whose call costs as much as a small row.
#if defined(__GNUC__) || defined(__clang__)
#define SUBD_ALWAYS_INLINE __attribute__((always_inline)) inline
#else
#define SUBD_ALWAYS_INLINE inline
#endif

/// Asks the processor to bring the cache line at `address` in ahead of a read. An asm
/// statement on x86: GCC 12 at -O2 deletes __builtin_prefetch in loops that have no other
/// effect (its aggressive dead-code elimination), which is what a look-ahead loop is.
inline void PrefetchForRead(const void* address) noexcept
{
#if defined(__x86_64__) || defined(__i386__)
  asm volatile("prefetcht0 %0" : : "m"(*static_cast<const char*>(address)));
#else
  __builtin_prefetch(address);
#endif
}

/// std::allocator, except that elements added without a value (resize, the size
/// constructor) are default-initialised: left as they are for int, float and plain structs.
/// Resizing a large array then writes no byte, so the first write to each page happens in
/// the (parallel) loop that fills it rather than in a serial zero-fill, which on a level of
/// tens of millions of elements is most of the cost of a serial pass. Every element must be
/// written before it is read; use assign() where zeros are meant.
template <typename T>
struct DefaultInitAllocator : std::allocator<T>
{
  DefaultInitAllocator() = default;
  template <typename U>
  DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept
  {
  }
  template <typename U>
  struct rebind
  {
    using other = DefaultInitAllocator<U>;
  };
  template <typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible<U>::value)
  {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args)
  {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

/// The kernel's large per-element arrays (see DefaultInitAllocator).
template <typename T>
using LevelArray = std::vector<T, DefaultInitAllocator<T>>;
using IndexArray = LevelArray<Index>;

/// A read-only view of contiguous indices (C++17 has no std::span).
struct IndexSpan
{
  const Index* Data = nullptr;
  Index Size = 0;

  const Index* begin() const { return Data; }
  const Index* end() const { return Data + Size; }
  Index operator[](Index i) const { return Data[i]; }
  Index size() const { return Size; }
  bool empty() const { return Size == 0; }
};

/// The entry of a two-entry span that is not `one` (one of them): the other face of a
/// two-faced edge, the other end of an edge. Without a branch, since which of the two `one`
/// is changes from item to item at random: a branch on it mispredicts every other time.
inline Index OtherOfTwo(IndexSpan two, Index one)
{
  return two[0] ^ two[1] ^ one;
}

/// The place (0, 1 or 2) of `x` among a triangle's three entries (x must be one of them),
/// without a branch (see OtherOfTwo).
inline Index PlaceInTriangle(const Index* three, Index x)
{
  return static_cast<Index>(three[1] == x) + 2 * static_cast<Index>(three[2] == x);
}

/// How the vertices of an open mesh's boundary are treated. The meanings are OpenSubdiv's
/// `Sdc::Options::VtxBoundaryInterpolation`, so results can be compared with it exactly:
/// - None: boundary edges still follow the boundary curve rule, but every face touching a
///   boundary vertex (whose boundary edges were not explicitly made infinitely sharp) is a
///   hole: it shapes its neighbours and is not emitted.
/// - EdgeOnly: boundary edges are infinitely sharp creases; a corner (a vertex with one face)
///   follows the crease rule.
/// - EdgeAndCorner: as EdgeOnly, and corners are infinitely sharp, so they are interpolated.
enum class BoundaryRule : int
{
  None = 0,
  EdgeOnly = 1,
  EdgeAndCorner = 2
};

SUBDKERNEL_EXPORT const char* ToString(BoundaryRule rule);

/// How much of a child level's topology a split builds. The last level of a refinement only
/// needs its faces (to be output); its edges and incidence relations, the costliest part of a
/// level at four times the size of the one before, are only built when another level follows
/// or the caller reads them (creases out, limit geometry).
enum class ChildTopology : int
{
  Full = 0,
  FacesOnly = 1
};
}

#endif
