#include "SubDCagePicking.h"

#include "vtkCellArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>

namespace subdapp
{
namespace
{
// Distance from (x, y) to the segment p-q.
double SegmentDistance(const double* p, const double* q, double x, double y)
{
  const double dx = q[0] - p[0], dy = q[1] - p[1];
  const double length2 = dx * dx + dy * dy;
  const double t = length2 > 0.0 ? std::clamp(((x - p[0]) * dx + (y - p[1]) * dy) / length2, 0.0, 1.0) : 0.0;
  return std::hypot(p[0] + t * dx - x, p[1] + t * dy - y);
}
}

PickedElement PickCageElement(vtkPolyData* cage, const std::vector<double>& screen, double x, double y,
  double vertexRadius, double edgeRadius)
{
  PickedElement picked;
  double best = vertexRadius;
  const vtkIdType numPoints = static_cast<vtkIdType>(screen.size() / 2);
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    const double d = std::hypot(screen[2 * i] - x, screen[2 * i + 1] - y);
    if (d <= best)
    {
      best = d;
      picked.A = i;
    }
  }
  if (picked.A >= 0)
  {
    return picked;
  }
  best = edgeRadius;
  vtkCellArray* polys = cage->GetPolys();
  vtkNew<vtkIdList> cell;
  for (polys->InitTraversal(); polys->GetNextCell(cell);)
  {
    const vtkIdType n = cell->GetNumberOfIds();
    for (vtkIdType k = 0; k < n; ++k)
    {
      const vtkIdType a = cell->GetId(k), b = cell->GetId((k + 1) % n);
      if (a >= numPoints || b >= numPoints)
      {
        continue;
      }
      const double d = SegmentDistance(&screen[2 * a], &screen[2 * b], x, y);
      if (d <= best)
      {
        best = d;
        picked.A = std::min(a, b);
        picked.B = std::max(a, b);
      }
    }
  }
  return picked;
}
}
