// libFuzzer target: every file format `subd` reads, on arbitrary bytes.
//
// The first byte picks the format (.off .obj .ply .stl .vtk .vtp), the rest is the file. A read
// must either fail with a message or give a mesh whose coordinates and cells a filter can take;
// what it gives is then refined one level by Catmull-Clark, as `subd` would. Crashes, leaks and
// undefined behaviour are what the sanitizers report; an answer without a message is reported
// here.
#include "SubDFuzzSupport.h"
#include "SubDMeshIO.h"
#include "SubDSchemeRegistry.h"
#include "vtkPolyData.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>

// Full stacks for leak reports: VTK's libraries are built without frame pointers, so the fast
// unwinder stops at their first frame and lsan.supp could not name the VTK function that leaks.
extern "C" const char* __asan_default_options()
{
  return "fast_unwind_on_malloc=0";
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  static const char* const extensions[] = { ".off", ".obj", ".ply", ".stl", ".vtk", ".vtp" };
  if (size < 1)
  {
    return 0;
  }
  subdfuzz::SilenceVTK();
  const std::string path =
    subdfuzz::ScratchDirectory() + "/input-" + std::to_string(getpid()) + extensions[data[0] % 6];
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  std::string error;
  vtkSmartPointer<vtkPolyData> mesh = subdapp::ReadMesh(path, error);
  std::remove(path.c_str());
  if (!mesh)
  {
    if (error.empty())
    {
      std::fprintf(stderr, "FuzzReaders: a read failed without a message\n");
      std::abort();
    }
    return 0;
  }
  subdapp::SchemeOptions options;
  options.Levels = 1;
  subdfuzz::RunAndCheck(*subdapp::FindScheme("catmull-clark"), options, mesh);
  return 0;
}
