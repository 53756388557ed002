// SubD kernel: a small piece of a level, refined on its own, to evaluate the limit surface
// over one face at any depth (the local refinement of feature-adaptive evaluation: Niessner,
// Loop, Meyer, DeRose, "Feature-Adaptive GPU Rendering of Catmull-Clark Subdivision
// Surfaces", ACM TOG 2012, done on the CPU and only where it is needed).
//
// The piece around a face t is every face sharing a vertex with t. That is enough: the
// child points of t, and every child face sharing a vertex with a child of t, depend only
// on the vertex, edge and face points of t's corners, their edges and their faces, all of
// which the piece holds with their true neighbourhoods and tags. The piece's own border
// gets wrong (boundary) rules, but nothing computed from it is ever read. So a child c of t
// is evaluated on the piece around c in the refined piece, and so on down.
//
// Points are tracked as combinations of "support" points (the points of the first piece):
// refining applies the scheme's stencils to those combinations, so the result of an
// evaluation is a stencil over the original level's points, which then evaluates positions
// and any point data alike.
#ifndef SubDLocalLevel_h
#define SubDLocalLevel_h

#include "SubDScheme.h"

#include <vector>

namespace subd
{
struct SUBDKERNEL_EXPORT LocalLevel
{
  Level Mesh;                  ///< full topology and tags
  Index SupportSize = 0;       ///< number of support points
  std::vector<double> Weights; ///< per point of Mesh, SupportSize weights on the support

  const double* GetWeights(Index point) const { return Weights.data() + static_cast<size_t>(point) * SupportSize; }
};

/// The faces of `level` that share a vertex with `face` (`face` first, its corners in order,
/// so that its parametrisation is kept). The support is the piece's own points;
/// `supportPoints` receives their indices in `level`.
SUBDKERNEL_EXPORT LocalLevel ExtractLocalLevel(const Level& level, Index face, std::vector<Index>& supportPoints);

/// The same around face `face` of a local level; the support is kept. The face is face 0
/// of the result.
SUBDKERNEL_EXPORT LocalLevel ExtractLocalLevel(const LocalLevel& local, Index face);

/// Refines a local level one level with `scheme` (weights follow the stencils).
SUBDKERNEL_EXPORT LocalLevel RefineLocalLevel(const Scheme& scheme, const LocalLevel& local);

/// The child of face `face` at corner `corner` in the quad split (SubDQuadSplit.h) or, with
/// `triangleSplit`, the triangle split (SubDTriangleSplit.h; corner 3: the middle triangle).
SUBDKERNEL_EXPORT Index ChildFace(const Level& parent, Index face, Index corner, bool triangleSplit);
}

#endif
