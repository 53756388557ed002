// SubD rendering: the few GLX entry points Debian's GLEW calls while VTK initialises OpenGL.
//
// Debian builds VTK for GLX only; its GLEW asks glXGetProcAddressARB for every entry point
// and glXGetCurrentDisplay for a display, which fail without an X server. libSubDRendering
// defines these symbols itself (exported, so they take precedence over libGL's when the
// library is loaded before it, as in any program linked against it) and answers from the
// offscreen context's own loader: eglGetProcAddress or OSMesaGetProcAddress.
#ifndef SubDGLXShim_h
#define SubDGLXShim_h

namespace subdgl
{
using ProcLoader = void* (*)(const char*);
/// The loader the shim forwards to (nullptr: none; glXGetProcAddressARB then answers null).
void SetProcLoader(ProcLoader loader);
}

#endif
