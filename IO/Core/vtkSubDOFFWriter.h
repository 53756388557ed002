/**
 * @class   vtkSubDOFFWriter
 * @brief   writes the polygons of a vtkPolyData in the Object File Format (.off)
 *
 * Writes the header `OFF`, the counts, the points with full double precision (17
 * significant digits, so a write/read round trip is exact) and every polygon (triangle
 * strips are written as their triangles). Lines and vertices have no place in OFF and are
 * skipped with a warning.
 */
#ifndef vtkSubDOFFWriter_h
#define vtkSubDOFFWriter_h

#include "SubDIOModule.h" // for export macro
#include "vtkWriter.h"

class vtkPolyData;

class SUBDIO_EXPORT vtkSubDOFFWriter : public vtkWriter
{
public:
  static vtkSubDOFFWriter* New();
  vtkTypeMacro(vtkSubDOFFWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Name of the file to write. */
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

protected:
  vtkSubDOFFWriter();
  ~vtkSubDOFFWriter() override;
  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  char* FileName = nullptr;

private:
  vtkSubDOFFWriter(const vtkSubDOFFWriter&) = delete;
  void operator=(const vtkSubDOFFWriter&) = delete;
};

#endif
