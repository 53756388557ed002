#include "vtkSubDScene.h"

#include "SubDDiscreteCurvature.h"
#include "SubDSceneColoring.h"
#include "SubDSeamShading.h"
#include "SubDSceneOverlays.h"
#include "vtkSubDOffscreenRenderWindow.h"

#include "vtkActor.h"
#include "vtkBoundingBox.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkDataArray.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkImageData.h"
#include "vtkPolyDataMapper.h"
#include "vtkTexture.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkScalarBarActor.h"
#include "vtkSmartPointer.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace
{
const double SurfaceColor[3] = { 0.78, 0.8, 0.86 };
const double Background[3] = { 0.32, 0.34, 0.43 };

struct View
{
  vtkSmartPointer<vtkPolyData> Surface;
  vtkSmartPointer<vtkPolyData> Cage;
  std::string Title;
};

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

// A surface made ready to draw: its polygons with the chosen curvature as active point
// scalars (none for COLOR_NONE) and normals split at 60 degrees, and the curvature values at
// its interior points (for the colour range).
struct PreparedSurface
{
  vtkSmartPointer<vtkPolyData> Mesh;
  std::vector<double> Values;
  // What it was made from: a surface that did not change is not prepared again (a toggle of
  // the cage, the wireframe or the colour map only redraws).
  vtkSmartPointer<vtkPolyData> Source; // held, so that its address is not reused
  vtkMTimeType SourceTime = 0;
  int Coloring = -1;
};

PreparedSurface PrepareSurface(vtkPolyData* surface, int coloring)
{
  PreparedSurface prepared;
  prepared.Source = surface;
  prepared.SourceTime = surface->GetMTime();
  prepared.Coloring = coloring;
  if (surface->GetNumberOfPolys() == 0)
  {
    prepared.Mesh = vtkSmartPointer<vtkPolyData>::New(); // a curve: drawn as tubes (Render)
    return prepared;
  }
  vtkSmartPointer<vtkPolyData> mesh = subdrender::PolygonsOf(surface);
  // Points split at texture seams: normals and curvature of the surface welded, so that no
  // seam shows as a crease.
  const std::vector<vtkIdType> weldOf = subdrender::FirstPointAtSamePosition(mesh);
  vtkSmartPointer<vtkPolyData> whole = weldOf.empty() ? mesh : subdrender::WeldedPolygons(mesh, weldOf);
  const char* name = subdrender::CurvatureArrayName(coloring);
  if (name)
  {
    const subdrender::PolygonAdjacency adjacency(whole);
    vtkDataArray* curvature = mesh->GetPointData()->GetArray(name);
    std::vector<bool> leftOut = adjacency.Boundary; // of the colour range
    if (!curvature)
    {
      // No limit curvature on the surface (ComputeCurvature): the discrete one of the mesh.
      vtkSmartPointer<vtkDoubleArray> discrete = subdrender::DiscreteCurvature(whole, adjacency, coloring);
      for (size_t p = 0; p < weldOf.size(); ++p)
      {
        discrete->SetValue(static_cast<vtkIdType>(p), discrete->GetValue(weldOf[p]));
        leftOut[p] = leftOut[p] || weldOf[p] != static_cast<vtkIdType>(p);
      }
      mesh->GetPointData()->AddArray(discrete);
      whole->GetPointData()->AddArray(discrete);
      curvature = discrete;
    }
    subdrender::AppendInteriorValues(leftOut, curvature, prepared.Values);
  }
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(whole);
  normals->SetFeatureAngle(60.0);
  normals->SplittingOn();
  normals->ConsistencyOff();
  normals->AutoOrientNormalsOff();
  normals->Update();
  prepared.Mesh = weldOf.empty() ? vtkSmartPointer<vtkPolyData>(normals->GetOutput())
                                 : subdrender::SplitAsBoth(mesh, normals->GetOutput());
  if (name)
  {
    prepared.Mesh->GetPointData()->SetActiveScalars(name);
  }
  return prepared;
}

}

class vtkSubDScene::vtkInternals
{
public:
  std::vector<View> Views;
  std::vector<PreparedSurface> Prepared; ///< of the views at the last Render()
  subdrender::CageOverlayCache CageOverlay;
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

namespace
{
const char* const ColoringNames[] = { "none", "mean", "gaussian", "k1", "k2" };
const char* const ColorMapNames[] = { "cool-to-warm", "rainbow", "black-body", "grayscale" };

template <size_t N>
int IndexOfName(const char* const (&names)[N], const char* name)
{
  for (size_t i = 0; name && i < N; ++i)
  {
    if (std::strcmp(names[i], name) == 0)
    {
      return static_cast<int>(i);
    }
  }
  return -1;
}
}

const char* vtkSubDScene::GetColoringAsString()
{
  return GetColoringName(this->Coloring);
}

const char* vtkSubDScene::GetColoringName(int coloring)
{
  return coloring >= COLOR_NONE && coloring <= COLOR_MINIMUM_CURVATURE ? ColoringNames[coloring] : "";
}

int vtkSubDScene::ColoringFromName(const char* name)
{
  return IndexOfName(ColoringNames, name);
}

const char* vtkSubDScene::GetColorMapName(int map)
{
  return map >= COLORMAP_COOL_TO_WARM && map <= COLORMAP_GRAYSCALE ? ColorMapNames[map] : "";
}

int vtkSubDScene::ColorMapFromName(const char* name)
{
  return IndexOfName(ColorMapNames, name);
}

void vtkSubDScene::SetCageSelection(vtkIdType a, vtkIdType b)
{
  if (a < 0)
  {
    a = b = -1;
  }
  if (a != this->CageSelection[0] || b != this->CageSelection[1])
  {
    this->CageSelection[0] = a;
    this->CageSelection[1] = b < 0 ? -1 : b;
    this->Modified();
  }
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

namespace
{
// Prepares the views' surfaces that changed since the last Render() (or whose colouring
// did), and gathers the interior curvature values of all views and the bounds of their
// surfaces and cages.
void PrepareViews(const std::vector<View>& views, int coloring, std::vector<PreparedSurface>& prepared,
  std::vector<double>& values, vtkBoundingBox& box)
{
  prepared.resize(views.size());
  for (size_t k = 0; k < views.size(); ++k)
  {
    const View& view = views[k];
    PreparedSurface& surface = prepared[k];
    if (surface.Source != view.Surface || surface.SourceTime != view.Surface->GetMTime() ||
      surface.Coloring != coloring)
    {
      surface = PrepareSurface(view.Surface, coloring);
    }
    values.insert(values.end(), surface.Values.begin(), surface.Values.end());
    double bounds[6];
    view.Surface->GetBounds(bounds);
    box.AddBounds(bounds);
    if (view.Cage && view.Cage->GetNumberOfPoints() > 0)
    {
      view.Cage->GetBounds(bounds);
      box.AddBounds(bounds);
    }
  }
}

// Places the one camera of all views: looking at the centre of `box` from `azimuth` and
// `elevation` (degrees; at least 70 for a scene of curves only), far enough for the bounding
// sphere to fit a view of the window's grid of `columns` x `rows`.
void PlaceCamera(vtkCamera* camera, const vtkBoundingBox& box, const std::vector<View>& views, double azimuthDegrees,
  double elevationDegrees, vtkRenderWindow* window, int columns, int rows)
{
  const double size = box.IsValid() ? box.GetDiagonalLength() : 1.0;
  double center[3];
  box.GetCenter(center);
  const double azimuth = vtkMath::RadiansFromDegrees(azimuthDegrees);
  // Curves are usually drawn in a plane: a scene of curves only is seen from higher up.
  bool curvesOnly = true;
  for (const View& view : views)
  {
    curvesOnly = curvesOnly && view.Surface->GetNumberOfPolys() == 0;
  }
  const double elevation =
    vtkMath::RadiansFromDegrees(curvesOnly ? std::max(elevationDegrees, 70.0) : elevationDegrees);
  const double direction[3] = { std::cos(elevation) * std::sin(azimuth), -std::cos(elevation) * std::cos(azimuth),
    std::sin(elevation) };
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
  camera->SetPosition(
    center[0] + distance * direction[0], center[1] + distance * direction[1], center[2] + distance * direction[2]);
  camera->SetViewUp(0.0, 0.0, 1.0);
}

// A checker of 8 x 8 squares per unit of texture space, repeated, its squares sharp.
vtkSmartPointer<vtkTexture> CheckerTexture()
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(8, 8, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  for (int j = 0; j < 8; ++j)
  {
    for (int i = 0; i < 8; ++i)
    {
      auto* rgb = static_cast<unsigned char*>(image->GetScalarPointer(i, j, 0));
      const bool light = (i + j) % 2 == 0;
      rgb[0] = light ? 235 : 60;
      rgb[1] = light ? 235 : 90;
      rgb[2] = light ? 225 : 140;
    }
  }
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(image);
  texture->InterpolateOff();
  texture->RepeatOn();
  texture->MipmapOff();
  return texture;
}

// Whether the view of `mesh` shows the checker (ShowTexture and texture coordinates).
bool Textured(vtkPolyData* mesh, bool showTexture)
{
  return showTexture && mesh->GetPointData()->GetTCoords() != nullptr;
}

// The actor of a prepared surface `mesh`: checkered (`textured`), coloured by its active
// scalars through `table`, or plain for COLOR_NONE.
vtkSmartPointer<vtkActor> SurfaceActor(vtkPolyData* mesh, int coloring, vtkLookupTable* table, bool textured)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(mesh);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  if (textured)
  {
    mapper->ScalarVisibilityOff();
    actor->SetTexture(CheckerTexture());
  }
  else if (coloring == vtkSubDScene::COLOR_NONE)
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
  return actor;
}

// A view's title, white at its top left, its font sized for views `viewWidth` pixels wide.
vtkSmartPointer<vtkTextActor> TitleActor(const std::string& text, int viewWidth)
{
  auto title = vtkSmartPointer<vtkTextActor>::New();
  title->SetInput(text.c_str());
  title->GetTextProperty()->SetFontSize(std::max(10, std::min(16, viewWidth / 12)));
  title->GetTextProperty()->SetColor(1.0, 1.0, 1.0);
  title->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  title->GetPositionCoordinate()->SetValue(0.02, 0.98);
  title->GetTextProperty()->SetVerticalJustificationToTop();
  return title;
}

// The horizontal scalar bar of `table` at a view's bottom, titled for `coloring`.
vtkSmartPointer<vtkScalarBarActor> ScalarBarActor(vtkLookupTable* table, int coloring)
{
  auto bar = vtkSmartPointer<vtkScalarBarActor>::New();
  bar->SetLookupTable(table);
  static const char* const titles[] = { "", "Mean curvature", "Gaussian curvature", "Maximum curvature k1",
    "Minimum curvature k2" };
  bar->SetTitle(titles[coloring]);
  bar->SetOrientationToHorizontal();
  bar->SetNumberOfLabels(3);
  bar->SetLabelFormat("%-#6.3g");
  bar->SetPosition(0.2, 0.01);
  bar->SetPosition2(0.6, 0.14);
  bar->UnconstrainedFontSizeOn();
  bar->GetTitleTextProperty()->SetFontSize(13);
  bar->GetLabelTextProperty()->SetFontSize(11);
  return bar;
}
}

// Adds the renderer of view k, cell k of the grid of `columns` x `rows`, to `window`: its
// surface (coloured through `table`) or curve, and the overlays the settings ask for.
void vtkSubDScene::AddViewRenderer(
  vtkRenderWindow* window, int k, int columns, int rows, vtkLookupTable* table, const vtkBoundingBox& box)
{
  const View& view = this->Internals->Views[k];
  const double size = box.IsValid() ? box.GetDiagonalLength() : 1.0;
  vtkSmartPointer<vtkRenderer> renderer = GridRenderer(k, columns, rows);
  renderer->SetActiveCamera(this->Internals->Camera);
  vtkPolyData* prepared = this->Internals->Prepared[k].Mesh;
  const bool textured = Textured(prepared, this->ShowTexture);
  renderer->AddActor(SurfaceActor(prepared, this->Coloring, table, textured));
  if (this->ShowWireframe && view.Surface->GetNumberOfPolys() > 0)
  {
    renderer->AddActor(subdrender::WireframeActor(view.Surface));
  }
  if (this->ShowCage && view.Cage && view.Cage->GetNumberOfPoints() > 0)
  {
    this->Internals->CageOverlay.AddCage(renderer, view.Cage, { size, this->CageOpacity });
  }
  if (view.Cage && this->CageSelection[0] >= 0)
  {
    subdrender::AddCageSelection(renderer, view.Cage, this->CageSelection[0], this->CageSelection[1], size);
  }
  if (view.Surface->GetNumberOfPolys() == 0)
  {
    // A curve: the refined polylines as tubes.
    renderer->AddActor(subdrender::TubeActor(subdrender::LinesOf(view.Surface), 0.008 * size, SurfaceColor));
  }
  else if (this->ShowCreases)
  {
    if (vtkSmartPointer<vtkActor> creases = subdrender::SharpLinesActor(view.Surface, 0.005 * size))
    {
      renderer->AddActor(creases);
    }
  }
  if (!view.Title.empty())
  {
    renderer->AddActor2D(TitleActor(view.Title, this->ViewSize[0]));
  }
  if (this->ShowScalarBar && this->Coloring != COLOR_NONE && view.Surface->GetNumberOfPolys() > 0 && !textured)
  {
    renderer->AddActor2D(ScalarBarActor(table, this->Coloring));
  }
  renderer->ResetCameraClippingRange(box.GetMinPoint()[0], box.GetMaxPoint()[0], box.GetMinPoint()[1],
    box.GetMaxPoint()[1], box.GetMinPoint()[2], box.GetMaxPoint()[2]);
  window->AddRenderer(renderer);
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

  std::vector<double> values; // interior curvature of every view, for one colour scale
  vtkBoundingBox box;
  PrepareViews(views, this->Coloring, this->Internals->Prepared, values, box);
  const std::array<double, 2> range = this->Coloring == COLOR_NONE
    ? std::array<double, 2>{ -1.0, 1.0 }
    : subdrender::ColorRange(values, this->RangeMode == RANGE_SYMMETRIC, this->RangePercentile);
  this->ColorRange[0] = range[0];
  this->ColorRange[1] = range[1];
  vtkSmartPointer<vtkLookupTable> table = subdrender::MakeColorTable(this->ColorMap, range[0], range[1]);
  if (this->AutoResetCamera || !this->Internals->CameraPlaced)
  {
    PlaceCamera(this->Internals->Camera, box, views, this->ViewAzimuth, this->ViewElevation, window, columns, rows);
    this->Internals->CameraPlaced = true;
  }

  for (int k = 0; k < n; ++k)
  {
    this->AddViewRenderer(window, k, columns, rows, table, box);
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
  os << indent << "RangeMode: " << (this->RangeMode == RANGE_SYMMETRIC ? "Symmetric" : "Percentile") << "\n";
  os << indent << "RangePercentile: " << this->RangePercentile << "\n";
  os << indent << "ColorRange: " << this->ColorRange[0] << " " << this->ColorRange[1] << "\n";
  os << indent << "ColorMap: " << GetColorMapName(this->ColorMap) << "\n";
  os << indent << "CageOpacity: " << this->CageOpacity << "\n";
  os << indent << "ShowWireframe: " << (this->ShowWireframe ? "On" : "Off") << "\n";
  os << indent << "ShowTexture: " << (this->ShowTexture ? "On" : "Off") << "\n";
  os << indent << "CageSelection: " << this->CageSelection[0] << " " << this->CageSelection[1] << "\n";
  os << indent << "ViewSize: " << this->ViewSize[0] << " x " << this->ViewSize[1] << "\n";
  os << indent << "ViewAzimuth: " << this->ViewAzimuth << "\n";
  os << indent << "ViewElevation: " << this->ViewElevation << "\n";
  os << indent << "FitWindowToViews: " << (this->FitWindowToViews ? "On" : "Off") << "\n";
  os << indent << "AutoResetCamera: " << (this->AutoResetCamera ? "On" : "Off") << "\n";
}
