// vtkSubDPLYReader: on every file vtkPLYWriter writes (ASCII, binary in both byte orders,
// with point or cell colours, alpha, texture coordinates) it reads exactly what vtkPLYReader
// reads; it also keeps the properties VTK drops, and names the problem in broken files.
#include "vtkSubDPLYReader.h"

#include "SubDReaderTestSupport.h"

#include "vtkFloatArray.h"
#include "vtkPLYReader.h"
#include "vtkPLYWriter.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

namespace
{
vtkSmartPointer<vtkPolyData> ColoredMesh(bool cellColors, int components)
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  for (int i = 0; i < 7; ++i)
  {
    points->InsertNextPoint(std::cos(i * 0.9) / 3.0, std::sin(i * 0.4) * 1e-6, i * 1e5 + 0.25);
  }
  mesh->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  const vtkIdType tri[3] = { 0, 1, 2 }, quad[4] = { 2, 3, 4, 5 }, penta[5] = { 0, 2, 5, 6, 1 };
  polys->InsertNextCell(3, tri);
  polys->InsertNextCell(4, quad);
  polys->InsertNextCell(5, penta);
  mesh->SetPolys(polys);
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("paint");
  colors->SetNumberOfComponents(components);
  colors->SetNumberOfTuples(cellColors ? 3 : 7);
  for (vtkIdType i = 0; i < colors->GetNumberOfValues(); ++i)
  {
    colors->SetValue(i, static_cast<unsigned char>((i * 53 + 7) % 256));
  }
  (cellColors ? static_cast<vtkDataSetAttributes*>(mesh->GetCellData()) : mesh->GetPointData())->SetScalars(colors);
  vtkNew<vtkFloatArray> uv;
  uv->SetName("uv");
  uv->SetNumberOfComponents(2);
  uv->SetNumberOfTuples(7);
  for (vtkIdType i = 0; i < 14; ++i)
  {
    uv->SetValue(i, static_cast<float>(i) / 13.0f);
  }
  mesh->GetPointData()->SetTCoords(uv);
  return mesh;
}

std::string PLYErrors(const std::string& text, vtkPolyData* result = nullptr)
{
  const std::string path = subdtest::ReaderTempPath("case.ply");
  subdtest::WriteFileBytes(path, text);
  vtkNew<vtkSubDPLYReader> reader;
  const std::string errors = subdtest::ReadErrorsOf(reader.Get(), path);
  if (result)
  {
    result->DeepCopy(reader->GetOutput());
  }
  return errors;
}

const std::string Cube = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                         "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                         "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
}

// (file type: 0 ASCII, 1 binary little endian, 2 binary big endian; cell colours; alpha)
class PLYWrittenByVTK : public ::testing::TestWithParam<std::tuple<int, bool, bool>>
{
};

TEST_P(PLYWrittenByVTK, ReadsWhatVTKReads)
{
  const auto [fileType, cellColors, alpha] = GetParam();
  auto mesh = ColoredMesh(cellColors, alpha ? 4 : 3);
  const std::string name = "written" + std::to_string(fileType) + (cellColors ? "-cells" : "-points") +
    (alpha ? "-rgba" : "-rgb") + ".ply";
  const std::string path = subdtest::ReaderTempPath(name);
  vtkNew<vtkPLYWriter> writer;
  writer->SetInputData(mesh);
  writer->SetFileName(path.c_str());
  writer->SetArrayName("paint");
  writer->SetEnableAlpha(alpha);
  if (fileType > 0)
  {
    writer->SetFileTypeToBinary();
    writer->SetDataByteOrder(fileType == 2 ? VTK_BIG_ENDIAN : VTK_LITTLE_ENDIAN);
  }
  ASSERT_EQ(writer->Write(), 1);

  vtkNew<vtkPLYReader> vtkReader;
  vtkReader->SetFileName(path.c_str());
  vtkReader->Update();
  vtkPolyData* expected = vtkReader->GetOutput();
  ASSERT_EQ(expected->GetNumberOfPoints(), 7);

  if (cellColors && alpha)
  {
    // vtkPLYReader adds cell RGBA without making it the active scalars (it does for RGB).
    expected->GetCellData()->SetActiveScalars("RGBA");
  }
  vtkNew<vtkSubDPLYReader> reader;
  EXPECT_EQ(subdtest::ReadErrorsOf(reader.Get(), path), "");
  subdtest::ExpectSamePolyData(expected, reader->GetOutput(), name);
}

INSTANTIATE_TEST_SUITE_P(AllLayouts, PLYWrittenByVTK,
  ::testing::Combine(::testing::Values(0, 1, 2), ::testing::Bool(), ::testing::Bool()));

TEST(PLYReader, KeepsThePropertiesVTKDropsAndSkipsOtherElements)
{
  vtkNew<vtkPolyData> mesh;
  const std::string text = "ply\nformat ascii 1.0\ncomment made by hand\nelement vertex 3\n"
                           "property double x\nproperty double y\nproperty double z\nproperty float quality\n"
                           "property list uchar int ignored_list\nproperty short flags\n"
                           "element edge 1\nproperty int vertex1\nproperty int vertex2\n"
                           "element face 1\nproperty list uint8 uint32 vertex_index\nproperty int material\n"
                           "end_header\n"
                           "0.1 0.2 0.30000000000000004 0.5 2 7 8 -3\n1 0 0 1.5 0 4\n0 1 0 2.5 1 9 5\n"
                           "0 1\n3 0 1 2 42\n";
  ASSERT_EQ(PLYErrors(text, mesh), "");
  ASSERT_EQ(mesh->GetNumberOfPoints(), 3);
  EXPECT_EQ(mesh->GetPoints()->GetDataType(), VTK_DOUBLE);
  double p[3];
  mesh->GetPoint(0, p);
  EXPECT_EQ(p[2], 0.30000000000000004);
  vtkDataArray* quality = mesh->GetPointData()->GetArray("quality");
  vtkDataArray* flags = mesh->GetPointData()->GetArray("flags");
  ASSERT_TRUE(quality && flags);
  EXPECT_EQ(quality->GetDataType(), VTK_FLOAT);
  EXPECT_EQ(flags->GetDataType(), VTK_SHORT);
  EXPECT_EQ(quality->GetComponent(2, 0), 2.5);
  EXPECT_EQ(flags->GetComponent(0, 0), -3);
  EXPECT_EQ(flags->GetComponent(2, 0), 5);
  ASSERT_EQ(mesh->GetNumberOfPolys(), 1);
  vtkDataArray* material = mesh->GetCellData()->GetArray("material");
  ASSERT_NE(material, nullptr);
  EXPECT_EQ(material->GetComponent(0, 0), 42);
}

TEST(PLYReader, BinaryRealColoursAreScaledToBytes)
{
  std::string text = "ply\nformat binary_big_endian 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                     "property float z\nproperty float red\nproperty float green\nproperty float blue\nend_header\n";
  const float values[6] = { 1, 2, 3, 1.0f, 0.5f, 0.0f };
  for (float v : values)
  {
    std::uint32_t bits;
    std::memcpy(&bits, &v, 4);
    for (int shift = 24; shift >= 0; shift -= 8)
    {
      text += static_cast<char>((bits >> shift) & 0xff);
    }
  }
  vtkNew<vtkPolyData> mesh;
  ASSERT_EQ(PLYErrors(text, mesh), "");
  double p[3];
  mesh->GetPoint(0, p);
  EXPECT_EQ(p[2], 3.0);
  vtkDataArray* rgb = mesh->GetPointData()->GetScalars();
  ASSERT_NE(rgb, nullptr);
  EXPECT_STREQ(rgb->GetName(), "RGB");
  EXPECT_EQ(rgb->GetComponent(0, 0), 255);
  EXPECT_EQ(rgb->GetComponent(0, 1), 128);
  EXPECT_EQ(rgb->GetComponent(0, 2), 0);
}

TEST(PLYReader, BrokenFilesNameTheirProblem)
{
  struct Case
  {
    std::string text, expected;
  };
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
                             "property float z\n";
  const Case cases[] = {
    { "", "first line must be 'ply'" },
    { "ply\nformat text 1.0\nend_header\n", "unknown format 'text'" },
    { header, "ends inside its header" },
    { "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nend_header\n", "x, y and z" },
    { "ply\nformat ascii 1.0\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n", "no vertex" },
    { "ply\nformat ascii 1.0\nproperty float x\n", "before any element" },
    { header + "property quaternion q\nend_header\n", "PLY types" },
    { header + "property list float int idx\nend_header\n", "PLY types" },
    { "ply\nformat ascii 1.0\nelement vertex many\n", "element name count" },
    { "ply\nformat ascii 1.0\nelement vertex -2\n", "element name count" },
    { header + "gibberish\n", "unknown header line 'gibberish'" },
    { "ply\nformat ascii 1.0\nelement vertex 2000000000\nproperty float x\nproperty float y\nproperty float z\n"
      "end_header\n0 0 0\n",
      "more than the rest of the file" },
    { header + "end_header\n0 0 0\n1    1\n", "vertex 1 of 2: property 'z'" },
    { header + "end_header\n0 0 0\n1 1 one\n", "line 9" },
    { header + "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 1 1\n3 0 1\n",
      "list 'vertex_indices' announces 3 values; value 2" },
    { header + "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 1 1\n3 0 1 2\n",
      "face 0 uses vertex 2" },
    { header + "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 1 1\n3 0 1.5 0\n",
      "value 1 is missing or not a number" },
    { header + "element face 1\nproperty list char int vertex_indices\nend_header\n0 0 0\n1 1 1\n-1 0\n",
      "length of list" },
    { header + "element face 1\nproperty list uchar int corners\nend_header\n0 0 0\n1 1 1\n2 0 1\n",
      "one list property vertex_indices (or vertex_index); it has 0" },
    { header + "element face 1\nproperty list uchar int vertex_indices\nproperty list uchar int vertex_index\n"
               "end_header\n0 0 0\n1 1 1\n2 0 1 2 0 1\n",
      "it has 2" },
    { "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n" + std::string(23, '\0'),
      "near byte" },
  };
  for (const Case& c : cases)
  {
    const std::string errors = PLYErrors(c.text);
    EXPECT_NE(errors.find(c.expected), std::string::npos)
      << "file:\n" << c.text << "\nexpected '" << c.expected << "' in: " << errors;
  }
}
