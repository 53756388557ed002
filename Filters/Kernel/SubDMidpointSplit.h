// SubD kernel: the midpoint split of Peters and Reif's "simplest subdivision scheme"
// (J. Peters, U. Reif, "The simplest subdivision scheme for smoothing polyhedra", ACM
// Transactions on Graphics 16(4), 1997).
//
// New points are the edge midpoints: edge e -> child point e. Child faces:
//   F-faces  one per face: the midpoints of its edges, in order (faces [0, F));
//   V-faces  one per manifold vertex: the midpoints of its edges in the order of the faces
//            around it (MeshTopology::GetOrderedVertexFaces).
// Boundaries are kept: a manifold boundary vertex also keeps its own point (child points
// E, E+1, ... in vertex order) and its V-face runs from it through the midpoints of its
// edges, so the refined boundary passes through the old boundary vertices and the
// midpoints of the boundary edges: the boundary polygon keeps its shape.
// Non-manifold vertices get no V-face (the surface opens there).
#ifndef SubDMidpointSplit_h
#define SubDMidpointSplit_h

#include "SubDLevel.h"
#include "SubDStencilTable.h"

namespace subd
{
/// The split and its stencils together: both depend on which boundary vertices are kept.
SUBDKERNEL_EXPORT LevelRefinement RefineMidpoint(const Level& parent, ChildTopology depth);
}

#endif
