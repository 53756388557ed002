#include "SubDMemoryEstimate.h"

#include <algorithm>
#include <vector>

namespace subd
{
namespace
{
double TopologyBytes(const MeshCounts& c)
{
  return 9.0 * c.Faces + 16.0 * c.Corners + 33.0 * c.Edges + 13.0 * c.Vertices;
}

double FacesBytes(const MeshCounts& c)
{
  return 4.0 * c.Corners + 4.0 * c.Faces;
}

// The model's bytes at the peak, without margin.
double ModelBytes(const Scheme& scheme, const RefinementRequest& request)
{
  const int levels = std::max(request.Levels, 0);
  std::vector<MeshCounts> counts{ request.Base };
  for (int l = 0; l < levels; ++l)
  {
    counts.push_back(scheme.PredictChildCounts(counts.back()));
  }
  const MeshCounts& finest = counts.back();
  const double output = finest.Vertices * request.OutputBytesPerPoint +
    (request.Finest == ChildTopology::Full ? TopologyBytes(finest) : FacesBytes(finest));
  if (levels == 0)
  {
    return output;
  }
  double scratch = 0.0;
  for (int l = std::max(levels - 2, 1); l < levels; ++l)
  {
    scratch += counts[l].Vertices * request.ScratchBytesPerPoint;
  }

  const bool writesRows = request.Rows == LevelRows::Written && scheme.MakeRowSource(std::make_shared<Level>());
  if (!writesRows)
  {
    // Stored tables: each level's topology lives only while the next one is refined.
    double tables = 0.0, refinePeak = 0.0;
    for (int l = 0; l < levels; ++l)
    {
      refinePeak = std::max(refinePeak, tables + TopologyBytes(counts[l]) + TopologyBytes(counts[l + 1]));
      tables += counts[l + 1].Vertices * (8 * 12.0 + 8.0);
    }
    return std::max(refinePeak, tables + output + scratch);
  }
  // Written rows keep the levels they are written from, with their writers' own arrays.
  double kept = 0.0;
  for (int l = 0; l < levels; ++l)
  {
    kept += TopologyBytes(counts[l]) + 4.0 * counts[l].Corners + 9.0 * counts[l].Vertices;
  }
  return kept + output + scratch;
}
}

double EstimatePeakBytes(const Scheme& scheme, const RefinementRequest& request)
{
  return EstimateMargin * ModelBytes(scheme, request) + EstimateLibraryBytes;
}
}
