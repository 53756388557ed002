// Private helper of vtkSubDSurfaceFilter: one piece of a distributed mesh, as VTK's parallel
// pipeline hands it over (vtkExtractPolyDataPiece, parallel readers, ParaView's pvbatch and
// pvserver): the piece's own cells plus layers of ghost cells around them, marked by the
// DUPLICATECELL bit of the cell-data array "vtkGhostType".
//
// The filter subdivides own and ghost faces together, so that every point its own faces'
// children need sees the whole neighbourhood its stencils read, and outputs only the children
// of its own faces: the union of the pieces' outputs is the serial output. A child face comes
// from one base face (Level::FaceOrigin). For the primal schemes and sqrt(3) that face is
// determined by the child's place in it; children made from several faces (Doo-Sabin's and
// the midpoint scheme's edge and vertex faces) come from the lowest-numbered of them. So that
// every piece agrees on it, such schemes number a piece's faces in an order all pieces share:
// by global id (the cell data's GlobalIds attribute) when there is one, else by their corners'
// coordinates, which are the same bits in every piece that holds the face. (With global ids
// equal to the serial cell ids, the children inherit the cell data the serial ones do; in
// coordinate order a face made from two faces may inherit the other one's. Two faces on the
// very same points would be ordered by chance.)
//
// Asked for G ghost levels itself, the filter asks upstream for G more layers than it needs
// and also outputs the children of the first G layers of ghost faces, marked as ghost cells.
#ifndef vtkSubDPieces_h
#define vtkSubDPieces_h

#include "SubDLevel.h"
#include "SubDMeshValidation.h"
#include "vtkType.h"

#include <cstdint>
#include <string>
#include <vector>

class vtkInformation;
class vtkInformationVector;
class vtkPolyData;

/// RequestUpdateExtent of a piece-aware filter: passes the piece asked of `outInfo` to `inInfo`
/// with `requiredLevels` layers of ghost cells plus those asked of the output, when the data is
/// split into several pieces (none otherwise).
void vtkSubDRequestPieceWithGhosts(vtkInformation* inInfo, vtkInformation* outInfo, int requiredLevels);

/// The piece a filter's output was asked for (RequestData of a piece-aware filter).
struct vtkSubDPieceRequest
{
  int Piece = 0;
  bool OneOfMany = false;   ///< one piece of several
  int OutputGhostLevels = 0; ///< ghost levels asked of the output (0 for a whole mesh)

  explicit vtkSubDPieceRequest(vtkInformation* outInfo);
  /// One of several pieces without polygons: an empty output, not an error.
  bool IsEmptyPiece(vtkPolyData* input) const;
  /// A piece other than the first of several: a filter computing on the whole mesh outputs
  /// nothing there, and piece 0 holds its whole result.
  bool IsLaterPiece() const { return this->OneOfMany && this->Piece > 0; }
};

/// RequestUpdateExtent of a filter whose result depends on the whole mesh at once (a global
/// solve): each of its `numPorts` inputs is asked for all of it (piece 0 of 1, no ghost cells).
void vtkSubDRequestWholeInput(vtkInformationVector** inputVector, int numPorts);

/// The warning of a filter given piece `piece` without any of the `requiredLevels` layers of
/// ghost cells it asked for.
std::string vtkSubDMissingGhostsWarning(int piece, int requiredLevels);

/// Per kept face (`faceCells` gives its input cell): 1 where that cell is a ghost cell. Empty
/// when none is.
std::vector<std::uint8_t> vtkSubDGhostFaces(vtkPolyData* input, const subd::LevelArray<vtkIdType>& faceCells);

/// Per face of `topology`: 0 for the piece's own faces, k for ghost faces k layers out (sharing a
/// vertex with a face of layer k - 1), up to `maxLayer`; 255 beyond. `faceIsGhost` as above.
std::vector<std::uint8_t> vtkSubDGhostLayers(
  const subd::MeshTopology& topology, const std::vector<std::uint8_t>& faceIsGhost, int maxLayer);

/// Gives `output`, whose cells carry "vtkGhostType", the matching point array: DUPLICATEPOINT
/// on the points of no cell of its own.
void vtkSubDMarkGhostPoints(vtkPolyData* output);

/// True when input cell `cell` is a ghost cell.
bool vtkSubDIsGhostCell(vtkPolyData* input, vtkIdType cell);

/// Each kept face's position in the order every piece agrees on (that of
/// vtkSubDOrderFacesAlikeInEveryPiece): of two faces several pieces hold, all find the same
/// one first.
std::vector<subd::Index> vtkSubDFaceRanksAlikeInEveryPiece(
  vtkPolyData* input, const subd::FaceScreening& faces, const subd::LevelArray<vtkIdType>& faceCells);

/// Per edge of `finest`: 1 where the crease line on it is a copy another piece outputs. A sharp
/// edge on a seam, or at a corner where three pieces meet, is in several pieces; it goes with
/// the first of its faces' base faces in the shared order (`baseFaceRank`; `faceGhostLayer` as
/// vtkSubDGhostLayers gives), so that exactly one piece owns it.
std::vector<std::uint8_t> vtkSubDSeamLineCopies(
  const subd::Level& finest, const std::vector<std::uint8_t>& faceGhostLayer, const std::vector<subd::Index>& baseFaceRank);

/// Reorders the kept faces (and `faceCells`, their input cells) into an order every piece
/// agrees on: increasing global cell id, else increasing sorted corner coordinates. Faces of
/// one cell (the triangles of a split polygon) keep their order.
void vtkSubDOrderFacesAlikeInEveryPiece(
  vtkPolyData* input, subd::FaceScreening& faces, subd::LevelArray<vtkIdType>& faceCells);

#endif
