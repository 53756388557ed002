#include "SubDCommandLine.h"

#include "SubDArgumentReader.h"
#include "SubDBuiltinCages.h"
#include "SubDMeshIO.h"
#include "vtkSubDSurfaceFilter.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iterator>
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

bool ParseCreaseMethod(const std::string& text, int& method)
{
  if (text != "uniform" && text != "chaikin")
  {
    return false;
  }
  method = text == "chaikin" ? 1 : 0;
  return true;
}

// A face-varying interpolation mode by its name (vtkSubDSurfaceFilter's).
bool ParseFaceVaryingInterpolation(const std::string& text, int& mode)
{
  const int named = vtkSubDSurfaceFilter::FaceVaryingInterpolationFromName(text.c_str());
  mode = named < 0 ? mode : named;
  return named >= 0;
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

bool IsOption(const std::string& arg)
{
  return !arg.empty() && arg[0] == '-';
}

// Which program takes which option. subd takes every option of ParseCommandLine but the
// MpiOnly ones; subd-mpi takes those marked Both or MpiOnly and refuses any other by name,
// saying why for the options of subd it leaves out on purpose.
enum class Use
{
  Both,
  MpiOnly,
  SubdOnly
};
struct OptionUse
{
  const char* Name;
  Use Programs;
  const char* WhyNotMpi; ///< SubdOnly: why subd-mpi does not take it
};
const char* const PictureReason = "pictures are drawn by subd (open the .pvtp in ParaView, or run subd --image)";
const char* const CurveReason = "subd-mpi refines surfaces; the curve schemes run in subd";
const OptionUse OptionUses[] = {
  { "-h", Use::Both, nullptr }, { "--help", Use::Both, nullptr }, { "--version", Use::Both, nullptr },
  { "-q", Use::Both, nullptr }, { "--quiet", Use::Both, nullptr }, { "--scheme", Use::Both, nullptr },
  { "--levels", Use::Both, nullptr }, { "--boundary", Use::Both, nullptr }, { "--tension", Use::Both, nullptr },
  { "--crease-method", Use::Both, nullptr }, { "--feature-angle", Use::Both, nullptr },
  { "--limit", Use::Both, nullptr }, { "--normals", Use::Both, nullptr }, { "--curvature", Use::Both, nullptr },
  { "--collapse-repeated-corners", Use::Both, nullptr }, { "--no-weld", Use::Both, nullptr },
  { "--fvar-interpolation", Use::Both, nullptr }, { "--smooth-triangles", Use::Both, nullptr },
  { "--builtin", Use::Both, nullptr }, { "-o", Use::Both, nullptr }, { "--output", Use::Both, nullptr },
  { "--compress", Use::Both, nullptr }, { "--threads", Use::MpiOnly, nullptr },
  { "--image", Use::SubdOnly, PictureReason }, { "--compare", Use::SubdOnly, PictureReason },
  { "--color", Use::SubdOnly, PictureReason }, { "--view-size", Use::SubdOnly, PictureReason },
  { "--no-cage", Use::SubdOnly, PictureReason }, { "--tangents", Use::SubdOnly, CurveReason },
  { "--closed", Use::SubdOnly, CurveReason },
  { "--tolerance", Use::SubdOnly,
    "the adaptive tessellation refines each face as its neighbours' refinement asks, across the whole mesh "
    "(run subd)" },
  { "--interpolate", Use::SubdOnly,
    "its solve couples every point of the mesh (write the cage with subd --interpolate --levels 0, "
    "then subdivide that with subd-mpi)" },
};

// Whether `program` takes the option `arg`; else false with `error` naming it. For subd, an
// option no program knows is left to ParseCommandLine ("unknown option").
bool Takes(Program program, const std::string& arg, std::string& error)
{
  const OptionUse* end = std::end(OptionUses);
  const OptionUse* use =
    std::find_if(std::begin(OptionUses), end, [&arg](const OptionUse& entry) { return arg == entry.Name; });
  if (program == Program::Subd)
  {
    if (use != end && use->Programs == Use::MpiOnly)
    {
      error = arg + " is an option of subd-mpi, not of subd (see --help)";
      return false;
    }
    return true;
  }
  if (use != end && use->Programs != Use::SubdOnly)
  {
    return true;
  }
  error = use != end ? arg + " is an option of subd only: " + use->WhyNotMpi
                     : "unknown option '" + arg + "' (see --help)";
  return false;
}

// The help texts and the parsing steps, defined after ParseCommandLine.
std::string SchemeOptionsHelp(Program program);
std::string InputAndOutputHelp(Program program);
std::string GeneralHelp();
std::string MpiUsageText();

// The outcome of a group of options' parser for one argument.
enum class Parsed
{
  NotHere, ///< not one of the group's options
  Done,
  Failed ///< `error` says why
};

// Failed, saying why in `error`.
Parsed Fail(const std::string& why, std::string& error)
{
  error = why;
  return Parsed::Failed;
}

Parsed ParseSchemeOption(ArgumentReader& arguments, CommandLine& cmd, std::string& error);
Parsed ParseSurfaceSetting(ArgumentReader& arguments, CommandLine& cmd, std::string& error);
Parsed ParsePictureOption(ArgumentReader& arguments, CommandLine& cmd, std::string& error);
bool TakeFileName(const std::string& arg, CommandLine& cmd, std::string& positionalOutput, std::string& error);
bool TakePositionalOutput(const std::string& positionalOutput, CommandLine& cmd, std::string& error);
bool CheckCombinations(CommandLine& cmd, std::string& error);
}

std::string UsageText(Program program)
{
  if (program == Program::SubdMpi)
  {
    return MpiUsageText();
  }
  std::ostringstream out;
  out << "usage: subd [INPUT] [--scheme NAME] [--levels N] [--tolerance EPS] [--boundary RULE] [--tension W]\n"
         "            [--crease-method METHOD] [--feature-angle DEG] [--limit] [--normals]\n"
         "            [--curvature] [--collapse-repeated-corners] [--no-weld] [--fvar-interpolation MODE]\n"
         "            [--smooth-triangles]\n"
         "            [--tangents] [--closed] [--interpolate]\n"
         "            [--output FILE] [--compress]\n"
         "            [--image FILE.png [--compare S1,S2,...] [--color C] [--view-size WxH] [--no-cage]]\n"
         "\n"
         "Subdivides the polygon mesh INPUT (" << SupportedExtensions() << ") and writes the\n"
         "result (" << WritableExtensions() << "); the formats are chosen by the file extensions. The curve schemes refine the\n"
         "input's lines and polylines instead (its polygons pass through). Without INPUT, a\n"
         "built-in control cage (or curve) is used.\n"
         "\n"
         "options:\n"
      << SchemeOptionsHelp(Program::Subd) <<
         "  --tangents         curves: add the unit tangents of the limit curve (point data \"Tangents\")\n"
         "  --closed           curves: every polyline is closed (otherwise only those whose last\n"
         "                     point repeats the first); a point with \"CornerSharpness\" >= 10 is\n"
         "                     a sharp corner of its curve\n"
         "  --interpolate      first solve for the cage (or control polygons) whose limit passes\n"
         "                     through the input's points - all, or those whose point data\n"
         "                     \"Interpolate\" is non-zero - then subdivide that cage (catmull-clark,\n"
         "                     loop, doo-sabin, chaikin, bspline; --levels 0 writes the cage itself)\n"
         "\n"
      << InputAndOutputHelp(Program::Subd) <<
         "\n"
         "Pictures (rendered offscreen: no display server needed):\n"
         "  --image FILE.png   render the result: curvature colours, control cage, creases\n"
         "  --compare S1,S2,.. with --image: a side-by-side grid of these schemes (or 'all') at\n"
         "                     the same level, seen through one camera\n"
         "  --color C          none, mean, gaussian, k1 or k2 (principal curvatures k1 >= k2):\n"
         "                     discrete curvature, or the limit's with --curvature (default mean)\n"
         "  --view-size WxH    pixels per view, 64..4096 each (default 500x500)\n"
         "  --no-cage          do not overlay the control cage\n"
      << GeneralHelp();
  return out.str();
}

namespace
{
// The options without a value, each setting one thing (and recorded as a surface or curve
// option where CheckCombinations needs to know); false for any other argument.
bool ParseSwitch(const std::string& arg, CommandLine& cmd)
{
  using Set = void (*)(CommandLine&);
  static const std::pair<const char*, Set> switches[] = {
    { "--limit", [](CommandLine& c) { c.Options.ProjectToLimit = true; } },
    { "--normals", [](CommandLine& c) { c.Options.LimitNormals = true; c.SurfaceOptions.push_back("--normals"); } },
    { "--curvature",
      [](CommandLine& c) { c.Options.LimitCurvature = true; c.SurfaceOptions.push_back("--curvature"); } },
    { "--collapse-repeated-corners",
      [](CommandLine& c) {
        c.Options.CollapseRepeatedCorners = true;
        c.SurfaceOptions.push_back("--collapse-repeated-corners");
      } },
    { "--no-weld", [](CommandLine& c) { c.Options.Weld = false; c.SurfaceOptions.push_back("--no-weld"); } },
    { "--smooth-triangles",
      [](CommandLine& c) { c.Options.SmoothTriangles = true; c.SurfaceOptions.push_back("--smooth-triangles"); } },
    { "--tangents", [](CommandLine& c) { c.Options.Tangents = true; c.CurveOptions.push_back("--tangents"); } },
    { "--closed", [](CommandLine& c) { c.Options.Closed = true; c.CurveOptions.push_back("--closed"); } },
    { "--interpolate", [](CommandLine& c) { c.Interpolate = true; } },
    { "--compress", [](CommandLine& c) { c.Compress = true; } },
    { "--no-cage", [](CommandLine& c) { c.Cage = false; } },
  };
  for (const auto& option : switches)
  {
    if (arg == option.first)
    {
      option.second(cmd);
      return true;
    }
  }
  return false;
}
}

bool ParseCommandLine(int argc, char* argv[], CommandLine& cmd, std::string& error, Program program)
{
  cmd.Tool = program;
  std::string positionalOutput; // subd-mpi's old command line: the output after the input
  for (ArgumentReader arguments(argc, argv); arguments.Next();)
  {
    const std::string arg = arguments.Current();
    auto value = [&](std::string& out) { return arguments.Value(out, error); };
    if (IsOption(arg) && !Takes(program, arg, error))
    {
      return false;
    }
    Parsed parsed = Parsed::NotHere;
    for (auto* parse : { &ParseSchemeOption, &ParseSurfaceSetting, &ParsePictureOption })
    {
      parsed = parsed == Parsed::NotHere ? parse(arguments, cmd, error) : parsed;
    }
    if (parsed == Parsed::Failed)
    {
      return false;
    }
    if (parsed == Parsed::Done)
    {
      continue;
    }
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
    else if (ParseSwitch(arg, cmd))
    {
      continue;
    }
    else if (!arg.empty() && arg[0] == '-')
    {
      error = "unknown option '" + arg + "' (see --help)";
      return false;
    }
    else if (!TakeFileName(arg, cmd, positionalOutput, error))
    {
      return false;
    }
  }
  return TakePositionalOutput(positionalOutput, cmd, error) && CheckCombinations(cmd, error);
}

namespace
{
// The help of the scheme and its settings, shared by subd and subd-mpi (surface schemes).
std::string SchemeOptionsHelp(Program program)
{
  const bool subd = program == Program::Subd;
  std::ostringstream out;
  out << "  --scheme NAME      subdivision scheme (default catmull-clark):\n";
  for (const SchemeEntry& entry : Schemes())
  {
    if (subd || !entry.Curve)
    {
      out << "                       " << entry.Name << ": " << entry.Summary << "\n";
    }
  }
  out << "  --levels N         number of subdivision levels, 0..30 (default 2)\n"
      << (subd ? "  --tolerance EPS    catmull-clark and loop: instead of refining, tessellate the limit\n"
                 "                     surface into triangles within EPS (a fraction of the bounding-box\n"
                 "                     diagonal) of it, crack-free, fine only where the surface curves;\n"
                 "                     --levels is then the deepest level (default 12)\n"
               : "")
      << "  --boundary RULE    boundary interpolation, OpenSubdiv's meanings (default edge-only):\n"
         "                       none: faces at the boundary become holes (shape, not output)\n"
         "                       edge-only: boundary edges are sharp creases\n"
         "                       edge-and-corner: also pin vertices that have a single face\n"
         "  --tension W        butterfly tension in [-0.0625, 0.0625] (default 0: 8-point butterfly)"
      << (subd ? ";\n                     four-point tension in [0, 0.125] (default 0.0625: reproduces cubics)\n"
               : "\n")
      << "  --crease-method M  how semi-sharp creases decay (default uniform):\n"
         "                       uniform: one unit of sharpness per level\n"
         "                       chaikin: averaged along the crease first (OpenSubdiv's Chaikin)\n"
         "  --feature-angle D  edges whose faces meet at more than D degrees become sharp creases\n"
         "  --collapse-repeated-corners\n"
         "                     remove a polygon's repeated corners first (4 3 5 5 becomes 4 3 5);\n"
         "                     otherwise catmull-clark, loop and linear keep such polygons as\n"
         "                     OpenSubdiv does, the repeated point a sharp corner of the surface\n"
         "  --no-weld          keep points with identical coordinates apart (by default they are one\n"
         "                     vertex: a mesh split at texture seams is subdivided whole, and data\n"
         "                     that differ there, such as texture coordinates, are face-varying)\n"
         "  --fvar-interpolation MODE\n"
         "                     how face-varying data are interpolated, OpenSubdiv's and USD's modes\n"
         "                     (default corners-plus1): none, corners-only, corners-plus1,\n"
         "                     corners-plus2, boundaries, all (catmull-clark, loop, linear)\n"
         "  --smooth-triangles catmull-clark: OpenSubdiv's smooth triangle rule (rounder over the\n"
         "                     input's triangles)\n"
         "  --limit            move the output points (and point data) to the limit surface\n"
         "                     (catmull-clark and loop: OpenSubdiv's limit masks; sqrt3, doo-sabin,\n"
         "                     midpoint: their closed-form limit points; linear and butterfly\n"
         "                     interpolate: their points are on the limit already)\n"
         "  --normals          add the exact normals of the limit surface (point data \"Normals\";\n"
         "                     sqrt3, doo-sabin, midpoint: at smooth vertices only)\n"
         "  --curvature        add the limit surface's curvature from its exact derivatives:\n"
         "                     Mean_Curvature, Gauss_Curvature, Maximum_/Minimum_Curvature and\n"
         "                     their directions (catmull-clark and loop)"
      << (subd ? "; --image then colours\n                     the main scheme's view with it instead of the discrete curvature\n"
               : "\n");
  return out.str();
}

// The help of the input's creases, the built-in cages and the output, shared by both programs.
std::string InputAndOutputHelp(Program program)
{
  const bool subd = program == Program::Subd;
  std::ostringstream out;
  out << "Creases come with the input: in .vtp/.vtk as line cells with the cell array\n"
         "\"Sharpness\" (0 smooth .. 10 infinitely sharp), \"CornerSharpness\" point data and\n"
         "\"Hole\" cell data; in .obj as OpenSubdiv's tags (t crease, t corner, t hole). The\n"
         "output carries the refined creases the same way (.obj, .vtp and .vtk keep them).\n"
         "\n"
         "  --builtin NAME     built-in cage when there is no INPUT:";
  for (const std::string& name : BuiltinCageNames())
  {
    out << " " << name;
  }
  out << " (default " << BuiltinCageNames().front() << (subd ? ");\n" : ")\n");
  if (subd)
  {
    out << "                     curves:";
    for (const std::string& name : BuiltinCurveNames())
    {
      out << " " << name;
    }
    out << " (default " << BuiltinCurveNames().front() << ")\n"
        << "  -o, --output FILE  output file (default <input>-<scheme>-L<levels>.vtp; with --image,\n"
           "                     no mesh is written unless --output is given)\n"
           "  --compress         .vtp: compress the arrays (zlib): about a third smaller, written\n"
           "                     ~15x slower; without it they are raw binary, written at disk speed\n";
  }
  else
  {
    out << "  -o, --output FILE  the .pvtp to write (default <input>-<scheme>-L<levels>.pvtp); each\n"
           "                     rank writes its piece beside it as FILE_<rank>.vtp\n"
           "  --compress         compress the pieces' arrays (zlib): about a third smaller, written\n"
           "                     ~15x slower; without it they are raw binary, written at disk speed\n";
  }
  return out.str();
}

// The general options and the exit status, the same in both programs.
std::string GeneralHelp()
{
  return "  -q, --quiet        no summary line\n"
         "  -h, --help         this text\n"
         "  --version          the program's version\n"
         "\n"
         "Exit status: 0 on success, 1 when the work failed, 2 on a usage error.\n";
}

// subd-mpi's help: the options it shares with subd, in subd's words, and its own.
std::string MpiUsageText()
{
  std::ostringstream out;
  out << "usage: mpirun -np N subd-mpi [INPUT] [--scheme NAME] [--levels N] [--boundary RULE]\n"
         "                     [--tension W] [--crease-method METHOD] [--feature-angle DEG]\n"
         "                     [--limit] [--normals] [--curvature] [--collapse-repeated-corners]\n"
         "                     [--no-weld] [--fvar-interpolation MODE] [--smooth-triangles]\n"
         "                     [--output FILE.pvtp] [--compress] [--threads T]\n"
         "\n"
         "Subdivides the polygon mesh INPUT ("
      << SupportedExtensions()
      << ") or a built-in\n"
         "cage on N MPI ranks, with the surface schemes and options of subd. Every rank reads\n"
         "the input, keeps its piece (and the ghost cells the scheme needs), subdivides it and\n"
         "writes it as FILE_<rank>.vtp; rank 0 writes FILE.pvtp, which names the pieces:\n"
         "ParaView opens it as one mesh, subd's output for the same options.\n"
         "\n"
         "options:\n"
      << SchemeOptionsHelp(Program::SubdMpi) << "\n"
      << InputAndOutputHelp(Program::SubdMpi)
      << "  --threads T        threads per rank, 1..1024 (default: the node's cores shared among\n"
         "                     the ranks on it)\n"
      << GeneralHelp() << "\nRefused, as subd's only (pictures, curves, interpolation, adaptive tessellation):\n ";
  for (const OptionUse& use : OptionUses)
  {
    if (use.Programs == Use::SubdOnly)
    {
      out << " " << use.Name;
    }
  }
  out << "\n"
         "Deprecated: the output named after the input without --output (subd-mpi's first\n"
         "command line); it still works, with a warning.\n";
  return out.str();
}

std::string UnknownSchemeError(const std::string& name)
{
  std::string error = "unknown scheme '" + name + "' (known:";
  for (const SchemeEntry& entry : Schemes())
  {
    error += " " + entry.Name;
  }
  return error + ")";
}

// The scheme, the levels (and subd-mpi's threads): options both programs share.
Parsed ParseSchemeOption(ArgumentReader& arguments, CommandLine& cmd, std::string& error)
{
  const std::string arg = arguments.Current();
  std::string text;
  if (arg == "--scheme")
  {
    if (!arguments.Value(cmd.Scheme, error))
    {
      return Parsed::Failed;
    }
    return FindScheme(cmd.Scheme) ? Parsed::Done : Fail(UnknownSchemeError(cmd.Scheme), error);
  }
  if (arg == "--levels" || arg == "--threads")
  {
    const bool levels = arg == "--levels";
    int& number = levels ? cmd.Options.Levels : cmd.Threads;
    const int low = levels ? 0 : 1, high = levels ? 30 : 1024;
    if (!arguments.Value(text, error))
    {
      return Parsed::Failed;
    }
    cmd.LevelsGiven = cmd.LevelsGiven || levels;
    const bool valid = ParseInt(text, number) && number >= low && number <= high;
    return valid ? Parsed::Done
                 : Fail(arg + " wants an integer in " + std::to_string(low) + ".." + std::to_string(high) +
                       ", not '" + text + "'", error);
  }
  return Parsed::NotHere;
}

// The surface schemes' settings both programs share: --boundary, --crease-method,
// --fvar-interpolation (named settings), --tension, --feature-angle.
Parsed ParseSurfaceSetting(ArgumentReader& arguments, CommandLine& cmd, std::string& error)
{
  const std::string arg = arguments.Current();
  std::string text;
  // A surface option naming one of a few settings.
  auto named = [&](bool (*parse)(const std::string&, int&), int& setting, const char* wants) {
    cmd.SurfaceOptions.push_back(arg);
    if (!arguments.Value(text, error))
    {
      return Parsed::Failed;
    }
    return parse(text, setting) ? Parsed::Done : Fail(arg + " wants " + wants + ", not '" + text + "'", error);
  };
  if (arg == "--boundary")
  {
    return named(ParseBoundary, cmd.Options.BoundaryRule, "none, edge-only or edge-and-corner");
  }
  if (arg == "--crease-method")
  {
    return named(ParseCreaseMethod, cmd.Options.CreaseMethod, "uniform or chaikin");
  }
  if (arg == "--fvar-interpolation")
  {
    return named(ParseFaceVaryingInterpolation, cmd.Options.FaceVaryingInterpolation,
      "none, corners-only, corners-plus1, corners-plus2, boundaries or all");
  }
  if (arg == "--tension")
  {
    if (!arguments.Value(text, error))
    {
      return Parsed::Failed;
    }
    cmd.Options.TensionGiven = true;
    return ParseDouble(text, cmd.Options.Tension) ? Parsed::Done
                                                  : Fail("--tension wants a number, not '" + text + "'", error);
  }
  // A surface option taking a number that `inRange` accepts.
  auto number = [&](double& value, bool (*inRange)(double), const char* wants) {
    cmd.SurfaceOptions.push_back(arg);
    if (!arguments.Value(text, error))
    {
      return Parsed::Failed;
    }
    return ParseDouble(text, value) && inRange(value) ? Parsed::Done
                                                      : Fail(arg + " wants " + wants + ", not '" + text + "'", error);
  };
  if (arg == "--tolerance")
  {
    return number(cmd.Options.Tolerance, [](double t) { return t > 0.0 && t < 1.0; },
      "a fraction of the bounding-box diagonal in (0, 1)");
  }
  if (arg == "--feature-angle")
  {
    return number(cmd.Options.FeatureAngle, [](double a) { return a > 0.0 && a <= 180.0; }, "degrees in (0, 180]");
  }
  return Parsed::NotHere;
}

// subd's pictures: --image, --compare, --color (its name checked by CheckImageOptions, which
// knows the renderer's colourings), --view-size.
Parsed ParsePictureOption(ArgumentReader& arguments, CommandLine& cmd, std::string& error)
{
  const std::string arg = arguments.Current();
  auto value = [&](std::string& out) { return arguments.Value(out, error); };
  std::string text;
  if (arg == "--image")
  {
    if (!value(cmd.Image))
    {
      return Parsed::Failed;
    }
    if (LowerExtension(cmd.Image) != ".png")
    {
      error = "--image writes PNG files: '" + cmd.Image + "' does not end in .png";
      return Parsed::Failed;
    }
  }
  else if (arg == "--compare")
  {
    if (!value(text) || !ParseSchemeList(text, cmd.Compare, error))
    {
      return Parsed::Failed;
    }
  }
  else if (arg == "--color")
  {
    if (!value(cmd.Color))
    {
      return Parsed::Failed;
    }
  }
  else if (arg == "--view-size")
  {
    if (!value(text))
    {
      return Parsed::Failed;
    }
    const auto x = text.find('x');
    if (x == std::string::npos || !ParseInt(text.substr(0, x), cmd.ViewSize[0]) ||
      !ParseInt(text.substr(x + 1), cmd.ViewSize[1]) || cmd.ViewSize[0] < 64 || cmd.ViewSize[1] < 64 ||
      cmd.ViewSize[0] > 4096 || cmd.ViewSize[1] > 4096)
    {
      error = "--view-size wants WxH with each in 64..4096, not '" + text + "'";
      return Parsed::Failed;
    }
  }
  else
  {
    return Parsed::NotHere;
  }
  return Parsed::Done;
}

// A file name on the command line: the input. For subd-mpi, a .pvtp (which no program reads)
// is the output named the way its old command line did, after the input: `positionalOutput`.
bool TakeFileName(const std::string& arg, CommandLine& cmd, std::string& positionalOutput, std::string& error)
{
  const bool mpi = cmd.Tool == Program::SubdMpi;
  if (mpi && LowerExtension(arg) == ".pvtp")
  {
    if (!positionalOutput.empty())
    {
      error = "more than one output ('" + positionalOutput + "', '" + arg + "')";
      return false;
    }
    positionalOutput = arg;
    return true;
  }
  if (cmd.Input.empty())
  {
    cmd.Input = arg;
    return true;
  }
  error = "more than one input file ('" + cmd.Input + "', '" + arg + "')";
  if (mpi)
  {
    error += "; the output is given with --output FILE.pvtp";
  }
  return false;
}

// subd-mpi's output named by a file name (its old command line): taken, with a deprecation
// warning, unless --output names one too.
bool TakePositionalOutput(const std::string& positionalOutput, CommandLine& cmd, std::string& error)
{
  if (positionalOutput.empty())
  {
    return true;
  }
  if (!cmd.Output.empty())
  {
    error = "two outputs: --output " + cmd.Output + " and " + positionalOutput;
    return false;
  }
  cmd.Output = positionalOutput;
  cmd.Warnings.push_back("the output as a file name after the input is deprecated: use --output " + positionalOutput);
  return true;
}

// --compare: only with --image; "all" becomes the schemes of the main scheme's kind, which every
// compared scheme must be.
bool CheckCompare(CommandLine& cmd, std::string& error)
{
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
  return true;
}

// subd-mpi: a surface scheme, and a .pvtp to write (one piece per rank).
bool CheckMpi(const CommandLine& cmd, std::string& error)
{
  if (FindScheme(cmd.Scheme)->Curve)
  {
    error = "'" + cmd.Scheme + "' is not a surface scheme: subd-mpi refines surfaces (curves: subd)";
    return false;
  }
  if (!cmd.Output.empty() && LowerExtension(cmd.Output) != ".pvtp")
  {
    error = "the output must be a .pvtp file (one piece per rank), not '" + cmd.Output + "'";
    return false;
  }
  return true;
}

// --tension: for butterfly or four-point (the main scheme or a compared one), in its range.
bool CheckTension(const CommandLine& cmd, std::string& error)
{
  if (!cmd.Options.TensionGiven)
  {
    return true;
  }
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
  return true;
}

// --tolerance: the limit surface of catmull-clark or loop, tessellated on its own (one scheme,
// none of the refinement's settings), --levels its deepest level (default 12).
bool CheckTolerance(CommandLine& cmd, std::string& error)
{
  if (!(cmd.Options.Tolerance > 0.0))
  {
    return true;
  }
  if (!FindScheme(cmd.Scheme)->LimitCurvature)
  {
    error = "--tolerance tessellates the limit surface of catmull-clark or loop, not of " + cmd.Scheme;
    return false;
  }
  if (!cmd.Compare.empty())
  {
    error = "--tolerance tessellates one scheme's limit surface: it cannot be combined with --compare";
    return false;
  }
  for (const char* refinementOnly : { "--smooth-triangles", "--collapse-repeated-corners", "--feature-angle" })
  {
    if (std::find(cmd.SurfaceOptions.begin(), cmd.SurfaceOptions.end(), refinementOnly) != cmd.SurfaceOptions.end())
    {
      error = std::string(refinementOnly) + " applies to refinement, not to --tolerance's tessellation of the limit";
      return false;
    }
  }
  if (cmd.LevelsGiven && cmd.Options.Levels > 24)
  {
    error = "with --tolerance, --levels is the deepest level of the tessellation, 0..24, not " +
      std::to_string(cmd.Options.Levels);
    return false;
  }
  cmd.Options.Levels = cmd.LevelsGiven ? cmd.Options.Levels : 12;
  return true;
}

// The options together: what one asks of another, and the built-in cage (or curve) by default.
bool CheckCombinations(CommandLine& cmd, std::string& error)
{
  if ((cmd.Tool == Program::SubdMpi && !CheckMpi(cmd, error)) || !CheckCompare(cmd, error))
  {
    return false;
  }
  const bool curve = FindScheme(cmd.Scheme)->Curve;
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
  const char* compressible = cmd.Tool == Program::SubdMpi ? ".pvtp" : ".vtp"; // subd-mpi: its .vtp pieces
  if (cmd.Compress && !cmd.Output.empty() && LowerExtension(cmd.Output) != compressible)
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
  if (!CheckTension(cmd, error) || !CheckTolerance(cmd, error))
  {
    return false;
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
  if (cmd.Options.Tolerance > 0.0)
  {
    return stem + "-" + cmd.Scheme + "-adaptive.vtp";
  }
  return stem + "-" + cmd.Scheme + "-L" + std::to_string(cmd.Options.Levels) +
    (cmd.Tool == Program::SubdMpi ? ".pvtp" : ".vtp");
}

bool WritesMesh(const CommandLine& cmd)
{
  return cmd.Image.empty() || !cmd.Output.empty();
}
}
