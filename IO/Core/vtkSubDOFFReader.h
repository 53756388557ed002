/**
 * @class   vtkSubDOFFReader
 * @brief   reads polygon meshes in the Object File Format (.off)
 *
 * OFF is the format of Geomview, CGAL's and many research data sets: an optional header
 * keyword (`OFF`, or `COFF` when vertices carry colours), the counts `V F E`, V lines of
 * coordinates (optionally followed by colour components), then F lines `n i0 ... i(n-1)`,
 * optionally followed by a face colour. `#` starts a comment. Vertex colours become the
 * point-data array "Colors" (unsigned char RGBA; float components in [0,1] are scaled).
 *
 * Truncated or malformed files are reported with the line number and what was expected;
 * the output is then empty and the error code is set.
 */
#ifndef vtkSubDOFFReader_h
#define vtkSubDOFFReader_h

#include "SubDIOModule.h" // for export macro
#include "vtkSubDPolyDataReader.h"

class SUBDIO_EXPORT vtkSubDOFFReader : public vtkSubDPolyDataReader
{
public:
  static vtkSubDOFFReader* New();
  vtkTypeMacro(vtkSubDOFFReader, vtkSubDPolyDataReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkSubDOFFReader() = default;
  ~vtkSubDOFFReader() override = default;
  bool ReadFile(std::istream& file, vtkPolyData* output) override;

private:
  vtkSubDOFFReader(const vtkSubDOFFReader&) = delete;
  void operator=(const vtkSubDOFFReader&) = delete;
};

#endif
