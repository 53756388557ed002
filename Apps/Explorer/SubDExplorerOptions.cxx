#include "SubDExplorerOptions.h"

#include "SubDArgumentReader.h"
#include "SubDBuiltinCages.h"
#include "SubDSchemeRegistry.h"

#include "vtkSubDScene.h"
#include "vtkSubDSurfaceFilter.h"

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
         "                     [--cage-opacity O] [--wireframe] [--texture] [--size WxH]\n"
         "                     [--fvar-interpolation MODE] [--tolerance EPS]\n"
         "                     [--screenshot VIEWS.png] [--window-shot WINDOW.png]\n"
         "                     [--crease A-B=S]... [--corner V=S]... [--select A-B|V]\n"
         "                     [--export-cage CAGE.vtp] [--cancel-after MS] [--time-edits N]\n"
         "                     [--no-settings | --settings FILE.ini] [--print-state] [--quit]\n"
         "\n"
         "Compares subdivision schemes side by side on a mesh (.vtp .vtk .obj .ply .stl .off\n"
         ".gltf .glb) or a built-in cage. --texture shows a checker on surfaces with texture\n"
         "coordinates, --fvar-interpolation sets how every view refines them (as subd's).\n"
         "--tolerance EPS: the Catmull-Clark and Loop views tessellate their limit surface within\n"
         "EPS of the cage's diagonal (as subd --tolerance), the level their deepest level.\n"
         "--screenshot/--window-shot save pictures once the views are up to date; with --quit\n"
         "the app then exits (scripted use, e.g. under xvfb-run).\n"
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

namespace
{
// The outcome of a group of options' parser for one argument.
enum class Parsed
{
  NotHere, ///< not one of the group's options
  Done,
  Failed ///< `error` says why
};

// `ok` as a Parsed: Done, or Failed (with `error` set).
Parsed DoneIf(bool ok)
{
  return ok ? Parsed::Done : Parsed::Failed;
}

// Failed, saying why in `error`.
Parsed Fail(const std::string& why, std::string& error)
{
  error = why;
  return Parsed::Failed;
}

// Parses the comma-separated scheme names `text` into `schemes`; false with `error` at an
// unknown one.
bool ParseSchemes(const std::string& text, std::vector<std::string>& schemes, std::string& error)
{
  schemes.clear();
  std::istringstream in(text);
  std::string name;
  while (std::getline(in, name, ','))
  {
    if (!subdapp::FindScheme(name))
    {
      error = "unknown scheme '" + name + "'";
      return false;
    }
    schemes.push_back(name);
  }
  return true;
}

// Parses the value `text` of `arg` (--crease A-B=S or --corner V=S) into `edit`; false with
// `error` when it is malformed.
bool ParseSharpnessEdit(
  const std::string& arg, const std::string& text, ExplorerOptions::SharpnessEdit& edit, std::string& error)
{
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
  return true;
}

// The options of what is subdivided and shown: --builtin, --views, --schemes, --levels,
// --limit, --tolerance, --fvar-interpolation.
Parsed ParseSceneOption(ArgumentReader& arguments, ExplorerOptions& options, std::string& error)
{
  const std::string arg = arguments.Current();
  std::string text;
  if (arg == "--builtin")
  {
    if (!arguments.Value(options.Builtin, error))
    {
      return Parsed::Failed;
    }
    if (!subdapp::MakeBuiltinCage(options.Builtin))
    {
      error = "unknown built-in cage '" + options.Builtin + "'";
      return Parsed::Failed;
    }
    return Parsed::Done;
  }
  if (arg == "--views")
  {
    if (!arguments.Value(text, error))
    {
      return Parsed::Failed;
    }
    if (text != "1" && text != "2" && text != "4")
    {
      error = "--views wants 1, 2 or 4, not '" + text + "'";
      return Parsed::Failed;
    }
    options.Views = std::atoi(text.c_str());
    return Parsed::Done;
  }
  if (arg == "--schemes")
  {
    return DoneIf(arguments.Value(text, error) && ParseSchemes(text, options.Schemes, error));
  }
  if (arg == "--levels")
  {
    return DoneIf(arguments.Value(text, error) &&
      IntegerIn(text, 0, 8, "--levels wants an integer in 0..8", options.Levels, error));
  }
  if (arg == "--limit")
  {
    options.Limit = true;
    return Parsed::Done;
  }
  if (arg == "--tolerance")
  {
    if (!arguments.Value(text, error))
    {
      return Parsed::Failed;
    }
    char* end = nullptr;
    options.Tolerance = std::strtod(text.c_str(), &end);
    return *end == '\0' && options.Tolerance > 0.0 && options.Tolerance < 1.0
      ? Parsed::Done
      : Fail("--tolerance wants a fraction of the cage's diagonal in (0, 1), not '" + text + "'", error);
  }
  if (arg == "--fvar-interpolation")
  {
    if (!arguments.Value(options.FaceVarying, error))
    {
      return Parsed::Failed;
    }
    if (vtkSubDSurfaceFilter::FaceVaryingInterpolationFromName(options.FaceVarying.c_str()) < 0)
    {
      error = "--fvar-interpolation wants none, corners-only, corners-plus1, corners-plus2, boundaries or all, "
              "not '" + options.FaceVarying + "'";
      return Parsed::Failed;
    }
    return Parsed::Done;
  }
  return Parsed::NotHere;
}

// The options of how the views are coloured: --color, --colormap, --range, --percentile.
Parsed ParseColorOption(ArgumentReader& arguments, ExplorerOptions& options, std::string& error)
{
  const std::string arg = arguments.Current();
  std::string text;
  // A named setting: its value read, then checked by `known`.
  auto named = [&](const std::string& value, bool known, const char* wants) {
    return known ? Parsed::Done : Fail(arg + " wants " + wants + ", not '" + value + "'", error);
  };
  if (arg == "--color")
  {
    return !arguments.Value(options.Color, error) ? Parsed::Failed
      : named(options.Color, vtkSubDScene::ColoringFromName(options.Color.c_str()) >= 0,
          "none, mean, gaussian, k1 or k2");
  }
  if (arg == "--colormap")
  {
    return !arguments.Value(options.ColorMap, error) ? Parsed::Failed
      : named(options.ColorMap, vtkSubDScene::ColorMapFromName(options.ColorMap.c_str()) >= 0,
          "cool-to-warm, rainbow, black-body or grayscale");
  }
  if (arg == "--range")
  {
    if (!arguments.Value(text, error))
    {
      return Parsed::Failed;
    }
    options.RangeSymmetric = text == "symmetric";
    return named(text, text == "symmetric" || text == "percentile", "symmetric or percentile");
  }
  if (arg == "--percentile")
  {
    return DoneIf(arguments.Value(text, error) &&
      IntegerIn(text, 50, 100, "--percentile wants an integer in 50..100", options.RangePercentile, error));
  }
  return Parsed::NotHere;
}

// The options of what the views show beside the surfaces, and the window's size:
// --cage-opacity, --no-cage, --wireframe, --texture, --size.
Parsed ParseDisplayOption(ArgumentReader& arguments, ExplorerOptions& options, std::string& error)
{
  const std::string arg = arguments.Current();
  static const struct
  {
    const char* Name;
    bool ExplorerOptions::*Member;
    bool Value;
  } switches[] = { { "--no-cage", &ExplorerOptions::Cage, false },
    { "--wireframe", &ExplorerOptions::Wireframe, true }, { "--texture", &ExplorerOptions::Texture, true } };
  for (const auto& option : switches)
  {
    if (arg == option.Name)
    {
      options.*option.Member = option.Value;
      return Parsed::Done;
    }
  }
  std::string text;
  if (arg == "--cage-opacity")
  {
    if (!arguments.Value(text, error))
    {
      return Parsed::Failed;
    }
    char* end = nullptr;
    options.CageOpacity = std::strtod(text.c_str(), &end);
    const bool valid = !text.empty() && *end == '\0' && options.CageOpacity >= 0.0 && options.CageOpacity <= 1.0;
    return valid ? Parsed::Done : Fail("--cage-opacity wants a number in [0, 1], not '" + text + "'", error);
  }
  if (arg == "--size")
  {
    if (!arguments.Value(text, error))
    {
      return Parsed::Failed;
    }
    const auto x = text.find('x');
    options.Width = x == std::string::npos ? 0 : std::atoi(text.substr(0, x).c_str());
    options.Height = x == std::string::npos ? 0 : std::atoi(text.substr(x + 1).c_str());
    const bool valid = options.Width >= 200 && options.Height >= 200 && options.Width <= 8192 && options.Height <= 8192;
    return valid ? Parsed::Done : Fail("--size wants WxH, each in 200..8192, not '" + text + "'", error);
  }
  return Parsed::NotHere;
}

// The options that edit the cage: --crease, --corner, --select, --export-cage.
Parsed ParseEditOption(ArgumentReader& arguments, ExplorerOptions& options, std::string& error)
{
  const std::string arg = arguments.Current();
  std::string text;
  if (arg == "--crease" || arg == "--corner")
  {
    ExplorerOptions::SharpnessEdit edit;
    if (!arguments.Value(text, error) || !ParseSharpnessEdit(arg, text, edit, error))
    {
      return Parsed::Failed;
    }
    options.Edits.push_back(edit);
    return Parsed::Done;
  }
  if (arg == "--select")
  {
    if (!arguments.Value(text, error))
    {
      return Parsed::Failed;
    }
    const char* end = ReadVertexIds(text.c_str(), options.SelectA, options.SelectB);
    if (!end || *end != '\0')
    {
      error = "--select wants A-B (an edge's two vertex ids) or V (a vertex id), not '" + text + "'";
      return Parsed::Failed;
    }
    return Parsed::Done;
  }
  if (arg == "--export-cage")
  {
    return DoneIf(arguments.Value(options.ExportCage, error));
  }
  return Parsed::NotHere;
}

// The options of scripted and remembered use: --help, --screenshot, --window-shot, --quit,
// --cancel-after, --time-edits, --settings, --no-settings, --print-state.
Parsed ParseRunOption(ArgumentReader& arguments, ExplorerOptions& options, std::string& error)
{
  const std::string arg = arguments.Current();
  std::string text;
  if (arg == "-h" || arg == "--help")
  {
    options.Help = true;
    return Parsed::Done;
  }
  if (arg == "--quit")
  {
    options.Quit = true;
    return Parsed::Done;
  }
  if (arg == "--no-settings")
  {
    options.NoSettings = true;
    return Parsed::Done;
  }
  if (arg == "--print-state")
  {
    options.PrintState = true;
    return Parsed::Done;
  }
  if (arg == "--screenshot" || arg == "--window-shot")
  {
    return DoneIf(arguments.Value(arg == "--screenshot" ? options.Screenshot : options.WindowShot, error));
  }
  if (arg == "--cancel-after")
  {
    return DoneIf(arguments.Value(text, error) &&
      IntegerIn(text, 0, 600000, "--cancel-after wants milliseconds in 0..600000", options.CancelAfter, error));
  }
  if (arg == "--time-edits")
  {
    return DoneIf(arguments.Value(text, error) &&
      IntegerIn(text, 1, 1000, "--time-edits wants an integer in 1..1000", options.TimeEdits, error));
  }
  if (arg == "--settings")
  {
    return DoneIf(arguments.Value(options.SettingsFile, error));
  }
  return Parsed::NotHere;
}

// A word that is no option: the file to load (one only); false with `error` otherwise.
bool TakeFileName(const std::string& arg, ExplorerOptions& options, std::string& error)
{
  if (!arg.empty() && arg[0] == '-')
  {
    error = "unknown option '" + arg + "'";
    return false;
  }
  if (!options.Load.empty())
  {
    error = "more than one file ('" + options.Load + "', '" + arg + "')";
    return false;
  }
  options.Load = arg;
  return true;
}
}

bool ParseExplorerOptions(int argc, char* argv[], ExplorerOptions& options, std::string& error)
{
  for (ArgumentReader arguments(argc, argv); arguments.Next();)
  {
    const std::string arg = arguments.Current();
    options.Given.insert(arg);
    Parsed parsed = Parsed::NotHere;
    for (auto* parse : { &ParseSceneOption, &ParseColorOption, &ParseDisplayOption, &ParseEditOption, &ParseRunOption })
    {
      parsed = parsed == Parsed::NotHere ? parse(arguments, options, error) : parsed;
    }
    if (parsed == Parsed::Failed || (parsed == Parsed::NotHere && !TakeFileName(arg, options, error)))
    {
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
