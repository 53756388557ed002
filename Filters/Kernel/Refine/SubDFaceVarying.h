// SubD kernel: face-varying channels (texture coordinates with seams, and any data given per
// face corner rather than per vertex).
//
// A channel gives each face corner the index of one of its own values; where neighbouring
// faces give a vertex different values, the channel has a seam. The channel is refined as a
// mesh of its own, by the mesh's scheme and masks: its vertices are the (vertex, value) pairs,
// its faces the mesh's faces in the same order, so its child faces are the mesh's child faces
// corner for corner. Across a seam the channel's mesh has a boundary, which its rules treat
// as a crease; away from seams it is the mesh itself, with the mesh's sharpness, so its values
// follow the vertex rules. The interpolation mode then pins values to corners exactly as
// OpenSubdiv's Sdc::Options::FVarLinearInterpolation does (Far::PrimvarRefiner
// ::InterpolateFaceVarying, LimitFaceVarying):
//
// - None: smooth everywhere; a value at a corner of its region (one face) is rounded too.
// - CornersOnly: values of one face are corners.
// - CornersPlus1: also every value of a vertex where three or more regions meet, and both
//   values of a vertex of two whose regions hold an infinitely sharp edge or touch twice; a
//   region without semi-sharp edges follows the transition of its partner that has some.
// - CornersPlus2: also darts of the channel (a seam ending inside the mesh) and both values
//   at a concave corner (one of two regions has a single face).
// - Boundaries: every value on a seam or on the mesh's boundary is a corner, seams and
//   boundaries linear.
// - All: linear everywhere.
#ifndef SubDFaceVarying_h
#define SubDFaceVarying_h

#include "SubDLevel.h"

namespace subd
{
/// OpenSubdiv's FVarLinearInterpolation, in its order.
enum class FaceVaryingInterpolation : int
{
  None = 0,
  CornersOnly = 1,
  CornersPlus1 = 2,
  CornersPlus2 = 3,
  Boundaries = 4,
  All = 5
};

SUBDKERNEL_EXPORT const char* ToString(FaceVaryingInterpolation mode);

/// A channel's base level, ready for Refine with the mesh's scheme.
struct FaceVaryingBase
{
  Level Values;          ///< faces as the mesh's, their corners the channel's values
  IndexArray UserValue;  ///< per vertex of Values: the index of the user's value it carries
};

/// The channel of `valueOfCorner` (one user value index per face corner of `mesh`, in its
/// face order) on `mesh`, the mesh's base level as MakeBaseLevel made it (its sharpness,
/// corners and holes). A user value shared by several vertices becomes one value per vertex.
SUBDKERNEL_EXPORT FaceVaryingBase MakeFaceVaryingBase(
  const Level& mesh, const Index* valueOfCorner, FaceVaryingInterpolation mode);
}

#endif
