// Private helper of vtkSubDLimitFilter: a watertight tessellation of the limit surface with
// the same number of segments along every edge of every face.
#ifndef vtkSubDUniformTessellation_h
#define vtkSubDUniformTessellation_h

#include "vtkSubDCage.h"
#include "vtkSubDLimitSamples.h"

/// Tessellates `faces` of the cage at `resolution` segments per edge: triangles (Loop,
/// `quads` false) into resolution^2 triangles, quads into resolution x resolution quads, other
/// polygons into one grid of quads per corner, resolution/2 across (resolution rounded up to
/// even when the cage has such polygons). A point shared by faces (on a cage vertex or edge)
/// is made once, owned by the first face that meets it; on a seam of the cage's channel, once per
/// side.
void vtkSubDTessellateUniform(const vtkSubDCage& cage, const std::vector<subd::Index>& faces, bool quads,
  int resolution, vtkSubDLimitSamples& samples);

#endif
