// subd: command-line parsing.
#ifndef SubDCommandLine_h
#define SubDCommandLine_h

#include "SubDSchemeRegistry.h"
#include <string>

namespace subdapp
{
struct CommandLine
{
  std::string Input;   ///< empty: use Builtin
  std::string Builtin; ///< built-in cage name
  std::string Output;  ///< empty: derived from input and scheme
  std::string Scheme = "catmull-clark";
  SchemeOptions Options;
  bool TensionGiven = false;
  bool Quiet = false;
  bool Help = false;
  bool Version = false;
};

/// Parses argv. On a usage error returns false and sets `error`.
bool ParseCommandLine(int argc, char* argv[], CommandLine& cmd, std::string& error);

std::string UsageText();

/// Output path when none was given: "<input stem>-<scheme>-L<levels>.vtp".
std::string DefaultOutputPath(const CommandLine& cmd);
}

#endif
