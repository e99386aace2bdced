/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkVisibilityRenderer.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkVisibilityRenderer.h"

#include "vtkVisibilityCameraFS.h"
#include "vtkVisibilityCompareFS.h"
#include "vtkVisibilityCompareVS.h"
#include "vtkVisibilityDepthFS.h"
#include "vtkVisibilityDepthVS.h"
#include "vtkVisibilityMatrixVS.h"
#include "vtkVisibilityPairFS.h"

#include "vtkNew.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace
{
// Receivers' queries in flight: one batch is issued while the previous one is read.
constexpr int QueryBatch = 16384;
// Directions whose bits share the storage buffer before it is read back.
constexpr int CompareBatch = 64;

// Column-major orthographic projection along -direction of the sphere of `radius` around the
// origin: x and y across the direction, depth increasing away from the light.
void LightMatrix(const std::array<double, 3>& l, double radius, float m[16])
{
  // Any unit vector across l, then the third axis.
  const double helper[3] = { std::abs(l[0]) < 0.6 ? 1.0 : 0.0, std::abs(l[0]) < 0.6 ? 0.0 : 1.0,
    0.0 };
  double r[3] = { l[1] * helper[2] - l[2] * helper[1], l[2] * helper[0] - l[0] * helper[2],
    l[0] * helper[1] - l[1] * helper[0] };
  const double rn = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
  for (double& c : r)
  {
    c /= rn;
  }
  const double u[3] = { l[1] * r[2] - l[2] * r[1], l[2] * r[0] - l[0] * r[2],
    l[0] * r[1] - l[1] * r[0] };
  const double s = 1.0 / radius;
  const float rows[4][4] = { { float(s * r[0]), float(s * r[1]), float(s * r[2]), 0.0f },
    { float(s * u[0]), float(s * u[1]), float(s * u[2]), 0.0f },
    { float(-s * l[0]), float(-s * l[1]), float(-s * l[2]), 0.0f }, { 0.0f, 0.0f, 0.0f, 1.0f } };
  for (int row = 0; row < 4; ++row)
  {
    for (int column = 0; column < 4; ++column)
    {
      m[4 * column + row] = rows[row][column];
    }
  }
}

// A new texture in place of `texture` (whose resources are released): texels read as they are
// (nearest, clamped).
void Replace(vtkSmartPointer<vtkTextureObject>& texture, vtkOpenGLRenderWindow* window)
{
  if (texture)
  {
    texture->ReleaseGraphicsResources(window);
  }
  texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(window);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
}

// Makes `texture` a width x height float depth texture, the only attachment of `framebuffer`
// (both created when missing), unless it already is; false with `error` otherwise, leaving no
// texture, so that the next call tries again.
bool DepthTarget(vtkOpenGLRenderWindow* window, vtkSmartPointer<vtkTextureObject>& texture,
  vtkSmartPointer<vtkOpenGLFramebufferObject>& framebuffer, int width, int height, const char* what,
  std::string& error)
{
  if (texture && texture->GetWidth() == static_cast<unsigned int>(width) &&
    texture->GetHeight() == static_cast<unsigned int>(height))
  {
    return true;
  }
  Replace(texture, window);
  bool ready = texture->AllocateDepth(width, height, vtkTextureObject::Float32);
  if (!ready)
  {
    error = "a " + std::to_string(width) + " x " + std::to_string(height) + " " + what +
      " depth texture could not be allocated";
  }
  else
  {
    if (!framebuffer)
    {
      framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
      framebuffer->SetContext(window);
    }
    vtkOpenGLState* state = window->GetState();
    state->PushFramebufferBindings();
    framebuffer->Bind();
    framebuffer->AddDepthAttachment(texture);
    framebuffer->DeactivateDrawBuffers();
    framebuffer->DeactivateReadBuffer();
    const char* status = nullptr;
    ready = vtkOpenGLFramebufferObject::GetFrameBufferStatus(GL_FRAMEBUFFER, status);
    state->PopFramebufferBindings();
    if (!ready)
    {
      error =
        std::string("the ") + what + " framebuffer is incomplete (" + (status ? status : "") + ")";
    }
  }
  if (!ready)
  {
    texture->ReleaseGraphicsResources(window);
    texture = nullptr;
  }
  return ready;
}

// Each direction with its opposite (-1 when the list lacks it; a lightsphere never does).
std::vector<std::pair<size_t, long>> OppositePairs(
  const std::vector<std::array<double, 3>>& directions)
{
  std::vector<std::pair<size_t, long>> pairs;
  std::vector<bool> taken(directions.size(), false);
  for (size_t i = 0; i < directions.size(); ++i)
  {
    if (taken[i])
    {
      continue;
    }
    long opposite = -1;
    for (size_t j = i + 1; j < directions.size() && opposite < 0; ++j)
    {
      const auto& a = directions[i];
      const auto& b = directions[j];
      if (!taken[j] && a[0] * b[0] + a[1] * b[1] + a[2] * b[2] < -1.0 + 1e-12)
      {
        opposite = static_cast<long>(j);
        taken[j] = true;
      }
    }
    taken[i] = true;
    pairs.emplace_back(i, opposite);
  }
  return pairs;
}

// The pairs from `first` on that fit the storage buffer's CompareBatch slots (a pair takes two);
// `first` moves past them.
std::vector<std::pair<size_t, long>> TakeBatch(
  const std::vector<std::pair<size_t, long>>& pairs, size_t& first)
{
  std::vector<std::pair<size_t, long>> batch;
  size_t slots = 0;
  while (first < pairs.size() && slots + (pairs[first].second >= 0 ? 2 : 1) <= CompareBatch)
  {
    slots += pairs[first].second >= 0 ? 2 : 1;
    batch.push_back(pairs[first++]);
  }
  return batch;
}

// The depth pass's state, restored when the object goes.
struct PassState
{
  explicit PassState(vtkOpenGLState* state)
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
  ~PassState() { glPolygonOffset(this->Factor, this->Units); }

  vtkOpenGLState::ScopedglViewport Viewport;
  vtkOpenGLState::ScopedglDepthMask DepthMask;
  vtkOpenGLState::ScopedglColorMask ColorMask;
  vtkOpenGLState::ScopedglDepthFunc DepthFunc;
  vtkOpenGLState::ScopedglEnableDisable DepthTest, CullFace, Blend, Scissor, Offset;
  float Factor = 0.0f, Units = 0.0f;
};
}

//------------------------------------------------------------------------------
vtkVisibilityRenderer::vtkVisibilityRenderer() = default;

//------------------------------------------------------------------------------
vtkVisibilityRenderer::~vtkVisibilityRenderer()
{
  this->ReleaseGraphicsResources(this->Window);
}

//------------------------------------------------------------------------------
std::string vtkVisibilityRenderer::Missing(bool depthCompare)
{
  if (depthCompare)
  {
    return GLEW_VERSION_4_3 ? std::string()
                            : "OpenGL 4.3 (shader storage buffers and atomic operations)";
  }
  return GLEW_VERSION_3_3 || GLEW_ARB_occlusion_query2
    ? std::string()
    : "OpenGL 3.3 occlusion queries (GL_ANY_SAMPLES_PASSED)";
}

//------------------------------------------------------------------------------
bool vtkVisibilityRenderer::SetScene(vtkOpenGLRenderWindow* window,
  const std::vector<float>& points, const std::vector<std::uint32_t>& triangles,
  vtkIdType receivers, double radius, int resolution, float factor, float units, std::string& error)
{
  if (this->Window != window)
  {
    this->ReleaseGraphicsResources(this->Window);
    this->Window = window;
  }
  window->MakeCurrent();
  this->NumberOfReceivers = receivers;
  this->NumberOfTriangles = static_cast<vtkIdType>(triangles.size() / 3);
  this->Radius = radius;
  this->Resolution = resolution;
  this->OffsetFactor = factor;
  this->OffsetUnits = units;
  this->DepthPasses = 0;

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
  if (points != this->UploadedPoints || points.empty())
  {
    if (!this->Points->Upload(points, vtkOpenGLBufferObject::ArrayBuffer))
    {
      this->UploadedPoints.clear();
      error = "the scene could not be uploaded to the GPU (" + this->Points->GetError() + ")";
      return false;
    }
    this->UploadedPoints = points;
    this->UploadedBytes += static_cast<vtkIdType>(points.size() * sizeof(float));
  }
  if (triangles != this->UploadedTriangles || triangles.empty())
  {
    if (!this->Triangles->Upload(triangles, vtkOpenGLBufferObject::ElementArrayBuffer))
    {
      this->UploadedTriangles.clear();
      error = "the scene could not be uploaded to the GPU (" + this->Triangles->GetError() + ")";
      return false;
    }
    this->UploadedTriangles = triangles;
    this->UploadedBytes += static_cast<vtkIdType>(triangles.size() * sizeof(std::uint32_t));
  }

  vtkOpenGLShaderCache* cache = window->GetShaderCache();
  if (!this->DepthProgram)
  {
    this->DepthProgram = cache->ReadyShaderProgram(vtkVisibilityDepthVS, vtkVisibilityDepthFS, "");
    if (!this->DepthProgram)
    {
      error = "the depth shader did not compile";
      return false;
    }
  }
  if (!this->DepthVAO)
  {
    this->DepthVAO = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
  }
  cache->ReadyShaderProgram(this->DepthProgram);
  this->DepthVAO->Bind();
  const bool bound = this->DepthVAO->AddAttributeArray(
    this->DepthProgram, this->Points, "vertexMC", 0, 3 * sizeof(float), VTK_FLOAT, 3, false);
  this->Triangles->Bind();
  this->DepthVAO->Release();
  if (!bound)
  {
    error = "the scene's points could not be bound to the depth shader";
    return false;
  }

  return DepthTarget(
    window, this->Depth, this->Framebuffer, resolution, resolution, "light-view", error);
}

//------------------------------------------------------------------------------
void vtkVisibilityRenderer::RenderDepth(const std::array<double, 3>& direction, float matrix[16])
{
  LightMatrix(direction, this->Radius, matrix);
  this->DrawSceneDepth(matrix);
  ++this->DepthPasses;
}

//------------------------------------------------------------------------------
void vtkVisibilityRenderer::DrawSceneDepth(const float matrix[16])
{
  vtkOpenGLState* state = this->Window->GetState();
  this->Window->GetShaderCache()->ReadyShaderProgram(this->DepthProgram);
  this->DepthProgram->SetUniformMatrix4x4("clipMatrix", const_cast<float*>(matrix));
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglClearDepth(1.0);
  state->vtkglClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(this->OffsetFactor, this->OffsetUnits);
  this->DepthVAO->Bind();
  this->Triangles->Bind();
  glDrawElements(
    GL_TRIANGLES, static_cast<GLsizei>(3 * this->NumberOfTriangles), GL_UNSIGNED_INT, nullptr);
  this->DepthVAO->Release();
  glDisable(GL_POLYGON_OFFSET_FILL);
}

//------------------------------------------------------------------------------
void vtkVisibilityRenderer::QueryEach(
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
bool vtkVisibilityRenderer::OcclusionQuery(const std::vector<std::array<double, 3>>& directions,
  std::vector<Bits>& visible, std::string& error, const std::vector<std::uint32_t>* subset)
{
  if (!this->Window || !this->DepthProgram)
  {
    error = "no scene";
    return false;
  }
  this->Window->MakeCurrent();
  vtkOpenGLState* state = this->Window->GetState();
  const vtkIdType n = this->NumberOfReceivers;
  const size_t count = subset ? subset->size() : static_cast<size_t>(n);
  auto receiver = [&](size_t i) { return subset ? static_cast<vtkIdType>((*subset)[i]) : i; };
  state->PushFramebufferBindings();
  {
    PassState pass(state);
    this->Framebuffer->Bind();
    state->vtkglViewport(0, 0, this->Resolution, this->Resolution);
    float matrix[16];
    for (const auto& direction : directions)
    {
      this->RenderDepth(direction, matrix);
      // Points test against the depth, without writing it (the paper's second pass).
      state->vtkglDepthMask(GL_FALSE);
      Bits bits((n + 63) / 64, 0);
      this->DepthVAO->Bind();
      this->QueryEach(
        count, [&](size_t i) { glDrawArrays(GL_POINTS, static_cast<GLint>(receiver(i)), 1); },
        [&](size_t i)
        {
          const vtkIdType id = receiver(i);
          bits[id / 64] |= std::uint64_t(1) << (id % 64);
        });
      this->DepthVAO->Release();
      visible.push_back(std::move(bits));
    }
  }
  state->PopFramebufferBindings();
  return true;
}

//------------------------------------------------------------------------------
bool vtkVisibilityRenderer::DepthCompare(const std::vector<std::array<double, 3>>& directions,
  std::vector<Bits>& visible, std::string& error, const std::function<bool(size_t)>& progress,
  const std::vector<std::uint32_t>* subset)
{
  if (!this->Window || !this->DepthProgram)
  {
    error = "no scene";
    return false;
  }
  this->Window->MakeCurrent();
  const int words = static_cast<int>((this->NumberOfReceivers + 31) / 32);
  if (!this->PreparePairs(error) || !this->PrepareCompare(subset, words, error))
  {
    return false;
  }
  const std::vector<std::pair<size_t, long>> pairs = OppositePairs(directions);
  std::vector<Bits> results(directions.size());
  size_t done = 0;
  bool stopped = false;
  vtkOpenGLState* state = this->Window->GetState();
  state->PushFramebufferBindings();
  {
    PassState pass(state);
    vtkOpenGLState::ScopedglBlendFuncSeparate blendFunction(state);
    state->vtkglViewport(0, 0, this->Resolution, this->Resolution);
    for (size_t first = 0; first < pairs.size() && !stopped;)
    {
      // As many pairs as the storage buffer has slots for: each direction is drawn and tested
      // into its slot, then all slots are read back at once.
      const std::vector<std::pair<size_t, long>> batch = TakeBatch(pairs, first);
      std::vector<std::pair<size_t, int>> slotOf =
        this->CompareBatchOfPairs(directions, batch, words, subset); // direction, slot
      this->ReadSlots(slotOf, words, results);
      done += slotOf.size();
      stopped = progress && !progress(done);
    }
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  state->PopFramebufferBindings();
  if (stopped)
  {
    error = "stopped";
    return false;
  }
  for (Bits& bits : results)
  {
    visible.push_back(std::move(bits));
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkVisibilityRenderer::PrepareCompare(
  const std::vector<std::uint32_t>* subset, int words, std::string& error)
{
  if (subset)
  {
    // The receivers to test, drawn by index: gl_VertexID is then the receiver's id.
    if (!this->Subset)
    {
      this->Subset = vtkSmartPointer<vtkOpenGLBufferObject>::New();
      this->Subset->SetType(vtkOpenGLBufferObject::ElementArrayBuffer);
    }
    if (!subset->empty() &&
      !this->Subset->Upload(*subset, vtkOpenGLBufferObject::ElementArrayBuffer))
    {
      error = "the receivers to test could not be uploaded (" + this->Subset->GetError() + ")";
      return false;
    }
  }
  if (!this->Storage)
  {
    glGenBuffers(1, &this->Storage);
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Storage);
  glBufferData(GL_SHADER_STORAGE_BUFFER,
    static_cast<GLsizeiptr>(words) * CompareBatch * sizeof(std::uint32_t), nullptr,
    GL_DYNAMIC_READ);
  return true;
}

//------------------------------------------------------------------------------
std::vector<std::pair<size_t, int>> vtkVisibilityRenderer::CompareBatchOfPairs(
  const std::vector<std::array<double, 3>>& directions,
  const std::vector<std::pair<size_t, long>>& batch, int words,
  const std::vector<std::uint32_t>* subset)
{
  const std::vector<std::uint32_t> zeros(static_cast<size_t>(words) * CompareBatch, 0u);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Storage);
  glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, zeros.size() * sizeof(std::uint32_t), zeros.data());
  std::vector<std::pair<size_t, int>> slotOf;
  int slot = 0;
  float matrix[16];
  for (const auto& pair : batch)
  {
    LightMatrix(directions[pair.first], this->Radius, matrix);
    this->DrawNearestFarthest(matrix);
    const int opposite = pair.second >= 0 ? slot + 1 : -1;
    this->CompareReceivers(matrix, slot, opposite, words, subset);
    slotOf.emplace_back(pair.first, slot);
    if (pair.second >= 0)
    {
      slotOf.emplace_back(static_cast<size_t>(pair.second), opposite);
    }
    slot += pair.second >= 0 ? 2 : 1;
  }
  return slotOf;
}

//------------------------------------------------------------------------------
void vtkVisibilityRenderer::DrawNearestFarthest(const float matrix[16])
{
  vtkOpenGLState* state = this->Window->GetState();
  GLint equationRGB = GL_FUNC_ADD, equationAlpha = GL_FUNC_ADD;
  glGetIntegerv(GL_BLEND_EQUATION_RGB, &equationRGB);
  glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &equationAlpha);
  this->PairFramebuffer->Bind();
  this->PairFramebuffer->ActivateDrawBuffers(2);
  this->Window->GetShaderCache()->ReadyShaderProgram(this->PairProgram);
  this->PairProgram->SetUniformMatrix4x4("clipMatrix", const_cast<float*>(matrix));
  this->PairProgram->SetUniformf("offsetFactor", this->OffsetFactor);
  this->PairProgram->SetUniformf("offsetUnits", this->OffsetUnits);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  const float far = 1.0f, near = 0.0f;
  glClearBufferfv(GL_COLOR, 0, &far);
  glClearBufferfv(GL_COLOR, 1, &near);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFunc(GL_ONE, GL_ONE);
  glBlendEquationi(0, GL_MIN);
  glBlendEquationi(1, GL_MAX);
  this->PairVAO->Bind();
  this->Triangles->Bind();
  glDrawElements(
    GL_TRIANGLES, static_cast<GLsizei>(3 * this->NumberOfTriangles), GL_UNSIGNED_INT, nullptr);
  this->PairVAO->Release();
  glBlendEquationSeparate(equationRGB, equationAlpha);
  state->vtkglDisable(GL_BLEND);
  state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  ++this->DepthPasses;
}

//------------------------------------------------------------------------------
void vtkVisibilityRenderer::CompareReceivers(const float matrix[16], int slot, int opposite,
  int words, const std::vector<std::uint32_t>* subset)
{
  // Back to the window's framebuffer: nothing is rasterised.
  vtkOpenGLState* state = this->Window->GetState();
  state->PopFramebufferBindings();
  state->PushFramebufferBindings();
  this->Window->GetShaderCache()->ReadyShaderProgram(this->CompareProgram);
  this->Nearest->Activate();
  this->Farthest->Activate();
  this->CompareProgram->SetUniformi("nearestMap", this->Nearest->GetTextureUnit());
  this->CompareProgram->SetUniformi("farthestMap", this->Farthest->GetTextureUnit());
  this->CompareProgram->SetUniformMatrix4x4("lightMatrix", const_cast<float*>(matrix));
  this->CompareProgram->SetUniformi("resolution", this->Resolution);
  this->CompareProgram->SetUniformi("slot", slot);
  this->CompareProgram->SetUniformi("opposite", opposite);
  this->CompareProgram->SetUniformi("words", words);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, this->Storage);
  glEnable(GL_RASTERIZER_DISCARD);
  this->CompareVAO->Bind();
  if (!subset)
  {
    glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(this->NumberOfReceivers));
  }
  else if (!subset->empty())
  {
    this->Subset->Bind();
    glDrawElements(GL_POINTS, static_cast<GLsizei>(subset->size()), GL_UNSIGNED_INT, nullptr);
  }
  this->CompareVAO->Release();
  glDisable(GL_RASTERIZER_DISCARD);
  this->Farthest->Deactivate();
  this->Nearest->Deactivate();
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

//------------------------------------------------------------------------------
void vtkVisibilityRenderer::ReadSlots(
  const std::vector<std::pair<size_t, int>>& slotOf, int words, std::vector<Bits>& results)
{
  std::vector<std::uint32_t> slots(static_cast<size_t>(words) * CompareBatch);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Storage);
  glGetBufferSubData(
    GL_SHADER_STORAGE_BUFFER, 0, slots.size() * sizeof(std::uint32_t), slots.data());
  for (const auto& entry : slotOf)
  {
    Bits bits((this->NumberOfReceivers + 63) / 64, 0);
    const std::uint32_t* row = slots.data() + entry.second * words;
    for (int w = 0; w < words; ++w)
    {
      bits[w / 2] |= std::uint64_t(row[w]) << (32 * (w % 2));
    }
    results[entry.first] = std::move(bits);
  }
}

//------------------------------------------------------------------------------
bool vtkVisibilityRenderer::ViewVisible(const float matrix[16], int width, int height,
  const std::vector<std::uint32_t>& candidates, bool queries, std::vector<char>& seen,
  std::string& error)
{
  if (!this->Window || !this->DepthProgram)
  {
    error = "no scene";
    return false;
  }
  const size_t count = candidates.size() / 3;
  seen.assign(count, 0);
  if (count == 0)
  {
    return true;
  }
  this->Window->MakeCurrent();
  if (!this->PrepareView(width, height, queries, error))
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
  vtkOpenGLState* state = this->Window->GetState();
  vtkOpenGLShaderCache* cache = this->Window->GetShaderCache();
  const GLsizei words = static_cast<GLsizei>((count + 31) / 32);
  state->PushFramebufferBindings();
  {
    PassState pass(state);
    this->ViewFramebuffer->Bind();
    state->vtkglViewport(0, 0, width, height);
    // The whole scene's depth, pushed back by the polygon offset so that a candidate is not
    // hidden by itself.
    this->DrawSceneDepth(matrix);
    state->vtkglDepthMask(GL_FALSE);
    state->vtkglDepthFunc(GL_LEQUAL);
    if (queries)
    {
      // The paper's pass: one query per triangle.
      this->DepthVAO->Bind();
      this->Candidates->Bind();
      this->QueryEach(
        count,
        [](size_t i)
        {
          glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT,
            reinterpret_cast<const void*>(3 * i * sizeof(std::uint32_t)));
        },
        [&seen](size_t i) { seen[i] = 1; });
      this->DepthVAO->Release();
    }
    else
    {
      const std::vector<std::uint32_t> zeros(words, 0u);
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->ViewStorage);
      glBufferData(
        GL_SHADER_STORAGE_BUFFER, words * sizeof(std::uint32_t), zeros.data(), GL_DYNAMIC_READ);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, this->ViewStorage);
      cache->ReadyShaderProgram(this->ViewProgram);
      this->ViewProgram->SetUniformMatrix4x4("clipMatrix", const_cast<float*>(matrix));
      this->ViewVAO->Bind();
      this->Candidates->Bind();
      glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(3 * count), GL_UNSIGNED_INT, nullptr);
      this->ViewVAO->Release();
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
      std::vector<std::uint32_t> bits(words);
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->ViewStorage);
      glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, words * sizeof(std::uint32_t), bits.data());
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
      for (size_t i = 0; i < count; ++i)
      {
        seen[i] = (bits[i / 32] >> (i % 32)) & 1u;
      }
    }
  }
  state->PopFramebufferBindings();
  return true;
}

//------------------------------------------------------------------------------
bool vtkVisibilityRenderer::PrepareView(int width, int height, bool queries, std::string& error)
{
  if (!queries && !this->ViewProgram)
  {
    if (!this->ReadyProgram(this->ViewProgram, this->ViewVAO, vtkVisibilityMatrixVS,
          vtkVisibilityCameraFS, "camera-view", error))
    {
      return false;
    }
    glGenBuffers(1, &this->ViewStorage);
  }
  return DepthTarget(
    this->Window, this->ViewDepth, this->ViewFramebuffer, width, height, "camera-view", error);
}

//------------------------------------------------------------------------------
bool vtkVisibilityRenderer::ReadyProgram(vtkSmartPointer<vtkShaderProgram>& program,
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
  // Kept only once complete, so that a failure is met again, not skipped, next time.
  program = compiled;
  vao = bound;
  return true;
}

//------------------------------------------------------------------------------
bool vtkVisibilityRenderer::PreparePairs(std::string& error)
{
  if (!this->ReadyProgram(this->PairProgram, this->PairVAO, vtkVisibilityMatrixVS,
        vtkVisibilityPairFS, "nearest-and-farthest", error) ||
    !this->ReadyProgram(this->CompareProgram, this->CompareVAO, vtkVisibilityCompareVS,
      vtkVisibilityCompareFS, "depth-compare", error))
  {
    return false;
  }
  if (this->Nearest && this->Nearest->GetWidth() == static_cast<unsigned int>(this->Resolution))
  {
    return true;
  }
  for (vtkSmartPointer<vtkTextureObject>* texture : { &this->Nearest, &this->Farthest })
  {
    Replace(*texture, this->Window);
    if (!(*texture)->Allocate2D(this->Resolution, this->Resolution, 1, VTK_FLOAT))
    {
      error = "a " + std::to_string(this->Resolution) + "^2 float texture could not be allocated";
      return false;
    }
  }
  if (!this->PairFramebuffer)
  {
    this->PairFramebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->PairFramebuffer->SetContext(this->Window);
  }
  vtkOpenGLState* state = this->Window->GetState();
  state->PushFramebufferBindings();
  this->PairFramebuffer->Bind();
  this->PairFramebuffer->AddColorAttachment(0, this->Nearest);
  this->PairFramebuffer->AddColorAttachment(1, this->Farthest);
  this->PairFramebuffer->ActivateDrawBuffers(2);
  const char* status = nullptr;
  const bool complete = vtkOpenGLFramebufferObject::GetFrameBufferStatus(GL_FRAMEBUFFER, status);
  state->PopFramebufferBindings();
  if (!complete)
  {
    error = std::string("the nearest-and-farthest framebuffer is incomplete (") +
      (status ? status : "") + ")";
  }
  return complete;
}

//------------------------------------------------------------------------------
void vtkVisibilityRenderer::ReleaseGraphicsResources(vtkWindow* window)
{
  if (!this->Window || window != this->Window)
  {
    return;
  }
  // GL objects die with a context that is gone; only a live one is asked to delete them.
  const bool live = this->Window->GetGenericContext() != nullptr;
  if (live)
  {
    this->Window->MakeCurrent();
  }
  if (live && !this->Queries.empty())
  {
    glDeleteQueries(static_cast<GLsizei>(this->Queries.size()), this->Queries.data());
  }
  for (unsigned int* buffer : { &this->Storage, &this->ViewStorage })
  {
    if (live && *buffer)
    {
      glDeleteBuffers(1, buffer);
    }
    *buffer = 0;
  }
  this->Queries.clear();
  for (auto* program :
    { &this->DepthProgram, &this->PairProgram, &this->CompareProgram, &this->ViewProgram })
  {
    *program = nullptr; // the window's shader cache releases its programs
  }
  for (auto* vao : { &this->DepthVAO, &this->PairVAO, &this->CompareVAO, &this->ViewVAO })
  {
    if (*vao)
    {
      (*vao)->ReleaseGraphicsResources();
      *vao = nullptr;
    }
  }
  for (auto* buffer : { &this->Points, &this->Triangles, &this->Subset, &this->Candidates })
  {
    if (*buffer)
    {
      (*buffer)->ReleaseGraphicsResources();
      *buffer = nullptr;
    }
  }
  for (auto* framebuffer : { &this->Framebuffer, &this->PairFramebuffer, &this->ViewFramebuffer })
  {
    if (*framebuffer)
    {
      (*framebuffer)->ReleaseGraphicsResources(window);
      *framebuffer = nullptr;
    }
  }
  for (auto* texture : { &this->Depth, &this->Nearest, &this->Farthest, &this->ViewDepth })
  {
    if (*texture)
    {
      (*texture)->ReleaseGraphicsResources(window);
      *texture = nullptr;
    }
  }
  this->UploadedPoints.clear();
  this->UploadedTriangles.clear();
  this->Window = nullptr;
}
