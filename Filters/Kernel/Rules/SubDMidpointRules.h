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
// midpoints of the boundary edges: the boundary polygon keeps its shape. A kept vertex
// with a single face in its sector gets no V-face (it would be a sliver triangle of three
// points on the boundary): the kept point becomes a corner of that face's F-face.
// Creases are treated like boundaries (ActsAsBoundary): a vertex with two or more crease or
// boundary edges, or a sharp vertex, is kept too, and its fan of faces is cut into sectors
// at those edges, each sector with its own V-face from the kept point through the
// midpoints; the midpoint of a crease edge is shared by both sides. A crease therefore
// keeps its polyline exactly, and each side of it is refined as if it were a boundary. A
// kept vertex with fewer than two such edges in a closed fan (a sharp vertex inside smooth
// surface or at a dart) has its fan cut at every edge: it becomes a corner of each F-face
// around it.
// A crease ending at a dart loses half of its last edge per level (the dart is not kept).
// Semi-sharp edges act as creases while their sharpness is positive; the halves of a
// crease edge inherit its sharpness one level down by the crease method
// (ChildEdgeSharpness), a kept vertex its vertex sharpness less one.
// Non-manifold vertices get no V-face (the surface opens there), nor do smooth vertices of
// two faces (whose V-face would have two sides): the two F-faces share an edge instead.
#ifndef SubDMidpointRules_h
#define SubDMidpointRules_h

#include "SubDLevel.h"
#include "SubDStencilTable.h"

#include <memory>

namespace subd
{
/// True for a vertex the split keeps (a child point of its own): on a boundary, sharp, or
/// with two or more crease edges; never a non-manifold or isolated one.
SUBDKERNEL_EXPORT bool MidpointKeepsVertex(const Level& level, Index v);

/// The split and its stencils together: both depend on which boundary vertices are kept.
SUBDKERNEL_EXPORT LevelRefinement RefineMidpoint(
  const Level& parent, ChildTopology depth, const ParallelFor& parallelFor = SerialFor);
/// The split alone (RefineMidpoint's child).
SUBDKERNEL_EXPORT Level SplitMidpoint(const Level& parent, ChildTopology depth, const ParallelFor& parallelFor = SerialFor);
/// RefineMidpoint's rows written as they are applied (SubDRowWriting.h): each midpoint from
/// its edge's ends, each kept vertex copied.
SUBDKERNEL_EXPORT std::shared_ptr<const RowSource> MakeMidpointRowSource(std::shared_ptr<const Level> parent);
}

#endif
