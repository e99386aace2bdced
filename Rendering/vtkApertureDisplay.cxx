/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureDisplay.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureDisplay.h"

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
    problem = std::string("cannot open the X display '") + (name ? name : "") +
      "' (Debian's VTK renders through X; without a screen, run under xvfb-run)";
    return false;
  }
  if (DefaultDepth(shared, DefaultScreen(shared)) < 24)
  {
    problem = std::string("the X display '") + (name ? name : "") +
      "' has fewer than 24 bits of colour, which OpenGL needs";
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
  void* display = nullptr;
  if (!vtkApertureDisplay::Get(display, problem))
  {
    problem = "No OpenGL context: " + problem + ".";
    return nullptr;
  }
  vtkRenderWindow* window = vtkRenderWindow::New();
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
