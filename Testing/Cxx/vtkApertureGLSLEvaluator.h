/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureGLSLEvaluator.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// For the tests of the GLSL twins: an off-screen OpenGL context that evaluates a fragment
// shader over inputs held in RGBA32F textures, one texel per case, in a full-screen pass into
// an RGBA32F target, and reads the results back.

#ifndef vtkApertureGLSLEvaluator_h
#define vtkApertureGLSLEvaluator_h

#include "vtkNew.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace vtkApertureTest
{
class GLSLEvaluator
{
public:
  GLSLEvaluator()
  {
    this->RenderWindow->SetOffScreenRendering(1);
    this->RenderWindow->SetSize(16, 16);
    this->RenderWindow->AddRenderer(this->Renderer);
    this->RenderWindow->Render();
    this->Window = vtkOpenGLRenderWindow::SafeDownCast(this->RenderWindow);
    this->Window->MakeCurrent();
  }

  vtkOpenGLRenderWindow* GetWindow() const { return this->Window; }

  /// An RGBA32F texture of width × height texels, four floats each.
  vtkSmartPointer<vtkTextureObject> Upload(int width, int height, std::vector<float>& data) const
  {
    auto texture = vtkSmartPointer<vtkTextureObject>::New();
    texture->SetContext(this->Window);
    texture->Create2DFromRaw(width, height, 4, VTK_FLOAT, data.data());
    return texture;
  }

  /// Renders `quad` into width × height texels of four floats (NaN where it could not run):
  /// each texture bound under its sampler's name, then `setUniforms` for the rest.
  std::vector<float> Run(vtkOpenGLQuadHelper& quad, int width, int height,
    const std::vector<std::pair<const char*, vtkTextureObject*>>& textures,
    const std::function<void(vtkShaderProgram*)>& setUniforms) const
  {
    vtkNew<vtkTextureObject> target;
    target->SetContext(this->Window);
    target->Create2D(width, height, 4, VTK_FLOAT, false);
    vtkNew<vtkOpenGLFramebufferObject> fbo;
    fbo->SetContext(this->Window);
    vtkOpenGLState* state = this->Window->GetState();
    state->PushFramebufferBindings();
    fbo->Bind();
    fbo->AddColorAttachment(0, target);
    fbo->ActivateDrawBuffer(0);
    fbo->ActivateReadBuffer(0);
    std::vector<float> result(4 * width * height, std::numeric_limits<float>::quiet_NaN());
    if (fbo->StartNonOrtho(width, height))
    {
      state->vtkglViewport(0, 0, width, height);
      state->vtkglDisable(GL_DEPTH_TEST);
      state->vtkglDisable(GL_BLEND);
      state->vtkglDisable(GL_SCISSOR_TEST);
      this->Window->GetShaderCache()->ReadyShaderProgram(quad.Program);
      for (const auto& texture : textures)
      {
        texture.second->Activate();
        quad.Program->SetUniformi(texture.first, texture.second->GetTextureUnit());
      }
      setUniforms(quad.Program);
      quad.Render();
      glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, result.data());
      for (const auto& texture : textures)
      {
        texture.second->Deactivate();
      }
    }
    state->PopFramebufferBindings();
    return result;
  }

private:
  vtkNew<vtkRenderWindow> RenderWindow;
  vtkNew<vtkRenderer> Renderer;
  vtkOpenGLRenderWindow* Window = nullptr;
};
}

#endif
// VTK-HeaderTest-Exclude: vtkApertureGLSLEvaluator.h
