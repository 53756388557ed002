#include "vtkSubDLegacyParser.h"

#include "vtkSubDReadValues.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <string>

namespace subdio
{
std::string Lower(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

std::string Upper(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::toupper(c); });
  return text;
}

// vtkDataWriter writes names with spaces and other special characters as %XX.
std::string DecodeName(const std::string& name)
{
  std::string decoded;
  for (size_t i = 0; i < name.size(); ++i)
  {
    // VTK 9.1 writes COLOR_SCALARS names through one printf too many: "%%20" for "%20".
    if (name.compare(i, 2, "%%") == 0 && i + 3 < name.size() && std::isxdigit(static_cast<unsigned char>(name[i + 2])))
    {
      ++i;
    }
    if (name[i] == '%' && i + 2 < name.size() && std::isxdigit(static_cast<unsigned char>(name[i + 1])) &&
      std::isxdigit(static_cast<unsigned char>(name[i + 2])))
    {
      decoded += static_cast<char>(std::stoi(name.substr(i + 1, 2), nullptr, 16));
      i += 2;
    }
    else
    {
      decoded += name[i];
    }
  }
  return decoded;
}

int LegacyTypeFromName(const std::string& name)
{
  static const std::map<std::string, int> types = { { "unsigned_char", VTK_UNSIGNED_CHAR },
    { "char", VTK_CHAR }, { "signed_char", VTK_SIGNED_CHAR }, { "unsigned_short", VTK_UNSIGNED_SHORT },
    { "short", VTK_SHORT }, { "unsigned_int", VTK_UNSIGNED_INT }, { "int", VTK_INT },
    { "unsigned_long", VTK_UNSIGNED_LONG }, { "long", VTK_LONG }, { "float", VTK_FLOAT },
    { "double", VTK_DOUBLE }, { "vtkidtype", VTK_ID_TYPE }, { "vtktypeint64", VTK_TYPE_INT64 },
    { "vtktypeuint64", VTK_TYPE_UINT64 }, { "vtktypeint32", VTK_TYPE_INT32 },
    { "vtktypeuint32", VTK_TYPE_UINT32 }, { "bit", -2 }, { "string", -2 }, { "utf8_string", -2 },
    { "variant", -2 } };
  const auto found = types.find(name);
  return found == types.end() ? -1 : found->second;
}

vtkSmartPointer<vtkIdTypeArray> ToIds(vtkDataArray* array)
{
  auto ids = vtkSmartPointer<vtkIdTypeArray>::New();
  ids->SetNumberOfValues(array->GetNumberOfValues());
  switch (array->GetDataType())
  {
    vtkTemplateMacro({
      const auto* values = static_cast<const VTK_TT*>(array->GetVoidPointer(0));
      std::transform(values, values + array->GetNumberOfValues(), ids->GetPointer(0),
        [](VTK_TT v) { return static_cast<vtkIdType>(v); });
    });
  }
  return ids;
}

namespace
{
bool IsIntegerType(int type)
{
  return type != VTK_FLOAT && type != VTK_DOUBLE;
}
}

bool LegacyParser::ReadHeader()
{
  std::string line;
  if (!this->Scanner.NextLine(line) || Lower(line).rfind("# vtk datafile version", 0) != 0)
  {
    return this->Fail("not a legacy VTK file: the first line must be '# vtk DataFile Version x.y'.");
  }
  const std::string version = line.substr(std::string("# vtk DataFile Version").size());
  this->MajorVersion = std::atoi(version.c_str());
  if (this->MajorVersion > 5)
  {
    return this->Fail("file version" + version + " is newer than this reader knows (up to 5.1).");
  }
  if (!this->Scanner.NextLine(line)) // the title: any text
  {
    return this->Fail("the file ends before its title line.");
  }
  std::string format;
  if (!this->Scanner.NextWord(format) || (Lower(format) != "ascii" && Lower(format) != "binary"))
  {
    return this->Fail("expected ASCII or BINARY after the title, found '" + format + "'.");
  }
  this->Binary = Lower(format) == "binary";
  std::string dataset, type;
  if (!this->Scanner.NextWord(dataset) || Lower(dataset) != "dataset" || !this->Scanner.NextWord(type))
  {
    return this->Fail("expected 'DATASET POLYDATA' after " + format + ".");
  }
  if (Lower(type) != "polydata")
  {
    return this->Fail("the file holds a " + type + " dataset; SubD reads polygonal data (DATASET POLYDATA).");
  }
  return true;
}

bool LegacyParser::NextKeyword(std::string& keyword)
{
  this->Scanner.NextWord(keyword);
  keyword = Lower(keyword);
  return !keyword.empty();
}

bool LegacyParser::ReadCount(const std::string& what, vtkIdType& count)
{
  if (!this->Scanner.NextNumber(count) || count < 0)
  {
    return this->Fail("expected a count (a whole number, 0 or more) for " + what + ".");
  }
  return true;
}

bool LegacyParser::ReadWordAfter(const std::string& what, std::string& word)
{
  if (!this->Scanner.NextWord(word))
  {
    return this->Fail("the file ends inside " + what + ".");
  }
  return true;
}

bool LegacyParser::ReadType(const std::string& what, int& type)
{
  std::string name;
  if (!this->ReadWordAfter(what, name))
  {
    return false;
  }
  type = LegacyTypeFromName(Lower(name));
  if (type == -2)
  {
    return this->Fail(what + " holds values of type '" + name +
      "', which this reader does not read (save the data as .vtp).");
  }
  if (type < 0)
  {
    return this->Fail("unknown value type '" + name + "' for " + what + ".");
  }
  return true;
}

bool LegacyParser::ReadValues(
  const std::string& what, int type, vtkIdType tuples, int components, vtkSmartPointer<vtkDataArray>& array)
{
  if (this->Binary && type == VTK_ID_TYPE)
  {
    // Binary files store vtkIdType values in 4 bytes, whatever vtkIdType's size.
    vtkSmartPointer<vtkDataArray> narrow;
    if (!this->ReadValues(what, VTK_INT, tuples, components, narrow))
    {
      return false;
    }
    array = ToIds(narrow);
    array->SetNumberOfComponents(components);
    this->LastArray = array;
    return true;
  }
  const double count = static_cast<double>(tuples) * components;
  array.TakeReference(vtkDataArray::CreateDataArray(type));
  const double bytesEach = this->Binary ? array->GetDataTypeSize() : 2.0; // ASCII: a digit and a space
  if (!this->Scanner.ReserveFor(count, bytesEach))
  {
    return this->Fail(what + " announces " + std::to_string(tuples) + " tuples, more than the rest of the file holds.");
  }
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  if (this->Binary)
  {
    this->Scanner.SkipRestOfLine(); // binary values start on the next line
  }
  if (!subdio::ReadArrayValues(this->Scanner, array, 0, tuples * components, this->Binary, true))
  {
    return this->Fail(what + ": " +
      (this->Binary ? std::string("the file ends before its values do.")
                    : "expected " + std::to_string(tuples * components) + " values of type " +
            array->GetDataTypeAsString() + ", found '" + this->Scanner.PeekWord() + "'."));
  }
  this->LastArray = array;
  return true;
}

bool LegacyParser::ReadPoints()
{
  vtkIdType count = 0;
  int type = 0;
  if (this->HavePoints)
  {
    return this->Fail("a second POINTS section.");
  }
  vtkSmartPointer<vtkDataArray> coordinates;
  if (!this->ReadCount("POINTS", count) || !this->ReadType("POINTS", type) ||
    !this->ReadValues("POINTS", type, count, 3, coordinates))
  {
    return false;
  }
  this->Points->SetData(coordinates);
  this->HavePoints = true;
  return true;
}

bool LegacyParser::ReadCells(const std::string& keyword, vtkCellArray* cells)
{
  vtkIdType first = 0, size = 0;
  if (cells->GetNumberOfCells() > 0)
  {
    return this->Fail("a second " + keyword + " section.");
  }
  if (!this->ReadCount(keyword, first) || !this->ReadCount(keyword, size))
  {
    return false;
  }
  // Version 5 files give each cell kind as OFFSETS and CONNECTIVITY arrays; older ones as
  // "n i0 ... i(n-1)" per cell.
  return this->MajorVersion >= 5 ? this->ReadOffsetCells(keyword, first, size, cells)
                                 : this->ReadClassicCells(keyword, first, size, cells);
}

bool LegacyParser::ReadClassicCells(
  const std::string& keyword, vtkIdType numCells, vtkIdType size, vtkCellArray* cells)
{
  vtkSmartPointer<vtkDataArray> values;
  if (!this->ReadValues(keyword, VTK_INT, size, 1, values))
  {
    return false;
  }
  const int* data = static_cast<const int*>(values->GetVoidPointer(0));
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfValues(numCells + 1);
  connectivity->Allocate(size);
  vtkIdType at = 0;
  offsets->SetValue(0, 0);
  for (vtkIdType c = 0; c < numCells; ++c)
  {
    if (at >= size || data[at] < 0 || data[at] > size - at - 1)
    {
      return this->Fail(keyword + ": cell " + std::to_string(c) + " of " + std::to_string(numCells) +
        " runs past the " + std::to_string(size) + " values the section announces.");
    }
    for (int k = 1; k <= data[at]; ++k)
    {
      connectivity->InsertNextValue(data[at + k]);
    }
    at += data[at] + 1;
    offsets->SetValue(c + 1, connectivity->GetNumberOfValues());
  }
  if (at != size)
  {
    return this->Fail(keyword + ": its " + std::to_string(numCells) + " cells use " + std::to_string(at) +
      " of the " + std::to_string(size) + " values the section announces.");
  }
  cells->SetData(offsets, connectivity);
  return true;
}

bool LegacyParser::ReadOffsetCells(
  const std::string& keyword, vtkIdType numOffsets, vtkIdType size, vtkCellArray* cells)
{
  vtkSmartPointer<vtkDataArray> arrays[2];
  const char* names[2] = { "offsets", "connectivity" };
  const vtkIdType counts[2] = { numOffsets, size };
  for (int k = 0; k < 2; ++k)
  {
    std::string word;
    int type = 0;
    const std::string what = keyword + " " + Lower(names[k]);
    if (!this->ReadWordAfter(keyword, word) || Lower(word) != names[k])
    {
      return this->Fail(keyword + ": expected " + Lower(names[k]) + " (version 5 layout), found '" + word + "'.");
    }
    if (!this->ReadType(what, type) || !this->ReadValues(what, type, counts[k], 1, arrays[k]))
    {
      return false;
    }
    if (!IsIntegerType(type))
    {
      return this->Fail(what + " must be of an integer type.");
    }
  }
  vtkSmartPointer<vtkIdTypeArray> offsets = ToIds(arrays[0]);
  if (numOffsets == 0 && size == 0)
  {
    return true; // no cells of this kind
  }
  const vtkIdType* o = offsets->GetPointer(0);
  bool valid = numOffsets > 0 && o[0] == 0 && o[numOffsets - 1] == size;
  for (vtkIdType c = 1; valid && c < numOffsets; ++c)
  {
    valid = o[c] >= o[c - 1];
  }
  if (!valid)
  {
    return this->Fail(keyword + ": the offsets must start at 0, never decrease and end at the connectivity size (" +
      std::to_string(size) + ").");
  }
  cells->SetData(offsets, ToIds(arrays[1]));
  return true;
}

bool LegacyParser::Parse(vtkPolyData* output)
{
  if (!this->ReadHeader())
  {
    return false;
  }
  std::string keyword;
  while (this->NextKeyword(keyword))
  {
    bool ok = true;
    if (keyword == "points")
    {
      ok = this->ReadPoints();
    }
    else if (keyword == "vertices" || keyword == "lines" || keyword == "polygons" || keyword == "triangle_strips")
    {
      vtkCellArray* cells = keyword == "vertices" ? this->Verts.Get()
        : keyword == "lines"                      ? this->Lines.Get()
        : keyword == "polygons"                   ? this->Polys.Get()
                                                  : this->Strips.Get();
      ok = this->ReadCells(Upper(keyword), cells);
    }
    else if (keyword == "field" && !this->Attributes)
    {
      ok = this->ReadField(this->DatasetField);
    }
    else if (keyword == "point_data" || keyword == "cell_data")
    {
      ok = this->ReadCount(Upper(keyword), this->AttributeTuples);
      this->Attributes = keyword == "point_data" ? static_cast<vtkDataSetAttributes*>(this->PointData)
                                                 : static_cast<vtkDataSetAttributes*>(this->CellData);
    }
    else if (keyword == "metadata")
    {
      ok = this->ReadMetaData();
    }
    else if (keyword == "scalars" || keyword == "color_scalars" || keyword == "lookup_table" ||
      keyword == "vectors" || keyword == "normals" || keyword == "texture_coordinates" || keyword == "tensors" ||
      keyword == "tensors6" || keyword == "global_ids" || keyword == "pedigree_ids" || keyword == "field")
    {
      ok = this->ReadAttribute(keyword); // lower case
    }
    else
    {
      ok = this->Fail("unknown keyword '" + keyword + "'.");
    }
    if (!ok)
    {
      return false;
    }
  }
  if (this->HavePoints)
  {
    output->SetPoints(this->Points);
  }
  output->SetVerts(this->Verts);
  output->SetLines(this->Lines);
  output->SetPolys(this->Polys);
  output->SetStrips(this->Strips);
  output->GetPointData()->ShallowCopy(this->PointData);
  output->GetCellData()->ShallowCopy(this->CellData);
  output->SetFieldData(this->DatasetField);
  return this->CheckSizes(output);
}
}
