/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkVisibilityScene.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkVisibilityScene.h"

#include "vtkVisibilityDepthFS.h"
#include "vtkVisibilityDepthVS.h"

#include "vtkNew.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>

namespace
{
// Queries in flight: one batch is issued while the previous one is read.
constexpr int QueryBatch = 16384;

// Uploads `values` into `buffer` unless `uploaded` holds them already; `bytes` grows by what
// was uploaded.
template <typename T>
bool UploadChanged(vtkOpenGLBufferObject* buffer, vtkOpenGLBufferObject::ObjectType type,
  const std::vector<T>& values, std::vector<T>& uploaded, vtkIdType& bytes, std::string& error)
{
  if (values == uploaded && !values.empty())
  {
    return true;
  }
  if (!buffer->Upload(values, type))
  {
    uploaded.clear();
    error = "the scene could not be uploaded to the GPU (" + buffer->GetError() + ")";
    return false;
  }
  uploaded = values;
  bytes += static_cast<vtkIdType>(values.size() * sizeof(T));
  return true;
}
}

//------------------------------------------------------------------------------
vtkVisibilityScene::~vtkVisibilityScene()
{
  this->ReleaseGraphicsResources(this->Window);
}

//------------------------------------------------------------------------------
std::string vtkVisibilityScene::Missing(bool storage)
{
  if (storage)
  {
    return GLEW_VERSION_4_3 ? std::string()
                            : "OpenGL 4.3 (shader storage buffers and atomic operations)";
  }
  return GLEW_VERSION_3_3 || GLEW_ARB_occlusion_query2
    ? std::string()
    : "OpenGL 3.3 occlusion queries (GL_ANY_SAMPLES_PASSED)";
}

//------------------------------------------------------------------------------
bool vtkVisibilityScene::Set(vtkOpenGLRenderWindow* window, const std::vector<float>& points,
  const std::vector<std::uint32_t>& triangles, float factor, float units, std::string& error)
{
  if (this->Window != window)
  {
    this->ReleaseGraphicsResources(this->Window);
    this->Window = window;
  }
  window->MakeCurrent();
  this->Ready = false;
  this->OffsetFactor = factor;
  this->OffsetUnits = units;
  if (!this->Upload(points, triangles, error))
  {
    return false;
  }
  this->Ready = this->ReadyProgram(
    this->DepthProgram, this->DepthVAO, vtkVisibilityDepthVS, vtkVisibilityDepthFS, "depth", error);
  return this->Ready;
}

//------------------------------------------------------------------------------
bool vtkVisibilityScene::MakeCurrent(std::string& error)
{
  if (!this->Ready)
  {
    error = "no scene";
    return false;
  }
  this->Window->MakeCurrent();
  return true;
}

//------------------------------------------------------------------------------
bool vtkVisibilityScene::Upload(
  const std::vector<float>& points, const std::vector<std::uint32_t>& triangles, std::string& error)
{
  if (!this->Points)
  {
    this->Points = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    this->Points->SetType(vtkOpenGLBufferObject::ArrayBuffer);
    this->Triangles = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    this->Triangles->SetType(vtkOpenGLBufferObject::ElementArrayBuffer);
    this->UploadedPoints.clear();
    this->UploadedTriangles.clear();
  }
  this->UploadedBytes = 0;
  return UploadChanged(this->Points, vtkOpenGLBufferObject::ArrayBuffer, points,
           this->UploadedPoints, this->UploadedBytes, error) &&
    UploadChanged(this->Triangles, vtkOpenGLBufferObject::ElementArrayBuffer, triangles,
      this->UploadedTriangles, this->UploadedBytes, error);
}

//------------------------------------------------------------------------------
void vtkVisibilityScene::DrawDepth(const float matrix[16])
{
  vtkOpenGLState* state = this->Window->GetState();
  this->Window->GetShaderCache()->ReadyShaderProgram(this->DepthProgram);
  this->DepthProgram->SetUniformMatrix4x4("clipMatrix", const_cast<float*>(matrix));
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglClearDepth(1.0);
  state->vtkglClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(this->OffsetFactor, this->OffsetUnits);
  this->DrawTriangles(this->DepthVAO);
  glDisable(GL_POLYGON_OFFSET_FILL);
}

//------------------------------------------------------------------------------
vtkOpenGLVertexArrayObject* vtkVisibilityScene::GetDepthVAO() const
{
  return this->DepthVAO;
}

//------------------------------------------------------------------------------
void vtkVisibilityScene::DrawTriangles(vtkOpenGLVertexArrayObject* vao)
{
  vao->Bind();
  this->Triangles->Bind();
  glDrawElements(
    GL_TRIANGLES, static_cast<GLsizei>(this->UploadedTriangles.size()), GL_UNSIGNED_INT, nullptr);
  vao->Release();
}

//------------------------------------------------------------------------------
std::string vtkVisibilityScene::PointsVS430()
{
  std::string vs = vtkVisibilityDepthVS;
  vtkShaderProgram::Substitute(vs, "//VTK::System::Dec", "#version 430 core");
  return vs;
}

//------------------------------------------------------------------------------
bool vtkVisibilityScene::ReadyProgram(vtkSmartPointer<vtkShaderProgram>& program,
  vtkSmartPointer<vtkOpenGLVertexArrayObject>& vao, const char* vs, const char* fs,
  const char* what, std::string& error)
{
  if (program)
  {
    return true;
  }
  vtkShaderProgram* compiled = this->Window->GetShaderCache()->ReadyShaderProgram(vs, fs, "");
  if (!compiled)
  {
    error = std::string("the ") + what + " shader did not compile";
    return false;
  }
  vtkNew<vtkOpenGLVertexArrayObject> bound;
  bound->Bind();
  const bool ok = bound->AddAttributeArray(
    compiled, this->Points, "vertexMC", 0, 3 * sizeof(float), VTK_FLOAT, 3, false);
  bound->Release();
  if (!ok)
  {
    error = std::string("the scene's points could not be bound to the ") + what + " shader";
    return false;
  }
  program = compiled;
  vao = bound;
  return true;
}

//------------------------------------------------------------------------------
bool vtkVisibilityScene::DepthTarget(vtkSmartPointer<vtkTextureObject>& texture,
  vtkSmartPointer<vtkOpenGLFramebufferObject>& framebuffer, int width, int height, const char* what,
  std::string& error)
{
  if (texture && texture->GetWidth() == static_cast<unsigned int>(width) &&
    texture->GetHeight() == static_cast<unsigned int>(height))
  {
    return true;
  }
  this->NewTexture(texture);
  bool ready = texture->AllocateDepth(width, height, vtkTextureObject::Float32);
  if (!ready)
  {
    error = "a " + std::to_string(width) + " x " + std::to_string(height) + " " + what +
      " depth texture could not be allocated";
  }
  else
  {
    ready = this->Attach(
      framebuffer,
      [&texture](vtkOpenGLFramebufferObject* bound)
      {
        bound->AddDepthAttachment(texture);
        bound->DeactivateDrawBuffers();
        bound->DeactivateReadBuffer();
      },
      what, error);
  }
  if (!ready)
  {
    texture->ReleaseGraphicsResources(this->Window);
    texture = nullptr;
  }
  return ready;
}

//------------------------------------------------------------------------------
bool vtkVisibilityScene::Attach(vtkSmartPointer<vtkOpenGLFramebufferObject>& framebuffer,
  const std::function<void(vtkOpenGLFramebufferObject*)>& attach, const char* what,
  std::string& error)
{
  if (!framebuffer)
  {
    framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    framebuffer->SetContext(this->Window);
  }
  vtkOpenGLState* state = this->Window->GetState();
  state->PushFramebufferBindings();
  framebuffer->Bind();
  attach(framebuffer);
  const char* status = nullptr;
  const bool complete = vtkOpenGLFramebufferObject::GetFrameBufferStatus(GL_FRAMEBUFFER, status);
  state->PopFramebufferBindings();
  if (!complete)
  {
    error =
      std::string("the ") + what + " framebuffer is incomplete (" + (status ? status : "") + ")";
  }
  return complete;
}

//------------------------------------------------------------------------------
void vtkVisibilityScene::NewTexture(vtkSmartPointer<vtkTextureObject>& texture)
{
  if (texture)
  {
    texture->ReleaseGraphicsResources(this->Window);
  }
  texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(this->Window);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
}

//------------------------------------------------------------------------------
void vtkVisibilityScene::QueryEach(
  size_t count, const std::function<void(size_t)>& draw, const std::function<void(size_t)>& passed)
{
  if (this->Queries.empty())
  {
    this->Queries.resize(2 * QueryBatch);
    glGenQueries(static_cast<GLsizei>(this->Queries.size()), this->Queries.data());
  }
  // Batches of queries: issue one, then read the one before, so that the GPU is not waited for
  // query by query.
  auto read = [&](size_t first, size_t number, const unsigned int* ids)
  {
    for (size_t i = 0; i < number; ++i)
    {
      GLuint samples = 0;
      glGetQueryObjectuiv(ids[i], GL_QUERY_RESULT, &samples);
      if (samples)
      {
        passed(first + i);
      }
    }
  };
  size_t pendingFirst = 0, pendingCount = 0;
  const unsigned int* pendingIds = nullptr;
  for (size_t first = 0, batch = 0; first < count; first += QueryBatch, ++batch)
  {
    const size_t number = std::min<size_t>(QueryBatch, count - first);
    const unsigned int* ids = this->Queries.data() + (batch % 2) * QueryBatch;
    for (size_t i = 0; i < number; ++i)
    {
      glBeginQuery(GL_ANY_SAMPLES_PASSED, ids[i]);
      draw(first + i);
      glEndQuery(GL_ANY_SAMPLES_PASSED);
    }
    if (pendingIds)
    {
      read(pendingFirst, pendingCount, pendingIds);
    }
    pendingFirst = first;
    pendingCount = number;
    pendingIds = ids;
  }
  if (pendingIds)
  {
    read(pendingFirst, pendingCount, pendingIds);
  }
}

//------------------------------------------------------------------------------
void vtkVisibilityScene::ResizeStorage(unsigned int& buffer, size_t bytes, const void* data)
{
  if (!buffer)
  {
    glGenBuffers(1, &buffer);
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
  glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(bytes), data, GL_DYNAMIC_READ);
}

//------------------------------------------------------------------------------
void vtkVisibilityScene::ReadStorage(unsigned int buffer, size_t bytes, void* data)
{
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(bytes), data);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

//------------------------------------------------------------------------------
vtkVisibilityScene::PassState::PassState(vtkOpenGLState* state)
  : Viewport(state)
  , DepthMask(state)
  , ColorMask(state)
  , DepthFunc(state)
  , DepthTest(state, GL_DEPTH_TEST)
  , CullFace(state, GL_CULL_FACE)
  , Blend(state, GL_BLEND)
  , Scissor(state, GL_SCISSOR_TEST)
  , Offset(state, GL_POLYGON_OFFSET_FILL)
{
  glGetFloatv(GL_POLYGON_OFFSET_FACTOR, &this->Factor);
  glGetFloatv(GL_POLYGON_OFFSET_UNITS, &this->Units);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_CULL_FACE);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglDepthFunc(GL_LESS);
  state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
}

//------------------------------------------------------------------------------
vtkVisibilityScene::PassState::~PassState()
{
  glPolygonOffset(this->Factor, this->Units);
}

//------------------------------------------------------------------------------
bool vtkVisibilityScene::MakeCurrentIfLive(vtkOpenGLRenderWindow* window)
{
  const bool live = window && window->GetGenericContext() != nullptr;
  if (live)
  {
    window->MakeCurrent();
  }
  return live;
}

//------------------------------------------------------------------------------
void vtkVisibilityScene::ReleaseGraphicsResources(vtkWindow* window)
{
  if (!this->Window || window != this->Window)
  {
    return;
  }
  if (MakeCurrentIfLive(this->Window) && !this->Queries.empty())
  {
    glDeleteQueries(static_cast<GLsizei>(this->Queries.size()), this->Queries.data());
  }
  this->Queries.clear();
  this->DepthProgram = nullptr; // the window's shader cache releases its programs
  if (this->DepthVAO)
  {
    this->DepthVAO->ReleaseGraphicsResources();
    this->DepthVAO = nullptr;
  }
  for (auto* buffer : { &this->Points, &this->Triangles })
  {
    if (*buffer)
    {
      (*buffer)->ReleaseGraphicsResources();
      *buffer = nullptr;
    }
  }
  this->UploadedPoints.clear();
  this->UploadedTriangles.clear();
  this->Window = nullptr;
  this->Ready = false;
}
