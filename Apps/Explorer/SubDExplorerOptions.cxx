#include "SubDExplorerOptions.h"

#include "SubDArgumentReader.h"
#include "SubDBuiltinCages.h"
#include "SubDSchemeRegistry.h"

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
}

std::string ExplorerUsage()
{
  std::ostringstream out;
  out << "usage: subd-explorer [FILE] [--builtin NAME] [--views 1|2|4] [--schemes S1,S2,...]\n"
         "                     [--levels N] [--color none|mean|gaussian] [--no-cage] [--limit]\n"
         "                     [--size WxH] [--screenshot VIEWS.png] [--window-shot WINDOW.png]\n"
         "                     [--crease A-B=S]... [--corner V=S]... [--export-cage CAGE.vtp]\n"
         "                     [--cancel-after MS] [--quit]\n"
         "\n"
         "Compares subdivision schemes side by side on a mesh (.vtp .vtk .obj .ply .stl .off)\n"
         "or a built-in cage. --screenshot/--window-shot save pictures once the views are up to\n"
         "date; with --quit the app then exits (scripted use, e.g. under xvfb-run).\n"
         "--cancel-after MS presses Cancel MS milliseconds into the first update (as the\n"
         "Cancel button does) and reports whether the update stopped. --crease and --corner\n"
         "set the sharpness of a cage edge or vertex as the Creases panel does.\n";
  return out.str();
}

bool ParseExplorerOptions(int argc, char* argv[], ExplorerOptions& options, std::string& error)
{
  for (ArgumentReader arguments(argc, argv); arguments.Next();)
  {
    const std::string arg = arguments.Current();
    auto value = [&](std::string& out) { return arguments.Value(out, error); };
    std::string text;
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
      char* end = nullptr;
      edit.A = std::strtoll(text.c_str(), &end, 10);
      if (arg == "--crease" && end != text.c_str() && *end == '-')
      {
        const char* second = end + 1;
        edit.B = std::strtoll(second, &end, 10);
        if (end == second)
        {
          edit.B = -2; // malformed
        }
      }
      const bool shapeOk = end != text.c_str() && *end == '=' && edit.A >= 0 && (arg == "--corner" || edit.B >= 0);
      if (shapeOk)
      {
        const char* number = end + 1;
        edit.Sharpness = std::strtod(number, &end);
      }
      if (!shapeOk || *end != '\0' || !(edit.Sharpness >= 0.0))
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
    else if (arg == "--color")
    {
      if (!value(options.Color))
      {
        return false;
      }
      if (options.Color != "none" && options.Color != "mean" && options.Color != "gaussian")
      {
        error = "--color wants none, mean or gaussian, not '" + options.Color + "'";
        return false;
      }
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
  return true;
}
}
