#include "vtkSubDLegacyParser.h"

#include "vtkLookupTable.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <charconv>
#include <string>
#include <utility>

namespace subdio
{
namespace
{
// Makes `array` the active attribute of its kind unless one is already set (later ones, or
// ones VTK refuses as that attribute, are added as plain arrays).
void SetAttributeOrAdd(vtkDataSetAttributes* attributes, vtkDataArray* array, int attribute)
{
  if (attribute < 0 || attributes->GetAbstractAttribute(attribute) != nullptr ||
    attributes->SetAttribute(array, attribute) < 0)
  {
    attributes->AddArray(array);
  }
}
}

bool LegacyParser::ReadAttribute(const std::string& keyword)
{
  if (!this->Attributes)
  {
    return this->Fail(Upper(keyword) + " outside POINT_DATA or CELL_DATA.");
  }
  if (keyword == "lookup_table")
  {
    return this->ReadLookupTable();
  }
  if (keyword == "field")
  {
    return this->ReadField(this->Attributes);
  }
  std::string name;
  if (!this->ReadWordAfter(keyword, name))
  {
    return false;
  }
  name = DecodeName(name);
  vtkSmartPointer<vtkDataArray> array;
  int type = 0, attribute = -1;
  const std::string what = Upper(keyword) + " '" + name + "'";
  bool ok = true;
  if (keyword == "scalars")
  {
    ok = this->ReadScalars(array);
    attribute = vtkDataSetAttributes::SCALARS;
  }
  else if (keyword == "color_scalars")
  {
    ok = this->ReadColorScalars(array);
    attribute = vtkDataSetAttributes::SCALARS;
  }
  else if (keyword == "texture_coordinates")
  {
    int dimension = 0;
    ok = this->Scanner.NextNumber(dimension) && dimension >= 1 && dimension <= 3;
    ok = ok ? this->ReadType(what, type) && this->ReadValues(what, type, this->AttributeTuples, dimension, array)
            : this->Fail(what + ": expected a dimension of 1, 2 or 3.");
    attribute = vtkDataSetAttributes::TCOORDS;
  }
  else
  {
    static const std::map<std::string, std::pair<int, int>> kinds = { // components, attribute
      { "vectors", { 3, vtkDataSetAttributes::VECTORS } }, { "normals", { 3, vtkDataSetAttributes::NORMALS } },
      { "tensors", { 9, vtkDataSetAttributes::TENSORS } }, { "tensors6", { 6, vtkDataSetAttributes::TENSORS } },
      { "global_ids", { 1, vtkDataSetAttributes::GLOBALIDS } },
      { "pedigree_ids", { 1, vtkDataSetAttributes::PEDIGREEIDS } }
    };
    const auto kind = kinds.find(keyword);
    ok = this->ReadType(what, type) &&
      this->ReadValues(what, type, this->AttributeTuples, kind->second.first, array);
    attribute = kind->second.second;
  }
  if (!ok)
  {
    return false;
  }
  array->SetName(name.c_str());
  SetAttributeOrAdd(this->Attributes, array, attribute);
  return true;
}

bool LegacyParser::ReadScalars(vtkSmartPointer<vtkDataArray>& array)
{
  // SCALARS name type [components] then LOOKUP_TABLE tableName, then the values.
  int type = 0;
  if (!this->ReadType("SCALARS", type))
  {
    return false;
  }
  std::string word, table;
  int components = 1;
  if (!this->ReadWordAfter("SCALARS", word))
  {
    return false;
  }
  if (Lower(word) != "lookup_table")
  {
    const auto parsed = std::from_chars(word.data(), word.data() + word.size(), components);
    if (parsed.ec != std::errc() || parsed.ptr != word.data() + word.size() || components < 1 || components > 4)
    {
      return this->Fail("SCALARS: expected 1 to 4 components or LOOKUP_TABLE, found '" + word + "'.");
    }
    this->ReadWordAfter("SCALARS", word);
  }
  if (Lower(word) != "lookup_table" || !this->ReadWordAfter("SCALARS", table))
  {
    return this->Fail("SCALARS: expected 'LOOKUP_TABLE name' before the values.");
  }
  if (!this->ReadValues("SCALARS", type, this->AttributeTuples, components, array))
  {
    return false;
  }
  if (Lower(table) != "default")
  {
    this->ScalarsByTable.emplace(DecodeName(table), array);
  }
  return true;
}

bool LegacyParser::ReadColorScalars(vtkSmartPointer<vtkDataArray>& array)
{
  // Binary files store bytes; ASCII ones numbers in [0, 1].
  int components = 0;
  if (!this->Scanner.NextNumber(components) || components < 1 || components > 4)
  {
    return this->Fail("COLOR_SCALARS: expected 1 to 4 components.");
  }
  if (this->Binary)
  {
    return this->ReadValues("COLOR_SCALARS", VTK_UNSIGNED_CHAR, this->AttributeTuples, components, array);
  }
  vtkSmartPointer<vtkDataArray> unit;
  if (!this->ReadValues("COLOR_SCALARS", VTK_FLOAT, this->AttributeTuples, components, unit))
  {
    return false;
  }
  vtkNew<vtkUnsignedCharArray> bytes;
  bytes->SetNumberOfComponents(components);
  bytes->SetNumberOfTuples(this->AttributeTuples);
  for (vtkIdType i = 0; i < unit->GetNumberOfValues(); ++i)
  {
    const double v = std::min(1.0, std::max(0.0, unit->GetVariantValue(i).ToDouble()));
    bytes->SetValue(i, static_cast<unsigned char>(v * 255.0 + 0.5));
  }
  array = bytes;
  this->LastArray = array;
  return true;
}

bool LegacyParser::ReadLookupTable()
{
  // LOOKUP_TABLE name size, then size RGBA entries (bytes in binary files, [0, 1] in ASCII).
  std::string name;
  vtkIdType size = 0;
  if (!this->ReadWordAfter("LOOKUP_TABLE", name) || !this->ReadCount("LOOKUP_TABLE", size))
  {
    return false;
  }
  vtkSmartPointer<vtkDataArray> entries;
  if (!this->ReadValues("LOOKUP_TABLE", this->Binary ? VTK_UNSIGNED_CHAR : VTK_FLOAT, size, 4, entries))
  {
    return false;
  }
  vtkNew<vtkLookupTable> table;
  table->SetNumberOfTableValues(size);
  const double scale = this->Binary ? 1.0 / 255.0 : 1.0;
  for (vtkIdType i = 0; i < size; ++i)
  {
    double rgba[4];
    entries->GetTuple(i, rgba);
    table->SetTableValue(i, rgba[0] * scale, rgba[1] * scale, rgba[2] * scale, rgba[3] * scale);
  }
  const auto users = this->ScalarsByTable.equal_range(DecodeName(name));
  for (auto user = users.first; user != users.second; ++user)
  {
    user->second->SetLookupTable(table);
  }
  this->LastArray = nullptr;
  return true;
}

bool LegacyParser::ReadField(vtkFieldData* field)
{
  // FIELD name numArrays, then per array: name components tuples type, values, [METADATA].
  std::string fieldName;
  vtkIdType numArrays = 0;
  if (!this->ReadWordAfter("FIELD", fieldName) || !this->ReadCount("FIELD", numArrays))
  {
    return false;
  }
  for (vtkIdType a = 0; a < numArrays; ++a)
  {
    std::string name;
    if (!this->ReadWordAfter("FIELD " + fieldName, name))
    {
      return false;
    }
    if (name == "NULL_ARRAY")
    {
      continue;
    }
    name = DecodeName(name);
    const std::string what = "field array '" + name + "'";
    int components = 0, type = 0;
    vtkIdType tuples = 0;
    if (!this->Scanner.NextNumber(components) || components < 1 || !this->ReadCount(what, tuples))
    {
      return this->Fail(what + ": expected 'components tuples type'.");
    }
    vtkSmartPointer<vtkDataArray> array;
    if (!this->ReadType(what, type) || !this->ReadValues(what, type, tuples, components, array))
    {
      return false;
    }
    array->SetName(name.c_str());
    field->AddArray(array);
    if (Lower(this->Scanner.PeekWord()) == "metadata")
    {
      this->Scanner.NextWord(name);
      this->ReadMetaData();
    }
  }
  return true;
}

bool LegacyParser::ReadMetaData()
{
  // Lines up to a blank one: COMPONENT_NAMES (one %-encoded name per component) and
  // INFORMATION entries (cached ranges; skipped).
  this->Scanner.SkipRestOfLine();
  std::string line;
  while (this->Scanner.NextLine(line) && line.find_first_not_of(" \t") != std::string::npos)
  {
    if (Lower(line) == "component_names" && this->LastArray)
    {
      for (int c = 0; c < this->LastArray->GetNumberOfComponents() && this->Scanner.NextLine(line); ++c)
      {
        this->LastArray->SetComponentName(c, DecodeName(line).c_str());
      }
    }
  }
  return true;
}

bool LegacyParser::CheckSizes(vtkPolyData* output)
{
  const vtkIdType numPoints = output->GetNumberOfPoints(), numCells = output->GetNumberOfCells();
  for (auto* attributes : { static_cast<vtkDataSetAttributes*>(output->GetPointData()),
         static_cast<vtkDataSetAttributes*>(output->GetCellData()) })
  {
    const bool points = attributes == output->GetPointData();
    const vtkIdType expected = points ? numPoints : numCells;
    for (int a = 0; a < attributes->GetNumberOfArrays(); ++a)
    {
      vtkAbstractArray* array = attributes->GetAbstractArray(a);
      if (array->GetNumberOfTuples() != expected)
      {
        return this->Report(0, std::string(points ? "point" : "cell") + " data array '" +
            (array->GetName() ? array->GetName() : "") + "' has " + std::to_string(array->GetNumberOfTuples()) +
            " tuples for " + std::to_string(expected) + (points ? " points." : " cells."));
      }
    }
  }
  return true;
}
}
