// SubD kernel: splitting polygons into triangles for the triangle schemes.
//
// A fan from the first corner is only correct for convex polygons. Concave polygons (an L-
// or U-shaped face, common in CAD exports) are triangulated by ear clipping in the plane
// of the polygon's Newell normal: repeatedly cut off a convex corner whose triangle contains
// no other corner. Ear clipping is O(n^2); polygons above a size limit, and polygons where
// no ear exists (self-intersecting, or degenerate projections), fall back to the fan.
#ifndef SubDPolygonTriangulation_h
#define SubDPolygonTriangulation_h

#include "SubDTypes.h"
#include <vector>

namespace subd
{
/// Appends n - 2 triangles, as corner numbers 0..n-1, to `triangles`, with the polygon's
/// orientation. `xyz` holds the n corners' positions. Returns false if it fell back to a fan.
SUBDKERNEL_EXPORT bool TriangulatePolygon(const double* xyz, Index n, std::vector<Index>& triangles);

/// Polygons with more corners than this are fanned (ear clipping is quadratic).
constexpr Index EarClippingLimit = 512;
}

#endif
