// Helpers shared by the filter tests: message capture and test meshes as vtkPolyData.
#ifndef SubDFilterTestSupport_h
#define SubDFilterTestSupport_h

#include "SubDOracleSupport.h"
#include "SubDTestMeshes.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkFeatureEdges.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace subdtest
{
// Records error and warning messages of an algorithm.
struct Messages
{
  std::string Errors, Warnings;
  int NumErrors = 0, NumWarnings = 0;
  void Watch(vtkObject* object)
  {
    vtkNew<vtkCallbackCommand> cb;
    cb->SetClientData(this);
    cb->SetCallback([](vtkObject*, unsigned long event, void* client, void* data) {
      auto* self = static_cast<Messages*>(client);
      const std::string text = data ? static_cast<const char*>(data) : "";
      if (event == vtkCommand::ErrorEvent)
      {
        self->Errors += text;
        ++self->NumErrors;
      }
      else
      {
        self->Warnings += text;
        ++self->NumWarnings;
      }
    });
    object->AddObserver(vtkCommand::ErrorEvent, cb);
    object->AddObserver(vtkCommand::WarningEvent, cb);
  }
};

/// A fixture mesh as vtkPolyData (double points, one polygon per face).
inline vtkSmartPointer<vtkPolyData> ToPolyData(const TestMesh& mesh)
{
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (subd::Index v = 0; v < mesh.NumVertices(); ++v)
    points->InsertNextPoint(&mesh.Points[3 * v]);
  vtkNew<vtkCellArray> polys;
  for (subd::Index f = 0; f < mesh.NumFaces(); ++f)
  {
    polys->InsertNextCell(mesh.Offsets[f + 1] - mesh.Offsets[f]);
    for (subd::Index k = mesh.Offsets[f]; k < mesh.Offsets[f + 1]; ++k)
      polys->InsertCellPoint(mesh.Vertices[k]);
  }
  poly->SetPoints(points);
  poly->SetPolys(polys);
  return poly;
}

// The points of a mesh as xyz triples.
inline std::vector<double> Coordinates(vtkPolyData* mesh)
{
  std::vector<double> xyz(static_cast<size_t>(mesh->GetNumberOfPoints()) * 3);
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    mesh->GetPoint(i, &xyz[3 * static_cast<size_t>(i)]);
  return xyz;
}

// The polygons of a mesh, each as its point ids, in order.
inline std::vector<std::vector<vtkIdType>> Faces(vtkPolyData* mesh)
{
  std::vector<std::vector<vtkIdType>> faces;
  vtkIdType size = 0;
  const vtkIdType* ids = nullptr;
  auto polys = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    polys->GetCurrentCell(size, ids);
    faces.emplace_back(ids, ids + size);
  }
  return faces;
}

// The max-norm distance from p to the nearest point of `mesh`.
inline double DistanceToNearestPoint(vtkPolyData* mesh, const double p[3])
{
  double distance;
  NearestPoint(Coordinates(mesh), p, distance);
  return distance;
}

// The largest coordinate difference between the i-th points of two point lists (3 values
// each); infinite when they differ in length.
inline double LargestPointwiseDifference(const std::vector<double>& a, const std::vector<double>& b)
{
  if (a.size() != b.size())
  {
    return std::numeric_limits<double>::infinity();
  }
  double worst = 0.0;
  for (size_t k = 0; k < a.size(); ++k)
  {
    worst = std::max(worst, std::abs(a[k] - b[k]));
  }
  return worst;
}

// The largest max-norm distance from a point of `a` to its nearest point of `b`: 0 when
// every point of `a` is a point of `b`.
inline double LargestDistanceToNearestPoint(vtkPolyData* a, vtkPolyData* b)
{
  const std::vector<double> ours = Coordinates(b);
  double worst = 0.0;
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    double p[3], distance;
    a->GetPoint(i, p);
    NearestPoint(ours, p, distance);
    worst = std::max(worst, distance);
  }
  return worst;
}

// Adds crease lines (one 2-point line per pair) with a "Sharpness" array (unless empty).
inline void AddCreases(vtkPolyData* mesh, const std::vector<std::array<vtkIdType, 2>>& edges,
  const std::vector<float>& sharpness)
{
  vtkNew<vtkCellArray> lines;
  for (const auto& e : edges)
    lines->InsertNextCell(2, e.data());
  mesh->SetLines(lines);
  if (!sharpness.empty())
  {
    vtkNew<vtkFloatArray> s;
    s->SetName("Sharpness");
    s->SetNumberOfTuples(mesh->GetNumberOfCells());
    s->Fill(0.0);
    for (size_t i = 0; i < sharpness.size(); ++i)
      s->SetValue(static_cast<vtkIdType>(i), sharpness[i]); // lines come first in cell order
    mesh->GetCellData()->AddArray(s);
  }
}

inline void AddCornerSharpness(vtkPolyData* mesh, const std::map<vtkIdType, float>& corners)
{
  vtkNew<vtkFloatArray> s;
  s->SetName("CornerSharpness");
  s->SetNumberOfTuples(mesh->GetNumberOfPoints());
  s->Fill(0.0);
  for (const auto& c : corners)
    s->SetValue(c.first, c.second);
  mesh->GetPointData()->AddArray(s);
}

// The edges of `mesh` used by one polygon only or by more than two: 0 for a watertight surface.
inline vtkIdType OpenOrNonManifoldEdges(vtkPolyData* mesh)
{
  vtkNew<vtkFeatureEdges> edges;
  edges->SetInputData(mesh);
  edges->BoundaryEdgesOn();
  edges->NonManifoldEdgesOn();
  edges->FeatureEdgesOff();
  edges->ManifoldEdgesOff();
  edges->Update();
  return edges->GetOutput()->GetNumberOfCells();
}
}

#endif
