/**
 * @class   vtkSubDGLTFWriter
 * @brief   writes the polygons of a vtkPolyData as a self-contained glTF 2.0 file (.gltf)
 *
 * One mesh of one primitive, through VTK's vtkGLTFWriter with the binary data inlined
 * (base64), so the file travels alone. glTF holds triangles: polygons are triangulated. The
 * points are written as floats, the TCoords as `TEXCOORD_0` (v turned to glTF's convention)
 * and the point normals, when there are any, as `NORMAL`. Other arrays have no glTF
 * attribute and are not written; lines and vertices are skipped with a warning.
 *
 * @sa vtkGLTFWriter vtkSubDGLTFReader
 */
#ifndef vtkSubDGLTFWriter_h
#define vtkSubDGLTFWriter_h

#include "SubDIOModule.h" // for export macro
#include "vtkSubDPolyDataWriter.h"

class SUBDIO_EXPORT vtkSubDGLTFWriter : public vtkSubDPolyDataWriter
{
public:
  static vtkSubDGLTFWriter* New();
  vtkTypeMacro(vtkSubDGLTFWriter, vtkSubDPolyDataWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkSubDGLTFWriter() = default;
  ~vtkSubDGLTFWriter() override = default;
  void WriteFile(vtkPolyData* input, std::ostream& file) override;

private:
  vtkSubDGLTFWriter(const vtkSubDGLTFWriter&) = delete;
  void operator=(const vtkSubDGLTFWriter&) = delete;
};

#endif
