// subd: command-line parsing.
#ifndef SubDCommandLine_h
#define SubDCommandLine_h

#include "SubDSchemeRegistry.h"
#include <string>
#include <vector>

namespace subdapp
{
struct CommandLine
{
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
  bool Compress = false;            ///< .vtp: zlib-compressed arrays (smaller, slower to write)
  bool Quiet = false;
  bool Help = false;
  bool Version = false;
};

/// Parses argv. On a usage error returns false and sets `error`.
bool ParseCommandLine(int argc, char* argv[], CommandLine& cmd, std::string& error);

std::string UsageText();

/// True when a mesh file is written: always, except with --image and no --output.
bool WritesMesh(const CommandLine& cmd);

/// Output path when none was given: "<input stem>-<scheme>-L<levels>.vtp".
std::string DefaultOutputPath(const CommandLine& cmd);
}

#endif
