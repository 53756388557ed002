#include "vtkSubDPLYReader.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSubDFileScanner.h"
#include "vtkSubDReadValues.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkSubDPLYReader);

namespace
{
bool IsFaceIndexList(const std::string& name)
{
  return name == "vertex_indices" || name == "vertex_index";
}

struct PLYProperty
{
  std::string Name;
  int Type = 0;      // of the values (the items, for a list)
  int CountType = 0; // of a list's count; 0 for a scalar property
  vtkSmartPointer<vtkDataArray> Values; // scalar properties of "vertex" and "face"
};

struct PLYElement
{
  std::string Name;
  vtkIdType Count = 0;
  std::vector<PLYProperty> Properties;
  PLYProperty* Find(const std::string& name)
  {
    for (PLYProperty& p : this->Properties)
    {
      if (p.Name == name && p.CountType == 0)
      {
        return &p;
      }
    }
    return nullptr;
  }
};

// The VTK type of a PLY type name (both spellings of the spec); 0 when unknown.
int TypeFromName(const std::string& name)
{
  static const std::map<std::string, int> types = { { "char", VTK_SIGNED_CHAR }, { "int8", VTK_SIGNED_CHAR },
    { "uchar", VTK_UNSIGNED_CHAR }, { "uint8", VTK_UNSIGNED_CHAR }, { "short", VTK_SHORT }, { "int16", VTK_SHORT },
    { "ushort", VTK_UNSIGNED_SHORT }, { "uint16", VTK_UNSIGNED_SHORT }, { "int", VTK_INT }, { "int32", VTK_INT },
    { "uint", VTK_UNSIGNED_INT }, { "uint32", VTK_UNSIGNED_INT }, { "float", VTK_FLOAT },
    { "float32", VTK_FLOAT }, { "double", VTK_DOUBLE }, { "float64", VTK_DOUBLE } };
  const auto found = types.find(name);
  return found == types.end() ? 0 : found->second;
}

int TypeSize(int type)
{
  vtkSmartPointer<vtkDataArray> probe;
  probe.TakeReference(vtkDataArray::CreateDataArray(type));
  return probe->GetDataTypeSize();
}

// One value of `type` as a double (exact for every PLY type).
template <typename T>
bool ReadOne(subdio::FileScanner& scanner, bool binary, bool bigEndian, double& value)
{
  T item{};
  const bool ok = binary ? scanner.NextBinary(&item, 1, bigEndian) : scanner.NextNumber(item);
  value = static_cast<double>(item);
  return ok;
}

bool ReadScalar(subdio::FileScanner& scanner, int type, bool binary, bool bigEndian, double& value)
{
  switch (type)
  {
    case VTK_SIGNED_CHAR:
      return ReadOne<signed char>(scanner, binary, bigEndian, value);
    case VTK_UNSIGNED_CHAR:
      return ReadOne<unsigned char>(scanner, binary, bigEndian, value);
    case VTK_SHORT:
      return ReadOne<short>(scanner, binary, bigEndian, value);
    case VTK_UNSIGNED_SHORT:
      return ReadOne<unsigned short>(scanner, binary, bigEndian, value);
    case VTK_INT:
      return ReadOne<int>(scanner, binary, bigEndian, value);
    case VTK_UNSIGNED_INT:
      return ReadOne<unsigned int>(scanner, binary, bigEndian, value);
    case VTK_FLOAT:
      return ReadOne<float>(scanner, binary, bigEndian, value);
    default:
      return ReadOne<double>(scanner, binary, bigEndian, value);
  }
}

class PLYParser : public subdio::FileParser
{
public:
  PLYParser(subdio::FileScanner& scanner, Reporter report)
    : FileParser(scanner, std::move(report))
  {
  }

  bool Parse(vtkPolyData* output);

private:
  bool ReadHeader();
  bool ReadHeaderLine(const std::string& line);
  bool ReadElement(PLYElement& element);
  bool ReadList(PLYElement& element, const PLYProperty& property, vtkIdType index);
  bool MakePoints(vtkPolyData* output);
  void MakeAttributes(PLYElement& element, vtkDataSetAttributes* attributes);

  bool BigEndian = false;
  std::vector<PLYElement> Elements;
  vtkIdType NumVertices = -1;
  vtkNew<vtkIdTypeArray> Offsets, Connectivity;
};

bool PLYParser::ReadHeader()
{
  std::string line;
  if (!this->Scanner.NextLine(line) || line != "ply")
  {
    return this->Fail("not a PLY file: the first line must be 'ply'.");
  }
  while (this->Scanner.NextLine(line))
  {
    if (line.find_first_not_of(" \t") == std::string::npos)
    {
      continue;
    }
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "end_header")
    {
      if (this->Elements.empty())
      {
        return this->Fail("the header declares no element.");
      }
      return true;
    }
    if (!this->ReadHeaderLine(line))
    {
      return false;
    }
  }
  return this->Fail("the file ends inside its header (no 'end_header').");
}

bool PLYParser::ReadHeaderLine(const std::string& line)
{
  std::istringstream words(line);
  std::string keyword;
  words >> keyword;
  if (keyword == "comment" || keyword == "obj_info")
  {
    return true;
  }
  if (keyword == "format")
  {
    std::string format, version;
    words >> format >> version;
    if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
    {
      return this->Fail("unknown format '" + format + "' (ascii, binary_little_endian or binary_big_endian).");
    }
    this->Binary = format != "ascii";
    this->BigEndian = format == "binary_big_endian";
    return true;
  }
  if (keyword == "element")
  {
    PLYElement element;
    std::string count, extra;
    words >> element.Name >> count;
    const auto parsed = std::from_chars(count.data(), count.data() + count.size(), element.Count);
    if (element.Name.empty() || parsed.ec != std::errc() || parsed.ptr != count.data() + count.size() ||
      element.Count < 0 || (words >> extra))
    {
      return this->Fail("expected 'element name count', found '" + line + "'.");
    }
    this->Elements.push_back(element);
    return true;
  }
  if (keyword == "property")
  {
    if (this->Elements.empty())
    {
      return this->Fail("a property before any element.");
    }
    PLYProperty property;
    std::string type, countType, itemType, extra;
    words >> type;
    if (type == "list")
    {
      words >> countType >> itemType >> property.Name;
      property.CountType = TypeFromName(countType);
      property.Type = TypeFromName(itemType);
      if (property.CountType == VTK_FLOAT || property.CountType == VTK_DOUBLE)
      {
        property.CountType = 0;
      }
    }
    else
    {
      words >> property.Name;
      property.Type = TypeFromName(type);
    }
    if (property.Name.empty() || property.Type == 0 || (type == "list" && property.CountType == 0) ||
      (words >> extra))
    {
      return this->Fail("expected 'property type name' or 'property list count-type item-type name' with PLY "
                        "types (char uchar short ushort int uint float double), found '" +
        line + "'.");
    }
    this->Elements.back().Properties.push_back(property);
    return true;
  }
  return this->Fail("unknown header line '" + line + "'.");
}

bool PLYParser::ReadList(PLYElement& element, const PLYProperty& property, vtkIdType index)
{
  double count = 0;
  if (!ReadScalar(this->Scanner, property.CountType, this->Binary, this->BigEndian, count) || count < 0)
  {
    return this->Fail(element.Name + " " + std::to_string(index) + ": expected the length of list '" +
      property.Name + "'.");
  }
  const bool faceIndices = element.Name == "face" && IsFaceIndexList(property.Name);
  for (double k = 0; k < count; ++k)
  {
    double value = 0;
    if (!ReadScalar(this->Scanner, property.Type, this->Binary, this->BigEndian, value))
    {
      return this->Fail(element.Name + " " + std::to_string(index) + ": list '" + property.Name + "' announces " +
        std::to_string(static_cast<long long>(count)) + " values; value " + std::to_string(static_cast<long long>(k)) +
        " is missing or not a number of its type.");
    }
    if (faceIndices)
    {
      if (!(value >= 0 && value < this->NumVertices) || value != std::floor(value))
      {
        return this->Fail("face " + std::to_string(index) + " uses vertex " + std::to_string(value) +
          ", but the file has " + std::to_string(this->NumVertices) + " vertices.");
      }
      this->Connectivity->InsertNextValue(static_cast<vtkIdType>(value));
    }
  }
  if (faceIndices)
  {
    this->Offsets->InsertNextValue(this->Connectivity->GetNumberOfValues());
  }
  return true;
}

bool PLYParser::ReadElement(PLYElement& element)
{
  // Before allocating: the fewest bytes an element can take (a list may be empty).
  double leastBytes = 0;
  for (const PLYProperty& p : element.Properties)
  {
    leastBytes += this->Binary ? TypeSize(p.CountType ? p.CountType : p.Type) : 2.0;
  }
  if (leastBytes == 0 || element.Count == 0)
  {
    return true; // nothing to read
  }
  if (!this->Scanner.ReserveFor(static_cast<double>(element.Count), leastBytes))
  {
    return this->Fail("the header announces " + std::to_string(element.Count) + " " + element.Name +
      " elements, more than the rest of the file holds.");
  }
  const bool kept = element.Name == "vertex" || element.Name == "face";
  for (PLYProperty& p : element.Properties)
  {
    if (kept && p.CountType == 0)
    {
      p.Values.TakeReference(vtkDataArray::CreateDataArray(p.Type));
      p.Values->SetName(p.Name.c_str());
      p.Values->SetNumberOfTuples(element.Count);
    }
  }
  if (element.Name == "face")
  {
    this->Offsets->Allocate(element.Count + 1);
    this->Offsets->InsertNextValue(0);
  }
  for (vtkIdType i = 0; i < element.Count; ++i)
  {
    for (const PLYProperty& p : element.Properties)
    {
      double ignored = 0;
      const bool ok = p.CountType ? this->ReadList(element, p, i)
        : p.Values ? subdio::ReadArrayValues(this->Scanner, p.Values, i, 1, this->Binary, this->BigEndian)
                   : ReadScalar(this->Scanner, p.Type, this->Binary, this->BigEndian, ignored);
      if (!ok)
      {
        return p.CountType ? false
                           : this->Fail(element.Name + " " + std::to_string(i) + " of " +
                               std::to_string(element.Count) + ": property '" + p.Name +
                               "' is missing or not a number of its type.");
      }
    }
  }
  return true;
}

// Takes the named properties out of `element` as one array of `components` = names.size()
// components, of `type`, scaled by `scale`; nullptr (taking nothing) unless all are present.
vtkSmartPointer<vtkDataArray> TakeGroup(
  PLYElement& element, const std::vector<std::string>& names, int type, const char* arrayName, double scale = 1)
{
  std::vector<PLYProperty*> parts;
  for (const std::string& name : names)
  {
    PLYProperty* p = element.Find(name);
    if (!p || !p->Values)
    {
      return nullptr;
    }
    parts.push_back(p);
  }
  vtkSmartPointer<vtkDataArray> group;
  group.TakeReference(vtkDataArray::CreateDataArray(type));
  group->SetName(arrayName);
  group->SetNumberOfComponents(static_cast<int>(parts.size()));
  group->SetNumberOfTuples(element.Count);
  for (size_t c = 0; c < parts.size(); ++c)
  {
    for (vtkIdType i = 0; i < element.Count; ++i)
    {
      double v = parts[c]->Values->GetComponent(i, 0) * scale;
      if (type == VTK_UNSIGNED_CHAR)
      {
        v = std::min(255.0, std::max(0.0, std::round(v)));
      }
      group->SetComponent(i, static_cast<int>(c), v);
    }
    parts[c]->Values = nullptr;
  }
  return group;
}

// Colours as bytes: byte properties as they are, real ones (in [0, 1]) scaled.
vtkSmartPointer<vtkDataArray> TakeColors(PLYElement& element, const std::string& prefix)
{
  std::vector<std::string> names = { prefix + "red", prefix + "green", prefix + "blue" };
  const bool alpha = element.Find(prefix + "alpha") != nullptr;
  if (alpha)
  {
    names.push_back(prefix + "alpha");
  }
  PLYProperty* red = element.Find(prefix + "red");
  const double scale = red && (red->Type == VTK_FLOAT || red->Type == VTK_DOUBLE) ? 255.0 : 1.0;
  return TakeGroup(element, names, VTK_UNSIGNED_CHAR, alpha ? "RGBA" : "RGB", scale);
}

void PLYParser::MakeAttributes(PLYElement& element, vtkDataSetAttributes* attributes)
{
  vtkSmartPointer<vtkDataArray> colors = TakeColors(element, "");
  colors = colors ? colors : TakeColors(element, "diffuse_");
  if (colors)
  {
    attributes->SetScalars(colors);
  }
  if (auto normals = TakeGroup(element, { "nx", "ny", "nz" }, VTK_FLOAT, "Normals"))
  {
    attributes->SetNormals(normals);
  }
  for (const auto& uv : std::vector<std::vector<std::string>>{
         { "u", "v" }, { "s", "t" }, { "texture_u", "texture_v" }, { "texture_s", "texture_t" } })
  {
    if (auto tcoords = TakeGroup(element, uv, VTK_FLOAT, "TCoords"))
    {
      attributes->SetTCoords(tcoords);
      break;
    }
  }
  for (PLYProperty& p : element.Properties)
  {
    if (p.Values)
    {
      attributes->AddArray(p.Values);
    }
  }
}

bool PLYParser::MakePoints(vtkPolyData* output)
{
  auto vertex = std::find_if(
    this->Elements.begin(), this->Elements.end(), [](const PLYElement& e) { return e.Name == "vertex"; });
  PLYProperty* xyz[3] = { vertex->Find("x"), vertex->Find("y"), vertex->Find("z") };
  const bool anyDouble = std::any_of(xyz, xyz + 3, [](PLYProperty* p) { return p->Type == VTK_DOUBLE; });
  vtkSmartPointer<vtkDataArray> coordinates =
    TakeGroup(*vertex, { "x", "y", "z" }, anyDouble ? VTK_DOUBLE : VTK_FLOAT, "Points");
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  output->SetPoints(points);
  this->MakeAttributes(*vertex, output->GetPointData());
  return true;
}

bool PLYParser::Parse(vtkPolyData* output)
{
  if (!this->ReadHeader())
  {
    return false;
  }
  for (PLYElement& element : this->Elements)
  {
    if (element.Name == "vertex")
    {
      if (this->NumVertices >= 0 || !element.Find("x") || !element.Find("y") || !element.Find("z"))
      {
        return this->Fail("the header must declare one vertex element with properties x, y and z.");
      }
      this->NumVertices = element.Count;
    }
    if (element.Name == "face" && element.Count > 0)
    {
      // Exactly one face index list: with none or two, faces would be lost or doubled.
      const auto lists = std::count_if(element.Properties.begin(), element.Properties.end(),
        [](const PLYProperty& p) { return p.CountType != 0 && IsFaceIndexList(p.Name); });
      if (lists != 1)
      {
        return this->Fail("the face element must have one list property vertex_indices (or vertex_index); it has " +
          std::to_string(lists) + ".");
      }
    }
  }
  if (this->NumVertices < 0)
  {
    return this->Fail("the header declares no vertex element.");
  }
  for (PLYElement& element : this->Elements)
  {
    if (!this->ReadElement(element))
    {
      return false;
    }
  }
  this->MakePoints(output);
  auto face = std::find_if(
    this->Elements.begin(), this->Elements.end(), [](const PLYElement& e) { return e.Name == "face"; });
  if (face != this->Elements.end() && this->Offsets->GetNumberOfValues() == face->Count + 1)
  {
    vtkNew<vtkCellArray> polys;
    polys->SetData(this->Offsets, this->Connectivity);
    output->SetPolys(polys);
    this->MakeAttributes(*face, output->GetCellData());
  }
  return true;
}
}

bool vtkSubDPLYReader::ReadFile(std::istream& file, vtkPolyData* output)
{
  return subdio::ParseFile<PLYParser>(
    file, output, [this](long line, const std::string& what) { return this->Fail(line, what); });
}

void vtkSubDPLYReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
