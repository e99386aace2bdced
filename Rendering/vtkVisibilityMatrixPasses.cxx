/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkVisibilityMatrixPasses.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkVisibilityMatrixPasses.h"

#include "vtkVisibilityCompareFS.h"
#include "vtkVisibilityCompareVS.h"
#include "vtkVisibilityPairFS.h"
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

#include <cmath>

namespace
{
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
}
//------------------------------------------------------------------------------
vtkVisibilityMatrixPasses::vtkVisibilityMatrixPasses(vtkVisibilityScene& scene)
  : Scene(scene)
{
}

//------------------------------------------------------------------------------
vtkVisibilityMatrixPasses::~vtkVisibilityMatrixPasses()
{
  this->ReleaseGraphicsResources(this->Scene.GetWindow());
}

//------------------------------------------------------------------------------
bool vtkVisibilityMatrixPasses::SetReceivers(
  vtkIdType receivers, double radius, int resolution, std::string& error)
{
  this->NumberOfReceivers = receivers;
  this->Radius = radius;
  this->Resolution = resolution;
  this->DepthPasses = 0;
  return this->Scene.MakeCurrent(error) &&
    this->Scene.DepthTarget(
      this->Depth, this->Framebuffer, resolution, resolution, "light-view", error);
}

//------------------------------------------------------------------------------
bool vtkVisibilityMatrixPasses::OcclusionQuery(const std::vector<std::array<double, 3>>& directions,
  std::vector<Bits>& visible, std::string& error, const std::vector<std::uint32_t>* subset)
{
  if (!this->Scene.MakeCurrent(error))
  {
    return false;
  }
  vtkOpenGLState* state = this->Scene.GetWindow()->GetState();
  const vtkIdType n = this->NumberOfReceivers;
  const size_t count = subset ? subset->size() : static_cast<size_t>(n);
  auto receiver = [&](size_t i) { return subset ? static_cast<vtkIdType>((*subset)[i]) : i; };
  state->PushFramebufferBindings();
  {
    vtkVisibilityScene::PassState pass(state);
    this->Framebuffer->Bind();
    state->vtkglViewport(0, 0, this->Resolution, this->Resolution);
    float matrix[16];
    for (const auto& direction : directions)
    {
      LightMatrix(direction, this->Radius, matrix);
      this->Scene.DrawDepth(matrix);
      ++this->DepthPasses;
      // Points test against the depth, without writing it (the paper's second pass).
      state->vtkglDepthMask(GL_FALSE);
      Bits bits((n + 63) / 64, 0);
      vtkOpenGLVertexArrayObject* points = this->Scene.GetDepthVAO();
      points->Bind();
      this->Scene.QueryEach(
        count, [&](size_t i) { glDrawArrays(GL_POINTS, static_cast<GLint>(receiver(i)), 1); },
        [&](size_t i)
        {
          const vtkIdType id = receiver(i);
          bits[id / 64] |= std::uint64_t(1) << (id % 64);
        });
      points->Release();
      visible.push_back(std::move(bits));
    }
  }
  state->PopFramebufferBindings();
  return true;
}

//------------------------------------------------------------------------------
bool vtkVisibilityMatrixPasses::DepthCompare(const std::vector<std::array<double, 3>>& directions,
  std::vector<Bits>& visible, std::string& error, const std::function<bool(size_t)>& progress,
  const std::vector<std::uint32_t>* subset)
{
  if (!this->Scene.MakeCurrent(error))
  {
    return false;
  }
  const int words = static_cast<int>((this->NumberOfReceivers + 31) / 32);
  if (!this->PreparePairs(error) || !this->PrepareCompare(subset, words, error))
  {
    return false;
  }
  const std::vector<std::pair<size_t, long>> pairs = OppositePairs(directions);
  std::vector<Bits> results(directions.size());
  size_t done = 0;
  bool stopped = false;
  vtkOpenGLState* state = this->Scene.GetWindow()->GetState();
  state->PushFramebufferBindings();
  {
    vtkVisibilityScene::PassState pass(state);
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
bool vtkVisibilityMatrixPasses::PrepareCompare(
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
  return true;
}

//------------------------------------------------------------------------------
std::vector<std::pair<size_t, int>> vtkVisibilityMatrixPasses::CompareBatchOfPairs(
  const std::vector<std::array<double, 3>>& directions,
  const std::vector<std::pair<size_t, long>>& batch, int words,
  const std::vector<std::uint32_t>* subset)
{
  const std::vector<std::uint32_t> zeros(static_cast<size_t>(words) * CompareBatch, 0u);
  vtkVisibilityScene::ResizeStorage(
    this->Storage, zeros.size() * sizeof(std::uint32_t), zeros.data());
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
void vtkVisibilityMatrixPasses::DrawNearestFarthest(const float matrix[16])
{
  vtkOpenGLState* state = this->Scene.GetWindow()->GetState();
  GLint equationRGB = GL_FUNC_ADD, equationAlpha = GL_FUNC_ADD;
  glGetIntegerv(GL_BLEND_EQUATION_RGB, &equationRGB);
  glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &equationAlpha);
  this->PairFramebuffer->Bind();
  this->PairFramebuffer->ActivateDrawBuffers(2);
  this->Scene.GetWindow()->GetShaderCache()->ReadyShaderProgram(this->PairProgram);
  this->PairProgram->SetUniformMatrix4x4("clipMatrix", const_cast<float*>(matrix));
  this->PairProgram->SetUniformf("offsetFactor", this->Scene.GetOffsetFactor());
  this->PairProgram->SetUniformf("offsetUnits", this->Scene.GetOffsetUnits());
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  const float far = 1.0f, near = 0.0f;
  glClearBufferfv(GL_COLOR, 0, &far);
  glClearBufferfv(GL_COLOR, 1, &near);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFunc(GL_ONE, GL_ONE);
  glBlendEquationi(0, GL_MIN);
  glBlendEquationi(1, GL_MAX);
  this->Scene.DrawTriangles(this->PairVAO);
  glBlendEquationSeparate(equationRGB, equationAlpha);
  state->vtkglDisable(GL_BLEND);
  state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  ++this->DepthPasses;
}

//------------------------------------------------------------------------------
void vtkVisibilityMatrixPasses::CompareReceivers(const float matrix[16], int slot, int opposite,
  int words, const std::vector<std::uint32_t>* subset)
{
  // Back to the window's framebuffer: nothing is rasterised.
  vtkOpenGLState* state = this->Scene.GetWindow()->GetState();
  state->PopFramebufferBindings();
  state->PushFramebufferBindings();
  this->Scene.GetWindow()->GetShaderCache()->ReadyShaderProgram(this->CompareProgram);
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
void vtkVisibilityMatrixPasses::ReadSlots(
  const std::vector<std::pair<size_t, int>>& slotOf, int words, std::vector<Bits>& results)
{
  std::vector<std::uint32_t> slots(static_cast<size_t>(words) * CompareBatch);
  vtkVisibilityScene::ReadStorage(
    this->Storage, slots.size() * sizeof(std::uint32_t), slots.data());
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
bool vtkVisibilityMatrixPasses::PreparePairs(std::string& error)
{
  if (!this->Scene.ReadyProgram(this->PairProgram, this->PairVAO,
        vtkVisibilityScene::PointsVS430().c_str(), vtkVisibilityPairFS, "nearest-and-farthest",
        error) ||
    !this->Scene.ReadyProgram(this->CompareProgram, this->CompareVAO, vtkVisibilityCompareVS,
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
    this->Scene.NewTexture(*texture);
    if (!(*texture)->Allocate2D(this->Resolution, this->Resolution, 1, VTK_FLOAT))
    {
      error = "a " + std::to_string(this->Resolution) + "^2 float texture could not be allocated";
      return false;
    }
  }
  return this->Scene.Attach(
    this->PairFramebuffer,
    [this](vtkOpenGLFramebufferObject* bound)
    {
      bound->AddColorAttachment(0, this->Nearest);
      bound->AddColorAttachment(1, this->Farthest);
      bound->ActivateDrawBuffers(2);
    },
    "nearest-and-farthest", error);
}

//------------------------------------------------------------------------------
void vtkVisibilityMatrixPasses::ReleaseGraphicsResources(vtkWindow* window)
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
  this->PairProgram = nullptr; // the window's shader cache releases its programs
  this->CompareProgram = nullptr;
  for (auto* vao : { &this->PairVAO, &this->CompareVAO })
  {
    if (*vao)
    {
      (*vao)->ReleaseGraphicsResources();
      *vao = nullptr;
    }
  }
  if (this->Subset)
  {
    this->Subset->ReleaseGraphicsResources();
    this->Subset = nullptr;
  }
  for (auto* framebuffer : { &this->Framebuffer, &this->PairFramebuffer })
  {
    if (*framebuffer)
    {
      (*framebuffer)->ReleaseGraphicsResources(window);
      *framebuffer = nullptr;
    }
  }
  for (auto* texture : { &this->Depth, &this->Nearest, &this->Farthest })
  {
    if (*texture)
    {
      (*texture)->ReleaseGraphicsResources(window);
      *texture = nullptr;
    }
  }
}
