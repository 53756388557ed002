// Private helper of SubD's writers (OBJ, OFF, PLY): bytes gathered in a buffer that goes to
// the stream in large pieces, numbers written as text (operator<<, std::to_chars) or as raw
// binary values (Put). Without a stream the buffer is a piece of text in memory, which is how
// vtkSubDFormatInParallel formats a file's lines on several threads.
//
// A stream's operator<< formats each number through the locale and a few virtual calls:
// writing a refined mesh of ten million quads that way took 51 s (armadillo, Catmull-Clark
// level 4, OBJ) after a refinement of 1.2 s. std::to_chars does neither, and for a double it
// gives the shortest text that reads back to the same bits: exact like setprecision(17),
// in fewer characters.
#ifndef vtkSubDBufferedOutput_h
#define vtkSubDBufferedOutput_h

#include "vtkCellArray.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <charconv>
#include <cstring>
#include <ostream>
#include <string>
#include <type_traits>
#include <vector>

class vtkSubDBufferedOutput
{
public:
  explicit vtkSubDBufferedOutput(std::ostream& stream)
    : Stream(&stream)
    , Buffer(std::size_t(1) << 20)
  {
  }
  /// Bytes kept in memory, growing as needed, until Clear (Append copies them elsewhere).
  vtkSubDBufferedOutput() = default;
  ~vtkSubDBufferedOutput() { this->Flush(); }
  vtkSubDBufferedOutput(const vtkSubDBufferedOutput&) = delete;
  vtkSubDBufferedOutput& operator=(const vtkSubDBufferedOutput&) = delete;

  vtkSubDBufferedOutput& operator<<(char c)
  {
    *this->Room(1) = c;
    ++this->Used;
    return *this;
  }
  vtkSubDBufferedOutput& operator<<(const char* text) { return this->Append(text, std::strlen(text)); }
  vtkSubDBufferedOutput& operator<<(const std::string& text) { return this->Append(text.data(), text.size()); }
  template <typename Integer,
    typename std::enable_if<std::is_integral<Integer>::value && !std::is_same<Integer, char>::value &&
        !std::is_same<Integer, bool>::value,
      int>::type = 0>
  vtkSubDBufferedOutput& operator<<(Integer value)
  {
    return this->Format(value);
  }
  vtkSubDBufferedOutput& operator<<(double value) { return this->Format(value); }

  /// A value's bytes as they are in memory (binary formats).
  template <typename T>
  void Put(T value)
  {
    static_assert(std::is_arithmetic<T>::value, "raw values are numbers");
    std::memcpy(this->Room(sizeof(T)), &value, sizeof(T));
    this->Used += sizeof(T);
  }

  /// Hands what is buffered to the stream (the destructor does too); nothing without a stream.
  void Flush()
  {
    if (this->Stream)
    {
      this->Stream->write(this->Buffer.data(), static_cast<std::streamsize>(this->Used));
      this->Used = 0;
    }
  }

  /// Appends the bytes another output holds in memory.
  void Append(const vtkSubDBufferedOutput& text) { this->Append(text.Buffer.data(), text.Used); }
  /// Forgets what is held in memory, keeping the room.
  void Clear() { this->Used = 0; }

private:
  vtkSubDBufferedOutput& Append(const char* text, std::size_t length)
  {
    if (this->Stream && length > this->Buffer.size())
    {
      this->Flush();
      this->Stream->write(text, static_cast<std::streamsize>(length));
      return *this;
    }
    std::memcpy(this->Room(length), text, length);
    this->Used += length;
    return *this;
  }
  // Room for `size` characters at the end of what is buffered: the stream takes what is
  // buffered, or (in memory) the buffer grows.
  char* Room(std::size_t size)
  {
    if (this->Used + size > this->Buffer.size())
    {
      this->Flush();
      if (this->Used + size > this->Buffer.size())
      {
        this->Buffer.resize(std::max(2 * this->Buffer.size(), this->Used + size));
      }
    }
    return this->Buffer.data() + this->Used;
  }
  template <typename T>
  vtkSubDBufferedOutput& Format(T value)
  {
    constexpr std::size_t longest = 32; // a 64-bit integer or the shortest form of any double
    char* first = this->Room(longest);
    this->Used += static_cast<std::size_t>(std::to_chars(first, first + longest, value).ptr - first);
    return *this;
  }

  std::ostream* Stream = nullptr;
  std::vector<char> Buffer;
  std::size_t Used = 0;
};

/// Writes items [0, count) to `out` with format(text, item), formatting them on vtkSMPTools'
/// threads: chunks of items are formatted each into its own text, a batch of chunks at a
/// time, and the texts appended in order. The bytes are those of one loop over the items;
/// the time is what to_chars costs (most of writing a text mesh), divided among the threads.
/// `format` must only read shared data.
template <typename Format>
void vtkSubDFormatInParallel(vtkSubDBufferedOutput& out, vtkIdType count, const Format& format)
{
  constexpr vtkIdType chunkSize = 8192;
  const vtkIdType numChunks = (count + chunkSize - 1) / chunkSize;
  // A few chunks per thread and batch: enough to balance, few enough that the texts held at
  // once stay small (some MiB) next to the mesh.
  const vtkIdType batchSize = 4 * std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads());
  std::vector<vtkSubDBufferedOutput> texts(static_cast<std::size_t>(std::min(batchSize, numChunks)));
  for (vtkIdType first = 0; first < numChunks; first += batchSize)
  {
    const vtkIdType last = std::min(numChunks, first + batchSize);
    vtkSMPTools::For(first, last, 1, [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType chunk = begin; chunk < end; ++chunk)
      {
        vtkSubDBufferedOutput& text = texts[static_cast<std::size_t>(chunk - first)];
        text.Clear();
        const vtkIdType itemEnd = std::min(count, (chunk + 1) * chunkSize);
        for (vtkIdType item = chunk * chunkSize; item < itemEnd; ++item)
        {
          format(text, item);
        }
      }
    });
    for (vtkIdType chunk = first; chunk < last; ++chunk)
    {
      out.Append(texts[static_cast<std::size_t>(chunk - first)]);
    }
  }
}

/// vtkSubDFormatInParallel over the cells of `cells`: format(text, points), `points` a range
/// of the cell's point ids (read from the cell array's own storage, 32- or 64-bit).
template <typename Format>
void vtkSubDFormatCellsInParallel(vtkSubDBufferedOutput& out, vtkCellArray* cells, const Format& format)
{
  cells->Visit([&](auto& storage) {
    vtkSubDFormatInParallel(out, cells->GetNumberOfCells(),
      [&](vtkSubDBufferedOutput& text, vtkIdType cell) { format(text, storage.GetCellRange(cell)); });
  });
}

#endif
