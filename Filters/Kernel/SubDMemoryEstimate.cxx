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
  // On a closed manifold whose vertices have three faces or more, the midpoint's finest level
  // comes from its grandparent alone, which is split with its faces, their edges, its edges'
  // ends and its faces' origins only (SubDMidpointGrandchild.h); the levels above keep their
  // edges' ends for their rows. The filters ask for a faces-only finest level only without
  // sharp features and holes: the counts are then exact.
  const bool grandchildAlone = levels >= 2 && request.Finest == ChildTopology::FacesOnly &&
    (request.Rows == LevelRows::WrittenLean || request.Rows == LevelRows::WrittenFromGrandparent) &&
    request.ClosedManifoldBase && request.ThreeFacesAtEveryBaseVertex && scheme.MaySplitForGrandchildAlone();
  std::vector<MeshCounts> counts{ request.Base };
  for (int l = 0; l < levels; ++l)
  {
    counts.push_back(grandchildAlone ? scheme.PredictClosedSmoothChildCounts(counts.back())
                                     : scheme.PredictChildCounts(counts.back()));
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

  // Stored tables: each level's topology lives only while the next one is refined.
  const bool writesRows = request.Rows != LevelRows::Stored && scheme.MakeRowSource(std::make_shared<Level>());
  if (!writesRows)
  {
    double tables = 0.0, refinePeak = 0.0;
    for (int l = 0; l < levels; ++l)
    {
      refinePeak = std::max(refinePeak, tables + TopologyBytes(counts[l]) + TopologyBytes(counts[l + 1]));
      tables += counts[l + 1].Vertices * (8 * 12.0 + 8.0);
    }
    return std::max(refinePeak, tables + output + scratch);
  }

  // The midpoint's levels above the grandparent keep their edges' ends for their rows; each is
  // split with what its child keeps only.
  if (grandchildAlone)
  {
    auto edgeEnds = [](const MeshCounts& c) { return 8.0 * c.Edges + 4.0 * c.Vertices; };
    // Offsets, the faces' edges, the edges' ends and the faces' origins.
    auto facesWithEdges = [](const MeshCounts& c) { return 8.0 * c.Faces + 4.0 * c.Corners + 8.0 * c.Edges; };
    // The base is whole; the levels below it are split from their parent's faces' edges
    // (with a table of four entries per edge of the parent).
    double kept = 0.0, splitPeak = 0.0;
    for (int l = 0; l + 2 < levels; ++l)
    {
      const MeshCounts& level = counts[l];
      const double parent = l == 0 ? TopologyBytes(level) : facesWithEdges(level) + 16.0 * level.Edges;
      splitPeak = std::max(splitPeak, kept + parent + edgeEnds(level) + facesWithEdges(counts[l + 1]));
      kept += edgeEnds(level);
    }
    const MeshCounts& grandparent = counts[levels - 2];
    // The base is whole where it is the grandparent.
    kept += levels == 2 ? TopologyBytes(grandparent) : facesWithEdges(grandparent);
    return std::max(splitPeak, kept + output + scratch + 4.0 * finest.Faces); // and the faces' origins
  }

  // Rows that read a part of their parent's topology keep that part of each level, and what
  // they number their rows with (Doo-Sabin's dual numbering: 8 bytes per corner where
  // corners are welded, two per vertex, and the corners before sharp edges, few; the
  // midpoint's kept vertices;
  // sqrt(3)'s vertex rules and the faces of its centroids); each level is whole while it is
  // split.
  MeshTopology::Part part;
  if (scheme.WrittenRowsReadOnly(part))
  {
    // On a closed manifold the finest rows may come from the grandparent (sqrt(3)): the
    // grandparent's own rows then read the fans of its triangles (4 bytes per corner and per
    // vertex) instead of its rings; the finest level's parent comes without its rings and
    // sharpness, is freed after its split, and the rows' own table (each grandparent edge's
    // first half-edge) comes after it.
    const bool finestFromGrandparent = levels >= 2 && request.Finest == ChildTopology::FacesOnly &&
      (request.Rows == LevelRows::WrittenLean || request.Rows == LevelRows::WrittenFromGrandparent) &&
      request.ClosedManifoldBase && scheme.MayWriteFinestRowsFromGrandparent();
    double kept = 0.0, splitPeak = 0.0;
    for (int l = 0; l < levels; ++l)
    {
      const MeshCounts& c = counts[l];
      const double rows = part == MeshTopology::Part::Faces
        ? FacesBytes(c) + 8.0 * c.Corners + 2.0 * c.Vertices
        : part == MeshTopology::Part::EdgeEnds ? 8.0 * c.Edges + 4.0 * c.Vertices
                                               : FacesBytes(c) + 8.0 * c.Edges + 5.0 * c.Vertices + 4.0 * c.Faces;
      const bool last = l + 1 == levels;
      // The finest level's parent comes without its lists of faces around vertices and its
      // faces' edges where the finest split reads neither (Scheme::SplitAndTrim's leanChild).
      const bool leanChild = l + 2 == levels && request.Finest == ChildTopology::FacesOnly &&
        !scheme.FinestSplitReadsVertexFacesOrFaceEdges();
      const bool finestGrandparent = finestFromGrandparent && l + 2 == levels;
      const MeshCounts& next = counts[l + 1];
      const double child = last ? output - finest.Vertices * request.OutputBytesPerPoint
                                : TopologyBytes(next) - (leanChild ? 12.0 * next.Corners : 0.0) -
          (finestGrandparent ? 12.0 * next.Edges + 8.0 * next.Vertices : 0.0);
      // Refine frees the faces' edges and the lists of faces around the vertices before a
      // faces-only finest level is split, where neither the split nor the rows read them;
      // some splits free the lists of edges around the vertices.
      const bool facesOnlyLast = last && request.Finest == ChildTopology::FacesOnly;
      const bool splitAlone = last && finestFromGrandparent;
      const double released = (facesOnlyLast && !scheme.FinestSplitReadsVertexFacesOrFaceEdges() ? 12.0 * c.Corners : 0.0) +
        (facesOnlyLast && (splitAlone || scheme.FacesOnlySplitFreesVertexEdgeLists()) ? 8.0 * c.Edges + 4.0 * c.Vertices
                                                                                   : 0.0) +
        (splitAlone ? 4.0 * c.Vertices + 4.0 * c.Edges : 0.0);
      const double keptRows = splitAlone ? 0.0
        : finestGrandparent             ? FacesBytes(c) + 4.0 * c.Corners + 9.0 * c.Vertices
                                        : rows;
      splitPeak = std::max(splitPeak, kept + TopologyBytes(c) - released + keptRows + child);
      kept += keptRows;
    }
    if (finestFromGrandparent)
    {
      kept += 4.0 * counts[levels - 2].Edges;
    }
    return std::max(splitPeak, kept + output + scratch);
  }

  // Written rows keep the levels they are written from; with WrittenFromGrandparent (or the
  // linear schemes' finest level) the levels between are built one at a time, or not at all.
  const bool everyOther = request.Rows == LevelRows::WrittenFromGrandparent && scheme.RefinesFromGrandparent();
  const bool finestAlone = request.Finest == ChildTopology::FacesOnly && scheme.RefinesFromGrandparentAlone();
  double kept = 0.0, transient = 0.0;
  for (int l = 0; l < levels; ++l)
  {
    const bool between = l >= 1 && (everyOther ? (levels - l) % 2 == 1 : (finestAlone && l == levels - 1));
    if (!between)
    {
      // With the writers' own per-level arrays (the butterfly's rings, smooth-vertex flags).
      kept += TopologyBytes(counts[l]) + 4.0 * counts[l].Corners + 9.0 * counts[l].Vertices;
      continue;
    }
    kept += 4.0 * counts[l].Edges; // the numbering of its edges, kept by the rows
    transient = std::max(transient, finestAlone && l == levels - 1 ? 0.0 : TopologyBytes(counts[l]));
  }
  if (everyOther && request.Finest == ChildTopology::Full)
  {
    // A full finest level is split from its parent, which is released only then.
    transient = std::max(transient, TopologyBytes(counts[levels - 1]) + TopologyBytes(finest));
  }
  // LowMemory makes the faces after the points and keeps no scratch: they never meet.
  const double evaluation = everyOther && request.Finest == ChildTopology::FacesOnly
    ? finest.Vertices * request.OutputBytesPerPoint + std::max(scratch, FacesBytes(finest))
    : output + scratch;
  return kept + std::max(transient, evaluation);
}
}

double EstimatePeakBytes(const Scheme& scheme, const RefinementRequest& request)
{
  return EstimateMargin * ModelBytes(scheme, request) + EstimateLibraryBytes;
}
}
