#include "SubDSeamShading.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"

#include <array>
#include <map>
#include <utility>

namespace subdrender
{
std::vector<vtkIdType> FirstPointAtSamePosition(vtkPolyData* mesh)
{
  const vtkIdType n = mesh->GetNumberOfPoints();
  std::map<std::array<double, 3>, vtkIdType> first;
  std::vector<vtkIdType> weldOf(static_cast<size_t>(n));
  bool any = false;
  for (vtkIdType p = 0; p < n; ++p)
  {
    std::array<double, 3> x;
    mesh->GetPoint(p, x.data());
    weldOf[p] = first.emplace(x, p).first->second;
    any = any || weldOf[p] != p;
  }
  return any ? weldOf : std::vector<vtkIdType>();
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
  std::map<std::pair<vtkIdType, vtkIdType>, vtkIdType> pointOf;
  std::vector<std::pair<vtkIdType, vtkIdType>> sources;
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
      const auto key = std::make_pair(a[k], b[k]);
      const auto inserted = pointOf.emplace(key, static_cast<vtkIdType>(sources.size()));
      if (inserted.second)
      {
        sources.push_back(key);
      }
      polys->InsertCellPoint(inserted.first->second);
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
