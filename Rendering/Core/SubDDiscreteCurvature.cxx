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

namespace subdrender
{
TriangleAdjacency::TriangleAdjacency(vtkPolyData* mesh)
{
  const vtkIdType numPoints = mesh->GetNumberOfPoints();
  vtkCellArray* polys = mesh->GetPolys();
  Corners.reserve(static_cast<size_t>(3 * polys->GetNumberOfConnectivityIds()));
  vtkIdType size;
  const vtkIdType* ids;
  for (polys->InitTraversal(); polys->GetNextCell(size, ids);)
  {
    for (vtkIdType k = 1; k + 1 < size; ++k)
    {
      Corners.insert(Corners.end(), { ids[0], ids[k], ids[k + 1] });
    }
  }
  const vtkIdType numTriangles = static_cast<vtkIdType>(Corners.size() / 3);
  // The triangles around each point, as compressed rows.
  std::vector<vtkIdType> offsets(static_cast<size_t>(numPoints + 1), 0);
  for (vtkIdType corner : Corners)
  {
    ++offsets[static_cast<size_t>(corner + 1)];
  }
  for (vtkIdType p = 0; p < numPoints; ++p)
  {
    offsets[p + 1] += offsets[p];
  }
  std::vector<vtkIdType> pointTriangles(Corners.size());
  std::vector<vtkIdType> fill(offsets.begin(), offsets.end() - 1);
  for (vtkIdType t = 0; t < numTriangles; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      pointTriangles[static_cast<size_t>(fill[Corners[3 * t + k]]++)] = t;
    }
  }
  // The twin of half edge a -> b is b -> a in one of b's triangles. Without one (or with more
  // than one) the edge is boundary or non-manifold, and curvature means little at its ends.
  Across.assign(Corners.size(), -1);
  Boundary.assign(static_cast<size_t>(numPoints), false);
  for (vtkIdType t = 0; t < numTriangles; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType a = Corners[3 * t + k], b = Corners[3 * t + (k + 1) % 3];
      vtkIdType found = -1, count = 0;
      for (vtkIdType i = offsets[b]; i < offsets[b + 1]; ++i)
      {
        const vtkIdType s = pointTriangles[i];
        for (int j = 0; j < 3 && s != t; ++j)
        {
          if (Corners[3 * s + j] == b && Corners[3 * s + (j + 1) % 3] == a)
          {
            found = s;
            ++count;
          }
        }
      }
      if (count == 1)
      {
        Across[static_cast<size_t>(3 * t + k)] = found;
      }
      else
      {
        Boundary[static_cast<size_t>(a)] = Boundary[static_cast<size_t>(b)] = true;
      }
    }
  }
}

vtkSmartPointer<vtkDoubleArray> DiscreteCurvature(vtkPolyData* mesh, const TriangleAdjacency& adjacency, int coloring)
{
  const vtkIdType numPoints = mesh->GetNumberOfPoints();
  const std::vector<vtkIdType>& corners = adjacency.Corners;
  const vtkIdType numTriangles = static_cast<vtkIdType>(corners.size() / 3);
  std::vector<double> xyz(static_cast<size_t>(3 * numPoints));
  for (vtkIdType p = 0; p < numPoints; ++p)
  {
    mesh->GetPoints()->GetPoint(p, &xyz[static_cast<size_t>(3 * p)]);
  }
  auto point = [&xyz](vtkIdType p) { return &xyz[static_cast<size_t>(3 * p)]; };

  // Per triangle: unit normal and area; per point: area share, angle sum, sum |e| b_e / 4.
  std::vector<double> normals(static_cast<size_t>(3 * numTriangles));
  std::vector<double> area(static_cast<size_t>(numPoints), 0.0), angles(static_cast<size_t>(numPoints), 0.0),
    bending(static_cast<size_t>(numPoints), 0.0);
  for (vtkIdType t = 0; t < numTriangles; ++t)
  {
    const double* p[3] = { point(corners[3 * t]), point(corners[3 * t + 1]), point(corners[3 * t + 2]) };
    double u[3], v[3], n[3];
    vtkMath::Subtract(p[1], p[0], u);
    vtkMath::Subtract(p[2], p[0], v);
    vtkMath::Cross(u, v, n);
    const double twiceArea = vtkMath::Norm(n);
    if (twiceArea > 0.0)
    {
      vtkMath::MultiplyScalar(n, 1.0 / twiceArea);
    }
    std::copy(n, n + 3, &normals[static_cast<size_t>(3 * t)]);
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType c = corners[3 * t + k];
      double e1[3], e2[3];
      vtkMath::Subtract(p[(k + 1) % 3], p[k], e1);
      vtkMath::Subtract(p[(k + 2) % 3], p[k], e2);
      double cross[3];
      vtkMath::Cross(e1, e2, cross);
      angles[static_cast<size_t>(c)] += std::atan2(vtkMath::Norm(cross), vtkMath::Dot(e1, e2));
      area[static_cast<size_t>(c)] += 0.5 * twiceArea;
    }
  }
  const bool needMean = coloring != vtkSubDScene::COLOR_GAUSSIAN_CURVATURE;
  for (vtkIdType t = 0; t < numTriangles && needMean; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType a = corners[3 * t + k], b = corners[3 * t + (k + 1) % 3];
      const vtkIdType s = adjacency.Across[static_cast<size_t>(3 * t + k)];
      if (s < t) // each interior edge once (from its lower-numbered triangle); none on the boundary
      {
        continue;
      }
      const double* n1 = &normals[static_cast<size_t>(3 * t)];
      const double* n2 = &normals[static_cast<size_t>(3 * s)];
      double e[3], cross[3];
      vtkMath::Subtract(point(b), point(a), e);
      vtkMath::Cross(n1, n2, cross);
      // Signed dihedral angle: the normals turn about the edge a -> b (t on its left) when
      // the surface is convex there.
      const double length = vtkMath::Norm(e);
      const double beta = length > 0.0 ? std::atan2(vtkMath::Dot(cross, e) / length, vtkMath::Dot(n1, n2)) : 0.0;
      bending[static_cast<size_t>(a)] += 0.25 * length * beta;
      bending[static_cast<size_t>(b)] += 0.25 * length * beta;
    }
  }

  auto curvature = vtkSmartPointer<vtkDoubleArray>::New();
  curvature->SetName(CurvatureArrayName(coloring));
  curvature->SetNumberOfTuples(numPoints);
  for (vtkIdType p = 0; p < numPoints; ++p)
  {
    const double share = area[static_cast<size_t>(p)] / 3.0;
    double value = 0.0;
    if (share > 0.0)
    {
      const double K = (2.0 * vtkMath::Pi() - angles[static_cast<size_t>(p)]) / share;
      const double H = bending[static_cast<size_t>(p)] / share;
      const double spread = std::sqrt(std::max(0.0, H * H - K));
      switch (coloring)
      {
        case vtkSubDScene::COLOR_GAUSSIAN_CURVATURE:
          value = K;
          break;
        case vtkSubDScene::COLOR_MAXIMUM_CURVATURE:
          value = H + spread;
          break;
        case vtkSubDScene::COLOR_MINIMUM_CURVATURE:
          value = H - spread;
          break;
        default:
          value = H;
      }
    }
    curvature->SetValue(p, value);
  }
  return curvature;
}
}
