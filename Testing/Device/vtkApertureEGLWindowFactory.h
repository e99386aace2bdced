/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureEGLWindowFactory.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureEGLWindowFactory
 * @brief   makes every vtkRenderWindow a vtkApertureEGLRenderWindow
 *
 * Built as the library ApertureEGLWindow, which registers this factory when it is loaded:
 * `LD_PRELOAD=.../libApertureEGLWindow.so program` runs an unchanged VTK program, test driver or
 * Python script on EGL, without an X display. See docs/testing.md.
 */

#ifndef vtkApertureEGLWindowFactory_h
#define vtkApertureEGLWindowFactory_h

#include "vtkObjectFactory.h"

class vtkApertureEGLWindowFactory : public vtkObjectFactory
{
public:
  static vtkApertureEGLWindowFactory* New();
  vtkTypeMacro(vtkApertureEGLWindowFactory, vtkObjectFactory);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  const char* GetVTKSourceVersion() override;
  const char* GetDescription() override;

protected:
  vtkApertureEGLWindowFactory();

private:
  vtkApertureEGLWindowFactory(const vtkApertureEGLWindowFactory&) = delete;
  void operator=(const vtkApertureEGLWindowFactory&) = delete;
};

#endif
