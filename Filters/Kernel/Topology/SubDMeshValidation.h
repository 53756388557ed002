// SubD kernel: checks and repairs polygon lists before a topology is built from them.
//
// Real meshes break the rules a subdivision scheme assumes (repeated ids from welding,
// two-point "faces", out-of-range ids from broken files), so faces are screened once here.
// A face that names a vertex at two corners is either kept as it is, as OpenSubdiv keeps it
// (MeshTopology::Build makes its degenerate edges non-manifold), or collapsed: consecutive
// repeats removed, the face dropped if a vertex still repeats. Faces left with fewer than
// three corners, or fewer than two distinct vertices, are dropped; all of it is counted, and
// out-of-range ids are reported (the caller refuses such input).
#ifndef SubDMeshValidation_h
#define SubDMeshValidation_h

#include "SubDParallel.h"
#include "SubDTypes.h"

#include <algorithm>
#include <atomic>
#include <vector>

namespace subd
{
/// What screening does with a face that names one vertex at several corners.
enum class RepeatedCorners
{
  Collapse,       ///< consecutive repeats removed; dropped if a vertex still repeats
  Keep,           ///< kept as it is if it has two distinct vertices (OpenSubdiv's semantics)
  KeepInTriangles ///< Keep for triangles, Collapse for larger faces (for schemes that triangulate them)
};

struct FaceScreening
{
  IndexArray Offsets{ 0 };          ///< kept faces, offsets
  IndexArray Vertices;              ///< kept faces, corners
  IndexArray KeptFaces;             ///< for each kept face, its index in the input
  Index NumOutOfRange = 0;          ///< faces naming a vertex outside [0, numVertices)
  Index FirstOutOfRangeFace = InvalidIndex;
  Index FirstOutOfRangeId = InvalidIndex;
  Index NumDropped = 0;             ///< faces with < 3 corners, < 2 distinct vertices, or repeats left
  Index FirstDroppedFace = InvalidIndex;
  Index NumRepeating = 0;           ///< faces (in range) naming a vertex at several corners
  Index FirstRepeatingFace = InvalidIndex;
  Index NumRepeatingKept = 0;       ///< of those, kept with their repeats
  Index NumRepeatingCollapsed = 0;  ///< of those, collapsed and kept
  Index NumCollapsedCorners = 0;    ///< consecutive duplicates removed from kept faces
};

/// Screens `numFaces` faces given as offsets (numFaces+1 entries) into `vertices`.
/// IdType is any integer type (VTK's vtkIdType, or Index). A mesh that needs no repair (the
/// usual case) is checked and copied on `parallelFor`'s threads.
template <typename IdType>
FaceScreening ScreenFaces(Index numVertices, Index numFaces, const IdType* offsets, const IdType* vertices,
  const ParallelFor& parallelFor = SerialFor, RepeatedCorners repeated = RepeatedCorners::Collapse);

/// True when the n corners hold a vertex twice (n small: pairwise, else sorted copy).
SUBDKERNEL_EXPORT bool HasRepeatedVertex(const Index* corners, Index n, std::vector<Index>& scratch);

/// Whether face [begin, end) of `vertices` is kept as it is by ScreenFaces: at least three
/// corners, all in range, no vertex twice. Faces of more than 16 corners are left to
/// ScreenFaces' own loop (false).
template <typename IdType>
bool IsCleanFace(Index numVertices, const IdType* vertices, IdType begin, IdType end)
{
  const IdType n = end - begin;
  if (n < 3 || n > 16)
  {
    return false;
  }
  bool clean = true;
  for (IdType i = begin; i < end; ++i)
  {
    clean &= vertices[i] >= 0 && vertices[i] < static_cast<IdType>(numVertices);
    for (IdType j = begin; j < i; ++j)
    {
      clean &= vertices[i] != vertices[j];
    }
  }
  return clean;
}

// Screens and copies every face on threads in one pass, for the common mesh that needs no
// repair; false (s partly written) as soon as a face is out of [first, last) or not clean.
template <typename IdType>
bool CopyCleanFaces(Index numVertices, Index numFaces, const IdType* offsets, const IdType* vertices, IdType first,
  IdType last, const ParallelFor& parallelFor, FaceScreening& s)
{
  s.Offsets.resize(static_cast<size_t>(numFaces) + 1);
  s.Vertices.resize(static_cast<size_t>(last - first));
  s.KeptFaces.resize(static_cast<size_t>(numFaces));
  s.Offsets[0] = 0;
  std::atomic<bool> allClean{ true };
  parallelFor(0, numFaces, [&](Index begin, Index end) {
    for (Index f = begin; f < end; ++f)
    {
      const IdType b = offsets[f], e = offsets[f + 1];
      if (!(first <= b && b <= e && e <= last) || !IsCleanFace(numVertices, vertices, b, e))
      {
        allClean = false;
        return;
      }
      s.Offsets[f + 1] = static_cast<Index>(e - offsets[0]);
      for (IdType k = b; k < e; ++k)
      {
        s.Vertices[static_cast<size_t>(k - offsets[0])] = static_cast<Index>(vertices[k]);
      }
      s.KeptFaces[f] = f;
    }
  });
  return allClean;
}

// Removes the consecutive repeats of the n corners (the last and the first included); returns
// how many are left.
SUBDKERNEL_EXPORT Index CollapseRepeatedCorners(Index* corners, Index n);

// Face f (corners [begin, end)) of the repair pass: appended as it is, or with its repeated
// consecutive corners collapsed, or counted as out of range or dropped.
template <typename IdType>
void ScreenFace(Index f, Index numVertices, const IdType* vertices, IdType begin, IdType end,
  RepeatedCorners repeated, FaceScreening& s, std::vector<Index>& scratch)
{
  for (IdType k = begin; k < end; ++k)
  {
    if (vertices[k] < 0 || vertices[k] >= static_cast<IdType>(numVertices))
    {
      if (s.NumOutOfRange++ == 0)
      {
        s.FirstOutOfRangeFace = f;
        s.FirstOutOfRangeId = static_cast<Index>(vertices[k] < 0 ? -1 : vertices[k]);
      }
      return;
    }
  }
  const size_t start = s.Vertices.size();
  for (IdType k = begin; k < end; ++k)
  {
    s.Vertices.push_back(static_cast<Index>(vertices[k]));
  }
  Index* corners = s.Vertices.data() + start;
  Index n = static_cast<Index>(end - begin);
  if (HasRepeatedVertex(corners, n, scratch))
  {
    s.FirstRepeatingFace = s.NumRepeating++ == 0 ? f : s.FirstRepeatingFace;
    const bool keep = repeated == RepeatedCorners::Keep || (repeated == RepeatedCorners::KeepInTriangles && n == 3);
    if (keep)
    {
      const bool twoDistinct = std::any_of(corners, corners + n, [corners](Index v) { return v != corners[0]; });
      n = twoDistinct ? n : 0;
      s.NumRepeatingKept += twoDistinct && n >= 3;
    }
    else
    {
      const Index left = CollapseRepeatedCorners(corners, n);
      s.NumCollapsedCorners += n - left;
      n = HasRepeatedVertex(corners, left, scratch) ? 0 : left;
      s.NumRepeatingCollapsed += n >= 3;
    }
  }
  if (n < 3)
  {
    s.Vertices.resize(start);
    s.FirstDroppedFace = s.NumDropped++ == 0 ? f : s.FirstDroppedFace;
    return;
  }
  s.Vertices.resize(start + static_cast<size_t>(n));
  s.Offsets.push_back(static_cast<Index>(s.Vertices.size()));
  s.KeptFaces.push_back(f);
}

template <typename IdType>
FaceScreening ScreenFaces(Index numVertices, Index numFaces, const IdType* offsets, const IdType* vertices,
  const ParallelFor& parallelFor, RepeatedCorners repeated)
{
  FaceScreening s;
  // A face whose corners are not within [offsets[0], offsets[numFaces]) (offsets that go
  // down: a corrupt cell array) is dropped unread.
  const IdType first = offsets[0], last = std::max(offsets[0], offsets[numFaces]);
  if (CopyCleanFaces(numVertices, numFaces, offsets, vertices, first, last, parallelFor, s))
  {
    return s;
  }
  s = FaceScreening();
  s.Offsets.reserve(static_cast<size_t>(numFaces) + 1);
  s.Vertices.reserve(static_cast<size_t>(last - first));
  s.KeptFaces.reserve(static_cast<size_t>(numFaces));
  std::vector<Index> scratch;
  for (Index f = 0; f < numFaces; ++f)
  {
    const IdType begin = offsets[f], end = offsets[f + 1];
    if (first <= begin && begin <= end && end <= last)
    {
      ScreenFace(f, numVertices, vertices, begin, end, repeated, s, scratch);
      continue;
    }
    s.FirstDroppedFace = s.NumDropped++ == 0 ? f : s.FirstDroppedFace;
  }
  return s;
}
}

#endif
