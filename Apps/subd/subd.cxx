// subd: the command-line program. Reads a polygon mesh (or takes a built-in cage), subdivides
// it with the chosen scheme and writes the result, printing a one-line summary.
#include "SubDBuiltinCages.h"
#include "SubDCommandLine.h"
#include "SubDImage.h"
#include "SubDMeshIO.h"
#include "SubDMessageCollector.h"
#include "SubDSchemeRegistry.h"

#include "vtkCallbackCommand.h"
#include "vtkLogger.h"
#include "vtkPolyData.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkVersion.h"

#include <chrono>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sys/stat.h>
#include <unistd.h>

namespace
{
using Clock = std::chrono::steady_clock;

// A progress bar on stderr, drawn only when stderr is a terminal and the work has already
// taken half a second (short runs stay quiet).
struct ProgressBar
{
  Clock::time_point Start = Clock::now();
  bool Enabled = ::isatty(STDERR_FILENO) != 0;
  bool Drawn = false;

  static void OnProgress(vtkObject*, unsigned long, void* client, void* callData)
  {
    auto* self = static_cast<ProgressBar*>(client);
    const double fraction = *static_cast<double*>(callData);
    if (!self->Enabled || std::chrono::duration<double>(Clock::now() - self->Start).count() < 0.5)
    {
      return;
    }
    const int width = 40;
    const int filled = static_cast<int>(fraction * width + 0.5);
    std::fprintf(stderr, "\r[%s%s] %3d%%", std::string(filled, '#').c_str(),
      std::string(width - filled, ' ').c_str(), static_cast<int>(fraction * 100 + 0.5));
    std::fflush(stderr);
    self->Drawn = true;
  }
  void Finish()
  {
    if (this->Drawn)
    {
      std::fprintf(stderr, "\r%60s\r", "");
    }
  }
};

bool SameFile(const std::string& a, const std::string& b)
{
  struct stat sa, sb;
  return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev &&
    sa.st_ino == sb.st_ino;
}

void PrintMessages(const std::string& lines, const char* kind)
{
  subdapp::PrintMessageLines("subd: ", lines, kind);
}

// The input mesh, or the built-in cage; null (the reason printed) if it cannot be read.
vtkSmartPointer<vtkPolyData> ReadInput(const subdapp::CommandLine& cmd, std::string& inputName)
{
  if (cmd.Input.empty())
  {
    inputName = "built-in " + cmd.Builtin;
    return subdapp::MakeBuiltinCage(cmd.Builtin);
  }
  inputName = cmd.Input;
  std::string error;
  vtkSmartPointer<vtkPolyData> input = subdapp::ReadMesh(cmd.Input, error);
  if (!input)
  {
    std::cerr << "subd: " << error << "\n";
  }
  return input;
}

// 0 if `output` may be written, else the exit code (the reason printed).
int CheckOutput(const subdapp::CommandLine& cmd, const std::string& output)
{
  if (!cmd.Input.empty() && SameFile(cmd.Input, output))
  {
    std::cerr << "subd: refusing to overwrite the input file '" << cmd.Input << "'\n";
    return 1;
  }
  if (subdapp::WritesMesh(cmd) && !subdapp::CanWrite(output))
  {
    std::cerr << "subd: cannot write '" << output << "': unknown output type (supported: "
              << subdapp::WritableExtensions() << ")\n";
    return 2;
  }
  return 0;
}

// Runs `filter` on `cage` with a progress bar; its output, or null (the messages printed).
vtkPolyData* Subdivide(vtkPolyDataAlgorithm* filter, vtkPolyData* cage)
{
  subdapp::MessageCollector messages;
  messages.Watch(filter);
  ProgressBar progress;
  vtkNew<vtkCallbackCommand> progressCallback;
  progressCallback->SetClientData(&progress);
  progressCallback->SetCallback(&ProgressBar::OnProgress);
  filter->AddObserver(vtkCommand::ProgressEvent, progressCallback);
  filter->SetInputData(cage);
  filter->Update();
  progress.Finish();
  PrintMessages(messages.Warnings, "warning");
  vtkPolyData* result = filter->GetOutput();
  if (!messages.Errors.empty() || filter->GetErrorCode() != 0 || result->GetNumberOfCells() == 0)
  {
    PrintMessages(messages.Errors.empty() ? "subdivision produced no output\n" : messages.Errors, "error");
    return nullptr;
  }
  return result;
}

// The one-line summary: input, interpolation, scheme and levels, output, time, files.
void PrintSummary(const subdapp::CommandLine& cmd, const subdapp::SchemeEntry& scheme, const std::string& inputName,
  vtkPolyData* input, const subdapp::InterpolationResult& interpolation, vtkPolyData* result, double seconds,
  const std::string& output)
{
  std::cout << "subd: " << inputName << " (" << input->GetNumberOfPoints() << " points, "
            << (scheme.Curve ? input->GetNumberOfLines() : input->GetNumberOfPolys() + input->GetNumberOfStrips())
            << (scheme.Curve ? " curves) -> " : " faces) -> ");
  if (cmd.Interpolate)
  {
    std::cout << "interpolating " << (scheme.Curve ? "polygons" : "cage") << " through " << interpolation.NumTagged
              << " points (residual " << interpolation.Residual << ") -> ";
  }
  if (cmd.Options.Tolerance > 0.0)
  {
    std::cout << cmd.Scheme << " limit within " << cmd.Options.Tolerance << " of the diagonal (levels <= "
              << cmd.Options.Levels << ") -> " << result->GetNumberOfPoints() << " points, ";
  }
  else
  {
    std::cout << cmd.Scheme << ", " << cmd.Options.Levels << " level(s) -> " << result->GetNumberOfPoints()
              << " points, ";
  }
  if (scheme.Curve)
  {
    std::cout << result->GetNumberOfLines() << " curves";
  }
  else
  {
    std::cout << result->GetNumberOfPolys() << " faces";
    if (result->GetNumberOfLines() > 0)
    {
      std::cout << ", " << result->GetNumberOfLines() << " crease edges";
    }
  }
  std::cout << " in " << seconds << " s";
  if (subdapp::WritesMesh(cmd))
  {
    std::cout << " -> " << output;
  }
  if (!cmd.Image.empty())
  {
    std::cout << " -> image " << cmd.Image;
  }
  std::cout << "\n";
}
}

int main(int argc, char* argv[])
{
  vtkNew<subdapp::QuietOutputWindow> outputWindow;
  vtkOutputWindow::SetInstance(outputWindow);
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF); // messages come through outputWindow
  subdapp::CommandLine cmd;
  std::string error;
  if (!subdapp::ParseCommandLine(argc, argv, cmd, error) || !subdapp::CheckImageOptions(cmd, error))
  {
    std::cerr << "subd: " << error << "\n";
    return 2;
  }
  if (cmd.Help)
  {
    std::cout << subdapp::UsageText();
    return 0;
  }
  if (cmd.Version)
  {
    std::cout << "subd " << SUBD_VERSION << " (VTK " << vtkVersion::GetVTKVersion() << ")\n";
    return 0;
  }

  std::string inputName;
  vtkSmartPointer<vtkPolyData> input = ReadInput(cmd, inputName);
  if (!input)
  {
    return 1;
  }
  const std::string output = cmd.Output.empty() ? subdapp::DefaultOutputPath(cmd) : cmd.Output;
  if (const int code = CheckOutput(cmd, output))
  {
    return code;
  }
  const subdapp::SchemeEntry* scheme = subdapp::FindScheme(cmd.Scheme);
  const Clock::time_point start = Clock::now();
  vtkSmartPointer<vtkPolyData> cage = input;
  subdapp::InterpolationResult interpolation;
  if (cmd.Interpolate)
  {
    subdapp::MessageCollector solverMessages;
    interpolation = subdapp::RunInterpolation(*scheme, cmd.Options, input, solverMessages);
    PrintMessages(solverMessages.Warnings, "warning");
    if (!interpolation.Cage)
    {
      PrintMessages(solverMessages.Errors.empty() ? "the interpolation failed\n" : solverMessages.Errors, "error");
      return 1;
    }
    cage = interpolation.Cage;
  }
  vtkSmartPointer<vtkPolyDataAlgorithm> filter = scheme->Make(cmd.Options);
  vtkPolyData* result = Subdivide(filter, cage);
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (!result)
  {
    return 1;
  }
  if (subdapp::WritesMesh(cmd) && !subdapp::WriteMesh(result, output, error, cmd.Compress))
  {
    std::cerr << "subd: " << error << "\n";
    return 1;
  }
  if (!cmd.Image.empty())
  {
    std::string warnings;
    const bool rendered = subdapp::RenderImage(cmd, cage, result, warnings, error);
    PrintMessages(warnings, "warning");
    if (!rendered)
    {
      std::cerr << "subd: " << error << "\n";
      return 1;
    }
  }
  if (!cmd.Quiet)
  {
    PrintSummary(cmd, *scheme, inputName, input, interpolation, result, seconds, output);
  }
  return 0;
}
