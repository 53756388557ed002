// subd: reading and writing meshes, the format chosen by the file extension.
#ifndef SubDMeshIO_h
#define SubDMeshIO_h

#include "vtkPolyData.h" // for vtkSmartPointer<vtkPolyData>
#include "vtkSmartPointer.h"
#include <string>

namespace subdapp
{
/// Extensions understood by ReadMesh (lower case, with the dot).
const char* SupportedExtensions();

/// Extensions understood by WriteMesh (all but .glb: VTK's glTF writer writes .gltf only).
const char* WritableExtensions();

/// Whether WriteMesh knows the extension of `path`.
bool CanWrite(const std::string& path);

/// Reads .vtp .vtk .obj .ply .stl .off .gltf .glb. On failure returns nullptr and sets `error`.
vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path, std::string& error);

/// Writes by extension, atomically: into a temporary file beside `path`, renamed over it only
/// when complete. Returns false and sets `error` on failure (nothing is left behind). A .vtp
/// holds its arrays as raw binary, appended (zlib-compressed with `compress`: about 15 times
/// slower to write, for files about a third smaller).
bool WriteMesh(vtkPolyData* mesh, const std::string& path, std::string& error, bool compress = false);

std::string LowerExtension(const std::string& path);
}

#endif
