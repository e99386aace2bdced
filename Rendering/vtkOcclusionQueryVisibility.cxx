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
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProp3D.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWeakPointer.h"

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
// occlusion ray per point and direction, 16 points to a packet. The points cast for are those of
// `order` (neighbours together, so that a packet's rays stay coherent), their bits set at their
// place in that order.
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
    const vtkIdType n = static_cast<vtkIdType>(this->Order.size());
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
            const vtkIdType id = first + lane < n ? this->Order[first + lane] : -1;
            // Directions below a point's tangent plane are hidden by its own surface.
            const float* normal = id >= 0 ? this->Surface.GetNormal(id) : nullptr;
            valid[lane] = id >= 0 && this->Surface.Valid[id] &&
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
class vtkOcclusionQueryVisibility::vtkInternals
{
public:
  // What everything below was computed for: the geometry and the settings.
  std::vector<vtkMTimeType> Key;
  vtkApertureSurface Receivers;
  std::vector<vtkApertureSurface> Occluders;
  // The scene for OpenGL (receivers' points first, triangles in Morton order), built on demand.
  bool SceneBuilt = false;
  std::vector<float> Points;
  std::vector<std::uint32_t> Triangles;
  std::vector<std::uint32_t> UnsortedTriangles;
  double Radius = 1.0;
  // Whether the scene went to the GPU in this update.
  bool Uploaded = false;
  // One bit set of points per direction, in lightsphere order; point i's bits hold for its first
  // Directions[i] directions.
  std::vector<Bits> Computed;
  std::vector<int> Directions;
  // Vertex filtering: receiver triangles not seen yet, points that need visibility, and whether
  // filtering goes on.
  std::vector<std::uint32_t> Unseen;
  std::vector<unsigned char> Seen;
  bool Filtering = false;
  std::unique_ptr<vtkApertureRayScene> RayScene;
  vtkWeakPointer<vtkRenderer> ViewRenderer;
  vtkWeakPointer<vtkProp3D> ViewProp;
  std::unique_ptr<vtkVisibilityRenderer> Renderer;
};

//------------------------------------------------------------------------------
vtkOcclusionQueryVisibility::vtkOcclusionQueryVisibility()
  : Internals(new vtkInternals)
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
void vtkOcclusionQueryVisibility::SetViewRenderer(vtkRenderer* renderer)
{
  if (this->Internals->ViewRenderer != renderer)
  {
    this->Internals->ViewRenderer = renderer;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkRenderer* vtkOcclusionQueryVisibility::GetViewRenderer()
{
  return this->Internals->ViewRenderer;
}

//------------------------------------------------------------------------------
void vtkOcclusionQueryVisibility::SetViewProp(vtkProp3D* prop)
{
  if (this->Internals->ViewProp != prop)
  {
    this->Internals->ViewProp = prop;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkProp3D* vtkOcclusionQueryVisibility::GetViewProp()
{
  return this->Internals->ViewProp;
}

//------------------------------------------------------------------------------
vtkIdType vtkOcclusionQueryVisibility::GetNumberOfUnseenTriangles()
{
  return static_cast<vtkIdType>(this->Internals->Unseen.size());
}

//------------------------------------------------------------------------------
bool vtkOcclusionQueryVisibility::GetFilteringActive()
{
  return this->Internals->Filtering;
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
  if (this->Internals->Renderer)
  {
    this->Internals->Renderer->ReleaseGraphicsResources(window);
  }
}

//------------------------------------------------------------------------------
bool vtkOcclusionQueryVisibility::PrepareOpenGL(bool needStorage, std::string& error)
{
  vtkInternals& in = *this->Internals;
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
        error = "No OpenGL context: " + problem + ".";
        return false;
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
        error = "No usable OpenGL context: VTK needs OpenGL 3.2 and this display offers less.";
        this->OwnWindow->Delete();
        this->OwnWindow = nullptr;
        return false;
      }
    }
    window = this->OwnWindow;
  }
  auto* glWindow = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!glWindow)
  {
    error =
      std::string("The render window is not an OpenGL window (") + window->GetClassName() + ").";
    return false;
  }
  glWindow->Initialize();
  glWindow->MakeCurrent();
  const std::string missing = vtkVisibilityRenderer::Missing(needStorage);
  if (!missing.empty())
  {
    error = std::string("The ") +
      (this->Backend == DEPTH_COMPARE ? "DepthCompare backend"
                                      : "camera pass of vertex filtering") +
      " needs " + missing + ", which this OpenGL context lacks.";
    return false;
  }
  if (in.Uploaded)
  {
    return true;
  }
  if (!in.SceneBuilt)
  {
    // Receivers first, then the occluders' points and triangles. (A surface's Points hold 3
    // floats per point and one of padding for Embree at the end.)
    const vtkIdType n = in.Receivers.GetNumberOfPoints();
    in.Points.assign(in.Receivers.Points.begin(), in.Receivers.Points.begin() + 3 * n);
    std::vector<std::uint32_t> triangles = in.Receivers.Triangles;
    for (const auto& s : in.Occluders)
    {
      const auto base = static_cast<std::uint32_t>(in.Points.size() / 3);
      in.Points.insert(
        in.Points.end(), s.Points.begin(), s.Points.begin() + 3 * s.GetNumberOfPoints());
      for (std::uint32_t id : s.Triangles)
      {
        triangles.push_back(base + id);
      }
    }
    // A deforming mesh keeps its triangles, and their order: they are not uploaded again.
    if (triangles != in.UnsortedTriangles)
    {
      in.UnsortedTriangles = triangles;
      SortTriangles(in.Points, triangles);
      in.Triangles.swap(triangles);
    }
    double radius = 0.0;
    for (size_t p = 0; p < in.Points.size(); p += 3)
    {
      const double r2 = double(in.Points[p]) * in.Points[p] +
        double(in.Points[p + 1]) * in.Points[p + 1] + double(in.Points[p + 2]) * in.Points[p + 2];
      if (std::isfinite(r2))
      {
        radius = std::max(radius, std::sqrt(r2));
      }
    }
    // A margin so that nothing touches the near and far planes.
    in.Radius = radius > 0.0 ? 1.01 * radius : 1.0;
    in.SceneBuilt = true;
  }
  if (!in.Renderer)
  {
    in.Renderer.reset(new vtkVisibilityRenderer);
  }
  if (!in.Renderer->SetScene(glWindow, in.Points, in.Triangles, in.Receivers.GetNumberOfPoints(),
        in.Radius, this->DepthResolution, this->PolygonOffsetFactor, this->PolygonOffsetUnits,
        error))
  {
    error = "OpenGL failed: " + error + ".";
    return false;
  }
  this->UploadedBytes = in.Renderer->GetUploadedBytes();
  in.Uploaded = true;
  return true;
}

//------------------------------------------------------------------------------
bool vtkOcclusionQueryVisibility::UpdateSeen(std::string& error)
{
  vtkInternals& in = *this->Internals;
  vtkRenderer* renderer = in.ViewRenderer;
  vtkCamera* camera = renderer->GetActiveCamera();
  int width = renderer->GetSize()[0], height = renderer->GetSize()[1];
  if (width <= 0 || height <= 0)
  {
    // Not rendered yet: the window's size, or VTK's default.
    const int* size =
      renderer->GetRenderWindow() ? renderer->GetRenderWindow()->GetSize() : nullptr;
    width = size && size[0] > 0 ? size[0] : 300;
    height = size && size[1] > 0 ? size[1] : 300;
  }
  // The paper's per-triangle queries with its backend, or where storage buffers are missing
  // (OpenGL 3.3 suffices for them); one draw into a storage buffer otherwise.
  if (!this->PrepareOpenGL(false, error))
  {
    return false;
  }
  const bool queries =
    this->Backend == OCCLUSION_QUERY || !vtkVisibilityRenderer::Missing(true).empty();

  // Local coordinates to the world (the prop's matrix after the local origin), then to the eye
  // as the renderer sees it (the camera's model-view, with its model and user transforms).
  vtkNew<vtkMatrix4x4> local;
  for (int c = 0; c < 3; ++c)
  {
    local->SetElement(c, 3, in.Receivers.Origin[c]);
  }
  vtkNew<vtkMatrix4x4> model;
  if (in.ViewProp)
  {
    vtkMatrix4x4::Multiply4x4(in.ViewProp->GetMatrix(), local, model);
  }
  else
  {
    model->DeepCopy(local);
  }
  vtkNew<vtkMatrix4x4> eye;
  vtkMatrix4x4::Multiply4x4(camera->GetModelViewTransformMatrix(), model, eye);
  // Near and far planes around the scene's bounding sphere (the camera's clipping range may
  // not have been reset for this view yet), on a copy of the camera, whose projection then has
  // everything else the renderer uses (view angle, window centre, shear, user matrix).
  double scale = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    scale = std::max(scale,
      std::sqrt(eye->GetElement(0, c) * eye->GetElement(0, c) +
        eye->GetElement(1, c) * eye->GetElement(1, c) +
        eye->GetElement(2, c) * eye->GetElement(2, c)));
  }
  const double radius = in.Radius * scale;
  const double depth = -eye->GetElement(2, 3);
  const double far = depth + radius;
  if (far <= 0.0)
  {
    // The scene is behind the camera: nothing is seen.
    return true;
  }
  vtkNew<vtkCamera> view;
  view->DeepCopy(camera);
  view->SetClippingRange(std::max(depth - radius, 1e-3 * far), far);
  vtkNew<vtkMatrix4x4> clip;
  vtkMatrix4x4::Multiply4x4(
    view->GetProjectionTransformMatrix(static_cast<double>(width) / height, -1.0, 1.0), eye, clip);
  float matrix[16];
  for (int row = 0; row < 4; ++row)
  {
    for (int column = 0; column < 4; ++column)
    {
      matrix[4 * column + row] = static_cast<float>(clip->GetElement(row, column));
    }
  }

  const std::vector<std::uint32_t>& triangles = in.Receivers.Triangles;
  std::vector<std::uint32_t> candidates;
  candidates.reserve(3 * in.Unseen.size());
  for (std::uint32_t t : in.Unseen)
  {
    candidates.insert(candidates.end(), &triangles[3 * size_t(t)], &triangles[3 * size_t(t) + 3]);
  }
  std::vector<char> seen;
  if (!in.Renderer->ViewVisible(matrix, width, height, candidates, queries, seen, error))
  {
    error = "OpenGL failed in the camera pass: " + error + ".";
    return false;
  }
  std::vector<std::uint32_t> unseen;
  for (size_t i = 0; i < in.Unseen.size(); ++i)
  {
    if (!seen[i])
    {
      unseen.push_back(in.Unseen[i]);
    }
  }
  // Below the threshold, the rest is computed now and filtering stops.
  const bool stop = static_cast<double>(unseen.size()) <=
    this->FilteringThreshold * static_cast<double>(in.Receivers.GetNumberOfTriangles());
  for (size_t i = 0; i < in.Unseen.size(); ++i)
  {
    if (seen[i] || stop)
    {
      for (int c = 0; c < 3; ++c)
      {
        in.Seen[triangles[3 * size_t(in.Unseen[i]) + c]] = 1;
      }
    }
  }
  in.Unseen = stop ? std::vector<std::uint32_t>() : unseen;
  in.Filtering = !stop;
  return true;
}

//------------------------------------------------------------------------------
int vtkOcclusionQueryVisibility::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInternals& in = *this->Internals;
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->NumberOfDepthPasses = 0;
  this->NumberOfComputedPoints = 0;
  this->UploadedBytes = 0;
  in.Uploaded = false;
  if (!input || input->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro("The input is empty: there are no points to compute visibility for.");
    return 0;
  }
  if (this->VertexFiltering && !in.ViewRenderer)
  {
    vtkErrorMacro("Vertex filtering follows a camera: SetViewRenderer() is needed.");
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

  // Visibility computed before for the same geometry and settings is kept: a higher level adds
  // its new directions, filtering adds the points it has newly seen.
  auto bitsOf = [](double value)
  {
    vtkMTimeType bits = 0;
    std::memcpy(&bits, &value, std::min(sizeof(bits), sizeof(value)));
    return bits;
  };
  std::vector<vtkMTimeType> key = { input->GetMTime(), static_cast<vtkMTimeType>(this->Backend),
    static_cast<vtkMTimeType>(this->DepthResolution), bitsOf(this->PolygonOffsetFactor),
    bitsOf(this->PolygonOffsetUnits), bitsOf(this->RayOffset),
    static_cast<vtkMTimeType>(this->VertexFiltering) };
  for (vtkPolyData* occluder : occluders)
  {
    key.push_back(occluder->GetMTime());
  }
  std::string error;
  if (key != in.Key)
  {
    in.Key.clear();
    if (!vtkApertureSurface::SetScene(input, occluders, in.Receivers, in.Occluders, error))
    {
      vtkErrorMacro(<< error);
      return 0;
    }
    const vtkIdType n = in.Receivers.GetNumberOfPoints();
    in.SceneBuilt = false;
    in.RayScene.reset();
    in.Computed.clear();
    in.Directions.assign(n, 0);
    // Without filtering every point is needed; with it, those of triangles not seen yet are not.
    in.Seen.assign(n, 1);
    in.Unseen.clear();
    in.Filtering = this->VertexFiltering;
    if (in.Filtering)
    {
      const vtkIdType triangles = in.Receivers.GetNumberOfTriangles();
      in.Unseen.resize(triangles);
      for (vtkIdType t = 0; t < triangles; ++t)
      {
        in.Unseen[t] = static_cast<std::uint32_t>(t);
        for (int c = 0; c < 3; ++c)
        {
          in.Seen[in.Receivers.Triangles[3 * t + c]] = 0;
        }
      }
    }
    in.Key = key;
  }
  const vtkApertureSurface& receivers = in.Receivers;
  const vtkIdType n = receivers.GetNumberOfPoints();

  if (in.Filtering && !this->UpdateSeen(error))
  {
    vtkErrorMacro(<< error);
    in.Key.clear();
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
  if (in.Computed.size() < static_cast<size_t>(k))
  {
    in.Computed.resize(k, Bits((n + 63) / 64, 0));
  }

  // The points that need directions, and the first direction one of them lacks.
  std::vector<std::uint32_t> todo;
  int first = k;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (in.Seen[i] && in.Directions[i] < k)
    {
      todo.push_back(static_cast<std::uint32_t>(i));
      first = std::min(first, in.Directions[i]);
    }
  }
  const Directions missing(directions.begin() + std::min(first, k), directions.end());
  const std::vector<std::uint32_t>* subset =
    static_cast<vtkIdType>(todo.size()) == n ? nullptr : &todo;
  // New bits are or-ed in: a point given a direction again gets the same bit.
  auto merge = [&](std::vector<Bits>& fresh, size_t offset)
  {
    for (size_t j = 0; j < fresh.size(); ++j)
    {
      Bits& bits = in.Computed[first + offset + j];
      for (size_t w = 0; w < bits.size(); ++w)
      {
        bits[w] |= fresh[j][w];
      }
    }
  };

  this->UpdateProgress(0.0);
  bool aborted = false;
  if (!todo.empty() && this->Backend == RAY_CAST)
  {
    // The Embree scene lasts as long as the geometry: filtering's later updates reuse it.
    if (!in.RayScene)
    {
      in.RayScene.reset(new vtkApertureRayScene);
      if (!in.RayScene->Build(receivers, in.Occluders))
      {
        vtkErrorMacro("Embree failed: " << in.RayScene->GetError());
        in.RayScene.reset();
        return 0;
      }
    }
    vtkApertureRayScene& scene = *in.RayScene;
    const auto m = static_cast<vtkIdType>(todo.size());
    const vtkIdType blocks = (m + 63) / 64;
    // Points in Morton order, so that each packet's rays start close together.
    std::vector<float> positions(3 * todo.size());
    for (size_t i = 0; i < todo.size(); ++i)
    {
      std::copy_n(&receivers.Points[3 * todo[i]], 3, &positions[3 * i]);
    }
    const std::vector<std::uint32_t> codes =
      MortonCodes(receivers.Points, positions.data(), todo.size());
    std::vector<vtkIdType> rank(todo.size());
    for (size_t i = 0; i < rank.size(); ++i)
    {
      rank[i] = static_cast<vtkIdType>(i);
    }
    std::sort(
      rank.begin(), rank.end(), [&codes](vtkIdType a, vtkIdType b) { return codes[a] < codes[b]; });
    std::vector<vtkIdType> order(todo.size());
    for (size_t i = 0; i < order.size(); ++i)
    {
      order[i] = todo[rank[i]];
    }
    for (size_t begin = 0; begin < missing.size() && !aborted; begin += Chunk)
    {
      const Directions chunk(
        missing.begin() + begin, missing.begin() + std::min(missing.size(), begin + Chunk));
      std::vector<Bits> visible(chunk.size(), Bits(blocks, 0));
      vtkSMPTools::For(0, blocks, 4,
        CastDirections(receivers, order, scene.GetScene(), chunk, this->RayOffset, visible));
      std::vector<Bits> fresh;
      for (const Bits& ordered : visible)
      {
        Bits bits((n + 63) / 64, 0);
        for (vtkIdType i = 0; i < m; ++i)
        {
          if (Bit(ordered, i))
          {
            bits[order[i] / 64] |= std::uint64_t(1) << (order[i] % 64);
          }
        }
        fresh.push_back(std::move(bits));
      }
      merge(fresh, begin);
      this->NumberOfDepthPasses += static_cast<int>(chunk.size());
      this->UpdateProgress(static_cast<double>(begin + chunk.size()) / missing.size());
      aborted = this->GetAbortExecute() != 0;
    }
    const std::string embreeError = scene.GetError();
    if (!embreeError.empty())
    {
      vtkErrorMacro("Embree failed while tracing: " << embreeError);
      in.Key.clear();
      return 0;
    }
  }
  else if (!todo.empty())
  {
    if (!this->PrepareOpenGL(this->Backend == DEPTH_COMPARE, error))
    {
      vtkErrorMacro(<< error << " SetBackendToRayCast() needs no OpenGL.");
      in.Key.clear();
      return 0;
    }
    bool ok = true;
    if (this->Backend == DEPTH_COMPARE)
    {
      // All directions at once, so that each can be paired with its opposite.
      std::vector<Bits> fresh;
      ok = in.Renderer->DepthCompare(
        missing, fresh, error,
        [&](size_t done)
        {
          this->UpdateProgress(static_cast<double>(done) / missing.size());
          return !this->GetAbortExecute();
        },
        subset);
      if (ok)
      {
        merge(fresh, 0);
      }
    }
    for (size_t begin = 0; ok && this->Backend == OCCLUSION_QUERY && begin < missing.size();
         begin += Chunk)
    {
      const Directions chunk(
        missing.begin() + begin, missing.begin() + std::min(missing.size(), begin + Chunk));
      std::vector<Bits> fresh;
      ok = in.Renderer->OcclusionQuery(chunk, fresh, error, subset);
      merge(fresh, begin);
      this->UpdateProgress(static_cast<double>(begin + chunk.size()) / missing.size());
      ok = ok && !this->GetAbortExecute();
    }
    // SetScene() in this update started the count.
    this->NumberOfDepthPasses = in.Renderer->GetNumberOfDepthPasses();
    aborted = this->GetAbortExecute() != 0;
    if (!ok && !aborted)
    {
      vtkErrorMacro("OpenGL failed: " << error << ".");
      in.Key.clear();
      return 0;
    }
  }
  if (aborted)
  {
    output->Initialize();
    return 1;
  }
  for (std::uint32_t i : todo)
  {
    in.Directions[i] = k;
  }
  this->NumberOfComputedPoints = static_cast<vtkIdType>(todo.size());

  // The output: the input, the arrays, and the lightsphere.
  output->ShallowCopy(input);
  vtkPointData* pd = output->GetPointData();
  if (receivers.NormalsComputed)
  {
    pd->SetNormals(receivers.Normals);
  }
  // Point i sees direction j when it is above its tangent plane and its bit is set.
  auto sees = [&](vtkIdType i, int j, double& cosine)
  {
    const float* normal = receivers.GetNormal(i);
    cosine =
      normal[0] * directions[j][0] + normal[1] * directions[j][1] + normal[2] * directions[j][2];
    return receivers.Valid[i] && cosine > 0.0 && j < in.Directions[i] && Bit(in.Computed[j], i);
  };
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
          for (int j = 0; j < k; ++j)
          {
            double c = 0.0;
            values[i * k + j] = sees(i, j, c) ? static_cast<float>(c) : 0.0f;
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
      for (int j = 0; j < k; ++j)
      {
        double c = 0.0;
        bits->SetValue(i * k + j, sees(i, j, c));
      }
    }
    pd->AddArray(bits);
  }
  if (this->VertexFiltering)
  {
    // Which points have their visibility yet: those of triangles not seen have none.
    vtkNew<vtkUnsignedCharArray> done;
    done->SetName("VisibilityComputed");
    done->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      done->SetValue(i, in.Directions[i] >= k ? 1 : 0);
    }
    pd->AddArray(done);
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
  os << indent << "VertexFiltering: " << (this->VertexFiltering ? "On" : "Off") << "\n";
  os << indent << "FilteringThreshold: " << this->FilteringThreshold << "\n";
  os << indent << "ViewRenderer: " << this->Internals->ViewRenderer.GetPointer() << "\n";
  os << indent << "ViewProp: " << this->Internals->ViewProp.GetPointer() << "\n";
  os << indent << "RenderWindow: " << this->RenderWindow << "\n";
  os << indent << "NumberOfDepthPasses: " << this->NumberOfDepthPasses << "\n";
  os << indent << "NumberOfComputedPoints: " << this->NumberOfComputedPoints << "\n";
  os << indent << "NumberOfUnseenTriangles: " << this->Internals->Unseen.size() << "\n";
  os << indent << "FilteringActive: " << (this->Internals->Filtering ? "Yes" : "No") << "\n";
  os << indent << "UploadedBytes: " << this->UploadedBytes << "\n";
}
