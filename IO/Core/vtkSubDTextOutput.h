// Private helper of SubD's text writers (OBJ, OFF): numbers formatted by std::to_chars into
// a buffer that goes to the stream in large pieces.
//
// A stream's operator<< formats each number through the locale and a few virtual calls:
// writing a refined mesh of ten million quads that way took 51 s (armadillo, Catmull-Clark
// level 4, OBJ) after a refinement of 1.2 s. std::to_chars does neither, and for a double it
// gives the shortest text that reads back to the same bits: exact like setprecision(17),
// in fewer characters.
#ifndef vtkSubDTextOutput_h
#define vtkSubDTextOutput_h

#include <charconv>
#include <cstring>
#include <ostream>
#include <type_traits>
#include <vector>

class vtkSubDTextOutput
{
public:
  explicit vtkSubDTextOutput(std::ostream& stream)
    : Stream(stream)
    , Buffer(std::size_t(1) << 20)
  {
  }
  ~vtkSubDTextOutput() { this->Flush(); }
  vtkSubDTextOutput(const vtkSubDTextOutput&) = delete;
  vtkSubDTextOutput& operator=(const vtkSubDTextOutput&) = delete;

  vtkSubDTextOutput& operator<<(char c)
  {
    *this->Room(1) = c;
    ++this->Used;
    return *this;
  }
  vtkSubDTextOutput& operator<<(const char* text)
  {
    const std::size_t length = std::strlen(text);
    if (length > this->Buffer.size())
    {
      this->Flush();
      this->Stream.write(text, static_cast<std::streamsize>(length));
      return *this;
    }
    std::memcpy(this->Room(length), text, length);
    this->Used += length;
    return *this;
  }
  template <typename Integer,
    typename std::enable_if<std::is_integral<Integer>::value && !std::is_same<Integer, char>::value &&
        !std::is_same<Integer, bool>::value,
      int>::type = 0>
  vtkSubDTextOutput& operator<<(Integer value)
  {
    return this->Format(value);
  }
  vtkSubDTextOutput& operator<<(double value) { return this->Format(value); }

  /// Hands what is buffered to the stream (the destructor does too).
  void Flush()
  {
    this->Stream.write(this->Buffer.data(), static_cast<std::streamsize>(this->Used));
    this->Used = 0;
  }

private:
  // Room for `size` characters at the end of what is buffered.
  char* Room(std::size_t size)
  {
    if (this->Used + size > this->Buffer.size())
    {
      this->Flush();
    }
    return this->Buffer.data() + this->Used;
  }
  template <typename T>
  vtkSubDTextOutput& Format(T value)
  {
    constexpr std::size_t longest = 32; // a 64-bit integer or the shortest form of any double
    char* first = this->Room(longest);
    this->Used += static_cast<std::size_t>(std::to_chars(first, first + longest, value).ptr - first);
    return *this;
  }

  std::ostream& Stream;
  std::vector<char> Buffer;
  std::size_t Used = 0;
};

#endif
