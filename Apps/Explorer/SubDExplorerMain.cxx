// SubD Explorer: compare subdivision schemes side by side (Qt5 + VTK).
#include "SubDExplorerOptions.h"
#include "SubDExplorerWindow.h"

#include "QVTKOpenGLNativeWidget.h"
#include "vtkCellArray.h"
#include "vtkPolyData.h"
#include "vtkSubDSurfaceFilter.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QSettings>
#include <QSurfaceFormat>
#include <QTimer>

#include <algorithm>
#include <iostream>
#include <vector>

namespace
{
using subdexplorer::ExplorerOptions;
using subdexplorer::ExplorerWindow;

// The command line's settings, over the remembered layout: only the options given.
void ApplyOptions(const ExplorerOptions& options, ExplorerWindow& window)
{
  auto given = [&](const char* name) { return options.Given.count(name) > 0; };
  for (size_t v = 0; v < options.Schemes.size() && v < ExplorerWindow::MaxViews; ++v)
  {
    window.SetScheme(static_cast<int>(v), options.Schemes[v]);
  }
  if (given("--views"))
    window.SetViewCount(options.Views);
  if (given("--levels"))
    window.SetLevels(options.Levels);
  if (given("--tolerance"))
    window.SetTolerance(options.Tolerance);
  if (given("--color"))
    window.SetColoring(options.Color);
  if (given("--colormap"))
    window.SetColorMap(options.ColorMap);
  if (given("--range") || given("--percentile"))
    window.SetColorRange(options.RangeSymmetric, options.RangePercentile);
  if (given("--no-cage"))
    window.SetShowCage(false);
  if (given("--cage-opacity"))
    window.SetCageOpacity(options.CageOpacity);
  if (given("--wireframe"))
    window.SetShowWireframe(true);
  if (given("--texture"))
    window.SetShowTexture(true);
  if (given("--fvar-interpolation"))
    window.SetFaceVaryingInterpolation(vtkSubDSurfaceFilter::FaceVaryingInterpolationFromName(options.FaceVarying.c_str()));
  if (given("--limit"))
    window.SetLimit(true);
}

// --time-edits: sets the sharpness of `count` cage edges in turn (2, then back to 0 on the
// next pass), each through the Creases panel's SetSharpness, waits for the views, and prints
// the median and worst times of the whole edit, the subdivision and the scene.
bool TimeEdits(ExplorerWindow& window, int count)
{
  vtkPolyData* cage = window.GetCage();
  std::vector<std::pair<vtkIdType, vtkIdType>> edges;
  vtkCellArray* polys = cage->GetPolys();
  const vtkIdType stride = std::max<vtkIdType>(1, polys->GetNumberOfCells() / std::max(1, count));
  vtkIdType size;
  const vtkIdType* ids;
  vtkIdType cell = 0;
  for (polys->InitTraversal(); polys->GetNextCell(size, ids); ++cell)
  {
    if (cell % stride == 0 && static_cast<int>(edges.size()) < count)
    {
      edges.emplace_back(ids[0], ids[1]);
    }
  }
  if (edges.empty())
  {
    std::cerr << "subd-explorer: --time-edits needs a cage with polygons\n";
    return false;
  }
  std::vector<double> total, subdivision, scene;
  for (int k = 0; k < count; ++k)
  {
    const auto& edge = edges[static_cast<size_t>(k) % edges.size()];
    const double sharpness = (k / edges.size()) % 2 == 0 ? 2.0 : 0.0;
    QElapsedTimer clock;
    clock.start();
    QString message;
    if (!window.SetSharpness(edge.first, edge.second, sharpness, message))
    {
      std::cerr << "subd-explorer: " << message.toStdString() << "\n";
      return false;
    }
    window.WaitForUpdate();
    total.push_back(static_cast<double>(clock.nsecsElapsed()) * 1e-6);
    subdivision.push_back(window.GetLastSubdivisionMilliseconds());
    scene.push_back(window.GetLastSceneMilliseconds());
  }
  auto report = [](const char* what, std::vector<double> values) {
    std::sort(values.begin(), values.end());
    std::cout << "  " << what << ": median " << values[values.size() / 2] << " ms, worst " << values.back()
              << " ms\n";
  };
  std::cout << "subd-explorer: " << count << " sharpness edits on a cage of " << cage->GetNumberOfPolys()
            << " faces\n";
  report("edit to picture", total);
  report("subdivision (worker)", subdivision);
  report("scene (colouring, overlays, render)", scene);
  return true;
}

// The cage the options name (a file or a built-in), with their sharpness edits and
// selection, exported if asked. False with `error` on failure.
bool SetUpCage(const ExplorerOptions& options, ExplorerWindow& window, std::string& error)
{
  QString message;
  bool done = true;
  if (options.Load.empty())
  {
    window.LoadBuiltin(options.Builtin);
  }
  else
  {
    done = window.LoadFile(QString::fromStdString(options.Load), message);
  }
  for (size_t k = 0; done && k < options.Edits.size(); ++k)
  {
    const ExplorerOptions::SharpnessEdit& edit = options.Edits[k];
    done = window.SetSharpness(edit.A, edit.B, edit.Sharpness, message);
  }
  if (!done)
  {
    error = message.toStdString();
    return false;
  }
  if (options.SelectA >= 0 && !window.SelectCageElement(options.SelectA, options.SelectB))
  {
    error = "--select: " + std::to_string(options.SelectA) +
      (options.SelectB >= 0 ? "-" + std::to_string(options.SelectB) : std::string()) +
      " is not a vertex or an edge of the cage";
    return false;
  }
  if (!options.ExportCage.empty() && !window.ExportCage(QString::fromStdString(options.ExportCage), message))
  {
    error = message.toStdString();
    return false;
  }
  return true;
}

// The scripted steps once the first update is done (its cancel, timing, state, pictures);
// returns the exit status they call for.
int RunScriptedSteps(const ExplorerOptions& options, ExplorerWindow& window)
{
  int status = 0;
  window.UpdateViews();
  QElapsedTimer clock;
  clock.start();
  if (options.CancelAfter >= 0)
  {
    QTimer::singleShot(options.CancelAfter, &window, [&window, clock]() {
      std::cout << "subd-explorer: cancel pressed after " << clock.elapsed() << " ms" << std::endl;
      window.CancelUpdate();
    });
  }
  window.WaitForUpdate();
  if (options.CancelAfter >= 0)
  {
    std::cout << "subd-explorer: update " << (window.WasLastUpdateCancelled() ? "cancelled" : "completed")
              << ", worker done after " << clock.elapsed() << " ms" << std::endl;
  }
  if (options.TimeEdits > 0 && !TimeEdits(window, options.TimeEdits))
  {
    status = 1;
  }
  if (options.PrintState)
  {
    std::cout << window.DescribeState() << std::flush;
  }
  QString message;
  if (!options.Screenshot.empty() && !window.SaveViewsImage(QString::fromStdString(options.Screenshot), message))
  {
    std::cerr << "subd-explorer: " << message.toStdString() << "\n";
    status = 1;
  }
  if (!options.WindowShot.empty() && !window.SaveWindowImage(QString::fromStdString(options.WindowShot), message))
  {
    std::cerr << "subd-explorer: " << message.toStdString() << "\n";
    status = 1;
  }
  return status;
}
}

int main(int argc, char* argv[])
{
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv); // removes Qt's own options from argv
  QApplication::setOrganizationName("SubD");
  QApplication::setApplicationName("SubD Explorer");

  ExplorerOptions options;
  std::string error;
  if (!subdexplorer::ParseExplorerOptions(argc, argv, options, error))
  {
    std::cerr << "subd-explorer: " << error << "\n" << subdexplorer::ExplorerUsage();
    return 2;
  }
  if (options.Help)
  {
    std::cout << subdexplorer::ExplorerUsage();
    return 0;
  }

  ExplorerWindow window;
  if (!options.NoSettings)
  {
    window.UseSettings(options.SettingsFile.empty()
        ? std::make_unique<QSettings>()
        : std::make_unique<QSettings>(QString::fromStdString(options.SettingsFile), QSettings::IniFormat));
  }
  if (options.Given.count("--size") || options.NoSettings)
  {
    window.resize(options.Width, options.Height);
  }
  ApplyOptions(options, window);
  if (!SetUpCage(options, window, error))
  {
    std::cerr << "subd-explorer: " << error << "\n";
    return 1;
  }
  window.show();

  int status = 0;
  QTimer::singleShot(0, &window, [&]() {
    status = RunScriptedSteps(options, window);
    if (options.Quit)
    {
      QApplication::exit(status);
    }
  });
  const int result = app.exec();
  window.SaveSettings();
  return status != 0 ? status : result;
}
