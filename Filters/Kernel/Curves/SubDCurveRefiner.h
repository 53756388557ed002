// SubD kernel: refines a set of curves level by level into stencil tables.
//
// Input curves (polylines of point ids, open or closed) are first cut into *pieces* at their
// corners: a piece is a polygon that one scheme refines on its own (SubDCurveRules.h). The
// end points of open pieces are *anchors*: every scheme interpolates them, so a point shared
// by several pieces (a corner, the joint of two polylines) stays one point at every level.
//
// Numbering of a level's points: the anchors first (the same anchors at every level), then
// the interior points of each piece, piece after piece. The first stencil table of the
// hierarchy gathers this numbering from the input point ids (so every piece owns its interior
// points, even when polylines share them); each further table is one level.
#ifndef SubDCurveRefiner_h
#define SubDCurveRefiner_h

#include "SubDCurveRules.h"
#include "SubDRefiner.h"

#include <vector>

namespace subd
{
struct SUBDKERNEL_EXPORT CurvePieces
{
  std::vector<Index> Offsets{ 0 };
  std::vector<Index> Points;
  std::vector<unsigned char> Closed; ///< a closed piece lists each point once
  Index NumAnchors = 0;             ///< points 0 .. NumAnchors-1 are anchors (refined levels)

  Index GetNumPieces() const { return static_cast<Index>(Offsets.size()) - 1; }
  IndexSpan GetPiece(Index p) const
  {
    return IndexSpan{ Points.data() + Offsets[p], Offsets[p + 1] - Offsets[p] };
  }
  bool IsClosed(Index p) const { return IsClosedPolygon(Offsets[p + 1] - Offsets[p], Closed[p] != 0); }
  void AddPiece(const Index* begin, const Index* end, bool closed);
};

/// Polylines given as offsets + point ids (a closed polyline lists each point once and has
/// closed[line] set). `isCorner` (per point, may be empty) marks the sharp corners.
struct CurveLines
{
  const std::vector<Index>* Offsets = nullptr;
  const std::vector<Index>* Ids = nullptr;
  const std::vector<unsigned char>* Closed = nullptr;
  const std::vector<unsigned char>* IsCorner = nullptr;
};

/// Cuts every polyline at its corners: an open polyline at each interior corner; a closed one
/// with corners is opened at its first corner and then cut at the others (its pieces start
/// and end at corners). `firstPiece` (size lines + 1) gives each polyline's pieces, in order.
SUBDKERNEL_EXPORT void SplitAtCorners(const CurveLines& lines, CurvePieces& pieces, std::vector<Index>& firstPiece);

/// The number of points `levels` levels of `rules` make of `pieces` (with their shared
/// anchors counted once), as a double so that a caller can refuse a request before overflow.
SUBDKERNEL_EXPORT double PredictCurvePoints(const CurveRules& rules, const CurvePieces& pieces, int levels);

/// Refines `base` (pieces over input point ids < numBasePoints) `levels` times. `out` gets the
/// gather table and one table per level; `finest` the pieces in the finest numbering.
/// Returns false if progress asked to stop.
SUBDKERNEL_EXPORT bool RefineCurves(const CurveRules& rules, Index numBasePoints, const CurvePieces& base,
  int levels, Hierarchy& out, CurvePieces& finest, const ProgressCallback& progress = nullptr);
}

#endif
