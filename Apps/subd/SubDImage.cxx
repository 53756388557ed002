#include "SubDImage.h"

#include "SubDMessageCollector.h"
#include "SubDSchemeRegistry.h"

#include "vtkPolyData.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"
#include "vtkSubDScene.h"

#include <sstream>
#include <vector>

namespace subdapp
{
namespace
{
// "loop, 3 levels", or for an adaptive tessellation "loop limit, tolerance 0.001".
std::string TitleOf(const std::string& scheme, const SchemeOptions& options)
{
  if (options.Tolerance > 0.0)
  {
    std::ostringstream title;
    title << scheme << " limit, tolerance " << options.Tolerance;
    return title.str();
  }
  return scheme + ", " + std::to_string(options.Levels) + (options.Levels == 1 ? " level" : " levels");
}
}

bool CheckImageOptions(const CommandLine& cmd, std::string& error)
{
  if (vtkSubDScene::ColoringFromName(cmd.Color.c_str()) < 0)
  {
    error = "--color wants none, mean, gaussian, k1 or k2, not '" + cmd.Color + "'";
    return false;
  }
  return true;
}

bool RenderImage(const CommandLine& cmd, vtkPolyData* cage, vtkPolyData* result, std::string& warnings,
  std::string& error)
{
  vtkNew<vtkSubDScene> scene;
  MessageCollector sceneMessages;
  sceneMessages.Watch(scene);
  sceneMessages.Watch(scene->GetRenderWindow());
  scene->SetColoring(vtkSubDScene::ColoringFromName(cmd.Color.c_str()));
  scene->SetShowCage(cmd.Cage);
  scene->SetShowWireframe(cmd.Options.Tolerance > 0.0); // an adaptive tessellation shows its triangles
  scene->SetViewSize(cmd.ViewSize[0], cmd.ViewSize[1]);
  std::vector<vtkSmartPointer<vtkPolyData>> keep; // the compared results outlive their filters
  if (cmd.Compare.empty())
  {
    scene->AddView(result, cage, TitleOf(cmd.Scheme, cmd.Options).c_str());
  }
  for (const std::string& name : cmd.Compare)
  {
    if (name == cmd.Scheme) // subdivided already
    {
      scene->AddView(result, cage, TitleOf(name, cmd.Options).c_str());
      continue;
    }
    MessageCollector messages;
    vtkSmartPointer<vtkPolyData> copy = RunScheme(*FindScheme(name), cmd.Options, cage, messages);
    warnings += messages.Warnings;
    if (!copy)
    {
      error = "--compare: the " + name + " scheme failed: " +
        (messages.Errors.empty() ? std::string("no output") : messages.Errors);
      return false;
    }
    keep.push_back(copy);
    scene->AddView(copy, cage, TitleOf(name, cmd.Options).c_str());
  }
  if (!scene->WritePNG(cmd.Image.c_str()))
  {
    error = "cannot render '" + cmd.Image + "': " +
      (sceneMessages.Errors.empty() ? std::string("rendering failed") : sceneMessages.Errors);
    return false;
  }
  return true;
}
}
