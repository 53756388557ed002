// SubD Explorer: the main window. One cage, 1, 2 or 4 views of it subdivided by different
// schemes, drawn by vtkSubDScene into one VTK widget (so the views share one camera), with
// the controls around it.
#ifndef SubDExplorerWindow_h
#define SubDExplorerWindow_h

#include "SubDUpdateJob.h"

#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <QMainWindow>
#include <QString>

#include <array>
#include <memory>
#include <string>

class QCheckBox;
class QComboBox;
class QDragEnterEvent;
class QDropEvent;
class QDoubleSpinBox;
class QGroupBox;
class QLabel;
class QProgressBar;
class QSettings;
class QSpinBox;
class QPushButton;
class QTimer;
class QSlider;
class QVTKOpenGLNativeWidget;
class vtkGenericOpenGLRenderWindow;
class vtkPolyData;
class vtkSubDScene;

namespace subdexplorer
{
class ExplorerWindow : public QMainWindow
{
  Q_OBJECT

public:
  static constexpr int MaxViews = 4;

  explicit ExplorerWindow(QWidget* parent = nullptr);
  ~ExplorerWindow() override;

  /// Opens a mesh file (any format `subd` reads); false with the reason on failure.
  bool LoadFile(const QString& path, QString& error);
  /// Shows a built-in cage or curve (SubDBuiltinCages.h).
  void LoadBuiltin(const std::string& name);

  vtkPolyData* GetCage() const;
  void SetViewCount(int count); ///< 1, 2 or 4
  void SetScheme(int view, const std::string& scheme);
  void SetLevels(int levels);
  /// Catmull-Clark and Loop views tessellate their limit surface within this fraction of the
  /// cage's diagonal (0: they refine, as the other schemes).
  void SetTolerance(double tolerance);
  double GetTolerance() const;
  void SetColoring(const std::string& coloring); ///< none, mean, gaussian, k1, k2
  void SetColorMap(const std::string& map);      ///< cool-to-warm, rainbow, black-body, grayscale
  /// Symmetric about zero, or the central `percentile` percent of the values (vtkSubDScene).
  void SetColorRange(bool symmetric, double percentile);
  void SetShowCage(bool show);
  void SetCageOpacity(double opacity); ///< in [0, 1]
  void SetShowWireframe(bool show);
  void SetShowTexture(bool show); ///< the checker on surfaces with texture coordinates
  void SetFaceVaryingInterpolation(int mode); ///< every view's
  void SetLimit(bool limit); ///< every view's Limit box

  /// Reads the layout (views, schemes and their options, level, colouring, overlays, window
  /// geometry) and recent files from `settings`, and writes them there from now on; with
  /// null, nothing is read or written (--no-settings).
  void UseSettings(std::unique_ptr<QSettings> settings);
  /// Writes the layout to the settings (at exit).
  void SaveSettings();
  /// One line per setting ("views 2", "scheme 1 loop", ...): what --print-state shows.
  std::string DescribeState() const;

  /// Brings every view up to date and renders (what the controls call). The subdivision
  /// runs on a worker thread (UpdateJob); a change while it runs restarts it.
  void UpdateViews();
  /// Stops the running update (the Cancel button, Esc); the views keep their last result.
  void CancelUpdate();
  bool IsUpdating() const { return this->Job != nullptr; }
  /// Processes events until no update runs (scripts: before screenshots and exports).
  void WaitForUpdate();
  /// Whether the last update that ended was cancelled.
  bool WasLastUpdateCancelled() const { return this->LastUpdateCancelled; }
  /// The views' pixels (the VTK widget) as a PNG.
  bool SaveViewsImage(const QString& path, QString& error);
  /// The whole window, controls included, as a PNG.
  bool SaveWindowImage(const QString& path, QString& error);
  /// Writes view `view`'s subdivided surface (any format `subd` writes).
  bool ExportSurface(int view, const QString& path, QString& error);
  /// Writes the cage with its creases and corners (.vtp, .vtk keep them as data, .obj as tags).
  bool ExportCage(const QString& path, QString& error);

  /// Sets the sharpness of cage edge (a, b), or of vertex a when b < 0, and updates the
  /// views: what the Sharpness spin box does (SubDCageEditing.h).
  bool SetSharpness(vtkIdType a, vtkIdType b, double sharpness, QString& error);
  /// Selects the cage edge or vertex nearest to display position (x, y) in the view there
  /// (Ctrl+click); false when none is close enough.
  bool SelectCageElementAt(int x, int y);
  /// Selects cage edge (a, b), or vertex a when b < 0 (a < 0: nothing): the Creases panel
  /// then edits it, and the views mark it.
  bool SelectCageElement(vtkIdType a, vtkIdType b);

  /// Timing of the last completed update, in milliseconds: the subdivision (worker thread,
  /// the views that had to be recomputed) and the scene (colouring, overlays, rendering).
  double GetLastSubdivisionMilliseconds() const { return this->LastSubdivisionMs; }
  double GetLastSceneMilliseconds() const { return this->LastSceneMs; }

protected:
  /// Dropping a mesh file on the window opens it.
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

private:
  struct ViewControls
  {
    QGroupBox* Box = nullptr;
    QComboBox* Scheme = nullptr;
    QComboBox* Boundary = nullptr;
    QDoubleSpinBox* Tension = nullptr;
    QComboBox* CreaseMethod = nullptr;
    QComboBox* FaceVarying = nullptr; ///< how texture coordinates are refined
    QCheckBox* Limit = nullptr;
    QLabel* Statistics = nullptr;
    vtkSmartPointer<vtkPolyData> Result;
    /// What Result was made from: a view whose scheme, options and cage are unchanged is
    /// not recomputed (colouring and overlays only redraw).
    bool HasResult = false;
    std::string ResultScheme;
    subdapp::SchemeOptions ResultOptions;
    unsigned long ResultCageRevision = 0;
  };

  void BuildMenus();
  /// The control panel: the groups below, connected, for one view.
  QWidget* BuildControls();
  /// The "All views" group: cage, layout, level, colouring, range and overlay controls.
  QGroupBox* BuildGlobalControls();
  /// The "Creases" group: the selected cage element and its sharpness (connected).
  QGroupBox* BuildCreaseControls();
  /// The group of view v: scheme, boundary, tension, crease method, limit, statistics.
  QGroupBox* BuildViewControls(int v);
  /// Connects view v's controls to the updates they trigger.
  void ConnectViewControls(int v);
  /// Connects the "All views" controls to the updates they trigger.
  void ConnectGlobalControls();
  void SetCage(vtkSmartPointer<vtkPolyData> cage, const QString& name);
  subdapp::SchemeOptions ViewOptions(int view) const;
  void ApplyResult(int view, const UpdateJob::ViewResult& result);
  /// Rebuilds the scene from the views' results and renders it (no subdivision).
  void RenderScene();
  /// Sets a control without triggering an update.
  template <typename Setter>
  void SetQuietly(Setter&& set);
  /// Sets controls quietly, then updates the views (unless an update is being set up).
  template <typename Setter>
  void SetControlsAndUpdate(Setter&& set);
  void ShowProgress();
  void FinishUpdate();
  void OpenDialog();
  void ExportDialog();
  void ExportCageDialog();
  void ShowCageStatistics();
  void ScreenshotDialog();
  void RememberRecentFile(const QString& path);
  void RefreshRecentMenu();

  QVTKOpenGLNativeWidget* VTKWidget = nullptr;
  vtkNew<vtkGenericOpenGLRenderWindow> RenderWindow;
  vtkNew<vtkSubDScene> Scene;
  vtkSmartPointer<vtkPolyData> Cage;
  unsigned long CageRevision = 0; ///< changes with every new cage and every sharpness edit
  unsigned long JobCageRevision = 0; ///< the revision the running job subdivides
  QString CageName;
  std::unique_ptr<QSettings> Settings; ///< null: --no-settings
  std::array<ViewControls, MaxViews> Views;
  int ViewCount = 1;
  QComboBox* Layout = nullptr;
  QSlider* LevelSlider = nullptr;
  QComboBox* Tolerance = nullptr; ///< off (0), or the adaptive tessellation's tolerance
  QLabel* LevelLabel = nullptr;
  QComboBox* Coloring = nullptr;
  QComboBox* ColorMap = nullptr;
  QComboBox* RangeMode = nullptr;
  QSpinBox* RangePercentile = nullptr;
  QCheckBox* ShowCage = nullptr;
  QSlider* CageOpacity = nullptr;
  QCheckBox* ShowWireframe = nullptr;
  QCheckBox* ShowTexture = nullptr;
  QLabel* CageLabel = nullptr;
  QLabel* SelectionLabel = nullptr;
  QDoubleSpinBox* Sharpness = nullptr;
  vtkIdType SelectedA = -1, SelectedB = -1; ///< the selected cage edge (a, b), or vertex a (b < 0)
  QMenu* RecentMenu = nullptr;
  bool Updating = false; ///< controls set programmatically do not trigger updates
  std::unique_ptr<UpdateJob> Job; ///< the running update, if any
  bool RerunPending = false;      ///< settings changed while Job ran
  bool LastUpdateCancelled = false;
  QProgressBar* ProgressBar = nullptr;
  QPushButton* CancelButton = nullptr;
  QTimer* ProgressTimer = nullptr;
  double LastSubdivisionMs = 0.0, LastSceneMs = 0.0;
};
}

#endif
