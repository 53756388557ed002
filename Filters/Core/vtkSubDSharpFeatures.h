// Private helper of vtkSubDSurfaceFilter: the sharp features of a vtkPolyData in, and the
// refined ones out (conventions in DESIGN.md):
//
// - crease edges are the segments of the input's Lines (lines and polylines) that are edges
//   of the surface, with the cell-data array "Sharpness" (any numeric type, OpenSubdiv's
//   scale: 0 smooth, >= 10 infinitely sharp; without the array every line is infinitely
//   sharp). Segments that are not surface edges are passed through unchanged, with a
//   warning. Sharpness on a boundary edge changes nothing (boundary edges are infinitely
//   sharp already);
// - vertex sharpness is the point-data array "CornerSharpness";
// - holes are the faces whose cell-data array "Hole" is non-zero;
// - optionally, every edge whose faces meet at a dihedral angle above a feature angle is an
//   infinitely sharp crease.
//
// Out: the sharp edges of the finest level as 2-point lines with their decayed sharpness in
// "Sharpness" (boundary and non-manifold edges, sharp by rule, are not repeated), and the
// decayed vertex sharpness as "CornerSharpness", so that feeding the output to the same
// filter again continues the same surface.
#ifndef vtkSubDSharpFeatures_h
#define vtkSubDSharpFeatures_h

#include "SubDLevel.h"
#include "vtkType.h"

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

class vtkPolyData;
class vtkDataArray;
class vtkFieldData;
class vtkPoints;

/// The names of the arrays that carry the sharp features (a filter's properties, so that a
/// mesh whose creases or holes are tagged under other names needs no renaming). An empty
/// name means "no such array".
struct vtkSubDFeatureArrayNames
{
  std::string Sharpness = "Sharpness";             // cell data of the crease lines
  std::string CornerSharpness = "CornerSharpness"; // point data
  std::string Hole = "Hole";                       // cell data of the faces
};

/// The array of `data` called `name`; nullptr for an empty name or no such numeric array.
vtkDataArray* vtkSubDNamedArray(vtkFieldData* data, const std::string& name);

struct vtkSubDSharpFeatures
{
  // The features as read from the input (comparable, so cached stencils can be reused
  // when they did not change).
  std::vector<subd::Index> SegmentPoints; // two point ids per line segment
  std::vector<float> SegmentSharpness;
  std::vector<vtkIdType> SegmentCell;   // the input line cell of each segment
  std::vector<float> CornerSharpness;   // per input point; empty when absent
  std::vector<std::uint8_t> FaceIsHole; // per kept face; empty when no "Hole" array
  vtkSubDFeatureArrayNames Names;       // where they were read from, and are written to

  bool operator==(const vtkSubDSharpFeatures& other) const
  {
    return SegmentPoints == other.SegmentPoints && SegmentSharpness == other.SegmentSharpness &&
      CornerSharpness == other.CornerSharpness && FaceIsHole == other.FaceIsHole;
  }

  /// Reads the lines, "Sharpness", "CornerSharpness" and "Hole" (or the arrays `names`
  /// gives) of `input`. `faceCells` gives the input cell id of each kept face. Returns false
  /// with `error` set when a sharpness is negative or not a number (naming the cell or point).
  bool Read(vtkPolyData* input, const subd::LevelArray<vtkIdType>& faceCells, std::string& error,
    const vtkSubDFeatureArrayNames& names = vtkSubDFeatureArrayNames());

  /// True when anything is tagged (sharp segments, sharp vertices, holes).
  bool Any() const;

  /// The base-level tags on `topology`. Segments that are not edges of it are listed in
  /// `unmatched` (indices into the segments). With featureAngle > 0 (degrees), edges whose
  /// two faces' normals differ by more than it are made infinitely sharp too.
  subd::BaseTags ToBaseTags(const subd::MeshTopology& topology, vtkPoints* points,
    double featureAngle, subd::CreaseMethod method, std::vector<subd::Index>& unmatched) const;
};

/// Maps between finest-level points and output points (-1: a finest point not output).
struct vtkSubDOutputPointMap
{
  std::function<vtkIdType(subd::Index)> OutputOfFinest;
  std::function<subd::Index(vtkIdType)> FinestOfOutput;
};

/// Crease lines on the seams of a piece of a distributed mesh (vtkSubDSeamLineCopies): per
/// finest edge, 1 where the line is a copy that another piece outputs. Copies are left out, or,
/// with WriteCopies (ghost levels asked of the output), written and flagged in LineIsCopy (per
/// line written) to be marked as ghost cells.
struct vtkSubDSeamLines
{
  const std::vector<std::uint8_t>& EdgeIsCopy;
  bool WriteCopies = false;
  std::vector<std::uint8_t> LineIsCopy;
};

/// Writes the sharp features of `finest` to `output` (whose points and interpolated point
/// data are set; `arrays` pairs each input point-data array with its output array):
/// "CornerSharpness" (features.Names; when the input had it) with the decayed vertex sharpness, and the
/// Lines: the crease edges of `finest` (sharp, neither boundary nor non-manifold, both
/// points output), then the `unmatched` input segments passed through with copies of their
/// points (and point data) appended. With `seams`, crease lines another piece outputs are
/// handled as it says. Returns the sharpness of each line written, in order.
std::vector<float> vtkSubDWriteSharpFeatures(const vtkSubDSharpFeatures& features,
  const std::vector<subd::Index>& unmatched, const subd::Level& finest, const vtkSubDOutputPointMap& map,
  vtkPolyData* input, const std::vector<std::pair<vtkDataArray*, vtkDataArray*>>& arrays,
  vtkPolyData* output, vtkSubDSeamLines* seams = nullptr);

#endif
