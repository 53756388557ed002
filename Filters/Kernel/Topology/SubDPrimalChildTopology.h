// SubD kernel: the full topology of a primal split's child (the quad split's and the
// triangle split's), derived from the parent's in closed form and in parallel.
//
// MeshTopology::Build finds a mesh's edges by sorting vertex pairs and its incidences by
// scattering every face corner: serial passes over the whole child, once the costliest part
// of a level. A split knows it all beforehand. Every child edge is a half of a parent edge
// or lies inside a parent face; the faces and edges around a child point are those around
// the parent face, edge or vertex it stands for. So each relation is written from the
// parent's, element by element, with the numbering and order Build gives:
//   - edges are numbered by first meeting, walking the child faces and their corners in
//     order. A half of parent edge e is first met in the first face of e, an edge inside a
//     face in that face: counting each parent face's new edges and summing the counts gives
//     every face the first number of its edges;
//   - incidence lists are sorted (faces and edges by index), as Build's scatters leave them;
//   - tags: a half keeps its parent edge's boundary and non-manifold tags (its faces are
//     the children of the parent edge's faces, oriented as they were), an edge point its
//     edge's, a vertex point its vertex's; everything inside a face is interior and manifold.
// The result equals MeshTopology::Build's on the same faces, for every input including
// non-manifold ones (tested), and does not depend on the number of threads. Except below a
// face that repeats a vertex: the two halves of its edge from that vertex to itself join the
// same two child points, two edges of one face each, as in OpenSubdiv (tested against it),
// where Build would make them one.
#ifndef SubDPrimalChildTopology_h
#define SubDPrimalChildTopology_h

#include "SubDLevel.h"
#include "SubDMeshTopology.h"
#include "SubDParallel.h"

#include <vector>

namespace subd
{
class SUBDKERNEL_EXPORT PrimalChildTopology
{
public:
  /// The child of the quad split of `parent` (SubDQuadSplit.h), whose faces (four corners
  /// each, numbered as the split numbers them) are `offsets` and `vertices`.
  static MeshTopology OfQuadSplit(
    const MeshTopology& parent, IndexArray offsets, IndexArray vertices, const ParallelFor& parallelFor);

  /// The child of the triangle split of the all-triangle `parent` (SubDTriangleSplit.h).
  static MeshTopology OfTriangleSplit(
    const MeshTopology& parent, IndexArray offsets, IndexArray vertices, const ParallelFor& parallelFor);

  enum class Split
  {
    Quads,
    Triangles
  };
  /// Finishes a primal split's child level from its faces: faces only, or the full topology
  /// derived from the parent's with the sharpness the child inherits (InheritPrimalSharpness).
  static void SetChildLevel(const Level& parent, Level& child, Split split, Index numChildVertices,
    IndexArray offsets, IndexArray vertices, ChildTopology depth, Index firstEdgePoint,
    Index firstVertexPoint, const ParallelFor& parallelFor);
};
}

#endif
