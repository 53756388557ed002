// Test support: file names in gtest's temporary folder private to the running process.
#ifndef SubDTempFiles_h
#define SubDTempFiles_h

#include <gtest/gtest.h>

#include <string>
#include <unistd.h>

namespace subdtest
{
/// `prefix` + `name` in the temporary folder, with the process id: ctest -j runs the cases
/// of one program side by side, each in its own process, and cases that write a file of
/// the same name must not read each other's.
inline std::string ProcessTempPath(const std::string& prefix, const std::string& name)
{
  return std::string(::testing::TempDir()) + prefix + std::to_string(::getpid()) + "_" + name;
}
}

#endif
