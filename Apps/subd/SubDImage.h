// subd: --image and --compare, the picture of a result (or of several schemes side by side)
// rendered offscreen with SubD's standard scene (vtkSubDScene).
#ifndef SubDImage_h
#define SubDImage_h

#include "SubDCommandLine.h"

#include <string>

class vtkPolyData;

namespace subdapp
{
/// Whether the picture options name what the renderer knows (--color); else false with `error`.
bool CheckImageOptions(const CommandLine& cmd, std::string& error);

/// Renders `result` (the subdivision of `cage` by cmd.Scheme), or with cmd.Compare each of
/// those schemes applied to `cage`, to cmd.Image. Returns false and sets `error` on failure;
/// warnings of the compared schemes' filters are appended to `warnings`.
bool RenderImage(const CommandLine& cmd, vtkPolyData* cage, vtkPolyData* result, std::string& warnings,
  std::string& error);
}

#endif
