// SubD kernel: the last two levels of a Catmull-Clark or Loop refinement at once, on a
// closed mesh without sharp features or holes, without building the level between.
//
// Rows written as they are applied keep the level they read (SubDRowWriting.h). For the
// finest level that is its parent P, the largest topology of the refinement: its full
// topology takes more bytes than the output itself. But where the grandparent G is closed,
// manifold and smooth, so is P, and every row of the finest level is the scheme's smooth
// mask; and P's neighbourhoods are known in closed form from G (PrimalSplitView). So the
// finest rows are written from G, a quarter of P, through the same mask functions
// (SubDCatmullClarkRules.h, SubDLoopRules.h) and in the order P's own row writer gives them
// (the same bits), and the finest faces are P's faces split again. What it costs: a row
// works its point's neighbourhood out each time it is applied, which makes applying them
// two to three times as slow. A refinement applied again and again (points that move) builds P
// when it is first applied again (BuildLevelBetween).
#ifndef SubDSmoothGrandchild_h
#define SubDSmoothGrandchild_h

#include "SubDRefiner.h"

#include <memory>

namespace subd
{
/// The rows of the finest level, read from the level between (whose points the
/// grandparent's own rows make), and the finest level: faces, holes and origins.
struct SmoothGrandchild
{
  std::shared_ptr<const RowSource> Rows;
  Level Finest;
};

/// Whether `scheme` can make the two levels below `grandparent` at once: Catmull-Clark on
/// quads or Loop, and a grandparent whose faces are closed and manifold, with no sharp edge
/// or vertex and no hole (points on no face stay where they are).
SUBDKERNEL_EXPORT bool HasSmoothGrandchild(const Scheme& scheme, const Level& grandparent);

/// The two levels below `grandparent` (HasSmoothGrandchild must hold). The rows keep it.
SUBDKERNEL_EXPORT SmoothGrandchild MakeSmoothGrandchild(
  const Scheme& scheme, std::shared_ptr<const Level> grandparent);

/// If the finest rows of `hierarchy` (made by Refine with `scheme`) are a SmoothGrandchild's,
/// replaces them with the scheme's own rows over the level between, built now: the same
/// points, applied two to three times as fast, for the memory of that level. Returns whether
/// it did.
SUBDKERNEL_EXPORT bool BuildLevelBetween(const Scheme& scheme, Hierarchy& hierarchy);
}

#endif
