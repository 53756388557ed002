// The parser behind vtkSubDLegacyReader: one pass over a legacy VTK polydata file.
// vtkSubDLegacyParser.cxx reads the header, points and cells; vtkSubDLegacyAttributes.cxx the
// POINT_DATA / CELL_DATA / FIELD sections.
#ifndef vtkSubDLegacyParser_h
#define vtkSubDLegacyParser_h

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSubDFileScanner.h"

#include <map>
#include <string>

namespace subdio
{
std::string Lower(std::string text);
std::string Upper(std::string text);
/// Undoes vtkDataWriter's %XX encoding of names.
std::string DecodeName(const std::string& name);
/// The VTK type of a legacy type name (lower case); -1 unknown, -2 known but not read here.
int LegacyTypeFromName(const std::string& name);
/// The values of an integer array as vtkIdType.
vtkSmartPointer<vtkIdTypeArray> ToIds(vtkDataArray* array);

/// One pass over a legacy file. Every method reports the first problem through Fail and
/// returns false; nothing is added to the output until the whole file has been read.
class LegacyParser : public FileParser
{
public:
  LegacyParser(FileScanner& scanner, Reporter report)
    : FileParser(scanner, std::move(report))
  {
  }

  bool Parse(vtkPolyData* output);

private:
  bool ReadHeader();
  bool NextKeyword(std::string& keyword);
  bool ReadCount(const std::string& what, vtkIdType& count);
  bool ReadWordAfter(const std::string& what, std::string& word);
  bool ReadType(const std::string& what, int& type);
  bool ReadValues(const std::string& what, int type, vtkIdType tuples, int components,
    vtkSmartPointer<vtkDataArray>& array);
  bool ReadPoints();
  bool ReadCells(const std::string& keyword, vtkCellArray* cells);
  bool ReadClassicCells(const std::string& keyword, vtkIdType numCells, vtkIdType size, vtkCellArray* cells);
  bool ReadOffsetCells(const std::string& keyword, vtkIdType numOffsets, vtkIdType size, vtkCellArray* cells);
  bool ReadAttribute(const std::string& keyword);
  bool ReadScalars(vtkSmartPointer<vtkDataArray>& array);
  bool ReadColorScalars(vtkSmartPointer<vtkDataArray>& array);
  bool ReadLookupTable();
  bool ReadField(vtkFieldData* field);
  bool ReadMetaData();
  bool CheckSizes(vtkPolyData* output);

  int MajorVersion = 0;
  vtkNew<vtkPoints> Points;
  bool HavePoints = false;
  vtkNew<vtkCellArray> Verts, Lines, Polys, Strips;
  vtkNew<vtkFieldData> DatasetField;
  vtkNew<vtkPointData> PointData;
  vtkNew<vtkCellData> CellData;
  vtkDataSetAttributes* Attributes = nullptr; // the section being read (POINT_DATA/CELL_DATA)
  vtkIdType AttributeTuples = -1;
  // Held, not borrowed: a later array of the same name replaces (and frees) one in the
  // attributes, and cell arrays are temporaries.
  vtkSmartPointer<vtkAbstractArray> LastArray; // METADATA blocks describe the array before them
  std::multimap<std::string, vtkSmartPointer<vtkDataArray>> ScalarsByTable;
};
}

#endif
