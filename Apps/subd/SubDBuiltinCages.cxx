#include "SubDBuiltinCages.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <cstdlib>
#include <utility>

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

vtkSmartPointer<vtkPolyData> Tetrahedron()
{
  return MakePolyData({ 1, 1, 1, -1, -1, 1, -1, 1, -1, 1, -1, -1 }, { { 0, 1, 2 }, { 0, 3, 1 }, { 0, 2, 3 }, { 1, 3, 2 } });
}

vtkSmartPointer<vtkPolyData> Octahedron()
{
  return MakePolyData({ 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1 },
    { { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 }, { 3, 0, 4 }, { 2, 0, 5 }, { 1, 2, 5 }, { 3, 1, 5 }, { 0, 3, 5 } });
}

// A torus of 8 x 6 quads: genus one, every vertex regular.
vtkSmartPointer<vtkPolyData> Torus()
{
  const int around = 8, tube = 6;
  std::vector<double> xyz;
  for (int i = 0; i < around; ++i)
  {
    for (int j = 0; j < tube; ++j)
    {
      const double u = 2 * M_PI * i / around, v = 2 * M_PI * j / tube, r = 1.0 + 0.4 * std::cos(v);
      xyz.insert(xyz.end(), { r * std::cos(u), r * std::sin(u), 0.4 * std::sin(v) });
    }
  }
  std::vector<std::vector<vtkIdType>> faces;
  for (int i = 0; i < around; ++i)
  {
    for (int j = 0; j < tube; ++j)
    {
      auto id = [&](int a, int b) { return static_cast<vtkIdType>(((a % around) * tube) + (b % tube)); };
      faces.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  }
  return MakePolyData(xyz, faces);
}

// A machined block, 2 x 1.4 x 1: each side a grid of quads, four across its flat middle, with
// support loops 0.08 from the rims, as a modeller holds an edge tight: large flat regions and
// tight rounding (what the adaptive tessellation, --tolerance, is for).
vtkSmartPointer<vtkPolyData> RoundedBox()
{
  const double half[3] = { 1.0, 0.7, 0.5 }, support = 0.08;
  std::vector<double> lines[3]; // the grid lines along each axis
  for (int axis = 0; axis < 3; ++axis)
  {
    const double h = half[axis];
    lines[axis] = { -h };
    for (int i = 0; i <= 4; ++i)
    {
      lines[axis].push_back(-h + support + (2 * (h - support)) * i / 4.0);
    }
    lines[axis].push_back(h);
  }
  std::vector<double> xyz;
  std::map<std::array<int, 3>, vtkIdType> ids; // grid position -> point
  auto point = [&](const std::array<int, 3>& at) {
    auto found = ids.emplace(at, static_cast<vtkIdType>(ids.size()));
    if (found.second)
    {
      xyz.insert(xyz.end(), { lines[0][at[0]], lines[1][at[1]], lines[2][at[2]] });
    }
    return found.first->second;
  };
  const int last = static_cast<int>(lines[0].size()) - 1;
  std::vector<std::vector<vtkIdType>> faces;
  for (int axis = 0; axis < 3; ++axis)
  {
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    for (int side : { 0, last })
    {
      for (int i = 0; i < last; ++i)
      {
        for (int j = 0; j < last; ++j)
        {
          std::vector<vtkIdType> quad;
          for (const auto& c : { std::array<int, 2>{ i, j }, { i + 1, j }, { i + 1, j + 1 }, { i, j + 1 } })
          {
            std::array<int, 3> at;
            at[axis] = side;
            at[a] = c[0];
            at[b] = c[1];
            quad.push_back(point(at));
          }
          if (side == 0)
          {
            std::reverse(quad.begin(), quad.end()); // counter-clockwise seen from outside
          }
          faces.push_back(quad);
        }
      }
    }
  }
  return MakePolyData(xyz, faces);
}

// An open fan of `valence` quads around a raised centre vertex: one extraordinary vertex
// (regular for 4) inside a boundary.
vtkSmartPointer<vtkPolyData> ValenceFan(int valence)
{
  std::vector<double> xyz{ 0, 0, 0.5 };
  for (int k = 0; k < valence; ++k)
  {
    const double a = 2 * M_PI * k / valence, b = 2 * M_PI * (k + 0.5) / valence;
    xyz.insert(xyz.end(), { std::cos(a), std::sin(a), 0.1 });
    xyz.insert(xyz.end(), { 1.6 * std::cos(b), 1.6 * std::sin(b), 0.0 });
  }
  std::vector<std::vector<vtkIdType>> faces;
  for (int k = 0; k < valence; ++k)
  {
    const vtkIdType edge = 1 + 2 * k, corner = edge + 1, next = 1 + 2 * ((k + 1) % valence);
    faces.push_back({ 0, edge, corner, next });
  }
  return MakePolyData(xyz, faces);
}

// The letter L as a closed block of quads: unit squares extruded by 0.6, so concave corners
// and valence-3/5 vertices appear.
vtkSmartPointer<vtkPolyData> LetterL()
{
  const std::vector<std::pair<int, int>> squares{ { 0, 0 }, { 1, 0 }, { 2, 0 }, { 0, 1 }, { 0, 2 }, { 0, 3 } };
  auto filled = [&](int x, int y) {
    for (const auto& sq : squares)
      if (sq.first == x && sq.second == y)
        return true;
    return false;
  };
  std::vector<double> xyz;
  std::vector<std::vector<vtkIdType>> faces;
  auto point = [&](int x, int y, int z) { // grid corner (x, y) on the bottom (0) or top (1)
    for (size_t i = 0; i < xyz.size(); i += 3)
      if (xyz[i] == x && xyz[i + 1] == y && xyz[i + 2] == 0.6 * z)
        return static_cast<vtkIdType>(i / 3);
    xyz.insert(xyz.end(), { double(x), double(y), 0.6 * z });
    return static_cast<vtkIdType>(xyz.size() / 3 - 1);
  };
  for (const auto& sq : squares)
  {
    const int x = sq.first, y = sq.second;
    faces.push_back({ point(x, y, 1), point(x + 1, y, 1), point(x + 1, y + 1, 1), point(x, y + 1, 1) });
    faces.push_back({ point(x, y, 0), point(x, y + 1, 0), point(x + 1, y + 1, 0), point(x + 1, y, 0) });
    // Walls where the neighbour square is empty, facing outwards.
    if (!filled(x, y - 1))
      faces.push_back({ point(x, y, 0), point(x + 1, y, 0), point(x + 1, y, 1), point(x, y, 1) });
    if (!filled(x + 1, y))
      faces.push_back({ point(x + 1, y, 0), point(x + 1, y + 1, 0), point(x + 1, y + 1, 1), point(x + 1, y, 1) });
    if (!filled(x, y + 1))
      faces.push_back({ point(x + 1, y + 1, 0), point(x, y + 1, 0), point(x, y + 1, 1), point(x + 1, y + 1, 1) });
    if (!filled(x - 1, y))
      faces.push_back({ point(x, y + 1, 0), point(x, y, 0), point(x, y, 1), point(x, y + 1, 1) });
  }
  return MakePolyData(xyz, faces);
}

// Mixed triangles and quads: a hexagonal prism (six quads around) whose ends are fans of
// six triangles around a raised centre. The rim vertices have two quads and two triangles,
// so every scheme shows what it does where triangles meet quads.
vtkSmartPointer<vtkPolyData> MixedTriQuad()
{
  std::vector<double> xyz;
  for (int ring = 0; ring < 2; ++ring)
  {
    for (int k = 0; k < 6; ++k)
    {
      const double angle = 2.0 * 3.14159265358979323846 * k / 6.0;
      xyz.insert(xyz.end(), { std::cos(angle), std::sin(angle), ring == 0 ? -0.6 : 0.6 });
    }
  }
  xyz.insert(xyz.end(), { 0.0, 0.0, -1.1, 0.0, 0.0, 1.1 }); // the centres: 12 below, 13 above
  std::vector<std::vector<vtkIdType>> faces;
  for (vtkIdType k = 0; k < 6; ++k)
  {
    const vtkIdType next = (k + 1) % 6;
    faces.push_back({ k, next, 6 + next, 6 + k });
    faces.push_back({ 12, next, k });
    faces.push_back({ 13, 6 + k, 6 + next });
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
  return { "cube", "creased-cube", "pyramid", "open-grid", "tetrahedron", "octahedron", "torus", "letter-l",
    "mixed-tri-quad", "rounded-box", "valence-3", "valence-4", "valence-5", "valence-6", "valence-7", "valence-8" };
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
  if (name == "tetrahedron")
  {
    return Tetrahedron();
  }
  if (name == "octahedron")
  {
    return Octahedron();
  }
  if (name == "torus")
  {
    return Torus();
  }
  if (name == "letter-l")
  {
    return LetterL();
  }
  if (name == "mixed-tri-quad")
  {
    return MixedTriQuad();
  }
  if (name == "rounded-box")
  {
    return RoundedBox();
  }
  if (name.rfind("valence-", 0) == 0)
  {
    const int valence = std::atoi(name.c_str() + 8);
    return valence >= 3 && valence <= 8 ? ValenceFan(valence) : nullptr;
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
