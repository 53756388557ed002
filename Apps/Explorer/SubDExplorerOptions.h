// SubD Explorer: the command line, which makes the app scriptable (tests, screenshots).
#ifndef SubDExplorerOptions_h
#define SubDExplorerOptions_h

#include <set>
#include <string>
#include <vector>

namespace subdexplorer
{
struct ExplorerOptions
{
  std::string Load;                 ///< a mesh file to open (empty: Builtin)
  std::string Builtin = "cube";     ///< a built-in cage or curve
  int Views = 1;                    ///< 1, 2 or 4 linked views
  std::vector<std::string> Schemes; ///< per view (missing ones: catmull-clark, loop, butterfly, doo-sabin)
  int Levels = 2;
  std::string Color = "mean"; ///< none, mean, gaussian, k1 or k2
  std::string ColorMap = "cool-to-warm";
  bool RangeSymmetric = true; ///< --range symmetric|percentile
  int RangePercentile = 95;
  bool Cage = true;
  double CageOpacity = 1.0;
  bool Wireframe = false;
  bool Texture = false;                        ///< --texture: the checker on textured surfaces
  std::string FaceVarying = "corners-plus1";  ///< --fvar-interpolation, every view
  bool Limit = false; ///< project to the limit (and use exact curvature) where the scheme can
  double Tolerance = 0.0; ///< > 0: Catmull-Clark and Loop views tessellate their limit adaptively
  long long SelectA = -1, SelectB = -1; ///< --select A-B or --select V
  std::string Screenshot; ///< PNG of the views, written once the views are up to date
  std::string WindowShot; ///< PNG of the whole window (controls included)
  bool Quit = false;      ///< quit after the screenshots
  int CancelAfter = -1;   ///< >= 0: cancel the first update after this many milliseconds
  struct SharpnessEdit
  {
    long long A = -1, B = -1; ///< an edge (A, B), or vertex A when B < 0
    double Sharpness = 0.0;
  };
  std::vector<SharpnessEdit> Edits; ///< --crease A-B=S and --corner V=S, in order
  std::string ExportCage;           ///< write the (edited) cage here
  int Width = 1100, Height = 750;
  bool NoSettings = false;  ///< neither read nor write the remembered layout
  std::string SettingsFile; ///< remember the layout in this INI file instead of the user's
  bool PrintState = false;  ///< print the layout once the views are up to date
  int TimeEdits = 0;        ///< > 0: time this many sharpness edits and print the figures
  bool Help = false;
  /// The options given on the command line ("--levels", ...): only these override the
  /// remembered layout.
  std::set<std::string> Given;
};

/// Parses argv (Qt's own options already removed). On a usage error returns false with `error`.
bool ParseExplorerOptions(int argc, char* argv[], ExplorerOptions& options, std::string& error);
std::string ExplorerUsage();
}

#endif
