/**
 * @class   vtkSubDPLYReader
 * @brief   reads polygon meshes in the Stanford PLY format (.ply), trusting nothing in the file
 *
 * PLY (Turk, "The PLY Polygon File Format", 1994) is a header of `element` and `property`
 * lines followed by the elements' values, as ASCII numbers or binary in either byte order.
 * This reader takes the `vertex` element's x, y, z as points (float when all three are
 * float, double otherwise), nx/ny/nz as the point normals "Normals", red/green/blue[/alpha]
 * (or diffuse_red...) as RGB(A) byte colours "RGB"/"RGBA" (the active scalars), u/v, s/t or
 * texture_u/texture_v as the texture coordinates "TCoords" - the arrays vtkPLYReader makes -
 * and keeps every other vertex property as a point-data array of its own name and type (VTK
 * drops them). The `face` element's vertex_indices (or vertex_index) list gives the
 * polygons; its colours and other scalar properties become cell data. Other elements (edge,
 * material, ...) and other list properties are read and skipped.
 *
 * Why not vtkPLYReader: VTK's PLY reader frees twice on a truncated file, loops for minutes
 * on a header announcing billions of elements, and reads past its buffers on a face line with
 * too few values (found by fuzzing `subd`). This reader weighs each element count against the
 * bytes left before allocating, checks every value's syntax, and checks that face indices
 * name existing vertices. Errors name the line (ASCII) or byte offset (binary) and the
 * element.
 */
#ifndef vtkSubDPLYReader_h
#define vtkSubDPLYReader_h

#include "SubDIOModule.h" // for export macro
#include "vtkSubDPolyDataReader.h"

class SUBDIO_EXPORT vtkSubDPLYReader : public vtkSubDPolyDataReader
{
public:
  static vtkSubDPLYReader* New();
  vtkTypeMacro(vtkSubDPLYReader, vtkSubDPolyDataReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkSubDPLYReader() = default;
  ~vtkSubDPLYReader() override = default;
  bool ReadFile(std::istream& file, vtkPolyData* output) override;

private:
  vtkSubDPLYReader(const vtkSubDPLYReader&) = delete;
  void operator=(const vtkSubDPLYReader&) = delete;
};

#endif
