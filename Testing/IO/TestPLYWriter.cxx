// vtkSubDPLYWriter: what it writes, vtkSubDPLYReader reads back bit for bit (double points,
// normals, colours, texture coordinates, one-component arrays in their types, polygons and
// strips' triangles), VTK's own vtkPLYReader reads too, and a face of more than 255 corners
// survives.
#include "vtkSubDPLYWriter.h"

#include "SubDReaderTestSupport.h"

#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkPLYReader.h"
#include "vtkShortArray.h"
#include "vtkSubDPLYReader.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace
{
vtkSmartPointer<vtkPolyData> AttributedMesh()
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int i = 0; i < 8; ++i)
  {
    points->InsertNextPoint(std::cos(i * 0.9) / 3.0, std::sin(i * 0.4) * 1e-7, i * 1e5 + 1.0 / 7.0);
  }
  mesh->SetPoints(points);
  vtkNew<vtkCellArray> polys, strips;
  const vtkIdType tri[3] = { 0, 1, 2 }, quad[4] = { 2, 3, 4, 5 }, penta[5] = { 0, 2, 5, 6, 1 }, strip[5] = { 3, 4, 5, 6, 7 };
  polys->InsertNextCell(3, tri);
  polys->InsertNextCell(4, quad);
  polys->InsertNextCell(5, penta);
  strips->InsertNextCell(5, strip);
  mesh->SetPolys(polys);
  mesh->SetStrips(strips);

  vtkPointData* pd = mesh->GetPointData();
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("RGB");
  colors->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("TCoords");
  tcoords->SetNumberOfComponents(2);
  vtkNew<vtkDoubleArray> quality;
  quality->SetName("quality measure");
  vtkNew<vtkShortArray> flags;
  flags->SetName("flags");
  vtkNew<vtkDoubleArray> pairs; // two components, not texture coordinates: no PLY form
  pairs->SetName("pairs");
  pairs->SetNumberOfComponents(2);
  for (int i = 0; i < 8; ++i)
  {
    normals->InsertNextTuple3(std::sin(i), std::cos(i), 0.5f / (i + 1));
    colors->InsertNextTuple3((i * 53 + 7) % 256, (i * 31) % 256, 255 - i);
    tcoords->InsertNextTuple2(i / 7.0f, 1.0f - i / 9.0f);
    quality->InsertNextValue(std::sqrt(2.0) * i);
    flags->InsertNextValue(static_cast<short>(-300 * i));
    pairs->InsertNextTuple2(i, -i);
  }
  pd->SetNormals(normals);
  pd->SetScalars(colors);
  pd->SetTCoords(tcoords);
  pd->AddArray(quality);
  pd->AddArray(flags);
  pd->AddArray(pairs);
  return mesh;
}

std::vector<std::vector<vtkIdType>> Faces(vtkPolyData* mesh)
{
  std::vector<std::vector<vtkIdType>> faces;
  vtkIdType n;
  const vtkIdType* pts;
  for (mesh->GetPolys()->InitTraversal(); mesh->GetPolys()->GetNextCell(n, pts);)
  {
    faces.emplace_back(pts, pts + n);
  }
  return faces;
}

// Writes `mesh` with vtkSubDPLYWriter; returns the warnings (empty when none).
std::string Write(vtkPolyData* mesh, const std::string& path)
{
  vtkNew<vtkSubDPLYWriter> writer;
  writer->SetInputData(mesh);
  writer->SetFileName(path.c_str());
  std::string warnings;
  vtkNew<vtkCallbackCommand> collect;
  collect->SetClientData(&warnings);
  collect->SetCallback([](vtkObject*, unsigned long, void* client, void* data) {
    *static_cast<std::string*>(client) += static_cast<const char*>(data);
  });
  writer->AddObserver(vtkCommand::WarningEvent, collect);
  EXPECT_EQ(writer->Write(), 1);
  EXPECT_EQ(writer->GetErrorCode(), 0ul);
  return warnings;
}
}

TEST(PLYWriter, RoundTripThroughSubDReaderIsExact)
{
  auto mesh = AttributedMesh();
  const std::string path = subdtest::ReaderTempPath("written-by-subd.ply");
  const std::string warnings = Write(mesh, path);
  EXPECT_NE(warnings.find("'pairs'"), std::string::npos) << warnings;

  vtkNew<vtkSubDPLYReader> reader;
  ASSERT_EQ(subdtest::ReadErrorsOf(reader.Get(), path), "");
  vtkPolyData* back = reader->GetOutput();
  ASSERT_EQ(back->GetNumberOfPoints(), 8);
  EXPECT_EQ(back->GetPoints()->GetDataType(), VTK_DOUBLE);
  subdtest::ExpectSameArray(mesh->GetPoints()->GetData(), back->GetPoints()->GetData(), "points");
  vtkPointData* pd = back->GetPointData();
  subdtest::ExpectSameArray(mesh->GetPointData()->GetNormals(), pd->GetArray("Normals"), "normals");
  subdtest::ExpectSameArray(mesh->GetPointData()->GetScalars(), pd->GetArray("RGB"), "colours");
  subdtest::ExpectSameArray(mesh->GetPointData()->GetTCoords(), pd->GetArray("TCoords"), "texture coordinates");
  vtkDataArray* quality = pd->GetArray("quality_measure");
  ASSERT_NE(quality, nullptr);
  EXPECT_EQ(quality->GetDataType(), VTK_DOUBLE);
  vtkDataArray* flags = pd->GetArray("flags");
  ASSERT_NE(flags, nullptr);
  EXPECT_EQ(flags->GetDataType(), VTK_SHORT);
  for (vtkIdType i = 0; i < 8; ++i)
  {
    EXPECT_EQ(quality->GetComponent(i, 0), mesh->GetPointData()->GetArray("quality measure")->GetComponent(i, 0));
    EXPECT_EQ(flags->GetComponent(i, 0), -300.0 * i);
  }
  EXPECT_EQ(pd->GetArray("pairs"), nullptr);

  // The polygons, then the strip's three triangles (every other one turned, as VTK does).
  const std::vector<std::vector<vtkIdType>> expected = { { 0, 1, 2 }, { 2, 3, 4, 5 }, { 0, 2, 5, 6, 1 },
    { 3, 4, 5 }, { 5, 4, 6 }, { 5, 6, 7 } };
  EXPECT_EQ(Faces(back), expected);
}

TEST(PLYWriter, VTKsReaderReadsIt)
{
  auto mesh = AttributedMesh();
  const std::string path = subdtest::ReaderTempPath("written-by-subd-for-vtk.ply");
  Write(mesh, path);
  vtkNew<vtkPLYReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* back = reader->GetOutput();
  ASSERT_EQ(back->GetNumberOfPoints(), 8);
  ASSERT_EQ(back->GetNumberOfPolys(), 6);
  for (vtkIdType i = 0; i < 8; ++i)
  {
    double a[3], b[3];
    mesh->GetPoint(i, a);
    back->GetPoint(i, b); // VTK's reader keeps floats
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(b[c], a[c], 1e-6 * (1.0 + std::fabs(a[c])));
    }
  }
}

TEST(PLYWriter, FacesOfMoreThan255Corners)
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  std::vector<vtkIdType> ring;
  for (int i = 0; i < 300; ++i)
  {
    points->InsertNextPoint(std::cos(i * 2 * M_PI / 300), std::sin(i * 2 * M_PI / 300), 0);
    ring.push_back(i);
  }
  mesh->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  polys->InsertNextCell(static_cast<vtkIdType>(ring.size()), ring.data());
  polys->InsertNextCell({ 0, 1, 2 });
  mesh->SetPolys(polys);
  const std::string path = subdtest::ReaderTempPath("wide-face.ply");
  EXPECT_EQ(Write(mesh, path), "");
  EXPECT_NE(subdtest::ReadFileBytes(path).find("property list int int vertex_indices"), std::string::npos);
  vtkNew<vtkSubDPLYReader> reader;
  ASSERT_EQ(subdtest::ReadErrorsOf(reader.Get(), path), "");
  EXPECT_EQ(Faces(reader->GetOutput()), Faces(mesh));
  EXPECT_EQ(reader->GetOutput()->GetPoints()->GetDataType(), VTK_FLOAT); // float points stay float
}
