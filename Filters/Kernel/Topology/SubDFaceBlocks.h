// SubD kernel: child faces written in parallel, in the serial order, by splits that cannot
// tell cheaply beforehand how many faces (and corners) each parent element gives: the dual
// split (welded corners, one V-face per sector, vanishing faces), sqrt(3)'s (flipped or
// kept edges, trisected faces).
//
// The parent's elements (numbered in the order their faces must come) are cut into at most
// 64 fixed ranges, each range writes its faces into a block of its own, and the blocks are
// then concatenated in element order, again in parallel. The number of threads does not
// change the result. Writing into blocks costs a copy of the faces, which is small next
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
  IndexArray Ends;                 ///< corner count after each face
  IndexArray Vertices;             ///< faces' corners; a face in progress is at the end
  IndexArray Origins;              ///< one per face
  LevelArray<std::uint8_t> Holes;  ///< one per face

  /// Starts a face: returns where its corners begin, for EndFaceWithoutRepeats.
  size_t BeginFace() const { return this->Vertices.size(); }
  /// A triangle, pushed and closed.
  void AddTriangle(Index a, Index b, Index c, Index origin, std::uint8_t hole)
  {
    this->Vertices.insert(this->Vertices.end(), { a, b, c });
    this->EndFace(origin, hole);
  }
  /// Closes the face of the corners pushed since the last face ended.
  void EndFace(Index origin, std::uint8_t hole)
  {
    this->Ends.push_back(static_cast<Index>(this->Vertices.size()));
    this->Origins.push_back(origin);
    this->Holes.push_back(hole);
  }
  /// The same, without repeats of welded points (consecutive, or last = first); a face left
  /// with fewer than three corners is dropped.
  void EndFaceWithoutRepeats(size_t first, Index origin, std::uint8_t hole);
};

/// The concatenated faces of all blocks.
struct EmittedFaces
{
  IndexArray Offsets;                ///< numFaces + 1 entries, from 0
  IndexArray Vertices;
  LevelArray<Index> Origins;         ///< one per face
  LevelArray<std::uint8_t> Holes;    ///< one per face
};

/// Runs write(begin, end, block) over at most 64 ranges covering [0, numElements), each
/// writing the faces of its elements in order, and concatenates the blocks in element order.
SUBDKERNEL_EXPORT EmittedFaces EmitFacesInParallel(Index numElements, const ParallelFor& parallelFor,
  const std::function<void(Index begin, Index end, FaceBlock& block)>& write);

}

#endif
