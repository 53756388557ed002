#include "SubDSeamShading.h"

#include "SubDCoincidentPoints.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"

#include <map>
#include <utility>

namespace subdrender
{
std::vector<vtkIdType> FirstPointAtSamePosition(vtkPolyData* mesh)
{
  const vtkIdType n = mesh->GetNumberOfPoints();
  std::vector<double> xyz(3 * static_cast<size_t>(n));
  for (vtkIdType p = 0; p < n; ++p)
  {
    mesh->GetPoint(p, &xyz[3 * static_cast<size_t>(p)]);
  }
  const std::vector<subd::Index> first = subd::FirstPointAtSamePosition(xyz.data(), static_cast<subd::Index>(n));
  bool any = false;
  for (vtkIdType p = 0; p < n && !any; ++p)
  {
    any = first[p] != p;
  }
  return any ? std::vector<vtkIdType>(first.begin(), first.end()) : std::vector<vtkIdType>();
}

vtkSmartPointer<vtkPolyData> WeldedPolygons(vtkPolyData* mesh, const std::vector<vtkIdType>& weldOf)
{
  vtkNew<vtkCellArray> polys;
  polys->DeepCopy(mesh->GetPolys());
  vtkDataArray* connectivity = polys->GetConnectivityArray();
  for (vtkIdType k = 0; k < connectivity->GetNumberOfTuples(); ++k)
  {
    connectivity->SetTuple1(k, static_cast<double>(weldOf[static_cast<vtkIdType>(connectivity->GetTuple1(k))]));
  }
  auto welded = vtkSmartPointer<vtkPolyData>::New();
  welded->SetPoints(mesh->GetPoints());
  welded->GetPointData()->ShallowCopy(mesh->GetPointData());
  welded->SetPolys(polys);
  return welded;
}

vtkSmartPointer<vtkPolyData> SplitAsBoth(vtkPolyData* split, vtkPolyData* shaded)
{
  vtkDataArray* normals = shaded->GetPointData()->GetNormals();
  // A split point has one shaded point but where the normals split at a sharp edge: the first
  // pair of each split point is kept in arrays, the others (few) in a map.
  std::vector<vtkIdType> firstShaded(static_cast<size_t>(split->GetNumberOfPoints()), -1);
  std::vector<vtkIdType> firstOutput(firstShaded.size(), -1);
  std::map<std::pair<vtkIdType, vtkIdType>, vtkIdType> otherOutput;
  std::vector<std::pair<vtkIdType, vtkIdType>> sources; // per output point
  auto outputPoint = [&](vtkIdType a, vtkIdType b) {
    const auto next = static_cast<vtkIdType>(sources.size());
    if (firstShaded[a] < 0)
    {
      firstShaded[a] = b;
      firstOutput[a] = next;
    }
    else if (firstShaded[a] != b)
    {
      const auto inserted = otherOutput.emplace(std::make_pair(a, b), next);
      if (!inserted.second)
      {
        return inserted.first->second;
      }
    }
    else
    {
      return firstOutput[a];
    }
    sources.emplace_back(a, b);
    return next;
  };
  vtkNew<vtkCellArray> polys;
  vtkIdType n, m;
  const vtkIdType *a, *b;
  vtkCellArray* splitPolys = split->GetPolys();
  vtkCellArray* shadedPolys = shaded->GetPolys();
  for (vtkIdType f = 0; f < splitPolys->GetNumberOfCells(); ++f)
  {
    splitPolys->GetCellAtId(f, n, a);
    shadedPolys->GetCellAtId(f, m, b);
    polys->InsertNextCell(n);
    for (vtkIdType k = 0; k < n; ++k)
    {
      polys->InsertCellPoint(outputPoint(a[k], b[k]));
    }
  }
  const vtkIdType numPoints = static_cast<vtkIdType>(sources.size());
  vtkNew<vtkPoints> points;
  points->SetDataType(split->GetPoints()->GetDataType());
  points->SetNumberOfPoints(numPoints);
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->GetPointData()->CopyAllocate(split->GetPointData(), numPoints);
  vtkSmartPointer<vtkDataArray> outNormals;
  outNormals.TakeReference(normals->NewInstance());
  outNormals->SetName(normals->GetName());
  outNormals->SetNumberOfComponents(3);
  outNormals->SetNumberOfTuples(numPoints);
  for (vtkIdType p = 0; p < numPoints; ++p)
  {
    points->SetPoint(p, split->GetPoint(sources[p].first));
    out->GetPointData()->CopyData(split->GetPointData(), sources[p].first, p);
    outNormals->SetTuple(p, sources[p].second, normals);
  }
  out->SetPoints(points);
  out->SetPolys(polys);
  out->GetPointData()->SetNormals(outNormals);
  return out;
}
}
