// SubD kernel: child faces written in parallel, in the serial order, by splits that cannot
// tell beforehand how many faces (and corners) each parent element gives: the dual split
// (welded corners, one V-face per sector, vanishing faces) and sqrt(3) (flipped, kept or
// trisected edges).
//
// The parent's elements (numbered in the order their faces must come) are cut into ranges,
// each range writes its faces into a block of its own, and the blocks are then concatenated
// in element order, again in parallel. How the ranges are cut (the number of threads) does
// not change the result. Writing into blocks costs a copy of the faces, which is small next
// to working out what they are, and spares a counting pass that would do that work twice.
#ifndef SubDFaceBlocks_h
#define SubDFaceBlocks_h

#include "SubDParallel.h"
#include "SubDTypes.h"

#include <functional>
#include <vector>

namespace subd
{
/// The faces written for one range of parent elements.
struct SUBDKERNEL_EXPORT FaceBlock
{
  // Level arrays: a large block's memory goes back to the system when it is freed (as the
  // blocks are concatenated, EmitFacesInParallel), instead of staying with the C library.
  IndexArray Ends;                 ///< corner count after each face
  IndexArray Vertices;             ///< faces' corners; a face in progress is at the end
  IndexArray Origins;              ///< one per face
  LevelArray<std::uint8_t> Holes;  ///< one per face

  /// Room for `faces` faces of `corners` corners in all (a writer's estimate).
  void Reserve(size_t faces, size_t corners)
  {
    this->Ends.reserve(faces);
    this->Origins.reserve(faces);
    this->Holes.reserve(faces);
    this->Vertices.reserve(corners);
  }
  /// Starts a face: returns where its corners begin, for EndFaceWithoutRepeats.
  size_t BeginFace() const { return this->Vertices.size(); }
  /// Closes the face of the corners pushed since the last face ended.
  SUBD_ALWAYS_INLINE void EndFace(Index origin, std::uint8_t hole)
  {
    this->Ends.push_back(static_cast<Index>(this->Vertices.size()));
    this->Origins.push_back(origin);
    this->Holes.push_back(hole);
  }
  /// The same, without repeats of welded points (consecutive, or last = first); a face left
  /// with fewer than three corners is dropped.
  void EndFaceWithoutRepeats(size_t first, Index origin, std::uint8_t hole);
  /// Appends a triangle (inlined, one push per value: the sqrt(3) split writes every face
  /// so, and the out-of-line range insert was half of that split's instructions).
  SUBD_ALWAYS_INLINE void AddTriangle(Index a, Index b, Index c, Index origin, std::uint8_t hole)
  {
    this->Vertices.push_back(a);
    this->Vertices.push_back(b);
    this->Vertices.push_back(c);
    this->EndFace(origin, hole);
  }
};

/// The concatenated faces of all blocks.
struct EmittedFaces
{
  IndexArray Offsets;                ///< numFaces + 1 entries, from 0
  IndexArray Vertices;
  LevelArray<Index> Origins;
  LevelArray<std::uint8_t> Holes;
};

/// Runs write(begin, end, block) over ranges covering [0, numElements), each writing the
/// faces of its elements in order, and concatenates the blocks in element order.
SUBDKERNEL_EXPORT EmittedFaces EmitFacesInParallel(Index numElements, const ParallelFor& parallelFor,
  const std::function<void(Index begin, Index end, FaceBlock& block)>& write);
}

#endif
