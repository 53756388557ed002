/**
 * @class   vtkSubDScene
 * @brief   SubD's standard picture of one or more subdivided surfaces, rendered offscreen
 *
 * Each view shows a surface coloured by a curvature (mean, Gaussian, or the principal
 * curvatures k1 >= k2): the exact curvature of the limit surface when the surface carries it
 * ("Mean_Curvature", "Gauss_Curvature", "Maximum_Curvature", "Minimum_Curvature" point data,
 * as SubD's filters make with ComputeCurvature), else the discrete curvature of the refined
 * mesh (angle deficits and dihedral angles, vtkCurvatures' definitions, computed on flat
 * arrays several times faster). The colours span one range for all views
 * (so that views are comparable), taken over the interior points (boundary points, where
 * discrete curvature means nothing, are left out) as a percentile, not the extremes, so that
 * spikes at corners do not wash out the picture: symmetric about zero (RangeMode Symmetric,
 * the default), or the central RangePercentile percent of the values (Percentile). The colour
 * map is Moreland's diverging cool-to-warm (K. Moreland, "Diverging Color Maps for Scientific
 * Visualization", ISVC 2009) by default, or a rainbow, black-body or grey ramp; a scalar bar
 * shows it.
 *
 * Overlays: the control cage (edges as tubes and vertices as spheres, in gold, with
 * CageOpacity), its crease edges ("Sharpness" line cells) and corners ("CornerSharpness")
 * coloured by sharpness from orange (barely semi-sharp) to magenta (infinitely sharp); the
 * surface's own crease lines (its line cells, as SubD's filters output them, with their
 * decayed sharpness) in the same colours; optionally the refined mesh's edges (ShowWireframe);
 * optionally a checker texture on surfaces with texture coordinates (ShowTexture);
 * and a selected cage edge or vertex in cyan (the explorer's crease editing). Shading uses
 * point normals split at 60 degrees, so sharp creases look sharp.
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
 * Exact and discrete curvature share vtkCurvatures' sign convention (a convex closed surface
 * is positive).
 */
#ifndef vtkSubDScene_h
#define vtkSubDScene_h

#include "SubDRenderingModule.h" // for export macro
#include "vtkObject.h"

#include <memory> // for std::unique_ptr

class vtkBoundingBox;
class vtkCamera;
class vtkLookupTable;
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
    COLOR_GAUSSIAN_CURVATURE = 2,
    COLOR_MAXIMUM_CURVATURE = 3, ///< k1, the larger principal curvature
    COLOR_MINIMUM_CURVATURE = 4  ///< k2, the smaller one
  };

  ///@{
  /**
   * What colours the surfaces (default COLOR_MEAN_CURVATURE). The short names "none",
   * "mean", "gaussian", "k1" and "k2" are what `subd --color` and the explorer take:
   * ColoringFromName returns -1 for any other.
   */
  vtkSetClampMacro(Coloring, int, COLOR_NONE, COLOR_MINIMUM_CURVATURE);
  vtkGetMacro(Coloring, int);
  void SetColoringToNone() { this->SetColoring(COLOR_NONE); }
  void SetColoringToMeanCurvature() { this->SetColoring(COLOR_MEAN_CURVATURE); }
  void SetColoringToGaussianCurvature() { this->SetColoring(COLOR_GAUSSIAN_CURVATURE); }
  void SetColoringToMaximumCurvature() { this->SetColoring(COLOR_MAXIMUM_CURVATURE); }
  void SetColoringToMinimumCurvature() { this->SetColoring(COLOR_MINIMUM_CURVATURE); }
  const char* GetColoringAsString();
  static const char* GetColoringName(int coloring);
  static int ColoringFromName(const char* name);
  ///@}

  enum RangeModes
  {
    RANGE_SYMMETRIC = 0, ///< [-m, m], m the RangePercentile-th percentile of |curvature|
    RANGE_PERCENTILE = 1 ///< the central RangePercentile percent of the values
  };

  ///@{
  /**
   * The range the colours span (default RANGE_SYMMETRIC, RangePercentile 95, in [50, 100];
   * 100 takes the extremes).
   */
  vtkSetClampMacro(RangeMode, int, RANGE_SYMMETRIC, RANGE_PERCENTILE);
  vtkGetMacro(RangeMode, int);
  void SetRangeModeToSymmetric() { this->SetRangeMode(RANGE_SYMMETRIC); }
  void SetRangeModeToPercentile() { this->SetRangeMode(RANGE_PERCENTILE); }
  vtkSetClampMacro(RangePercentile, double, 50.0, 100.0);
  vtkGetMacro(RangePercentile, double);
  ///@}

  /**
   * The range the colours spanned at the last Render() ([-1, 1] before, or without colouring).
   */
  vtkGetVector2Macro(ColorRange, double);

  enum ColorMaps
  {
    COLORMAP_COOL_TO_WARM = 0,
    COLORMAP_RAINBOW = 1,
    COLORMAP_BLACK_BODY = 2,
    COLORMAP_GRAYSCALE = 3
  };

  ///@{
  /**
   * The colour map (default COLORMAP_COOL_TO_WARM). Short names: "cool-to-warm", "rainbow",
   * "black-body", "grayscale" (ColorMapFromName returns -1 for any other).
   */
  vtkSetClampMacro(ColorMap, int, COLORMAP_COOL_TO_WARM, COLORMAP_GRAYSCALE);
  vtkGetMacro(ColorMap, int);
  static const char* GetColorMapName(int map);
  static int ColorMapFromName(const char* name);
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
   * Opacity of the cage's edges and vertices, in [0, 1] (default 1); its creases and corners
   * stay opaque.
   */
  vtkSetClampMacro(CageOpacity, double, 0.0, 1.0);
  vtkGetMacro(CageOpacity, double);
  ///@}

  ///@{
  /**
   * Draw the edges of the refined surface's polygons (default off).
   */
  vtkSetMacro(ShowWireframe, bool);
  vtkGetMacro(ShowWireframe, bool);
  vtkBooleanMacro(ShowWireframe, bool);
  ///@}

  ///@{
  /**
   * Draw surfaces that have texture coordinates (TCoords) with a checker texture instead of
   * their colouring (default off): 8 x 8 squares per unit of texture space, so that a seam
   * whose two sides disagree, or a stretched or folded map, shows at a glance. Surfaces
   * without texture coordinates keep their colouring.
   */
  vtkSetMacro(ShowTexture, bool);
  vtkGetMacro(ShowTexture, bool);
  vtkBooleanMacro(ShowTexture, bool);
  ///@}

  ///@{
  /**
   * Mark the cage edge (a, b), or the cage vertex a when b < 0, in every view; a < 0 marks
   * nothing (the default).
   */
  void SetCageSelection(vtkIdType a, vtkIdType b);
  vtkIdType GetCageSelectionA() const { return this->CageSelection[0]; }
  vtkIdType GetCageSelectionB() const { return this->CageSelection[1]; }
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
  int RangeMode = RANGE_SYMMETRIC;
  double RangePercentile = 95.0;
  double ColorRange[2] = { -1.0, 1.0 };
  int ColorMap = COLORMAP_COOL_TO_WARM;
  double CageOpacity = 1.0;
  bool ShowWireframe = false;
  bool ShowTexture = false;
  vtkIdType CageSelection[2] = { -1, -1 };
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

  // Render()'s step for view k: its renderer, in cell k of the grid, added to `window`.
  void AddViewRenderer(
    vtkRenderWindow* window, int k, int columns, int rows, vtkLookupTable* table, const vtkBoundingBox& box);
};

#endif
