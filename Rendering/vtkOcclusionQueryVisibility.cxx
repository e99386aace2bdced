/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkOcclusionQueryVisibility.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkOcclusionQueryVisibility.h"

#include "vtkApertureDisplay.h"
#include "vtkApertureSurface.h"
#include "vtkMortonOrder.h"
#include "vtkVisibilityCameraPass.h"
#include "vtkVisibilityMatrixPasses.h"
#include "vtkVisibilityScene.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkProp3D.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <cmath>
#include <cstring>

vtkStandardNewMacro(vtkOcclusionQueryVisibility);

namespace
{
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

}

//------------------------------------------------------------------------------
class vtkOcclusionQueryVisibility::vtkInternals
{
public:
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
  // Vertex filtering: receiver triangles not seen yet, and whether filtering goes on.
  std::vector<std::uint32_t> Unseen;
  bool Filtering = false;
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
  this->Internals->WindowGone->SetClientData(this);
  this->Internals->WindowGone->SetCallback(
    [](vtkObject* window, unsigned long, void* self, void*)
    {
      static_cast<vtkOcclusionQueryVisibility*>(self)->ReleaseGraphicsResources(
        static_cast<vtkWindow*>(window));
    });
}

//------------------------------------------------------------------------------
vtkOcclusionQueryVisibility::~vtkOcclusionQueryVisibility()
{
  this->SetRenderWindow(nullptr);
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
      this->GetReceivers().GetNumberOfPoints(), in.Radius, this->DepthResolution, error))
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
  const vtkApertureSurface& receivers = this->GetReceivers();
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
  for (const auto& s : this->GetOccluders())
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
// Vertex filtering: the triangles the camera now sees move from the unseen list to the points
// needed.
bool vtkOcclusionQueryVisibility::SelectPoints(std::string& error)
{
  vtkInternals& in = *this->Internals;
  if (!in.Filtering)
  {
    return true;
  }
  const vtkApertureSurface& receivers = this->GetReceivers();
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
  if (!CameraClipMatrix(in.ViewRenderer->GetActiveCamera(), in.ViewProp, receivers.Origin,
        in.Radius, width, height, matrix))
  {
    return true; // the scene is behind the camera: nothing is seen
  }
  const bool queries =
    this->Backend == OCCLUSION_QUERY || !vtkVisibilityScene::Missing(true).empty();
  std::vector<char> seen;
  if (!in.CameraPass.Visible(matrix, width, height,
        SceneCorners(receivers.Triangles, in.ReceiverVertices, in.Unseen), queries, seen, error))
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
    this->FilteringThreshold * static_cast<double>(receivers.GetNumberOfTriangles());
  std::vector<unsigned char>& needed = this->GetNeededPoints();
  for (size_t i = 0; i < in.Unseen.size(); ++i)
  {
    if (seen[i] || stop)
    {
      for (int c = 0; c < 3; ++c)
      {
        needed[receivers.CornerPoints[3 * size_t(in.Unseen[i]) + c]] = 1;
      }
    }
  }
  in.Unseen = stop ? std::vector<std::uint32_t>() : unseen;
  in.Filtering = !stop;
  return true;
}

//------------------------------------------------------------------------------
bool vtkOcclusionQueryVisibility::CheckSettings(std::string& error)
{
  if (this->VertexFiltering && !this->Internals->ViewRenderer)
  {
    error = "Vertex filtering follows a camera: SetViewRenderer() is needed.";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkOcclusionQueryVisibility::AppendCacheKey(std::vector<vtkMTimeType>& key)
{
  this->Superclass::AppendCacheKey(key);
  auto bitsOf = [](float value)
  {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &value, sizeof(bits));
    return static_cast<vtkMTimeType>(bits);
  };
  key.insert(key.end(),
    { static_cast<vtkMTimeType>(this->Backend), static_cast<vtkMTimeType>(this->DepthResolution),
      bitsOf(this->PolygonOffsetFactor), bitsOf(this->PolygonOffsetUnits),
      static_cast<vtkMTimeType>(this->VertexFiltering) });
}

//------------------------------------------------------------------------------
// New surfaces: the OpenGL scene is built again, and vertex filtering starts with every receiver
// triangle unseen and no point needed.
void vtkOcclusionQueryVisibility::SurfacesChanged()
{
  vtkInternals& in = *this->Internals;
  in.SceneBuilt = false;
  in.Unseen.clear();
  in.Filtering = this->VertexFiltering;
  if (!in.Filtering)
  {
    return;
  }
  const vtkApertureSurface& receivers = this->GetReceivers();
  in.Unseen.resize(receivers.GetNumberOfTriangles());
  for (size_t t = 0; t < in.Unseen.size(); ++t)
  {
    in.Unseen[t] = static_cast<std::uint32_t>(t);
  }
  std::vector<unsigned char>& needed = this->GetNeededPoints();
  for (const std::uint32_t point : receivers.CornerPoints)
  {
    needed[point] = 0;
  }
}

//------------------------------------------------------------------------------
bool vtkOcclusionQueryVisibility::LeavesPointsOut()
{
  return this->VertexFiltering;
}

//------------------------------------------------------------------------------
// RAY_CAST is the superclass's computation; NumberOfDepthPasses counts its directions.
bool vtkOcclusionQueryVisibility::ComputeDirections(const Directions& directions,
  const std::vector<std::uint32_t>& points, std::vector<Bits>& visible,
  const std::function<bool(size_t)>& progress, std::string& error)
{
  if (this->Backend != RAY_CAST)
  {
    return this->RenderOpenGL(directions, points, visible, progress, error);
  }
  auto counted = [&](size_t done)
  {
    this->NumberOfDepthPasses = static_cast<int>(done);
    return progress(done);
  };
  return this->Superclass::ComputeDirections(directions, points, visible, counted, error);
}

//------------------------------------------------------------------------------
bool vtkOcclusionQueryVisibility::RenderOpenGL(const Directions& directions,
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
    static_cast<vtkIdType>(points.size()) == this->GetReceivers().GetNumberOfPoints() ? nullptr
                                                                                      : &points;
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

//------------------------------------------------------------------------------
int vtkOcclusionQueryVisibility::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->NumberOfDepthPasses = 0;
  this->UploadedBytes = 0;
  this->Internals->Uploaded = false;
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
void vtkOcclusionQueryVisibility::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Backend: " << this->GetBackendAsString() << "\n";
  os << indent << "DepthResolution: " << this->DepthResolution << "\n";
  os << indent << "PolygonOffsetFactor: " << this->PolygonOffsetFactor << "\n";
  os << indent << "PolygonOffsetUnits: " << this->PolygonOffsetUnits << "\n";
  os << indent << "VertexFiltering: " << (this->VertexFiltering ? "On" : "Off") << "\n";
  os << indent << "FilteringThreshold: " << this->FilteringThreshold << "\n";
  os << indent << "ViewRenderer: " << this->Internals->ViewRenderer.GetPointer() << "\n";
  os << indent << "ViewProp: " << this->Internals->ViewProp.GetPointer() << "\n";
  os << indent << "RenderWindow: " << this->GetRenderWindow() << "\n";
  os << indent << "NumberOfDepthPasses: " << this->NumberOfDepthPasses << "\n";
  os << indent << "NumberOfUnseenTriangles: " << this->Internals->Unseen.size() << "\n";
  os << indent << "FilteringActive: " << (this->Internals->Filtering ? "Yes" : "No") << "\n";
  os << indent << "UploadedBytes: " << this->UploadedBytes << "\n";
}
