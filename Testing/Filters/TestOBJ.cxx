// OBJ reader/writer with OpenSubdiv's sharp-feature tags: the tags become SubD's arrays,
// survive a round trip, and broken files give errors naming the line. Texture seams through OBJ
// and glTF files.
#include "vtkSubDOBJReader.h"
#include "vtkSubDOBJWriter.h"
#include "vtkSubDCatmullClarkFilter.h"
#include "vtkOBJReader.h"
#include "vtkSubDGLTFReader.h"
#include "vtkSubDGLTFWriter.h"
#include "vtkTriangleFilter.h"

#include "SubDFilterTestSupport.h"
#include "SubDTempFiles.h"
#include "SubDTexturedCube.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"

#include <gtest/gtest.h>

#include <array>
#include <fstream>
#include <set>
#include <string>

namespace
{
std::string TempPath(const std::string& name)
{
  return subdtest::ProcessTempPath("subd_obj_", name);
}

// The file read by `Reader`, its messages in `messages`.
template <typename Reader>
vtkSmartPointer<vtkPolyData> Read(const std::string& path, subdtest::Messages& messages)
{
  vtkNew<Reader> reader;
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
  vtkSmartPointer<vtkPolyData> mesh = Read<vtkSubDOBJReader>(path, messages);
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
  vtkSmartPointer<vtkPolyData> mesh = Read<vtkSubDOBJReader>(path, messages);
  vtkNew<vtkSubDOBJWriter> writer;
  writer->SetInputData(mesh);
  writer->SetFileName(again.c_str());
  ASSERT_EQ(writer->Write(), 1);
  vtkSmartPointer<vtkPolyData> back = Read<vtkSubDOBJReader>(again, messages);
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
    { "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/2\n", "face 0 uses texture coordinate 1" },
    { "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2 3/1\n", "line 5: a face mixes corners with and without texture" },
    { "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt nan 0\nf 1/1 2/1 3/1\n", "line 4: a texture coordinate needs 2 finite" },
    { "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/-2 2/1 3/1\n", "line 5: '1/-2' has no valid texture coordinate" },
  };
  int k = 0;
  for (const auto& c : cases)
  {
    const std::string path = TempPath("broken" + std::to_string(k++) + ".obj");
    std::ofstream(path) << c.first;
    subdtest::Messages messages;
    vtkSmartPointer<vtkPolyData> mesh = Read<vtkSubDOBJReader>(path, messages);
    EXPECT_NE(messages.Errors.find(c.second), std::string::npos) << c.second << " in: " << messages.Errors;
    EXPECT_EQ(mesh->GetNumberOfPoints(), 0);
  }
}

// A cube whose six faces are texture islands of their own (24 `vt`): read, its points split
// at the seams carry "TCoords"; subdivided, the surface is the untextured cube's and the
// output is split at the same seams; written and read back, the file keeps 8 positions'
// worth of surface and every corner's texture coordinate.
TEST(OBJ, TextureSeamsSurviveSubdivisionAndRoundTrip)
{
  std::string text;
  const char* positions[8] = { "0 0 0", "1 0 0", "1 1 0", "0 1 0", "0 0 1", "1 0 1", "1 1 1", "0 1 1" };
  for (const char* p : positions)
    text += std::string("v ") + p + "\n";
  const int faces[6][4] = { { 1, 4, 3, 2 }, { 5, 6, 7, 8 }, { 1, 2, 6, 5 }, { 2, 3, 7, 6 }, { 3, 4, 8, 7 }, { 4, 1, 5, 8 } };
  for (int f = 0; f < 6; ++f)
    for (int k = 0; k < 4; ++k)
      text += "vt " + std::to_string(2 * f + (k == 1 || k == 2 ? 1 : 0)) + " " + std::to_string(k >= 2 ? 1 : 0) + "\n";
  for (int f = 0; f < 6; ++f)
  {
    text += "f";
    for (int k = 0; k < 4; ++k)
      text += " " + std::to_string(faces[f][k]) + "/" + std::to_string(4 * f + k + 1) + "/1";
    text += "\n";
  }
  const std::string path = TempPath("islands.obj"), out = TempPath("islands-cc.obj");
  std::ofstream(path) << text;
  subdtest::Messages messages;
  vtkSmartPointer<vtkPolyData> mesh = Read<vtkSubDOBJReader>(path, messages);
  EXPECT_EQ(messages.Errors, "");
  ASSERT_EQ(mesh->GetNumberOfPoints(), 24); // a point per (vertex, texture coordinate)
  ASSERT_NE(mesh->GetPointData()->GetTCoords(), nullptr);

  vtkNew<vtkSubDCatmullClarkFilter> filter;
  filter->SetInputData(mesh);
  filter->SetNumberOfSubdivisions(2);
  filter->Update();
  vtkPolyData* refined = filter->GetOutput();
  ASSERT_EQ(refined->GetNumberOfPolys(), 96);
  vtkDataArray* tcoords = refined->GetPointData()->GetTCoords();
  ASSERT_NE(tcoords, nullptr);
  // Each island keeps its own coordinates: 6 islands of 5 x 5 points.
  EXPECT_EQ(refined->GetNumberOfPoints(), 6 * 25);
  vtkNew<vtkSubDCatmullClarkFilter> plain; // the same cube without its `vt`
  const std::string plainPath = TempPath("plain.obj");
  std::ofstream(plainPath) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                              "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
  plain->SetInputData(Read<vtkSubDOBJReader>(plainPath, messages));
  plain->SetNumberOfSubdivisions(2);
  plain->Update();
  std::set<std::array<double, 3>> a, b;
  for (vtkIdType p = 0; p < refined->GetNumberOfPoints(); ++p)
    a.insert({ refined->GetPoint(p)[0], refined->GetPoint(p)[1], refined->GetPoint(p)[2] });
  for (vtkIdType p = 0; p < plain->GetOutput()->GetNumberOfPoints(); ++p)
    b.insert({ plain->GetOutput()->GetPoint(p)[0], plain->GetOutput()->GetPoint(p)[1], plain->GetOutput()->GetPoint(p)[2] });
  EXPECT_EQ(a, b); // the surface is the cube's, no crease along the seams

  vtkNew<vtkSubDOBJWriter> writer;
  writer->SetInputData(refined);
  writer->SetFileName(out.c_str());
  ASSERT_EQ(writer->Write(), 1);
  vtkSmartPointer<vtkPolyData> back = Read<vtkSubDOBJReader>(out, messages);
  // (Points of two islands with the same position and coordinates read back as one.)
  ASSERT_EQ(back->GetNumberOfPolys(), refined->GetNumberOfPolys());
  vtkDataArray* backCoords = back->GetPointData()->GetTCoords();
  ASSERT_NE(backCoords, nullptr);
  for (vtkIdType c = 0; c < refined->GetNumberOfPolys(); ++c)
  {
    vtkIdType n1, n2;
    const vtkIdType *p1, *p2;
    refined->GetPolys()->GetCellAtId(c, n1, p1);
    back->GetPolys()->GetCellAtId(c, n2, p2);
    ASSERT_EQ(n1, n2);
    for (vtkIdType k = 0; k < n1; ++k)
    {
      for (int d = 0; d < 3; ++d)
        EXPECT_EQ(refined->GetPoint(p1[k])[d], back->GetPoint(p2[k])[d]) << "face " << c;
      for (int d = 0; d < 2; ++d)
        EXPECT_EQ(static_cast<float>(tcoords->GetComponent(p1[k], d)), static_cast<float>(backCoords->GetComponent(p2[k], d)))
          << "face " << c << " corner " << k;
    }
  }
}

using Corners = std::set<std::array<double, 5>>;

// The points of a mesh with their texture coordinates, as a set.
Corners PointsWithTCoords(vtkPolyData* mesh)
{
  vtkDataArray* tcoords = mesh->GetPointData()->GetTCoords();
  Corners set;
  for (vtkIdType p = 0; tcoords && p < mesh->GetNumberOfPoints(); ++p)
  {
    const double* x = mesh->GetPoint(p);
    set.insert({ x[0], x[1], x[2], tcoords->GetComponent(p, 0), tcoords->GetComponent(p, 1) });
  }
  return set;
}

// Catmull-Clark, two levels: the output's polygon count and its points with coordinates.
Corners RefinedCorners(vtkPolyData* input, vtkIdType expectedPolys)
{
  vtkNew<vtkSubDCatmullClarkFilter> filter;
  filter->SetInputData(input);
  filter->SetNumberOfSubdivisions(2);
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPolys(), expectedPolys);
  return PointsWithTCoords(filter->GetOutput());
}

// Every element of `a` has one in `b` within `tolerance`, and the sets are as large.
void ExpectSameCorners(const Corners& a, const Corners& b, double tolerance)
{
  EXPECT_FALSE(a.empty());
  EXPECT_EQ(a.size(), b.size());
  for (const auto& ours : a)
  {
    const bool found = std::any_of(b.begin(), b.end(), [&](const std::array<double, 5>& theirs) {
      for (int d = 0; d < 5; ++d)
        if (std::abs(ours[d] - theirs[d]) > tolerance)
          return false;
      return true;
    });
    EXPECT_TRUE(found) << ::testing::PrintToString(ours) << " has no counterpart";
  }
}

// VTK's own OBJ reader splits every corner of a textured file into a point of its own: welded,
// the filters give the same surface and texture coordinates as from SubD's reader, which
// splits only at seams.
TEST(OBJ, VTKsSplitReadingWeldsToTheSameResult)
{
  const std::string path = TempPath("cross.obj");
  std::ofstream(path) << subdtest::CrossUnwrappedCubeOBJ();
  subdtest::Messages messages;
  vtkSmartPointer<vtkPolyData> ours = Read<vtkSubDOBJReader>(path, messages);
  vtkNew<vtkOBJReader> vtkReader;
  vtkReader->SetFileName(path.c_str());
  vtkReader->Update();
  vtkPolyData* split = vtkReader->GetOutput();
  ASSERT_GT(split->GetNumberOfPoints(), ours->GetNumberOfPoints());
  ASSERT_NE(split->GetPointData()->GetTCoords(), nullptr);
  // (vtkOBJReader's points are floats: the two agree to float precision.)
  ExpectSameCorners(RefinedCorners(ours, 96), RefinedCorners(split, 96), 1e-6);
}

void WriteGLTF(vtkPolyData* mesh, const std::string& path)
{
  vtkNew<vtkSubDGLTFWriter> writer;
  writer->SetInputData(mesh);
  writer->SetFileName(path.c_str());
  ASSERT_EQ(writer->Write(), 1);
}

// glTF keeps a vertex per (position, attributes) and triangles only. The cross-unwrapped cube,
// triangulated and written as glTF, reads back split at its seams; welded and refined it gives
// the seamed OBJ's surface and texture coordinates (to float precision, glTF's). A refined mesh
// written and read back keeps every point with its coordinates.
TEST(GLTF, SplitTrianglesWeldToTheSeamedResultAndRoundTrip)
{
  const std::string path = TempPath("cross-tris.obj"), gltf = TempPath("cross.gltf"), refinedPath = TempPath("cc.gltf");
  std::ofstream(path) << subdtest::CrossUnwrappedCubeOBJ();
  subdtest::Messages messages;
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(Read<vtkSubDOBJReader>(path, messages));
  triangles->Update();
  vtkPolyData* cage = triangles->GetOutput();
  WriteGLTF(cage, gltf);
  vtkSmartPointer<vtkPolyData> split = Read<vtkSubDGLTFReader>(gltf, messages);
  EXPECT_EQ(messages.Errors, "");
  ASSERT_EQ(split->GetNumberOfPolys(), 12);
  ASSERT_NE(split->GetPointData()->GetTCoords(), nullptr);
  EXPECT_EQ(split->GetPointData()->GetTCoords()->GetName(), std::string("TCoords"));
  ExpectSameCorners(RefinedCorners(cage, 144), RefinedCorners(split, 144), 1e-6);

  vtkNew<vtkSubDCatmullClarkFilter> filter;
  filter->SetInputData(cage);
  filter->SetNumberOfSubdivisions(2);
  filter->Update();
  WriteGLTF(filter->GetOutput(), refinedPath);
  vtkSmartPointer<vtkPolyData> back = Read<vtkSubDGLTFReader>(refinedPath, messages);
  EXPECT_EQ(messages.Errors, "");
  EXPECT_EQ(back->GetNumberOfPolys(), 2 * filter->GetOutput()->GetNumberOfPolys()); // quads as two triangles
  ExpectSameCorners(PointsWithTCoords(filter->GetOutput()), PointsWithTCoords(back), 1e-6);
}

// A scene's node transforms place its meshes: a unit square scaled by 2 in a child node,
// moved by 10 along x in its parent, reads back as the square [10, 12] x [0, 2].
TEST(GLTF, NodeTransformsAreApplied)
{
  const std::string path = TempPath("nodes.gltf");
  // Four points (float x, y, z) and two triangles (uint32), base64.
  std::ofstream(path) << R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
                         R"("nodes":[{"children":[1],"translation":[10,0,0]},{"mesh":0,"scale":[2,2,2]}],)"
                         R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],)"
                         R"("buffers":[{"byteLength":72,"uri":"data:application/octet-stream;base64,)"
                         R"(AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAACAPwAAgD8AAAAAAAAAAAAAgD8AAAAAAAAAAAEAAAACAAAAAAAAAAIAAAADAAAA"}],)"
                         R"("bufferViews":[{"buffer":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":24}],)"
                         R"("accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3",)"
                         R"("min":[0,0,0],"max":[1,1,0]},{"bufferView":1,"componentType":5125,"count":6,"type":"SCALAR"}]})";
  subdtest::Messages messages;
  vtkSmartPointer<vtkPolyData> mesh = Read<vtkSubDGLTFReader>(path, messages);
  EXPECT_EQ(messages.Errors, "");
  ASSERT_EQ(mesh->GetNumberOfPoints(), 4);
  double bounds[6];
  mesh->GetBounds(bounds);
  const double expected[6] = { 10, 12, 0, 2, 0, 0 };
  for (int k = 0; k < 6; ++k)
    EXPECT_DOUBLE_EQ(bounds[k], expected[k]) << "bound " << k;
}

// A broken file gives an error naming the fault and an empty output (VTK 9.1's own reader
// crashes on it).
TEST(GLTF, BrokenReferencesAreErrorsNotCrashes)
{
  const std::string path = TempPath("broken.gltf");
  std::ofstream(path) << R"({"asset":{"version":"2.0"},"meshes":[{"primitives":[{"attributes":{"POSITION":5}}]}]})";
  subdtest::Messages messages;
  vtkSmartPointer<vtkPolyData> mesh = Read<vtkSubDGLTFReader>(path, messages);
  EXPECT_NE(messages.Errors.find("refers to accessors[5]"), std::string::npos) << messages.Errors;
  EXPECT_EQ(mesh->GetNumberOfPoints(), 0);
}
}
