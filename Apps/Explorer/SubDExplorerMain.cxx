// SubD Explorer: compare subdivision schemes side by side (Qt5 + VTK).
#include "SubDExplorerOptions.h"
#include "SubDExplorerWindow.h"

#include "QVTKOpenGLNativeWidget.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QSurfaceFormat>
#include <QTimer>

#include <iostream>

int main(int argc, char* argv[])
{
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv); // removes Qt's own options from argv
  QApplication::setOrganizationName("SubD");
  QApplication::setApplicationName("SubD Explorer");

  subdexplorer::ExplorerOptions options;
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

  subdexplorer::ExplorerWindow window;
  window.resize(options.Width, options.Height);
  for (size_t v = 0; v < options.Schemes.size() && v < subdexplorer::ExplorerWindow::MaxViews; ++v)
  {
    window.SetScheme(static_cast<int>(v), options.Schemes[v]);
  }
  window.SetViewCount(options.Views);
  window.SetLevels(options.Levels);
  window.SetColoring(options.Color);
  window.SetShowCage(options.Cage);
  window.SetLimit(options.Limit);
  if (!options.Load.empty())
  {
    QString message;
    if (!window.LoadFile(QString::fromStdString(options.Load), message))
    {
      std::cerr << "subd-explorer: " << message.toStdString() << "\n";
      return 1;
    }
  }
  else
  {
    window.LoadBuiltin(options.Builtin);
  }
  for (const subdexplorer::ExplorerOptions::SharpnessEdit& edit : options.Edits)
  {
    QString message;
    if (!window.SetSharpness(edit.A, edit.B, edit.Sharpness, message))
    {
      std::cerr << "subd-explorer: " << message.toStdString() << "\n";
      return 1;
    }
  }
  if (!options.ExportCage.empty())
  {
    QString message;
    if (!window.ExportCage(QString::fromStdString(options.ExportCage), message))
    {
      std::cerr << "subd-explorer: " << message.toStdString() << "\n";
      return 1;
    }
  }
  window.show();

  int status = 0;
  QTimer::singleShot(0, &window, [&]() {
    window.UpdateViews();
    QElapsedTimer clock;
    clock.start();
    if (options.CancelAfter >= 0)
    {
      QTimer::singleShot(options.CancelAfter, &window, [&]() {
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
    QString message;
    if (!options.Screenshot.empty() && !window.SaveViewsImage(QString::fromStdString(options.Screenshot), message))
    {
      std::cerr << "subd-explorer: " << message.toStdString() << "\n";
      status = 1;
    }
    if (!options.WindowShot.empty() &&
      !window.SaveWindowImage(QString::fromStdString(options.WindowShot), message))
    {
      std::cerr << "subd-explorer: " << message.toStdString() << "\n";
      status = 1;
    }
    if (options.Quit)
    {
      QApplication::exit(status);
    }
  });
  const int result = app.exec();
  return status != 0 ? status : result;
}
