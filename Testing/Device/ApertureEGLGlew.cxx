/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureEGLGlew.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Debian's GLEW is built for GLX: its glewInit loads every OpenGL function of the current
// context, EGL's too, then fails for want of an X display while it looks for GLX's extensions,
// and VTK gives up on the context. Preloaded with the EGL window, this glewInit takes the place
// of GLEW's and accepts that one failure. Without GLEW_EGL, nothing else of GLEW's needs X.
#include <GL/glew.h>

#include <dlfcn.h>

extern "C" GLenum GLEWAPIENTRY glewInit()
{
  using Init = GLenum (*)();
  static const Init glew = reinterpret_cast<Init>(dlsym(RTLD_NEXT, "glewInit"));
  if (!glew)
  {
    return GLEW_ERROR_NO_GL_VERSION;
  }
  const GLenum result = glew();
  return result == GLEW_ERROR_NO_GLX_DISPLAY ? GLEW_OK : result;
}
