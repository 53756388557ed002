// Comparing a subdivided mesh made in pieces (VTK's pieces and ghost cells) with the serial
// one: the pieces' faces together must be the serial faces, with the same points and point
// data, and their crease lines the serial lines. Used by the in-process piece tests and by
// the MPI tests, which gather the pieces on one rank first.
//
// Faces are compared as sequences of corners, each rotated to start at its lowest corner (so
// orientation counts), and sorted, since a piece numbers them differently. With `byInputCell`
// they are first grouped by the cell-data array "TestCellId" (the input cell each face
// inherits from; the input must carry it), which checks the inherited cell data too.
#ifndef SubDPieceComparison_h
#define SubDPieceComparison_h

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace subdtest
{
/// A corner's values: coordinates, then every point-data array's components (but the ghost
/// marks, which only pieces have).
using Corner = std::vector<double>;
using Face = std::vector<Corner>;

inline Corner CornerOf(vtkPolyData* mesh, vtkIdType point)
{
  Corner c(3);
  mesh->GetPoint(point, c.data());
  vtkPointData* pd = mesh->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    if (array && array->GetName() && std::string(array->GetName()) == "vtkGhostType")
    {
      continue;
    }
    for (int k = 0; array && k < array->GetNumberOfComponents(); ++k)
    {
      c.push_back(array->GetComponent(point, k));
    }
  }
  return c;
}

/// Whether two corners hold as many values, equal to `tolerance`: the coordinates absolutely,
/// the point data relative to their size where it exceeds 1 (curvature can be large).
inline bool SameCorner(const Corner& a, const Corner& b, double tolerance)
{
  if (a.size() != b.size())
  {
    return false;
  }
  for (size_t i = 0; i < a.size(); ++i)
  {
    const double scale = i < 3 ? 1.0 : std::max(1.0, std::abs(a[i]));
    if (std::abs(a[i] - b[i]) > tolerance * scale)
    {
      return false;
    }
  }
  return true;
}

/// Whether two faces (or polylines) have the same corners in the same order, to `tolerance`.
inline bool SameFace(const Face& a, const Face& b, double tolerance)
{
  return a.size() == b.size() &&
    std::equal(a.begin(), a.end(), b.begin(), [tolerance](const Corner& p, const Corner& q) { return SameCorner(p, q, tolerance); });
}

// Orders corners by their coordinates rounded to 1e-9: a piece's round-off (a coordinate of
// 1e-17 where the serial one is -1e-17) must not change the order.
inline bool CoordinatesLess(const Corner& a, const Corner& b)
{
  for (int k = 0; k < 3; ++k)
  {
    const double qa = std::round(a[k] * 1e9), qb = std::round(b[k] * 1e9);
    if (qa != qb)
    {
      return qa < qb;
    }
  }
  return false;
}

inline bool FaceLess(const Face& a, const Face& b)
{
  return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(), CoordinatesLess);
}

/// What value `index` of a corner of `mesh` (CornerOf) is: a coordinate, or a component of a
/// point-data array.
inline std::string CornerValueName(vtkPolyData* mesh, size_t index)
{
  if (index < 3)
  {
    return std::string("coordinate ") + "xyz"[index];
  }
  size_t first = 3;
  vtkPointData* pd = mesh->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    if (!array || (array->GetName() && std::string(array->GetName()) == "vtkGhostType"))
    {
      continue;
    }
    const size_t components = static_cast<size_t>(array->GetNumberOfComponents());
    if (index < first + components)
    {
      return std::string("point data \"") + (array->GetName() ? array->GetName() : "") + "\" component " +
        std::to_string(index - first);
    }
    first += components;
  }
  return "value " + std::to_string(index) + " (beyond the point data)";
}

/// The faces of `mesh`, canonical and sorted; with `byInputCell`, grouped by the input cell
/// they come from ("TestCellId"), else all in group 0.
inline std::map<vtkIdType, std::vector<Face>> FacesByInputCell(vtkPolyData* mesh, bool byInputCell, std::string& error)
{
  std::map<vtkIdType, std::vector<Face>> faces;
  vtkDataArray* origin = mesh->GetCellData()->GetArray("TestCellId");
  if (byInputCell && mesh->GetNumberOfPolys() > 0 && !origin)
  {
    error = "no TestCellId cell data";
    return faces;
  }
  const vtkIdType firstPoly = mesh->GetNumberOfVerts() + mesh->GetNumberOfLines();
  vtkIdType c = 0;
  vtkIdType n;
  const vtkIdType* pts;
  vtkCellArray* polys = mesh->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, pts); ++c)
  {
    Face face;
    for (vtkIdType k = 0; k < n; ++k)
    {
      face.push_back(CornerOf(mesh, pts[k]));
    }
    std::rotate(face.begin(), std::min_element(face.begin(), face.end(), CoordinatesLess), face.end());
    faces[byInputCell ? static_cast<vtkIdType>(origin->GetComponent(firstPoly + c, 0)) : 0].push_back(face);
  }
  for (auto& group : faces)
  {
    std::sort(group.second.begin(), group.second.end(), FaceLess);
  }
  return faces;
}

/// The cells of `mesh` (crease lines and polygons) that are ghost cells (`ghosts`) or not, with
/// all its points and point data and the cell data the comparisons read ("TestCellId",
/// "Sharpness").
inline vtkSmartPointer<vtkPolyData> CellsByGhostMark(vtkPolyData* mesh, bool ghosts)
{
  auto part = vtkSmartPointer<vtkPolyData>::New();
  part->SetPoints(mesh->GetPoints());
  part->GetPointData()->PassData(mesh->GetPointData());
  part->GetPointData()->RemoveArray("vtkGhostType");
  vtkDataArray* marks = mesh->GetCellData()->GetArray("vtkGhostType");
  vtkCellData* in = mesh->GetCellData();
  vtkNew<vtkCellArray> lines, polys;
  vtkNew<vtkIdTypeArray> origins;
  vtkNew<vtkDoubleArray> sharpness;
  origins->SetName("TestCellId");
  sharpness->SetName("Sharpness");
  auto keep = [&](vtkCellArray* from, vtkCellArray* to, vtkIdType firstCell) {
    vtkIdType c = firstCell, n;
    const vtkIdType* pts;
    for (from->InitTraversal(); from->GetNextCell(n, pts); ++c)
    {
      const bool ghost = marks && (static_cast<int>(marks->GetComponent(c, 0)) & 1) != 0; // DUPLICATECELL
      if (ghost == ghosts)
      {
        to->InsertNextCell(n, pts);
        origins->InsertNextValue(in->GetArray("TestCellId") ? in->GetArray("TestCellId")->GetComponent(c, 0) : 0);
        sharpness->InsertNextValue(in->GetArray("Sharpness") ? in->GetArray("Sharpness")->GetComponent(c, 0) : 0);
      }
    }
  };
  keep(mesh->GetLines(), lines, mesh->GetNumberOfVerts());
  keep(mesh->GetPolys(), polys, mesh->GetNumberOfVerts() + mesh->GetNumberOfLines());
  part->SetLines(lines);
  part->SetPolys(polys);
  part->GetCellData()->AddArray(origins);
  if (in->GetArray("Sharpness"))
  {
    part->GetCellData()->AddArray(sharpness);
  }
  return part;
}

/// "" when every face of `part` is a face of `serial` (corners and point data to `tolerance`;
/// with `byInputCell`, of the same input cell), else the first that is not.
inline std::string FacesAreAmong(vtkPolyData* serial, vtkPolyData* part, double tolerance, bool byInputCell)
{
  std::string error;
  const auto all = FacesByInputCell(serial, byInputCell, error);
  for (const auto& group : FacesByInputCell(part, byInputCell, error))
  {
    const auto found = all.find(group.first);
    for (size_t f = 0; f < group.second.size(); ++f)
    {
      if (found == all.end() ||
        std::none_of(found->second.begin(), found->second.end(), [&](const Face& g) { return SameFace(g, group.second[f], tolerance); }))
      {
        return "face " + std::to_string(f) + " of input cell " + std::to_string(group.first) + " is no serial face";
      }
    }
  }
  return error;
}

/// The crease lines of all `meshes` as (lower end, upper end, sharpness), sorted; a line that
/// several pieces hold (within `tolerance`) once.
inline std::vector<Corner> Lines(const std::vector<vtkPolyData*>& meshes, double tolerance)
{
  std::vector<Corner> lines;
  for (vtkPolyData* mesh : meshes)
  {
    vtkDataArray* sharpness = mesh->GetCellData()->GetArray("Sharpness");
    vtkIdType n;
    const vtkIdType* pts;
    vtkIdType c = mesh->GetNumberOfVerts();
    vtkCellArray* cells = mesh->GetLines();
    for (cells->InitTraversal(); cells->GetNextCell(n, pts); ++c)
    {
      Corner a(3), b(3);
      mesh->GetPoint(pts[0], a.data());
      mesh->GetPoint(pts[n - 1], b.data());
      if (CoordinatesLess(b, a))
      {
        std::swap(a, b);
      }
      a.insert(a.end(), b.begin(), b.end());
      a.push_back(sharpness ? sharpness->GetComponent(c, 0) : -1.0);
      lines.push_back(a);
    }
  }
  // Ends rounded as CoordinatesLess does, then sharpness: round-off (a coordinate of 1e-17
  // in one piece, -1e-17 in another) must not change the order.
  std::sort(lines.begin(), lines.end(), [](const Corner& a, const Corner& b) {
    const Corner endsA(a.begin() + 3, a.end()), endsB(b.begin() + 3, b.end());
    if (CoordinatesLess(a, b) || CoordinatesLess(b, a))
    {
      return CoordinatesLess(a, b);
    }
    if (CoordinatesLess(endsA, endsB) || CoordinatesLess(endsB, endsA))
    {
      return CoordinatesLess(endsA, endsB);
    }
    return a[6] < b[6];
  });
  lines.erase(std::unique(lines.begin(), lines.end(),
                [tolerance](const Corner& a, const Corner& b) { return SameCorner(a, b, tolerance); }),
    lines.end());
  return lines;
}

/// "" when the pieces together are `serial` (faces, their corners' coordinates and point
/// data to `tolerance`, crease lines), else what differs first.
inline std::string ComparePieces(
  vtkPolyData* serial, const std::vector<vtkPolyData*>& pieces, double tolerance, bool byInputCell)
{
  std::string error;
  const auto expected = FacesByInputCell(serial, byInputCell, error);
  std::map<vtkIdType, std::vector<Face>> got;
  for (vtkPolyData* piece : pieces)
  {
    for (auto& group : FacesByInputCell(piece, byInputCell, error))
    {
      std::vector<Face>& faces = got[group.first];
      faces.insert(faces.end(), group.second.begin(), group.second.end());
    }
  }
  if (!error.empty())
  {
    return error;
  }
  std::ostringstream why;
  for (auto& group : got)
  {
    std::sort(group.second.begin(), group.second.end(), FaceLess);
  }
  if (expected.size() != got.size())
  {
    why << "faces come from " << got.size() << " input cells, serially from " << expected.size();
    return why.str();
  }
  for (const auto& group : expected)
  {
    const auto found = got.find(group.first);
    if (found == got.end() || found->second.size() != group.second.size())
    {
      why << "input cell " << group.first << ": " << (found == got.end() ? 0 : found->second.size())
          << " faces, serially " << group.second.size();
      return why.str();
    }
    for (size_t f = 0; f < group.second.size(); ++f)
    {
      const Face& a = group.second[f];
      const Face& b = found->second[f];
      if (!SameFace(a, b, tolerance))
      {
        size_t k = 0;
        while (k + 1 < std::min(a.size(), b.size()) && SameCorner(a[k], b[k], tolerance))
        {
          ++k;
        }
        why.precision(17);
        why << "input cell " << group.first << ", face " << f << " (" << b.size() << " corners, serially "
            << a.size() << "): corner " << k << " is (" << b[k][0] << ", " << b[k][1] << ", " << b[k][2]
            << "), serially (" << a[k][0] << ", " << a[k][1] << ", " << a[k][2] << ")";
        if (a[k].size() != b[k].size())
        {
          why << "; " << b[k].size() << " values at the corner, serially " << a[k].size();
        }
        for (size_t v = 3; v < std::min(a[k].size(), b[k].size()); ++v)
        {
          if (std::abs(a[k][v] - b[k][v]) > tolerance * std::max(1.0, std::abs(a[k][v])))
          {
            why << "; its " << CornerValueName(serial, v) << " is " << b[k][v] << ", serially " << a[k][v];
            break;
          }
        }
        return why.str();
      }
    }
  }
  const std::vector<Corner> serialLines = Lines({ serial }, tolerance);
  const std::vector<Corner> pieceLines = Lines(pieces, tolerance);
  if (serialLines.size() != pieceLines.size())
  {
    why << pieceLines.size() << " distinct crease lines, serially " << serialLines.size();
    return why.str();
  }
  for (size_t l = 0; l < serialLines.size(); ++l)
  {
    if (!SameCorner(serialLines[l], pieceLines[l], tolerance))
    {
      why << "crease line " << l << " differs";
      return why.str();
    }
  }
  return "";
}
}

#endif
