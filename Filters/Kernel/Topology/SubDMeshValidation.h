// SubD kernel: checks and repairs polygon lists before a topology is built from them.
//
// Subdivision rules assume every face has at least three distinct corners. Real meshes break
// that (repeated ids from welding, two-point "faces", out-of-range ids from broken files), so
// faces are screened once here: consecutive repeated corners are collapsed, faces left with
// fewer than three corners or repeating a vertex elsewhere are dropped and counted, and
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
struct FaceScreening
{
  IndexArray Offsets{ 0 };          ///< kept faces, offsets
  IndexArray Vertices;              ///< kept faces, corners
  IndexArray KeptFaces;             ///< for each kept face, its index in the input
  Index NumOutOfRange = 0;          ///< faces naming a vertex outside [0, numVertices)
  Index FirstOutOfRangeFace = InvalidIndex;
  Index FirstOutOfRangeId = InvalidIndex;
  Index NumDropped = 0;             ///< faces with < 3 distinct corners or repeated vertices
  Index FirstDroppedFace = InvalidIndex;
  Index NumCollapsedCorners = 0;    ///< consecutive duplicates removed from kept faces
};

/// Screens `numFaces` faces given as offsets (numFaces+1 entries) into `vertices`.
/// IdType is any integer type (VTK's vtkIdType, or Index). A mesh that needs no repair (the
/// usual case) is checked and copied on `parallelFor`'s threads.
template <typename IdType>
FaceScreening ScreenFaces(Index numVertices, Index numFaces, const IdType* offsets, const IdType* vertices,
  const ParallelFor& parallelFor = SerialFor);

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

// Face f (corners [begin, end)) of the repair pass: appended with its repeated consecutive
// corners collapsed, or counted as out of range or dropped.
template <typename IdType>
void ScreenFace(Index f, Index numVertices, const IdType* vertices, IdType begin, IdType end, FaceScreening& s,
  std::vector<Index>& scratch)
{
  auto drop = [&s, f]() {
    s.FirstDroppedFace = s.NumDropped == 0 ? f : s.FirstDroppedFace;
    ++s.NumDropped;
  };
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
    const Index v = static_cast<Index>(vertices[k]);
    if (s.Vertices.size() > start && s.Vertices.back() == v)
    {
      ++s.NumCollapsedCorners;
      continue;
    }
    s.Vertices.push_back(v);
  }
  while (s.Vertices.size() > start + 1 && s.Vertices.back() == s.Vertices[start])
  {
    s.Vertices.pop_back();
    ++s.NumCollapsedCorners;
  }
  const Index n = static_cast<Index>(s.Vertices.size() - start);
  if (n < 3 || HasRepeatedVertex(s.Vertices.data() + start, n, scratch))
  {
    s.Vertices.resize(start);
    drop();
    return;
  }
  s.Offsets.push_back(static_cast<Index>(s.Vertices.size()));
  s.KeptFaces.push_back(f);
}

template <typename IdType>
FaceScreening ScreenFaces(Index numVertices, Index numFaces, const IdType* offsets, const IdType* vertices,
  const ParallelFor& parallelFor)
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
      ScreenFace(f, numVertices, vertices, begin, end, s, scratch);
      continue;
    }
    s.FirstDroppedFace = s.NumDropped == 0 ? f : s.FirstDroppedFace;
    ++s.NumDropped;
  }
  return s;
}
}

#endif
