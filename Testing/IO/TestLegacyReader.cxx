// vtkSubDLegacyReader: on every file vtkPolyDataWriter writes (ASCII and binary, file
// versions 4.2 and 5.1, every attribute kind and value type) it reads exactly what VTK's own
// reader reads; on broken files it names the problem instead of crashing.
#include "vtkSubDLegacyReader.h"

#include "SubDReaderTestSupport.h"

#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkLongArray.h"
#include "vtkLookupTable.h"
#include "vtkPolyDataReader.h"
#include "vtkPolyDataWriter.h"
#include "vtkShortArray.h"
#include "vtkSignedCharArray.h"
#include "vtkTypeInt64Array.h"
#include "vtkTypeUInt64Array.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedIntArray.h"
#include "vtkUnsignedShortArray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace
{
template <typename ArrayType>
vtkSmartPointer<ArrayType> Filled(const char* name, int components, vtkIdType tuples, double scale)
{
  auto array = vtkSmartPointer<ArrayType>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  for (vtkIdType i = 0; i < array->GetNumberOfValues(); ++i)
  {
    using Value = typename ArrayType::ValueType;
    const double shift = std::numeric_limits<Value>::is_signed && scale >= 1 ? 20 : 0; // negatives where they fit
    array->SetValue(i, static_cast<Value>(std::fmod(i * scale, 100.0) - shift));
  }
  return array;
}

// Every cell kind and attribute kind; `colors` makes the active point scalars RGBA bytes
// (written as COLOR_SCALARS), otherwise they are floats with a lookup table.
vtkSmartPointer<vtkPolyData> RichMesh(bool colors, int pointType)
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataType(pointType);
  for (int i = 0; i < 12; ++i)
  {
    points->InsertNextPoint(std::cos(i * 0.7) * 1.0 / 3.0, std::sin(i * 1.3) * 1e-7, i * 2.5e5 + 0.1);
  }
  mesh->SetPoints(points);
  vtkNew<vtkCellArray> verts, lines, polys, strips;
  const vtkIdType vert[1] = { 11 }, line[3] = { 0, 5, 9 }, tri[3] = { 0, 1, 2 }, quad[4] = { 2, 3, 4, 5 },
                  penta[5] = { 5, 6, 7, 8, 9 }, strip[5] = { 7, 8, 9, 10, 11 };
  verts->InsertNextCell(1, vert);
  lines->InsertNextCell(3, line);
  polys->InsertNextCell(3, tri);
  polys->InsertNextCell(4, quad);
  polys->InsertNextCell(5, penta);
  strips->InsertNextCell(5, strip);
  mesh->SetVerts(verts);
  mesh->SetLines(lines);
  mesh->SetPolys(polys);
  mesh->SetStrips(strips);

  const vtkIdType n = 12;
  vtkPointData* pd = mesh->GetPointData();
  if (colors)
  {
    auto rgba = Filled<vtkUnsignedCharArray>("Surface colour", 4, n, 37);
    for (vtkIdType i = 0; i < rgba->GetNumberOfValues(); ++i)
    {
      rgba->SetValue(i, static_cast<unsigned char>((i * 37) % 256));
    }
    pd->SetScalars(rgba);
  }
  else
  {
    auto temperature = Filled<vtkFloatArray>("Temperature", 1, n, 0.37);
    vtkNew<vtkLookupTable> table;
    table->SetNumberOfTableValues(3);
    table->SetTableValue(0, 0, 0, 1, 1);
    table->SetTableValue(1, 0, 1, 0, 0.5);
    table->SetTableValue(2, 1, 0, 0, 1);
    temperature->SetLookupTable(table);
    pd->SetScalars(temperature);
  }
  pd->SetVectors(Filled<vtkDoubleArray>("Velocity", 3, n, 1.0 / 7.0));
  pd->SetNormals(Filled<vtkFloatArray>("Normals", 3, n, 0.125));
  pd->SetTCoords(Filled<vtkFloatArray>("UV", 2, n, 0.3));
  pd->SetTensors(Filled<vtkDoubleArray>("Stress", 9, n, 1.5));
  pd->SetGlobalIds(Filled<vtkIdTypeArray>("Ids", 1, n, 3));
  auto labelled = Filled<vtkIntArray>("labelled", 2, n, 11);
  labelled->SetComponentName(0, "first part");
  labelled->SetComponentName(1, "second");
  pd->AddArray(labelled);
  pd->AddArray(Filled<vtkUnsignedShortArray>("ushort", 1, n, 13));
  pd->AddArray(Filled<vtkShortArray>("short", 1, n, 17));
  pd->AddArray(Filled<vtkSignedCharArray>("schar", 1, n, 19));
  pd->AddArray(Filled<vtkUnsignedIntArray>("uint", 1, n, 23));
  pd->AddArray(Filled<vtkLongArray>("long", 1, n, 29));
  pd->AddArray(Filled<vtkTypeInt64Array>("int64", 1, n, 31));
  pd->AddArray(Filled<vtkTypeUInt64Array>("uint64", 1, n, 41));

  const vtkIdType cells = mesh->GetNumberOfCells();
  vtkCellData* cd = mesh->GetCellData();
  cd->SetScalars(Filled<vtkIntArray>("Region", 1, cells, 5));
  cd->SetNormals(Filled<vtkDoubleArray>("Face normals", 3, cells, 0.25));
  cd->AddArray(Filled<vtkFloatArray>("area", 1, cells, 0.1));

  mesh->GetFieldData()->AddArray(Filled<vtkDoubleArray>("Time", 1, 1, 1));
  mesh->GetFieldData()->AddArray(Filled<vtkIntArray>("Steps", 1, 5, 7));
  return mesh;
}

std::string WriteWithVTK(vtkPolyData* mesh, bool binary, int version, const std::string& name)
{
  const std::string path = subdtest::ReaderTempPath(name);
  vtkNew<vtkPolyDataWriter> writer;
  writer->SetInputData(mesh);
  writer->SetFileName(path.c_str());
  writer->SetFileVersion(version);
  if (binary)
  {
    writer->SetFileTypeToBinary();
  }
  EXPECT_EQ(writer->Write(), 1);
  return path;
}

vtkSmartPointer<vtkPolyData> ReadWithVTK(const std::string& path)
{
  vtkNew<vtkPolyDataReader> reader;
  reader->SetFileName(path.c_str());
  reader->ReadAllScalarsOn();
  reader->ReadAllVectorsOn();
  reader->ReadAllNormalsOn();
  reader->ReadAllTensorsOn();
  reader->ReadAllColorScalarsOn();
  reader->ReadAllTCoordsOn();
  reader->ReadAllFieldsOn();
  reader->Update();
  return reader->GetOutput();
}

// Reads `text` as a legacy file with SubD's reader: the error messages ("" when none).
std::string LegacyErrors(const std::string& text, vtkPolyData* result = nullptr)
{
  const std::string path = subdtest::ReaderTempPath("case.vtk");
  subdtest::WriteFileBytes(path, text);
  vtkNew<vtkSubDLegacyReader> reader;
  const std::string errors = subdtest::ReadErrorsOf(reader.Get(), path);
  if (result)
  {
    result->DeepCopy(reader->GetOutput());
  }
  return errors;
}

const std::string Header = "# vtk DataFile Version 3.0\nhand made\nASCII\nDATASET POLYDATA\n";
const std::string Square = Header + "POINTS 4 float\n0 0 0 1 0 0 1 1 0 0 1 0\nPOLYGONS 1 5\n4 0 1 2 3\n";
}

class LegacyWrittenByVTK : public ::testing::TestWithParam<std::tuple<bool, int, bool, int>>
{
};

TEST_P(LegacyWrittenByVTK, ReadsWhatVTKReads)
{
  const auto [binary, version, colors, pointType] = GetParam();
  auto mesh = RichMesh(colors, pointType);
  const std::string name = std::string(binary ? "binary" : "ascii") + std::to_string(version) +
    (colors ? "-colors" : "-lut") + (pointType == VTK_FLOAT ? "-float" : "-double") + ".vtk";
  const std::string path = WriteWithVTK(mesh, binary, version, name);
  vtkSmartPointer<vtkPolyData> expected = ReadWithVTK(path);
  ASSERT_EQ(expected->GetNumberOfPoints(), 12);

  vtkNew<vtkSubDLegacyReader> reader;
  EXPECT_EQ(subdtest::ReadErrorsOf(reader.Get(), path), "");
  // VTK's reader makes "signed_char" values plain chars; this one keeps the written type.
  subdtest::ExpectSameArray(mesh->GetPointData()->GetArray("schar"),
    reader->GetOutput()->GetPointData()->GetArray("schar"), name + " signed chars");
  expected->GetPointData()->RemoveArray("schar");
  if (colors)
  {
    // VTK 9.1 writes the name of COLOR_SCALARS as "Surface%%20colour" and reads back "Surface".
    vtkDataArray* rgba = reader->GetOutput()->GetPointData()->GetScalars();
    ASSERT_NE(rgba, nullptr);
    EXPECT_STREQ(rgba->GetName(), "Surface colour");
    expected->GetPointData()->GetScalars()->SetName("Surface colour");
  }
  reader->GetOutput()->GetPointData()->RemoveArray("schar");
  subdtest::ExpectSamePolyData(expected, reader->GetOutput(), name);
  if (!colors)
  {
    auto* scalars = reader->GetOutput()->GetPointData()->GetScalars();
    auto* expectedScalars = expected->GetPointData()->GetScalars();
    ASSERT_TRUE(scalars && scalars->GetLookupTable() && expectedScalars->GetLookupTable());
    ASSERT_EQ(scalars->GetLookupTable()->GetNumberOfTableValues(), 3);
    for (int i = 0; i < 3; ++i)
    {
      double e[4], a[4];
      expectedScalars->GetLookupTable()->GetTableValue(i, e);
      scalars->GetLookupTable()->GetTableValue(i, a);
      for (int c = 0; c < 4; ++c)
      {
        EXPECT_EQ(a[c], e[c]) << name << " table entry " << i;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllLayouts, LegacyWrittenByVTK,
  ::testing::Combine(::testing::Bool(), ::testing::Values(42, 51), ::testing::Bool(),
    ::testing::Values(VTK_FLOAT, VTK_DOUBLE)));

TEST(LegacyReader, KeywordsMatchWithoutCaseAndEverySectionIsKept)
{
  vtkNew<vtkPolyData> mesh;
  const std::string text = "# vtk DataFile Version 2.0\ncase\nascii\ndataset polydata\npoints 4 double\n"
                           "0 0 0 1 0 0 1 1 0 0 1 0\nPolygons 1 5\n4 0 1 2 3\npoint_data 4\n"
                           "scalars first float\nlookup_table default\n1 2 3 4\n"
                           "SCALARS second%20one int 2\nLOOKUP_TABLE default\n1 2 3 4 5 6 7 8\n";
  ASSERT_EQ(LegacyErrors(text, mesh), "");
  EXPECT_EQ(mesh->GetNumberOfPolys(), 1);
  ASSERT_NE(mesh->GetPointData()->GetScalars(), nullptr);
  EXPECT_STREQ(mesh->GetPointData()->GetScalars()->GetName(), "first");
  vtkDataArray* second = mesh->GetPointData()->GetArray("second one"); // VTK's reader drops it by default
  ASSERT_NE(second, nullptr);
  EXPECT_EQ(second->GetNumberOfComponents(), 2);
  EXPECT_EQ(second->GetComponent(3, 1), 8);
}

TEST(LegacyReader, ValuesMayCarryASignOrUnderflow)
{
  vtkNew<vtkPolyData> mesh;
  ASSERT_EQ(LegacyErrors(Header + "POINTS 2 double\n+1 -0 1e-400 nan inf -2.5E+3\n", mesh), "");
  double p[3];
  mesh->GetPoint(0, p);
  EXPECT_EQ(p[0], 1.0);
  EXPECT_EQ(p[2], 0.0);
  mesh->GetPoint(1, p);
  EXPECT_TRUE(std::isnan(p[0]));
  EXPECT_TRUE(std::isinf(p[1]));
  EXPECT_EQ(p[2], -2500.0);
}

// Arrays the parser refers to after they may be gone (both were use-after-free before the
// parser held them; the sanitizer build checks): a lookup table naming an array that a later
// array of the same name replaced, and METADATA after a cell section (a temporary array).
TEST(LegacyReader, ReplacedAndTemporaryArraysAreNotReachedAfterTheyAreGone)
{
  vtkNew<vtkPolyData> mesh;
  const std::string replaced = Square + "POINT_DATA 4\nSCALARS s float\nLOOKUP_TABLE t\n1 2 3 4\n"
                                        "SCALARS s int\nLOOKUP_TABLE default\n5 6 7 8\n"
                                        "LOOKUP_TABLE t 1\n0 0 0 1\n";
  ASSERT_EQ(LegacyErrors(replaced, mesh), "");
  ASSERT_NE(mesh->GetPointData()->GetArray("s"), nullptr);
  EXPECT_EQ(mesh->GetPointData()->GetArray("s")->GetComponent(3, 0), 8); // the later one
  const std::string afterCells = Square + "METADATA\nCOMPONENT_NAMES\nfirst\n\n";
  EXPECT_EQ(LegacyErrors(afterCells, mesh), "");
  EXPECT_EQ(mesh->GetNumberOfPolys(), 1);
}

TEST(LegacyReader, BrokenFilesNameTheirProblem)
{
  struct Case
  {
    std::string text, expected;
  };
  const Case cases[] = {
    { "", "first line" },
    { "# vtk DataFile Version 9.0\nt\nASCII\nDATASET POLYDATA\n", "newer" },
    { "# vtk DataFile Version 3.0\nt\nTEXT\n", "ASCII or BINARY" },
    { "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n", "UNSTRUCTURED_GRID dataset" },
    { Header + "POINTS 2000000000 float\n0 0 0\n", "more than the rest of the file" },
    { Header + "POINTS 4 float\n0 0 0 1 0 0 1 1 0 0 1\n", "expected 12 values" },
    { Header + "POINTS 2 quaternion\n", "unknown value type 'quaternion'" },
    { Header + "POINTS 1 float\n0 0 0\nFIELD f 1\nnames 1 1 string\nabc\n", "type 'string'" },
    { Header + "POINTS -1 float\n", "count" },
    { Square + "LINES 1 6\n3 0 1 2 1 3\n", "use 4 of the 6 values" },
    { Header + "POINTS 4 float\n0 0 0 1 0 0 1 1 0 0 1 0\nPOLYGONS 2 9\n4 0 1 2 3\n4 0 1 2\n", "runs past" },
    { Header + "POINTS 4 float\n0 0 0 1 0 0 1 1 0 0 1 0\nPOLYGONS 1 5\n4 0 1 2.5 3\n", "values of type int" },
    { Square + "POINT_DATA 4\nSCALARS s float\nLOOKUP_TABLE default\n1 2 x 4\n", "line 12" },
    { Square + "POINT_DATA 3\nSCALARS s float\nLOOKUP_TABLE default\n1 2 3\n", "3 tuples for 4 points" },
    { Square + "CELL_DATA 1\nVECTORS v float\n1 2 3\nPOINTS 1 float\n0 0 0\n", "second POINTS" },
    { Square + "SCALARS s float\n", "outside POINT_DATA" },
    { Square + "POINT_DATA 4\nSCALARS s float\n1 2 3 4\n", "LOOKUP_TABLE" },
    { Square + "CELLS 1 2\n", "unknown keyword 'cells'" },
    { "# vtk DataFile Version 5.1\nt\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n0 0 0 1 0 0 0 1 0\n"
      "POLYGONS 2 3\nOFFSETS vtktypeint64\n0 4\nCONNECTIVITY vtktypeint64\n0 1 2\n",
      "offsets must" },
    { "# vtk DataFile Version 5.1\nt\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n0 0 0 1 0 0 0 1 0\n"
      "POLYGONS 2 3\n0 3\n",
      "expected offsets" },
    { "# vtk DataFile Version 3.0\nt\nBINARY\nDATASET POLYDATA\nPOINTS 2 double\n" + std::string(47, 'x'),
      "ends before its values" },
    { "# vtk DataFile Version 3.0\nt\nBINARY\nDATASET POLYDATA\nPOINTS 2 double\n" + std::string(40, 'x'),
      "more than the rest" },
  };
  for (const Case& c : cases)
  {
    const std::string errors = LegacyErrors(c.text);
    EXPECT_NE(errors.find(c.expected), std::string::npos)
      << "file:\n" << c.text << "\nexpected '" << c.expected << "' in: " << errors;
  }
}
