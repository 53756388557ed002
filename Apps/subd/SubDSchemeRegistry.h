// subd: the one place that lists the schemes `subd --scheme` knows.
#ifndef SubDSchemeRegistry_h
#define SubDSchemeRegistry_h

#include "vtkSmartPointer.h"
#include <functional>
#include <string>
#include <vector>

class vtkPolyData;
class vtkPolyDataAlgorithm;

namespace subdapp
{
struct SchemeOptions
{
  int Levels = 2;
  int BoundaryRule = 1; // vtkSubDSurfaceFilter::BOUNDARY_EDGE_ONLY
  double Tension = 0.0; // butterfly and four-point (see TensionGiven)
  bool TensionGiven = false; // otherwise each scheme's default (butterfly 0, four-point 1/16)
  int CreaseMethod = 0;      // vtkSubDSurfaceFilter::CREASE_UNIFORM
  double FeatureAngle = 0.0; // > 0: edges sharper than this (degrees) become creases
  bool ProjectToLimit = false; // move the output points to the limit surface
  bool LimitNormals = false;   // add the exact limit normals
  bool LimitCurvature = false; // add the limit curvature arrays
  bool Tangents = false;       // curves: add the unit limit tangents
  bool Closed = false;         // curves: every polyline is closed
  bool CollapseRepeatedCorners = false; // surfaces: collapse polygons that repeat a point
  bool Weld = true;                      // surfaces: weld points split at seams
  int FaceVaryingInterpolation = 2;      // vtkSubDSurfaceFilter::FVAR_LINEAR_CORNERS_PLUS1
  bool SmoothTriangles = false;          // catmull-clark: OpenSubdiv's smooth triangle rule
  double Tolerance = 0.0; // > 0: catmull-clark and loop tessellate their limit surface to this
                          // fraction of the bounding-box diagonal, at most Levels deep
};

/// Whether two option sets configure a filter alike (the explorer reuses a view's result).
inline bool operator==(const SchemeOptions& a, const SchemeOptions& b)
{
  return a.Levels == b.Levels && a.BoundaryRule == b.BoundaryRule && a.Tension == b.Tension &&
    a.TensionGiven == b.TensionGiven && a.CreaseMethod == b.CreaseMethod && a.FeatureAngle == b.FeatureAngle &&
    a.ProjectToLimit == b.ProjectToLimit && a.LimitNormals == b.LimitNormals &&
    a.LimitCurvature == b.LimitCurvature && a.Tangents == b.Tangents && a.Closed == b.Closed &&
    a.CollapseRepeatedCorners == b.CollapseRepeatedCorners && a.Weld == b.Weld &&
    a.FaceVaryingInterpolation == b.FaceVaryingInterpolation && a.SmoothTriangles == b.SmoothTriangles &&
    a.Tolerance == b.Tolerance;
}
inline bool operator!=(const SchemeOptions& a, const SchemeOptions& b)
{
  return !(a == b);
}

struct SchemeEntry
{
  std::string Name;
  std::string Summary;
  bool Curve;          ///< refines the input's lines (vtkSubDCurveFilter), not its polygons
  bool LimitPositions; ///< ProjectToLimit works (limit masks, or interpolating)
  /// The exact limit evaluator: limit normals and curvature (LimitNormals, LimitCurvature), and
  /// the adaptive tessellation of the limit (Tolerance).
  bool LimitCurvature;
  /// A configured filter for the options.
  vtkSmartPointer<vtkPolyDataAlgorithm> (*Make)(const SchemeOptions&);
  /// --interpolate: the Scheme of vtkSubDInterpolateFilter (surfaces) or of
  /// vtkSubDCurveInterpolateFilter (curves) that solves for this scheme's cage; -1 when the
  /// scheme has none (InterpolationNote says why).
  int InterpolationScheme;
  const char* InterpolationNote;
};

class MessageCollector;

const std::vector<SchemeEntry>& Schemes();

/// Reports a filter's progress in [0, 1]; returning false asks the filter to stop.
using SchemeProgress = std::function<bool(double)>;

/// Runs `entry`'s filter on `input` with `options`, its messages going to `messages`. Returns
/// a copy of the output, or nullptr when the filter reported an error, made nothing, or was
/// stopped by `progress`.
vtkSmartPointer<vtkPolyData> RunScheme(const SchemeEntry& entry, const SchemeOptions& options, vtkPolyData* input,
  MessageCollector& messages, const SchemeProgress& progress = nullptr);
const SchemeEntry* FindScheme(const std::string& name);

/// The cage (or control polygons) whose limit passes through the points of `input`
/// (SchemeEntry::InterpolationScheme must be >= 0), or nullptr with the messages; the
/// number of interpolated points and the solve's residual.
struct InterpolationResult
{
  vtkSmartPointer<vtkPolyData> Cage;
  long long NumTagged = 0;
  double Residual = 0.0;
};
InterpolationResult RunInterpolation(
  const SchemeEntry& entry, const SchemeOptions& options, vtkPolyData* input, MessageCollector& messages);
}

#endif
