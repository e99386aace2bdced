/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderDisplay.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The X display aperture-render renders on. VTK 9.1 aborts the program when it cannot reach one
// or finds no 24-bit visual, so the connection is opened and checked here and handed to the
// render window; holding it also keeps the X server from resetting between VTK's own
// connections, which made them fail at random under Xvfb. (A file of its own: Xlib's macros
// clash with VTK's names.)

#ifndef ApertureRenderDisplay_h
#define ApertureRenderDisplay_h

#include <string>

namespace ApertureRender
{
// An open connection to the X display (an X11 Display*), or nullptr with one sentence in `error`.
void* OpenDisplay(std::string& error);

void CloseDisplay(void* display);
}

#endif
