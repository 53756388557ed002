#include "SubDDiscreteCurvature.h"

#include "SubDSceneColoring.h"
#include "vtkSubDScene.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkMath.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>

namespace
{
// The points of `mesh` as a flat array of coordinates.
std::vector<double> PointCoordinates(vtkPolyData* mesh)
{
  const vtkIdType numPoints = mesh->GetNumberOfPoints();
  std::vector<double> xyz(static_cast<size_t>(3 * numPoints));
  for (vtkIdType p = 0; p < numPoints; ++p)
  {
    mesh->GetPoints()->GetPoint(p, &xyz[static_cast<size_t>(3 * p)]);
  }
  return xyz;
}

// Per polygon: its unit normal (Newell's, into `normals`); per point (`xyz`): adds its share
// of each polygon's area to `share` and its corner angles to `angles`.
void PolygonNormalsAndAngles(const std::vector<double>& xyz, const subdrender::PolygonAdjacency& adjacency,
  std::vector<double>& normals, std::vector<double>& share, std::vector<double>& angles)
{
  const std::vector<vtkIdType>& corners = adjacency.Corners;
  auto point = [&xyz](vtkIdType p) { return &xyz[static_cast<size_t>(3 * p)]; };
  for (vtkIdType f = 0; f < adjacency.GetNumberOfPolygons(); ++f)
  {
    const vtkIdType first = adjacency.Offsets[f], size = adjacency.Offsets[f + 1] - first;
    double n[3] = { 0.0, 0.0, 0.0 };
    for (vtkIdType c = first; c < first + size; ++c)
    {
      const double* p = point(corners[c]);
      const double* q = point(corners[adjacency.Next(f, c)]);
      n[0] += (p[1] - q[1]) * (p[2] + q[2]);
      n[1] += (p[2] - q[2]) * (p[0] + q[0]);
      n[2] += (p[0] - q[0]) * (p[1] + q[1]);
    }
    const double twiceArea = vtkMath::Norm(n);
    if (twiceArea > 0.0)
    {
      vtkMath::MultiplyScalar(n, 1.0 / twiceArea);
    }
    std::copy(n, n + 3, &normals[static_cast<size_t>(3 * f)]);
    for (vtkIdType c = first; c < first + size; ++c)
    {
      const vtkIdType previous = c == first ? first + size - 1 : c - 1;
      const double* p = point(corners[c]);
      double e1[3], e2[3], cross[3];
      vtkMath::Subtract(point(corners[adjacency.Next(f, c)]), p, e1);
      vtkMath::Subtract(point(corners[previous]), p, e2);
      vtkMath::Cross(e1, e2, cross);
      angles[static_cast<size_t>(corners[c])] += std::atan2(vtkMath::Norm(cross), vtkMath::Dot(e1, e2));
      share[static_cast<size_t>(corners[c])] += 0.5 * twiceArea / static_cast<double>(size);
    }
  }
}

// Adds |e| b_e / 4 of each interior edge e (b_e its signed dihedral angle, from the polygon
// `normals`) to the `bending` of both its ends.
void AddEdgeBending(const std::vector<double>& xyz, const subdrender::PolygonAdjacency& adjacency,
  const std::vector<double>& normals, std::vector<double>& bending)
{
  const std::vector<vtkIdType>& corners = adjacency.Corners;
  auto point = [&xyz](vtkIdType p) { return &xyz[static_cast<size_t>(3 * p)]; };
  for (vtkIdType f = 0; f < adjacency.GetNumberOfPolygons(); ++f)
  {
    for (vtkIdType c = adjacency.Offsets[f]; c < adjacency.Offsets[f + 1]; ++c)
    {
      const vtkIdType a = corners[c], b = corners[adjacency.Next(f, c)];
      const vtkIdType g = adjacency.Across[static_cast<size_t>(c)];
      if (g < f) // each interior edge once (from its lower-numbered polygon); none on the boundary
      {
        continue;
      }
      const double* n1 = &normals[static_cast<size_t>(3 * f)];
      const double* n2 = &normals[static_cast<size_t>(3 * g)];
      double e[3], cross[3];
      vtkMath::Subtract(point(b), point(a), e);
      vtkMath::Cross(n1, n2, cross);
      // Signed dihedral angle: the normals turn about the edge a -> b (f on its left) when
      // the surface is convex there.
      const double length = vtkMath::Norm(e);
      const double beta = length > 0.0 ? std::atan2(vtkMath::Dot(cross, e) / length, vtkMath::Dot(n1, n2)) : 0.0;
      bending[static_cast<size_t>(a)] += 0.25 * length * beta;
      bending[static_cast<size_t>(b)] += 0.25 * length * beta;
    }
  }
}

// The curvature `coloring` at a point from its area `share`, corner angle sum and bending
// (0 without area).
double PointCurvature(int coloring, double share, double angles, double bending)
{
  if (!(share > 0.0))
  {
    return 0.0;
  }
  const double K = (2.0 * vtkMath::Pi() - angles) / share;
  const double H = bending / share;
  const double spread = std::sqrt(std::max(0.0, H * H - K));
  switch (coloring)
  {
    case vtkSubDScene::COLOR_GAUSSIAN_CURVATURE:
      return K;
    case vtkSubDScene::COLOR_MAXIMUM_CURVATURE:
      return H + spread;
    case vtkSubDScene::COLOR_MINIMUM_CURVATURE:
      return H - spread;
    default:
      return H;
  }
}
}

namespace subdrender
{
PolygonAdjacency::PolygonAdjacency(vtkPolyData* mesh)
{
  const vtkIdType numPoints = mesh->GetNumberOfPoints();
  vtkCellArray* polys = mesh->GetPolys();
  Offsets.reserve(static_cast<size_t>(polys->GetNumberOfCells() + 1));
  Corners.reserve(static_cast<size_t>(polys->GetNumberOfConnectivityIds()));
  Offsets.push_back(0);
  vtkIdType size;
  const vtkIdType* ids;
  for (polys->InitTraversal(); polys->GetNextCell(size, ids);)
  {
    Corners.insert(Corners.end(), ids, ids + size);
    Offsets.push_back(static_cast<vtkIdType>(Corners.size()));
  }
  const vtkIdType numPolygons = this->GetNumberOfPolygons();
  // The polygons around each point, as compressed rows.
  std::vector<vtkIdType> rows(static_cast<size_t>(numPoints + 1), 0);
  for (vtkIdType corner : Corners)
  {
    ++rows[static_cast<size_t>(corner + 1)];
  }
  for (vtkIdType p = 0; p < numPoints; ++p)
  {
    rows[p + 1] += rows[p];
  }
  std::vector<vtkIdType> pointPolygons(Corners.size());
  std::vector<vtkIdType> fill(rows.begin(), rows.end() - 1);
  for (vtkIdType f = 0; f < numPolygons; ++f)
  {
    for (vtkIdType c = Offsets[f]; c < Offsets[f + 1]; ++c)
    {
      pointPolygons[static_cast<size_t>(fill[Corners[c]]++)] = f;
    }
  }
  // The twin of edge a -> b is b -> a in one of b's polygons. Without one (or with more than
  // one) the edge is boundary or non-manifold, and curvature means little at its ends.
  Across.assign(Corners.size(), -1);
  Boundary.assign(static_cast<size_t>(numPoints), false);
  for (vtkIdType f = 0; f < numPolygons; ++f)
  {
    for (vtkIdType c = Offsets[f]; c < Offsets[f + 1]; ++c)
    {
      const vtkIdType a = Corners[c], b = Corners[this->Next(f, c)];
      vtkIdType found = -1, count = 0;
      for (vtkIdType i = rows[b]; i < rows[b + 1]; ++i)
      {
        const vtkIdType g = pointPolygons[i];
        for (vtkIdType d = Offsets[g]; d < Offsets[g + 1] && g != f; ++d)
        {
          if (Corners[d] == b && Corners[this->Next(g, d)] == a)
          {
            found = g;
            ++count;
          }
        }
      }
      if (count == 1)
      {
        Across[static_cast<size_t>(c)] = found;
      }
      else
      {
        Boundary[static_cast<size_t>(a)] = Boundary[static_cast<size_t>(b)] = true;
      }
    }
  }
}

vtkSmartPointer<vtkDoubleArray> DiscreteCurvature(vtkPolyData* mesh, const PolygonAdjacency& adjacency, int coloring)
{
  const vtkIdType numPoints = mesh->GetNumberOfPoints();
  const std::vector<double> xyz = PointCoordinates(mesh);
  // Per polygon: unit normal (Newell's); per point: area share, angle sum, sum |e| b_e / 4.
  std::vector<double> normals(static_cast<size_t>(3 * adjacency.GetNumberOfPolygons()));
  std::vector<double> share(static_cast<size_t>(numPoints), 0.0), angles(static_cast<size_t>(numPoints), 0.0),
    bending(static_cast<size_t>(numPoints), 0.0);
  PolygonNormalsAndAngles(xyz, adjacency, normals, share, angles);
  if (coloring != vtkSubDScene::COLOR_GAUSSIAN_CURVATURE)
  {
    AddEdgeBending(xyz, adjacency, normals, bending);
  }

  auto curvature = vtkSmartPointer<vtkDoubleArray>::New();
  curvature->SetName(CurvatureArrayName(coloring));
  curvature->SetNumberOfTuples(numPoints);
  for (vtkIdType p = 0; p < numPoints; ++p)
  {
    const size_t i = static_cast<size_t>(p);
    curvature->SetValue(p, PointCurvature(coloring, share[i], angles[i], bending[i]));
  }
  return curvature;
}
}
