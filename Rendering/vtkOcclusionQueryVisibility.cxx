/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkOcclusionQueryVisibility.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkOcclusionQueryVisibility.h"

#include "vtkApertureDisplay.h"
#include "vtkApertureRayScene.h"
#include "vtkApertureSurface.h"
#include "vtkLightSphere.h"
#include "vtkVisibilityRenderer.h"

#include "vtkBitArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>

vtkStandardNewMacro(vtkOcclusionQueryVisibility);
vtkCxxSetObjectMacro(vtkOcclusionQueryVisibility, RenderWindow, vtkRenderWindow);

namespace
{
using Directions = std::vector<std::array<double, 3>>;
using Bits = vtkVisibilityRenderer::Bits;

// Directions handled between two progress events.
constexpr size_t Chunk = 8;

// Casts, for blocks of 64 points (so that no two threads share a word of the bit sets), one
// occlusion ray per point and direction, 16 points to a packet. Points are taken in `order`
// (neighbours together, so that a packet's rays stay coherent) and their bits set at their place
// in that order.
class CastDirections
{
public:
  CastDirections(const vtkApertureSurface& surface, const std::vector<vtkIdType>& order,
    RTCScene scene, const Directions& directions, double offset, std::vector<Bits>& visible)
    : Surface(surface)
    , Order(order)
    , Scene(scene)
    , Dirs(directions)
    , Offset(offset)
    , Visible(visible)
  {
  }

  void operator()(vtkIdType beginBlock, vtkIdType endBlock) const
  {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    // A packet is 16 neighbouring points looking the same way.
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    alignas(64) RTCRay16 ray;
    alignas(64) int valid[16];
    const vtkIdType n = this->Surface.GetNumberOfPoints();
    for (vtkIdType block = beginBlock; block < endBlock; ++block)
    {
      for (size_t j = 0; j < this->Dirs.size(); ++j)
      {
        const auto& l = this->Dirs[j];
        std::uint64_t word = 0;
        for (vtkIdType first = 64 * block; first < std::min(n, 64 * block + 64); first += 16)
        {
          for (int lane = 0; lane < 16; ++lane)
          {
            const vtkIdType id = first + lane < n ? this->Order[first + lane] : n;
            // Directions below a point's tangent plane are hidden by its own surface.
            const float* normal = id < n ? this->Surface.GetNormal(id) : nullptr;
            valid[lane] = id < n && this->Surface.Valid[id] &&
                normal[0] * l[0] + normal[1] * l[1] + normal[2] * l[2] > 0.0
              ? -1
              : 0;
            if (!valid[lane])
            {
              continue;
            }
            const float* p = &this->Surface.Points[3 * id];
            const float lift = static_cast<float>(this->Offset * this->Surface.EdgeLength[id]);
            ray.org_x[lane] = p[0] + lift * normal[0];
            ray.org_y[lane] = p[1] + lift * normal[1];
            ray.org_z[lane] = p[2] + lift * normal[2];
            ray.dir_x[lane] = static_cast<float>(l[0]);
            ray.dir_y[lane] = static_cast<float>(l[1]);
            ray.dir_z[lane] = static_cast<float>(l[2]);
            ray.tnear[lane] = 0.0f;
            ray.tfar[lane] = std::numeric_limits<float>::infinity();
            ray.time[lane] = 0.0f;
            ray.mask[lane] = 0xFFFFFFFF;
            ray.id[lane] = 0;
            ray.flags[lane] = 0;
          }
          rtcOccluded16(valid, this->Scene, &context, &ray);
          for (int lane = 0; lane < 16; ++lane)
          {
            // Occluded rays come back with tfar = -inf.
            if (valid[lane] && ray.tfar[lane] >= 0.0f)
            {
              word |= std::uint64_t(1) << ((first + lane) % 64);
            }
          }
        }
        this->Visible[j][block] = word;
      }
    }
  }

private:
  const vtkApertureSurface& Surface;
  const std::vector<vtkIdType>& Order;
  RTCScene Scene;
  const Directions& Dirs;
  double Offset;
  std::vector<Bits>& Visible;
};

// Morton (Z-order) codes of positions (3 floats each, `count` of them) within the bounds of the
// finite `points`: sorting by them puts neighbours together.
std::vector<std::uint32_t> MortonCodes(
  const std::vector<float>& points, const float* positions, size_t count)
{
  float lo[3] = { FLT_MAX, FLT_MAX, FLT_MAX }, hi[3] = { -FLT_MAX, -FLT_MAX, -FLT_MAX };
  for (size_t p = 0; p + 2 < points.size(); p += 3)
  {
    for (int c = 0; c < 3; ++c)
    {
      if (std::isfinite(points[p + c]))
      {
        lo[c] = std::min(lo[c], points[p + c]);
        hi[c] = std::max(hi[c], points[p + c]);
      }
    }
  }
  // Spreads 10 bits to every third bit.
  auto spread = [](std::uint32_t v)
  {
    v = (v | (v << 16)) & 0x030000FF;
    v = (v | (v << 8)) & 0x0300F00F;
    v = (v | (v << 4)) & 0x030C30C3;
    return (v | (v << 2)) & 0x09249249;
  };
  std::vector<std::uint32_t> codes(count, 0);
  for (size_t i = 0; i < count; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      const float x = positions[3 * i + c];
      const float unit = hi[c] > lo[c] && std::isfinite(x) ? (x - lo[c]) / (hi[c] - lo[c]) : 0.0f;
      codes[i] |= spread(static_cast<std::uint32_t>(std::min(std::max(unit, 0.0f), 1.0f) * 1023.0f))
        << c;
    }
  }
  return codes;
}

// Orders triangles along a Morton curve of their centroids: any order gives the same depth, and
// neighbours drawn together share vertices and screen tiles, which makes a software rasteriser
// (llvmpipe) 1.5 times as fast on scanned meshes stored in no particular order.
void SortTriangles(const std::vector<float>& points, std::vector<std::uint32_t>& triangles)
{
  const size_t count = triangles.size() / 3;
  std::vector<float> centroids(3 * count);
  for (size_t t = 0; t < count; ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      centroids[3 * t + c] =
        (points[3 * triangles[3 * t] + c] + points[3 * triangles[3 * t + 1] + c] +
          points[3 * triangles[3 * t + 2] + c]) /
        3.0f;
    }
  }
  const std::vector<std::uint32_t> codes = MortonCodes(points, centroids.data(), count);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> keys(count);
  for (size_t t = 0; t < count; ++t)
  {
    keys[t] = { codes[t], static_cast<std::uint32_t>(t) };
  }
  std::sort(keys.begin(), keys.end());
  std::vector<std::uint32_t> sorted(triangles.size());
  for (size_t t = 0; t < count; ++t)
  {
    std::copy_n(&triangles[3 * keys[t].second], 3, &sorted[3 * t]);
  }
  triangles.swap(sorted);
}

bool Bit(const Bits& bits, vtkIdType i)
{
  return (bits[i / 64] >> (i % 64)) & 1u;
}
}

//------------------------------------------------------------------------------
vtkOcclusionQueryVisibility::vtkOcclusionQueryVisibility()
{
  this->SetNumberOfInputPorts(2);
}

//------------------------------------------------------------------------------
vtkOcclusionQueryVisibility::~vtkOcclusionQueryVisibility()
{
  this->ReleaseGraphicsResources(this->RenderWindow ? this->RenderWindow : this->OwnWindow);
  this->SetRenderWindow(nullptr);
  if (this->OwnWindow)
  {
    this->OwnWindow->Finalize();
    this->OwnWindow->Delete();
  }
}

//------------------------------------------------------------------------------
const char* vtkOcclusionQueryVisibility::GetBackendAsString()
{
  switch (this->Backend)
  {
    case OCCLUSION_QUERY:
      return "OcclusionQuery";
    case RAY_CAST:
      return "RayCast";
    default:
      return "DepthCompare";
  }
}

//------------------------------------------------------------------------------
void vtkOcclusionQueryVisibility::AddOccluderConnection(vtkAlgorithmOutput* occluder)
{
  this->AddInputConnection(1, occluder);
}

//------------------------------------------------------------------------------
int vtkOcclusionQueryVisibility::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkOcclusionQueryVisibility::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Renderer)
  {
    this->Renderer->ReleaseGraphicsResources(window);
  }
}

//------------------------------------------------------------------------------
int vtkOcclusionQueryVisibility::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->NumberOfDepthPasses = 0;
  if (!input || input->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro("The input is empty: there are no points to compute visibility for.");
    return 0;
  }
  std::vector<vtkPolyData*> occluders;
  for (int i = 0; i < inputVector[1]->GetNumberOfInformationObjects(); ++i)
  {
    if (auto* occluder = vtkPolyData::GetData(inputVector[1], i))
    {
      occluders.push_back(occluder);
    }
  }

  std::string error;
  vtkApertureSurface receivers;
  std::vector<vtkApertureSurface> occluderSurfaces;
  if (!vtkApertureSurface::SetScene(input, occluders, receivers, occluderSurfaces, error))
  {
    vtkErrorMacro(<< error);
    return 0;
  }

  vtkNew<vtkLightSphere> sphere;
  sphere->SetLevel(this->Level);
  const int k = sphere->GetNumberOfDirections();
  Directions directions(k);
  for (int j = 0; j < k; ++j)
  {
    sphere->GetDirection(j, directions[j].data());
  }

  // Visibility computed before for the same geometry and settings is kept; a higher level adds
  // its new directions.
  auto bitsOf = [](double value)
  {
    vtkMTimeType bits = 0;
    std::memcpy(&bits, &value, std::min(sizeof(bits), sizeof(value)));
    return bits;
  };
  std::vector<vtkMTimeType> key = { input->GetMTime(), static_cast<vtkMTimeType>(this->Backend),
    static_cast<vtkMTimeType>(this->DepthResolution), bitsOf(this->PolygonOffsetFactor),
    bitsOf(this->PolygonOffsetUnits), bitsOf(this->RayOffset) };
  for (vtkPolyData* occluder : occluders)
  {
    key.push_back(occluder->GetMTime());
  }
  if (key != this->ComputedFor)
  {
    this->Computed.clear();
    this->ComputedFor = key;
  }
  const Directions todo(
    directions.begin() + std::min<size_t>(this->Computed.size(), k), directions.end());

  const vtkIdType n = receivers.GetNumberOfPoints();
  this->UpdateProgress(0.0);
  if (!todo.empty() && this->Backend == RAY_CAST)
  {
    vtkApertureRayScene scene;
    if (!scene.Build(receivers, occluderSurfaces))
    {
      vtkErrorMacro("Embree failed: " << scene.GetError());
      return 0;
    }
    const vtkIdType blocks = (n + 63) / 64;
    // Points in Morton order, so that each packet's rays start close together.
    const std::vector<std::uint32_t> codes =
      MortonCodes(receivers.Points, receivers.Points.data(), static_cast<size_t>(n));
    std::vector<vtkIdType> order(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      order[i] = i;
    }
    std::sort(order.begin(), order.end(),
      [&codes](vtkIdType a, vtkIdType b) { return codes[a] < codes[b]; });
    for (size_t first = 0; first < todo.size(); first += Chunk)
    {
      const Directions chunk(
        todo.begin() + first, todo.begin() + std::min(todo.size(), first + Chunk));
      std::vector<Bits> visible(chunk.size(), Bits(blocks, 0));
      vtkSMPTools::For(0, blocks, 4,
        CastDirections(receivers, order, scene.GetScene(), chunk, this->RayOffset, visible));
      for (const Bits& ordered : visible)
      {
        Bits bits(blocks, 0);
        for (vtkIdType i = 0; i < n; ++i)
        {
          if (Bit(ordered, i))
          {
            bits[order[i] / 64] |= std::uint64_t(1) << (order[i] % 64);
          }
        }
        this->Computed.push_back(std::move(bits));
      }
      this->NumberOfDepthPasses += static_cast<int>(chunk.size());
      this->UpdateProgress(static_cast<double>(this->Computed.size()) / k);
      if (this->GetAbortExecute())
      {
        output->Initialize();
        return 1;
      }
    }
    const std::string embreeError = scene.GetError();
    if (!embreeError.empty())
    {
      vtkErrorMacro("Embree failed while tracing: " << embreeError);
      return 0;
    }
  }
  else if (!todo.empty())
  {
    // The OpenGL context: the caller's window, or an off-screen one of our own.
    vtkRenderWindow* window = this->RenderWindow;
    if (!window)
    {
      if (!this->OwnWindow)
      {
        std::string problem;
        void* display = nullptr;
        if (!vtkApertureDisplay::Get(display, problem))
        {
          vtkErrorMacro("No OpenGL context: " << problem << ". SetBackendToRayCast() needs none.");
          return 0;
        }
        this->OwnWindow = vtkRenderWindow::New();
        if (display)
        {
          this->OwnWindow->SetDisplayId(display);
        }
        this->OwnWindow->SetOffScreenRendering(1);
        this->OwnWindow->SetSize(16, 16);
        if (!this->OwnWindow->SupportsOpenGL())
        {
          vtkErrorMacro("No usable OpenGL context: VTK needs OpenGL 3.2 and "
            << "this display offers less. SetBackendToRayCast() needs none.");
          this->OwnWindow->Delete();
          this->OwnWindow = nullptr;
          return 0;
        }
      }
      window = this->OwnWindow;
    }
    auto* glWindow = vtkOpenGLRenderWindow::SafeDownCast(window);
    if (!glWindow)
    {
      vtkErrorMacro("The render window is not an OpenGL window ("
        << window->GetClassName() << "). SetBackendToRayCast() needs none.");
      return 0;
    }
    glWindow->Initialize();
    glWindow->MakeCurrent();
    const std::string missing = vtkVisibilityRenderer::Missing(this->Backend == DEPTH_COMPARE);
    if (!missing.empty())
    {
      vtkErrorMacro("The " << this->GetBackendAsString() << " backend needs " << missing
                           << ", which this OpenGL context lacks. SetBackendToRayCast() needs "
                              "no OpenGL.");
      return 0;
    }

    // The scene on the GPU: receivers first, then the occluders' points and triangles.
    // (A surface's Points hold 3 floats per point and one of padding for Embree at the end.)
    std::vector<float> points(receivers.Points.begin(), receivers.Points.begin() + 3 * n);
    std::vector<std::uint32_t> indices(receivers.Triangles);
    for (const auto& s : occluderSurfaces)
    {
      const auto base = static_cast<std::uint32_t>(points.size() / 3);
      points.insert(points.end(), s.Points.begin(), s.Points.begin() + 3 * s.GetNumberOfPoints());
      for (std::uint32_t id : s.Triangles)
      {
        indices.push_back(base + id);
      }
    }
    SortTriangles(points, indices);
    double radius = 0.0;
    for (size_t p = 0; p < points.size(); p += 3)
    {
      const double r2 = double(points[p]) * points[p] + double(points[p + 1]) * points[p + 1] +
        double(points[p + 2]) * points[p + 2];
      if (std::isfinite(r2))
      {
        radius = std::max(radius, std::sqrt(r2));
      }
    }
    // A margin so that nothing touches the near and far planes.
    radius = radius > 0.0 ? 1.01 * radius : 1.0;
    if (!this->Renderer)
    {
      this->Renderer.reset(new vtkVisibilityRenderer);
    }
    if (!this->Renderer->SetScene(glWindow, points, indices, n, radius, this->DepthResolution,
          this->PolygonOffsetFactor, this->PolygonOffsetUnits, error))
    {
      vtkErrorMacro("OpenGL failed: " << error << ".");
      return 0;
    }
    const size_t before = this->Computed.size();
    bool ok = true;
    if (this->Backend == DEPTH_COMPARE)
    {
      // All directions at once, so that each can be paired with its opposite.
      ok = this->Renderer->DepthCompare(todo, this->Computed, error,
        [&](size_t done)
        {
          this->UpdateProgress(static_cast<double>(before + done) / k);
          return !this->GetAbortExecute();
        });
    }
    for (size_t first = 0; ok && this->Backend == OCCLUSION_QUERY && first < todo.size();
         first += Chunk)
    {
      const Directions chunk(
        todo.begin() + first, todo.begin() + std::min(todo.size(), first + Chunk));
      ok = this->Renderer->OcclusionQuery(chunk, this->Computed, error);
      this->UpdateProgress(static_cast<double>(this->Computed.size()) / k);
      ok = ok && !this->GetAbortExecute();
    }
    this->NumberOfDepthPasses = this->Renderer->GetNumberOfDepthPasses();
    if (this->GetAbortExecute())
    {
      this->Computed.resize(before);
      output->Initialize();
      return 1;
    }
    if (!ok)
    {
      vtkErrorMacro("OpenGL failed: " << error << ".");
      this->Computed.clear();
      return 0;
    }
  }

  // The output: the input, the arrays, and the lightsphere.
  output->ShallowCopy(input);
  vtkPointData* pd = output->GetPointData();
  if (receivers.NormalsComputed)
  {
    pd->SetNormals(receivers.Normals);
  }
  if (this->ComputeVisibility)
  {
    vtkNew<vtkFloatArray> visibility;
    visibility->SetName("Visibility");
    visibility->SetNumberOfComponents(k);
    visibility->SetNumberOfTuples(n);
    float* values = visibility->GetPointer(0);
    vtkSMPTools::For(0, n,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          const float* normal = receivers.GetNormal(i);
          for (int j = 0; j < k; ++j)
          {
            const double c = normal[0] * directions[j][0] + normal[1] * directions[j][1] +
              normal[2] * directions[j][2];
            values[i * k + j] = receivers.Valid[i] && c > 0.0 && Bit(this->Computed[j], i)
              ? static_cast<float>(c)
              : 0.0f;
          }
        }
      });
    pd->AddArray(visibility);
  }
  if (this->ComputeVisibilityBits)
  {
    vtkNew<vtkBitArray> bits;
    bits->SetName("VisibilityBits");
    bits->SetNumberOfComponents(k);
    bits->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      const float* normal = receivers.GetNormal(i);
      for (int j = 0; j < k; ++j)
      {
        const double c = normal[0] * directions[j][0] + normal[1] * directions[j][1] +
          normal[2] * directions[j][2];
        bits->SetValue(i * k + j, receivers.Valid[i] && c > 0.0 && Bit(this->Computed[j], i));
      }
    }
    pd->AddArray(bits);
  }
  vtkSmartPointer<vtkDoubleArray> lightDirections;
  lightDirections.TakeReference(sphere->NewDirections());
  vtkSmartPointer<vtkDoubleArray> lightWeights;
  lightWeights.TakeReference(sphere->NewWeights());
  vtkNew<vtkFieldData> fields;
  fields->ShallowCopy(input->GetFieldData());
  fields->AddArray(lightDirections);
  fields->AddArray(lightWeights);
  output->SetFieldData(fields);

  if (receivers.NonFinitePoints > 0)
  {
    vtkWarningMacro(<< receivers.NonFinitePoints
                    << " point(s) are not finite (NaN or infinite); they see nothing, and no "
                       "cell that uses them casts shadows.");
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkOcclusionQueryVisibility::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Level: " << this->Level << "\n";
  os << indent << "Backend: " << this->GetBackendAsString() << "\n";
  os << indent << "DepthResolution: " << this->DepthResolution << "\n";
  os << indent << "PolygonOffsetFactor: " << this->PolygonOffsetFactor << "\n";
  os << indent << "PolygonOffsetUnits: " << this->PolygonOffsetUnits << "\n";
  os << indent << "RayOffset: " << this->RayOffset << "\n";
  os << indent << "ComputeVisibility: " << (this->ComputeVisibility ? "On" : "Off") << "\n";
  os << indent << "ComputeVisibilityBits: " << (this->ComputeVisibilityBits ? "On" : "Off") << "\n";
  os << indent << "RenderWindow: " << this->RenderWindow << "\n";
  os << indent << "NumberOfDepthPasses: " << this->NumberOfDepthPasses << "\n";
}
