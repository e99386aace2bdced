/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureRayScene.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureRayScene.h"

#include "vtkApertureRayRisks.h"
#include "vtkApertureSurface.h"
#include "vtkApertureText.h"

#include <algorithm>
#include <atomic>
#include <fstream>
#include <unistd.h>
#include <utility>

namespace
{
// Set when this library's statics are destroyed, at exit: before those of Embree and TBB, which
// were initialised before it (statics are destroyed in the reverse order), and before those of
// libraries loaded earlier, such as ParaView's.
std::atomic<bool> ProcessExiting{ false };
struct ExitWatch
{
  ~ExitWatch() { ProcessExiting = true; }
} TheExitWatch;

std::string ErrorName(RTCError code)
{
  switch (code)
  {
    case RTC_ERROR_NONE:
      return "no error";
    case RTC_ERROR_INVALID_ARGUMENT:
      return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION:
      return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY:
      return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU:
      return "unsupported CPU";
    case RTC_ERROR_CANCELLED:
      return "cancelled";
    default:
      return "unknown error";
  }
}
}

//------------------------------------------------------------------------------
vtkApertureRayScene::~vtkApertureRayScene()
{
  // A scene deleted while the process exits (ParaView deletes its pipelines then) is left to
  // the system: TBB, which Embree's release needs, may be finalised already.
  if (ProcessExiting)
  {
    return;
  }
  if (this->Scene)
  {
    rtcReleaseScene(this->Scene);
  }
  if (this->Device)
  {
    rtcReleaseDevice(this->Device);
  }
}

//------------------------------------------------------------------------------
bool vtkApertureRayScene::IsCompact(int structure, vtkIdType triangles)
{
  return structure == COMPACT || (structure == AUTOMATIC && triangles > GetCompactThreshold());
}

//------------------------------------------------------------------------------
vtkIdType vtkApertureRayScene::GetCompactThreshold()
{
  static const vtkIdType threshold = []()
  {
    const long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGESIZE);
    // Where the memory cannot be read (sysconf fails: -1), an 8 GiB machine's.
    double bytes = pages > 0 && size > 0 ? double(pages) * size : 8.0 * (1 << 30);
    // A container's limit where lower (cgroup v2, then v1; "max" or a huge value: none).
    for (const char* file :
      { "/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes" })
    {
      std::ifstream limit(file);
      double cgroup = 0.0;
      bytes = limit >> cgroup && cgroup > 0.0 ? std::min(bytes, cgroup) : bytes;
    }
    return static_cast<vtkIdType>(bytes / 8.0 / 128.0);
  }();
  return threshold;
}

//------------------------------------------------------------------------------
void vtkApertureRayScene::ReportError(void* self, RTCError code, const char* message)
{
  auto* scene = static_cast<vtkApertureRayScene*>(self);
  std::lock_guard<std::mutex> lock(scene->ErrorMutex);
  if (scene->Error.empty())
  {
    scene->Error = ErrorName(code) + (message ? std::string(": ") + message : std::string());
  }
}

//------------------------------------------------------------------------------
void vtkApertureRayScene::Filter(const RTCFilterFunctionNArguments* args)
{
  const auto* context = reinterpret_cast<const Context*>(args->context);
  const vtkApertureSurface* source = context->Source;
  const auto* geometry = static_cast<const Filtered*>(args->geometryUserPtr);
  const bool own = geometry->Surface == source;
  const unsigned int n = args->N;
  for (unsigned int i = 0; i < n; ++i)
  {
    if (args->valid[i] != -1)
    {
      continue;
    }
    const bool front = RTCRayN_dir_x(args->ray, n, i) * RTCHitN_Ng_x(args->hit, n, i) +
        RTCRayN_dir_y(args->ray, n, i) * RTCHitN_Ng_y(args->hit, n, i) +
        RTCRayN_dir_z(args->ray, n, i) * RTCHitN_Ng_z(args->hit, n, i) <
      0.0f;
    const unsigned int point = RTCRayN_id(args->ray, n, i);
    bool incident = false;
    if (own)
    {
      const std::uint32_t* triangle =
        &source->Triangles[3 * size_t(geometry->Triangles[RTCHitN_primID(args->hit, n, i)])];
      const std::uint32_t vertex = source->PointVertex[point];
      incident = triangle[0] == vertex || triangle[1] == vertex || triangle[2] == vertex;
    }
    const bool near = RTCRayN_tfar(args->ray, n, i) <= source->Near[point];
    const bool blocks = front || (!near && !incident);
    if (!blocks)
    {
      args->valid[i] = 0;
    }
  }
}

//------------------------------------------------------------------------------
std::string vtkApertureRayScene::GetError()
{
  std::lock_guard<std::mutex> lock(this->ErrorMutex);
  return this->Error;
}

//------------------------------------------------------------------------------
bool vtkApertureRayScene::Failed()
{
  return !this->GetError().empty();
}

//------------------------------------------------------------------------------
bool vtkApertureRayScene::Build(const std::vector<const vtkApertureSurface*>& receivers,
  const std::vector<const vtkApertureSurface*>& occluders, int structure,
  const std::string& configuration)
{
  std::vector<const vtkApertureSurface*> surfaces = receivers;
  surfaces.insert(surfaces.end(), occluders.begin(), occluders.end());
  vtkIdType triangles = 0;
  for (const vtkApertureSurface* s : surfaces)
  {
    triangles += s->GetNumberOfTriangles();
  }
  this->Device = rtcNewDevice(configuration.c_str());
  if (!this->Device)
  {
    // The callback cannot be installed before the device exists.
    std::lock_guard<std::mutex> lock(this->ErrorMutex);
    this->Error = "could not create a device with the configuration " +
      vtkApertureText::Quote(configuration) + " (" + ErrorName(rtcGetDeviceError(nullptr)) + ")";
    return false;
  }
  rtcSetDeviceErrorFunction(this->Device, &vtkApertureRayScene::ReportError, this);
  this->Scene = rtcNewScene(this->Device);
  if (!this->Scene || this->Failed())
  {
    return false;
  }
  // Robust traversal does not let rays slip between triangles sharing an edge.
  rtcSetSceneFlags(this->Scene,
    static_cast<RTCSceneFlags>(
      RTC_SCENE_FLAG_ROBUST | (IsCompact(structure, triangles) ? RTC_SCENE_FLAG_COMPACT : 0)));
  rtcSetSceneBuildQuality(this->Scene, RTC_BUILD_QUALITY_MEDIUM);
  const vtkApertureRayRisks risks(receivers);
  bool built = true;
  const std::vector<unsigned char> all;
  for (size_t k = 0; k < surfaces.size() && built; ++k)
  {
    const std::vector<unsigned char>& keep = surfaces[k] == this->KeptSurface ? this->Kept : all;
    built =
      this->AddSurface(*surfaces[k], risks.Find(*surfaces[k], k < receivers.size(), keep), keep);
  }
  if (built)
  {
    rtcCommitScene(this->Scene);
  }
  return built && !this->Failed();
}

//------------------------------------------------------------------------------
void vtkApertureRayScene::KeepOnly(
  const vtkApertureSurface& surface, std::vector<unsigned char> triangles)
{
  this->KeptSurface = &surface;
  this->Kept = std::move(triangles);
}

//------------------------------------------------------------------------------
bool vtkApertureRayScene::Build(const vtkApertureSurface& receivers,
  const std::vector<vtkApertureSurface>& occluders, int structure)
{
  std::vector<const vtkApertureSurface*> others;
  for (const vtkApertureSurface& occluder : occluders)
  {
    others.push_back(&occluder);
  }
  return this->Build({ &receivers }, others, structure);
}

//------------------------------------------------------------------------------
// The plain triangles are mostly long runs between a few filtered ones: each run is a geometry
// over the surface's own index buffer, so that the largest array of a large surface is not
// copied. Where the runs are many (an Embree geometry costs hundreds of bytes), they are copied
// into one geometry instead.
bool vtkApertureRayScene::AddSurface(const vtkApertureSurface& surface,
  const std::vector<unsigned char>& risky, const std::vector<unsigned char>& keep)
{
  std::unique_ptr<Filtered> filtered(new Filtered{ &surface, {}, {} });
  std::vector<std::pair<size_t, size_t>> runs; // first plain triangle, end
  for (size_t t = 0; t < risky.size(); ++t)
  {
    if (!keep.empty() && !keep[t])
    {
      continue; // a gap between runs
    }
    if (risky[t])
    {
      auto& to = filtered->Indices;
      to.insert(to.end(), &surface.Triangles[3 * t], &surface.Triangles[3 * t + 3]);
      filtered->Triangles.push_back(static_cast<std::uint32_t>(t));
    }
    else if (!runs.empty() && runs.back().second == t)
    {
      ++runs.back().second;
    }
    else
    {
      runs.emplace_back(t, t + 1);
    }
  }
  this->FilteredTriangles += static_cast<vtkIdType>(filtered->Triangles.size());
  this->Risky.push_back(std::move(filtered));
  bool added = true;
  if (static_cast<vtkIdType>(runs.size()) <= this->MaximumSharedRuns)
  {
    this->SharedRuns += static_cast<vtkIdType>(runs.size());
    for (const auto& run : runs)
    {
      added = added &&
        this->AddGeometry(
          surface, surface.Triangles.data() + 3 * run.first, run.second - run.first, nullptr);
    }
  }
  else
  {
    std::vector<std::uint32_t> plain;
    for (const auto& run : runs)
    {
      const std::uint32_t* triangles = surface.Triangles.data();
      plain.insert(plain.end(), triangles + 3 * run.first, triangles + 3 * run.second);
    }
    this->Plain.push_back(std::move(plain));
    added =
      this->AddGeometry(surface, this->Plain.back().data(), this->Plain.back().size() / 3, nullptr);
  }
  const std::vector<std::uint32_t>& indices = this->Risky.back()->Indices;
  return added &&
    this->AddGeometry(surface, indices.data(), indices.size() / 3, this->Risky.back().get());
}

//------------------------------------------------------------------------------
bool vtkApertureRayScene::AddGeometry(const vtkApertureSurface& surface,
  const std::uint32_t* indices, size_t triangles, Filtered* filtered)
{
  if (triangles == 0)
  {
    return true;
  }
  RTCGeometry geometry = rtcNewGeometry(this->Device, RTC_GEOMETRY_TYPE_TRIANGLE);
  if (!geometry)
  {
    return false;
  }
  rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
    surface.Vertices.data(), 0, 3 * sizeof(float), surface.GetNumberOfVertices());
  rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, indices, 0,
    3 * sizeof(std::uint32_t), triangles);
  if (filtered)
  {
    rtcSetGeometryUserData(geometry, filtered);
    rtcSetGeometryOccludedFilterFunction(geometry, &vtkApertureRayScene::Filter);
  }
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(this->Scene, geometry);
  rtcReleaseGeometry(geometry);
  return !this->Failed();
}
