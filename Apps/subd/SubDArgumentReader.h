// subd and the explorer: walking the command line, an option and its value at a time.
#ifndef SubDArgumentReader_h
#define SubDArgumentReader_h

#include <string>

namespace subdapp
{
class ArgumentReader
{
public:
  ArgumentReader(int argc, char* argv[])
    : Count(argc)
    , Arguments(argv)
  {
  }

  /// Moves to the next argument (the first one on the first call); false past the end.
  bool Next()
  {
    if (++this->Position >= this->Count)
    {
      return false;
    }
    this->CurrentArgument = this->Arguments[this->Position];
    return true;
  }
  const std::string& Current() const { return this->CurrentArgument; }

  /// The value that follows the current option (consumed); false with `error` when missing.
  bool Value(std::string& out, std::string& error)
  {
    if (this->Position + 1 >= this->Count)
    {
      error = "option " + this->CurrentArgument + " needs a value";
      return false;
    }
    out = this->Arguments[++this->Position];
    return true;
  }

private:
  int Count;
  char** Arguments;
  int Position = 0; // argv[0] is the program
  std::string CurrentArgument;
};
}

#endif
