// SubD kernel: the dual split (corner cutting) of Doo-Sabin subdivision.
//
// Every face corner gets a new point, numbered like the corners: the point of corner j of
// face f is child point FaceOffset(f) + j. Child faces, in three blocks:
//   F-faces  one per face: its corner points, same orientation (faces [0, F));
//   E-faces  one per interior manifold edge: the quad of the four corner points at its ends;
//   V-faces  one per interior manifold vertex: the corner points around it, in the order of
//            the faces around it (MeshTopology::GetOrderedVertexFaces).
// Boundary and non-manifold edges and vertices get no E- or V-face, so the refined surface
// shrinks back from an open boundary (what CGAL's Doo-Sabin does). F-faces inherit their
// face's hole flag and origin; an E- or V-face takes the origin of its first face.
#ifndef SubDDualSplit_h
#define SubDDualSplit_h

#include "SubDLevel.h"

namespace subd
{
SUBDKERNEL_EXPORT Level SplitDual(const Level& parent, ChildTopology depth);
}

#endif
