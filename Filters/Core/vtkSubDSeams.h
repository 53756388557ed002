// Private helper of vtkSubDSurfaceFilter: points that VTK's readers split at texture seams.
//
// vtkOBJReader, vtkGLTFReader and their kind give a point per (position, texture coordinate,
// normal) combination, so a textured surface arrives cut along every seam. Welding makes the
// points at one position one vertex again (the first of them), so that the surface is
// subdivided whole. Each point-data array whose values differ between welded points is then
// face-varying: its values are refined as a channel (SubDFaceVarying.h) whose values are the
// input's points with distinct data, so its seams are where the input was split and the data
// differ, and the output is split there again, each side with its own values (the filter's
// output points are the channel's); the other arrays stay vertex data.
#ifndef vtkSubDSeams_h
#define vtkSubDSeams_h

#include "SubDFaceVarying.h"
#include "SubDMeshValidation.h"
#include "SubDRefiner.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkCellArray;
class vtkPolyData;

struct vtkSubDSeams
{
  /// Per screened face corner, the channel's value: the first input point with the
  /// position and data of the point the corner named (points split where their data agree
  /// are no seam); empty when no welded points differ in their data.
  subd::IndexArray ValueOfCorner;
  /// The point-data arrays (by index in the input's point data) whose values differ across
  /// welded points.
  std::vector<int> Arrays;
  /// Per input point, the point it was welded to (itself if none); empty if none was.
  std::vector<subd::Index> WeldedTo;
  bool Any() const { return !this->Arrays.empty(); }
  bool operator==(const vtkSubDSeams& other) const
  {
    return this->ValueOfCorner == other.ValueOfCorner && this->Arrays == other.Arrays &&
      this->WeldedTo == other.WeldedTo;
  }
};

/// Welds the input's points that have identical coordinates in `screened` (every corner
/// renamed to the first point at its position) and returns the seams that leaves. `byData`
/// (schemes that cannot refine a channel) welds only points whose point data are equal too,
/// so that no seam is left. Faces that welding leaves with a point repeated they did not
/// repeat before are dropped (counted in `numDropped`).
vtkSubDSeams vtkSubDWeldCoincidentPoints(
  vtkPolyData* input, subd::FaceScreening& screened, bool byData, subd::Index& numDropped);

/// The channel of the seams, refined with the mesh; cached with the mesh's refinement.
struct vtkSubDSeamChannel
{
  subd::Hierarchy Hierarchy;
  subd::IndexArray UserValue; ///< per base channel vertex: its input point
  // The split output, made once per topology: a point per finest channel vertex that an
  // output face uses, in the channel's order.
  // Both empty when every value is output (the identity): the common case.
  std::vector<vtkIdType> OutputPointOfValue; ///< per finest channel vertex (-1: no output face uses it)
  std::vector<vtkIdType> ValueOfOutput;      ///< per output point
};

/// Refines the seams' channel of the mesh's base level `base` with the mesh's scheme.
/// `limit` appends the channel's limit table (ProjectToLimit). False with `error` if the
/// limit masks do not apply; false without one if progress asked to stop.
bool vtkSubDRefineSeams(const subd::Scheme& scheme, const subd::Level& base, const vtkSubDSeams& seams,
  subd::FaceVaryingInterpolation mode, int levels, bool limit, vtkSubDSeamChannel& channel, std::string& error);

/// The output split at the seams: a point per finest channel vertex that one of the finest
/// faces `emitted` (nullptr: all) uses (the channel's faces correspond to the mesh's corner
/// for corner).
/// Fills the channel's maps, per output point the finest mesh point it is
/// (`finestPointOfOutput`) and per finest mesh point one of its output points, -1 for none
/// (`outputPointOfFinest`).
void vtkSubDSelectSplitOutput(const subd::MeshTopology& finest, const std::vector<subd::Index>* emitted,
  vtkSubDSeamChannel& channel, std::vector<vtkIdType>& finestPointOfOutput, std::vector<vtkIdType>& outputPointOfFinest);

/// Adds the face-varying arrays of `input` (seams.Arrays), refined by the channel, to the
/// split output's point data (points beyond the channel's, ends of lines passed through, get
/// zeros). False if `progress` asked to stop.
bool vtkSubDAddFaceVaryingArrays(vtkPolyData* input, const vtkSubDSeams& seams, const vtkSubDSeamChannel& channel,
  const subd::ProgressCallback& progress, vtkPolyData* output);

#endif
