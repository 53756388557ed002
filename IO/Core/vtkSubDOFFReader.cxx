#include "vtkSubDOFFReader.h"

#include "vtkSubDFileScanner.h"

#include "vtkCellArray.h"
#include "vtkIdTypeArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSubDOFFReader);

namespace
{
// The first word of a line (as written: a count can be too large for any integer type).
std::string FirstWord(const std::string& line)
{
  const auto begin = line.find_first_not_of(" \t\r");
  if (begin == std::string::npos)
  {
    return std::string();
  }
  return line.substr(begin, line.find_first_of(" \t\r", begin) - begin);
}

// Splits the file into lines without comments or blank lines, remembering line numbers so
// errors can point at the offending line.
class OFFLines
{
public:
  explicit OFFLines(std::istream& in)
    : In(in)
  {
  }

  // Next non-empty line (comment stripped); false at end of file.
  bool Next(std::string& line)
  {
    while (std::getline(this->In, line))
    {
      ++this->Number;
      const auto hash = line.find('#');
      if (hash != std::string::npos)
      {
        line.erase(hash);
      }
      if (line.find_first_not_of(" \t\r\n") != std::string::npos)
      {
        return true;
      }
    }
    return false;
  }
  long GetNumber() const { return this->Number; }

private:
  std::istream& In;
  long Number = 0;
};

// Parses whitespace-separated numbers of a line.
bool ParseNumbers(const std::string& line, std::vector<double>& values)
{
  values.clear();
  // Whatever the C locale (a Qt application sets the user's, with its decimal comma).
  const char* p = line.data();
  const char* const last = line.data() + line.size();
  while (true)
  {
    p = std::find_if_not(p, last, subdio::FileScanner::IsSpace);
    if (p == last)
    {
      return true;
    }
    const char* wordEnd = std::find_if(p, last, subdio::FileScanner::IsSpace);
    double v;
    if (!subdio::FileScanner::ParseWord(p, wordEnd, v))
    {
      return false;
    }
    values.push_back(v);
    p = wordEnd;
  }
}
}

namespace
{
// The bytes from the stream's position to its end, or -1 when it cannot seek.
std::streamoff RemainingBytes(std::istream& in)
{
  in.clear(); // a last line without a newline leaves the stream at its end with eofbit set
  const std::streampos here = in.tellg();
  if (here == std::streampos(-1) || !in.seekg(0, std::ios::end))
  {
    in.clear();
    return -1;
  }
  const std::streamoff remaining = in.tellg() - here;
  in.seekg(here);
  return remaining;
}

// Reads the header line (the next line of `lines`): `vertexColors` for COFF; `line` is then
// the line of the counts (the header's rest, or the next line). A problem, or "".
std::string ReadHeader(OFFLines& lines, std::string& line, bool& vertexColors)
{
  vertexColors = false;
  if (!lines.Next(line))
  {
    return "the file is empty; expected an OFF header.";
  }
  std::istringstream words(line);
  std::string first;
  words >> first;
  if (first.size() >= 3 && first.compare(first.size() - 3, 3, "OFF") == 0)
  {
    const std::string prefix = first.substr(0, first.size() - 3);
    if (!prefix.empty() && prefix != "C")
    {
      return "header '" + first + "' is not supported (OFF and COFF are).";
    }
    vertexColors = prefix == "C";
    std::string rest;
    std::getline(words, rest);
    if (rest.find_first_not_of(" \t\r") != std::string::npos)
    {
      line = rest; // counts on the header line
    }
    else if (!lines.Next(line))
    {
      return "the file ends after its header; expected 'vertices faces edges'.";
    }
  }
  return "";
}

// Reads the counts line `line` into `numVertices` and `numFaces`. A problem, or "".
std::string ParseCounts(const std::string& line, vtkIdType& numVertices, vtkIdType& numFaces)
{
  std::vector<double> values;
  if (!ParseNumbers(line, values) || values.size() < 2)
  {
    return "expected the counts 'vertices faces edges', found '" + line + "'.";
  }
  const double numVerticesValue = values[0], numFacesValue = values[1];
  // Written so that NaN fails too (before the casts below, undefined for NaN).
  if (!(numVerticesValue >= 0 && numVerticesValue <= 2e9) || !(numFacesValue >= 0 && numFacesValue <= 2e9) ||
    numVerticesValue != static_cast<double>(static_cast<long long>(numVerticesValue)) ||
    numFacesValue != static_cast<double>(static_cast<long long>(numFacesValue)))
  {
    return "invalid vertex or face count in '" + line + "'.";
  }
  numVertices = static_cast<vtkIdType>(numVerticesValue);
  numFaces = static_cast<vtkIdType>(numFacesValue);
  return "";
}

// A header may promise more than the file holds: refuses (a problem, else "") before
// allocating for it. The shortest vertex line is "0 0 0" and a newline, the shortest face
// "1 0" and a newline. (Small promises are read as far as they go, for the exact line where
// the file ends.)
std::string CheckPromise(std::istream& file, vtkIdType numVertices, vtkIdType numFaces)
{
  const std::streamoff remaining = RemainingBytes(file);
  const double promised = 6 * static_cast<double>(numVertices) + 4 * static_cast<double>(numFaces);
  if (remaining >= 0 && promised > remaining && promised > 1e6)
  {
    return "the header announces " + std::to_string(numVertices) + " vertices and " + std::to_string(numFaces) +
      " faces, more than the " + std::to_string(remaining) + " bytes after it can hold.";
  }
  return "";
}

// The RGBA colour of a COFF vertex line's numbers `values` (after its 3 coordinates): unit
// values are scaled to 0-255, missing channels are 255.
void VertexColor(const std::vector<double>& values, unsigned char rgba[4])
{
  std::fill(rgba, rgba + 4, 255);
  const size_t numColor = values.size() - 3;
  bool unit = true;
  for (size_t c = 3; c < values.size(); ++c)
  {
    unit = unit && values[c] <= 1.0 && std::floor(values[c]) != values[c];
  }
  for (size_t c = 0; c < numColor && c < 4; ++c)
  {
    double v = values[3 + c] * (unit ? 255.0 : 1.0);
    v = v < 0 ? 0 : (v > 255 ? 255 : v);
    rgba[c] = static_cast<unsigned char>(v + 0.5);
  }
}

// Reads `numVertices` vertex lines into `points` (sized for them), and into `colors` (sized
// for them) when `vertexColors`. A problem, or "".
std::string ReadVertices(
  OFFLines& lines, vtkIdType numVertices, bool vertexColors, vtkPoints* points, vtkUnsignedCharArray* colors)
{
  std::string line;
  std::vector<double> values;
  for (vtkIdType i = 0; i < numVertices; ++i)
  {
    if (!lines.Next(line))
    {
      return "the file ends after " + std::to_string(i) + " of " + std::to_string(numVertices) + " vertices.";
    }
    if (!ParseNumbers(line, values) || values.size() < 3)
    {
      return "expected the coordinates of vertex " + std::to_string(i) + ", found '" + line + "'.";
    }
    points->SetPoint(i, values[0], values[1], values[2]);
    if (vertexColors)
    {
      unsigned char rgba[4];
      VertexColor(values, rgba);
      colors->SetTypedTuple(i, rgba);
    }
  }
  return "";
}

// Appends face f, the line `line` (`n i0 i1 ...`), to `connectivity`, using `values` as
// scratch. A problem, or "".
std::string ParseFace(const std::string& line, vtkIdType f, vtkIdType numVertices, std::vector<double>& values,
  vtkIdTypeArray* connectivity)
{
  if (!ParseNumbers(line, values) || values.empty())
  {
    return "expected face " + std::to_string(f) + " as 'n i0 i1 ...', found '" + line + "'.";
  }
  const double n = values[0];
  if (n < 1 || n != std::floor(n))
  {
    return "face " + std::to_string(f) + " announces " + FirstWord(line) +
      " vertices; a face lists a whole number of them, at least one.";
  }
  if (static_cast<double>(values.size()) < n + 1)
  {
    return "face " + std::to_string(f) + " announces " + FirstWord(line) + " vertices but lists " +
      std::to_string(values.size() - 1) + ".";
  }
  for (vtkIdType k = 1; k <= static_cast<vtkIdType>(n); ++k)
  {
    const double id = values[k];
    if (id < 0 || id >= static_cast<double>(numVertices) || id != std::floor(id))
    {
      return "face " + std::to_string(f) + " uses vertex " + std::to_string(id) + ", but the file has " +
        std::to_string(numVertices) + " vertices.";
    }
    connectivity->InsertNextValue(static_cast<vtkIdType>(id));
  }
  return "";
}

// Reads `numFaces` face lines into `polys`. A problem, or "".
std::string ReadFaces(OFFLines& lines, vtkIdType numVertices, vtkIdType numFaces, vtkCellArray* polys)
{
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->Allocate(numFaces + 1);
  connectivity->Allocate(4 * numFaces);
  offsets->InsertNextValue(0);
  std::string line;
  std::vector<double> values;
  for (vtkIdType f = 0; f < numFaces; ++f)
  {
    if (!lines.Next(line))
    {
      return "the file ends after " + std::to_string(f) + " of " + std::to_string(numFaces) + " faces.";
    }
    const std::string problem = ParseFace(line, f, numVertices, values, connectivity);
    if (!problem.empty())
    {
      return problem;
    }
    offsets->InsertNextValue(connectivity->GetNumberOfTuples());
  }
  polys->SetData(offsets, connectivity);
  return "";
}
}

bool vtkSubDOFFReader::ReadFile(std::istream& file, vtkPolyData* output)
{
  OFFLines lines(file);
  std::string line;
  bool vertexColors = false;
  vtkIdType numVertices = 0, numFaces = 0;
  std::string problem = ReadHeader(lines, line, vertexColors);
  if (problem.empty())
  {
    problem = ParseCounts(line, numVertices, numFaces);
  }
  if (problem.empty())
  {
    problem = CheckPromise(file, numVertices, numFaces);
  }
  if (!problem.empty())
  {
    return this->Fail(lines.GetNumber(), problem);
  }

  vtkNew<vtkPoints> points;
  points->SetDataType(VTK_DOUBLE);
  points->SetNumberOfPoints(numVertices);
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("Colors");
  colors->SetNumberOfComponents(4);
  if (vertexColors)
  {
    colors->SetNumberOfTuples(numVertices);
  }
  vtkNew<vtkCellArray> polys;
  problem = ReadVertices(lines, numVertices, vertexColors, points, colors);
  if (problem.empty())
  {
    problem = ReadFaces(lines, numVertices, numFaces, polys);
  }
  if (!problem.empty())
  {
    return this->Fail(lines.GetNumber(), problem);
  }
  output->SetPoints(points);
  output->SetPolys(polys);
  if (vertexColors)
  {
    output->GetPointData()->SetScalars(colors);
  }
  return true;
}

void vtkSubDOFFReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
