/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureDisplay.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureDisplay.h"

#include "vtkApertureText.h"
#include "vtkRenderWindow.h"

#ifdef APERTURE_USE_X11
#include <X11/Xlib.h>
#endif

#include <chrono>
#include <cstdlib>
#include <mutex>
#include <thread>

//------------------------------------------------------------------------------
bool vtkApertureDisplay::Get(void*& display, std::string& problem)
{
  display = nullptr;
#ifdef APERTURE_USE_X11
  static std::mutex mutex;
  static Display* shared = nullptr;
  std::lock_guard<std::mutex> lock(mutex);
  const char* name = std::getenv("DISPLAY");
  // A server resetting after its last client left refuses connections for a moment.
  for (int attempt = 0; !shared && attempt < 5; ++attempt)
  {
    if (attempt > 0)
    {
      std::this_thread::sleep_for(std::chrono::milliseconds(50 * attempt));
    }
    shared = XOpenDisplay(nullptr);
  }
  if (!shared)
  {
    problem = "cannot open the X display " + vtkApertureText::Quote(name ? name : "") +
      " (this VTK renders through X; without a screen, run under xvfb-run)";
    return false;
  }
  if (DefaultDepth(shared, DefaultScreen(shared)) < 24)
  {
    problem = "the X display " + vtkApertureText::Quote(name ? name : "") +
      " has fewer than 24 bits of colour, which OpenGL needs";
    return false;
  }
  display = shared;
#else
  (void)problem;
#endif
  return true;
}

//------------------------------------------------------------------------------
vtkRenderWindow* vtkApertureDisplay::NewOffScreenWindow(std::string& problem)
{
  // The window VTK was built with: only an X window needs the X display (an EGL or OSMesa
  // build of VTK renders without one, even where X11 was found when this module was built).
  vtkRenderWindow* window = vtkRenderWindow::New();
  void* display = nullptr;
  if (window->IsA("vtkXOpenGLRenderWindow") && !vtkApertureDisplay::Get(display, problem))
  {
    problem = "No OpenGL context: " + problem + ".";
    window->Delete();
    return nullptr;
  }
  if (display)
  {
    window->SetDisplayId(display);
  }
  window->SetOffScreenRendering(1);
  window->SetSize(16, 16);
  if (!window->SupportsOpenGL())
  {
    problem = "No usable OpenGL context: VTK needs OpenGL 3.2 and this display offers less.";
    window->Delete();
    return nullptr;
  }
  return window;
}
