// SubD kernel: the full topology of the dual split's child (SubDDualSplit.h) in closed form
// and in parallel, for the case every level of a smooth closed surface is in: a closed
// manifold parent whose vertices all have three faces or more, with nothing welded.
//
// There the child is regular in a way the split fixes beforehand. Its points are the
// parent's face corners; each lies on four faces (its F-face, the E-faces of the two parent
// edges at the corner, its vertex's V-face) and four edges. With C parent corners and E
// parent edges, walking the child faces in order (as MeshTopology::Build numbers edges)
// meets:
//   - in the F-faces, every F-face edge first: the edge leaving child point c is edge c;
//   - in E-face e, whose corners are (b, a) of the face running a->b and (a, b) of the other,
//     the two edges across the parent edge: C + 2e at a, C + 2e + 1 at b (the other two
//     are F-face edges);
//   - in the V-faces, nothing new: consecutive corners of a V-face are joined across a
//     parent edge.
// So every relation is written element by element, in the order Build gives it (incidence
// lists sorted), and every tag is zero. The result equals MeshTopology::Build's on the same
// faces (tested) and does not depend on the number of threads. Other parents (boundaries,
// creases, non-manifold or 2-face vertices) go through MeshTopology::Build.
#ifndef SubDDualChildTopology_h
#define SubDDualChildTopology_h

#include "SubDDualSplit.h"
#include "SubDLevel.h"
#include "SubDMeshTopology.h"

namespace subd
{
class SUBDKERNEL_EXPORT DualChildTopology
{
public:
  /// Whether the closed form holds for the split of `parent` into `points`.
  static bool Applies(const Level& parent, const DualPoints& points);

  /// The child topology, from the child faces the dual split wrote (`offsets`, `vertices`:
  /// F-faces, then an E-face per parent edge, then a V-face per parent vertex). Requires
  /// Applies().
  static MeshTopology OfDualSplit(const MeshTopology& parent, IndexArray offsets, IndexArray vertices,
    const ParallelFor& parallelFor);

private:
  struct Split;
  /// Each child face's edges.
  static void WriteFaceEdges(const Split& split, MeshTopology& child);
  /// Each child edge's ends and two faces.
  static void WriteEdges(const Split& split, MeshTopology& child);
  /// The faces (with the point's corner in each) and edges around each child point.
  static void WritePointRelations(const Split& split, MeshTopology& child);
};
}

#endif
