// Test support: the heap a test's work holds, where it can be measured.
#ifndef SubDTestHeap_h
#define SubDTestHeap_h

#include <cstddef>
#include <malloc.h>

// The AddressSanitizer build's allocator is not the one mallinfo2 sees.
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SUBD_HEAP_NOT_MEASURABLE
#endif
#endif
// SUBD_HEAP_MEASURABLE: the heap in use can be read (glibc 2.33's mallinfo2, no ASan).
#if defined(__GLIBC__) && !defined(SUBD_HEAP_NOT_MEASURABLE) && (__GLIBC__ > 2 || __GLIBC_MINOR__ >= 33)
#define SUBD_HEAP_MEASURABLE
namespace subdtest
{
/// The heap in use: the C library's small blocks and its mapped large ones.
inline std::size_t HeapInUse()
{
  return mallinfo2().uordblks + mallinfo2().hblkhd;
}
}
#endif

#endif
