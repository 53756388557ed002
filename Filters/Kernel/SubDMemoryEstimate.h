// SubD kernel: the peak memory of a refinement and its evaluation, predicted from the base
// mesh's counts before anything is allocated (for size guards).
//
// The prediction follows what Refine and Hierarchy::Evaluate hold at their peak, level by
// level (Scheme::PredictChildCounts gives each level's counts):
// - a level's full topology: about 9 bytes per face, 16 per corner, 33 per edge and 13 per
//   vertex (the incidence lists, offsets, tags and sharpness of SubDMeshTopology.h and
//   SubDLevel.h); a faces-only level: 4 per corner and 4 per face;
// - rows written as they are applied keep every level above the finest (LevelRows::Written),
//   with their writers' own arrays (4 bytes per corner and 9 per vertex: the butterfly's
//   rings), or only every other one (WrittenFromGrandparent, whose levels between are built
//   and released one at a time, or not at all for the linear schemes' finest level's parent);
//   stored tables are counted at 8 entries per row;
// - the evaluation holds the output values and two levels of scratch values, except with
//   LowMemory, whose faces are made after the points once the scratch is freed.
// On the benchmark meshes (every scheme, levels 2 to 5) the result, 25 % and the process's
// libraries included, is 1.1 to 1.3 times the peak RSS for the schemes that write their rows
// and up to 3.7 times for those that store them (Doo-Sabin, sqrt(3), midpoint): never below.
#ifndef SubDMemoryEstimate_h
#define SubDMemoryEstimate_h

#include "SubDRefiner.h"
#include "SubDScheme.h"

namespace subd
{
/// What a refinement is asked to do, for EstimatePeakBytes.
struct RefinementRequest
{
  MeshCounts Base;
  int Levels = 0;
  ChildTopology Finest = ChildTopology::FacesOnly;
  LevelRows Rows = LevelRows::Written;
  double OutputBytesPerPoint = 24.0;  ///< the finest values kept (points, point data)
  double ScratchBytesPerPoint = 24.0; ///< the values of the levels between (in double)
  /// The base has no boundary, no non-manifold edge or vertex and no vertex without faces:
  /// then sqrt(3)'s finest rows may come from the grandparent
  /// (Scheme::MayWriteFinestRowsFromGrandparent); false counts the general path.
  bool ClosedManifoldBase = false;
  /// Besides, every vertex of the base has three faces or more: then, with a faces-only
  /// finest level (no sharp feature, no hole), the midpoint's finest level comes from its
  /// grandparent alone (Scheme::MaySplitForGrandchildAlone).
  bool ThreeFacesAtEveryBaseVertex = false;
};

/// The model's margin, and the process's own code and small data it adds.
constexpr double EstimateMargin = 1.25;
constexpr double EstimateLibraryBytes = 32.0 * 1024 * 1024;

/// The predicted peak memory in bytes (see above): EstimateMargin times the model, plus
/// EstimateLibraryBytes.
SUBDKERNEL_EXPORT double EstimatePeakBytes(const Scheme& scheme, const RefinementRequest& request);
}

#endif
