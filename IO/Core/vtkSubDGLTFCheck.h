// Structural checks of a glTF 2.0 file before VTK's glTF reader sees it.
//
// VTK 9.1's vtkGLTFReader trusts the indices and sizes a file declares: an accessor index out of
// range or a buffer file that is missing crashes it, and a buffer shorter than its views is read
// past its end. These checks follow every reference the reader follows (scene -> node -> mesh ->
// primitive -> accessor -> buffer view -> buffer, skins, animations, images) and every byte range
// it reads, so that a broken or hostile file gets a message instead.
#ifndef vtkSubDGLTFCheck_h
#define vtkSubDGLTFCheck_h

#include <string>

/// Checks the .gltf or .glb file `fileName` (external buffers and images relative to its
/// directory). Returns false and sets `problem` to what is wrong.
bool vtkSubDCheckGLTF(const std::string& fileName, std::string& problem);

#endif
