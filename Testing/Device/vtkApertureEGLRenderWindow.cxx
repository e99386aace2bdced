/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureEGLRenderWindow.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureEGLRenderWindow.h"

#include "vtkObjectFactory.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdlib>
#include <vector>

vtkStandardNewMacro(vtkApertureEGLRenderWindow);

namespace
{
// VTK draws into framebuffers of its own; the pbuffer only has to make the context current.
const EGLint PbufferSide = 16;

// An OpenGL (not ES) pbuffer config with the colour and depth VTK asks of its windows.
EGLConfig ChooseConfig(EGLDisplay display)
{
  const EGLint attributes[] = { EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RED_SIZE, 8, EGL_GREEN_SIZE,
    8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8, EGL_DEPTH_SIZE, 24, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
    EGL_NONE };
  EGLConfig config = nullptr;
  EGLint count = 0;
  if (!eglChooseConfig(display, attributes, &config, 1, &count) || count < 1)
  {
    return nullptr;
  }
  return config;
}

// The EGL devices (GPUs, Mesa's software device), where the driver lists them.
std::vector<EGLDeviceEXT> QueryDevices()
{
  auto queryDevices =
    reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  EGLint count = 0;
  if (!queryDevices || !queryDevices(0, nullptr, &count) || count < 1)
  {
    return {};
  }
  std::vector<EGLDeviceEXT> devices(static_cast<size_t>(count));
  queryDevices(count, devices.data(), &count);
  devices.resize(static_cast<size_t>(count));
  return devices;
}
}

//------------------------------------------------------------------------------
vtkApertureEGLRenderWindow::vtkApertureEGLRenderWindow()
{
  this->SetOffScreenRendering(1);
  this->SetReadyForRendering(true);
}

//------------------------------------------------------------------------------
vtkApertureEGLRenderWindow::~vtkApertureEGLRenderWindow()
{
  this->Finalize();
}

//------------------------------------------------------------------------------
bool vtkApertureEGLRenderWindow::OpenDisplay()
{
  auto platformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
    eglGetProcAddress("eglGetPlatformDisplayEXT"));
  const std::vector<EGLDeviceEXT> devices = QueryDevices();
  const char* chosen = std::getenv("APERTURE_EGL_DEVICE");
  const int only = chosen ? std::atoi(chosen) : -1;
  for (size_t i = 0; platformDisplay && i < devices.size(); ++i)
  {
    if (only >= 0 && static_cast<size_t>(only) != i)
    {
      continue;
    }
    EGLDisplay display = platformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
    EGLint major = 0, minor = 0;
    if (display != EGL_NO_DISPLAY && eglInitialize(display, &major, &minor))
    {
      if (EGLConfig config = ChooseConfig(display))
      {
        this->Display = display;
        this->Config = config;
        this->Description = "EGL device " + std::to_string(i);
        return true;
      }
      eglTerminate(display);
    }
  }
  // Drivers without device enumeration: the default display (EGL_PLATFORM picks Mesa's).
  EGLDisplay display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  EGLint major = 0, minor = 0;
  if (only < 0 && display != EGL_NO_DISPLAY && eglInitialize(display, &major, &minor))
  {
    if (EGLConfig config = ChooseConfig(display))
    {
      this->Display = display;
      this->Config = config;
      this->Description = "EGL default display";
      return true;
    }
  }
  this->Description = "no EGL device gives an OpenGL pbuffer";
  return false;
}

//------------------------------------------------------------------------------
bool vtkApertureEGLRenderWindow::CreateContext()
{
  if (this->Context || this->Failed)
  {
    return this->Context != nullptr;
  }
  this->Failed = true;
  if (!this->OpenDisplay() || !eglBindAPI(EGL_OPENGL_API))
  {
    vtkErrorMacro("No OpenGL context: " << this->Description << ".");
    return false;
  }
  const EGLint surfaceAttributes[] = { EGL_WIDTH, PbufferSide, EGL_HEIGHT, PbufferSide, EGL_NONE };
  this->Surface = eglCreatePbufferSurface(this->Display, this->Config, surfaceAttributes);
  // The newest core version first: NVIDIA's EGL gives exactly the version asked for, and 3.2,
  // VTK 9.1's least, lacks what the DepthCompare visibility and the volume mapper use.
  const EGLint versions[][2] = { { 4, 6 }, { 4, 5 }, { 4, 3 }, { 3, 3 }, { 3, 2 } };
  this->Context = EGL_NO_CONTEXT;
  for (size_t i = 0; this->Context == EGL_NO_CONTEXT && i < sizeof(versions) / sizeof(*versions);
       ++i)
  {
    const EGLint contextAttributes[] = { EGL_CONTEXT_MAJOR_VERSION, versions[i][0],
      EGL_CONTEXT_MINOR_VERSION, versions[i][1], EGL_CONTEXT_OPENGL_PROFILE_MASK,
      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE };
    this->Context =
      eglCreateContext(this->Display, this->Config, EGL_NO_CONTEXT, contextAttributes);
  }
  if (this->Surface == EGL_NO_SURFACE || this->Context == EGL_NO_CONTEXT)
  {
    vtkErrorMacro("No OpenGL context: " << this->Description
                                        << " refused an OpenGL 3.2 core context (EGL error 0x"
                                        << std::hex << eglGetError() << std::dec << ").");
    this->DestroyContext();
    return false;
  }
  this->Failed = false;
  return true;
}

//------------------------------------------------------------------------------
void vtkApertureEGLRenderWindow::DestroyContext()
{
  if (this->Display)
  {
    if (eglGetCurrentContext() == this->Context)
    {
      eglMakeCurrent(this->Display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    if (this->Context && this->Context != EGL_NO_CONTEXT)
    {
      eglDestroyContext(this->Display, this->Context);
    }
    if (this->Surface && this->Surface != EGL_NO_SURFACE)
    {
      eglDestroySurface(this->Display, this->Surface);
    }
  }
  // The display stays initialised: EGL shares it between all windows of the process.
  this->Context = nullptr;
  this->Surface = nullptr;
}

//------------------------------------------------------------------------------
void vtkApertureEGLRenderWindow::Initialize()
{
  if (!this->CreateContext())
  {
    return;
  }
  this->MakeCurrent();
  if (!this->Initialized)
  {
    this->OpenGLInit();
  }
}

//------------------------------------------------------------------------------
void vtkApertureEGLRenderWindow::Finalize()
{
  if (this->Context)
  {
    this->MakeCurrent();
    this->ReleaseGraphicsResources(this);
  }
  this->DestroyContext();
  this->Initialized = false;
}

//------------------------------------------------------------------------------
void vtkApertureEGLRenderWindow::MakeCurrent()
{
  if (this->CreateContext() && !this->IsCurrent())
  {
    eglMakeCurrent(this->Display, this->Surface, this->Surface, this->Context);
  }
}

//------------------------------------------------------------------------------
bool vtkApertureEGLRenderWindow::IsCurrent()
{
  return this->Context && eglGetCurrentContext() == this->Context;
}

//------------------------------------------------------------------------------
int vtkApertureEGLRenderWindow::SupportsOpenGL()
{
  return this->CreateContext() ? 1 : 0;
}

//------------------------------------------------------------------------------
void vtkApertureEGLRenderWindow::Frame()
{
  // vtkOpenGLRenderWindow's copy of the finished frame into the front buffer, which
  // vtkGenericOpenGLRenderWindow leaves to its observers; a pbuffer has nothing to swap.
  this->MakeCurrent();
  this->vtkOpenGLRenderWindow::Frame();
}

//------------------------------------------------------------------------------
void vtkApertureEGLRenderWindow::Start()
{
  this->Initialize();
  this->Superclass::Start();
}

//------------------------------------------------------------------------------
void vtkApertureEGLRenderWindow::Render()
{
  this->Initialize();
  if (this->Context)
  {
    this->Superclass::Render();
  }
}

//------------------------------------------------------------------------------
void vtkApertureEGLRenderWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Context: " << (this->Context ? "made" : (this->Failed ? "failed" : "not yet"))
     << "\n";
  os << indent << "ContextDescription: " << this->Description << "\n";
}
