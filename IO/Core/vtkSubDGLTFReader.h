/**
 * @class   vtkSubDGLTFReader
 * @brief   reads the meshes of a glTF 2.0 scene (.gltf or .glb) as one vtkPolyData
 *
 * glTF stores each primitive with its own vertices, split wherever an attribute differs (at
 * every UV seam and hard normal), in the nodes of a scene. This reader runs VTK's
 * vtkGLTFReader on the file's default scene (node transforms applied) and appends every
 * primitive into one polydata, the form SubD's surface filters take: vtkSubDSurfaceFilter
 * welds the split points back (WeldCoincidentPoints) and refines the texture coordinates as
 * face-varying data.
 *
 * `TEXCOORD_0` becomes the output's TCoords, "TCoords", with v turned back to VTK's and OBJ's
 * convention (glTF puts the image's origin at the top left: v_vtk = 1 - v_gltf). `NORMAL` and
 * `TANGENT` are dropped (they describe the cage, not the subdivided surface, which has normals
 * of its own); other attributes that every primitive has are kept as point data.
 *
 * Before VTK's reader sees the file, its structure is checked (every index in range, every
 * byte range inside its buffer, buffer files present): VTK 9.1's reader would crash on such
 * files. A broken file gives an error naming what is wrong and an empty output.
 *
 * @sa vtkGLTFReader vtkSubDGLTFWriter
 */
#ifndef vtkSubDGLTFReader_h
#define vtkSubDGLTFReader_h

#include "SubDIOModule.h" // for export macro
#include "vtkSubDPolyDataReader.h"

class SUBDIO_EXPORT vtkSubDGLTFReader : public vtkSubDPolyDataReader
{
public:
  static vtkSubDGLTFReader* New();
  vtkTypeMacro(vtkSubDGLTFReader, vtkSubDPolyDataReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkSubDGLTFReader() = default;
  ~vtkSubDGLTFReader() override = default;
  /// VTK's reader opens the file (and its buffers) by name; the stream is not used.
  bool ReadFile(std::istream& file, vtkPolyData* output) override;

private:
  vtkSubDGLTFReader(const vtkSubDGLTFReader&) = delete;
  void operator=(const vtkSubDGLTFReader&) = delete;
};

#endif
