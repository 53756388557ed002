// Private helper of SubD's filters that work on the cage itself (vtkSubDLimitFilter,
// vtkSubDInterpolateFilter): the input polygons as a kernel base level.
#ifndef vtkSubDCage_h
#define vtkSubDCage_h

#include "SubDFaceVarying.h"
#include "SubDLevel.h"
#include "SubDMeshValidation.h" // RepeatedCorners
#include "vtkSubDSeams.h"
#include "vtkPolyData.h"

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

// The cage as a kernel level, its points, and the input cell id of each face.
struct vtkSubDCage
{
  subd::Level Level;
  std::vector<double> Points;
  subd::LevelArray<vtkIdType> FaceCell;             ///< input cell id of each face
  std::unordered_map<vtkIdType, subd::Index> FaceOfCell; ///< and back
  std::vector<std::uint8_t> FaceIsGhost;            ///< 1 for a ghost cell of a piece; empty if none is
  /// Points welded at texture seams, and the point-data arrays that differ across them
  /// (face-varying: vtkSubDSeams.h); none unless read with welding.
  vtkSubDSeams Seams;
  /// The face-varying channel of the seams (vtkSubDMakeCageChannel): its faces are the cage's,
  /// corner for corner, its vertices the input points with their own data.
  subd::FaceVaryingBase Channel;

  bool HasChannel() const { return this->Seams.Any(); }
  /// Which side of a seam a point of face f is on (0 without seams), so that the output has a
  /// point per side: at corner k, the channel's vertex there; inside edge k, the channel's
  /// vertices at its ends, in the edge's own direction.
  std::int64_t SeamSideOfCorner(subd::Index f, subd::Index k) const;
  std::int64_t SeamSideOfEdge(subd::Index f, subd::Index k) const;
};

/// Builds cage.Channel from cage.Seams with `mode` (OpenSubdiv's face-varying interpolation).
void vtkSubDMakeCageChannel(vtkSubDCage& cage, subd::FaceVaryingInterpolation mode);

/// How the cage's faces are taken: as they are (Catmull-Clark), triangles only (Loop on a
/// given cage), or with other polygons split into triangles as the Loop filter splits them.
enum class vtkSubDCageFaces
{
  Polygons,
  Triangles,
  Triangulated
};

/// Reads `input`'s polygons (screened as vtkSubDSurfaceFilter screens them: degenerate ones
/// dropped and polygons repeating a point kept or collapsed, as `repeated` says, with a
/// warning), their ghost marks (a piece of a distributed mesh: the non-manifold warning counts
/// only its own faces) and sharp features into `cage`. Triangulated: polygons with more than
/// three corners are split (with a warning), and are then not in FaceOfCell. `weld`: points at
/// one position become one vertex, as vtkSubDSurfaceFilter welds them (cage.Seams). False, with the
/// reason in `error`, for no polygons, a non-finite point, an id outside the points, or (as
/// `faces` asks) a face that is not a triangle.
bool vtkSubDReadCage(vtkPolyData* input, vtkSubDCageFaces faces, subd::RepeatedCorners repeated,
  subd::BoundaryRule rule, subd::CreaseMethod creasing, vtkSubDCage& cage, std::string& error, std::string& warning,
  bool weld = false);

#endif
