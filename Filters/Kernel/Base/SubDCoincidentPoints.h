// SubD kernel: points at one position.
//
// Readers split a mesh's points at texture seams (a point per position and texture
// coordinate); the filters weld them back and the scene shades them as one surface. Both find
// the points that share a position here, exactly (no tolerance: the copies a reader makes are
// bit for bit equal), with -0 and +0 one position.
#ifndef SubDCoincidentPoints_h
#define SubDCoincidentPoints_h

#include "SubDTypes.h"

#include <vector>

namespace subd
{
/// Per point of `xyz` (`numPoints` points, three doubles each), the first point at exactly its
/// position: itself if none comes before it.
SUBDKERNEL_EXPORT std::vector<Index> FirstPointAtSamePosition(const double* xyz, Index numPoints);
}

#endif
