/**
 * @class   vtkSubDOFFWriter
 * @brief   writes the polygons of a vtkPolyData in the Object File Format (.off)
 *
 * Writes the header `OFF`, the counts, the points in the shortest decimal form that reads
 * back to the same double (so a write/read round trip is exact) and every polygon (triangle
 * strips are written as their triangles). Lines and vertices have no place in OFF and are
 * skipped with a warning.
 */
#ifndef vtkSubDOFFWriter_h
#define vtkSubDOFFWriter_h

#include "SubDIOModule.h" // for export macro
#include "vtkSubDPolyDataWriter.h"

class vtkPolyData;

class SUBDIO_EXPORT vtkSubDOFFWriter : public vtkSubDPolyDataWriter
{
public:
  static vtkSubDOFFWriter* New();
  vtkTypeMacro(vtkSubDOFFWriter, vtkSubDPolyDataWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkSubDOFFWriter() = default;
  ~vtkSubDOFFWriter() override = default;
  void WriteFile(vtkPolyData* input, std::ostream& file) override;

private:
  vtkSubDOFFWriter(const vtkSubDOFFWriter&) = delete;
  void operator=(const vtkSubDOFFWriter&) = delete;
};

#endif
