/**
 * @class   vtkSubDScene
 * @brief   SubD's standard picture of one or more subdivided surfaces, rendered offscreen
 *
 * Each view shows a surface, coloured by its curvature (mean or Gaussian): the exact
 * curvature of the limit surface when the surface carries it ("Mean_Curvature" /
 * "Gauss_Curvature" point data, as SubD's filters make with ComputeCurvature), else its
 * discrete curvature (vtkCurvatures on the triangulated surface), with a diverging cool-to-warm colour map
 * (K. Moreland, "Diverging Color Maps for Scientific Visualization", ISVC 2009) over a
 * symmetric range (the 95th percentile of |curvature| over the interior points of all views,
 * so that views are comparable; boundary points, where discrete curvature means nothing,
 * and spikes at corners do not wash out the picture) and a scalar bar; its
 * control cage overlaid (edges as tubes and vertices as spheres, in gold); and the crease
 * lines of the surface (its line cells, as the SubD filters output them) in magenta. Shading
 * uses point normals split at 60 degrees, so sharp creases look sharp.
 *
 * A view whose "surface" has no polygons is a curve (vtkSubDCurveFilter's output): its lines
 * are drawn as tubes in the surface colour, with its control polygon (the cage's lines)
 * overlaid as for a cage; curves have no curvature colouring.
 *
 * Several views are laid out in a grid (as square as possible, in the order added), all
 * seen through one camera fitted to the union of their bounds from a fixed direction
 * (ViewAzimuth, ViewElevation), so a comparison shows each surface at the same scale. The
 * window size is the grid size times ViewSize. Rendering happens in a
 * vtkSubDOffscreenRenderWindow (no display server needed) unless another window is set.
 *
 * Both curvatures share vtkCurvatures' sign convention (a convex closed surface is positive).
 */
#ifndef vtkSubDScene_h
#define vtkSubDScene_h

#include "SubDRenderingModule.h" // for export macro
#include "vtkObject.h"

#include <memory> // for std::unique_ptr

class vtkCamera;
class vtkPolyData;
class vtkRenderWindow;

class SUBDRENDERING_EXPORT vtkSubDScene : public vtkObject
{
public:
  static vtkSubDScene* New();
  vtkTypeMacro(vtkSubDScene, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Adds a view of `surface` with its control `cage` (may be null) and a title (may be null).
   * The data are referenced, not copied.
   */
  void AddView(vtkPolyData* surface, vtkPolyData* cage, const char* title);
  void RemoveAllViews();
  int GetNumberOfViews() const;

  enum Colorings
  {
    COLOR_NONE = 0,
    COLOR_MEAN_CURVATURE = 1,
    COLOR_GAUSSIAN_CURVATURE = 2
  };

  ///@{
  /**
   * What colours the surfaces (default COLOR_MEAN_CURVATURE).
   */
  vtkSetClampMacro(Coloring, int, COLOR_NONE, COLOR_GAUSSIAN_CURVATURE);
  vtkGetMacro(Coloring, int);
  void SetColoringToNone() { this->SetColoring(COLOR_NONE); }
  void SetColoringToMeanCurvature() { this->SetColoring(COLOR_MEAN_CURVATURE); }
  void SetColoringToGaussianCurvature() { this->SetColoring(COLOR_GAUSSIAN_CURVATURE); }
  const char* GetColoringAsString();
  ///@}

  ///@{
  /**
   * Overlays: the control cage, the crease lines, the scalar bar (all on by default).
   */
  vtkSetMacro(ShowCage, bool);
  vtkGetMacro(ShowCage, bool);
  vtkBooleanMacro(ShowCage, bool);
  vtkSetMacro(ShowCreases, bool);
  vtkGetMacro(ShowCreases, bool);
  vtkBooleanMacro(ShowCreases, bool);
  vtkSetMacro(ShowScalarBar, bool);
  vtkGetMacro(ShowScalarBar, bool);
  vtkBooleanMacro(ShowScalarBar, bool);
  ///@}

  ///@{
  /**
   * Size in pixels of each view (default 400 x 400, at least 64 x 64).
   */
  void SetViewSize(int width, int height);
  void SetViewSize(const int size[2]) { this->SetViewSize(size[0], size[1]); }
  vtkGetVector2Macro(ViewSize, int);
  ///@}

  ///@{
  /**
   * Direction the camera looks from, in degrees around +z and above the xy plane (default
   * 30 and 25). A scene whose views are all curves is seen from at least 70 degrees up.
   */
  vtkSetClampMacro(ViewAzimuth, double, -360.0, 360.0);
  vtkGetMacro(ViewAzimuth, double);
  vtkSetClampMacro(ViewElevation, double, -89.0, 89.0);
  vtkGetMacro(ViewElevation, double);
  ///@}

  ///@{
  /**
   * The window to render into. Default: a vtkSubDOffscreenRenderWindow made at the first
   * Render().
   */
  void SetRenderWindow(vtkRenderWindow* window);
  vtkRenderWindow* GetRenderWindow();
  ///@}

  ///@{
  /**
   * For interactive use (the explorer): when off, Render() leaves the window's size alone
   * (default on: the window becomes the grid size times ViewSize).
   */
  vtkSetMacro(FitWindowToViews, bool);
  vtkGetMacro(FitWindowToViews, bool);
  vtkBooleanMacro(FitWindowToViews, bool);
  ///@}

  ///@{
  /**
   * The one camera of all views. Render() places it (fitted to the views, from ViewAzimuth
   * and ViewElevation) at the first render and after ResetCamera(), and on every render
   * while AutoResetCamera is on (the default); with it off, a camera the user moved stays.
   */
  vtkCamera* GetCamera();
  void ResetCamera();
  vtkSetMacro(AutoResetCamera, bool);
  vtkGetMacro(AutoResetCamera, bool);
  vtkBooleanMacro(AutoResetCamera, bool);
  ///@}

  /**
   * Builds the scene and renders it. Returns false (with an error) if there is no view or
   * no OpenGL context.
   */
  bool Render();

  /**
   * Render() and write the window's pixels to a PNG file. Returns false with an error on
   * failure.
   */
  bool WritePNG(const char* fileName);

protected:
  vtkSubDScene();
  ~vtkSubDScene() override;

  int Coloring = COLOR_MEAN_CURVATURE;
  bool ShowCage = true;
  bool ShowCreases = true;
  bool ShowScalarBar = true;
  int ViewSize[2] = { 400, 400 };
  double ViewAzimuth = 30.0;
  double ViewElevation = 25.0;
  bool FitWindowToViews = true;
  bool AutoResetCamera = true;

private:
  vtkSubDScene(const vtkSubDScene&) = delete;
  void operator=(const vtkSubDScene&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
