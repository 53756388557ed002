// OFF reader/writer: exact round trip, colours, and clear errors for broken files; the mesh
// writers (OFF, OBJ, PLY) the same bytes on any number of threads.
#include "vtkSubDOBJReader.h"
#include "vtkSubDOBJWriter.h"
#include "vtkSubDOFFReader.h"
#include "vtkSubDOFFWriter.h"
#include "vtkSubDPLYReader.h"
#include "vtkSubDPLYWriter.h"

#include "SubDFilterTestSupport.h"
#include "SubDTempFiles.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace
{
std::string TempPath(const std::string& name)
{
  return subdtest::ProcessTempPath("subd_off_", name);
}

void WriteText(const std::string& path, const std::string& text)
{
  std::ofstream(path) << text;
}

// Appends the error messages of `object` to `errors`.
void CollectErrors(vtkObject* object, std::string& errors)
{
  vtkNew<vtkCallbackCommand> cb;
  cb->SetClientData(&errors);
  cb->SetCallback([](vtkObject*, unsigned long, void* client, void* data) {
    *static_cast<std::string*>(client) += static_cast<const char*>(data);
  });
  object->AddObserver(vtkCommand::ErrorEvent, cb);
}

std::string ReadText(const std::string& path)
{
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

// The bytes `writer` writes for `mesh` with `threads` vtkSMPTools threads.
template <typename Writer>
std::string WrittenBytes(vtkPolyData* mesh, int threads, const std::string& path)
{
  vtkSMPTools::Initialize(threads);
  vtkNew<Writer> writer;
  writer->SetInputData(mesh);
  writer->SetFileName(path.c_str());
  EXPECT_EQ(writer->Write(), 1);
  return ReadText(path);
}

// Reads `path` back with `Reader` and checks it is `mesh`'s points and faces, bit for bit;
// returns what it read.
template <typename Reader>
vtkSmartPointer<vtkPolyData> ExpectReadBack(const std::string& path, vtkPolyData* mesh)
{
  vtkNew<Reader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkSmartPointer<vtkPolyData> back = reader->GetOutput();
  EXPECT_EQ(subdtest::Coordinates(back), subdtest::Coordinates(mesh));
  EXPECT_EQ(subdtest::Faces(back), subdtest::Faces(mesh));
  return back;
}

// Reads `text` as an OFF file; returns the collected error text ("" if none).
std::string ReadErrors(const std::string& text, vtkPolyData* result = nullptr)
{
  const std::string path = TempPath("case.off");
  WriteText(path, text);
  vtkNew<vtkSubDOFFReader> reader;
  std::string errors;
  CollectErrors(reader, errors);
  reader->SetFileName(path.c_str());
  reader->Update();
  std::remove(path.c_str());
  if (result)
    result->DeepCopy(reader->GetOutput());
  if (!errors.empty())
  {
    EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
    EXPECT_NE(reader->GetErrorCode(), 0ul);
  }
  return errors;
}
}

TEST(OFF, RoundTripIsExact)
{
  vtkNew<vtkPolyData> mesh;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->InsertNextPoint(0.1, 1.0 / 3.0, -2.5e-7);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(1, 1, 0);
  points->InsertNextPoint(0, 1, 3.141592653589793);
  points->InsertNextPoint(0.5, 2, 0);
  vtkNew<vtkCellArray> polys;
  const vtkIdType quad[4] = { 0, 1, 2, 3 }, tri[3] = { 3, 2, 4 };
  polys->InsertNextCell(4, quad);
  polys->InsertNextCell(3, tri);
  mesh->SetPoints(points);
  mesh->SetPolys(polys);

  const std::string path = TempPath("roundtrip.off");
  vtkNew<vtkSubDOFFWriter> writer;
  writer->SetInputData(mesh);
  writer->SetFileName(path.c_str());
  ASSERT_EQ(writer->Write(), 1);

  vtkNew<vtkSubDOFFReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* back = reader->GetOutput();
  ASSERT_EQ(back->GetNumberOfPoints(), 5);
  ASSERT_EQ(back->GetNumberOfPolys(), 2);
  EXPECT_EQ(subdtest::Coordinates(back), subdtest::Coordinates(mesh)); // bit for bit
  vtkIdType n;
  const vtkIdType* pts;
  back->GetPolys()->GetCellAtId(1, n, pts);
  ASSERT_EQ(n, 3);
  EXPECT_EQ(pts[0], 3);
  EXPECT_EQ(pts[2], 4);
  std::remove(path.c_str());
}

TEST(OFF, CommentsCountsOnHeaderLineAndColours)
{
  vtkNew<vtkPolyData> mesh;
  EXPECT_EQ(ReadErrors("COFF 3 1 0 # counts on the header line\n"
                       "0 0 0 255 0 0 255\n# a comment line\n"
                       "1 0 0 0 255 0 255\n0 1 0 0 0 255 128\n3 0 1 2\n",
              mesh),
    "");
  EXPECT_EQ(mesh->GetNumberOfPolys(), 1);
  auto* colors = vtkUnsignedCharArray::SafeDownCast(mesh->GetPointData()->GetScalars());
  ASSERT_NE(colors, nullptr);
  EXPECT_EQ(colors->GetValue(4 * 1 + 1), 255);
  EXPECT_EQ(colors->GetValue(4 * 2 + 3), 128);
}

TEST(OFF, HeaderlessFileIsAccepted)
{
  vtkNew<vtkPolyData> mesh;
  EXPECT_EQ(ReadErrors("3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", mesh), "");
  EXPECT_EQ(mesh->GetNumberOfPoints(), 3);
}

TEST(OFF, BrokenFilesGiveClearErrors)
{
  EXPECT_NE(ReadErrors("").find("empty"), std::string::npos);
  EXPECT_NE(ReadErrors("OFF\n").find("ends after its header"), std::string::npos);
  EXPECT_NE(ReadErrors("OFF\nthree two one\n").find("expected the counts"), std::string::npos);
  EXPECT_NE(ReadErrors("OFF\n4 1 0\n0 0 0\n1 0 0\n").find("ends after 2 of 4 vertices"), std::string::npos);
  EXPECT_NE(ReadErrors("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n").find("ends after 0 of 1 faces"), std::string::npos);
  EXPECT_NE(ReadErrors("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n").find("uses vertex 7"), std::string::npos);
  EXPECT_NE(ReadErrors("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n").find("announces 4"), std::string::npos);
  // A face size beyond any integer type is reported as written (fuzzing found the cast).
  EXPECT_NE(ReadErrors("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n  477777777777777777777 0 1 2\n")
              .find("announces 477777777777777777777 vertices but lists 3"),
    std::string::npos);
  EXPECT_NE(ReadErrors("OFF\n3 1 0\n0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n").find("line 4"), std::string::npos);
  EXPECT_NE(ReadErrors("OFF\n-3 1 0\n").find("invalid vertex or face count"), std::string::npos);
  EXPECT_NE(ReadErrors("NOFF\n3 1 0\n").find("not supported"), std::string::npos);
}

TEST(OFF, MissingFileIsAnError)
{
  vtkNew<vtkSubDOFFReader> reader;
  std::string errors;
  CollectErrors(reader, errors);
  reader->SetFileName("/nonexistent/dir/mesh.off");
  reader->Update();
  EXPECT_NE(errors.find("Cannot open"), std::string::npos);
}

// The writers make their lines (records) on threads, chunk by chunk, and write the chunks in
// order: on a mesh of many chunks (and batches of chunks) the file must not depend on the
// number of threads, and must read back exactly. The faces are in 32-bit storage, as the
// filters make them, and of several sizes; PLY also writes a point-data array.
TEST(MeshWriters, SameBytesOnOneAndTwoThreadsAndExactRoundTrip)
{
  const vtkIdType side = 400; // 160000 points: 20 chunks of points, several batches
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (vtkIdType j = 0; j < side; ++j)
  {
    for (vtkIdType i = 0; i < side; ++i)
    {
      points->InsertNextPoint(i / 3.0, std::sqrt(static_cast<double>(j)), std::sin(0.001 * i * j));
    }
  }
  vtkNew<vtkCellArray> polys;
  polys->Use32BitStorage();
  for (vtkIdType j = 0; j + 1 < side; ++j)
  {
    for (vtkIdType i = 0; i + 1 < side; ++i)
    {
      const vtkIdType a = j * side + i, b = a + 1, c = a + side + 1, d = a + side;
      if ((i + j) % 3 == 0)
      {
        const vtkIdType first[3] = { a, b, c }, second[3] = { a, c, d };
        polys->InsertNextCell(3, first);
        polys->InsertNextCell(3, second);
      }
      else
      {
        const vtkIdType quad[4] = { a, b, c, d };
        polys->InsertNextCell(4, quad);
      }
    }
  }
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  vtkNew<vtkDoubleArray> quality;
  quality->SetName("quality");
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    quality->InsertNextValue(std::cos(0.01 * i) / 7.0);
  }
  mesh->GetPointData()->AddArray(quality);

  const int threads = vtkSMPTools::GetEstimatedNumberOfThreads();
  const std::string off = TempPath("threads.off"), obj = TempPath("threads.obj"), ply = TempPath("threads.ply");
  const std::string offOne = WrittenBytes<vtkSubDOFFWriter>(mesh, 1, off);
  const std::string offTwo = WrittenBytes<vtkSubDOFFWriter>(mesh, 2, off);
  const std::string objOne = WrittenBytes<vtkSubDOBJWriter>(mesh, 1, obj);
  const std::string objTwo = WrittenBytes<vtkSubDOBJWriter>(mesh, 2, obj);
  const std::string plyOne = WrittenBytes<vtkSubDPLYWriter>(mesh, 1, ply);
  const std::string plyTwo = WrittenBytes<vtkSubDPLYWriter>(mesh, 2, ply);
  vtkSMPTools::Initialize(threads);
  ASSERT_GT(offOne.size(), 1000000u);
  EXPECT_TRUE(offOne == offTwo);
  EXPECT_TRUE(objOne == objTwo);
  EXPECT_TRUE(plyOne == plyTwo);
  ExpectReadBack<vtkSubDOFFReader>(off, mesh);
  ExpectReadBack<vtkSubDOBJReader>(obj, mesh);
  vtkSmartPointer<vtkPolyData> back = ExpectReadBack<vtkSubDPLYReader>(ply, mesh);
  vtkDataArray* backQuality = back->GetPointData()->GetArray("quality");
  ASSERT_NE(backQuality, nullptr);
  ASSERT_EQ(backQuality->GetNumberOfTuples(), quality->GetNumberOfTuples());
  for (vtkIdType i = 0; i < quality->GetNumberOfTuples(); ++i)
  {
    ASSERT_EQ(backQuality->GetComponent(i, 0), quality->GetValue(i)) << "point " << i;
  }
  std::remove(off.c_str());
  std::remove(obj.c_str());
  std::remove(ply.c_str());
}
