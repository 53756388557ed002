/**
 * @class   vtkSubDOBJReader
 * @brief   reads Wavefront OBJ polygon meshes with OpenSubdiv's sharp-feature tags
 *
 * Reads `v` (positions), `f` (polygons; `v`, `v/vt`, `v//vn` and `v/vt/vn` corners,
 * 1-based or negative relative indices) and `l` (polylines) elements, and the tag lines
 * OpenSubdiv's test shapes use for sharp features, `t name nInts/nFloats/nStrings args`
 * with 0-based indices:
 *
 * - `t crease N/1/0 v0 ... vN-1 s`: a crease chain of N-1 edges of sharpness s (one polyline
 *   line cell), or `t crease N/(N-1)/0 v0 ... vN-1 s0 ... sN-2`: one sharpness per edge (one
 *   2-point line cell each);
 * - `t corner N/1/0 v... s` or `t corner N/N/0 v... s...`: vertex sharpness;
 * - `t hole N/0/0 f...`: faces that are holes.
 *
 * They become what SubD's surface filters read (vtkSubDSurfaceFilter): the crease lines in
 * Lines with the float cell-data array "Sharpness" (`l` polylines are infinitely sharp,
 * 10), the point-data array "CornerSharpness" and the cell-data array "Hole" (unsigned
 * char). Each array exists only if the file tags something.
 *
 * Texture coordinates (`vt`, named per corner by `f v/vt ...`) become the point-data array
 * "TCoords" (the output's TCoords), the points split at the seams as VTK's readers split them:
 * a point per (vertex, texture coordinate). The file's vertices keep their numbers, so lines
 * and tags name them, and each copy follows, as sharp as its vertex; vtkSubDSurfaceFilter
 * welds them back (WeldCoincidentPoints) and refines the coordinates as face-varying data. A
 * face that gives texture coordinates to some corners only, or names one that does not
 * exist, is an error. Normals (`vn`), groups and materials are skipped (the subdivided surface
 * has normals of its own); other tags are skipped with one warning naming them.
 * Malformed lines and out-of-range indices are errors naming the line; the output is then
 * empty and the error code set.
 */
#ifndef vtkSubDOBJReader_h
#define vtkSubDOBJReader_h

#include "SubDIOModule.h" // for export macro
#include "vtkSubDPolyDataReader.h"

class SUBDIO_EXPORT vtkSubDOBJReader : public vtkSubDPolyDataReader
{
public:
  static vtkSubDOBJReader* New();
  vtkTypeMacro(vtkSubDOBJReader, vtkSubDPolyDataReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkSubDOBJReader() = default;
  ~vtkSubDOBJReader() override = default;
  bool ReadFile(std::istream& file, vtkPolyData* output) override;

private:
  vtkSubDOBJReader(const vtkSubDOBJReader&) = delete;
  void operator=(const vtkSubDOBJReader&) = delete;
};

#endif
