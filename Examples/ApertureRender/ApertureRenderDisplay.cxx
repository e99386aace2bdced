/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderDisplay.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "ApertureRenderDisplay.h"

#include "vtkApertureText.h"
#include "vtkRenderWindow.h"

#include <X11/Xlib.h>

#include <cstdlib>

namespace ApertureRender
{
namespace
{
void* OpenDisplay(std::string& error)
{
  const char* name = std::getenv("DISPLAY");
  Display* display = XOpenDisplay(nullptr);
  if (!display)
  {
    error = "cannot open the X display " + vtkApertureText::Quote(name ? name : "") +
      " (Debian's VTK renders through X: run under xvfb-run -a -s '-screen 0 1280x1024x24' "
      "for pictures without a screen)";
    return nullptr;
  }
  const int depth = DefaultDepth(display, DefaultScreen(display));
  if (depth < 24)
  {
    XCloseDisplay(display);
    error = "the X display " + vtkApertureText::Quote(name ? name : "") + " has " +
      std::to_string(depth) +
      "-bit colour; OpenGL needs 24 (with Xvfb: xvfb-run -a -s '-screen 0 1280x1024x24')";
    return nullptr;
  }
  return display;
}
}

bool AttachDisplay(vtkRenderWindow* window, void*& display, std::string& error)
{
  display = nullptr;
  if (!window->IsA("vtkXOpenGLRenderWindow"))
  {
    return true;
  }
  display = OpenDisplay(error);
  window->SetDisplayId(display);
  return display != nullptr;
}

void CloseDisplay(void* display)
{
  if (display)
  {
    XCloseDisplay(static_cast<Display*>(display));
  }
}
}
