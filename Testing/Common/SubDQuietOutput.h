// Tests and fuzz targets that check VTK messages through observers (subdapp::MessageCollector)
// do not want the rest printed: the executive's "returned failure" follow-ups (logged through
// vtkLogger), and messages of objects nobody watches. (vtkObject::GlobalWarningDisplayOff would silence the observers too.)
#ifndef SubDQuietOutput_h
#define SubDQuietOutput_h

#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"

namespace subdtest
{
class DiscardingOutputWindow : public vtkOutputWindow
{
public:
  static DiscardingOutputWindow* New();
  vtkTypeMacro(DiscardingOutputWindow, vtkOutputWindow);
  void DisplayText(const char*) override {}
  void DisplayErrorText(const char*) override {}
  void DisplayWarningText(const char*) override {}
  void DisplayGenericWarningText(const char*) override {}
  void DisplayDebugText(const char*) override {}
};
inline DiscardingOutputWindow* DiscardingOutputWindow::New()
{
  VTK_STANDARD_NEW_BODY(DiscardingOutputWindow);
}

/// Installs the discarding output window once for the process.
inline void DiscardUnobservedMessages()
{
  static bool installed = false;
  if (!installed)
  {
    vtkNew<DiscardingOutputWindow> window;
    vtkOutputWindow::SetInstance(window);
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF); // the executive logs directly
    installed = true;
  }
}
}

#endif
