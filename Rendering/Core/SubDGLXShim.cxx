#include "SubDGLXShim.h"

#include <cstring>
#include <dlfcn.h>

namespace
{
subdgl::ProcLoader CurrentLoader = nullptr;
int FakeDisplay = 0;

// The next definition of a GLX function (libGL's), for programs that also render to X
// windows: with no offscreen context active the shim is transparent.
template <typename Function>
Function Next(const char* name)
{
  return reinterpret_cast<Function>(::dlsym(RTLD_NEXT, name));
}
}

namespace subdgl
{
void SetProcLoader(ProcLoader loader)
{
  CurrentLoader = loader;
}
}

#define SUBD_GLX_EXPORT extern "C" __attribute__((visibility("default")))

// GLEW only needs a non-null display to proceed; it never dereferences it.
SUBD_GLX_EXPORT void* glXGetCurrentDisplay()
{
  if (!CurrentLoader)
  {
    auto next = Next<void* (*)()>("glXGetCurrentDisplay");
    return next ? next() : nullptr;
  }
  return &FakeDisplay;
}

SUBD_GLX_EXPORT void* glXGetProcAddressARB(const unsigned char* name)
{
  if (!CurrentLoader)
  {
    auto next = Next<void* (*)(const unsigned char*)>("glXGetProcAddressARB");
    return next ? next(name) : nullptr;
  }
  // GLEW looks the display query up through the loader too; neither EGL nor OSMesa has it.
  if (std::strcmp(reinterpret_cast<const char*>(name), "glXGetCurrentDisplay") == 0)
  {
    return reinterpret_cast<void*>(&glXGetCurrentDisplay);
  }
  return CurrentLoader(reinterpret_cast<const char*>(name));
}

SUBD_GLX_EXPORT void* glXGetProcAddress(const unsigned char* name)
{
  return glXGetProcAddressARB(name);
}

SUBD_GLX_EXPORT int glXQueryVersion(void* display, int* major, int* minor)
{
  if (!CurrentLoader)
  {
    auto next = Next<int (*)(void*, int*, int*)>("glXQueryVersion");
    return next ? next(display, major, minor) : 0;
  }
  *major = 1;
  *minor = 4;
  return 1;
}

SUBD_GLX_EXPORT const char* glXGetClientString(void* display, int name)
{
  if (!CurrentLoader)
  {
    auto next = Next<const char* (*)(void*, int)>("glXGetClientString");
    return next ? next(display, name) : nullptr;
  }
  return "";
}
