// SubD kernel: the peak memory of a refinement and its evaluation, predicted from the base
// mesh's counts before anything is allocated (for size guards).
//
// The prediction follows what Refine and Hierarchy::Evaluate hold at their peak, level by
// level (Scheme::PredictChildCounts gives each level's counts):
// - a level's full topology: about 9 bytes per face, 16 per corner, 33 per edge and 13 per
//   vertex (the incidence lists, offsets, tags and sharpness of SubDMeshTopology.h and
//   SubDLevel.h); a faces-only level: 4 per corner and 4 per face;
// - rows written as they are applied (LevelRows::Written) keep every level above the finest,
//   with their writers' own arrays (about 4 bytes per corner and 9 per vertex); where the
//   finest level's parent is not built (SubDSmoothGrandchild.h) it is still counted: a
//   re-application builds it (BuildLevelBetween); stored tables
//   are counted at 8 entries per row, each level's topology living only while the next one is
//   refined;
// - the evaluation holds the output values and two levels of scratch values.
// The result adds EstimateMargin and the process's own code and data (EstimateLibraryBytes),
// so that it stays above the measured peak on the benchmark meshes.
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
};

/// The model's margin, and the process's own code and small data it adds.
constexpr double EstimateMargin = 1.25;
constexpr double EstimateLibraryBytes = 32.0 * 1024 * 1024;

/// The predicted peak memory in bytes (see above): EstimateMargin times the model, plus
/// EstimateLibraryBytes.
SUBDKERNEL_EXPORT double EstimatePeakBytes(const Scheme& scheme, const RefinementRequest& request);
}

#endif
