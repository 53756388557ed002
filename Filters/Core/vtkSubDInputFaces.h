// Private helper of SubD's filters: the faces of an input vtkPolyData (polygons, then the
// triangles of its strips) as one offsets/connectivity pair with the input cell id of each,
// and the check for points that cannot be subdivided.
#ifndef vtkSubDInputFaces_h
#define vtkSubDInputFaces_h

#include "SubDMeshValidation.h" // RepeatedCorners, FaceScreening
#include "vtkType.h"

#include <cstdint>
#include <string>
#include <vector>

namespace subd
{
class MeshTopology;
}
class vtkPoints;
class vtkPolyData;

// Polygons are read in place when there are no strips.
struct vtkSubDInputFaces
{
  const vtkIdType* Offsets = nullptr;
  const vtkIdType* Connectivity = nullptr;
  vtkIdType NumFaces = 0;
  std::vector<vtkIdType> OwnedOffsets, OwnedConnectivity;
  vtkIdType FirstPolyCellId = 0;
  std::vector<vtkIdType> StripCellIds; // cell id of faces past the polygons

  vtkIdType CellIdOf(vtkIdType face, vtkIdType numPolys) const
  {
    return face < numPolys ? this->FirstPolyCellId + face : this->StripCellIds[face - numPolys];
  }
};

/// The faces of `input`. A strip p0 p1 p2 p3 ... gives the triangles (p0 p1 p2), (p2 p1 p3), ...
vtkSubDInputFaces vtkSubDGatherFaces(vtkPolyData* input);

/// `faces` screened (subd::ScreenFaces, on vtkSMPTools' threads) with the input's words for
/// what was found: false and an `error` for point ids that do not exist; a `warning` ("" when
/// nothing was repaired) counting the faces that repeat a corner (kept or collapsed, as
/// `repeated` says) and the faces dropped, each with its first cell.
bool vtkSubDScreenFaces(const vtkSubDInputFaces& faces, vtkIdType numPoints, vtkIdType numPolys,
  subd::RepeatedCorners repeated, subd::FaceScreening& screened, std::string& error, std::string& warning);

/// Splits every face of `faces` with more than three corners into triangles (ear clipping, so
/// that concave polygons come out right; SubDPolygonTriangulation.h), each triangle keeping
/// its polygon's entry in KeptFaces. Returns how many faces were split.
subd::Index vtkSubDTriangulateFaces(subd::FaceScreening& faces, vtkPoints* points);

/// The warning for `split` polygons split into triangles (without a full stop).
std::string vtkSubDSplitPolygonsWarning(subd::Index split);

/// The first point with a NaN or infinite coordinate, or -1.
vtkIdType vtkSubDFirstNonFinitePoint(vtkPoints* points);

/// The first cell (verts, lines, polygons, strips: VTK's cell order) naming a point id outside
/// [0, number of points), or -1.
vtkIdType vtkSubDFirstCellOutsidePoints(vtkPolyData* input);

/// The warning for a non-manifold input ("" when it is manifold): such edges and vertices are
/// subdivided as infinitely sharp, as OpenSubdiv does. For a piece with ghost faces (1 in
/// `faceIsGhost`), only the edges and vertices of its own faces count. What a face repeating a
/// point makes non-manifold by itself is not counted: vtkSubDScreenFaces' warning tells it.
std::string vtkSubDNonManifoldWarning(
  const subd::MeshTopology& topology, const std::vector<std::uint8_t>& faceIsGhost = {});

#endif
