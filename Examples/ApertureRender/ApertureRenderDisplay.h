/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderDisplay.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The X display aperture-render renders on, where VTK's window is an X window. VTK 9.1 aborts
// the program when it cannot reach one or finds no 24-bit visual, so the connection is opened and
// checked here and handed to the render window; holding it also keeps the X server from
// resetting between VTK's own connections, which made them fail at random under Xvfb. Other
// windows (an EGL or OSMesa build of VTK, the EGL window of docs/testing.md) need no display.
// (A file of its own: Xlib's macros clash with VTK's names.)

#ifndef ApertureRenderDisplay_h
#define ApertureRenderDisplay_h

#include <string>

class vtkRenderWindow;

namespace ApertureRender
{
// Gives an X window its checked connection to the X display (an X11 Display*, returned in
// `display` for CloseDisplay()); false with one sentence in `error` when there is none. Other
// windows get nothing and need nothing.
bool AttachDisplay(vtkRenderWindow* window, void*& display, std::string& error);

void CloseDisplay(void* display);
}

#endif
