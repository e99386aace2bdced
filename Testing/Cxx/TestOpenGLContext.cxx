/*=========================================================================

  Program:   ApertureLighting
  Module:    TestOpenGLContext.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Rendering smoke test: an OpenGL core context can be created (under Xvfb in CI), reports what
// the module's shaders need, and renders a known picture.

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtk_glew.h"

#include <iostream>

namespace
{
const char* GLString(GLenum name)
{
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "(unknown)";
}
}

int TestOpenGLContext(int argc, char* argv[])
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.9, 0.6, 0.3);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.1, 0.1, 0.2);
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetSize(300, 300);
  renWin->AddRenderer(renderer);
  renWin->Render();

  auto* win = vtkOpenGLRenderWindow::SafeDownCast(renWin);
  if (!win || !win->SupportsOpenGL())
  {
    std::cerr << "No usable OpenGL context\n";
    return EXIT_FAILURE;
  }
  win->MakeCurrent();
  GLint major = 0, minor = 0, profile = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  std::cout << "OpenGL " << major << "." << minor
            << ((profile & GL_CONTEXT_CORE_PROFILE_BIT) ? " core" : "") << " from "
            << GLString(GL_VENDOR) << ", " << GLString(GL_RENDERER) << "\n";
  // The aperture mapper needs 3.2 core; the batched visibility paths need 4.3 (SSBOs).
  if (major * 10 + minor < 32)
  {
    std::cerr << "OpenGL 3.2 or later is required\n";
    return EXIT_FAILURE;
  }
  std::cout << "OpenGL 4.3 features (SSBO, compute): "
            << (major * 10 + minor >= 43 ? "available" : "missing") << "\n";

  int retVal = vtkRegressionTestImage(renWin);
  return !retVal;
}
