/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureEGLRenderWindow.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureEGLRenderWindow
 * @brief   an off-screen render window on an EGL pbuffer, for VTK builds that render through X
 *
 * Debian's VTK 9.1 opens every window on an X display. This window makes its own context
 * through EGL instead, on the first EGL device that gives an OpenGL 3.2 core context with a
 * pbuffer (or the one APERTURE_EGL_DEVICE names by index), so that the tests and tools run on a
 * machine with a GPU and no X server, and here, without a display, on Mesa. It always renders
 * off screen; everything else is vtkOpenGLRenderWindow's. vtkApertureEGLWindowFactory puts it
 * in place of vtkRenderWindow (see docs/testing.md).
 */

#ifndef vtkApertureEGLRenderWindow_h
#define vtkApertureEGLRenderWindow_h

#include "vtkGenericOpenGLRenderWindow.h"

#include <string>

class vtkApertureEGLRenderWindow : public vtkGenericOpenGLRenderWindow
{
public:
  static vtkApertureEGLRenderWindow* New();
  vtkTypeMacro(vtkApertureEGLRenderWindow, vtkGenericOpenGLRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Initialize() override;
  void Finalize() override;
  void MakeCurrent() override;
  bool IsCurrent() override;
  int SupportsOpenGL() override;
  int IsDirect() override { return 1; }
  void Frame() override;
  void Render() override;
  void Start() override;

  /**
   * What the context runs on ("EGL device 0: NVIDIA ..."), or why there is none.
   */
  const std::string& GetContextDescription() const { return this->Description; }

protected:
  vtkApertureEGLRenderWindow();
  ~vtkApertureEGLRenderWindow() override;

private:
  vtkApertureEGLRenderWindow(const vtkApertureEGLRenderWindow&) = delete;
  void operator=(const vtkApertureEGLRenderWindow&) = delete;

  bool CreateContext();
  bool OpenDisplay();
  void DestroyContext();

  // EGL's handles, kept as void* so that this header needs no EGL header.
  void* Display = nullptr;
  void* Config = nullptr;
  void* Context = nullptr;
  void* Surface = nullptr;
  bool Failed = false;
  std::string Description;
};

#endif
