#include "vtkSubDOffscreenRenderWindow.h"

#include "SubDGLXShim.h"

#include "vtkObjectFactory.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <cstring>
#include <dlfcn.h>
#include <string>
#include <vector>

namespace
{
// Contexts alive in the process: the GLX shim answers from their loader while any exists.
int LiveContexts = 0;

void RetainLoader(subdgl::ProcLoader loader)
{
  ++LiveContexts;
  subdgl::SetProcLoader(loader);
}

void ReleaseLoader()
{
  if (--LiveContexts == 0)
  {
    subdgl::SetProcLoader(nullptr);
  }
}

// OSMesa's entry points, from the process (the program links libOSMesa).
struct OSMesaFunctions
{
  using Context = void*;
  Context (*CreateContextExt)(unsigned format, int depth, int stencil, int accum, Context share) = nullptr;
  unsigned char (*MakeCurrent)(Context, void* buffer, unsigned type, int width, int height) = nullptr;
  void (*DestroyContext)(Context) = nullptr;
  Context (*GetCurrentContext)() = nullptr;
  subdgl::ProcLoader GetProcAddress = nullptr;

  bool Load()
  {
    auto get = [](const char* name) { return ::dlsym(RTLD_DEFAULT, name); };
    CreateContextExt = reinterpret_cast<decltype(CreateContextExt)>(get("OSMesaCreateContextExt"));
    MakeCurrent = reinterpret_cast<decltype(MakeCurrent)>(get("OSMesaMakeCurrent"));
    DestroyContext = reinterpret_cast<decltype(DestroyContext)>(get("OSMesaDestroyContext"));
    GetCurrentContext = reinterpret_cast<decltype(GetCurrentContext)>(get("OSMesaGetCurrentContext"));
    GetProcAddress = reinterpret_cast<subdgl::ProcLoader>(get("OSMesaGetProcAddress"));
    return CreateContextExt && MakeCurrent && DestroyContext && GetCurrentContext && GetProcAddress;
  }
};

void* EGLLoader(const char* name)
{
  return reinterpret_cast<void*>(::eglGetProcAddress(name));
}

const char* EGLErrorName(EGLint error)
{
  switch (error)
  {
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    default: return "EGL error";
  }
}
}

// One offscreen context of a fixed size: an EGL pbuffer or an OSMesa buffer.
class vtkSubDOffscreenRenderWindow::vtkContext
{
public:
  bool IsOSMesa = false;
  int Width = 0, Height = 0;
  EGLDisplay Display = EGL_NO_DISPLAY;
  EGLSurface Surface = EGL_NO_SURFACE;
  EGLContext Egl = EGL_NO_CONTEXT;
  OSMesaFunctions OSMesa;
  void* OSMesaContext = nullptr;
  std::vector<unsigned char> Buffer; // OSMesa's colour buffer, RGBA

  ~vtkContext()
  {
    if (this->IsOSMesa && this->OSMesaContext)
    {
      this->OSMesa.DestroyContext(this->OSMesaContext);
      ReleaseLoader();
    }
    else if (this->Display != EGL_NO_DISPLAY)
    {
      ::eglMakeCurrent(this->Display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      if (this->Egl != EGL_NO_CONTEXT)
      {
        ::eglDestroyContext(this->Display, this->Egl);
        ReleaseLoader();
      }
      if (this->Surface != EGL_NO_SURFACE)
      {
        ::eglDestroySurface(this->Display, this->Surface);
      }
    }
  }

  bool CreateOSMesa(std::string& error)
  {
    if (!vtkSubDOffscreenRenderWindow::ProcessUsesOSMesa() || !this->OSMesa.Load())
    {
      error = "OSMesa is not this process's OpenGL: link the program with libOSMesa ahead of "
              "libGL (or use the EGL backend)";
      return false;
    }
    const unsigned rgba = 0x1908; // GL_RGBA
    this->OSMesaContext = this->OSMesa.CreateContextExt(rgba, 24, 0, 0, nullptr);
    if (!this->OSMesaContext)
    {
      error = "OSMesaCreateContextExt failed";
      return false;
    }
    this->IsOSMesa = true;
    RetainLoader(this->OSMesa.GetProcAddress);
    this->Buffer.resize(static_cast<size_t>(this->Width) * this->Height * 4);
    return true;
  }

  bool CreateEGL(std::string& error)
  {
    auto getPlatformDisplay =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(::eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay)
    {
      error = "EGL has no eglGetPlatformDisplayEXT (install libegl-mesa0)";
      return false;
    }
    this->Display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (this->Display == EGL_NO_DISPLAY || !::eglInitialize(this->Display, &major, &minor))
    {
      error = "no EGL surfaceless display (Mesa's EGL, libegl-mesa0, is needed)";
      return false;
    }
    if (!::eglBindAPI(EGL_OPENGL_API))
    {
      error = "EGL cannot bind the desktop OpenGL API";
      return false;
    }
    const EGLint configAttributes[] = { EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8,
      EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8, EGL_DEPTH_SIZE, 24, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE };
    EGLConfig config;
    EGLint numConfigs = 0;
    if (!::eglChooseConfig(this->Display, configAttributes, &config, 1, &numConfigs) || numConfigs < 1)
    {
      error = "no EGL config with an 8-bit RGBA pbuffer and a depth buffer";
      return false;
    }
    const EGLint surfaceAttributes[] = { EGL_WIDTH, this->Width, EGL_HEIGHT, this->Height, EGL_NONE };
    this->Surface = ::eglCreatePbufferSurface(this->Display, config, surfaceAttributes);
    if (this->Surface == EGL_NO_SURFACE)
    {
      error = std::string("eglCreatePbufferSurface failed: ") + EGLErrorName(::eglGetError());
      return false;
    }
    const EGLint contextAttributes[] = { EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 2,
      EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE };
    this->Egl = ::eglCreateContext(this->Display, config, EGL_NO_CONTEXT, contextAttributes);
    if (this->Egl == EGL_NO_CONTEXT)
    {
      error = std::string("no OpenGL 3.2 core EGL context: ") + EGLErrorName(::eglGetError());
      return false;
    }
    RetainLoader(&EGLLoader);
    return true;
  }

  bool MakeCurrent()
  {
    if (this->IsOSMesa)
    {
      const unsigned unsignedByte = 0x1401; // GL_UNSIGNED_BYTE
      return this->OSMesa.MakeCurrent(
               this->OSMesaContext, this->Buffer.data(), unsignedByte, this->Width, this->Height) != 0;
    }
    return ::eglMakeCurrent(this->Display, this->Surface, this->Surface, this->Egl) == EGL_TRUE;
  }

  bool IsCurrent() const
  {
    return this->IsOSMesa ? this->OSMesa.GetCurrentContext() == this->OSMesaContext
                          : ::eglGetCurrentContext() == this->Egl;
  }
};

vtkStandardNewMacro(vtkSubDOffscreenRenderWindow);

vtkSubDOffscreenRenderWindow::vtkSubDOffscreenRenderWindow()
{
  this->SetMultiSamples(0); // deterministic pixels
  this->SetOffScreenRendering(1);
  this->SetUseOffScreenBuffers(true);
}

vtkSubDOffscreenRenderWindow::~vtkSubDOffscreenRenderWindow()
{
  this->Finalize();
}

bool vtkSubDOffscreenRenderWindow::ProcessUsesOSMesa()
{
  void* clear = ::dlsym(RTLD_DEFAULT, "glClear");
  Dl_info info;
  return clear && ::dladdr(clear, &info) && info.dli_fname && std::strstr(info.dli_fname, "OSMesa");
}

const char* vtkSubDOffscreenRenderWindow::GetBackendInUse()
{
  if (!this->Context)
  {
    return "none";
  }
  return this->Context->IsOSMesa ? "osmesa" : "egl";
}

bool vtkSubDOffscreenRenderWindow::CreateContext()
{
  if (this->Context)
  {
    return true;
  }
  if (this->ContextFailed)
  {
    return false;
  }
  auto context = std::make_unique<vtkContext>();
  context->Width = this->Size[0] > 0 ? this->Size[0] : 300;
  context->Height = this->Size[1] > 0 ? this->Size[1] : 300;
  const bool osmesa = this->Backend == BACKEND_OSMESA || (this->Backend == BACKEND_AUTO && ProcessUsesOSMesa());
  std::string error;
  if (!(osmesa ? context->CreateOSMesa(error) : context->CreateEGL(error)) || !context->MakeCurrent())
  {
    vtkErrorMacro(<< "Cannot create an offscreen " << (osmesa ? "OSMesa" : "EGL")
                  << " OpenGL context: " << (error.empty() ? "make-current failed" : error) << ".");
    this->ContextFailed = true;
    return false;
  }
  this->Context = std::move(context);
  this->Superclass::SetSize(this->Context->Width, this->Context->Height);
  if (!this->InitializeFromCurrentContext())
  {
    vtkErrorMacro(<< "VTK could not initialise OpenGL from the offscreen context.");
    this->Context.reset();
    this->ContextFailed = true;
    return false;
  }
  this->SetReadyForRendering(true);
  this->SetIsCurrent(true);
  return true;
}

void vtkSubDOffscreenRenderWindow::Render()
{
  if (!this->CreateContext())
  {
    return;
  }
  this->Superclass::Render();
}

void vtkSubDOffscreenRenderWindow::MakeCurrent()
{
  if (this->Context)
  {
    this->Context->MakeCurrent();
  }
}

bool vtkSubDOffscreenRenderWindow::IsCurrent()
{
  return this->Context && this->Context->IsCurrent();
}

int vtkSubDOffscreenRenderWindow::SupportsOpenGL()
{
  return this->CreateContext() ? 1 : 0;
}

vtkTypeBool vtkSubDOffscreenRenderWindow::IsDirect()
{
  return this->Context ? 1 : 0;
}

void vtkSubDOffscreenRenderWindow::SetSize(int width, int height)
{
  if (this->Context && (width != this->Context->Width || height != this->Context->Height))
  {
    vtkWarningMacro(<< "The offscreen buffer is " << this->Context->Width << "x" << this->Context->Height
                    << " since the first render; SetSize(" << width << ", " << height << ") is ignored.");
    return;
  }
  this->Superclass::SetSize(width, height);
}

void vtkSubDOffscreenRenderWindow::Finalize()
{
  if (this->Context)
  {
    this->Context->MakeCurrent();
    this->ReleaseGraphicsResources(this);
    this->Context.reset();
  }
  this->SetReadyForRendering(false);
}

void vtkSubDOffscreenRenderWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  static const char* const names[] = { "Auto", "EGL", "OSMesa" };
  os << indent << "Backend: " << names[this->Backend] << "\n";
  os << indent << "BackendInUse: " << this->GetBackendInUse() << "\n";
}
