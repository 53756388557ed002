#include "SubDCommandLine.h"

#include "SubDArgumentReader.h"
#include "SubDBuiltinCages.h"
#include "SubDMeshIO.h"

#include "vtkSubDScene.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace subdapp
{
namespace
{
bool ParseInt(const std::string& text, int& value)
{
  char* end = nullptr;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || v < -1000000 || v > 1000000)
  {
    return false;
  }
  value = static_cast<int>(v);
  return true;
}

bool ParseDouble(const std::string& text, double& value)
{
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v))
  {
    return false;
  }
  value = v;
  return true;
}

// A comma-separated list of scheme names, or "all".
bool ParseSchemeList(const std::string& text, std::vector<std::string>& names, std::string& error)
{
  names.clear();
  if (text == "all")
  {
    names.push_back("all"); // resolved once the main scheme is known: the schemes of its kind
    return true;
  }
  std::istringstream in(text);
  std::string name;
  while (std::getline(in, name, ','))
  {
    if (!FindScheme(name))
    {
      error = "--compare: unknown scheme '" + name + "' (see --help)";
      return false;
    }
    names.push_back(name);
  }
  if (names.empty())
  {
    error = "--compare wants a comma-separated list of schemes, or 'all'";
    return false;
  }
  return true;
}

bool ParseBoundary(const std::string& text, int& rule)
{
  if (text == "none")
  {
    rule = 0;
  }
  else if (text == "edge-only")
  {
    rule = 1;
  }
  else if (text == "edge-and-corner")
  {
    rule = 2;
  }
  else
  {
    return false;
  }
  return true;
}
}

std::string UsageText()
{
  std::ostringstream out;
  out << "usage: subd [INPUT] [--scheme NAME] [--levels N] [--boundary RULE] [--tension W]\n"
         "            [--crease-method METHOD] [--feature-angle DEG] [--limit] [--normals]\n"
         "            [--curvature] [--tangents] [--closed] [--interpolate]\n"
         "            [--output FILE] [--compress]\n"
         "            [--image FILE.png [--compare S1,S2,...] [--color C] [--view-size WxH] [--no-cage]]\n"
         "\n"
         "Subdivides the polygon mesh INPUT (" << SupportedExtensions() << ") and writes the\n"
         "result; the formats are chosen by the file extensions. The curve schemes refine the\n"
         "input's lines and polylines instead (its polygons pass through). Without INPUT, a\n"
         "built-in control cage (or curve) is used.\n"
         "\n"
         "options:\n"
         "  --scheme NAME      subdivision scheme (default catmull-clark):\n";
  for (const SchemeEntry& entry : Schemes())
  {
    out << "                       " << entry.Name << ": " << entry.Summary << "\n";
  }
  out << "  --levels N         number of subdivision levels, 0..30 (default 2)\n"
         "  --boundary RULE    boundary interpolation, OpenSubdiv's meanings (default edge-only):\n"
         "                       none: faces at the boundary become holes (shape, not output)\n"
         "                       edge-only: boundary edges are sharp creases\n"
         "                       edge-and-corner: also pin vertices that have a single face\n"
         "  --tension W        butterfly tension in [-0.0625, 0.0625] (default 0: 8-point butterfly);\n"
         "                     four-point tension in [0, 0.125] (default 0.0625: reproduces cubics)\n"
         "  --crease-method M  how semi-sharp creases decay (default uniform):\n"
         "                       uniform: one unit of sharpness per level\n"
         "                       chaikin: averaged along the crease first (OpenSubdiv's Chaikin)\n"
         "  --feature-angle D  edges whose faces meet at more than D degrees become sharp creases\n"
         "  --limit            move the output points (and point data) to the limit surface\n"
         "                     (catmull-clark and loop: OpenSubdiv's limit masks; sqrt3, doo-sabin,\n"
         "                     midpoint: their closed-form limit points; linear and butterfly\n"
         "                     interpolate: their points are on the limit already)\n"
         "  --normals          add the exact normals of the limit surface (point data \"Normals\";\n"
         "                     sqrt3, doo-sabin, midpoint: at smooth vertices only)\n"
         "  --curvature        add the limit surface's curvature from its exact derivatives:\n"
         "                     Mean_Curvature, Gauss_Curvature, Maximum_/Minimum_Curvature and\n"
         "                     their directions (catmull-clark and loop); --image then colours\n"
         "                     the main scheme's view with it instead of the discrete curvature\n"
         "  --tangents         curves: add the unit tangents of the limit curve (point data \"Tangents\")\n"
         "  --closed           curves: every polyline is closed (otherwise only those whose last\n"
         "                     point repeats the first); a point with \"CornerSharpness\" >= 10 is\n"
         "                     a sharp corner of its curve\n"
         "  --interpolate      first solve for the cage (or control polygons) whose limit passes\n"
         "                     through the input's points - all, or those whose point data\n"
         "                     \"Interpolate\" is non-zero - then subdivide that cage (catmull-clark,\n"
         "                     loop, doo-sabin, chaikin, bspline; --levels 0 writes the cage itself)\n"
         "\n"
         "Creases come with the input: in .vtp/.vtk as line cells with the cell array\n"
         "\"Sharpness\" (0 smooth .. 10 infinitely sharp), \"CornerSharpness\" point data and\n"
         "\"Hole\" cell data; in .obj as OpenSubdiv's tags (t crease, t corner, t hole). The\n"
         "output carries the refined creases the same way (.obj, .vtp and .vtk keep them).\n"
         "\n"
         "  --builtin NAME     built-in cage when there is no INPUT:";
  for (const std::string& name : BuiltinCageNames())
  {
    out << " " << name;
  }
  out << " (default " << BuiltinCageNames().front() << ");\n"
         "                     curves:";
  for (const std::string& name : BuiltinCurveNames())
  {
    out << " " << name;
  }
  out << " (default " << BuiltinCurveNames().front() << ")\n"
         "  -o, --output FILE  output file (default <input>-<scheme>-L<levels>.vtp; with --image,\n"
         "                     no mesh is written unless --output is given)\n"
         "  --compress         .vtp: compress the arrays (zlib): about a third smaller, written\n"
         "                     ~15x slower; without it they are raw binary, written at disk speed\n"
         "\n"
         "Pictures (rendered offscreen: no display server needed):\n"
         "  --image FILE.png   render the result: curvature colours, control cage, creases\n"
         "  --compare S1,S2,.. with --image: a side-by-side grid of these schemes (or 'all') at\n"
         "                     the same level, seen through one camera\n"
         "  --color C          none, mean, gaussian, k1 or k2 (principal curvatures k1 >= k2):\n"
         "                     discrete curvature, or the limit's with --curvature (default mean)\n"
         "  --view-size WxH    pixels per view, 64..4096 each (default 500x500)\n"
         "  --no-cage          do not overlay the control cage\n"
         "  -q, --quiet        no summary line\n"
         "  -h, --help         this text\n"
         "  --version          the program's version\n"
         "\n"
         "Exit status: 0 on success, 1 when the work failed, 2 on a usage error.\n";
  return out.str();
}

bool ParseCommandLine(int argc, char* argv[], CommandLine& cmd, std::string& error)
{
  for (ArgumentReader arguments(argc, argv); arguments.Next();)
  {
    const std::string arg = arguments.Current();
    auto value = [&](std::string& out) { return arguments.Value(out, error); };
    std::string text;
    if (arg == "-h" || arg == "--help")
    {
      cmd.Help = true;
    }
    else if (arg == "--version")
    {
      cmd.Version = true;
    }
    else if (arg == "-q" || arg == "--quiet")
    {
      cmd.Quiet = true;
    }
    else if (arg == "--scheme")
    {
      if (!value(cmd.Scheme))
      {
        return false;
      }
      if (!FindScheme(cmd.Scheme))
      {
        error = "unknown scheme '" + cmd.Scheme + "' (known:";
        for (const SchemeEntry& entry : Schemes())
        {
          error += " " + entry.Name;
        }
        error += ")";
        return false;
      }
    }
    else if (arg == "--levels")
    {
      if (!value(text))
      {
        return false;
      }
      if (!ParseInt(text, cmd.Options.Levels) || cmd.Options.Levels < 0 || cmd.Options.Levels > 30)
      {
        error = "--levels wants an integer in 0..30, not '" + text + "'";
        return false;
      }
    }
    else if (arg == "--boundary")
    {
      cmd.SurfaceOptions.push_back(arg);
      if (!value(text))
      {
        return false;
      }
      if (!ParseBoundary(text, cmd.Options.BoundaryRule))
      {
        error = "--boundary wants none, edge-only or edge-and-corner, not '" + text + "'";
        return false;
      }
    }
    else if (arg == "--tension")
    {
      if (!value(text))
      {
        return false;
      }
      if (!ParseDouble(text, cmd.Options.Tension))
      {
        error = "--tension wants a number, not '" + text + "'";
        return false;
      }
      cmd.Options.TensionGiven = true;
    }
    else if (arg == "--crease-method")
    {
      cmd.SurfaceOptions.push_back(arg);
      if (!value(text))
      {
        return false;
      }
      if (text != "uniform" && text != "chaikin")
      {
        error = "--crease-method wants uniform or chaikin, not '" + text + "'";
        return false;
      }
      cmd.Options.CreaseMethod = text == "chaikin" ? 1 : 0;
    }
    else if (arg == "--feature-angle")
    {
      cmd.SurfaceOptions.push_back(arg);
      if (!value(text))
      {
        return false;
      }
      if (!ParseDouble(text, cmd.Options.FeatureAngle) || cmd.Options.FeatureAngle <= 0.0 ||
        cmd.Options.FeatureAngle > 180.0)
      {
        error = "--feature-angle wants degrees in (0, 180], not '" + text + "'";
        return false;
      }
    }
    else if (arg == "--builtin")
    {
      if (!value(cmd.Builtin))
      {
        return false;
      }
      if (!MakeBuiltinCage(cmd.Builtin))
      {
        error = "unknown built-in cage '" + cmd.Builtin + "'";
        return false;
      }
    }
    else if (arg == "-o" || arg == "--output")
    {
      if (!value(cmd.Output))
      {
        return false;
      }
    }
    else if (arg == "--image")
    {
      if (!value(cmd.Image))
      {
        return false;
      }
      if (LowerExtension(cmd.Image) != ".png")
      {
        error = "--image writes PNG files: '" + cmd.Image + "' does not end in .png";
        return false;
      }
    }
    else if (arg == "--compare")
    {
      if (!value(text))
      {
        return false;
      }
      if (!ParseSchemeList(text, cmd.Compare, error))
      {
        return false;
      }
    }
    else if (arg == "--color")
    {
      if (!value(cmd.Color))
      {
        return false;
      }
      if (vtkSubDScene::ColoringFromName(cmd.Color.c_str()) < 0)
      {
        error = "--color wants none, mean, gaussian, k1 or k2, not '" + cmd.Color + "'";
        return false;
      }
    }
    else if (arg == "--view-size")
    {
      if (!value(text))
      {
        return false;
      }
      const auto x = text.find('x');
      if (x == std::string::npos || !ParseInt(text.substr(0, x), cmd.ViewSize[0]) ||
        !ParseInt(text.substr(x + 1), cmd.ViewSize[1]) || cmd.ViewSize[0] < 64 || cmd.ViewSize[1] < 64 ||
        cmd.ViewSize[0] > 4096 || cmd.ViewSize[1] > 4096)
      {
        error = "--view-size wants WxH with each in 64..4096, not '" + text + "'";
        return false;
      }
    }
    else if (arg == "--limit")
    {
      cmd.Options.ProjectToLimit = true;
    }
    else if (arg == "--normals")
    {
      cmd.Options.LimitNormals = true;
      cmd.SurfaceOptions.push_back(arg);
    }
    else if (arg == "--curvature")
    {
      cmd.Options.LimitCurvature = true;
      cmd.SurfaceOptions.push_back(arg);
    }
    else if (arg == "--tangents")
    {
      cmd.Options.Tangents = true;
      cmd.CurveOptions.push_back(arg);
    }
    else if (arg == "--closed")
    {
      cmd.Options.Closed = true;
      cmd.CurveOptions.push_back(arg);
    }
    else if (arg == "--interpolate")
    {
      cmd.Interpolate = true;
    }
    else if (arg == "--compress")
    {
      cmd.Compress = true;
    }
    else if (arg == "--no-cage")
    {
      cmd.Cage = false;
    }
    else if (!arg.empty() && arg[0] == '-')
    {
      error = "unknown option '" + arg + "' (see --help)";
      return false;
    }
    else if (cmd.Input.empty())
    {
      cmd.Input = arg;
    }
    else
    {
      error = "more than one input file ('" + cmd.Input + "', '" + arg + "')";
      return false;
    }
  }
  if (!cmd.Compare.empty() && cmd.Image.empty())
  {
    error = "--compare draws a picture: give --image FILE.png too";
    return false;
  }
  const bool curve = FindScheme(cmd.Scheme)->Curve;
  if (cmd.Compare.size() == 1 && cmd.Compare.front() == "all")
  {
    cmd.Compare.clear();
    for (const SchemeEntry& entry : Schemes())
    {
      if (entry.Curve == curve)
      {
        cmd.Compare.push_back(entry.Name);
      }
    }
  }
  for (const std::string& name : cmd.Compare)
  {
    if (name == "all" || FindScheme(name)->Curve != curve)
    {
      error = "--compare: '" + name + "' is not a " + (curve ? "curve" : "surface") + " scheme like " + cmd.Scheme;
      return false;
    }
  }
  const SchemeEntry* scheme = FindScheme(cmd.Scheme);
  if (cmd.Interpolate && scheme->InterpolationScheme < 0)
  {
    error = "--interpolate: " + cmd.Scheme + " " + scheme->InterpolationNote;
    return false;
  }
  if (cmd.Interpolate && cmd.Options.FeatureAngle > 0.0)
  {
    error = "--interpolate honours the input's creases but not --feature-angle (the solve would not know "
            "the creases it adds)";
    return false;
  }
  if (cmd.Compress && !cmd.Output.empty() && LowerExtension(cmd.Output) != ".vtp")
  {
    error = "--compress applies to .vtp output, not to '" + cmd.Output + "'";
    return false;
  }
  if (cmd.Interpolate && !cmd.Compare.empty())
  {
    error = "--interpolate solves for one scheme's cage: it cannot be combined with --compare";
    return false;
  }
  const std::vector<std::string>& misplaced = curve ? cmd.SurfaceOptions : cmd.CurveOptions;
  if (!misplaced.empty())
  {
    error = misplaced.front() + " applies to " + (curve ? "surface" : "curve") + " schemes, not to " + cmd.Scheme;
    return false;
  }
  if (cmd.Options.TensionGiven)
  {
    const bool butterfly = cmd.Scheme == "butterfly" ||
      std::find(cmd.Compare.begin(), cmd.Compare.end(), std::string("butterfly")) != cmd.Compare.end();
    const bool fourPoint = cmd.Scheme == "four-point" ||
      std::find(cmd.Compare.begin(), cmd.Compare.end(), std::string("four-point")) != cmd.Compare.end();
    const double low = butterfly ? -0.0625 : 0.0, high = butterfly ? 0.0625 : 0.125;
    if (!butterfly && !fourPoint)
    {
      error = "--tension applies to the butterfly and four-point schemes only";
      return false;
    }
    if (cmd.Options.Tension < low || cmd.Options.Tension > high)
    {
      std::ostringstream message;
      message << "--tension wants a number in [" << low << ", " << high << "] for the "
              << (butterfly ? "butterfly" : "four-point") << " scheme, not " << cmd.Options.Tension;
      error = message.str();
      return false;
    }
  }
  if (!cmd.Input.empty() && !cmd.Builtin.empty())
  {
    error = "give either an input file or --builtin, not both";
    return false;
  }
  if (cmd.Input.empty() && cmd.Builtin.empty())
  {
    cmd.Builtin = curve ? BuiltinCurveNames().front() : BuiltinCageNames().front();
  }
  return true;
}

std::string DefaultOutputPath(const CommandLine& cmd)
{
  std::string stem = cmd.Builtin;
  if (!cmd.Input.empty())
  {
    stem = cmd.Input;
    const auto slash = stem.find_last_of('/');
    if (slash != std::string::npos)
    {
      stem = stem.substr(slash + 1);
    }
    const auto dot = stem.find_last_of('.');
    if (dot != std::string::npos && dot > 0)
    {
      stem = stem.substr(0, dot);
    }
  }
  return stem + "-" + cmd.Scheme + "-L" + std::to_string(cmd.Options.Levels) + ".vtp";
}

bool WritesMesh(const CommandLine& cmd)
{
  return cmd.Image.empty() || !cmd.Output.empty();
}
}
