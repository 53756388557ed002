// OBJ reader/writer with OpenSubdiv's sharp-feature tags: the tags become SubD's arrays,
// survive a round trip, and broken files give errors naming the line.
#include "vtkSubDOBJReader.h"
#include "vtkSubDOBJWriter.h"

#include "SubDFilterTestSupport.h"
#include "SubDTempFiles.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace
{
std::string TempPath(const std::string& name)
{
  return subdtest::ProcessTempPath("subd_obj_", name);
}

vtkSmartPointer<vtkPolyData> ReadOBJ(const std::string& path, subdtest::Messages& messages)
{
  vtkNew<vtkSubDOBJReader> reader;
  messages.Watch(reader);
  reader->SetFileName(path.c_str());
  reader->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(reader->GetOutput());
  return out;
}

// A cube in OpenSubdiv's test-shape style: 1-based faces with texture indices, a crease
// chain with one sharpness, a chain with per-edge sharpness, corners and a hole.
const char* TaggedCube = R"(# cube
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
vt 0 0
f 1/1 4/1 3/1 2/1
f 5 6 7 8
f 1//1 2//1 6//1 5//1
f 2 3 7 6
f 3 4 8 7
f -8 -4 -1 -5
t crease 3/1/0 4 5 6 2.5
t crease 3/2/0 0 1 2 1.0 0.25
t corner 2/1/0 3 7 4.0
t hole 1/0/0 1
t interpolateboundary 1/0/0 1
)";

TEST(OBJ, TagsBecomeSubDArrays)
{
  const std::string path = TempPath("tagged.obj");
  std::ofstream(path) << TaggedCube;
  subdtest::Messages messages;
  vtkSmartPointer<vtkPolyData> mesh = ReadOBJ(path, messages);
  EXPECT_EQ(messages.NumErrors, 0) << messages.Errors;
  EXPECT_NE(messages.Warnings.find("interpolateboundary"), std::string::npos);
  ASSERT_EQ(mesh->GetNumberOfPoints(), 8);
  ASSERT_EQ(mesh->GetNumberOfPolys(), 6);
  ASSERT_EQ(mesh->GetNumberOfLines(), 3); // one chain, two single edges
  vtkDataArray* sharpness = mesh->GetCellData()->GetArray("Sharpness");
  ASSERT_NE(sharpness, nullptr);
  EXPECT_FLOAT_EQ(sharpness->GetComponent(0, 0), 2.5f);
  EXPECT_FLOAT_EQ(sharpness->GetComponent(1, 0), 1.0f);
  EXPECT_FLOAT_EQ(sharpness->GetComponent(2, 0), 0.25f);
  vtkDataArray* hole = mesh->GetCellData()->GetArray("Hole");
  ASSERT_NE(hole, nullptr);
  for (vtkIdType f = 0; f < 6; ++f)
    EXPECT_EQ(hole->GetComponent(3 + f, 0), f == 1 ? 1.0 : 0.0) << "face " << f;
  vtkDataArray* corners = mesh->GetPointData()->GetArray("CornerSharpness");
  ASSERT_NE(corners, nullptr);
  EXPECT_EQ(corners->GetComponent(3, 0), 4.0);
  EXPECT_EQ(corners->GetComponent(7, 0), 4.0);
  EXPECT_EQ(corners->GetComponent(0, 0), 0.0);
  // The last face used negative (relative) indices: -8 is vertex 0.
  vtkIdType n;
  const vtkIdType* pts;
  mesh->GetCellPoints(3 + 5, n, pts);
  ASSERT_EQ(n, 4);
  EXPECT_EQ(pts[0], 0);
  EXPECT_EQ(pts[1], 4);
  EXPECT_EQ(pts[2], 7);
  EXPECT_EQ(pts[3], 3);
}

TEST(OBJ, RoundTripKeepsPointsFacesAndTags)
{
  const std::string path = TempPath("tagged.obj"), again = TempPath("again.obj");
  std::ofstream(path) << TaggedCube;
  subdtest::Messages messages;
  vtkSmartPointer<vtkPolyData> mesh = ReadOBJ(path, messages);
  vtkNew<vtkSubDOBJWriter> writer;
  writer->SetInputData(mesh);
  writer->SetFileName(again.c_str());
  ASSERT_EQ(writer->Write(), 1);
  vtkSmartPointer<vtkPolyData> back = ReadOBJ(again, messages);
  ASSERT_EQ(back->GetNumberOfPoints(), mesh->GetNumberOfPoints());
  ASSERT_EQ(back->GetNumberOfCells(), mesh->GetNumberOfCells());
  EXPECT_EQ(subdtest::Coordinates(back), subdtest::Coordinates(mesh));
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    vtkIdType n1, n2;
    const vtkIdType *p1, *p2;
    mesh->GetCellPoints(c, n1, p1);
    back->GetCellPoints(c, n2, p2);
    ASSERT_EQ(n1, n2);
    EXPECT_TRUE(std::equal(p1, p1 + n1, p2)) << "cell " << c;
  }
  for (const char* name : { "Sharpness", "Hole" })
    for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
      EXPECT_EQ(mesh->GetCellData()->GetArray(name)->GetComponent(c, 0),
        back->GetCellData()->GetArray(name)->GetComponent(c, 0)) << name << " " << c;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    EXPECT_EQ(mesh->GetPointData()->GetArray("CornerSharpness")->GetComponent(i, 0),
      back->GetPointData()->GetArray("CornerSharpness")->GetComponent(i, 0));
}

TEST(OBJ, BrokenFilesNameTheProblem)
{
  const std::pair<const char*, const char*> cases[] = {
    { "v 0 0 0\nv 1 0\n", "line 2: a vertex needs 3" },
    { "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n", "line 4: 'x' is not a vertex index" },
    { "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", "face 0 uses vertex 8" },
    { "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nt crease 3/1/0 0 1\n", "line 5: tag 'crease' needs 3 integer" },
    { "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nt crease 2/3/0 0 1 1 1 1\n", "crease tag needs" },
    { "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nt hole 1/0/0 4\n", "hole tag names face 4" },
    { "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nt corner 1/1/0 7 2\n", "corner tag names vertex 7" },
    { "garbage\n", "no vertices" },
  };
  int k = 0;
  for (const auto& c : cases)
  {
    const std::string path = TempPath("broken" + std::to_string(k++) + ".obj");
    std::ofstream(path) << c.first;
    subdtest::Messages messages;
    vtkSmartPointer<vtkPolyData> mesh = ReadOBJ(path, messages);
    EXPECT_NE(messages.Errors.find(c.second), std::string::npos) << c.second << " in: " << messages.Errors;
    EXPECT_EQ(mesh->GetNumberOfPoints(), 0);
  }
}
}
