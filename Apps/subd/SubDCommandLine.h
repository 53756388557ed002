// subd and subd-mpi: their one command line. The options, their help text and defaults are
// here (SubDCommandLine.cxx) for both programs; subd-mpi takes the surface options of subd
// under the same names, plus --threads, and refuses the others by name.
#ifndef SubDCommandLine_h
#define SubDCommandLine_h

#include "SubDSchemeRegistry.h"
#include <string>
#include <vector>

namespace subdapp
{
/// The program whose command line is parsed.
enum class Program
{
  Subd,   ///< subd: every option
  SubdMpi ///< subd-mpi: the surface options, --threads; the output is a .pvtp
};

struct CommandLine
{
  Program Tool = Program::Subd; ///< set by ParseCommandLine
  std::string Input;   ///< empty: use Builtin
  std::string Builtin; ///< built-in cage name
  std::string Output;  ///< empty: derived from input and scheme
  std::string Scheme = "catmull-clark";
  SchemeOptions Options;
  std::vector<std::string> SurfaceOptions; ///< options given that only surface schemes take
  std::vector<std::string> CurveOptions;   ///< options given that only curve schemes take
  std::string Image;                ///< PNG to render the result to (empty: none)
  std::vector<std::string> Compare; ///< with Image: the schemes of a side-by-side grid
  std::string Color = "mean";       ///< none, mean, gaussian, k1 or k2 (curvature colouring)
  int ViewSize[2] = { 500, 500 };   ///< pixels per view
  bool Cage = true;                 ///< overlay the control cage
  bool Interpolate = false;         ///< solve for the cage whose limit passes through the input
  bool LevelsGiven = false;         ///< --levels was given (with --tolerance: the deepest level)
  bool Compress = false;            ///< .vtp: zlib-compressed arrays (smaller, slower to write)
  bool Quiet = false;
  bool Help = false;
  bool Version = false;
  int Threads = 0;                   ///< subd-mpi --threads: per rank (0: the node's cores over its ranks)
  std::vector<std::string> Warnings; ///< usage that still works but is deprecated, to print
};

/// Parses argv for `program`. On a usage error returns false and sets `error`.
bool ParseCommandLine(int argc, char* argv[], CommandLine& cmd, std::string& error,
  Program program = Program::Subd);

/// The --help text of `program`.
std::string UsageText(Program program = Program::Subd);

/// True when a mesh file is written: always, except with --image and no --output.
bool WritesMesh(const CommandLine& cmd);

/// Output path when none was given: "<input stem>-<scheme>-L<levels>.vtp" (subd-mpi: .pvtp;
/// with --tolerance "<input stem>-<scheme>-adaptive.vtp").
std::string DefaultOutputPath(const CommandLine& cmd);
}

#endif
