/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkVisibilityCameraPass.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkVisibilityCameraPass.h"

#include "vtkVisibilityCameraFS.h"
#include "vtkVisibilityScene.h"

#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

//------------------------------------------------------------------------------
vtkVisibilityCameraPass::vtkVisibilityCameraPass(vtkVisibilityScene& scene)
  : Scene(scene)
{
}

//------------------------------------------------------------------------------
vtkVisibilityCameraPass::~vtkVisibilityCameraPass()
{
  this->ReleaseGraphicsResources(this->Scene.GetWindow());
}

//------------------------------------------------------------------------------
bool vtkVisibilityCameraPass::Visible(const float matrix[16], int width, int height,
  const std::vector<std::uint32_t>& candidates, bool queries, std::vector<char>& seen,
  std::string& error)
{
  seen.assign(candidates.size() / 3, 0);
  if (seen.empty())
  {
    return true;
  }
  if (!this->Prepare(width, height, candidates, queries, error))
  {
    return false;
  }
  vtkOpenGLState* state = this->Scene.GetWindow()->GetState();
  state->PushFramebufferBindings();
  {
    vtkVisibilityScene::PassState pass(state);
    this->Framebuffer->Bind();
    state->vtkglViewport(0, 0, width, height);
    // The whole scene's depth, pushed back by the polygon offset so that a candidate is not
    // hidden by itself.
    this->Scene.DrawDepth(matrix);
    state->vtkglDepthMask(GL_FALSE);
    state->vtkglDepthFunc(GL_LEQUAL);
    if (queries)
    {
      this->QueryCandidates(seen);
    }
    else
    {
      this->MarkCandidates(matrix, seen);
    }
  }
  state->PopFramebufferBindings();
  return true;
}

//------------------------------------------------------------------------------
bool vtkVisibilityCameraPass::Prepare(int width, int height,
  const std::vector<std::uint32_t>& candidates, bool queries, std::string& error)
{
  if (!this->Scene.MakeCurrent(error))
  {
    return false;
  }
  if ((!queries &&
        !this->Scene.ReadyProgram(this->Program, this->VAO,
          vtkVisibilityScene::PointsVS430().c_str(), vtkVisibilityCameraFS, "camera-view",
          error)) ||
    !this->Scene.DepthTarget(this->Depth, this->Framebuffer, width, height, "camera-view", error))
  {
    return false;
  }
  if (!this->Candidates)
  {
    this->Candidates = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    this->Candidates->SetType(vtkOpenGLBufferObject::ElementArrayBuffer);
  }
  if (!this->Candidates->Upload(candidates, vtkOpenGLBufferObject::ElementArrayBuffer))
  {
    error = "the triangles to test could not be uploaded (" + this->Candidates->GetError() + ")";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkVisibilityCameraPass::QueryCandidates(std::vector<char>& seen)
{
  // The paper's pass: one query per triangle, with the depth program DrawDepth() left current.
  vtkOpenGLVertexArrayObject* points = this->Scene.GetDepthVAO();
  points->Bind();
  this->Candidates->Bind();
  this->Scene.QueryEach(
    seen.size(),
    [](size_t i)
    {
      glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT,
        reinterpret_cast<const void*>(3 * i * sizeof(std::uint32_t)));
    },
    [&seen](size_t i) { seen[i] = 1; });
  points->Release();
}

//------------------------------------------------------------------------------
void vtkVisibilityCameraPass::MarkCandidates(const float matrix[16], std::vector<char>& seen)
{
  const size_t count = seen.size();
  std::vector<std::uint32_t> bits((count + 31) / 32, 0u);
  const size_t bytes = bits.size() * sizeof(std::uint32_t);
  vtkVisibilityScene::ResizeStorage(this->Storage, bytes, bits.data());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, this->Storage);
  this->Scene.GetWindow()->GetShaderCache()->ReadyShaderProgram(this->Program);
  this->Program->SetUniformMatrix4x4("clipMatrix", const_cast<float*>(matrix));
  this->VAO->Bind();
  this->Candidates->Bind();
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(3 * count), GL_UNSIGNED_INT, nullptr);
  this->VAO->Release();
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  vtkVisibilityScene::ReadStorage(this->Storage, bytes, bits.data());
  for (size_t i = 0; i < count; ++i)
  {
    seen[i] = (bits[i / 32] >> (i % 32)) & 1u;
  }
}

//------------------------------------------------------------------------------
void vtkVisibilityCameraPass::ReleaseGraphicsResources(vtkWindow* window)
{
  if (!window || window != this->Scene.GetWindow())
  {
    return;
  }
  if (vtkVisibilityScene::MakeCurrentIfLive(this->Scene.GetWindow()) && this->Storage)
  {
    glDeleteBuffers(1, &this->Storage);
  }
  this->Storage = 0;
  this->Program = nullptr; // the window's shader cache releases its programs
  if (this->VAO)
  {
    this->VAO->ReleaseGraphicsResources();
    this->VAO = nullptr;
  }
  if (this->Candidates)
  {
    this->Candidates->ReleaseGraphicsResources();
    this->Candidates = nullptr;
  }
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(window);
    this->Framebuffer = nullptr;
  }
  if (this->Depth)
  {
    this->Depth->ReleaseGraphicsResources(window);
    this->Depth = nullptr;
  }
}
