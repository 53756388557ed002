#include "SubDFileChecks.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iterator>
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
      // The count as written: it may be beyond any integer type (or not a number at all).
      const size_t close = text.find('"', quote + 1);
      const std::string written = text.substr(quote + 1, std::min<size_t>(close, quote + 41) - quote - 1);
      error = "'" + path + "' is not a valid VTK XML file: '" + text.substr(at, quote - at + 1) + written +
        "\"' announces more than its " + std::to_string(bytes.size()) + " bytes can hold";
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
