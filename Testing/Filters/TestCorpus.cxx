// Every filter against every entry of the corpus of bad and awkward inputs
// (Testing/Data/Corpus/make_corpus.py writes the files and the answer each must get).
//
// For each entry: reading it through `subd`'s readers gives the expected answer; then every
// surface scheme (plain, with limit positions, with limit normals and curvature where the
// scheme has them), the limit tessellation and the three curve schemes each either give a valid
// output or a clear error matching the manifest, with an empty output. "Valid" is checked
// independently of the scheme: every cell names existing points, every coordinate and every
// attribute value is finite, every array has one tuple per point (cell). A hang is caught by
// ctest's timeout, a crash by the test process dying.
#include "SubDMeshIO.h"
#include "SubDMessageCollector.h"
#include "SubDOutputChecks.h"
#include "SubDQuietOutput.h"
#include "SubDSchemeRegistry.h"
#include "vtkCellArray.h"
#include "vtkPolyData.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkSubDCurveFilter.h"
#include "vtkSubDLimitFilter.h"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace
{
struct CorpusEntry
{
  std::string File;
  int Levels = 0;
  std::string Read, Surface, Curve, Exact, Linear;
};

// gtest prints a parameter with this (the test's name in ctest's listing).
void PrintTo(const CorpusEntry& entry, std::ostream* os)
{
  *os << entry.File;
}

std::vector<CorpusEntry> LoadCorpus()
{
  std::vector<CorpusEntry> entries;
  std::ifstream in(SUBD_CORPUS_DIR "/corpus.txt");
  std::string line;
  while (std::getline(in, line))
  {
    if (line.empty() || line[0] == '#')
    {
      continue;
    }
    std::istringstream fields(line);
    CorpusEntry e;
    std::string levels;
    std::getline(fields, e.File, '\t');
    std::getline(fields, levels, '\t');
    std::getline(fields, e.Read, '\t');
    std::getline(fields, e.Surface, '\t');
    std::getline(fields, e.Curve, '\t');
    std::getline(fields, e.Exact, '\t');
    std::getline(fields, e.Linear, '\t');
    e.Levels = std::stoi(levels);
    entries.push_back(e);
  }
  return entries;
}

std::string TestName(const ::testing::TestParamInfo<CorpusEntry>& info)
{
  std::string name = info.param.File;
  for (char& c : name)
  {
    if (!std::isalnum(static_cast<unsigned char>(c)))
    {
      c = '_';
    }
  }
  return name;
}

bool Matches(const std::string& text, const std::string& pattern)
{
  return std::regex_search(text, std::regex(pattern, std::regex::icase | std::regex::ECMAScript));
}

/// Runs `filter` on `input` and checks its answer against `expectation` ("ok", "ok~REGEX" for
/// a warning that must come, "error~REGEX", or "either~REGEX": ok, or an error matching REGEX).
void CheckFilter(vtkPolyDataAlgorithm* filter, vtkPolyData* input, const std::string& expectation,
  const std::string& what)
{
  SCOPED_TRACE(what + ", expecting " + expectation);
  subdapp::MessageCollector messages;
  messages.Watch(filter);
  filter->SetInputData(input);
  filter->Update();
  vtkPolyData* out = filter->GetOutput();
  const auto tilde = expectation.find('~');
  const std::string kind = expectation.substr(0, tilde);
  const std::string pattern = tilde == std::string::npos ? "" : expectation.substr(tilde + 1);
  EXPECT_EQ(subdtest::OutputProblems(out, input), "");
  if (kind == "error" || (kind == "either" && !messages.Errors.empty()))
  {
    EXPECT_TRUE(Matches(messages.Errors, pattern)) << "errors: '" << messages.Errors << "'";
    EXPECT_EQ(out->GetNumberOfPoints(), 0);
    EXPECT_EQ(out->GetNumberOfCells(), 0);
    return;
  }
  EXPECT_EQ(messages.Errors, "");
  EXPECT_EQ(out->GetNumberOfPoints() > 0, input->GetNumberOfPoints() > 0);
  if (kind == "ok" && !pattern.empty())
  {
    EXPECT_TRUE(Matches(messages.Warnings, pattern)) << "warnings: '" << messages.Warnings << "'";
  }
}

class Corpus : public ::testing::TestWithParam<CorpusEntry>
{
};

TEST_P(Corpus, EveryFilterGivesAValidOutputOrAClearError)
{
  const CorpusEntry& entry = GetParam();
  subdtest::DiscardUnobservedMessages();
  std::string readError;
  vtkSmartPointer<vtkPolyData> input = subdapp::ReadMesh(SUBD_CORPUS_DIR "/" + entry.File, readError);
  std::string surface = entry.Surface, curve = entry.Curve;
  std::string exact = entry.Exact == "-" ? entry.Surface : entry.Exact;
  std::string linear = entry.Linear.empty() || entry.Linear == "-" ? entry.Surface : entry.Linear;
  if (entry.Read == "ok")
  {
    ASSERT_TRUE(input) << readError; // (readers do not check ids: some entries test the filters')
  }
  else
  {
    ASSERT_FALSE(input) << "the read should have failed";
    EXPECT_TRUE(Matches(readError, entry.Read.substr(entry.Read.find('~') + 1))) << readError;
    EXPECT_NE(readError.find(entry.File), std::string::npos) << "the message names the file: " << readError;
    // What a failed read leaves downstream: nothing. Every filter must say so.
    input = vtkSmartPointer<vtkPolyData>::New();
    surface = exact = linear = "error~no points|no polygons";
    curve = "ok~no lines"; // the curve filter passes through what it cannot refine
  }

  for (const subdapp::SchemeEntry& scheme : subdapp::Schemes())
  {
    subdapp::SchemeOptions options;
    options.Levels = entry.Levels;
    CheckFilter(
      scheme.Make(options), input, scheme.Curve ? curve : scheme.Name == "linear" ? linear : surface, scheme.Name);
    if (scheme.Curve)
    {
      options.ProjectToLimit = options.Tangents = true;
      CheckFilter(scheme.Make(options), input, curve, scheme.Name + " limit and tangents");
      continue;
    }
    if (scheme.LimitCurvature && entry.Levels <= 2)
    {
      options.ProjectToLimit = options.LimitNormals = options.LimitCurvature = true;
      CheckFilter(scheme.Make(options), input, exact, scheme.Name + " limit, normals and curvature");
    }
    else if (scheme.LimitPositions && entry.Levels <= 2)
    {
      // sqrt(3), Doo-Sabin and midpoint have closed-form limit points at some vertices only:
      // elsewhere (e.g. a non-manifold vertex) the documented answer is an error naming it.
      options.ProjectToLimit = true;
      CheckFilter(scheme.Make(options), input, Matches(surface, "^ok") ? "either~has no closed-form" : surface,
        scheme.Name + " limit positions");
    }
  }

  // The limit tessellation has no levels: refusing a level count does not apply to it.
  const bool refusedLevels = Matches(surface, "^error~refusing");
  for (const char* limitScheme : { "catmull-clark", "loop" })
  {
    vtkNew<vtkSubDLimitFilter> limit;
    limit->SetScheme(limitScheme[0] == 'l' ? vtkSubDLimitFilter::LOOP : vtkSubDLimitFilter::CATMULL_CLARK);
    limit->SetResolution(3);
    limit->SetComputeNormals(true);
    limit->SetComputeCurvature(true);
    const std::string expected = refusedLevels ? "ok" : exact;
    CheckFilter(limit, input, expected, std::string("limit tessellation, ") + limitScheme);
  }
}

INSTANTIATE_TEST_SUITE_P(Entry, Corpus, ::testing::ValuesIn(LoadCorpus()), TestName);
}
