// The fuzz targets without libFuzzer (any compiler): replays files and directories of inputs,
// then, with --random N, N inputs of random bytes from a fixed seed. Every build runs the
// committed crash inputs and a short random run through this driver; the sanitizer build links
// the same targets with libFuzzer instead.
//   SubDFuzzReplay... [--random N] [--seed S] PATH...
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace
{
void RunFile(const std::filesystem::path& file, long& count)
{
  std::ifstream in(file, std::ios::binary);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::fprintf(stderr, "replay: %s (%zu bytes)\n", file.c_str(), bytes.size());
  LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
  ++count;
}
}

int main(int argc, char** argv)
{
  long random = 0;
  unsigned seed = 1;
  std::vector<std::filesystem::path> paths;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--random" && i + 1 < argc)
    {
      random = std::atol(argv[++i]);
      continue;
    }
    if (arg == "--seed" && i + 1 < argc)
    {
      seed = static_cast<unsigned>(std::strtoul(argv[++i], nullptr, 10));
      continue;
    }
    paths.emplace_back(arg);
  }
  long count = 0;
  for (const auto& path : paths)
  {
    if (std::filesystem::is_directory(path))
    {
      std::vector<std::filesystem::path> files;
      for (const auto& entry : std::filesystem::directory_iterator(path))
      {
        if (entry.is_regular_file() && entry.path().filename().string()[0] != '.')
        {
          files.push_back(entry.path());
        }
      }
      std::sort(files.begin(), files.end());
      for (const auto& file : files)
      {
        RunFile(file, count);
      }
    }
    else if (std::filesystem::exists(path))
    {
      RunFile(path, count);
    }
    else
    {
      std::fprintf(stderr, "replay: no such file or directory: %s\n", path.c_str());
      return 2;
    }
  }
  std::mt19937 generator(seed);
  std::uniform_int_distribution<int> byte(0, 255), length(0, 400);
  std::vector<uint8_t> input;
  for (long r = 0; r < random; ++r)
  {
    input.resize(static_cast<size_t>(length(generator)));
    for (uint8_t& b : input)
    {
      b = static_cast<uint8_t>(byte(generator));
    }
    LLVMFuzzerTestOneInput(input.data(), input.size());
    ++count;
  }
  std::printf("replay: %ld inputs, no failure\n", count);
  return 0;
}
