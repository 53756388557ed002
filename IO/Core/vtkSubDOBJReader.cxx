#include "vtkSubDOBJReader.h"

#include "vtkSubDFileScanner.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSubDOBJReader);

namespace
{
// The parsed file: everything is collected first, then checked and turned into VTK cells
// (indices may refer to vertices defined later in the file).
struct OBJContents
{
  std::vector<double> Points;
  std::vector<vtkIdType> FaceOffsets{ 0 };      // face f's corners: [FaceOffsets[f], FaceOffsets[f + 1])
  std::vector<vtkIdType> FaceCorners;           // 0-based
  std::vector<double> TexCoords;                // `vt`: u, v per texture coordinate
  std::vector<long> FaceTexCorners;             // per face corner: its `vt`, 0-based, or -1 (none)
  bool AnyTexCorner = false;
  std::vector<long> CopyOf;                     // per point past the file's vertices: its vertex
  std::vector<long> PointTexCoord;              // per point: its `vt` (-1: none), once split
  std::vector<std::vector<long>> Polylines;     // `l` elements, 0-based
  std::vector<std::vector<long>> CreaseChains;  // from tags, 0-based
  std::vector<float> ChainSharpness;
  std::map<long, float> Corners;
  std::set<long> Holes;
  std::set<std::string> SkippedTags;
};

bool ParseLong(const std::string& token, long& value)
{
  char* end = nullptr;
  errno = 0;
  value = std::strtol(token.c_str(), &end, 10);
  return end != token.c_str() && errno != ERANGE;
}

// Real numbers are parsed whatever the C locale (a Qt application sets the user's).
bool ParseFiniteDouble(const char* first, const char* last, double& value)
{
  return subdio::FileScanner::ParseWord(first, last, value) && std::isfinite(value);
}

bool ParseFloat(const std::string& token, float& value)
{
  return subdio::FileScanner::ParseWord(token.data(), token.data() + token.size(), value);
}

// An OBJ index (the word [first, last): 1-based, or negative: relative to the vertices read
// so far) to 0-based.
bool ObjIndex(const char* first, const char* last, long numPoints, long& index)
{
  long i;
  if (!subdio::FileScanner::ParseWord(first, last, i) || i == 0)
  {
    return false;
  }
  index = i > 0 ? i - 1 : numPoints + i;
  return true;
}

// The words of a line, split at white space without copying them: a file of millions of
// vertices and faces is read at the speed of std::from_chars, not of a string stream per line.
class LineWords
{
public:
  explicit LineWords(const std::string& line)
    : Position(line.data())
    , End(line.data() + line.size())
  {
  }
  /// The next word as [first, last); false after the last.
  bool Next(const char*& first, const char*& last)
  {
    while (this->Position != this->End && subdio::FileScanner::IsSpace(*this->Position))
    {
      ++this->Position;
    }
    first = this->Position;
    while (this->Position != this->End && !subdio::FileScanner::IsSpace(*this->Position))
    {
      ++this->Position;
    }
    last = this->Position;
    return first != last;
  }
  /// What follows the words read so far.
  std::string Rest() const { return std::string(this->Position, this->End); }

private:
  const char* Position;
  const char* End;
};

bool IsWord(const char* first, const char* last, const char* word)
{
  const size_t length = std::strlen(word);
  return static_cast<size_t>(last - first) == length && std::equal(first, last, word);
}

// Parses `t name nInts/nFloats/nStrings ints floats strings` into `contents`.
std::string ParseTag(std::istringstream& in, OBJContents& contents)
{
  std::string name, counts;
  in >> name >> counts;
  long nInts = 0, nFloats = 0, nStrings = 0;
  char s1 = 0, s2 = 0;
  std::istringstream countStream(counts);
  countStream >> nInts >> s1 >> nFloats >> s2 >> nStrings;
  if (!countStream || s1 != '/' || s2 != '/' || nInts < 0 || nFloats < 0 || nStrings < 0)
  {
    return "tag '" + name + "' has counts '" + counts + "', expected nInts/nFloats/nStrings";
  }
  std::vector<long> ints(static_cast<size_t>(nInts));
  std::vector<float> floats(static_cast<size_t>(nFloats));
  std::string token;
  for (long& v : ints)
  {
    if (!(in >> token) || !ParseLong(token, v))
    {
      return "tag '" + name + "' needs " + std::to_string(nInts) + " integer(s)";
    }
  }
  for (float& v : floats)
  {
    if (!(in >> token) || !ParseFloat(token, v))
    {
      return "tag '" + name + "' needs " + std::to_string(nFloats) + " number(s)";
    }
  }
  if (name == "crease")
  {
    if (nInts < 2 || (nFloats != 1 && nFloats != nInts - 1))
    {
      return "crease tag needs N >= 2 vertices and 1 or N-1 sharpness values, got " + counts;
    }
    if (nFloats == 1)
    {
      contents.CreaseChains.push_back(ints);
      contents.ChainSharpness.push_back(floats[0]);
    }
    else
    {
      for (long k = 0; k + 1 < nInts; ++k)
      {
        contents.CreaseChains.push_back({ ints[k], ints[k + 1] });
        contents.ChainSharpness.push_back(floats[k]);
      }
    }
  }
  else if (name == "corner")
  {
    if (nInts < 1 || (nFloats != 1 && nFloats != nInts))
    {
      return "corner tag needs N >= 1 vertices and 1 or N sharpness values, got " + counts;
    }
    for (long k = 0; k < nInts; ++k)
    {
      contents.Corners[ints[k]] = floats[nFloats == 1 ? 0 : k];
    }
  }
  else if (name == "hole")
  {
    contents.Holes.insert(ints.begin(), ints.end());
  }
  else
  {
    contents.SkippedTags.insert(name);
  }
  return "";
}

// Appends the next `count` words, finite numbers, to `values`; `problem` if they are not.
std::string ParseNumbers(LineWords& words, int count, std::vector<double>& values, const char* problem)
{
  const char *first, *last;
  double number[3];
  for (int k = 0; k < count; ++k)
  {
    if (!words.Next(first, last) || !ParseFiniteDouble(first, last, number[k]))
    {
      return problem;
    }
  }
  values.insert(values.end(), number, number + count);
  return "";
}

// The `vt` index of a corner word v/vt/vn ([slash, last) after its vertex): 0-based, or -1
// when it has none (`v`, `v//vn`); false if it is not an index.
bool TexIndex(const char* slash, const char* last, long numTexCoords, long& index)
{
  index = -1;
  if (slash == last || slash + 1 == last || slash[1] == '/')
  {
    return true;
  }
  return ObjIndex(slash + 1, std::find(slash + 1, last, '/'), numTexCoords, index) && index >= 0;
}

// Reads the corners of an `f` (face) or `l` (polyline) element into `contents`, using
// `element` and `texCorners` as scratch; a problem, or "".
std::string ParseElement(LineWords& words, bool face, OBJContents& contents, std::vector<long>& element)
{
  const char *first, *last;
  element.clear();
  const long numPoints = static_cast<long>(contents.Points.size() / 3);
  const long numTexCoords = static_cast<long>(contents.TexCoords.size() / 2);
  long withTexture = 0;
  while (words.Next(first, last))
  {
    long index, texture;
    const char* slash = std::find(first, last, '/');
    if (!ObjIndex(first, slash, numPoints, index))
    {
      return "'" + std::string(first, last) + "' is not a vertex index";
    }
    if (face && !TexIndex(slash, last, numTexCoords, texture))
    {
      return "'" + std::string(first, last) + "' has no valid texture coordinate index";
    }
    element.push_back(index);
    if (face)
    {
      contents.FaceTexCorners.push_back(texture);
      withTexture += texture >= 0 ? 1 : 0;
    }
  }
  if (element.size() < (face ? 3u : 2u))
  {
    return face ? "a face needs at least 3 vertices" : "a line needs at least 2 vertices";
  }
  if (face && withTexture != 0 && withTexture != static_cast<long>(element.size()))
  {
    return "a face mixes corners with and without texture coordinates";
  }
  if (face)
  {
    contents.AnyTexCorner |= withTexture > 0;
    contents.FaceCorners.insert(contents.FaceCorners.end(), element.begin(), element.end());
    contents.FaceOffsets.push_back(static_cast<vtkIdType>(contents.FaceCorners.size()));
  }
  else
  {
    contents.Polylines.push_back(element);
  }
  return "";
}

// Reads one line of the file (comment included) into `contents`; a problem, or "".
std::string ParseLine(std::string& line, OBJContents& contents, std::vector<long>& element)
{
  const auto hash = line.find('#');
  if (hash != std::string::npos)
  {
    line.erase(hash);
  }
  LineWords words(line);
  const char *keyword, *keywordEnd;
  if (!words.Next(keyword, keywordEnd))
  {
    return "";
  }
  if (IsWord(keyword, keywordEnd, "v"))
  {
    return ParseNumbers(words, 3, contents.Points, "a vertex needs 3 finite coordinates");
  }
  if (IsWord(keyword, keywordEnd, "vt")) // (a third number, w, is dropped)
  {
    return ParseNumbers(words, 2, contents.TexCoords, "a texture coordinate needs 2 finite numbers");
  }
  if (IsWord(keyword, keywordEnd, "f") || IsWord(keyword, keywordEnd, "l"))
  {
    return ParseElement(words, *keyword == 'f', contents, element);
  }
  if (IsWord(keyword, keywordEnd, "t"))
  {
    std::istringstream in(words.Rest()); // tags are few: parsed as a stream
    return ParseTag(in, contents);
  }
  // vn (normals are the surface's own once subdivided), vp, g, o, s, usemtl, mtllib and the
  // like carry nothing SubD uses.
  return "";
}

// Cell c of `what`, the vertices [first, last): false (with `error`) if one does not exist.
template <typename Index>
bool CheckCell(long numPoints, size_t c, const Index* first, const Index* last, const char* what, std::string& error)
{
  for (; first != last; ++first)
  {
    if (*first < 0 || *first >= numPoints)
    {
      error = std::string(what) + " " + std::to_string(c) + " uses vertex " + std::to_string(*first) +
        " but the file has " + std::to_string(numPoints) + " vertices";
      return false;
    }
  }
  return true;
}

// Every cell of `cells` (named `what`): false (with `error`) at the first with a missing vertex.
bool CheckCells(long numPoints, const std::vector<std::vector<long>>& cells, const char* what, std::string& error)
{
  for (size_t c = 0; c < cells.size(); ++c)
  {
    if (!CheckCell(numPoints, c, cells[c].data(), cells[c].data() + cells[c].size(), what, error))
    {
      return false;
    }
  }
  return true;
}

// The first index of the whole file naming a vertex or face it does not have, as an error
// message; "" when all are in range (`contents` has vertices).
std::string CheckIndices(const OBJContents& contents)
{
  const long numPoints = static_cast<long>(contents.Points.size() / 3);
  std::string error;
  const vtkIdType numFaces = static_cast<vtkIdType>(contents.FaceOffsets.size()) - 1;
  const vtkIdType* corners = contents.FaceCorners.data();
  for (vtkIdType f = 0; f < numFaces && error.empty(); ++f)
  {
    CheckCell(numPoints, static_cast<size_t>(f), corners + contents.FaceOffsets[f],
      corners + contents.FaceOffsets[f + 1], "face", error);
  }
  const long numTexCoords = static_cast<long>(contents.TexCoords.size() / 2);
  for (vtkIdType f = 0; f < numFaces && error.empty() && contents.AnyTexCorner; ++f)
  {
    for (vtkIdType h = contents.FaceOffsets[f]; h < contents.FaceOffsets[f + 1] && error.empty(); ++h)
    {
      const long t = contents.FaceTexCorners[h];
      if (t < -1 || t >= numTexCoords)
      {
        error = "face " + std::to_string(f) + " uses texture coordinate " + std::to_string(t) + " but the file has " +
          std::to_string(numTexCoords);
      }
    }
  }
  if (!error.empty() || !CheckCells(numPoints, contents.Polylines, "line", error) ||
    !CheckCells(numPoints, contents.CreaseChains, "crease tag", error))
  {
    return error;
  }
  for (const auto& corner : contents.Corners)
  {
    if (corner.first < 0 || corner.first >= numPoints)
    {
      return "corner tag names vertex " + std::to_string(corner.first) + " of " + std::to_string(numPoints);
    }
  }
  for (long f : contents.Holes)
  {
    if (f < 0 || f >= numFaces)
    {
      return "hole tag names face " + std::to_string(f) + " of " + std::to_string(numFaces);
    }
  }
  return "";
}

// Appends each element of `elements` to `cells` as one cell.
void ToCells(const std::vector<std::vector<long>>& elements, vtkCellArray* cells)
{
  for (const auto& element : elements)
  {
    cells->InsertNextCell(static_cast<vtkIdType>(element.size()));
    for (long v : element)
    {
      cells->InsertCellPoint(v);
    }
  }
}

// Splits the vertices at texture seams as VTK's readers do: a corner whose vertex carries
// another texture coordinate in an earlier corner gets a copy of the vertex, a point per
// (vertex, texture coordinate). The file's vertices keep their numbers (lines and tags name
// them); copies follow. Corners without texture coordinates use the vertex itself.
void SplitAtTextureSeams(OBJContents& contents)
{
  const long numVertices = static_cast<long>(contents.Points.size() / 3);
  contents.PointTexCoord.assign(static_cast<size_t>(numVertices), -1);
  std::map<std::pair<long, long>, long> copies;
  for (size_t h = 0; h < contents.FaceCorners.size(); ++h)
  {
    const long v = static_cast<long>(contents.FaceCorners[h]), t = contents.FaceTexCorners[h];
    if (t < 0 || contents.PointTexCoord[v] == t)
    {
      continue;
    }
    if (contents.PointTexCoord[v] < 0)
    {
      contents.PointTexCoord[v] = t;
      continue;
    }
    const auto copy = copies.emplace(std::make_pair(v, t), static_cast<long>(contents.PointTexCoord.size()));
    if (copy.second)
    {
      contents.Points.insert(contents.Points.end(), { contents.Points[3 * v], contents.Points[3 * v + 1],
                                                      contents.Points[3 * v + 2] });
      contents.PointTexCoord.push_back(t);
      contents.CopyOf.push_back(v);
    }
    contents.FaceCorners[h] = copy.first->second;
  }
}

// The "TCoords" point data of the split points ((0, 0) for a point no textured face uses).
void AddTexCoords(const OBJContents& contents, vtkPolyData* output)
{
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("TCoords");
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(static_cast<vtkIdType>(contents.PointTexCoord.size()));
  for (size_t p = 0; p < contents.PointTexCoord.size(); ++p)
  {
    const long t = contents.PointTexCoord[p];
    tcoords->SetTuple2(static_cast<vtkIdType>(p), t < 0 ? 0.0 : contents.TexCoords[2 * t],
      t < 0 ? 0.0 : contents.TexCoords[2 * t + 1]);
  }
  output->GetPointData()->SetTCoords(tcoords);
}

// Sets the output's points, its faces (Polys) and its polylines then crease chains (Lines,
// only if there are some).
void BuildGeometry(const OBJContents& contents, vtkPolyData* output)
{
  const long numPoints = static_cast<long>(contents.Points.size() / 3);
  const vtkIdType numFaces = static_cast<vtkIdType>(contents.FaceOffsets.size()) - 1;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(numPoints);
  for (long i = 0; i < numPoints; ++i)
  {
    points->SetPoint(i, &contents.Points[3 * i]);
  }
  vtkNew<vtkCellArray> polys, lines;
  {
    vtkNew<vtkIdTypeArray> offsets, connectivity; // the flat lists as they are
    offsets->SetNumberOfValues(numFaces + 1);
    std::copy(contents.FaceOffsets.begin(), contents.FaceOffsets.end(), offsets->GetPointer(0));
    connectivity->SetNumberOfValues(static_cast<vtkIdType>(contents.FaceCorners.size()));
    std::copy(contents.FaceCorners.begin(), contents.FaceCorners.end(), connectivity->GetPointer(0));
    polys->SetData(offsets, connectivity);
  }
  ToCells(contents.Polylines, lines);
  ToCells(contents.CreaseChains, lines);
  output->SetPoints(points);
  output->SetPolys(polys);
  if (lines->GetNumberOfCells() > 0)
  {
    output->SetLines(lines);
  }
}

// Adds the "Sharpness", "Hole" and "CornerSharpness" arrays the file's tags ask for to the
// output BuildGeometry made.
void AddTagArrays(const OBJContents& contents, vtkPolyData* output)
{
  // Cell order is lines (polylines, then crease tags), then faces.
  const vtkIdType numLines = static_cast<vtkIdType>(contents.Polylines.size() + contents.CreaseChains.size());
  const vtkIdType numCells = numLines + static_cast<vtkIdType>(contents.FaceOffsets.size()) - 1;
  if (!contents.CreaseChains.empty())
  {
    vtkNew<vtkFloatArray> sharpness;
    sharpness->SetName("Sharpness");
    sharpness->SetNumberOfTuples(numCells);
    sharpness->Fill(0.0);
    const vtkIdType numPolylines = static_cast<vtkIdType>(contents.Polylines.size());
    for (vtkIdType c = 0; c < numPolylines; ++c)
    {
      sharpness->SetValue(c, 10.0f);
    }
    for (size_t c = 0; c < contents.ChainSharpness.size(); ++c)
    {
      sharpness->SetValue(numPolylines + static_cast<vtkIdType>(c), contents.ChainSharpness[c]);
    }
    output->GetCellData()->AddArray(sharpness);
  }
  if (!contents.Holes.empty())
  {
    vtkNew<vtkUnsignedCharArray> holes;
    holes->SetName("Hole");
    holes->SetNumberOfTuples(numCells);
    holes->Fill(0);
    for (long f : contents.Holes)
    {
      holes->SetValue(numLines + f, 1);
    }
    output->GetCellData()->AddArray(holes);
  }
  if (!contents.Corners.empty())
  {
    vtkNew<vtkFloatArray> corners;
    corners->SetName("CornerSharpness");
    corners->SetNumberOfTuples(static_cast<vtkIdType>(contents.Points.size() / 3));
    corners->Fill(0.0);
    for (const auto& corner : contents.Corners)
    {
      corners->SetValue(corner.first, corner.second);
    }
    const vtkIdType numVertices = corners->GetNumberOfTuples() - static_cast<vtkIdType>(contents.CopyOf.size());
    for (size_t c = 0; c < contents.CopyOf.size(); ++c) // a vertex's copies at seams are as sharp
    {
      corners->SetValue(numVertices + static_cast<vtkIdType>(c), corners->GetValue(contents.CopyOf[c]));
    }
    output->GetPointData()->AddArray(corners);
  }
}

// The names of `tags`, separated by ", ".
std::string JoinNames(const std::set<std::string>& tags)
{
  std::string names;
  for (const std::string& name : tags)
  {
    names += (names.empty() ? "" : ", ") + name;
  }
  return names;
}
}

bool vtkSubDOBJReader::ReadFile(std::istream& file, vtkPolyData* output)
{
  OBJContents contents;
  std::string line;
  std::vector<long> element;
  for (long lineNumber = 1; std::getline(file, line); ++lineNumber)
  {
    const std::string problem = ParseLine(line, contents, element);
    if (!problem.empty())
    {
      return this->Fail(lineNumber, problem);
    }
  }
  // Indices are checked once the whole file is read, then the cells are built.
  if (contents.Points.empty())
  {
    return this->Fail(0, "no vertices");
  }
  const std::string error = CheckIndices(contents);
  if (!error.empty())
  {
    return this->Fail(0, error);
  }
  if (contents.AnyTexCorner)
  {
    SplitAtTextureSeams(contents);
  }
  BuildGeometry(contents, output);
  AddTagArrays(contents, output);
  if (contents.AnyTexCorner)
  {
    AddTexCoords(contents, output);
  }
  if (!contents.SkippedTags.empty())
  {
    vtkWarningMacro("'" << this->FileName << "': skipped tag(s) SubD does not use: " << JoinNames(contents.SkippedTags)
                        << ".");
  }
  return true;
}

void vtkSubDOBJReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
