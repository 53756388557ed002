#include "SubDExplorerOptions.h"

#include "SubDArgumentReader.h"
#include "SubDBuiltinCages.h"
#include "SubDSchemeRegistry.h"

#include "vtkSubDScene.h"

#include <cstdlib>
#include <sstream>

namespace subdexplorer
{
using subdapp::ArgumentReader;

namespace
{
// Parses `text` as an integer in [low, high] into `out`; else says `what` in `error`.
bool IntegerIn(const std::string& text, long low, long high, const char* what, int& out, std::string& error)
{
  char* end = nullptr;
  const long number = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || number < low || number > high)
  {
    error = std::string(what) + ", not '" + text + "'";
    return false;
  }
  out = static_cast<int>(number);
  return true;
}

// Reads "A" or "A-B" (vertex ids >= 0) at the start of `text` into a and b (b = -1 for "A").
// Returns where the ids end, or nullptr when they are malformed.
const char* ReadVertexIds(const char* text, long long& a, long long& b)
{
  char* end = nullptr;
  a = std::strtoll(text, &end, 10);
  b = -1;
  if (end == text || a < 0)
  {
    return nullptr;
  }
  if (*end == '-')
  {
    const char* second = end + 1;
    b = std::strtoll(second, &end, 10);
    if (end == second || b < 0)
    {
      return nullptr;
    }
  }
  return end;
}
}

std::string ExplorerUsage()
{
  std::ostringstream out;
  out << "usage: subd-explorer [FILE] [--builtin NAME] [--views 1|2|4] [--schemes S1,S2,...]\n"
         "                     [--levels N] [--color none|mean|gaussian|k1|k2] [--limit]\n"
         "                     [--colormap cool-to-warm|rainbow|black-body|grayscale]\n"
         "                     [--range symmetric|percentile] [--percentile P] [--no-cage]\n"
         "                     [--cage-opacity O] [--wireframe] [--size WxH]\n"
         "                     [--screenshot VIEWS.png] [--window-shot WINDOW.png]\n"
         "                     [--crease A-B=S]... [--corner V=S]... [--select A-B|V]\n"
         "                     [--export-cage CAGE.vtp] [--cancel-after MS] [--time-edits N]\n"
         "                     [--no-settings | --settings FILE.ini] [--print-state] [--quit]\n"
         "\n"
         "Compares subdivision schemes side by side on a mesh (.vtp .vtk .obj .ply .stl .off)\n"
         "or a built-in cage. --screenshot/--window-shot save pictures once the views are up to\n"
         "date; with --quit the app then exits (scripted use, e.g. under xvfb-run).\n"
         "--cancel-after MS presses Cancel MS milliseconds into the first update (as the\n"
         "Cancel button does) and reports whether the update stopped. --crease and --corner\n"
         "set the sharpness of a cage edge or vertex as the Creases panel does; --select\n"
         "selects one (marked in the views) as Ctrl+click does. --time-edits N times N\n"
         "sharpness edits (subdivision and drawing) and prints the figures.\n"
         "The layout (views, schemes, options, colouring, overlays) is remembered between\n"
         "runs; options given on the command line override it. --no-settings neither reads\n"
         "nor writes it; --print-state prints it once the views are up to date.\n";
  return out.str();
}

bool ParseExplorerOptions(int argc, char* argv[], ExplorerOptions& options, std::string& error)
{
  for (ArgumentReader arguments(argc, argv); arguments.Next();)
  {
    const std::string arg = arguments.Current();
    auto value = [&](std::string& out) { return arguments.Value(out, error); };
    std::string text;
    options.Given.insert(arg);
    if (arg == "-h" || arg == "--help")
    {
      options.Help = true;
    }
    else if (arg == "--builtin")
    {
      if (!value(options.Builtin))
      {
        return false;
      }
      if (!subdapp::MakeBuiltinCage(options.Builtin))
      {
        error = "unknown built-in cage '" + options.Builtin + "'";
        return false;
      }
    }
    else if (arg == "--views")
    {
      if (!value(text))
      {
        return false;
      }
      if (text != "1" && text != "2" && text != "4")
      {
        error = "--views wants 1, 2 or 4, not '" + text + "'";
        return false;
      }
      options.Views = std::atoi(text.c_str());
    }
    else if (arg == "--schemes")
    {
      if (!value(text))
      {
        return false;
      }
      options.Schemes.clear();
      std::istringstream in(text);
      std::string name;
      while (std::getline(in, name, ','))
      {
        if (!subdapp::FindScheme(name))
        {
          error = "unknown scheme '" + name + "'";
          return false;
        }
        options.Schemes.push_back(name);
      }
    }
    else if (arg == "--levels")
    {
      if (!value(text) || !IntegerIn(text, 0, 8, "--levels wants an integer in 0..8", options.Levels, error))
      {
        return false;
      }
    }
    else if (arg == "--cancel-after")
    {
      if (!value(text) ||
        !IntegerIn(text, 0, 600000, "--cancel-after wants milliseconds in 0..600000", options.CancelAfter, error))
      {
        return false;
      }
    }
    else if (arg == "--crease" || arg == "--corner")
    {
      if (!value(text))
      {
        return false;
      }
      ExplorerOptions::SharpnessEdit edit;
      const char* ids = ReadVertexIds(text.c_str(), edit.A, edit.B);
      const bool shapeOk = ids && *ids == '=' && (arg == "--corner") == (edit.B < 0);
      char* end = nullptr;
      if (shapeOk)
      {
        edit.Sharpness = std::strtod(ids + 1, &end);
      }
      if (!shapeOk || *end != '\0' || end == ids + 1 || !(edit.Sharpness >= 0.0))
      {
        error = arg + (arg == "--crease" ? " wants A-B=S (two vertex ids and a sharpness >= 0), not '"
                                         : " wants V=S (a vertex id and a sharpness >= 0), not '") + text + "'";
        return false;
      }
      options.Edits.push_back(edit);
    }
    else if (arg == "--export-cage")
    {
      if (!value(options.ExportCage))
      {
        return false;
      }
    }
    else if (arg == "--select")
    {
      if (!value(text))
      {
        return false;
      }
      const char* end = ReadVertexIds(text.c_str(), options.SelectA, options.SelectB);
      if (!end || *end != '\0')
      {
        error = "--select wants A-B (an edge's two vertex ids) or V (a vertex id), not '" + text + "'";
        return false;
      }
    }
    else if (arg == "--color")
    {
      if (!value(options.Color))
      {
        return false;
      }
      if (vtkSubDScene::ColoringFromName(options.Color.c_str()) < 0)
      {
        error = "--color wants none, mean, gaussian, k1 or k2, not '" + options.Color + "'";
        return false;
      }
    }
    else if (arg == "--colormap")
    {
      if (!value(options.ColorMap))
      {
        return false;
      }
      if (vtkSubDScene::ColorMapFromName(options.ColorMap.c_str()) < 0)
      {
        error = "--colormap wants cool-to-warm, rainbow, black-body or grayscale, not '" + options.ColorMap + "'";
        return false;
      }
    }
    else if (arg == "--range")
    {
      if (!value(text))
      {
        return false;
      }
      if (text != "symmetric" && text != "percentile")
      {
        error = "--range wants symmetric or percentile, not '" + text + "'";
        return false;
      }
      options.RangeSymmetric = text == "symmetric";
    }
    else if (arg == "--percentile")
    {
      if (!value(text) ||
        !IntegerIn(text, 50, 100, "--percentile wants an integer in 50..100", options.RangePercentile, error))
      {
        return false;
      }
    }
    else if (arg == "--cage-opacity")
    {
      if (!value(text))
      {
        return false;
      }
      char* end = nullptr;
      options.CageOpacity = std::strtod(text.c_str(), &end);
      if (text.empty() || *end != '\0' || !(options.CageOpacity >= 0.0 && options.CageOpacity <= 1.0))
      {
        error = "--cage-opacity wants a number in [0, 1], not '" + text + "'";
        return false;
      }
    }
    else if (arg == "--time-edits")
    {
      if (!value(text) || !IntegerIn(text, 1, 1000, "--time-edits wants an integer in 1..1000", options.TimeEdits, error))
      {
        return false;
      }
    }
    else if (arg == "--settings")
    {
      if (!value(options.SettingsFile))
      {
        return false;
      }
    }
    else if (arg == "--no-settings")
    {
      options.NoSettings = true;
    }
    else if (arg == "--print-state")
    {
      options.PrintState = true;
    }
    else if (arg == "--wireframe")
    {
      options.Wireframe = true;
    }
    else if (arg == "--size")
    {
      if (!value(text))
      {
        return false;
      }
      const auto x = text.find('x');
      options.Width = x == std::string::npos ? 0 : std::atoi(text.substr(0, x).c_str());
      options.Height = x == std::string::npos ? 0 : std::atoi(text.substr(x + 1).c_str());
      if (options.Width < 200 || options.Height < 200 || options.Width > 8192 || options.Height > 8192)
      {
        error = "--size wants WxH, each in 200..8192, not '" + text + "'";
        return false;
      }
    }
    else if (arg == "--screenshot" || arg == "--window-shot")
    {
      if (!value(arg == "--screenshot" ? options.Screenshot : options.WindowShot))
      {
        return false;
      }
    }
    else if (arg == "--no-cage")
    {
      options.Cage = false;
    }
    else if (arg == "--limit")
    {
      options.Limit = true;
    }
    else if (arg == "--quit")
    {
      options.Quit = true;
    }
    else if (!arg.empty() && arg[0] == '-')
    {
      error = "unknown option '" + arg + "'";
      return false;
    }
    else if (options.Load.empty())
    {
      options.Load = arg;
    }
    else
    {
      error = "more than one file ('" + options.Load + "', '" + arg + "')";
      return false;
    }
  }
  if (options.NoSettings && !options.SettingsFile.empty())
  {
    error = "--no-settings and --settings exclude each other";
    return false;
  }
  return true;
}
}
