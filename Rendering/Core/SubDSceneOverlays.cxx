#include "SubDSceneOverlays.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkExtractEdges.h"
#include "vtkFloatArray.h"
#include "vtkGlyph3D.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTubeFilter.h"

#include <algorithm>
#include <cmath>

namespace subdrender
{
namespace
{
const double CageColor[3] = { 0.95, 0.75, 0.1 };
const double SelectionColor[3] = { 0.1, 0.95, 1.0 };
const double WireColor[3] = { 0.12, 0.12, 0.16 };

// Sharpness 0+ .. 10 (infinitely sharp) to [0, 1], logarithmically.
double SharpnessParameter(double sharpness)
{
  return std::log1p(std::max(0.0, std::min(10.0, sharpness))) / std::log1p(10.0);
}

// Orange (barely sharp) to magenta (infinitely sharp).
vtkSmartPointer<vtkLookupTable> SharpnessTable()
{
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  table->SetNumberOfTableValues(64);
  table->SetRange(0.0, 1.0);
  for (int i = 0; i < 64; ++i)
  {
    const double t = i / 63.0;
    table->SetTableValue(i, 1.0 - 0.1 * t, 0.55 - 0.35 * t, 0.1 + 0.75 * t, 1.0);
  }
  return table;
}

vtkSmartPointer<vtkPolyDataMapper> SharpnessMapper()
{
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetLookupTable(SharpnessTable());
  mapper->UseLookupTableScalarRangeOn();
  mapper->ScalarVisibilityOn();
  return mapper;
}

// A sphere of `radius` at every point of `points` (carrying their scalars along).
vtkSmartPointer<vtkGlyph3D> SphereGlyphs(vtkPolyData* points, double radius)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(12);
  sphere->SetPhiResolution(8);
  auto glyphs = vtkSmartPointer<vtkGlyph3D>::New();
  glyphs->SetInputData(points);
  glyphs->SetSourceConnection(sphere->GetOutputPort());
  glyphs->ScalingOff();
  glyphs->OrientOff();
  glyphs->SetColorModeToColorByScalar();
  return glyphs;
}

vtkSmartPointer<vtkActor> SphereActor(vtkPolyData* points, double radius, const double color[3])
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(SphereGlyphs(points, radius)->GetOutputPort());
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(color[0], color[1], color[2]);
  return actor;
}

// The cage's corners (vertices with "CornerSharpness" > 0) as spheres coloured by sharpness.
vtkSmartPointer<vtkActor> CornerActor(vtkPolyData* cage, double radius)
{
  vtkDataArray* sharpness = cage->GetPointData()->GetArray("CornerSharpness");
  if (!sharpness)
  {
    return nullptr;
  }
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> parameter;
  for (vtkIdType i = 0; i < sharpness->GetNumberOfTuples() && i < cage->GetNumberOfPoints(); ++i)
  {
    const double s = sharpness->GetComponent(i, 0);
    if (s > 0.0)
    {
      points->InsertNextPoint(cage->GetPoint(i));
      parameter->InsertNextValue(static_cast<float>(SharpnessParameter(s)));
    }
  }
  if (points->GetNumberOfPoints() == 0)
  {
    return nullptr;
  }
  vtkNew<vtkPolyData> corners;
  corners->SetPoints(points);
  corners->GetPointData()->SetScalars(parameter);
  vtkSmartPointer<vtkPolyDataMapper> mapper = SharpnessMapper();
  mapper->SetInputConnection(SphereGlyphs(corners, radius)->GetOutputPort());
  mapper->SetScalarModeToUsePointData();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}
}

vtkSmartPointer<vtkPolyData> PolygonsOf(vtkPolyData* mesh)
{
  auto faces = vtkSmartPointer<vtkPolyData>::New();
  faces->SetPoints(mesh->GetPoints());
  faces->SetPolys(mesh->GetPolys());
  faces->GetPointData()->ShallowCopy(mesh->GetPointData());
  return faces;
}

vtkSmartPointer<vtkPolyData> LinesOf(vtkPolyData* mesh)
{
  auto lines = vtkSmartPointer<vtkPolyData>::New();
  lines->SetPoints(mesh->GetPoints());
  lines->SetLines(mesh->GetLines());
  return lines;
}

vtkSmartPointer<vtkActor> TubeActor(vtkPolyData* lines, double radius, const double color[3])
{
  vtkNew<vtkTubeFilter> tubes;
  tubes->SetInputData(lines);
  tubes->SetRadius(radius);
  tubes->SetNumberOfSides(8);
  tubes->CappingOn();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(tubes->GetOutputPort());
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(color[0], color[1], color[2]);
  return actor;
}

vtkSmartPointer<vtkActor> SharpLinesActor(vtkPolyData* mesh, double radius)
{
  vtkCellArray* lines = mesh->GetLines();
  if (!lines || lines->GetNumberOfCells() == 0)
  {
    return nullptr;
  }
  // Line cell k is cell numVerts + k (VTK orders cells verts, lines, polys, strips).
  const vtkIdType firstLine = mesh->GetNumberOfVerts();
  vtkDataArray* sharpness = mesh->GetCellData()->GetArray("Sharpness");
  vtkNew<vtkCellArray> kept;
  vtkNew<vtkFloatArray> parameter;
  vtkIdType k = 0, size;
  const vtkIdType* ids;
  for (lines->InitTraversal(); lines->GetNextCell(size, ids); ++k)
  {
    const vtkIdType cell = firstLine + k;
    const double s = sharpness && cell < sharpness->GetNumberOfTuples() ? sharpness->GetComponent(cell, 0) : 10.0;
    if (s > 0.0)
    {
      kept->InsertNextCell(size, ids);
      parameter->InsertNextValue(static_cast<float>(SharpnessParameter(s)));
    }
  }
  if (kept->GetNumberOfCells() == 0)
  {
    return nullptr;
  }
  vtkNew<vtkPolyData> sharp;
  sharp->SetPoints(mesh->GetPoints());
  sharp->SetLines(kept);
  sharp->GetCellData()->SetScalars(parameter);
  vtkNew<vtkTubeFilter> tubes;
  tubes->SetInputData(sharp);
  tubes->SetRadius(radius);
  tubes->SetNumberOfSides(8);
  tubes->CappingOn();
  vtkSmartPointer<vtkPolyDataMapper> mapper = SharpnessMapper();
  mapper->SetInputConnection(tubes->GetOutputPort());
  mapper->SetScalarModeToUseCellData();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

namespace
{
vtkMTimeType TimeOf(vtkObject* object)
{
  return object ? object->GetMTime() : 0;
}
}

void CageOverlayCache::AddCage(vtkRenderer* renderer, vtkPolyData* cage, const CageStyle& style)
{
  const bool surfaceCage = cage->GetNumberOfPolys() > 0;
  Key key{ cage, TimeOf(cage->GetPoints()), TimeOf(cage->GetPolys()), surfaceCage ? 0 : TimeOf(cage->GetLines()),
    style.Size };
  if (!(key == this->Built))
  {
    vtkSmartPointer<vtkPolyData> cageEdges = LinesOf(cage);
    if (surfaceCage)
    {
      vtkNew<vtkExtractEdges> edges;
      edges->SetInputData(PolygonsOf(cage));
      edges->Update();
      cageEdges = edges->GetOutput();
    }
    vtkNew<vtkPolyData> points;
    points->SetPoints(cageEdges->GetPoints());
    this->Large = cageEdges->GetNumberOfLines() > LargeCageEdges;
    this->Edges = vtkSmartPointer<vtkPolyDataMapper>::New();
    this->Vertices = vtkSmartPointer<vtkPolyDataMapper>::New();
    if (this->Large)
    {
      this->Edges->SetInputData(cageEdges);
      vtkNew<vtkCellArray> vertexCells;
      for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
      {
        vertexCells->InsertNextCell(1, &i);
      }
      points->SetVerts(vertexCells);
      this->Vertices->SetInputData(points);
    }
    else
    {
      vtkNew<vtkTubeFilter> tubes;
      tubes->SetInputData(cageEdges);
      tubes->SetRadius(0.004 * style.Size);
      tubes->SetNumberOfSides(8);
      tubes->CappingOn();
      this->Edges->SetInputConnection(tubes->GetOutputPort());
      this->Vertices->SetInputConnection(SphereGlyphs(points, 0.012 * style.Size)->GetOutputPort());
    }
    this->Edges->ScalarVisibilityOff();
    this->Vertices->ScalarVisibilityOff();
    this->Built = key;
  }
  vtkNew<vtkActor> edgeActor;
  edgeActor->SetMapper(this->Edges);
  edgeActor->GetProperty()->SetColor(CageColor[0], CageColor[1], CageColor[2]);
  edgeActor->GetProperty()->SetOpacity(style.Opacity);
  vtkNew<vtkActor> vertexActor;
  vertexActor->SetMapper(this->Vertices);
  vertexActor->GetProperty()->SetColor(CageColor[0] * 0.8, CageColor[1] * 0.8, CageColor[2] * 0.8);
  vertexActor->GetProperty()->SetOpacity(style.Opacity);
  if (this->Large)
  {
    edgeActor->GetProperty()->RenderLinesAsTubesOn();
    edgeActor->GetProperty()->SetLineWidth(2.5);
    vertexActor->GetProperty()->RenderPointsAsSpheresOn();
    vertexActor->GetProperty()->SetPointSize(5.0);
  }
  renderer->AddActor(edgeActor);
  renderer->AddActor(vertexActor);
  if (surfaceCage) // a curve's control polygon is its lines: no crease among them
  {
    if (vtkSmartPointer<vtkActor> creases = SharpLinesActor(cage, 0.0065 * style.Size))
    {
      renderer->AddActor(creases);
    }
  }
  if (vtkSmartPointer<vtkActor> corners = CornerActor(cage, 0.02 * style.Size))
  {
    renderer->AddActor(corners);
  }
}

void AddCageSelection(vtkRenderer* renderer, vtkPolyData* cage, vtkIdType a, vtkIdType b, double size)
{
  const vtkIdType n = cage->GetNumberOfPoints();
  if (a < 0 || a >= n || b >= n)
  {
    return;
  }
  if (b >= 0)
  {
    vtkNew<vtkPolyData> edge;
    edge->SetPoints(cage->GetPoints());
    vtkNew<vtkCellArray> line;
    const vtkIdType ids[2] = { a, b };
    line->InsertNextCell(2, ids);
    edge->SetLines(line);
    renderer->AddActor(TubeActor(edge, 0.009 * size, SelectionColor));
    return;
  }
  vtkNew<vtkPoints> point;
  point->InsertNextPoint(cage->GetPoint(a));
  vtkNew<vtkPolyData> vertex;
  vertex->SetPoints(point);
  renderer->AddActor(SphereActor(vertex, 0.024 * size, SelectionColor));
}

vtkSmartPointer<vtkActor> WireframeActor(vtkPolyData* surface)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(PolygonsOf(surface));
  mapper->ScalarVisibilityOff();
  // Drawn slightly in front of the shaded faces they lie on.
  mapper->SetResolveCoincidentTopologyToPolygonOffset();
  mapper->SetRelativeCoincidentTopologyLineOffsetParameters(-1.0, -4.0);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetRepresentationToWireframe();
  actor->GetProperty()->SetColor(WireColor[0], WireColor[1], WireColor[2]);
  actor->GetProperty()->SetLineWidth(1.0);
  actor->GetProperty()->LightingOff();
  return actor;
}
}
