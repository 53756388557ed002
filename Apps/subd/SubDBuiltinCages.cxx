#include "SubDBuiltinCages.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cmath>

namespace subdapp
{
namespace
{
vtkSmartPointer<vtkPolyData> MakePolyData(
  const std::vector<double>& xyz, const std::vector<std::vector<vtkIdType>>& faces)
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataType(VTK_DOUBLE);
  for (size_t i = 0; i + 2 < xyz.size(); i += 3)
  {
    points->InsertNextPoint(xyz[i], xyz[i + 1], xyz[i + 2]);
  }
  vtkNew<vtkCellArray> polys;
  for (const auto& face : faces)
  {
    polys->InsertNextCell(static_cast<vtkIdType>(face.size()), face.data());
  }
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  return mesh;
}

// The unit cube: every vertex has valence 3, the classic Catmull-Clark test.
vtkSmartPointer<vtkPolyData> Cube()
{
  return MakePolyData({ 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1 },
    { { 0, 3, 2, 1 }, { 4, 5, 6, 7 }, { 0, 1, 5, 4 }, { 1, 2, 6, 5 }, { 2, 3, 7, 6 }, { 3, 0, 4, 7 } });
}

// The cube with a semi-sharp crease loop around its top face (sharpness 2.5, so it
// softens after a few levels) and an infinitely sharp corner at the bottom.
vtkSmartPointer<vtkPolyData> CreasedCube()
{
  vtkSmartPointer<vtkPolyData> mesh = Cube();
  vtkNew<vtkCellArray> lines;
  const vtkIdType top[] = { 4, 5, 6, 7, 4 };
  lines->InsertNextCell(5, top);
  mesh->SetLines(lines);
  vtkNew<vtkFloatArray> sharpness;
  sharpness->SetName("Sharpness");
  sharpness->SetNumberOfTuples(mesh->GetNumberOfCells());
  sharpness->Fill(0.0);
  sharpness->SetValue(0, 2.5f); // the line is cell 0: lines come before polygons
  mesh->GetCellData()->AddArray(sharpness);
  vtkNew<vtkFloatArray> corners;
  corners->SetName("CornerSharpness");
  corners->SetNumberOfTuples(mesh->GetNumberOfPoints());
  corners->Fill(0.0);
  corners->SetValue(0, 10.0f);
  mesh->GetPointData()->AddArray(corners);
  return mesh;
}

// A square pyramid: a quad base and four triangles, an apex of valence 4 and base vertices
// of valence 3 -- mixed face sizes.
vtkSmartPointer<vtkPolyData> Pyramid()
{
  return MakePolyData({ -1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0, 0, 0, 1.5 },
    { { 0, 3, 2, 1 }, { 0, 1, 4 }, { 1, 2, 4 }, { 2, 3, 4 }, { 3, 0, 4 } });
}

// An open 4x4 grid of quads, gently curved: boundary edges and corners.
vtkSmartPointer<vtkPolyData> OpenGrid()
{
  std::vector<double> xyz;
  const int n = 5;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const double x = i - 2.0, y = j - 2.0;
      xyz.insert(xyz.end(), { x, y, 0.15 * (x * x - y * y) });
    }
  }
  std::vector<std::vector<vtkIdType>> faces;
  for (int j = 0; j + 1 < n; ++j)
  {
    for (int i = 0; i + 1 < n; ++i)
    {
      const vtkIdType a = j * n + i;
      faces.push_back({ a, a + 1, a + n + 1, a + n });
    }
  }
  return MakePolyData(xyz, faces);
}

// Control polygons as polylines (for the curve schemes): `closed` repeats the first point.
vtkSmartPointer<vtkPolyData> MakePolyline(const std::vector<double>& xyz, bool closed)
{
  auto curve = MakePolyData(xyz, {});
  curve->SetPolys(nullptr);
  std::vector<vtkIdType> ids;
  for (vtkIdType i = 0; i < curve->GetNumberOfPoints(); ++i)
  {
    ids.push_back(i);
  }
  if (closed)
  {
    ids.push_back(0);
  }
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  curve->SetLines(lines);
  return curve;
}

// A closed five-pointed star whose top tip is a sharp corner ("CornerSharpness" 10): the
// other tips round off, that one stays.
vtkSmartPointer<vtkPolyData> Star()
{
  std::vector<double> xyz;
  for (int k = 0; k < 10; ++k)
  {
    const double angle = M_PI / 2 + k * M_PI / 5, radius = k % 2 ? 0.45 : 1.0;
    xyz.insert(xyz.end(), { radius * std::cos(angle), radius * std::sin(angle), 0.0 });
  }
  vtkSmartPointer<vtkPolyData> curve = MakePolyline(xyz, true);
  vtkNew<vtkFloatArray> corners;
  corners->SetName("CornerSharpness");
  corners->SetNumberOfTuples(curve->GetNumberOfPoints());
  corners->Fill(0.0);
  corners->SetValue(0, 10.0f);
  curve->GetPointData()->AddArray(corners);
  return curve;
}

// An open zigzag climbing a helix: end rules, and a curve that is not planar.
vtkSmartPointer<vtkPolyData> Zigzag()
{
  std::vector<double> xyz;
  for (int k = 0; k < 9; ++k)
  {
    const double angle = k * M_PI / 4, radius = k % 2 ? 1.3 : 0.8;
    xyz.insert(xyz.end(), { radius * std::cos(angle), radius * std::sin(angle), 0.2 * k });
  }
  return MakePolyline(xyz, false);
}
}

std::vector<std::string> BuiltinCurveNames()
{
  return { "star", "zigzag" };
}

std::vector<std::string> BuiltinCageNames()
{
  return { "cube", "creased-cube", "pyramid", "open-grid" };
}

vtkSmartPointer<vtkPolyData> MakeBuiltinCage(const std::string& name)
{
  if (name == "cube")
  {
    return Cube();
  }
  if (name == "creased-cube")
  {
    return CreasedCube();
  }
  if (name == "pyramid")
  {
    return Pyramid();
  }
  if (name == "open-grid")
  {
    return OpenGrid();
  }
  if (name == "star")
  {
    return Star();
  }
  if (name == "zigzag")
  {
    return Zigzag();
  }
  return nullptr;
}
}
