/**
 * @class   vtkSubDLegacyReader
 * @brief   reads polygonal data in VTK's legacy file format (.vtk), trusting nothing in the file
 *
 * Reads what vtkPolyDataWriter writes (ASCII or BINARY, file versions up to 5.1): the
 * `DATASET POLYDATA` points, vertices, lines, polygons and triangle strips (classic
 * `n i0 i1 ...` cells and the OFFSETS/CONNECTIVITY layout of version 5), the dataset's FIELD
 * data, and all POINT_DATA and CELL_DATA sections: SCALARS (with their lookup tables),
 * COLOR_SCALARS, VECTORS, NORMALS, TEXTURE_COORDINATES, TENSORS, TENSORS6, GLOBAL_IDS,
 * PEDIGREE_IDS and FIELD arrays, with component names from METADATA blocks. Keywords match
 * without case, names are %-decoded, binary values are big-endian. Unlike vtkPolyDataReader it
 * keeps every SCALARS/VECTORS/... section (the first of each kind is the active attribute, the
 * others are added as arrays).
 *
 * Why not vtkPolyDataReader: VTK's legacy reader trusts the counts in the file. A count that
 * does not match its values, a keyword in another case, a real number where an id belongs or a
 * count larger than the file make it read past its buffers, crash or allocate gigabytes
 * (found by fuzzing SubD's `subd` program). This reader weighs every count against the bytes
 * left before allocating, checks every value's syntax, cell offsets and array sizes, and
 * reports the first problem with its line (ASCII files) and section. Cell point ids are not
 * compared with the number of points (as in VTK); SubD's filters check them.
 *
 * Not read (a clear error names them): other dataset types, `bit`, `string` and `variant`
 * arrays.
 */
#ifndef vtkSubDLegacyReader_h
#define vtkSubDLegacyReader_h

#include "SubDIOModule.h" // for export macro
#include "vtkSubDPolyDataReader.h"

class SUBDIO_EXPORT vtkSubDLegacyReader : public vtkSubDPolyDataReader
{
public:
  static vtkSubDLegacyReader* New();
  vtkTypeMacro(vtkSubDLegacyReader, vtkSubDPolyDataReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkSubDLegacyReader() = default;
  ~vtkSubDLegacyReader() override = default;
  bool ReadFile(std::istream& file, vtkPolyData* output) override;

private:
  vtkSubDLegacyReader(const vtkSubDLegacyReader&) = delete;
  void operator=(const vtkSubDLegacyReader&) = delete;
};

#endif
