/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureEGLWindowFactory.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureEGLWindowFactory.h"

#include "vtkApertureEGLRenderWindow.h"
#include "vtkVersion.h"

vtkStandardNewMacro(vtkApertureEGLWindowFactory);

namespace
{
vtkObject* NewEGLRenderWindow()
{
  return vtkApertureEGLRenderWindow::New();
}

// Registered when the library is loaded. Libraries the program loads beside this one may have
// registered VTK's own window factory already: their windows are switched off; factories that
// come later come after this one, and the first factory that makes a class wins.
struct Registration
{
  Registration()
  {
    vtkObjectFactory::SetAllEnableFlags(0, "vtkRenderWindow");
    vtkApertureEGLWindowFactory* factory = vtkApertureEGLWindowFactory::New();
    vtkObjectFactory::RegisterFactory(factory);
    factory->Delete();
  }
} registration;
}

//------------------------------------------------------------------------------
vtkApertureEGLWindowFactory::vtkApertureEGLWindowFactory()
{
  this->RegisterOverride("vtkRenderWindow", "vtkApertureEGLRenderWindow",
    "an off-screen OpenGL window on an EGL pbuffer", 1, NewEGLRenderWindow);
}

//------------------------------------------------------------------------------
const char* vtkApertureEGLWindowFactory::GetVTKSourceVersion()
{
  return VTK_SOURCE_VERSION;
}

//------------------------------------------------------------------------------
const char* vtkApertureEGLWindowFactory::GetDescription()
{
  return "ApertureLighting's EGL render windows";
}

//------------------------------------------------------------------------------
void vtkApertureEGLWindowFactory::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
