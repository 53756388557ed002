#include "vtkSubDPLYWriter.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSubDBufferedOutput.h"
#include "vtkSubDFileScanner.h" // MachineIsBigEndian
#include "vtkSubDStripTriangles.h"

#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSubDPLYWriter);

namespace
{
// One property of the vertex element: a component of a point array, written as `Type`.
struct Column
{
  vtkDataArray* Array;
  int Component;
  int Type; // a VTK type PLY has (VTK_CHAR ... VTK_DOUBLE)
  std::string Name;

  // The array's memory when it is laid out as one block of tuples (nearly always): values
  // are then read from it directly, not through the array's virtual GetComponent.
  const void* Values = Array->HasStandardMemoryLayout() ? Array->GetVoidPointer(0) : nullptr;
  int SourceType = Array->GetDataType();
  int Components = Array->GetNumberOfComponents();

  double Value(vtkIdType i) const
  {
    const vtkIdType at = i * this->Components + this->Component;
    switch (this->Values ? this->SourceType : VTK_VOID)
    {
      vtkTemplateMacro(return static_cast<double>(static_cast<const VTK_TT*>(this->Values)[at]));
    }
    return this->Array->GetComponent(i, this->Component);
  }
};

// The PLY type for a VTK type, and the VTK type values are written as: PLY has 8-, 16- and
// 32-bit integers, float and double; the rest are written as double.
int WrittenType(int vtkType)
{
  switch (vtkType)
  {
    case VTK_CHAR:
    case VTK_SIGNED_CHAR:
      return VTK_SIGNED_CHAR;
    case VTK_UNSIGNED_CHAR:
    case VTK_SHORT:
    case VTK_UNSIGNED_SHORT:
    case VTK_INT:
    case VTK_UNSIGNED_INT:
    case VTK_FLOAT:
      return vtkType;
    default:
      return VTK_DOUBLE;
  }
}

const char* PLYTypeName(int writtenType)
{
  switch (writtenType)
  {
    case VTK_SIGNED_CHAR:
      return "char";
    case VTK_UNSIGNED_CHAR:
      return "uchar";
    case VTK_SHORT:
      return "short";
    case VTK_UNSIGNED_SHORT:
      return "ushort";
    case VTK_INT:
      return "int";
    case VTK_UNSIGNED_INT:
      return "uint";
    case VTK_FLOAT:
      return "float";
    default:
      return "double";
  }
}

// `value` (read as a double: exact for every type written) stored as `writtenType`, one of
// WrittenType's (VTK's C types for them have PLY's sizes).
void PutAs(vtkSubDBufferedOutput& out, int writtenType, double value)
{
  switch (writtenType)
  {
    vtkTemplateMacro(out.Put(static_cast<VTK_TT>(value)));
  }
}

// A PLY property name: one word.
std::string PropertyName(const char* arrayName, int index)
{
  std::string name = arrayName && *arrayName ? arrayName : "array" + std::to_string(index);
  for (char& c : name)
  {
    c = subdio::FileScanner::IsSpace(c) ? '_' : c;
  }
  return name;
}

// Appends the columns of point-data array `a` of `pd` to `columns` as the reader names them
// (normals, colours, texture coordinates, single components), or its name to `skipped` when
// PLY has no property form for it.
void AddPointDataColumns(vtkPointData* pd, int a, std::vector<Column>& columns, std::vector<std::string>& skipped)
{
  vtkDataArray* array = pd->GetArray(a);
  if (!array)
  {
    skipped.push_back(pd->GetAbstractArray(a)->GetName() ? pd->GetAbstractArray(a)->GetName() : "");
    return;
  }
  const int components = array->GetNumberOfComponents();
  const int type = WrittenType(array->GetDataType());
  const char* name = array->GetName() ? array->GetName() : "";
  if (array == pd->GetNormals() && components == 3)
  {
    for (int c = 0; c < 3; ++c)
    {
      columns.push_back({ array, c, type, std::string("n") + "xyz"[c] });
    }
  }
  else if (array->GetDataType() == VTK_UNSIGNED_CHAR && (components == 3 || components == 4) &&
    (array == pd->GetScalars() || std::strcmp(name, "RGB") == 0 || std::strcmp(name, "RGBA") == 0))
  {
    const char* channels[] = { "red", "green", "blue", "alpha" };
    for (int c = 0; c < components; ++c)
    {
      columns.push_back({ array, c, type, channels[c] });
    }
  }
  else if (array == pd->GetTCoords() && components == 2)
  {
    columns.push_back({ array, 0, type, "u" });
    columns.push_back({ array, 1, type, "v" });
  }
  else if (components == 1)
  {
    columns.push_back({ array, 0, type, PropertyName(name, a) });
  }
  else
  {
    skipped.push_back(name);
  }
}

// The vertex element's properties: the points, then the point data as the reader names it;
// the names of the point-data arrays not written go to `skipped`.
std::vector<Column> VertexColumns(vtkPolyData* input, std::vector<std::string>& skipped)
{
  std::vector<Column> columns;
  vtkDataArray* coordinates = input->GetNumberOfPoints() > 0 ? input->GetPoints()->GetData() : nullptr;
  const int pointType = coordinates && coordinates->GetDataType() == VTK_FLOAT ? VTK_FLOAT : VTK_DOUBLE;
  for (int c = 0; c < 3 && coordinates; ++c)
  {
    columns.push_back({ coordinates, c, pointType, std::string(1, "xyz"[c]) });
  }
  vtkPointData* pd = input->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    AddPointDataColumns(pd, a, columns, skipped);
  }
  return columns;
}

// `names` quoted and separated by ", ".
std::string QuotedNames(const std::vector<std::string>& names)
{
  std::string quoted;
  for (const std::string& name : names)
  {
    quoted += (quoted.empty() ? "'" : ", '") + name + "'";
  }
  return quoted;
}

// Writes the PLY header: binary in the machine's byte order, the vertex element's `columns`,
// the face element with its vertex counts as int when `wideCounts`, else uchar.
void WriteHeader(vtkSubDBufferedOutput& out, vtkIdType numPoints, const std::vector<Column>& columns,
  vtkIdType numFaces, bool wideCounts)
{
  out << "ply\nformat " << (subdio::FileScanner::MachineIsBigEndian() ? "binary_big_endian" : "binary_little_endian")
      << " 1.0\ncomment written by SubD\nelement vertex " << numPoints << "\n";
  for (const Column& column : columns)
  {
    out << "property " << PLYTypeName(column.Type) << ' ' << column.Name << "\n";
  }
  out << "element face " << numFaces << "\nproperty list " << (wideCounts ? "int" : "uchar")
      << " int vertex_indices\nend_header\n";
}

// Writes the face element: the polygons, then the strips' triangles, each as its vertex count
// (int when `wideCounts`, else uchar) and int vertex indices.
void WriteFaces(vtkSubDBufferedOutput& out, vtkCellArray* polys, vtkCellArray* strips, bool wideCounts)
{
  auto putCount = [wideCounts](vtkSubDBufferedOutput& record, vtkIdType n) {
    if (wideCounts)
    {
      record.Put(static_cast<std::int32_t>(n));
    }
    else
    {
      record.Put(static_cast<std::uint8_t>(n));
    }
  };
  vtkSubDFormatCellsInParallel(out, polys, [&putCount](vtkSubDBufferedOutput& record, const auto& pts) {
    putCount(record, pts.size());
    for (const auto id : pts)
    {
      record.Put(static_cast<std::int32_t>(id));
    }
  });
  vtkSubDForEachStripTriangle(strips, [&](vtkIdType a, vtkIdType b, vtkIdType c) {
    putCount(out, 3);
    out.Put(static_cast<std::int32_t>(a));
    out.Put(static_cast<std::int32_t>(b));
    out.Put(static_cast<std::int32_t>(c));
  });
}
}

void vtkSubDPLYWriter::WriteFile(vtkPolyData* input, std::ostream& file)
{
  const vtkIdType numPoints = input->GetNumberOfPoints();
  if (numPoints > std::numeric_limits<std::int32_t>::max())
  {
    vtkErrorMacro(<< numPoints << " points: more than PLY's int vertex indices can name.");
    return;
  }
  if (input->GetNumberOfLines() + input->GetNumberOfVerts() > 0)
  {
    vtkWarningMacro("PLY holds only polygons here: " << input->GetNumberOfLines() << " lines and "
                                                    << input->GetNumberOfVerts() << " verts are not written.");
  }
  if (input->GetCellData()->GetNumberOfArrays() > 0)
  {
    vtkWarningMacro("Cell data is not written to PLY (" << input->GetCellData()->GetNumberOfArrays()
                                                        << " array(s)).");
  }
  std::vector<std::string> skipped;
  const std::vector<Column> columns = VertexColumns(input, skipped);
  if (!skipped.empty())
  {
    vtkWarningMacro("Point-data array(s) " << QuotedNames(skipped) << " have no PLY property form and are not written.");
  }

  vtkCellArray* polys = input->GetPolys();
  vtkCellArray* strips = input->GetStrips();
  const vtkIdType numFaces = polys->GetNumberOfCells() + vtkSubDCountStripTriangles(strips);
  const bool wideCounts = polys->GetMaxCellSize() > 255;
  vtkSubDBufferedOutput out(file);
  WriteHeader(out, numPoints, columns, numFaces, wideCounts);
  // Records made on threads, chunk by chunk, and written in order (vtkSubDFormatInParallel).
  vtkSubDFormatInParallel(out, numPoints, [&columns](vtkSubDBufferedOutput& record, vtkIdType i) {
    for (const Column& column : columns)
    {
      PutAs(record, column.Type, column.Value(i));
    }
  });
  WriteFaces(out, polys, strips, wideCounts);
}

void vtkSubDPLYWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
