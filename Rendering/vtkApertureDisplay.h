/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureDisplay.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureDisplay
 * @brief   the render windows the module opens itself, and their X display (private)
 *
 * VTK 9.1's X render windows abort the program when they cannot reach the X server. An X server
 * whose last client leaves resets itself, and a connection attempted meanwhile fails, so windows
 * opened and closed one after another (one per filter) would fail at random. The module
 * therefore opens one connection when it first needs it, reports a missing display as an error,
 * hands that connection to its windows (vtkRenderWindow::SetDisplayId()), and keeps it open for
 * the rest of the program. A VTK whose windows are not X windows (EGL, OSMesa) needs no display,
 * and none is checked.
 *
 * NewOffScreenWindow() opens such a window for filters that render without one of the caller's.
 */

#ifndef vtkApertureDisplay_h
#define vtkApertureDisplay_h

#include "vtkApertureLightingRenderingModule.h" // For export macro

#include <string>

class vtkRenderWindow;

class VTKAPERTURELIGHTINGRENDERING_EXPORT vtkApertureDisplay
{
public:
  /**
   * The shared connection (an X11 Display*, or nullptr without X11). Returns false, with the
   * reason in `problem`, when there is no display to open.
   */
  static bool Get(void*& display, std::string& problem);

  /**
   * A new small off-screen render window on the shared connection whose OpenGL VTK can use (the
   * caller deletes it), or nullptr with the reason, a sentence, in `problem`.
   */
  static vtkRenderWindow* NewOffScreenWindow(std::string& problem);
};

#endif
// VTK-HeaderTest-Exclude: vtkApertureDisplay.h
