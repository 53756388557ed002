#include "SubDFileChecks.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

namespace subdapp
{
namespace
{
bool ReadWholeFile(const std::string& path, std::vector<char>& bytes, std::string& error)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    error = "cannot open '" + path + "'";
    return false;
  }
  bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return true;
}

// Opens `path` for reading from its start, with its size in bytes.
bool OpenMeasured(const std::string& path, std::ifstream& in, std::streamoff& size, std::string& error)
{
  in.open(path, std::ios::binary | std::ios::ate);
  if (!in)
  {
    error = "cannot open '" + path + "'";
    return false;
  }
  size = in.tellg();
  in.seekg(0);
  return true;
}

// Size in bytes of a PLY scalar type, 0 when the name is not one.
int PLYTypeSize(const std::string& type)
{
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8")
  {
    return 1;
  }
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16")
  {
    return 2;
  }
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32")
  {
    return 4;
  }
  if (type == "double" || type == "float64")
  {
    return 8;
  }
  return 0;
}

struct PLYProperty
{
  std::string Name;
  bool IsList = false;
  std::string CountType; // lists: the type of the length
  int Size = 0;          // scalars: the value; lists: one item
  bool Integer = false;  // the value (lists: the items) is an integer type
};

struct PLYElement
{
  std::string Name;
  long long Count = 0;
  std::vector<PLYProperty> Properties;
};

// Reads an unsigned or signed integer of the PLY type `type` (1, 2 or 4 bytes).
long long ReadCount(const char* p, const std::string& type, bool bigEndian)
{
  const int size = PLYTypeSize(type);
  std::uint32_t value = 0;
  for (int k = 0; k < size; ++k)
  {
    const auto byte = static_cast<unsigned char>(p[bigEndian ? k : size - 1 - k]);
    value = (value << 8) | byte;
  }
  const bool isSigned = type == "char" || type == "int8" || type == "short" || type == "int16" || type == "int" ||
    type == "int32";
  if (isSigned && size < 4 && (value >> (8 * size - 1)))
  {
    return static_cast<long long>(value) - (1LL << (8 * size));
  }
  return isSigned ? static_cast<long long>(static_cast<std::int32_t>(value)) : static_cast<long long>(value);
}

bool IsIntegerType(const std::string& type)
{
  return PLYTypeSize(type) > 0 && PLYTypeSize(type) <= 4 && type.find("float") == std::string::npos;
}
}

bool CheckPLYFile(const std::string& path, std::string& error)
{
  std::vector<char> bytes;
  if (!ReadWholeFile(path, bytes, error))
  {
    return false;
  }
  const auto fail = [&](const std::string& what) {
    error = "'" + path + "' is not a valid PLY file: " + what;
    return false;
  };
  // Header: lines up to "end_header".
  size_t pos = 0;
  std::string format;
  std::vector<PLYElement> elements;
  bool ended = false;
  for (int lineNumber = 1; pos < bytes.size() && !ended; ++lineNumber)
  {
    size_t end = pos;
    while (end < bytes.size() && bytes[end] != '\n')
    {
      ++end;
    }
    std::string line(bytes.data() + pos, end - pos);
    pos = end + 1;
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (lineNumber == 1)
    {
      if (keyword != "ply")
      {
        return fail("it does not start with 'ply'");
      }
      continue;
    }
    if (keyword == "format")
    {
      words >> format;
    }
    else if (keyword == "element")
    {
      PLYElement element;
      if (!(words >> element.Name >> element.Count) || element.Count < 0)
      {
        return fail("header line " + std::to_string(lineNumber) + " ('" + line + "') is not 'element NAME COUNT'");
      }
      elements.push_back(element);
    }
    else if (keyword == "property")
    {
      PLYProperty property;
      std::string type;
      words >> type;
      if (type == "list")
      {
        std::string itemType;
        words >> property.CountType >> itemType >> property.Name;
        property.IsList = true;
        property.Size = PLYTypeSize(itemType);
        property.Integer = IsIntegerType(itemType);
        if (!IsIntegerType(property.CountType) || property.Size == 0)
        {
          return fail("header line " + std::to_string(lineNumber) + " ('" + line + "') has an unknown list type");
        }
      }
      else
      {
        words >> property.Name;
        property.Size = PLYTypeSize(type);
        property.Integer = IsIntegerType(type);
        if (property.Size == 0)
        {
          return fail("header line " + std::to_string(lineNumber) + " ('" + line + "') has an unknown type");
        }
      }
      if (elements.empty() || property.Name.empty())
      {
        return fail("header line " + std::to_string(lineNumber) + " ('" + line + "') is a property of no element");
      }
      elements.back().Properties.push_back(property);
    }
    else if (keyword == "end_header")
    {
      ended = true;
    }
    else if (keyword != "comment" && keyword != "obj_info" && !keyword.empty())
    {
      return fail("header line " + std::to_string(lineNumber) + " ('" + line + "') is not PLY");
    }
  }
  if (!ended)
  {
    return fail("its header has no 'end_header'");
  }
  const bool ascii = format == "ascii";
  const bool bigEndian = format == "binary_big_endian";
  if (!ascii && !bigEndian && format != "binary_little_endian")
  {
    return fail("format '" + format + "' is not ascii, binary_little_endian or binary_big_endian");
  }
  bool hasXYZ = false;
  for (const PLYElement& element : elements)
  {
    int coordinates = 0;
    bool indices = false;
    for (const PLYProperty& p : element.Properties)
    {
      coordinates += !p.IsList && (p.Name == "x" || p.Name == "y" || p.Name == "z");
      indices = indices || (p.IsList && (p.Name == "vertex_indices" || p.Name == "vertex_index"));
    }
    if (element.Name == "vertex")
    {
      hasXYZ = coordinates == 3;
    }
    if (element.Name == "face" && element.Count > 0 && !indices)
    {
      return fail("its faces have no 'vertex_indices' list");
    }
  }
  if (!hasXYZ)
  {
    return fail("it has no 'vertex' element with x, y and z");
  }

  // Body: every element's instances, in order. Each instance takes at least one byte (two
  // in ASCII), so a count beyond the remaining bytes is refused before walking it.
  for (const PLYElement& element : elements)
  {
    const size_t remaining = bytes.size() - std::min(pos, bytes.size());
    if (static_cast<double>(element.Count) > static_cast<double>(remaining) / (ascii ? 2.0 : 1.0))
    {
      return fail("the header announces " + std::to_string(element.Count) + " '" + element.Name +
        "' elements, more than the " + std::to_string(remaining) + " bytes of data can hold");
    }
    for (long long i = 0; i < element.Count; ++i)
    {
      // ASCII: one element per line (vtkPLYReader reads it as one line of words).
      size_t lineEnd = pos;
      if (ascii)
      {
        while (pos < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[pos])))
        {
          ++pos;
        }
        lineEnd = pos;
        while (lineEnd < bytes.size() && bytes[lineEnd] != '\n')
        {
          ++lineEnd;
        }
      }
      for (const PLYProperty& property : element.Properties)
      {
        long long items = 1;
        if (ascii)
        {
          // Words: the list length (an integer), then the items.
          for (long long t = 0; t < items + (property.IsList ? 1 : 0); ++t)
          {
            while (pos < lineEnd && std::isspace(static_cast<unsigned char>(bytes[pos])))
            {
              ++pos;
            }
            if (pos >= lineEnd)
            {
              return fail("line of '" + element.Name + "' element " + std::to_string(i) + " of " +
                std::to_string(element.Count) + " ends before its '" + property.Name + "' values");
            }
            const char* start = bytes.data() + pos;
            size_t length = 0;
            while (pos + length < lineEnd && !std::isspace(static_cast<unsigned char>(start[length])))
            {
              ++length;
            }
            const std::string token(start, length);
            pos += length;
            const bool integer = (property.IsList && t == 0) || property.Integer;
            char* parsed = nullptr;
            const double value = integer ? static_cast<double>(std::strtoll(token.c_str(), &parsed, 10))
                                         : std::strtod(token.c_str(), &parsed);
            if (parsed != token.c_str() + token.size())
            {
              return fail("'" + token + "' in '" + element.Name + "' element " + std::to_string(i) + " is not " +
                (integer ? "an integer" : "a number"));
            }
            if (property.IsList && t == 0)
            {
              if (value < 0 || value != static_cast<double>(static_cast<long long>(value)) ||
                value > static_cast<double>(bytes.size()))
              {
                return fail("list length '" + token + "' in '" + element.Name + "' element " + std::to_string(i));
              }
              items = static_cast<long long>(value);
            }
          }
          continue;
        }
        size_t need = static_cast<size_t>(property.Size);
        if (property.IsList)
        {
          const size_t countSize = static_cast<size_t>(PLYTypeSize(property.CountType));
          if (pos + countSize > bytes.size())
          {
            return fail("the file ends inside '" + element.Name + "' element " + std::to_string(i));
          }
          items = ReadCount(bytes.data() + pos, property.CountType, bigEndian);
          pos += countSize;
          if (items < 0)
          {
            return fail("a negative list length in '" + element.Name + "' element " + std::to_string(i));
          }
          need = static_cast<size_t>(items) * static_cast<size_t>(property.Size);
        }
        if (need > bytes.size() - std::min(pos, bytes.size()))
        {
          return fail("the file ends inside '" + element.Name + "' element " + std::to_string(i) + " of " +
            std::to_string(element.Count));
        }
        pos += need;
      }
      if (ascii)
      {
        pos = lineEnd; // words past the element's values are ignored, as the reader does
      }
    }
  }
  return true;
}

namespace
{
// Walks an ASCII legacy polydata's geometry (POINTS and the four cell sections, in the classic
// "n size" layout or the OFFSETS/CONNECTIVITY one) and returns what does not add up, or "".
// vtkPolyDataReader reads past a section whose counts do not match its values and crashes.
std::string LegacyASCIIProblem(std::istream& in)
{
  std::string token;
  // A number (a coordinate), or with `integer` an id or count: VTK reads "0.5" where it wants
  // an integer as 0 and then trips over ".5".
  const auto number = [&in, &token](double& value, bool integer = false) {
    if (!(in >> token))
    {
      return false;
    }
    char* end = nullptr;
    value = integer ? static_cast<double>(std::strtoll(token.c_str(), &end, 10)) : std::strtod(token.c_str(), &end);
    return end == token.c_str() + token.size();
  };
  std::string line;
  std::getline(in, line); // "# vtk DataFile Version x.y"
  std::getline(in, line); // the title
  in >> token >> token >> token; // ASCII DATASET POLYDATA: words, as the reader reads them
  std::string word;
  while (in >> word)
  {
    // vtkDataReader compares keywords without case, by their first letters.
    std::string keyword;
    for (const char* known : { "POINTS", "VERTICES", "LINES", "POLYGONS", "TRIANGLE_STRIPS" })
    {
      std::string upper = word.substr(0, std::string(known).size());
      std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char c) { return std::toupper(c); });
      keyword = upper == known ? known : keyword;
    }
    double count = 0, size = 0, value = 0;
    if (keyword == "POINTS")
    {
      if (!number(count, true) || !(in >> token))
      {
        return "POINTS has no count and type";
      }
      for (double k = 0; k < 3 * count; ++k)
      {
        if (!number(value))
        {
          return "POINTS announces " + std::to_string(static_cast<long long>(count)) + " points; value " +
            std::to_string(static_cast<long long>(k)) + " is missing or not a number";
        }
      }
      continue;
    }
    if (keyword.empty())
    {
      return ""; // attributes and the rest: the reader's own checks
    }
    if (!number(count, true) || !number(size, true) || count < 0 || size < 0)
    {
      return keyword + " has no valid counts";
    }
    const std::streampos start = in.tellg();
    if (in >> token && token == "OFFSETS")
    {
      // OFFSETS type and `count` offsets, then CONNECTIVITY type and `size` ids.
      in >> token;
      for (double k = 0; k < count; ++k)
      {
        if (!number(value, true))
        {
          return keyword + " ends before its " + std::to_string(static_cast<long long>(count)) + " offsets";
        }
      }
      if (!(in >> token) || token != "CONNECTIVITY" || !(in >> token))
      {
        return keyword + " has OFFSETS but no CONNECTIVITY";
      }
      for (double k = 0; k < size; ++k)
      {
        if (!number(value, true))
        {
          return keyword + " ends before its " + std::to_string(static_cast<long long>(size)) + " point ids";
        }
      }
      continue;
    }
    in.clear();
    in.seekg(start);
    double used = 0;
    for (double c = 0; c < count; ++c)
    {
      double n = 0;
      if (!number(n, true) || n < 0)
      {
        return keyword + " cell " + std::to_string(static_cast<long long>(c)) + " has no valid point count";
      }
      used += 1 + n;
      if (used > size)
      {
        return keyword + " holds more values than its size " + std::to_string(static_cast<long long>(size));
      }
      for (double k = 0; k < n; ++k)
      {
        if (!number(value, true))
        {
          return keyword + " cell " + std::to_string(static_cast<long long>(c)) + " ends early";
        }
      }
    }
    if (used != size)
    {
      return keyword + " announces " + std::to_string(static_cast<long long>(size)) + " values but its cells hold " +
        std::to_string(static_cast<long long>(used));
    }
  }
  return "";
}
}

bool CheckLegacyVTKFile(const std::string& path, std::string& error)
{
  std::ifstream in;
  std::streamoff fileSize = 0;
  if (!OpenMeasured(path, in, fileSize, error))
  {
    return false;
  }
  const double size = static_cast<double>(fileSize);
  // Every value takes at least one byte (binary files: at least four, ASCII: a digit and a
  // separator), so a count above the file's size is a lie whatever the encoding.
  std::string line;
  for (int lineNumber = 1; std::getline(in, line); ++lineNumber)
  {
    std::istringstream words(line);
    std::string keyword;
    double count = 0, values = 0;
    if (!(words >> keyword >> count))
    {
      continue;
    }
    if (keyword == "POINTS")
    {
      values = 3 * count;
    }
    else if (keyword == "VERTICES" || keyword == "LINES" || keyword == "POLYGONS" || keyword == "TRIANGLE_STRIPS")
    {
      double total = 0;
      values = (words >> total) ? std::max(count, total) : count;
    }
    else if (keyword == "POINT_DATA" || keyword == "CELL_DATA")
    {
      values = count;
    }
    if (values > size)
    {
      error = "'" + path + "' is not a valid VTK file: line " + std::to_string(lineNumber) + " ('" + line +
        "') announces more values than the file's " + std::to_string(static_cast<long long>(size)) + " bytes hold";
      return false;
    }
  }
  // ASCII files: the geometry's values must add up (the third line says ASCII or BINARY).
  in.clear();
  in.seekg(0);
  std::string header[3];
  for (std::string& h : header)
  {
    std::getline(in, h);
  }
  if (header[2].rfind("ASCII", 0) == 0)
  {
    in.seekg(0);
    const std::string problem = LegacyASCIIProblem(in);
    if (!problem.empty())
    {
      error = "'" + path + "' is not a valid VTK file: " + problem;
      return false;
    }
  }
  return true;
}

bool CheckXMLPolyDataFile(const std::string& path, std::string& error)
{
  std::vector<char> bytes;
  if (!ReadWholeFile(path, bytes, error))
  {
    return false;
  }
  const std::string text(bytes.begin(), bytes.end());
  const double limit = 1100.0 * static_cast<double>(bytes.size());
  for (size_t at = text.find("NumberOf"); at != std::string::npos; at = text.find("NumberOf", at + 8))
  {
    const size_t quote = text.find('"', at);
    if (quote == std::string::npos || quote > at + 40)
    {
      continue;
    }
    const double count = std::strtod(text.c_str() + quote + 1, nullptr);
    // A point has 3 values; a cell at least 2 (an offset and a point id).
    const double values = (text.compare(at, 14, "NumberOfPoints") == 0 ? 3.0 : 2.0) * count;
    if (!(values <= limit))
    {
      error = "'" + path + "' is not a valid VTK XML file: '" + text.substr(at, quote - at) +
        std::to_string(static_cast<long long>(count)) + "' announces more than its " + std::to_string(bytes.size()) +
        " bytes can hold";
      return false;
    }
  }
  return true;
}

bool CheckSTLFile(const std::string& path, std::string& error)
{
  std::ifstream in;
  std::streamoff size = 0;
  if (!OpenMeasured(path, in, size, error))
  {
    return false;
  }
  char head[84] = {};
  in.read(head, sizeof head);
  const std::streamsize got = in.gcount();
  // VTK's reader takes a file for ASCII when it starts with "solid" and has no binary bytes
  // in the part it looks at. Any non-text byte in the first megabyte, and the file is held
  // to the binary layout here, whatever its first word.
  bool text = got >= 5 && std::string(head, 5) == "solid";
  std::vector<char> start(head, head + got);
  if (text)
  {
    start.resize(1 << 20);
    in.clear();
    in.seekg(0);
    in.read(start.data(), static_cast<std::streamsize>(start.size()));
    start.resize(static_cast<size_t>(in.gcount()));
  }
  for (size_t k = 0; text && k < start.size(); ++k)
  {
    const auto c = static_cast<unsigned char>(start[k]);
    text = c == '\n' || c == '\r' || c == '\t' || (c >= 32 && c < 127);
  }
  if (text)
  {
    return true;
  }
  if (got < 84)
  {
    error = "'" + path + "' is not a valid STL file: " + std::to_string(size) +
      " bytes are too few for a binary STL header (84 bytes)";
    return false;
  }
  const std::uint32_t triangles = static_cast<std::uint32_t>(static_cast<unsigned char>(head[80])) |
    static_cast<std::uint32_t>(static_cast<unsigned char>(head[81])) << 8 |
    static_cast<std::uint32_t>(static_cast<unsigned char>(head[82])) << 16 |
    static_cast<std::uint32_t>(static_cast<unsigned char>(head[83])) << 24;
  if (84 + 50 * static_cast<double>(triangles) > static_cast<double>(size))
  {
    error = "'" + path + "' is not a valid STL file: its header counts " + std::to_string(triangles) +
      " triangles, but its " + std::to_string(size) + " bytes hold " + std::to_string((size - 84) / 50);
    return false;
  }
  return true;
}
}
