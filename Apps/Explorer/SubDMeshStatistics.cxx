#include "SubDMeshStatistics.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace subdexplorer
{
MeshStatistics ComputeMeshStatistics(vtkPolyData* mesh)
{
  MeshStatistics stats;
  if (!mesh)
  {
    return stats;
  }
  stats.Vertices = mesh->GetNumberOfPoints();
  stats.Faces = mesh->GetNumberOfPolys();
  stats.Lines = mesh->GetNumberOfLines();
  // Every polygon side as (low, high); sorting groups the copies of an edge: one copy is a
  // boundary edge, two an interior one.
  std::vector<std::pair<vtkIdType, vtkIdType>> sides;
  vtkIdType triangles = 0, quads = 0;
  auto it = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    triangles += n == 3 ? 1 : 0;
    quads += n == 4 ? 1 : 0;
    for (vtkIdType k = 0; k < n; ++k)
    {
      const vtkIdType a = ids[k], b = ids[(k + 1) % n];
      sides.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(sides.begin(), sides.end());
  std::vector<int> valence(static_cast<size_t>(stats.Vertices), 0);
  std::vector<char> boundary(static_cast<size_t>(stats.Vertices), 0);
  for (size_t i = 0; i < sides.size();)
  {
    size_t j = i;
    while (j < sides.size() && sides[j] == sides[i])
    {
      ++j;
    }
    ++stats.Edges;
    ++valence[sides[i].first];
    ++valence[sides[i].second];
    if (j - i == 1)
    {
      boundary[sides[i].first] = boundary[sides[i].second] = 1;
    }
    i = j;
  }
  const int regular = triangles > quads ? 6 : 4;
  for (vtkIdType v = 0; v < stats.Vertices; ++v)
  {
    if (valence[v] > 0 && !boundary[v] && valence[v] != regular)
    {
      ++stats.Extraordinary;
    }
  }
  return stats;
}
}
