// SubD kernel: basic types shared by every kernel component.
//
// The kernel stores meshes in flat arrays indexed by 32-bit integers (no per-element
// allocation), so a level with tens of millions of faces stays compact and cache friendly.
#ifndef SubDTypes_h
#define SubDTypes_h

#include "SubDKernelModule.h" // export macro
#include <cstdint>
#include <cstddef>

namespace subd
{
using Index = std::int32_t;
constexpr Index InvalidIndex = -1;

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
/// level at four times the size of the one before, are only built when another level follows.
enum class ChildTopology : int
{
  Full = 0,
  FacesOnly = 1
};
}

#endif
