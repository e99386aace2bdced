/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkOcclusionQueryVisibility.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkOcclusionQueryVisibility.h"

#include "vtkApertureDisplay.h"
#include "vtkApertureDistributedOccluders.h"
#include "vtkApertureSurface.h"
#include "vtkLightSphere.h"
#include "vtkMortonOrder.h"
#include "vtkRayCastVisibility.h"
#include "vtkVisibilityCameraPass.h"
#include "vtkVisibilityMatrixPasses.h"
#include "vtkVisibilityScene.h"

#include "vtkBitArray.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
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

namespace
{
using Directions = std::vector<std::array<double, 3>>;
using Bits = vtkVisibilityMatrixPasses::Bits;

// Directions handled between two progress events.
constexpr size_t Chunk = 8;

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
  float lo[3], hi[3];
  vtkMortonOrder::Bounds(points.data(), points.size() / 3, lo, hi);
  const std::vector<std::uint32_t> codes = vtkMortonOrder::Codes(centroids.data(), count, lo, hi);
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

Directions AllDirections(vtkLightSphere* sphere)
{
  Directions directions(sphere->GetNumberOfDirections());
  for (size_t j = 0; j < directions.size(); ++j)
  {
    sphere->GetDirection(static_cast<int>(j), directions[j].data());
  }
  return directions;
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
  // The scene for OpenGL, built on demand: the receiving points first (the points tested), then
  // the vertices of the receivers (from ReceiverVertices on) and the occluders; triangles in
  // Morton order.
  bool SceneBuilt = false;
  std::vector<float> Points;
  std::uint32_t ReceiverVertices = 0;
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
  vtkRayCastVisibility RayCast;
  // Weak: the window usually renders this filter's output, and a reference back would make a
  // cycle that nothing frees. When it goes, the GL objects made in its context go first.
  vtkWeakPointer<vtkRenderWindow> RenderWindow;
  vtkNew<vtkCallbackCommand> WindowGone;
  unsigned long WindowGoneTag = 0;
  vtkWeakPointer<vtkRenderer> ViewRenderer;
  vtkWeakPointer<vtkProp3D> ViewProp;
  // The GL passes over the scene uploaded (declared after it: they go first).
  vtkVisibilityScene GLScene;
  vtkVisibilityMatrixPasses MatrixPasses{ GLScene };
  vtkVisibilityCameraPass CameraPass{ GLScene };
};

//------------------------------------------------------------------------------
vtkOcclusionQueryVisibility::vtkOcclusionQueryVisibility()
  : Internals(new vtkInternals)
{
  this->SetNumberOfInputPorts(2);
  this->SetController(vtkMultiProcessController::GetGlobalController());
  this->Internals->WindowGone->SetClientData(this);
  this->Internals->WindowGone->SetCallback(
    [](vtkObject* window, unsigned long, void* self, void*)
    {
      static_cast<vtkOcclusionQueryVisibility*>(self)->ReleaseGraphicsResources(
        static_cast<vtkWindow*>(window));
    });
}

//------------------------------------------------------------------------------
vtkCxxSetObjectMacro(vtkOcclusionQueryVisibility, Controller, vtkMultiProcessController);

//------------------------------------------------------------------------------
vtkOcclusionQueryVisibility::~vtkOcclusionQueryVisibility()
{
  this->SetRenderWindow(nullptr);
  this->SetController(nullptr);
  this->ReleaseGraphicsResources(this->OwnWindow);
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
void vtkOcclusionQueryVisibility::SetRenderWindow(vtkRenderWindow* window)
{
  vtkInternals& in = *this->Internals;
  if (in.RenderWindow == window)
  {
    return;
  }
  if (in.RenderWindow)
  {
    this->ReleaseGraphicsResources(in.RenderWindow);
    in.RenderWindow->RemoveObserver(in.WindowGoneTag);
  }
  in.RenderWindow = window;
  in.WindowGoneTag = window ? window->AddObserver(vtkCommand::DeleteEvent, in.WindowGone) : 0;
  this->Modified();
}

//------------------------------------------------------------------------------
vtkRenderWindow* vtkOcclusionQueryVisibility::GetRenderWindow()
{
  return this->Internals->RenderWindow;
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
  vtkInternals& in = *this->Internals;
  in.CameraPass.ReleaseGraphicsResources(window);
  in.MatrixPasses.ReleaseGraphicsResources(window);
  in.GLScene.ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
bool vtkOcclusionQueryVisibility::PrepareOpenGL(bool needStorage, std::string& error)
{
  vtkInternals& in = *this->Internals;
  vtkOpenGLRenderWindow* glWindow = this->OpenGLWindow(needStorage, error);
  if (!glWindow || in.Uploaded)
  {
    return glWindow != nullptr;
  }
  if (!in.SceneBuilt)
  {
    this->BuildOpenGLScene();
  }
  if (in.GLScene.GetWindow() != glWindow)
  {
    this->ReleaseGraphicsResources(in.GLScene.GetWindow());
  }
  if (!in.GLScene.Set(glWindow, in.Points, in.Triangles, this->PolygonOffsetFactor,
        this->PolygonOffsetUnits, error) ||
    !in.MatrixPasses.SetReceivers(
      in.Receivers.GetNumberOfPoints(), in.Radius, this->DepthResolution, error))
  {
    error = "OpenGL failed: " + error + ".";
    return false;
  }
  this->UploadedBytes = in.GLScene.GetUploadedBytes();
  in.Uploaded = true;
  return true;
}

//------------------------------------------------------------------------------
vtkOpenGLRenderWindow* vtkOcclusionQueryVisibility::OpenGLWindow(
  bool needStorage, std::string& error)
{
  vtkRenderWindow* window = this->GetRenderWindow();
  if (!window)
  {
    if (!this->OwnWindow && !(this->OwnWindow = vtkApertureDisplay::NewOffScreenWindow(error)))
    {
      return nullptr;
    }
    window = this->OwnWindow;
  }
  auto* glWindow = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!glWindow)
  {
    error =
      std::string("The render window is not an OpenGL window (") + window->GetClassName() + ").";
    return nullptr;
  }
  glWindow->Initialize();
  glWindow->MakeCurrent();
  const std::string missing = vtkVisibilityScene::Missing(needStorage);
  if (!missing.empty())
  {
    error = std::string("The ") +
      (this->Backend == DEPTH_COMPARE ? "DepthCompare backend"
                                      : "camera pass of vertex filtering") +
      " needs " + missing + ", which this OpenGL context lacks.";
    return nullptr;
  }
  return glWindow;
}

//------------------------------------------------------------------------------
void vtkOcclusionQueryVisibility::BuildOpenGLScene()
{
  vtkInternals& in = *this->Internals;
  const vtkApertureSurface& receivers = in.Receivers;
  const vtkIdType n = receivers.GetNumberOfPoints();
  // The points tested come first: the receivers' vertices themselves when they are one per
  // vertex (nothing welded, nothing split), else copies of the receiving points' positions.
  bool oneToOne = n == receivers.GetNumberOfVertices();
  for (vtkIdType i = 0; i < n && oneToOne; ++i)
  {
    oneToOne = receivers.PointVertex[i] == static_cast<std::uint32_t>(i);
  }
  in.Points.clear();
  for (vtkIdType i = 0; i < n && !oneToOne; ++i)
  {
    in.Points.insert(in.Points.end(), receivers.GetPosition(i), receivers.GetPosition(i) + 3);
  }
  in.ReceiverVertices = static_cast<std::uint32_t>(in.Points.size() / 3);
  std::vector<std::uint32_t> triangles;
  auto add = [&](const vtkApertureSurface& s)
  {
    // A surface's Vertices hold 3 floats per vertex and one of padding at the end.
    const auto base = static_cast<std::uint32_t>(in.Points.size() / 3);
    in.Points.insert(
      in.Points.end(), s.Vertices.begin(), s.Vertices.begin() + 3 * s.GetNumberOfVertices());
    for (std::uint32_t id : s.Triangles)
    {
      triangles.push_back(base + id);
    }
  };
  add(receivers);
  for (const auto& s : in.Occluders)
  {
    add(s);
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

namespace
{
// The view's size in pixels: the renderer's, or before its first render its window's (or VTK's
// default).
void ViewSize(vtkRenderer* renderer, int& width, int& height)
{
  width = renderer->GetSize()[0];
  height = renderer->GetSize()[1];
  if (width <= 0 || height <= 0)
  {
    const int* size =
      renderer->GetRenderWindow() ? renderer->GetRenderWindow()->GetSize() : nullptr;
    width = size && size[0] > 0 ? size[0] : 300;
    height = size && size[1] > 0 ? size[1] : 300;
  }
}

// The column-major matrix from the scene's local coordinates (`origin` shifted, within `radius`)
// to the camera's clip space: the prop's matrix after the local origin, the camera's model-view
// (with its model and user transforms), then its projection with near and far planes around the
// scene's bounding sphere (the camera's clipping range may not have been reset for this view
// yet), on a copy of the camera, whose projection then has everything else the renderer uses.
// False when the scene is behind the camera.
bool CameraClipMatrix(vtkCamera* camera, vtkProp3D* prop, const double origin[3], double radius,
  int width, int height, float matrix[16])
{
  vtkNew<vtkMatrix4x4> local;
  for (int c = 0; c < 3; ++c)
  {
    local->SetElement(c, 3, origin[c]);
  }
  vtkNew<vtkMatrix4x4> model;
  if (prop)
  {
    vtkMatrix4x4::Multiply4x4(prop->GetMatrix(), local, model);
  }
  else
  {
    model->DeepCopy(local);
  }
  vtkNew<vtkMatrix4x4> eye;
  vtkMatrix4x4::Multiply4x4(camera->GetModelViewTransformMatrix(), model, eye);
  double scale = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    scale = std::max(scale,
      std::sqrt(eye->GetElement(0, c) * eye->GetElement(0, c) +
        eye->GetElement(1, c) * eye->GetElement(1, c) +
        eye->GetElement(2, c) * eye->GetElement(2, c)));
  }
  const double depth = -eye->GetElement(2, 3);
  const double far = depth + radius * scale;
  if (far <= 0.0)
  {
    return false;
  }
  vtkNew<vtkCamera> view;
  view->DeepCopy(camera);
  view->SetClippingRange(std::max(depth - radius * scale, 1e-3 * far), far);
  vtkNew<vtkMatrix4x4> clip;
  vtkMatrix4x4::Multiply4x4(
    view->GetProjectionTransformMatrix(static_cast<double>(width) / height, -1.0, 1.0), eye, clip);
  for (int row = 0; row < 4; ++row)
  {
    for (int column = 0; column < 4; ++column)
    {
      matrix[4 * column + row] = static_cast<float>(clip->GetElement(row, column));
    }
  }
  return true;
}

// The `triangles`' corners as the OpenGL scene numbers them (receivers' vertices from `base`).
std::vector<std::uint32_t> SceneCorners(const std::vector<std::uint32_t>& triangles,
  std::uint32_t base, const std::vector<std::uint32_t>& which)
{
  std::vector<std::uint32_t> corners;
  corners.reserve(3 * which.size());
  for (std::uint32_t t : which)
  {
    for (int c = 0; c < 3; ++c)
    {
      corners.push_back(base + triangles[3 * size_t(t) + c]);
    }
  }
  return corners;
}
}

//------------------------------------------------------------------------------
bool vtkOcclusionQueryVisibility::UpdateSeen(std::string& error)
{
  vtkInternals& in = *this->Internals;
  // 1. The camera pass: which of the triangles unseen so far the camera sees now, by the
  // paper's per-triangle queries with its backend or where storage buffers are missing (OpenGL
  // 3.3 suffices for them), by one draw into a storage buffer otherwise.
  if (!this->PrepareOpenGL(false, error))
  {
    return false;
  }
  int width, height;
  ViewSize(in.ViewRenderer, width, height);
  float matrix[16];
  if (!CameraClipMatrix(in.ViewRenderer->GetActiveCamera(), in.ViewProp, in.Receivers.Origin,
        in.Radius, width, height, matrix))
  {
    return true; // the scene is behind the camera: nothing is seen
  }
  const bool queries =
    this->Backend == OCCLUSION_QUERY || !vtkVisibilityScene::Missing(true).empty();
  std::vector<char> seen;
  if (!in.CameraPass.Visible(matrix, width, height,
        SceneCorners(in.Receivers.Triangles, in.ReceiverVertices, in.Unseen), queries, seen, error))
  {
    error = "OpenGL failed in the camera pass: " + error + ".";
    return false;
  }
  // 2. Their points are computed; below the threshold, the rest is computed now and filtering
  // stops.
  std::vector<std::uint32_t> unseen;
  for (size_t i = 0; i < in.Unseen.size(); ++i)
  {
    if (!seen[i])
    {
      unseen.push_back(in.Unseen[i]);
    }
  }
  const bool stop = static_cast<double>(unseen.size()) <=
    this->FilteringThreshold * static_cast<double>(in.Receivers.GetNumberOfTriangles());
  for (size_t i = 0; i < in.Unseen.size(); ++i)
  {
    if (seen[i] || stop)
    {
      for (int c = 0; c < 3; ++c)
      {
        in.Seen[in.Receivers.CornerPoints[3 * size_t(in.Unseen[i]) + c]] = 1;
      }
    }
  }
  in.Unseen = stop ? std::vector<std::uint32_t>() : unseen;
  in.Filtering = !stop;
  return true;
}

//------------------------------------------------------------------------------
// Visibility computed before for the same geometry and settings is kept: a higher level adds its
// new directions, filtering adds the points it has newly seen.
bool vtkOcclusionQueryVisibility::UpdateCache(
  vtkPolyData* input, const std::vector<vtkPolyData*>& occluders, std::string& error)
{
  vtkInternals& in = *this->Internals;
  auto bitsOf = [](double value)
  {
    vtkMTimeType bits = 0;
    std::memcpy(&bits, &value, std::min(sizeof(bits), sizeof(value)));
    return bits;
  };
  std::vector<vtkMTimeType> key = { input->GetMTime(), static_cast<vtkMTimeType>(this->Backend),
    static_cast<vtkMTimeType>(this->DepthResolution), bitsOf(this->PolygonOffsetFactor),
    bitsOf(this->PolygonOffsetUnits), bitsOf(this->RayOffset), bitsOf(this->FeatureAngle),
    static_cast<vtkMTimeType>(this->VertexFiltering) };
  for (vtkPolyData* occluder : occluders)
  {
    key.push_back(occluder->GetMTime());
  }
  if (key == in.Key)
  {
    return true;
  }
  in.Key.clear();
  if (!vtkApertureSurface::SetScene(
        input, occluders, this->FeatureAngle, this->RayOffset, in.Receivers, in.Occluders, error))
  {
    return false;
  }
  const vtkIdType n = in.Receivers.GetNumberOfPoints();
  in.SceneBuilt = false;
  in.RayCast.ReleaseScene();
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
    }
    for (const std::uint32_t point : in.Receivers.CornerPoints)
    {
      in.Seen[point] = 0;
    }
  }
  in.Key = key;
  return true;
}

//------------------------------------------------------------------------------
// Gives every point that needs them the directions of the level it lacks, by the backend.
bool vtkOcclusionQueryVisibility::ComputeMissing(
  const std::vector<std::array<double, 3>>& directions, bool& aborted, std::string& error)
{
  vtkInternals& in = *this->Internals;
  const vtkIdType n = in.Receivers.GetNumberOfPoints();
  const int k = static_cast<int>(directions.size());
  if (in.Computed.size() < directions.size())
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
  aborted = false;
  if (todo.empty())
  {
    return true;
  }
  const Directions missing(directions.begin() + first, directions.end());
  auto progress = [&](size_t done)
  {
    this->UpdateProgress(static_cast<double>(done) / missing.size());
    return !this->GetAbortExecute();
  };
  std::vector<Bits> fresh;
  bool ok = this->Backend == RAY_CAST ? this->CastRays(missing, todo, fresh, progress, error)
                                      : this->RenderOpenGL(missing, todo, fresh, progress, error);
  aborted = this->GetAbortExecute() != 0;
  if (!ok || aborted)
  {
    return aborted;
  }
  // New bits are or-ed in: a point given a direction again gets the same bit.
  for (size_t j = 0; j < fresh.size(); ++j)
  {
    Bits& bits = in.Computed[first + j];
    for (size_t w = 0; w < bits.size(); ++w)
    {
      bits[w] |= fresh[j][w];
    }
  }
  for (std::uint32_t i : todo)
  {
    in.Directions[i] = k;
  }
  this->NumberOfComputedPoints = static_cast<vtkIdType>(todo.size());
  return true;
}

//------------------------------------------------------------------------------
bool vtkOcclusionQueryVisibility::CastRays(const std::vector<std::array<double, 3>>& directions,
  const std::vector<std::uint32_t>& points, std::vector<Bits>& visible,
  const std::function<bool(size_t)>& progress, std::string& error)
{
  vtkInternals& in = *this->Internals;
  // The Embree scene lasts as long as the geometry: filtering's later updates reuse it.
  if (!in.RayCast.HasScene() && !in.RayCast.SetScene(in.Receivers, in.Occluders, error))
  {
    return false;
  }
  auto counted = [&](size_t done)
  {
    this->NumberOfDepthPasses = static_cast<int>(done);
    return progress(done);
  };
  return in.RayCast.Cast(directions, points, visible, counted, error);
}

//------------------------------------------------------------------------------
bool vtkOcclusionQueryVisibility::RenderOpenGL(const std::vector<std::array<double, 3>>& directions,
  const std::vector<std::uint32_t>& points, std::vector<Bits>& visible,
  const std::function<bool(size_t)>& progress, std::string& error)
{
  vtkInternals& in = *this->Internals;
  if (!this->PrepareOpenGL(this->Backend == DEPTH_COMPARE, error))
  {
    error += " SetBackendToRayCast() needs no OpenGL.";
    return false;
  }
  const std::vector<std::uint32_t>* subset =
    static_cast<vtkIdType>(points.size()) == in.Receivers.GetNumberOfPoints() ? nullptr : &points;
  bool ok = true;
  if (this->Backend == DEPTH_COMPARE)
  {
    // All directions at once, so that each can be paired with its opposite.
    ok = in.MatrixPasses.DepthCompare(directions, visible, error, progress, subset);
  }
  for (size_t begin = 0; ok && this->Backend == OCCLUSION_QUERY && begin < directions.size();
       begin += Chunk)
  {
    const Directions chunk(
      directions.begin() + begin, directions.begin() + std::min(directions.size(), begin + Chunk));
    std::vector<Bits> bits;
    ok = in.MatrixPasses.OcclusionQuery(chunk, bits, error, subset);
    visible.insert(visible.end(), bits.begin(), bits.end());
    ok = ok && progress(begin + chunk.size());
  }
  // SetReceivers() in this update started the count.
  this->NumberOfDepthPasses = in.MatrixPasses.GetNumberOfDepthPasses();
  if (!ok && !this->GetAbortExecute())
  {
    error = "OpenGL failed: " + error + ".";
  }
  return ok;
}

namespace
{
// Output point o sees direction j when its receiving point is above its tangent plane and has
// its bit set; `cosine` gets n . l.
struct Sees
{
  const vtkApertureSurface& Receivers;
  const std::vector<vtkIdType>& Points; // each output point's receiving point, or -1
  const std::vector<int>& Done;         // directions computed per receiving point
  const std::vector<Bits>& Computed;
  const std::vector<std::array<double, 3>>& Directions;

  bool operator()(vtkIdType o, int j, double& cosine) const
  {
    const vtkIdType i = this->Points[o];
    if (i < 0 || !this->Receivers.Valid[i] || j >= this->Done[i])
    {
      return false;
    }
    const float* n = this->Receivers.GetNormal(i);
    const auto& l = this->Directions[j];
    cosine = n[0] * l[0] + n[1] * l[1] + n[2] * l[2];
    return cosine > 0.0 && Bit(this->Computed[j], i);
  }
};

// M_oj = max(n . l_j, 0) where output point o sees direction j.
vtkSmartPointer<vtkFloatArray> VisibilityArray(const Sees& sees, vtkIdType m, int k)
{
  auto visibility = vtkSmartPointer<vtkFloatArray>::New();
  visibility->SetName("Visibility");
  visibility->SetNumberOfComponents(k);
  visibility->SetNumberOfTuples(m);
  float* values = visibility->GetPointer(0);
  vtkSMPTools::For(0, m,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType o = begin; o < end; ++o)
      {
        for (int j = 0; j < k; ++j)
        {
          double c = 0.0;
          values[o * k + j] = sees(o, j, c) ? static_cast<float>(c) : 0.0f;
        }
      }
    });
  return visibility;
}

// The raw visibility, one bit per output point and direction.
vtkSmartPointer<vtkBitArray> VisibilityBitsArray(const Sees& sees, vtkIdType m, int k)
{
  auto bits = vtkSmartPointer<vtkBitArray>::New();
  bits->SetName("VisibilityBits");
  bits->SetNumberOfComponents(k);
  bits->SetNumberOfTuples(m);
  for (vtkIdType o = 0; o < m; ++o)
  {
    for (int j = 0; j < k; ++j)
    {
      double c = 0.0;
      bits->SetValue(o * k + j, sees(o, j, c));
    }
  }
  return bits;
}

// Which output points have their visibility yet (vertex filtering: those of triangles not seen
// have none).
vtkSmartPointer<vtkUnsignedCharArray> ComputedArray(const Sees& sees, vtkIdType m, int k)
{
  auto done = vtkSmartPointer<vtkUnsignedCharArray>::New();
  done->SetName("VisibilityComputed");
  done->SetNumberOfTuples(m);
  for (vtkIdType o = 0; o < m; ++o)
  {
    done->SetValue(o, sees.Points[o] >= 0 && sees.Done[sees.Points[o]] >= k ? 1 : 0);
  }
  return done;
}
}

//------------------------------------------------------------------------------
// The output: the input's points (split where creases split them) with the arrays, and the
// lightsphere in the field data.
void vtkOcclusionQueryVisibility::WriteOutputs(vtkPolyData* input, vtkPolyData* output,
  vtkLightSphere* sphere, const std::vector<std::array<double, 3>>& directions)
{
  vtkInternals& in = *this->Internals;
  const vtkApertureSurface& receivers = in.Receivers;
  const int k = static_cast<int>(directions.size());
  std::vector<vtkIdType> points;
  receivers.MakeOutput(input, output, points);
  const vtkIdType m = static_cast<vtkIdType>(points.size());
  vtkPointData* pd = output->GetPointData();
  receivers.AddComputedNormals(pd, points);
  const Sees sees{ receivers, points, in.Directions, in.Computed, directions };
  if (this->ComputeVisibility)
  {
    pd->AddArray(VisibilityArray(sees, m, k));
  }
  if (this->ComputeVisibilityBits)
  {
    pd->AddArray(VisibilityBitsArray(sees, m, k));
  }
  if (this->VertexFiltering)
  {
    pd->AddArray(ComputedArray(sees, m, k));
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
  // A distributed run: the other ranks' surfaces occlude too (collective, before any check).
  vtkSmartPointer<vtkPolyData> remote;
  if (vtkApertureDistributedOccluders::GatherForPiece(
        this->Controller, outputVector->GetInformationObject(0), input, remote) &&
    (!input || input->GetNumberOfPoints() == 0))
  {
    output->Initialize(); // an empty piece
    return 1;
  }
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

  // 1. The surfaces, and what is kept of earlier updates.
  std::string error;
  if (!this->UpdateCache(
        input, vtkApertureDistributedOccluders::Occluders(inputVector[1], remote), error))
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  // 2. Vertex filtering: the points of the triangles the camera now sees.
  if (in.Filtering && !this->UpdateSeen(error))
  {
    vtkErrorMacro(<< error);
    in.Key.clear();
    return 0;
  }
  // 3. The directions of the level that points lack, by the backend.
  vtkNew<vtkLightSphere> sphere;
  sphere->SetLevel(this->Level);
  const Directions directions = AllDirections(sphere);
  this->UpdateProgress(0.0);
  bool aborted = false;
  if (!this->ComputeMissing(directions, aborted, error))
  {
    vtkErrorMacro(<< error);
    in.Key.clear();
    return 0;
  }
  if (aborted)
  {
    output->Initialize();
    return 1;
  }
  // 4. The output, and a word on points left out.
  this->WriteOutputs(input, output, sphere, directions);
  if (in.Receivers.NonFinitePoints > 0)
  {
    vtkWarningMacro(<< in.Receivers.NonFinitePoints
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
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "Backend: " << this->GetBackendAsString() << "\n";
  os << indent << "DepthResolution: " << this->DepthResolution << "\n";
  os << indent << "PolygonOffsetFactor: " << this->PolygonOffsetFactor << "\n";
  os << indent << "PolygonOffsetUnits: " << this->PolygonOffsetUnits << "\n";
  os << indent << "RayOffset: " << this->RayOffset << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "ComputeVisibility: " << (this->ComputeVisibility ? "On" : "Off") << "\n";
  os << indent << "ComputeVisibilityBits: " << (this->ComputeVisibilityBits ? "On" : "Off") << "\n";
  os << indent << "VertexFiltering: " << (this->VertexFiltering ? "On" : "Off") << "\n";
  os << indent << "FilteringThreshold: " << this->FilteringThreshold << "\n";
  os << indent << "ViewRenderer: " << this->Internals->ViewRenderer.GetPointer() << "\n";
  os << indent << "ViewProp: " << this->Internals->ViewProp.GetPointer() << "\n";
  os << indent << "RenderWindow: " << this->GetRenderWindow() << "\n";
  os << indent << "NumberOfDepthPasses: " << this->NumberOfDepthPasses << "\n";
  os << indent << "NumberOfComputedPoints: " << this->NumberOfComputedPoints << "\n";
  os << indent << "NumberOfUnseenTriangles: " << this->Internals->Unseen.size() << "\n";
  os << indent << "FilteringActive: " << (this->Internals->Filtering ? "Yes" : "No") << "\n";
  os << indent << "UploadedBytes: " << this->UploadedBytes << "\n";
}
