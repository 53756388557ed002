/**
 * @class   vtkSubDPLYWriter
 * @brief   writes the polygons of a vtkPolyData as binary PLY, the points in their own precision
 *
 * Writes a binary PLY file (Turk, "The PLY Polygon File Format", 1994) in the machine's byte
 * order: the `vertex` element with x, y, z in the points' own type (double points stay
 * double: VTK's vtkPLYWriter writes float, which drops half the digits of a refined mesh), the
 * point normals as nx, ny, nz, unsigned-char colours "RGB"/"RGBA" as red, green, blue[,
 * alpha], the texture coordinates as u, v and every other one-component numeric point-data
 * array as a property of its own name (spaces made underscores) and type (double for the
 * types PLY lacks) - what vtkSubDPLYReader reads back - then the `face` element's
 * vertex_indices (an unsigned-char count, int when some face has more than 255 corners; int
 * indices). Triangle strips are written as their triangles. Lines, vertices, cell data and
 * point arrays of other shapes have no place in it and are skipped with a warning.
 *
 * The values go out in large blocks, read straight from the arrays' memory: the ten million
 * quads of a level-4 Catmull-Clark armadillo (410 MB) take about two seconds, much of it the
 * system copying the bytes, against six for vtkPLYWriter (and its file is 290 MB because its
 * points are float).
 */
#ifndef vtkSubDPLYWriter_h
#define vtkSubDPLYWriter_h

#include "SubDIOModule.h" // for export macro
#include "vtkSubDPolyDataWriter.h"

class vtkPolyData;

class SUBDIO_EXPORT vtkSubDPLYWriter : public vtkSubDPolyDataWriter
{
public:
  static vtkSubDPLYWriter* New();
  vtkTypeMacro(vtkSubDPLYWriter, vtkSubDPolyDataWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkSubDPLYWriter() = default;
  ~vtkSubDPLYWriter() override = default;
  void WriteFile(vtkPolyData* input, std::ostream& file) override;

private:
  vtkSubDPLYWriter(const vtkSubDPLYWriter&) = delete;
  void operator=(const vtkSubDPLYWriter&) = delete;
};

#endif
