// subd: collects the error and warning messages of VTK objects instead of letting them go to
// VTK's output window, so the program can print them as one clear line each.
#ifndef SubDMessageCollector_h
#define SubDMessageCollector_h

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"

#include <cctype>
#include <string>

namespace subdapp
{
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
}

#endif
