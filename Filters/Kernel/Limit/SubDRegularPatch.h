// SubD kernel: faces whose limit surface is a polynomial patch, and their control points.
//
// Away from extraordinary vertices and features, Catmull-Clark is the uniform bicubic
// B-spline (Catmull, Clark 1978) and Loop the quartic three-direction box spline (Loop 1987),
// so the limit over a face is one polynomial patch of its 1-ring:
//
// - Catmull-Clark: a quad whose corners are smooth of valence 4; or, along infinitely sharp
//   creases and boundaries, a crease corner whose side of the crease has 2 quads, or a
//   corner vertex whose face is alone between its two sharp edges. Points beyond the crease
//   are replaced by "phantom" points reflected through it, P' = 2 P_crease - P_inside, which
//   makes the B-spline reproduce the crease rules exactly (the crease is then the cubic
//   B-spline of its points and the corner stays put); this is how OpenSubdiv's regular
//   boundary and corner patches are built. 16 points on a 4x4 grid, row-major in (u, v):
//   point 4 j + i at grid (i, j), the face's corners at (1,1), (2,1), (2,2), (1,2).
// - Loop: a triangle whose corners are smooth of valence 6, or crease corners whose side of
//   the crease has 3 triangles; beyond the crease, the phantom a + b - c of each triangle abc
//   on it (the box spline then reproduces Loop's crease rules). 12 points of the triangular
//   lattice in the order of BoxSplineLattice(), the face's corners first at (0,0), (1,0), (0,1).
//
// Semi-sharp edges or vertices at a corner, and transitions, make a face irregular: it is
// refined until they decay.
#ifndef SubDRegularPatch_h
#define SubDRegularPatch_h

#include "SubDLevel.h"

namespace subd
{
enum class PatchKind : std::uint8_t
{
  BSpline = 0,  ///< Catmull-Clark: 16 points
  BoxSpline = 1 ///< Loop: 12 points
};

/// A patch control point: a point of the level, or a phantom combination of up to four.
struct PatchPoint
{
  int Count = 0;
  Index Points[4];
  double Weights[4];
};

struct RegularPatch
{
  PatchKind Kind;
  int NumPoints = 0; ///< 16 or 12
  PatchPoint Points[16];
};

/// The 12 lattice positions (a, b) of the box-spline patch (the triangle (0,0), (1,0), (0,1)
/// and its 1-ring; a along corner 0 -> 1, b along corner 0 -> 2).
SUBDKERNEL_EXPORT const int (&BoxSplineLattice())[12][2];

/// True if the vertex at corner `corner` of `face` has a rule that stays the same from level
/// to level: its edges and itself smooth or infinitely sharp (semi-sharp ones decay), no
/// transition, and all its faces of `faceSize` sides (4 Catmull-Clark, 3 Loop).
SUBDKERNEL_EXPORT bool IsStableCorner(const Level& level, Index face, Index corner, Index faceSize);

/// True if the vertex at corner `corner` of `face` lets the face be regular (see above).
SUBDKERNEL_EXPORT bool IsRegularCorner(const Level& level, Index face, Index corner, PatchKind kind);

/// If `face` is regular, fills its control points and returns true.
SUBDKERNEL_EXPORT bool GatherRegularPatch(const Level& level, Index face, PatchKind kind, RegularPatch& patch);

/// The faces around corner `corner` of `face` that lie between the same sharp edges (the
/// whole fan without them), in order around the vertex (a non-manifold vertex: the faces
/// reached without crossing a non-manifold edge). Used to find the side of a crease a face is on.
SUBDKERNEL_EXPORT std::vector<Index> SectorFaces(const Level& level, Index face, Index corner);

/// True if the edge can be crossed within a smooth region: two faces, manifold, not sharp.
SUBDKERNEL_EXPORT bool IsSmoothInteriorEdge(const Level& level, Index e);
}

#endif
