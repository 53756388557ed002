// subd: collects the error and warning messages of VTK objects instead of letting them go to
// VTK's output window, so the program can print them as one clear line each.
#ifndef SubDMessageCollector_h
#define SubDMessageCollector_h

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"

#include <cctype>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>

namespace subdapp
{
/// Prints each non-empty line of `lines` to stderr as "<prefix><kind>: <line>".
inline void PrintMessageLines(const std::string& prefix, const std::string& lines, const char* kind)
{
  std::istringstream in(lines);
  std::string line;
  while (std::getline(in, line))
  {
    if (!line.empty())
    {
      std::cerr << prefix << kind << ": " << line << "\n";
    }
  }
}

class MessageCollector
{
public:
  void Watch(vtkObject* object)
  {
    vtkNew<vtkCallbackCommand> callback;
    callback->SetClientData(this);
    callback->SetCallback(&MessageCollector::Collect);
    object->AddObserver(vtkCommand::ErrorEvent, callback);
    object->AddObserver(vtkCommand::WarningEvent, callback);
  }
  std::string Errors, Warnings; ///< one message per line

private:
  static void Collect(vtkObject*, unsigned long event, void* client, void* callData)
  {
    auto* self = static_cast<MessageCollector*>(client);
    std::string text = callData ? static_cast<const char*>(callData) : "";
    // VTK messages read "In <file>, line N\n<class> (0x...): <message>": keep the message.
    const auto colon = text.find("): ");
    if (colon != std::string::npos)
    {
      text = text.substr(colon + 3);
    }
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
    {
      text.pop_back();
    }
    (event == vtkCommand::ErrorEvent ? self->Errors : self->Warnings) += text + "\n";
  }
};

/// Replaces VTK's output window: messages the program did not collect itself (from objects
/// without observers) are printed as "subd: <message>", and the executive's follow-up
/// "Algorithm ... returned failure" reports, which repeat an error already shown, are dropped.
class QuietOutputWindow : public vtkOutputWindow
{
public:
  static QuietOutputWindow* New();
  vtkTypeMacro(QuietOutputWindow, vtkOutputWindow);
  void DisplayText(const char* text) override
  {
    std::string message = text ? text : "";
    if (message.find("returned failure for request") != std::string::npos)
    {
      return;
    }
    const auto colon = message.find("): ");
    if (colon != std::string::npos)
    {
      message = message.substr(colon + 3);
    }
    while (!message.empty() && std::isspace(static_cast<unsigned char>(message.back())))
    {
      message.pop_back();
    }
    std::fprintf(stderr, "subd: %s\n", message.c_str());
  }
};
inline QuietOutputWindow* QuietOutputWindow::New()
{
  VTK_STANDARD_NEW_BODY(QuietOutputWindow);
}
}

#endif
