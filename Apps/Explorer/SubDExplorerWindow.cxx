#include "SubDExplorerWindow.h"

#include "SubDBuiltinCages.h"
#include "SubDCageEditing.h"
#include "SubDCagePicking.h"
#include "SubDMeshIO.h"
#include "SubDMeshStatistics.h"
#include "SubDSchemeRegistry.h"

#include "QVTKOpenGLNativeWidget.h"
#include "vtkGenericOpenGLRenderWindow.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkPolyData.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkSubDScene.h"
#include "vtkSubDSurfaceFilter.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QElapsedTimer>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QImage>
#include <QLabel>
#include <QMenuBar>
#include <QMimeData>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QShortcut>
#include <QTimer>
#include <QMessageBox>
#include <QSettings>
#include <QSlider>
#include <QSpinBox>
#include <QStatusBar>
#include <QVBoxLayout>

#include <cmath>
#include <sstream>
#include <utility>

namespace subdexplorer
{
namespace
{
const char* const DefaultSchemes[ExplorerWindow::MaxViews] = { "catmull-clark", "loop", "butterfly", "doo-sabin" };

// Ctrl+click selects the cage edge or vertex under the mouse (and is not passed on to the
// camera's interactor style).
class CagePickCommand : public vtkCommand
{
public:
  static CagePickCommand* New() { return new CagePickCommand; }
  ExplorerWindow* Window = nullptr;
  void Execute(vtkObject* caller, unsigned long, void*) override
  {
    auto* interactor = static_cast<vtkRenderWindowInteractor*>(caller);
    if (interactor->GetControlKey() && this->Window)
    {
      const int* position = interactor->GetEventPosition();
      this->Window->SelectCageElementAt(position[0], position[1]);
      this->SetAbortFlag(1);
    }
  }
};

}

ExplorerWindow::ExplorerWindow(QWidget* parent)
  : QMainWindow(parent)
{
  this->setWindowTitle("SubD Explorer");
  this->VTKWidget = new QVTKOpenGLNativeWidget(this);
  this->VTKWidget->setRenderWindow(this->RenderWindow);
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  this->RenderWindow->GetInteractor()->SetInteractorStyle(style);
  vtkNew<CagePickCommand> pick;
  pick->Window = this;
  this->RenderWindow->GetInteractor()->AddObserver(vtkCommand::LeftButtonPressEvent, pick, 1.0f);
  this->Scene->SetRenderWindow(this->RenderWindow);
  this->Scene->FitWindowToViewsOff(); // the widget's size is the user's
  this->Scene->AutoResetCameraOff();  // a camera the user moved stays put
  this->setCentralWidget(this->VTKWidget);
  this->setAcceptDrops(true);

  auto* dock = new QDockWidget("Schemes", this);
  dock->setObjectName("SchemesDock");
  dock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);
  // Scrollable, so that the panel never forces the window above the size asked for.
  auto* scroll = new QScrollArea;
  scroll->setWidget(this->BuildControls());
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  dock->setWidget(scroll);
  this->addDockWidget(Qt::RightDockWidgetArea, dock);
  this->BuildMenus();
  this->ProgressBar = new QProgressBar;
  this->ProgressBar->setRange(0, 1000);
  this->ProgressBar->setTextVisible(false);
  this->ProgressBar->setMaximumWidth(200);
  this->ProgressBar->setVisible(false);
  this->CancelButton = new QPushButton("Cancel");
  this->CancelButton->setToolTip("Stop the running subdivision (Esc); the views keep their previous result");
  this->CancelButton->setVisible(false);
  connect(this->CancelButton, &QPushButton::clicked, this, &ExplorerWindow::CancelUpdate);
  auto* cancelShortcut = new QShortcut(QKeySequence(Qt::Key_Escape), this);
  connect(cancelShortcut, &QShortcut::activated, this, &ExplorerWindow::CancelUpdate);
  this->statusBar()->addPermanentWidget(this->ProgressBar);
  this->statusBar()->addPermanentWidget(this->CancelButton);
  this->ProgressTimer = new QTimer(this);
  connect(this->ProgressTimer, &QTimer::timeout, this, &ExplorerWindow::ShowProgress);
  this->statusBar()->showMessage("Drag to rotate, right-drag or wheel to zoom, middle-drag to pan; R resets the camera.");
  this->LoadBuiltin("cube");
  // Wide enough for the controls and a vertical scroll bar; long labels wrap.
  scroll->setMinimumWidth(360 + scroll->verticalScrollBar()->sizeHint().width());
}

ExplorerWindow::~ExplorerWindow()
{
  this->Job.reset(); // cancels and joins the worker before the widgets go
}

QWidget* ExplorerWindow::BuildControls()
{
  auto* panel = new QWidget;
  auto* layout = new QVBoxLayout(panel);
  layout->addWidget(this->BuildGlobalControls());
  layout->addWidget(this->BuildCreaseControls());
  for (int v = 0; v < MaxViews; ++v)
  {
    layout->addWidget(this->BuildViewControls(v));
    this->ConnectViewControls(v);
  }
  layout->addStretch(1);
  this->ConnectGlobalControls();
  this->SetViewCount(1);
  return panel;
}

QGroupBox* ExplorerWindow::BuildGlobalControls()
{
  auto* global = new QGroupBox("All views");
  auto* form = new QFormLayout(global);
  this->CageLabel = new QLabel;
  form->addRow("Cage", this->CageLabel);
  this->Layout = new QComboBox;
  this->Layout->addItems({ "1 view", "2 views", "4 views" });
  form->addRow("Layout", this->Layout);
  this->LevelSlider = new QSlider(Qt::Horizontal);
  this->LevelSlider->setRange(0, 8);
  this->LevelSlider->setValue(2);
  this->LevelSlider->setTickPosition(QSlider::TicksBelow);
  this->LevelLabel = new QLabel("2");
  auto* levelRow = new QHBoxLayout;
  levelRow->addWidget(this->LevelSlider);
  levelRow->addWidget(this->LevelLabel);
  form->addRow("Level", levelRow);
  this->Tolerance = new QComboBox;
  this->Tolerance->addItem("off: refine", 0.0);
  for (double tolerance : { 1e-2, 3e-3, 1e-3, 3e-4, 1e-4 })
  {
    this->Tolerance->addItem(QString("limit within %1").arg(tolerance), tolerance);
  }
  this->Tolerance->setToolTip("Catmull-Clark and Loop: instead of refining, tessellate the limit surface into "
                              "triangles within this fraction of the cage's diagonal, fine only where it curves "
                              "(as deep as it needs, up to level 12). The view's F counts its triangles.");
  form->addRow("Tolerance", this->Tolerance);
  this->Coloring = new QComboBox;
  for (int c = vtkSubDScene::COLOR_NONE; c <= vtkSubDScene::COLOR_MINIMUM_CURVATURE; ++c)
  {
    this->Coloring->addItem(vtkSubDScene::GetColoringName(c));
  }
  this->Coloring->setCurrentIndex(vtkSubDScene::COLOR_MEAN_CURVATURE);
  this->Coloring->setToolTip("Curvature colouring (k1 >= k2 are the principal curvatures; the K key cycles): "
                             "the exact limit curvature for Catmull-Clark and Loop with 'Limit', the refined "
                             "mesh's discrete curvature otherwise");
  form->addRow("Curvature", this->Coloring);
  this->ColorMap = new QComboBox;
  for (int m = vtkSubDScene::COLORMAP_COOL_TO_WARM; m <= vtkSubDScene::COLORMAP_GRAYSCALE; ++m)
  {
    this->ColorMap->addItem(vtkSubDScene::GetColorMapName(m));
  }
  form->addRow("Colour map", this->ColorMap);
  this->RangeMode = new QComboBox;
  this->RangeMode->addItems({ "symmetric", "percentile" });
  this->RangeMode->setToolTip("symmetric: [-m, m] around zero, m the percentile of |curvature|; percentile: the "
                              "central percentage of the values. Over all views, interior points only.");
  this->RangePercentile = new QSpinBox;
  this->RangePercentile->setRange(50, 100);
  this->RangePercentile->setValue(95);
  this->RangePercentile->setSuffix(" %");
  auto* rangeRow = new QHBoxLayout;
  rangeRow->addWidget(this->RangeMode, 1);
  rangeRow->addWidget(this->RangePercentile);
  form->addRow("Range", rangeRow);
  this->ShowCage = new QCheckBox("Control cage");
  this->ShowCage->setChecked(true);
  this->CageOpacity = new QSlider(Qt::Horizontal);
  this->CageOpacity->setRange(0, 100);
  this->CageOpacity->setValue(100);
  this->CageOpacity->setToolTip("Opacity of the cage's edges and vertices (its creases stay opaque)");
  auto* cageRow = new QHBoxLayout;
  cageRow->addWidget(this->ShowCage);
  cageRow->addWidget(this->CageOpacity, 1);
  form->addRow(cageRow);
  this->ShowWireframe = new QCheckBox("Refined wireframe (W)");
  form->addRow(this->ShowWireframe);
  this->ShowTexture = new QCheckBox("Checker texture (T)");
  this->ShowTexture->setToolTip("Surfaces with texture coordinates: a checker instead of the colouring, so that "
                                "seams and stretching show");
  form->addRow(this->ShowTexture);
  return global;
}

QGroupBox* ExplorerWindow::BuildCreaseControls()
{
  auto* creases = new QGroupBox("Creases");
  auto* creaseForm = new QFormLayout(creases);
  this->SelectionLabel = new QLabel("Ctrl+click an edge or a vertex of the cage");
  this->SelectionLabel->setWordWrap(true);
  creaseForm->addRow("Selected", this->SelectionLabel);
  this->Sharpness = new QDoubleSpinBox;
  this->Sharpness->setRange(0.0, 10.0);
  this->Sharpness->setSingleStep(0.5);
  this->Sharpness->setDecimals(2);
  this->Sharpness->setEnabled(false);
  this->Sharpness->setToolTip("OpenSubdiv's scale: 0 smooth, fractions semi-sharp, 10 infinitely sharp. "
                              "Edges become crease lines, vertices get \"CornerSharpness\".");
  creaseForm->addRow("Sharpness", this->Sharpness);
  connect(this->Sharpness, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double value) {
    if (this->Updating || this->SelectedA < 0)
      return;
    QString error;
    if (!this->SetSharpness(this->SelectedA, this->SelectedB, value, error))
      this->statusBar()->showMessage(error, 8000);
  });
  return creases;
}

QGroupBox* ExplorerWindow::BuildViewControls(int v)
{
  ViewControls& view = this->Views[v];
  view.Box = new QGroupBox(QString("View %1").arg(v + 1));
  auto* viewForm = new QFormLayout(view.Box);
  view.Scheme = new QComboBox;
  for (const subdapp::SchemeEntry& entry : subdapp::Schemes())
  {
    view.Scheme->addItem(QString::fromStdString(entry.Name));
    view.Scheme->setItemData(view.Scheme->count() - 1, QString::fromStdString(entry.Summary), Qt::ToolTipRole);
  }
  view.Scheme->setCurrentText(DefaultSchemes[v]);
  viewForm->addRow("Scheme", view.Scheme);
  view.Boundary = new QComboBox;
  view.Boundary->addItems({ "none", "edge-only", "edge-and-corner" });
  view.Boundary->setCurrentIndex(1);
  viewForm->addRow("Boundary", view.Boundary);
  view.Tension = new QDoubleSpinBox;
  view.Tension->setDecimals(4);
  view.Tension->setSingleStep(0.005);
  view.Tension->setToolTip("butterfly: [-0.0625, 0.0625], four-point: [0, 0.125]");
  viewForm->addRow("Tension", view.Tension);
  view.CreaseMethod = new QComboBox;
  view.CreaseMethod->addItems({ "uniform", "chaikin" });
  view.CreaseMethod->setToolTip("How semi-sharp creases decay: one unit per level, or averaged along the "
                                "crease first (OpenSubdiv's Chaikin)");
  viewForm->addRow("Creases", view.CreaseMethod);
  view.FaceVarying = new QComboBox;
  for (int mode = vtkSubDSurfaceFilter::FVAR_LINEAR_NONE; mode <= vtkSubDSurfaceFilter::FVAR_LINEAR_ALL; ++mode)
  {
    view.FaceVarying->addItem(vtkSubDSurfaceFilter::GetFaceVaryingInterpolationName(mode));
  }
  view.FaceVarying->setCurrentIndex(vtkSubDSurfaceFilter::FVAR_LINEAR_CORNERS_PLUS1);
  view.FaceVarying->setToolTip("How texture coordinates are refined where UV seams split the mesh (OpenSubdiv's "
                               "face-varying interpolation): what stays linear");
  viewForm->addRow("UV seams", view.FaceVarying);
  view.Limit = new QCheckBox("Limit: project, exact curvature (L)");
  view.Limit->setToolTip("Move the points to the limit surface where the scheme has limit masks; Catmull-Clark "
                         "and Loop also colour by the limit's exact curvature");
  viewForm->addRow(view.Limit);
  view.Statistics = new QLabel;
  view.Statistics->setWordWrap(true);
  view.Statistics->setTextInteractionFlags(Qt::TextSelectableByMouse);
  viewForm->addRow(view.Statistics);
  return view.Box;
}

void ExplorerWindow::ConnectViewControls(int v)
{
  ViewControls& view = this->Views[v];
  auto schemeChanged = [this, v]() {
    ViewControls& changed = this->Views[v];
    const std::string scheme = changed.Scheme->currentText().toStdString();
    const bool fourPoint = scheme == "four-point";
    const bool updating = this->Updating;
    this->Updating = true;
    changed.Tension->setEnabled(scheme == "butterfly" || fourPoint);
    changed.Tension->setRange(fourPoint ? 0.0 : -0.0625, fourPoint ? 0.125 : 0.0625);
    changed.Tension->setValue(fourPoint ? 0.0625 : 0.0);
    const subdapp::SchemeEntry* entry = subdapp::FindScheme(scheme);
    changed.Boundary->setEnabled(!entry->Curve);
    changed.CreaseMethod->setEnabled(!entry->Curve);
    changed.FaceVarying->setEnabled(!entry->Curve);
    changed.Limit->setEnabled(entry->LimitPositions);
    this->Updating = updating;
    if (!this->Updating)
    {
      this->UpdateViews();
    }
  };
  connect(view.Scheme, &QComboBox::currentTextChanged, this, schemeChanged);
  schemeChanged();
  connect(view.Boundary, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this]() {
    if (!this->Updating)
      this->UpdateViews();
  });
  connect(view.Tension, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this]() {
    if (!this->Updating)
      this->UpdateViews();
  });
  connect(view.CreaseMethod, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this]() {
    if (!this->Updating)
      this->UpdateViews();
  });
  connect(view.FaceVarying, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this]() {
    if (!this->Updating)
      this->UpdateViews();
  });
  connect(view.Limit, &QCheckBox::toggled, this, [this]() {
    if (!this->Updating)
      this->UpdateViews();
  });
}

void ExplorerWindow::ConnectGlobalControls()
{
  connect(this->Layout, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
    [this](int index) { this->SetViewCount(index == 0 ? 1 : (index == 1 ? 2 : 4)); });
  connect(this->LevelSlider, &QSlider::valueChanged, this, [this](int level) {
    this->LevelLabel->setText(QString::number(level));
    if (!this->Updating)
      this->UpdateViews();
  });
  connect(this->Tolerance, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this]() {
    if (!this->Updating)
      this->UpdateViews();
  });
  connect(this->Coloring, &QComboBox::currentTextChanged, this,
    [this](const QString& text) { this->SetColoring(text.toStdString()); });
  connect(this->ColorMap, &QComboBox::currentTextChanged, this,
    [this](const QString& text) { this->SetColorMap(text.toStdString()); });
  auto rangeChanged = [this]() {
    if (!this->Updating)
      this->SetColorRange(this->RangeMode->currentIndex() == 0, this->RangePercentile->value());
  };
  connect(this->RangeMode, QOverload<int>::of(&QComboBox::currentIndexChanged), this, rangeChanged);
  connect(this->RangePercentile, QOverload<int>::of(&QSpinBox::valueChanged), this, rangeChanged);
  connect(this->ShowCage, &QCheckBox::toggled, this, [this](bool show) { this->SetShowCage(show); });
  connect(this->CageOpacity, &QSlider::valueChanged, this, [this](int value) {
    if (!this->Updating)
      this->SetCageOpacity(value / 100.0);
  });
  connect(this->ShowWireframe, &QCheckBox::toggled, this, [this](bool show) { this->SetShowWireframe(show); });
  connect(this->ShowTexture, &QCheckBox::toggled, this, [this](bool show) { this->SetShowTexture(show); });
}

void ExplorerWindow::BuildMenus()
{
  QMenu* file = this->menuBar()->addMenu("&File");
  file->addAction("&Open...", this, &ExplorerWindow::OpenDialog, QKeySequence::Open);
  QMenu* builtins = file->addMenu("&Built-in cage");
  std::vector<std::string> names = subdapp::BuiltinCageNames();
  for (const std::string& curve : subdapp::BuiltinCurveNames())
  {
    names.push_back(curve);
  }
  for (const std::string& name : names)
  {
    builtins->addAction(QString::fromStdString(name), this, [this, name]() { this->LoadBuiltin(name); });
  }
  this->RecentMenu = file->addMenu("&Recent files");
  this->RefreshRecentMenu();
  file->addSeparator();
  file->addAction("&Export surface...", this, &ExplorerWindow::ExportDialog, QKeySequence(Qt::CTRL | Qt::Key_E));
  file->addAction("Export &cage with creases...", this, &ExplorerWindow::ExportCageDialog,
    QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E));
  file->addAction("Save views &image...", this, &ExplorerWindow::ScreenshotDialog, QKeySequence(Qt::CTRL | Qt::Key_P));
  file->addSeparator();
  file->addAction("&Quit", this, &QWidget::close, QKeySequence::Quit);

  QMenu* view = this->menuBar()->addMenu("&View");
  for (int count : { 1, 2, 4 })
  {
    view->addAction(QString("%1 view%2").arg(count).arg(count > 1 ? "s" : ""), this,
      [this, count]() { this->SetViewCount(count); }, QKeySequence(Qt::CTRL | (Qt::Key_0 + count)));
  }
  view->addSeparator();
  view->addAction("Level &up", this, [this]() { this->LevelSlider->setValue(this->LevelSlider->value() + 1); },
    QKeySequence(Qt::Key_Plus));
  view->addAction("Level &down", this, [this]() { this->LevelSlider->setValue(this->LevelSlider->value() - 1); },
    QKeySequence(Qt::Key_Minus));
  view->addAction("Toggle &cage", this, [this]() { this->ShowCage->toggle(); }, QKeySequence(Qt::Key_C));
  view->addAction("Toggle &wireframe", this, [this]() { this->ShowWireframe->toggle(); }, QKeySequence(Qt::Key_W));
  view->addAction("Toggle checker &texture", this, [this]() { this->ShowTexture->toggle(); }, QKeySequence(Qt::Key_T));
  view->addAction("Toggle &limit (all views)", this, [this]() { this->SetLimit(!this->Views[0].Limit->isChecked()); },
    QKeySequence(Qt::Key_L));
  view->addAction("Next curvature &colouring", this,
    [this]() { this->Coloring->setCurrentIndex((this->Coloring->currentIndex() + 1) % this->Coloring->count()); },
    QKeySequence(Qt::Key_K));
  view->addAction("Next colour &map", this,
    [this]() { this->ColorMap->setCurrentIndex((this->ColorMap->currentIndex() + 1) % this->ColorMap->count()); },
    QKeySequence(Qt::Key_M));
  view->addAction("&Reset camera", this,
    [this]() {
      this->Scene->ResetCamera();
      this->UpdateViews();
    },
    QKeySequence(Qt::Key_R));

  QMenu* help = this->menuBar()->addMenu("&Help");
  help->addAction("&Keyboard and mouse", this, [this]() {
    QMessageBox::information(this, "Keyboard and mouse",
      "<table>"
      "<tr><td>Drag / right-drag, wheel / middle-drag</td><td>rotate / zoom / pan</td></tr>"
      "<tr><td>Ctrl+click</td><td>select a cage edge or vertex (Creases panel)</td></tr>"
      "<tr><td>+ / -</td><td>level up / down</td></tr>"
      "<tr><td>Ctrl+1, Ctrl+2, Ctrl+4</td><td>1, 2 or 4 views</td></tr>"
      "<tr><td>C, W, L</td><td>cage, refined wireframe, limit (all views)</td></tr>"
      "<tr><td>K, M</td><td>next curvature colouring, next colour map</td></tr>"
      "<tr><td>R</td><td>reset the camera</td></tr>"
      "<tr><td>Esc</td><td>cancel the running update</td></tr>"
      "<tr><td>Ctrl+O, Ctrl+E, Ctrl+Shift+E, Ctrl+P</td><td>open, export surface, export cage, save image</td></tr>"
      "</table>");
  }, QKeySequence::HelpContents);
}

void ExplorerWindow::SetCage(vtkSmartPointer<vtkPolyData> cage, const QString& name)
{
  this->Cage = cage;
  ++this->CageRevision;
  this->CageName = name;
  this->SelectCageElement(-1, -1);
  this->ShowCageStatistics();
  this->setWindowTitle("SubD Explorer - " + name);
  this->Scene->ResetCamera();
  this->UpdateViews();
}

vtkPolyData* ExplorerWindow::GetCage() const
{
  return this->Cage;
}

void ExplorerWindow::ShowCageStatistics()
{
  const MeshStatistics stats = ComputeMeshStatistics(this->Cage);
  this->CageLabel->setText(QString("%1\n%2 points, %3 faces\n%4 crease lines, %5 extraordinary")
                             .arg(this->CageName)
                             .arg(stats.Vertices)
                             .arg(stats.Faces)
                             .arg(stats.Lines)
                             .arg(stats.Extraordinary));
}

void ExplorerWindow::LoadBuiltin(const std::string& name)
{
  vtkSmartPointer<vtkPolyData> cage = subdapp::MakeBuiltinCage(name);
  if (cage)
  {
    this->SetCage(cage, QString::fromStdString("built-in " + name));
  }
}

bool ExplorerWindow::LoadFile(const QString& path, QString& error)
{
  std::string message;
  vtkSmartPointer<vtkPolyData> cage = subdapp::ReadMesh(path.toStdString(), message);
  if (!cage)
  {
    error = QString::fromStdString(message);
    return false;
  }
  this->RememberRecentFile(path);
  this->SetCage(cage, QFileInfo(path).fileName());
  return true;
}

void ExplorerWindow::SetViewCount(int count)
{
  this->ViewCount = count == 2 || count == 4 ? count : 1;
  const bool updating = this->Updating;
  this->Updating = true;
  this->Layout->setCurrentIndex(this->ViewCount == 1 ? 0 : (this->ViewCount == 2 ? 1 : 2));
  this->Updating = updating;
  for (int v = 0; v < MaxViews; ++v)
  {
    this->Views[v].Box->setVisible(v < this->ViewCount);
  }
  if (!this->Updating && this->Cage)
  {
    this->UpdateViews();
  }
}

void ExplorerWindow::SetScheme(int view, const std::string& scheme)
{
  if (view >= 0 && view < MaxViews && subdapp::FindScheme(scheme))
  {
    this->Views[view].Scheme->setCurrentText(QString::fromStdString(scheme));
  }
}

void ExplorerWindow::SetLevels(int levels)
{
  this->LevelSlider->setValue(levels);
}

void ExplorerWindow::SetTolerance(double tolerance)
{
  int index = this->Tolerance->findData(tolerance);
  if (index < 0)
  {
    this->Tolerance->addItem(QString("limit within %1").arg(tolerance), tolerance);
    index = this->Tolerance->count() - 1;
  }
  this->Tolerance->setCurrentIndex(index);
}

double ExplorerWindow::GetTolerance() const
{
  return this->Tolerance->currentData().toDouble();
}

template <typename Setter>
void ExplorerWindow::SetQuietly(Setter&& set)
{
  const bool updating = this->Updating;
  this->Updating = true;
  set();
  this->Updating = updating;
}

template <typename Setter>
void ExplorerWindow::SetControlsAndUpdate(Setter&& set)
{
  this->SetQuietly(std::forward<Setter>(set));
  if (!this->Updating)
  {
    this->UpdateViews();
  }
}

void ExplorerWindow::SetColoring(const std::string& coloring)
{
  const int value = vtkSubDScene::ColoringFromName(coloring.c_str());
  if (value < 0)
  {
    return;
  }
  this->Scene->SetColoring(value);
  // (An update: exact curvature may now be needed, or no longer.)
  this->SetControlsAndUpdate([&]() { this->Coloring->setCurrentIndex(value); });
}

void ExplorerWindow::SetColorMap(const std::string& map)
{
  const int value = vtkSubDScene::ColorMapFromName(map.c_str());
  if (value < 0)
  {
    return;
  }
  this->Scene->SetColorMap(value);
  this->SetControlsAndUpdate([&]() { this->ColorMap->setCurrentIndex(value); });
}

void ExplorerWindow::SetColorRange(bool symmetric, double percentile)
{
  this->Scene->SetRangeMode(symmetric ? vtkSubDScene::RANGE_SYMMETRIC : vtkSubDScene::RANGE_PERCENTILE);
  this->Scene->SetRangePercentile(percentile);
  this->SetControlsAndUpdate([&]() {
    this->RangeMode->setCurrentIndex(symmetric ? 0 : 1);
    this->RangePercentile->setValue(static_cast<int>(std::lround(this->Scene->GetRangePercentile())));
  });
}

void ExplorerWindow::SetShowCage(bool show)
{
  this->Scene->SetShowCage(show);
  this->SetControlsAndUpdate([&]() {
    this->ShowCage->setChecked(show);
    this->CageOpacity->setEnabled(show);
  });
}

void ExplorerWindow::SetCageOpacity(double opacity)
{
  this->Scene->SetCageOpacity(opacity);
  const int percent = static_cast<int>(std::lround(100.0 * this->Scene->GetCageOpacity()));
  this->SetControlsAndUpdate([&]() { this->CageOpacity->setValue(percent); });
}

void ExplorerWindow::SetShowWireframe(bool show)
{
  this->Scene->SetShowWireframe(show);
  this->SetControlsAndUpdate([&]() { this->ShowWireframe->setChecked(show); });
}

void ExplorerWindow::SetShowTexture(bool show)
{
  this->Scene->SetShowTexture(show);
  this->SetControlsAndUpdate([&]() { this->ShowTexture->setChecked(show); });
}

void ExplorerWindow::SetFaceVaryingInterpolation(int mode)
{
  this->SetControlsAndUpdate([&]() {
    for (ViewControls& view : this->Views)
    {
      view.FaceVarying->setCurrentIndex(mode);
    }
  });
}

void ExplorerWindow::SetLimit(bool limit)
{
  this->SetControlsAndUpdate([&]() {
    for (ViewControls& view : this->Views)
    {
      view.Limit->setChecked(limit);
    }
  });
}

bool ExplorerWindow::SetSharpness(vtkIdType a, vtkIdType b, double sharpness, QString& error)
{
  std::string message;
  const bool done = b < 0 ? subdapp::SetVertexSharpness(this->Cage, a, sharpness, message)
                          : subdapp::SetEdgeSharpness(this->Cage, a, b, sharpness, message);
  if (!done)
  {
    error = QString::fromStdString(message);
    return false;
  }
  ++this->CageRevision;
  this->ShowCageStatistics();
  this->UpdateViews();
  return true;
}

bool ExplorerWindow::SelectCageElementAt(int x, int y)
{
  vtkRenderer* renderer = this->RenderWindow->GetInteractor()->FindPokedRenderer(x, y);
  if (!renderer || !this->Cage)
  {
    return false;
  }
  // The cage's points on the screen, in this view's camera.
  const vtkIdType numPoints = this->Cage->GetNumberOfPoints();
  std::vector<double> screen(static_cast<size_t>(2 * numPoints));
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    const double* p = this->Cage->GetPoint(i);
    renderer->SetWorldPoint(p[0], p[1], p[2], 1.0);
    renderer->WorldToDisplay();
    const double* d = renderer->GetDisplayPoint();
    screen[2 * i] = d[0];
    screen[2 * i + 1] = d[1];
  }
  const subdapp::PickedElement picked = subdapp::PickCageElement(this->Cage, screen, x, y);
  if (!this->SelectCageElement(picked.A, picked.B))
  {
    this->SelectionLabel->setText("nothing there: Ctrl+click closer to an edge or a vertex");
    return false;
  }
  return true;
}

bool ExplorerWindow::SelectCageElement(vtkIdType a, vtkIdType b)
{
  const vtkIdType n = this->Cage ? this->Cage->GetNumberOfPoints() : 0;
  if (a >= n || b >= n || (a >= 0 && b >= 0 && !subdapp::IsCageEdge(this->Cage, a, b)))
  {
    a = b = -1;
  }
  this->SelectedA = a;
  this->SelectedB = a < 0 ? -1 : b;
  this->SetQuietly([&]() {
    this->Sharpness->setEnabled(a >= 0);
    if (a < 0)
    {
      this->SelectionLabel->setText("Ctrl+click an edge or a vertex of the cage");
    }
    else if (b < 0)
    {
      this->SelectionLabel->setText(QString("vertex %1").arg(a));
      this->Sharpness->setValue(subdapp::GetVertexSharpness(this->Cage, a));
    }
    else
    {
      this->SelectionLabel->setText(QString("edge %1 - %2").arg(a).arg(b));
      this->Sharpness->setValue(subdapp::GetEdgeSharpness(this->Cage, a, b));
    }
  });
  this->Scene->SetCageSelection(this->SelectedA, this->SelectedB);
  if (!this->Updating && !this->Job && this->Scene->GetNumberOfViews() > 0)
  {
    this->RenderScene();
  }
  return a >= 0;
}

subdapp::SchemeOptions ExplorerWindow::ViewOptions(int v) const
{
  const ViewControls& view = this->Views[v];
  const subdapp::SchemeEntry* entry = subdapp::FindScheme(view.Scheme->currentText().toStdString());
  subdapp::SchemeOptions options;
  options.Levels = this->LevelSlider->value();
  options.BoundaryRule = view.Boundary->currentIndex();
  options.Tension = view.Tension->value();
  options.TensionGiven = view.Tension->isEnabled();
  options.CreaseMethod = view.CreaseMethod->currentIndex();
  options.FaceVaryingInterpolation = view.FaceVarying->currentIndex();
  options.ProjectToLimit = view.Limit->isChecked() && entry->LimitPositions;
  options.LimitCurvature = options.ProjectToLimit && entry->LimitCurvature &&
    this->Scene->GetColoring() != vtkSubDScene::COLOR_NONE;
  if (entry->LimitCurvature && this->GetTolerance() > 0.0) // the schemes with an exact limit
  {
    options.Tolerance = this->GetTolerance();
    options.Levels = 12; // as deep as the tolerance needs: subd --tolerance's default
    options.LimitCurvature = this->Scene->GetColoring() != vtkSubDScene::COLOR_NONE;
  }
  return options;
}

void ExplorerWindow::ApplyResult(int v, const UpdateJob::ViewResult& result)
{
  ViewControls& view = this->Views[v];
  const subdapp::SchemeEntry* entry = subdapp::FindScheme(view.Scheme->currentText().toStdString());
  view.Result = result.Surface;
  view.Statistics->setToolTip(QString::fromStdString(result.Warnings).trimmed());
  if (!view.Result)
  {
    view.Statistics->setText(QString("<span style='color:#c0392b'>%1</span>")
                               .arg(QString::fromStdString(result.Errors.empty() ? "no output" : result.Errors)
                                      .toHtmlEscaped()));
    return;
  }
  const MeshStatistics stats = ComputeMeshStatistics(view.Result);
  QString text = entry->Curve
    ? QString("%1 points on %2 curves").arg(stats.Vertices).arg(stats.Lines)
    : QString("V %1 · E %2 · F %3 · extraordinary %4").arg(stats.Vertices).arg(stats.Edges).arg(stats.Faces).arg(stats.Extraordinary);
  text += QString(" · %1 ms").arg(result.Milliseconds, 0, 'f', 1);
  if (!result.Warnings.empty())
  {
    text += " · <span style='color:#b9770e'>warnings (hover)</span>";
  }
  view.Statistics->setText(text);
}

void ExplorerWindow::UpdateViews()
{
  if (!this->Cage)
  {
    return;
  }
  if (this->Job)
  {
    // Restart with the new settings once the running update has stopped.
    this->Job->Cancel();
    this->RerunPending = true;
    return;
  }
  // Only the views whose scheme, options or cage changed are subdivided again.
  std::vector<UpdateJob::ViewTask> tasks;
  bool anyTask = false;
  for (int v = 0; v < this->ViewCount; ++v)
  {
    const ViewControls& view = this->Views[v];
    const std::string scheme = view.Scheme->currentText().toStdString();
    const subdapp::SchemeOptions options = this->ViewOptions(v);
    const bool current = view.HasResult && view.ResultScheme == scheme && view.ResultOptions == options &&
      view.ResultCageRevision == this->CageRevision;
    tasks.push_back({ current ? nullptr : subdapp::FindScheme(scheme), options });
    anyTask = anyTask || !current;
  }
  if (!anyTask)
  {
    this->LastSubdivisionMs = 0.0;
    this->RenderScene();
    return;
  }
  this->Job = std::make_unique<UpdateJob>(this->Cage, std::move(tasks));
  this->JobCageRevision = this->CageRevision;
  this->LastUpdateCancelled = false;
  this->ProgressBar->setValue(0);
  this->ProgressTimer->start(100);
  this->Job->Start([this]() { QMetaObject::invokeMethod(this, [this]() { this->FinishUpdate(); }, Qt::QueuedConnection); });
}

void ExplorerWindow::ShowProgress()
{
  if (!this->Job)
  {
    return;
  }
  // Short updates never show the bar; long ones show it with Cancel.
  this->ProgressBar->setVisible(true);
  this->CancelButton->setVisible(true);
  this->ProgressBar->setValue(static_cast<int>(1000.0 * this->Job->GetProgress()));
}

void ExplorerWindow::FinishUpdate()
{
  if (!this->Job)
  {
    return;
  }
  this->Job->Wait();
  const std::unique_ptr<UpdateJob> job = std::move(this->Job);
  this->ProgressTimer->stop();
  this->ProgressBar->setVisible(false);
  this->CancelButton->setVisible(false);
  if (this->RerunPending)
  {
    this->RerunPending = false;
    this->UpdateViews();
    return;
  }
  if (job->IsCancelled())
  {
    this->LastUpdateCancelled = true;
    this->statusBar()->showMessage("Update cancelled: the views show the previous result.", 8000);
    return;
  }
  this->LastSubdivisionMs = 0.0;
  for (size_t v = 0; v < job->GetTasks().size(); ++v)
  {
    const UpdateJob::ViewTask& task = job->GetTasks()[v];
    if (task.Entry) // recomputed (the others kept their result)
    {
      ViewControls& view = this->Views[v];
      view.HasResult = true;
      view.ResultScheme = task.Entry->Name;
      view.ResultOptions = task.Options;
      view.ResultCageRevision = this->JobCageRevision;
      this->ApplyResult(static_cast<int>(v), job->GetResults()[v]);
      this->LastSubdivisionMs += job->GetResults()[v].Milliseconds;
    }
  }
  this->RenderScene();
}

void ExplorerWindow::RenderScene()
{
  QElapsedTimer clock;
  clock.start();
  this->Scene->RemoveAllViews();
  vtkNew<vtkPolyData> empty;
  for (int v = 0; v < this->ViewCount; ++v)
  {
    const ViewControls& view = this->Views[v];
    std::ostringstream title;
    title << view.Scheme->currentText().toStdString();
    if (view.ResultOptions.Tolerance > 0.0)
      title << " limit, tolerance " << view.ResultOptions.Tolerance;
    else
      title << ", level " << this->LevelSlider->value() << (view.ResultOptions.ProjectToLimit ? ", limit" : "");
    this->Scene->AddView(
      view.Result ? view.Result.GetPointer() : empty.GetPointer(), this->Cage, title.str().c_str());
  }
  if (this->VTKWidget->isVisible())
  {
    this->Scene->Render();
  }
  this->VTKWidget->update();
  this->LastSceneMs = static_cast<double>(clock.nsecsElapsed()) * 1e-6;
}

void ExplorerWindow::CancelUpdate()
{
  if (this->Job)
  {
    this->RerunPending = false;
    this->Job->Cancel();
  }
}

void ExplorerWindow::WaitForUpdate()
{
  while (this->Job)
  {
    QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
  }
}

bool ExplorerWindow::SaveViewsImage(const QString& path, QString& error)
{
  if (this->Scene->GetNumberOfViews() == 0)
  {
    error = "no views to save yet (the first update did not complete)";
    return false;
  }
  this->Scene->Render();
  const QImage image = this->VTKWidget->grabFramebuffer();
  if (image.isNull() || !image.save(path, "PNG"))
  {
    error = "cannot write the image '" + path + "'";
    return false;
  }
  return true;
}

bool ExplorerWindow::SaveWindowImage(const QString& path, QString& error)
{
  this->Scene->Render();
  // The GL widget's pixels come from its framebuffer; grab() composes them with the rest.
  const QPixmap pixmap = this->grab();
  if (pixmap.isNull() || !pixmap.save(path, "PNG"))
  {
    error = "cannot write the image '" + path + "'";
    return false;
  }
  return true;
}

bool ExplorerWindow::ExportSurface(int view, const QString& path, QString& error)
{
  if (view < 0 || view >= this->ViewCount || !this->Views[view].Result)
  {
    error = "view " + QString::number(view + 1) + " has no surface to export";
    return false;
  }
  std::string message;
  if (!subdapp::WriteMesh(this->Views[view].Result, path.toStdString(), message))
  {
    error = QString::fromStdString(message);
    return false;
  }
  return true;
}

void ExplorerWindow::dragEnterEvent(QDragEnterEvent* event)
{
  if (event->mimeData()->hasUrls() && event->mimeData()->urls().front().isLocalFile())
  {
    event->acceptProposedAction();
  }
}

void ExplorerWindow::dropEvent(QDropEvent* event)
{
  const QString path = event->mimeData()->urls().front().toLocalFile();
  QString error;
  if (!this->LoadFile(path, error))
  {
    QMessageBox::warning(this, "Cannot open", error);
  }
  event->acceptProposedAction();
}

void ExplorerWindow::OpenDialog()
{
  const QString path = QFileDialog::getOpenFileName(this, "Open a mesh", QString(),
    "Meshes (*.vtp *.vtk *.obj *.ply *.stl *.off);;All files (*)");
  QString error;
  if (!path.isEmpty() && !this->LoadFile(path, error))
  {
    QMessageBox::warning(this, "Cannot open", error);
  }
}

void ExplorerWindow::ExportDialog()
{
  const QString path = QFileDialog::getSaveFileName(this, "Export view 1's surface", "surface.vtp",
    "Meshes (*.vtp *.vtk *.obj *.ply *.stl *.off)");
  QString error;
  if (!path.isEmpty() && !this->ExportSurface(0, path, error))
  {
    QMessageBox::warning(this, "Cannot export", error);
  }
}

bool ExplorerWindow::ExportCage(const QString& path, QString& error)
{
  std::string message;
  if (!this->Cage || !subdapp::WriteMesh(this->Cage, path.toStdString(), message))
  {
    error = this->Cage ? QString::fromStdString(message) : "no cage";
    return false;
  }
  return true;
}

void ExplorerWindow::ExportCageDialog()
{
  const QString path = QFileDialog::getSaveFileName(this, "Export the cage with its creases", "cage.vtp",
    "Meshes with creases (*.vtp *.vtk *.obj)");
  QString error;
  if (!path.isEmpty() && !this->ExportCage(path, error))
  {
    QMessageBox::warning(this, "Cannot export", error);
  }
}

void ExplorerWindow::ScreenshotDialog()
{
  const QString path = QFileDialog::getSaveFileName(this, "Save the views as an image", "views.png", "PNG (*.png)");
  QString error;
  if (!path.isEmpty() && !this->SaveViewsImage(path, error))
  {
    QMessageBox::warning(this, "Cannot save", error);
  }
}

void ExplorerWindow::RememberRecentFile(const QString& path)
{
  if (!this->Settings)
  {
    return;
  }
  QStringList recent = this->Settings->value("recentFiles").toStringList();
  recent.removeAll(path);
  recent.prepend(path);
  while (recent.size() > 8)
  {
    recent.removeLast();
  }
  this->Settings->setValue("recentFiles", recent);
  this->RefreshRecentMenu();
}

void ExplorerWindow::RefreshRecentMenu()
{
  this->RecentMenu->clear();
  const QStringList recent = this->Settings ? this->Settings->value("recentFiles").toStringList() : QStringList();
  for (const QString& path : recent)
  {
    this->RecentMenu->addAction(path, this, [this, path]() {
      QString error;
      if (!this->LoadFile(path, error))
      {
        QMessageBox::warning(this, "Cannot open", error);
      }
    });
  }
  this->RecentMenu->setEnabled(!this->RecentMenu->isEmpty());
}

void ExplorerWindow::UseSettings(std::unique_ptr<QSettings> settings)
{
  this->Settings = std::move(settings);
  this->RefreshRecentMenu();
  if (!this->Settings)
  {
    return;
  }
  QSettings& in = *this->Settings;
  this->SetQuietly([&]() {
    in.beginGroup("layout");
    for (int v = 0; v < MaxViews; ++v)
    {
      ViewControls& view = this->Views[v];
      in.beginGroup(QString("view%1").arg(v + 1));
      const QString scheme = in.value("scheme", view.Scheme->currentText()).toString();
      if (subdapp::FindScheme(scheme.toStdString()))
      {
        view.Scheme->setCurrentText(scheme); // resets the tension to the scheme's default
      }
      view.Boundary->setCurrentIndex(in.value("boundary", view.Boundary->currentIndex()).toInt());
      view.Tension->setValue(in.value("tension", view.Tension->value()).toDouble());
      view.CreaseMethod->setCurrentIndex(in.value("creaseMethod", view.CreaseMethod->currentIndex()).toInt());
      view.FaceVarying->setCurrentIndex(in.value("fvarInterpolation", view.FaceVarying->currentIndex()).toInt());
      view.Limit->setChecked(in.value("limit", view.Limit->isChecked()).toBool());
      in.endGroup();
    }
    this->SetViewCount(in.value("views", this->ViewCount).toInt());
    this->LevelSlider->setValue(in.value("level", this->LevelSlider->value()).toInt());
    this->SetTolerance(in.value("tolerance", this->GetTolerance()).toDouble());
    this->SetColoring(in.value("coloring", this->Coloring->currentText()).toString().toStdString());
    this->SetColorMap(in.value("colorMap", this->ColorMap->currentText()).toString().toStdString());
    this->SetColorRange(in.value("rangeSymmetric", this->RangeMode->currentIndex() == 0).toBool(),
      in.value("rangePercentile", this->RangePercentile->value()).toDouble());
    this->SetShowCage(in.value("cage", this->ShowCage->isChecked()).toBool());
    this->SetCageOpacity(in.value("cageOpacity", this->Scene->GetCageOpacity()).toDouble());
    this->SetShowWireframe(in.value("wireframe", this->ShowWireframe->isChecked()).toBool());
    this->SetShowTexture(in.value("texture", this->ShowTexture->isChecked()).toBool());
    in.endGroup();
  });
  this->restoreGeometry(in.value("window/geometry").toByteArray());
  this->restoreState(in.value("window/state").toByteArray());
}

void ExplorerWindow::SaveSettings()
{
  if (!this->Settings)
  {
    return;
  }
  QSettings& out = *this->Settings;
  out.beginGroup("layout");
  for (int v = 0; v < MaxViews; ++v)
  {
    const ViewControls& view = this->Views[v];
    out.beginGroup(QString("view%1").arg(v + 1));
    out.setValue("scheme", view.Scheme->currentText());
    out.setValue("boundary", view.Boundary->currentIndex());
    out.setValue("tension", view.Tension->value());
    out.setValue("creaseMethod", view.CreaseMethod->currentIndex());
    out.setValue("fvarInterpolation", view.FaceVarying->currentIndex());
    out.setValue("limit", view.Limit->isChecked());
    out.endGroup();
  }
  out.setValue("views", this->ViewCount);
  out.setValue("level", this->LevelSlider->value());
  out.setValue("tolerance", this->GetTolerance());
  out.setValue("coloring", this->Coloring->currentText());
  out.setValue("colorMap", this->ColorMap->currentText());
  out.setValue("rangeSymmetric", this->RangeMode->currentIndex() == 0);
  out.setValue("rangePercentile", this->RangePercentile->value());
  out.setValue("cage", this->ShowCage->isChecked());
  out.setValue("cageOpacity", this->Scene->GetCageOpacity());
  out.setValue("wireframe", this->ShowWireframe->isChecked());
  out.setValue("texture", this->ShowTexture->isChecked());
  out.endGroup();
  out.setValue("window/geometry", this->saveGeometry());
  out.setValue("window/state", this->saveState());
  out.sync();
}

std::string ExplorerWindow::DescribeState() const
{
  std::ostringstream out;
  out << "views " << this->ViewCount << "\n";
  for (int v = 0; v < this->ViewCount; ++v)
  {
    const ViewControls& view = this->Views[v];
    out << "view " << v + 1 << " " << view.Scheme->currentText().toStdString() << " boundary "
        << view.Boundary->currentText().toStdString() << " tension " << view.Tension->value() << " creases "
        << view.CreaseMethod->currentText().toStdString() << " uv-seams "
        << view.FaceVarying->currentText().toStdString() << " limit " << (view.Limit->isChecked() ? "on" : "off")
        << "\n";
  }
  out << "level " << this->LevelSlider->value() << "\n"
      << "tolerance ";
  if (this->GetTolerance() > 0.0)
    out << this->GetTolerance() << "\n";
  else
    out << "off\n";
  out
      << "color " << this->Coloring->currentText().toStdString() << "\n"
      << "colormap " << this->ColorMap->currentText().toStdString() << "\n"
      << "range " << this->RangeMode->currentText().toStdString() << " " << this->RangePercentile->value() << "\n"
      << "cage " << (this->ShowCage->isChecked() ? "on" : "off") << " opacity " << this->Scene->GetCageOpacity()
      << "\n"
      << "wireframe " << (this->ShowWireframe->isChecked() ? "on" : "off") << "\n"
      << "texture " << (this->ShowTexture->isChecked() ? "on" : "off") << "\n";
  return out.str();
}
}
