// SubD kernel: linear subdivision, which adds resolution without smoothing.
//
// - Bilinear (on the quad split, SubDQuadSplit.h): face point = centroid of the face, edge
//   point = midpoint, vertex point = the vertex. The same surface for any polygon mesh, and
//   OpenSubdiv's Sdc::SCHEME_BILINEAR.
// - Linear triangles (on the triangle split, SubDTriangleSplit.h): edge point = midpoint,
//   vertex point = the vertex; what VTK's vtkLinearSubdivisionFilter does.
// Both are exact for data that varies linearly over each face (bilinearly over a quad).
#ifndef SubDLinearRules_h
#define SubDLinearRules_h

#include "SubDLevel.h"
#include "SubDStencilTable.h"

namespace subd
{
SUBDKERNEL_EXPORT StencilTable BuildBilinearStencils(const Level& parent);
/// Requires every face of `parent` to be a triangle.
SUBDKERNEL_EXPORT StencilTable BuildLinearTriangleStencils(const Level& parent);
}

#endif
