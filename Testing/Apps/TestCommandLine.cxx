// The command line subd and subd-mpi share (SubDCommandLine): the same surface options give
// both programs the same settings; every option subd-mpi's help names, it takes; the options
// of subd it refuses, it names; its output is a .pvtp.
#include "SubDCommandLine.h"

#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <string>
#include <vector>

namespace
{
using subdapp::Program;

// Parses `args` (the arguments after the program's name) for `program`.
bool Parse(Program program, std::vector<std::string> args, subdapp::CommandLine& cmd, std::string& error)
{
  std::vector<char*> argv{ const_cast<char*>("program") };
  for (std::string& arg : args)
  {
    argv.push_back(&arg[0]);
  }
  return subdapp::ParseCommandLine(static_cast<int>(argv.size()), argv.data(), cmd, error, program);
}

// The options ("-o", "--levels", ...) that `text` names, each after a space, '[' or '('.
std::set<std::string> OptionsNamed(const std::string& text)
{
  std::set<std::string> names;
  const std::regex option("(^|[ \\[(])(--?[a-z][a-z-]*)");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), option); it != std::sregex_iterator(); ++it)
  {
    names.insert((*it)[2]);
  }
  return names;
}

bool Refused(const std::string& error)
{
  return error.find("unknown option") != std::string::npos || error.find("is an option of") != std::string::npos;
}

TEST(CommandLine, SubdMpiTakesTheSurfaceOptionsOfSubdAlike)
{
  const std::vector<std::string> surface = { "in.obj", "--scheme", "loop", "--levels", "3", "--boundary",
    "edge-and-corner", "--crease-method", "chaikin", "--feature-angle", "40", "--limit", "--normals", "--curvature",
    "--collapse-repeated-corners", "--no-weld", "--fvar-interpolation", "boundaries", "--smooth-triangles",
    "--compress", "-q" };
  subdapp::CommandLine subd, mpi;
  std::string error;
  std::vector<std::string> args = surface;
  args.insert(args.end(), { "-o", "out.vtp" });
  ASSERT_TRUE(Parse(Program::Subd, args, subd, error)) << error;
  args = surface;
  args.insert(args.end(), { "--output", "out.pvtp", "--threads", "2" });
  ASSERT_TRUE(Parse(Program::SubdMpi, args, mpi, error)) << error;
  EXPECT_TRUE(subd.Options == mpi.Options);
  EXPECT_EQ(mpi.Options.CreaseMethod, 1);
  EXPECT_TRUE(mpi.Options.LimitNormals && mpi.Options.LimitCurvature && mpi.Options.ProjectToLimit);
  EXPECT_TRUE(mpi.Options.CollapseRepeatedCorners);
  EXPECT_FALSE(mpi.Options.Weld);
  EXPECT_EQ(mpi.Options.FaceVaryingInterpolation, 4);
  EXPECT_TRUE(mpi.Options.SmoothTriangles);
  EXPECT_EQ(subd.Scheme, mpi.Scheme);
  EXPECT_EQ(subd.Input, mpi.Input);
  EXPECT_TRUE(mpi.Compress && mpi.Quiet);
  EXPECT_EQ(mpi.Output, "out.pvtp");
  EXPECT_EQ(mpi.Threads, 2);
  EXPECT_TRUE(mpi.Warnings.empty());
}

TEST(CommandLine, SubdMpiTakesWhatItsHelpNamesAndRefusesTheRestByName)
{
  const std::string help = subdapp::UsageText(Program::SubdMpi);
  const auto refusedAt = help.find("Refused"), deprecatedAt = help.find("Deprecated");
  ASSERT_NE(refusedAt, std::string::npos);
  ASSERT_NE(deprecatedAt, std::string::npos);
  const std::string usageLine = "usage: mpirun -np N subd-mpi";
  ASSERT_EQ(help.compare(0, usageLine.size(), usageLine), 0);
  std::set<std::string> taken = OptionsNamed(help.substr(usageLine.size(), refusedAt - usageLine.size()));
  const std::set<std::string> refused = OptionsNamed(help.substr(refusedAt, deprecatedAt - refusedAt));
  for (const char* name : { "--scheme", "--levels", "--boundary", "--tension", "--crease-method", "--feature-angle",
         "--limit", "--normals", "--curvature", "--collapse-repeated-corners", "--no-weld", "--fvar-interpolation",
         "--smooth-triangles",
         "--builtin", "-o", "--output",
         "--compress", "--threads" })
  {
    EXPECT_EQ(taken.count(name), 1u) << name << " is not in subd-mpi's help";
  }
  for (const std::string& name : taken)
  {
    subdapp::CommandLine cmd;
    std::string error;
    Parse(Program::SubdMpi, { name, "x" }, cmd, error); // a bad value is fine, a refusal is not
    EXPECT_FALSE(Refused(error)) << name << ": " << error;
  }
  ASSERT_GE(refused.size(), 8u);
  for (const std::string& name : refused)
  {
    subdapp::CommandLine cmd;
    std::string error;
    EXPECT_FALSE(Parse(Program::SubdMpi, { name, "x.png" }, cmd, error)) << name;
    EXPECT_NE(error.find(name + " is an option of subd only: "), std::string::npos) << error;
    subdapp::CommandLine forSubd;
    std::string subdError;
    Parse(Program::Subd, { name, "x.png" }, forSubd, subdError);
    EXPECT_FALSE(Refused(subdError)) << "subd refuses " << name << ": " << subdError;
  }
  for (const char* name : { "--frobnicate", "--low-memory" })
  {
    subdapp::CommandLine cmd;
    std::string error;
    EXPECT_FALSE(Parse(Program::SubdMpi, { name }, cmd, error));
    EXPECT_EQ(error, "unknown option '" + std::string(name) + "' (see --help)");
  }
}

TEST(CommandLine, SubdKeepsItsOwnOptionsAndRefusesThreads)
{
  subdapp::CommandLine cmd;
  std::string error;
  EXPECT_FALSE(Parse(Program::Subd, { "--threads", "2" }, cmd, error));
  EXPECT_EQ(error, "--threads is an option of subd-mpi, not of subd (see --help)");
  EXPECT_EQ(subdapp::UsageText(Program::Subd).find("--threads"), std::string::npos);
  EXPECT_NE(subdapp::UsageText(Program::Subd).find("--image FILE.png"), std::string::npos);
}

TEST(CommandLine, SubdMpiWritesAPvtp)
{
  subdapp::CommandLine cmd;
  std::string error;
  ASSERT_TRUE(Parse(Program::SubdMpi, { "--builtin", "torus", "--levels", "1" }, cmd, error)) << error;
  EXPECT_EQ(subdapp::DefaultOutputPath(cmd), "torus-catmull-clark-L1.pvtp");
  EXPECT_FALSE(Parse(Program::SubdMpi, { "-o", "out.vtp" }, cmd = {}, error));
  EXPECT_EQ(error, "the output must be a .pvtp file (one piece per rank), not 'out.vtp'");
  EXPECT_FALSE(Parse(Program::SubdMpi, { "--scheme", "bspline" }, cmd = {}, error));
  EXPECT_NE(error.find("'bspline' is not a surface scheme"), std::string::npos) << error;
  // subd-mpi's first command line: the output after the input, still taken, with a warning.
  ASSERT_TRUE(Parse(Program::SubdMpi, { "in.off", "out.pvtp" }, cmd = {}, error)) << error;
  EXPECT_EQ(cmd.Input, "in.off");
  EXPECT_EQ(cmd.Output, "out.pvtp");
  ASSERT_EQ(cmd.Warnings.size(), 1u);
  EXPECT_NE(cmd.Warnings.front().find("deprecated: use --output out.pvtp"), std::string::npos);
  EXPECT_FALSE(Parse(Program::SubdMpi, { "in.off", "out.pvtp", "-o", "other.pvtp" }, cmd = {}, error));
  EXPECT_EQ(error, "two outputs: --output other.pvtp and out.pvtp");
  // For subd a .pvtp is just a file name: its input.
  ASSERT_TRUE(Parse(Program::Subd, { "in.pvtp" }, cmd = {}, error)) << error;
  EXPECT_EQ(cmd.Input, "in.pvtp");
  EXPECT_TRUE(cmd.Warnings.empty());
}
}

// --tolerance: the deepest level is --levels when given, else 12; the default output is named
// for the adaptive tessellation.
TEST(CommandLine, ToleranceTakesLevelsAsTheDeepestLevel)
{
  subdapp::CommandLine cmd;
  std::string error;
  ASSERT_TRUE(Parse(Program::Subd, { "part.obj", "--tolerance", "1e-3" }, cmd, error)) << error;
  EXPECT_EQ(cmd.Options.Tolerance, 1e-3);
  EXPECT_EQ(cmd.Options.Levels, 12);
  EXPECT_EQ(subdapp::DefaultOutputPath(cmd), "part-catmull-clark-adaptive.vtp");
  subdapp::CommandLine capped;
  ASSERT_TRUE(Parse(Program::Subd, { "part.obj", "--scheme", "loop", "--levels", "5", "--tolerance", "0.01" }, capped,
    error))
    << error;
  EXPECT_EQ(capped.Options.Levels, 5);
  EXPECT_FALSE(cmd.Options == capped.Options);
}
