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

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
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
#include <QStatusBar>
#include <QVBoxLayout>

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
  this->Coloring = new QComboBox;
  this->Coloring->addItems({ "none", "mean", "gaussian" });
  this->Coloring->setCurrentIndex(1);
  this->Coloring->setToolTip("Curvature colouring: exact limit curvature for Catmull-Clark and Loop with "
                             "'Limit', discrete curvature of the refined mesh otherwise");
  form->addRow("Curvature", this->Coloring);
  this->ShowCage = new QCheckBox("Control cage");
  this->ShowCage->setChecked(true);
  form->addRow(this->ShowCage);
  this->Limit = new QCheckBox("Limit (project, exact curvature)");
  form->addRow(this->Limit);
  layout->addWidget(global);

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
  layout->addWidget(creases);

  for (int v = 0; v < MaxViews; ++v)
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
    view.Statistics = new QLabel;
    view.Statistics->setWordWrap(true);
    view.Statistics->setWordWrap(true);
    view.Statistics->setTextInteractionFlags(Qt::TextSelectableByMouse);
    viewForm->addRow(view.Statistics);
    layout->addWidget(view.Box);

    auto schemeChanged = [this, v]() {
      ViewControls& changed = this->Views[v];
      const std::string scheme = changed.Scheme->currentText().toStdString();
      const bool fourPoint = scheme == "four-point";
      const bool updating = this->Updating;
      this->Updating = true;
      changed.Tension->setEnabled(scheme == "butterfly" || fourPoint);
      changed.Tension->setRange(fourPoint ? 0.0 : -0.0625, fourPoint ? 0.125 : 0.0625);
      changed.Tension->setValue(fourPoint ? 0.0625 : 0.0);
      changed.Boundary->setEnabled(!subdapp::FindScheme(scheme)->Curve);
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
  }
  layout->addStretch(1);

  connect(this->Layout, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
    [this](int index) { this->SetViewCount(index == 0 ? 1 : (index == 1 ? 2 : 4)); });
  connect(this->LevelSlider, &QSlider::valueChanged, this, [this](int level) {
    this->LevelLabel->setText(QString::number(level));
    if (!this->Updating)
      this->UpdateViews();
  });
  connect(this->Coloring, &QComboBox::currentTextChanged, this,
    [this](const QString& text) { this->SetColoring(text.toStdString()); });
  connect(this->ShowCage, &QCheckBox::toggled, this, [this](bool show) { this->SetShowCage(show); });
  connect(this->Limit, &QCheckBox::toggled, this, [this](bool limit) { this->SetLimit(limit); });
  this->SetViewCount(1);
  return panel;
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
  file->addAction("Export &cage with creases...", this, &ExplorerWindow::ExportCageDialog);
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
  view->addAction("&Reset camera", this,
    [this]() {
      this->Scene->ResetCamera();
      this->UpdateViews();
    },
    QKeySequence(Qt::Key_R));
}

void ExplorerWindow::SetCage(vtkSmartPointer<vtkPolyData> cage, const QString& name)
{
  this->Cage = cage;
  this->CageName = name;
  this->SelectedA = this->SelectedB = -1;
  this->SelectionLabel->setText("Ctrl+click an edge or a vertex of the cage");
  this->Sharpness->setEnabled(false);
  this->ShowCageStatistics();
  this->setWindowTitle("SubD Explorer - " + name);
  this->Scene->ResetCamera();
  this->UpdateViews();
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

void ExplorerWindow::SetColoring(const std::string& coloring)
{
  const int value = coloring == "none" ? vtkSubDScene::COLOR_NONE
                                       : (coloring == "gaussian" ? vtkSubDScene::COLOR_GAUSSIAN_CURVATURE
                                                                 : vtkSubDScene::COLOR_MEAN_CURVATURE);
  this->Scene->SetColoring(value);
  const bool updating = this->Updating;
  this->Updating = true;
  this->Coloring->setCurrentText(QString::fromStdString(coloring));
  this->Updating = updating;
  if (!this->Updating)
  {
    this->UpdateViews();
  }
}

void ExplorerWindow::SetShowCage(bool show)
{
  this->Scene->SetShowCage(show);
  this->ShowCage->setChecked(show);
  if (!this->Updating)
  {
    this->UpdateViews();
  }
}

void ExplorerWindow::SetLimit(bool limit)
{
  this->Limit->setChecked(limit);
  if (!this->Updating)
  {
    this->UpdateViews();
  }
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
  this->SelectedA = picked.A;
  this->SelectedB = picked.B;
  const bool updating = this->Updating;
  this->Updating = true;
  if (picked.A < 0)
  {
    this->SelectionLabel->setText("nothing there: Ctrl+click closer to an edge or a vertex");
    this->Sharpness->setEnabled(false);
  }
  else if (picked.B < 0)
  {
    this->SelectionLabel->setText(QString("vertex %1").arg(picked.A));
    this->Sharpness->setEnabled(true);
    this->Sharpness->setValue(subdapp::GetVertexSharpness(this->Cage, picked.A));
  }
  else
  {
    this->SelectionLabel->setText(QString("edge %1 - %2").arg(picked.A).arg(picked.B));
    this->Sharpness->setEnabled(true);
    this->Sharpness->setValue(subdapp::GetEdgeSharpness(this->Cage, picked.A, picked.B));
  }
  this->Updating = updating;
  return picked.A >= 0;
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
  options.ProjectToLimit = this->Limit->isChecked() && entry->LimitPositions;
  options.LimitCurvature = options.ProjectToLimit && entry->LimitCurvature &&
    this->Scene->GetColoring() != vtkSubDScene::COLOR_NONE;
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
  std::vector<UpdateJob::ViewTask> tasks;
  for (int v = 0; v < this->ViewCount; ++v)
  {
    tasks.push_back({ subdapp::FindScheme(this->Views[v].Scheme->currentText().toStdString()), this->ViewOptions(v) });
  }
  this->Job = std::make_unique<UpdateJob>(this->Cage, std::move(tasks));
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
  for (int v = 0; v < this->ViewCount; ++v)
  {
    this->ApplyResult(v, job->GetResults()[static_cast<size_t>(v)]);
  }
  this->Scene->RemoveAllViews();
  vtkNew<vtkPolyData> empty;
  for (int v = 0; v < this->ViewCount; ++v)
  {
    const std::string title = this->Views[v].Scheme->currentText().toStdString() + ", level " +
      std::to_string(this->LevelSlider->value());
    this->Scene->AddView(this->Views[v].Result ? this->Views[v].Result.GetPointer() : empty.GetPointer(),
      this->Cage, title.c_str());
  }
  if (this->VTKWidget->isVisible())
  {
    this->Scene->Render();
  }
  this->VTKWidget->update();
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
  QSettings settings;
  QStringList recent = settings.value("recentFiles").toStringList();
  recent.removeAll(path);
  recent.prepend(path);
  while (recent.size() > 8)
  {
    recent.removeLast();
  }
  settings.setValue("recentFiles", recent);
  this->RefreshRecentMenu();
}

void ExplorerWindow::RefreshRecentMenu()
{
  this->RecentMenu->clear();
  QSettings settings;
  for (const QString& path : settings.value("recentFiles").toStringList())
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
}
