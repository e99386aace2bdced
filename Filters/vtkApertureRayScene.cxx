/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureRayScene.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureRayScene.h"

#include "vtkApertureSurface.h"

namespace
{
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
bool vtkApertureRayScene::Initialize(const std::string& configuration, bool compact)
{
  this->Device = rtcNewDevice(configuration.c_str());
  if (!this->Device)
  {
    // The callback cannot be installed before the device exists.
    std::lock_guard<std::mutex> lock(this->ErrorMutex);
    this->Error = "could not create a device with the configuration \"" + configuration + "\" (" +
      ErrorName(rtcGetDeviceError(nullptr)) + ")";
    return false;
  }
  rtcSetDeviceErrorFunction(this->Device, &vtkApertureRayScene::ReportError, this);
  this->Scene = rtcNewScene(this->Device);
  if (this->Scene)
  {
    // Robust traversal does not let rays slip between triangles sharing an edge.
    rtcSetSceneFlags(this->Scene,
      static_cast<RTCSceneFlags>(RTC_SCENE_FLAG_ROBUST | (compact ? RTC_SCENE_FLAG_COMPACT : 0)));
    rtcSetSceneBuildQuality(this->Scene, RTC_BUILD_QUALITY_MEDIUM);
  }
  return this->Scene && !this->Failed();
}

//------------------------------------------------------------------------------
bool vtkApertureRayScene::AddSurface(const vtkApertureSurface& surface)
{
  const size_t triangles = surface.Triangles.size() / 3;
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
    surface.Points.data(), 0, 3 * sizeof(float), surface.GetNumberOfPoints());
  rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
    surface.Triangles.data(), 0, 3 * sizeof(std::uint32_t), triangles);
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(this->Scene, geometry);
  rtcReleaseGeometry(geometry);
  return !this->Failed();
}

//------------------------------------------------------------------------------
bool vtkApertureRayScene::Commit()
{
  rtcCommitScene(this->Scene);
  return !this->Failed();
}

//------------------------------------------------------------------------------
bool vtkApertureRayScene::Build(
  const vtkApertureSurface& receivers, const std::vector<vtkApertureSurface>& occluders)
{
  bool built = this->Initialize(std::string(), false) && this->AddSurface(receivers);
  for (const vtkApertureSurface& occluder : occluders)
  {
    built = built && this->AddSurface(occluder);
  }
  return built && this->Commit();
}
