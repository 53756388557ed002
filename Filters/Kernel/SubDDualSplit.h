// SubD kernel: the dual split (corner cutting) of Doo-Sabin subdivision.
//
// Every face corner gets a new point, numbered like the corners: the point of corner j of
// face f is child point FaceOffset(f) + j. Child faces, in three blocks:
//   F-faces  one per face: its corner points, same orientation (faces [0, F));
//   E-faces  one per interior manifold edge: the quad of the four corner points at its ends;
//   V-faces  one per manifold vertex with at least three faces: the corner points around it,
//            in the order of the faces around it (MeshTopology::GetOrderedVertexFaces); at
//            a boundary vertex the face is closed along the boundary.
// Boundary and non-manifold edges get no E-face; non-manifold vertices no V-face. With the
// boundary rows of SubDDooSabinRules.h the open boundary is then refined by Chaikin's rule.
// F-faces inherit their face's hole flag and origin; an E- or V-face takes the origin of its
// first face.
#ifndef SubDDualSplit_h
#define SubDDualSplit_h

#include "SubDLevel.h"

namespace subd
{
SUBDKERNEL_EXPORT Level SplitDual(const Level& parent, ChildTopology depth);
}

#endif
