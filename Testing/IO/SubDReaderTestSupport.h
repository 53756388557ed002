// Shared by the reader tests: an exact comparison of two polydata (the reader under test
// against VTK's reader on the same valid file), and reading a text through a reader while
// collecting its errors.
#ifndef SubDReaderTestSupport_h
#define SubDReaderTestSupport_h

#include "SubDTempFiles.h"

#include "vtkAbstractArray.h"
#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <string>

namespace subdtest
{
inline std::string ReaderTempPath(const std::string& name)
{
  return ProcessTempPath("subd_reader_", name);
}

inline void WriteFileBytes(const std::string& path, const std::string& bytes)
{
  std::ofstream(path, std::ios::binary) << bytes;
}

inline std::string ReadFileBytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Same type, components, names and values (bit for bit: NaN equals NaN).
inline void ExpectSameArray(vtkAbstractArray* expected, vtkAbstractArray* actual, const std::string& where)
{
  ASSERT_NE(actual, nullptr) << where;
  EXPECT_EQ(actual->GetDataType(), expected->GetDataType()) << where;
  EXPECT_EQ(actual->GetNumberOfComponents(), expected->GetNumberOfComponents()) << where;
  ASSERT_EQ(actual->GetNumberOfTuples(), expected->GetNumberOfTuples()) << where;
  for (int c = 0; c < expected->GetNumberOfComponents(); ++c)
  {
    const char* e = expected->GetComponentName(c);
    const char* a = actual->GetComponentName(c);
    EXPECT_EQ(std::string(e ? e : ""), std::string(a ? a : "")) << where << " component " << c;
  }
  auto* e = vtkDataArray::SafeDownCast(expected);
  auto* a = vtkDataArray::SafeDownCast(actual);
  ASSERT_TRUE(e && a) << where;
  if (e->GetDataType() == a->GetDataType() && e->GetNumberOfValues() > 0)
  {
    EXPECT_EQ(0, std::memcmp(e->GetVoidPointer(0), a->GetVoidPointer(0), e->GetNumberOfValues() * e->GetDataTypeSize()))
      << where << " values differ";
  }
}

inline void ExpectSameCells(vtkCellArray* expected, vtkCellArray* actual, const std::string& where)
{
  ASSERT_EQ(actual->GetNumberOfCells(), expected->GetNumberOfCells()) << where;
  for (vtkIdType c = 0; c < expected->GetNumberOfCells(); ++c)
  {
    vtkNew<vtkIdList> e, a;
    expected->GetCellAtId(c, e);
    actual->GetCellAtId(c, a);
    ASSERT_EQ(a->GetNumberOfIds(), e->GetNumberOfIds()) << where << " cell " << c;
    for (vtkIdType k = 0; k < e->GetNumberOfIds(); ++k)
    {
      EXPECT_EQ(a->GetId(k), e->GetId(k)) << where << " cell " << c;
    }
  }
}

inline void ExpectSameField(vtkFieldData* expected, vtkFieldData* actual, const std::string& where)
{
  ASSERT_EQ(actual->GetNumberOfArrays(), expected->GetNumberOfArrays()) << where;
  for (int i = 0; i < expected->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* e = expected->GetAbstractArray(i);
    ExpectSameArray(e, actual->GetAbstractArray(e->GetName()), where + " array '" + e->GetName() + "'");
  }
}

inline void ExpectSameAttributes(vtkDataSetAttributes* expected, vtkDataSetAttributes* actual, const std::string& where)
{
  ExpectSameField(expected, actual, where);
  for (int kind = 0; kind < vtkDataSetAttributes::NUM_ATTRIBUTES; ++kind)
  {
    vtkAbstractArray* e = expected->GetAbstractAttribute(kind);
    vtkAbstractArray* a = actual->GetAbstractAttribute(kind);
    EXPECT_EQ(e == nullptr, a == nullptr) << where << " attribute " << vtkDataSetAttributes::GetAttributeTypeAsString(kind);
    if (e && a)
    {
      EXPECT_STREQ(e->GetName(), a->GetName()) << where;
    }
  }
}

/// `actual` holds exactly what `expected` holds: points, the four cell kinds, point, cell and
/// field data.
inline void ExpectSamePolyData(vtkPolyData* expected, vtkPolyData* actual, const std::string& where)
{
  ASSERT_EQ(actual->GetNumberOfPoints(), expected->GetNumberOfPoints()) << where;
  if (expected->GetPoints())
  {
    ExpectSameArray(expected->GetPoints()->GetData(), actual->GetPoints()->GetData(), where + " points");
  }
  ExpectSameCells(expected->GetVerts(), actual->GetVerts(), where + " verts");
  ExpectSameCells(expected->GetLines(), actual->GetLines(), where + " lines");
  ExpectSameCells(expected->GetPolys(), actual->GetPolys(), where + " polys");
  ExpectSameCells(expected->GetStrips(), actual->GetStrips(), where + " strips");
  ExpectSameAttributes(expected->GetPointData(), actual->GetPointData(), where + " point data");
  ExpectSameAttributes(expected->GetCellData(), actual->GetCellData(), where + " cell data");
  ExpectSameField(expected->GetFieldData(), actual->GetFieldData(), where + " field data");
}

/// Runs `reader` on the file `path`; returns its error messages ("" when none). On an
/// error, the output must be empty and the error code set.
template <typename Reader>
std::string ReadErrorsOf(Reader* reader, const std::string& path)
{
  std::string errors;
  vtkNew<vtkCallbackCommand> collect;
  collect->SetClientData(&errors);
  collect->SetCallback([](vtkObject*, unsigned long, void* client, void* data) {
    *static_cast<std::string*>(client) += static_cast<const char*>(data);
  });
  const unsigned long tag = reader->AddObserver(vtkCommand::ErrorEvent, collect);
  reader->SetFileName(path.c_str());
  reader->Modified();
  reader->Update();
  reader->RemoveObserver(tag);
  if (!errors.empty())
  {
    EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0) << path;
    EXPECT_NE(reader->GetErrorCode(), 0ul) << path;
  }
  return errors;
}
}

#endif
