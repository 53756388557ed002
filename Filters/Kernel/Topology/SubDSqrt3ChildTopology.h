// SubD kernel: the full topology of a sqrt(3) step's child (SubDSqrt3Rules.h) in closed form
// and in parallel, for the case every level of a smooth closed surface is in: a closed
// manifold triangle mesh without sharp edges, where every old edge is flipped and nothing
// is trisected.
//
// The child points are the centroids (point f for face f) and the old vertices (F + v). Edge
// e, running a->b in its first face f1 and with f2 across, becomes the triangles
//   2e = (a, m2, m1) and 2e + 1 = (b, m1, m2).
// Every child edge is either a flipped edge (m1, m2), first met in triangle 2e, or a spoke
// joining an old vertex to the centroid of one of its faces, which lies in the triangles of
// the two edges of that face at the vertex and is first met in the one of the smaller edge.
// Counting the edges each old edge's two triangles meet first and summing the counts numbers
// the child edges as MeshTopology::Build does (by first meeting, walking the triangles in
// order); every other relation is written element by element in Build's order (incidence
// lists sorted), and every tag is zero. The result equals Build's on the same faces (tested)
// and does not depend on the number of threads. Other parents go through Build.
#ifndef SubDSqrt3ChildTopology_h
#define SubDSqrt3ChildTopology_h

#include "SubDLevel.h"
#include "SubDMeshTopology.h"

namespace subd
{
class SUBDKERNEL_EXPORT Sqrt3ChildTopology
{
public:
  /// Whether the closed form holds for the step from `parent`, whose child has `numPoints`
  /// points (nothing trisected: one centroid per face, then the old vertices).
  static bool Applies(const Level& parent, Index numPoints);

  /// The child topology, from the triangles the step wrote (`offsets`, `vertices`: two per
  /// old edge, in edge order). Requires Applies().
  static MeshTopology OfSqrt3Step(
    const MeshTopology& parent, IndexArray offsets, IndexArray vertices, const ParallelFor& parallelFor);

private:
  struct EdgeNames;
  /// Numbers the child edges (ends, triangles) and writes each triangle's edges.
  static void NumberEdges(const MeshTopology& parent, MeshTopology& child, EdgeNames& names,
    const ParallelFor& parallelFor);
  /// The faces and edges around each child point, and their offsets.
  static void WriteVertexLists(const MeshTopology& parent, const EdgeNames& names, MeshTopology& child,
    const ParallelFor& parallelFor);
};
}

#endif
