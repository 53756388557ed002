#include "vtkSubDScene.h"

#include "vtkSubDOffscreenRenderWindow.h"

#include "vtkActor.h"
#include "vtkBoundingBox.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkColorTransferFunction.h"
#include "vtkCurvatures.h"
#include "vtkDataArray.h"
#include "vtkExtractEdges.h"
#include "vtkGlyph3D.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkScalarBarActor.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkTriangleFilter.h"
#include "vtkTubeFilter.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <map>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace
{
const double CageColor[3] = { 0.95, 0.75, 0.1 };
const double CreaseColor[3] = { 0.9, 0.2, 0.85 };
const double SurfaceColor[3] = { 0.78, 0.8, 0.86 };
const double Background[3] = { 0.32, 0.34, 0.43 };

struct View
{
  vtkSmartPointer<vtkPolyData> Surface;
  vtkSmartPointer<vtkPolyData> Cage;
  std::string Title;
};

// The points and polygons of a mesh (its lines and vertices left out).
vtkSmartPointer<vtkPolyData> PolygonsOf(vtkPolyData* mesh)
{
  auto faces = vtkSmartPointer<vtkPolyData>::New();
  faces->SetPoints(mesh->GetPoints());
  faces->SetPolys(mesh->GetPolys());
  return faces;
}

// The renderer of cell k of a grid of `columns` x `rows` views, filled from the top left.
vtkSmartPointer<vtkRenderer> GridRenderer(int k, int columns, int rows)
{
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  const int column = k % columns, row = k / columns;
  renderer->SetViewport(static_cast<double>(column) / columns, 1.0 - static_cast<double>(row + 1) / rows,
    static_cast<double>(column + 1) / columns, 1.0 - static_cast<double>(row) / rows);
  renderer->SetBackground(Background[0], Background[1], Background[2]);
  return renderer;
}

// |curvature| at the points of a triangle mesh that are not on its boundary (where discrete
// curvature is meaningless: vtkCurvatures' angle deficit there is about pi).
void AppendInteriorMagnitudes(vtkPolyData* triangles, vtkDataArray* curvature, std::vector<double>& magnitudes)
{
  std::map<std::pair<vtkIdType, vtkIdType>, int> edgeUses;
  vtkCellArray* cells = triangles->GetPolys();
  vtkIdType n;
  const vtkIdType* ids;
  for (cells->InitTraversal(); cells->GetNextCell(n, ids);)
  {
    for (vtkIdType k = 0; k < n; ++k)
    {
      const vtkIdType a = ids[k], b = ids[(k + 1) % n];
      ++edgeUses[{ std::min(a, b), std::max(a, b) }];
    }
  }
  std::vector<bool> boundary(static_cast<size_t>(triangles->GetNumberOfPoints()), false);
  for (const auto& edge : edgeUses)
  {
    if (edge.second == 1)
    {
      boundary[edge.first.first] = boundary[edge.first.second] = true;
    }
  }
  for (vtkIdType i = 0; i < curvature->GetNumberOfTuples(); ++i)
  {
    const double value = std::abs(curvature->GetComponent(i, 0));
    if (!boundary[i] && std::isfinite(value))
    {
      magnitudes.push_back(value);
    }
  }
}

// The surface's polygons as triangles, with the chosen curvature as active point scalars
// (none for COLOR_NONE), shaded with normals split at 60 degrees. The interior curvature
// magnitudes are appended to `magnitudes`.
vtkSmartPointer<vtkPolyData> PrepareSurface(vtkPolyData* surface, int coloring, std::vector<double>& magnitudes)
{
  if (surface->GetNumberOfPolys() == 0)
  {
    return vtkSmartPointer<vtkPolyData>::New(); // a curve: drawn as tubes (Render)
  }
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(PolygonsOf(surface));
  triangles->PassLinesOff();
  triangles->PassVertsOff();
  vtkSmartPointer<vtkAlgorithm> last = triangles;
  vtkNew<vtkCurvatures> curvatures;
  const char* name = coloring == vtkSubDScene::COLOR_MEAN_CURVATURE ? "Mean_Curvature" : "Gauss_Curvature";
  triangles->Update();
  vtkDataArray* exact = triangles->GetOutput()->GetPointData()->GetArray(name);
  if (coloring != vtkSubDScene::COLOR_NONE && exact)
  {
    // The surface carries its limit surface's curvature (ComputeCurvature): use it.
    AppendInteriorMagnitudes(triangles->GetOutput(), exact, magnitudes);
  }
  else if (coloring != vtkSubDScene::COLOR_NONE)
  {
    curvatures->SetInputConnection(triangles->GetOutputPort());
    curvatures->SetCurvatureType(
      coloring == vtkSubDScene::COLOR_MEAN_CURVATURE ? VTK_CURVATURE_MEAN : VTK_CURVATURE_GAUSS);
    curvatures->Update();
    AppendInteriorMagnitudes(
      curvatures->GetOutput(), curvatures->GetOutput()->GetPointData()->GetArray(name), magnitudes);
    last = curvatures;
  }
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(last->GetOutputPort());
  normals->SetFeatureAngle(60.0);
  normals->SplittingOn();
  normals->ConsistencyOff();
  normals->AutoOrientNormalsOff();
  normals->Update();
  vtkSmartPointer<vtkPolyData> result = normals->GetOutput();
  if (coloring != vtkSubDScene::COLOR_NONE)
  {
    result->GetPointData()->SetActiveScalars(name);
  }
  return result;
}

// The 95th percentile of the magnitudes: a symmetric range robust to the spikes discrete
// curvature has at corners and creases.
double SymmetricRange(std::vector<double>& magnitudes)
{
  if (magnitudes.empty())
  {
    return 1.0;
  }
  const size_t k = std::min(magnitudes.size() - 1, static_cast<size_t>(0.95 * magnitudes.size()));
  std::nth_element(magnitudes.begin(), magnitudes.begin() + static_cast<std::ptrdiff_t>(k), magnitudes.end());
  return magnitudes[k] > 1e-12 ? magnitudes[k] : 1.0;
}

// Moreland's cool-to-warm map sampled into a table over [-range, range].
vtkSmartPointer<vtkLookupTable> DivergingTable(double range)
{
  vtkNew<vtkColorTransferFunction> map;
  map->SetColorSpaceToDiverging();
  map->AddRGBPoint(-range, 0.230, 0.299, 0.754);
  map->AddRGBPoint(range, 0.706, 0.016, 0.150);
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  table->SetNumberOfTableValues(256);
  table->SetRange(-range, range);
  for (int i = 0; i < 256; ++i)
  {
    double rgb[3];
    map->GetColor(-range + 2.0 * range * i / 255.0, rgb);
    table->SetTableValue(i, rgb[0], rgb[1], rgb[2], 1.0);
  }
  return table;
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

// The points of `mesh` with its lines only.
vtkSmartPointer<vtkPolyData> LinesOf(vtkPolyData* mesh)
{
  auto lines = vtkSmartPointer<vtkPolyData>::New();
  lines->SetPoints(mesh->GetPoints());
  lines->SetLines(mesh->GetLines());
  return lines;
}

// The edges of the cage's polygons (or, for a curve's control polygon, its lines) as tubes,
// and its vertices as spheres.
void AddCage(vtkRenderer* renderer, vtkPolyData* cage, double size)
{
  vtkSmartPointer<vtkPolyData> cageEdges = LinesOf(cage);
  if (cage->GetNumberOfPolys() > 0)
  {
    vtkNew<vtkExtractEdges> edges;
    edges->SetInputData(PolygonsOf(cage));
    edges->Update();
    cageEdges = edges->GetOutput();
  }
  renderer->AddActor(TubeActor(cageEdges, 0.004 * size, CageColor));
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(0.012 * size);
  sphere->SetThetaResolution(12);
  sphere->SetPhiResolution(8);
  vtkNew<vtkPolyData> points;
  points->SetPoints(cageEdges->GetPoints());
  vtkNew<vtkGlyph3D> glyphs;
  glyphs->SetInputData(points);
  glyphs->SetSourceConnection(sphere->GetOutputPort());
  glyphs->ScalingOff();
  glyphs->OrientOff();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(glyphs->GetOutputPort());
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(CageColor[0] * 0.8, CageColor[1] * 0.8, CageColor[2] * 0.8);
  renderer->AddActor(actor);
}
}

class vtkSubDScene::vtkInternals
{
public:
  std::vector<View> Views;
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkNew<vtkCamera> Camera;
  bool CameraPlaced = false;
};

vtkStandardNewMacro(vtkSubDScene);

vtkSubDScene::vtkSubDScene()
  : Internals(new vtkInternals)
{
}

vtkSubDScene::~vtkSubDScene() = default;

void vtkSubDScene::AddView(vtkPolyData* surface, vtkPolyData* cage, const char* title)
{
  if (!surface)
  {
    vtkErrorMacro("AddView needs a surface.");
    return;
  }
  this->Internals->Views.push_back({ surface, cage, title ? title : "" });
  this->Modified();
}

void vtkSubDScene::RemoveAllViews()
{
  this->Internals->Views.clear();
  this->Modified();
}

int vtkSubDScene::GetNumberOfViews() const
{
  return static_cast<int>(this->Internals->Views.size());
}

const char* vtkSubDScene::GetColoringAsString()
{
  static const char* const names[] = { "none", "mean curvature", "Gaussian curvature" };
  return names[this->Coloring];
}

void vtkSubDScene::SetViewSize(int width, int height)
{
  width = std::max(64, std::min(width, 8192));
  height = std::max(64, std::min(height, 8192));
  if (width != this->ViewSize[0] || height != this->ViewSize[1])
  {
    this->ViewSize[0] = width;
    this->ViewSize[1] = height;
    this->Modified();
  }
}

void vtkSubDScene::SetRenderWindow(vtkRenderWindow* window)
{
  this->Internals->Window = window;
  this->Modified();
}

vtkRenderWindow* vtkSubDScene::GetRenderWindow()
{
  if (!this->Internals->Window)
  {
    this->Internals->Window = vtkSmartPointer<vtkSubDOffscreenRenderWindow>::New();
  }
  return this->Internals->Window;
}

bool vtkSubDScene::Render()
{
  const std::vector<View>& views = this->Internals->Views;
  if (views.empty())
  {
    vtkErrorMacro("Nothing to render: add a view first.");
    return false;
  }
  const int n = static_cast<int>(views.size());
  const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  const int rows = (n + columns - 1) / columns;
  vtkRenderWindow* window = this->GetRenderWindow();
  if (this->FitWindowToViews)
  {
    window->SetSize(columns * this->ViewSize[0], rows * this->ViewSize[1]);
  }
  window->GetRenderers()->RemoveAllItems();

  std::vector<vtkSmartPointer<vtkPolyData>> surfaces;
  std::vector<double> magnitudes; // interior |curvature| of every view, for one colour scale
  vtkBoundingBox box;
  for (const View& view : views)
  {
    surfaces.push_back(PrepareSurface(view.Surface, this->Coloring, magnitudes));
    double bounds[6];
    view.Surface->GetBounds(bounds);
    box.AddBounds(bounds);
    if (view.Cage && view.Cage->GetNumberOfPoints() > 0)
    {
      view.Cage->GetBounds(bounds);
      box.AddBounds(bounds);
    }
  }
  const double size = box.IsValid() ? box.GetDiagonalLength() : 1.0;
  const double range = this->Coloring == COLOR_NONE ? 1.0 : SymmetricRange(magnitudes);
  vtkSmartPointer<vtkLookupTable> table = DivergingTable(range);

  // One camera for all views, looking at the centre of the union of the bounds.
  vtkCamera* camera = this->Internals->Camera;
  if (this->AutoResetCamera || !this->Internals->CameraPlaced)
  {
    double center[3];
    box.GetCenter(center);
    const double azimuth = vtkMath::RadiansFromDegrees(this->ViewAzimuth);
    // Curves are usually drawn in a plane: a scene of curves only is seen from higher up.
    bool curvesOnly = true;
    for (const View& view : views)
    {
      curvesOnly = curvesOnly && view.Surface->GetNumberOfPolys() == 0;
    }
    const double elevation =
      vtkMath::RadiansFromDegrees(curvesOnly ? std::max(this->ViewElevation, 70.0) : this->ViewElevation);
    const double direction[3] = { std::cos(elevation) * std::sin(azimuth),
      -std::cos(elevation) * std::cos(azimuth), std::sin(elevation) };
    camera->SetViewAngle(30.0);
    // Fit the bounding sphere into the view angle (vertical), and into the width too when a
    // view is narrower than tall.
    const int* windowSize = window->GetSize();
    const double aspect = windowSize[0] > 0 && windowSize[1] > 0
      ? (static_cast<double>(windowSize[0]) / columns) / (static_cast<double>(windowSize[1]) / rows)
      : 1.0;
    const double distance = 0.5 * (size > 0 ? size : 1.0) / std::sin(vtkMath::RadiansFromDegrees(15.0)) * 1.02 *
      std::max(1.0, 1.0 / aspect);
    camera->SetFocalPoint(center);
    camera->SetPosition(center[0] + distance * direction[0], center[1] + distance * direction[1],
      center[2] + distance * direction[2]);
    camera->SetViewUp(0.0, 0.0, 1.0);
    this->Internals->CameraPlaced = true;
  }

  for (int k = 0; k < n; ++k)
  {
    const View& view = views[k];
    vtkSmartPointer<vtkRenderer> renderer = GridRenderer(k, columns, rows);
    renderer->SetActiveCamera(camera);

    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(surfaces[k]);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    if (this->Coloring == COLOR_NONE)
    {
      mapper->ScalarVisibilityOff();
      actor->GetProperty()->SetColor(SurfaceColor[0], SurfaceColor[1], SurfaceColor[2]);
    }
    else
    {
      mapper->ScalarVisibilityOn();
      mapper->SetLookupTable(table);
      mapper->UseLookupTableScalarRangeOn();
      mapper->SetScalarModeToUsePointData();
    }
    actor->GetProperty()->SetSpecular(0.2);
    actor->GetProperty()->SetSpecularPower(20.0);
    renderer->AddActor(actor);

    if (this->ShowCage && view.Cage && view.Cage->GetNumberOfPoints() > 0)
    {
      AddCage(renderer, view.Cage, size);
    }
    if (view.Surface->GetNumberOfPolys() == 0)
    {
      // A curve: the refined polylines as tubes.
      renderer->AddActor(TubeActor(LinesOf(view.Surface), 0.008 * size, SurfaceColor));
    }
    else if (this->ShowCreases && view.Surface->GetNumberOfLines() > 0)
    {
      renderer->AddActor(TubeActor(LinesOf(view.Surface), 0.005 * size, CreaseColor));
    }
    if (!view.Title.empty())
    {
      vtkNew<vtkTextActor> title;
      title->SetInput(view.Title.c_str());
      title->GetTextProperty()->SetFontSize(std::max(10, std::min(16, this->ViewSize[0] / 12)));
      title->GetTextProperty()->SetColor(1.0, 1.0, 1.0);
      title->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
      title->GetPositionCoordinate()->SetValue(0.02, 0.98);
      title->GetTextProperty()->SetVerticalJustificationToTop();
      renderer->AddActor2D(title);
    }
    if (this->ShowScalarBar && this->Coloring != COLOR_NONE && view.Surface->GetNumberOfPolys() > 0)
    {
      vtkNew<vtkScalarBarActor> bar;
      bar->SetLookupTable(table);
      bar->SetTitle(this->Coloring == COLOR_MEAN_CURVATURE ? "Mean curvature" : "Gaussian curvature");
      bar->SetOrientationToHorizontal();
      bar->SetNumberOfLabels(3);
      bar->SetLabelFormat("%-#6.3g");
      bar->SetPosition(0.2, 0.01);
      bar->SetPosition2(0.6, 0.14);
      bar->UnconstrainedFontSizeOn();
      bar->GetTitleTextProperty()->SetFontSize(13);
      bar->GetLabelTextProperty()->SetFontSize(11);
      renderer->AddActor2D(bar);
    }
    renderer->ResetCameraClippingRange(box.GetMinPoint()[0], box.GetMaxPoint()[0], box.GetMinPoint()[1],
      box.GetMaxPoint()[1], box.GetMinPoint()[2], box.GetMaxPoint()[2]);
    window->AddRenderer(renderer);
  }
  for (int k = n; k < rows * columns; ++k) // empty cells of the grid
  {
    window->AddRenderer(GridRenderer(k, columns, rows));
  }
  window->Render();
  if (auto* offscreen = vtkSubDOffscreenRenderWindow::SafeDownCast(window))
  {
    if (std::string(offscreen->GetBackendInUse()) == "none")
    {
      return false; // the window reported why
    }
  }
  return true;
}

vtkCamera* vtkSubDScene::GetCamera()
{
  return this->Internals->Camera;
}

void vtkSubDScene::ResetCamera()
{
  this->Internals->CameraPlaced = false;
  this->Modified();
}

bool vtkSubDScene::WritePNG(const char* fileName)
{
  if (!fileName || !*fileName)
  {
    vtkErrorMacro("WritePNG needs a file name.");
    return false;
  }
  {
    std::ofstream probe(fileName, std::ios::binary); // fail early, before rendering
    if (!probe)
    {
      vtkErrorMacro(<< "Cannot open '" << fileName << "' for writing: " << std::strerror(errno) << ".");
      return false;
    }
  }
  if (!this->Render())
  {
    return false;
  }
  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(this->GetRenderWindow());
  capture->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(capture->GetOutputPort());
  writer->SetFileName(fileName);
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    vtkErrorMacro(<< "Cannot write the image to '" << fileName << "'.");
    return false;
  }
  return true;
}

void vtkSubDScene::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Views: " << this->Internals->Views.size() << "\n";
  os << indent << "Coloring: " << this->GetColoringAsString() << "\n";
  os << indent << "ShowCage: " << (this->ShowCage ? "On" : "Off") << "\n";
  os << indent << "ShowCreases: " << (this->ShowCreases ? "On" : "Off") << "\n";
  os << indent << "ShowScalarBar: " << (this->ShowScalarBar ? "On" : "Off") << "\n";
  os << indent << "ViewSize: " << this->ViewSize[0] << " x " << this->ViewSize[1] << "\n";
  os << indent << "ViewAzimuth: " << this->ViewAzimuth << "\n";
  os << indent << "ViewElevation: " << this->ViewElevation << "\n";
  os << indent << "FitWindowToViews: " << (this->FitWindowToViews ? "On" : "Off") << "\n";
  os << indent << "AutoResetCamera: " << (this->AutoResetCamera ? "On" : "Off") << "\n";
}
