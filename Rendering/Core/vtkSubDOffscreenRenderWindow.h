/**
 * @class   vtkSubDOffscreenRenderWindow
 * @brief   an OpenGL render window with no display server: EGL surfaceless or OSMesa
 *
 * Debian's VTK 9.1 is built for X/GLX only, so a plain vtkRenderWindow needs an X server
 * (or Xvfb). This window owns an offscreen OpenGL context it creates itself and drives
 * VTK's vtkGenericOpenGLRenderWindow with it, so images render on a headless machine with
 * Mesa's software rasterizer (llvmpipe):
 *
 * - EGL: Mesa's surfaceless platform (EGL_MESA_platform_surfaceless), a pbuffer of the
 *   window's size and an OpenGL 3.2 core context. Works in any process, Python included,
 *   because glvnd dispatches GL calls to whichever context is current.
 * - OSMesa: an OSMesa context rendering into a buffer in memory. Its GL entry points must
 *   come before libGL's in the process's symbol lookup (the program links libOSMesa first,
 *   as `subd` and the image tests do): otherwise the GL calls VTK makes go to glvnd, which
 *   knows nothing of OSMesa contexts.
 *
 * BACKEND_AUTO takes OSMesa when the process's GL entry points are libOSMesa's and EGL
 * otherwise. Either way the same scene gives the same pixels (llvmpipe in both, no
 * multisampling). Debian's GLEW still asks GLX for entry points; this library answers
 * those queries from the active context's loader (SubDGLXShim.h).
 *
 * The context is created at the first Render() with the size set then; a later SetSize
 * is refused with a warning (the offscreen buffer has a fixed size). If no context can be
 * made, Render() reports an error and draws nothing; GetBackendInUse() says what was used.
 */
#ifndef vtkSubDOffscreenRenderWindow_h
#define vtkSubDOffscreenRenderWindow_h

#include "SubDRenderingModule.h" // for export macro
#include "vtkGenericOpenGLRenderWindow.h"

#include <memory> // for std::unique_ptr

class SUBDRENDERING_EXPORT vtkSubDOffscreenRenderWindow : public vtkGenericOpenGLRenderWindow
{
public:
  static vtkSubDOffscreenRenderWindow* New();
  vtkTypeMacro(vtkSubDOffscreenRenderWindow, vtkGenericOpenGLRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Backends
  {
    BACKEND_AUTO = 0,
    BACKEND_EGL = 1,
    BACKEND_OSMESA = 2
  };

  ///@{
  /**
   * Which offscreen context to create (default BACKEND_AUTO). Only effective before the
   * first Render().
   */
  vtkSetClampMacro(Backend, int, BACKEND_AUTO, BACKEND_OSMESA);
  vtkGetMacro(Backend, int);
  void SetBackendToAuto() { this->SetBackend(BACKEND_AUTO); }
  void SetBackendToEGL() { this->SetBackend(BACKEND_EGL); }
  void SetBackendToOSMesa() { this->SetBackend(BACKEND_OSMESA); }
  ///@}

  /**
   * "egl" or "osmesa" once a context exists, "none" before or if creating it failed.
   */
  const char* GetBackendInUse();

  /**
   * True if the process's GL entry points are libOSMesa's (BACKEND_AUTO then uses OSMesa).
   */
  static bool ProcessUsesOSMesa();

  /**
   * Creates the context now (Render() does it when needed). Returns false, with an error,
   * if no offscreen context could be made.
   */
  bool CreateContext();

  void Render() override;
  void MakeCurrent() override;
  bool IsCurrent() override;
  int SupportsOpenGL() override;
  vtkTypeBool IsDirect() override;
  void SetSize(int width, int height) override;
  void SetSize(int size[2]) override { this->SetSize(size[0], size[1]); }
  void Finalize() override;

protected:
  vtkSubDOffscreenRenderWindow();
  ~vtkSubDOffscreenRenderWindow() override;

  int Backend = BACKEND_AUTO;

private:
  vtkSubDOffscreenRenderWindow(const vtkSubDOffscreenRenderWindow&) = delete;
  void operator=(const vtkSubDOffscreenRenderWindow&) = delete;

  class vtkContext;
  std::unique_ptr<vtkContext> Context;
  bool ContextFailed = false;
};

#endif
