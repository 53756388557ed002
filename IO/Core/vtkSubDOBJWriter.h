/**
 * @class   vtkSubDOBJWriter
 * @brief   writes polygon meshes as Wavefront OBJ with OpenSubdiv's sharp-feature tags
 *
 * Writes the points (`v`, each coordinate in the shortest form that reads back to the same
 * double) and polygons (`f`; triangle strips as triangles), and the sharp features SubD's
 * filters use as the tags vtkSubDOBJReader reads (OpenSubdiv's convention, 0-based
 * indices): each line cell as
 * `t crease N/1/0 v0 ... vN-1 s` with its "Sharpness" (10, infinitely sharp, when the
 * array is absent), non-zero "CornerSharpness" as one `t corner N/N/0` tag, and faces with a
 * non-zero "Hole" as `t hole N/0/0`. Texture coordinates (the TCoords point data, on points
 * split at seams as VTK's readers and SubD's filters give them) are written as `vt` with
 * faces `f v/vt`: each position is one `v`, each distinct coordinate one `vt`, so the seams
 * read back as they were. Other attributes are not written (OBJ has no place for them). The
 * file is written completely or an error is reported.
 */
#ifndef vtkSubDOBJWriter_h
#define vtkSubDOBJWriter_h

#include "SubDIOModule.h" // for export macro
#include "vtkSubDPolyDataWriter.h"

class vtkPolyData;

class SUBDIO_EXPORT vtkSubDOBJWriter : public vtkSubDPolyDataWriter
{
public:
  static vtkSubDOBJWriter* New();
  vtkTypeMacro(vtkSubDOBJWriter, vtkSubDPolyDataWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkSubDOBJWriter() = default;
  ~vtkSubDOBJWriter() override = default;
  void WriteFile(vtkPolyData* input, std::ostream& file) override;

private:
  vtkSubDOBJWriter(const vtkSubDOBJWriter&) = delete;
  void operator=(const vtkSubDOBJWriter&) = delete;
};

#endif
