// vtkSubDFileScanner: the bytes of a whole file, read as words, lines and raw values, never
// past their end.
//
// SubD's legacy VTK and PLY readers parse headers made of words and bodies that are either
// ASCII numbers or raw binary values. Both trust nothing in the file: every count is weighed
// against the bytes left before anything is allocated for it (ReserveFor), every read is
// bounds-checked, and numbers are parsed without the C locale (std::from_chars), so a comma
// locale cannot change what a file means.
#ifndef vtkSubDFileScanner_h
#define vtkSubDFileScanner_h

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <functional>
#include <istream>
#include <iterator>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

namespace subdio
{
class FileScanner
{
public:
  /// Reads the whole stream. False (with nothing read) when it cannot be read.
  bool Load(std::istream& in)
  {
    // One read of the known size where the stream can seek (files); else byte by byte.
    const std::streamoff start = in.tellg();
    const std::streamoff end = start >= 0 && in.seekg(0, std::ios::end) ? std::streamoff(in.tellg()) : -1;
    if (start >= 0 && end >= start && in.seekg(start))
    {
      this->Bytes.resize(static_cast<size_t>(end - start));
      in.read(&this->Bytes[0], static_cast<std::streamsize>(this->Bytes.size()));
      this->Bytes.resize(static_cast<size_t>(in.gcount()));
      in.clear(in.rdstate() & ~(std::ios::failbit | std::ios::eofbit)); // a short read is not an error
    }
    else
    {
      in.clear(in.rdstate() & ~std::ios::failbit);
      this->Bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    this->Position = 0;
    this->LineNumber = 1;
    return !in.bad();
  }

  size_t Remaining() const { return this->Bytes.size() - this->Position; }
  bool AtEnd() const { return this->Position >= this->Bytes.size(); }
  /// Where the next read starts, in bytes from the start of the file.
  size_t Offset() const { return this->Position; }
  /// The line the next text read starts on (counting stops being exact after binary data).
  long Line() const { return this->LineNumber; }

  /// Skips white space (the C set: space, \t, \n, \v, \f, \r) and reads the next word; false at
  /// the end of the bytes.
  bool NextWord(std::string& word)
  {
    this->SkipSpace();
    const size_t start = this->Position;
    while (!this->AtEnd() && !IsSpace(this->Bytes[this->Position]))
    {
      ++this->Position;
    }
    word.assign(this->Bytes, start, this->Position - start);
    return !word.empty();
  }

  /// The next word without consuming it; empty at the end.
  std::string PeekWord()
  {
    const size_t position = this->Position;
    const long line = this->LineNumber;
    std::string word;
    this->NextWord(word);
    this->Position = position;
    this->LineNumber = line;
    return word;
  }

  /// The rest of the current line (without its \n or a \r before it), moving past its end.
  /// False at the end of the bytes.
  bool NextLine(std::string& line)
  {
    if (this->AtEnd())
    {
      return false;
    }
    const size_t start = this->Position;
    const size_t newline = this->Bytes.find('\n', start);
    const size_t end = newline == std::string::npos ? this->Bytes.size() : newline;
    line.assign(this->Bytes, start, end - start);
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    this->Position = newline == std::string::npos ? end : end + 1;
    this->LineNumber += newline == std::string::npos ? 0 : 1;
    return true;
  }

  /// Moves past the end of the current line (binary data starts after it).
  void SkipRestOfLine()
  {
    std::string ignored;
    this->NextLine(ignored);
  }

  /// Reads the next word as a number of type T. Integer types accept only integers within
  /// their range; floating types accept what strtod does in the C locale, "nan" and "inf" too.
  template <typename T>
  bool NextNumber(T& value)
  {
    this->SkipSpace();
    const char* first = this->Bytes.data() + this->Position;
    const char* last = this->Bytes.data() + this->Bytes.size();
    const char* wordEnd = std::find_if(first, last, IsSpace);
    if (!ParseWord(first, wordEnd, value))
    {
      return false;
    }
    this->Position = static_cast<size_t>(wordEnd - this->Bytes.data());
    return true;
  }

  /// Parses the whole word [first, last) as a number of type T, as NextNumber does, whatever
  /// the C locale (readers that tokenise on their own use it too).
  template <typename T>
  static bool ParseWord(const char* first, const char* last, T& value)
  {
    const char* digits = (first != last && *first == '+') ? first + 1 : first; // from_chars refuses '+'
    const ParseResult result = Parse(digits, last, value);
    return digits != last && result.ptr == last && result.ec == std::errc();
  }

  /// Copies `count` raw values of type T, swapping their bytes when the file's byte order
  /// (`bigEndian`) is not the machine's. False, reading nothing, when the bytes run out.
  template <typename T>
  bool NextBinary(T* values, size_t count, bool bigEndian)
  {
    if (count > this->Remaining() / sizeof(T))
    {
      return false;
    }
    std::memcpy(values, this->Bytes.data() + this->Position, count * sizeof(T));
    this->Position += count * sizeof(T);
    if (bigEndian != MachineIsBigEndian() && sizeof(T) > 1)
    {
      auto* bytes = reinterpret_cast<unsigned char*>(values);
      for (size_t i = 0; i < count; ++i)
      {
        std::reverse(bytes + i * sizeof(T), bytes + (i + 1) * sizeof(T));
      }
    }
    return true;
  }

  /// True when `count` values, each taking at least `bytesEach` bytes in the file, can still
  /// be in it: checked before allocating for a count the file announces.
  bool ReserveFor(double count, double bytesEach) const
  {
    return count * bytesEach <= static_cast<double>(this->Remaining()) + 1;
  }

  static bool MachineIsBigEndian()
  {
    const std::uint16_t probe = 1;
    unsigned char first;
    std::memcpy(&first, &probe, 1);
    return first == 0;
  }

  static bool IsSpace(char c)
  {
    return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
  }

private:
  struct ParseResult
  {
    const char* ptr;
    std::errc ec;
  };

  template <typename T>
  static ParseResult Parse(const char* first, const char* last, T& value)
  {
    if constexpr (std::is_floating_point<T>::value)
    {
      // from_chars reports a value too small for T as out of range; a file of doubles
      // written as text may hold such a value, which stands for zero. Too large stays an error.
      auto r = std::from_chars(first, last, value, std::chars_format::general);
      if (r.ec == std::errc::result_out_of_range)
      {
        const std::string text(first, r.ptr);
        const bool tiny = text.find("e-") != std::string::npos || text.find("E-") != std::string::npos;
        value = 0;
        return { r.ptr, tiny ? std::errc() : r.ec };
      }
      return { r.ptr, r.ec };
    }
    else
    {
      auto r = std::from_chars(first, last, value);
      return { r.ptr, r.ec };
    }
  }

  void SkipSpace()
  {
    while (!this->AtEnd() && IsSpace(this->Bytes[this->Position]))
    {
      this->LineNumber += this->Bytes[this->Position] == '\n' ? 1 : 0;
      ++this->Position;
    }
  }

  std::string Bytes;
  size_t Position = 0;
  long LineNumber = 1;
};

/// Base of the parsers of SubD's readers: the file's bytes and how a problem is reported.
class FileParser
{
public:
  /// Reports a problem at a line of the file (0: no line) and returns false.
  using Reporter = std::function<bool(long line, const std::string& what)>;

protected:
  FileParser(FileScanner& scanner, Reporter report)
    : Scanner(scanner)
    , Report(std::move(report))
  {
  }

  /// Reports `what` where the scanner stands: at its line in a text file, at its byte offset
  /// in binary data (where line numbers mean little).
  bool Fail(const std::string& what)
  {
    return this->Binary ? this->Report(0, "near byte " + std::to_string(this->Scanner.Offset()) + ": " + what)
                        : this->Report(this->Scanner.Line(), what);
  }

  FileScanner& Scanner;
  Reporter Report;
  bool Binary = false;
};

/// Reads the whole `file` and runs Parser(scanner, report).Parse(output).
template <typename Parser, typename Output>
bool ParseFile(std::istream& file, Output* output, FileParser::Reporter report)
{
  FileScanner scanner;
  if (!scanner.Load(file))
  {
    return report(0, "the file cannot be read.");
  }
  Parser parser(scanner, std::move(report));
  return parser.Parse(output);
}
}

#endif
