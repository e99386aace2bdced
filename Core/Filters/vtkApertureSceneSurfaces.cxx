/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureSceneSurfaces.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureSceneSurfaces.h"

#include "vtkApertureGridSurface.h"
#include "vtkApertureMeshSurface.h"
#include "vtkApertureRayOffsets.h"
#include "vtkApertureSurface.h"

#include "vtkImageData.h"
#include "vtkPolyData.h"

namespace
{
using Receiver = vtkApertureSceneSurfaces::Receiver;

// The local origin: the middle of every receiver's and occluder's finite points.
void SceneOrigin(const std::vector<Receiver>& receivers, const std::vector<vtkPolyData*>& occluders,
  double heightScale, double origin[3])
{
  double bounds[6];
  vtkApertureSurface::InitializeBounds(bounds);
  for (const Receiver& r : receivers)
  {
    if (auto* image = vtkImageData::SafeDownCast(r.Input))
    {
      vtkApertureGridSurface::ExpandBounds(image, r.Heights, heightScale, bounds);
    }
    else
    {
      vtkApertureSurface::ExpandBounds(vtkPolyData::SafeDownCast(r.Input), bounds);
    }
  }
  for (vtkPolyData* occluder : occluders)
  {
    vtkApertureSurface::ExpandBounds(occluder, bounds);
  }
  vtkApertureSurface::OriginOf(bounds, origin);
}
}

//------------------------------------------------------------------------------
bool vtkApertureSceneSurfaces::Build(const std::vector<Receiver>& receivers,
  const std::vector<vtkPolyData*>& occluders, const Settings& settings,
  std::vector<vtkApertureSurface>& occluderSurfaces, std::string& error)
{
  double origin[3];
  SceneOrigin(receivers, occluders, settings.HeightScale, origin);
  std::string problem;
  for (const Receiver& r : receivers)
  {
    auto* image = vtkImageData::SafeDownCast(r.Input);
    const bool ok = image
      ? vtkApertureGridSurface::Set(
          *r.Surface, image, r.Heights, settings.HeightScale, origin, problem)
      : vtkApertureMeshSurface::Set(
          *r.Surface, vtkPolyData::SafeDownCast(r.Input), origin, settings.FeatureAngle, problem);
    if (!ok)
    {
      error = "Cannot use the input: " + problem + ".";
      return false;
    }
    vtkApertureRayOffsets::Set(*r.Surface, settings.RayOffset);
  }
  occluderSurfaces = std::vector<vtkApertureSurface>(occluders.size());
  for (size_t i = 0; i < occluders.size(); ++i)
  {
    if (!vtkApertureMeshSurface::Set(
          occluderSurfaces[i], occluders[i], origin, settings.FeatureAngle, problem))
    {
      error = "Cannot use occluder " + std::to_string(i) + ": " + problem + ".";
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkApertureSceneSurfaces::Build(vtkPolyData* input, const std::vector<vtkPolyData*>& occluders,
  const Settings& settings, vtkApertureSurface& receivers,
  std::vector<vtkApertureSurface>& occluderSurfaces, std::string& error)
{
  Receiver receiver;
  receiver.Input = input;
  receiver.Surface = &receivers;
  if (!Build({ receiver }, occluders, settings, occluderSurfaces, error))
  {
    return false;
  }
  vtkIdType triangles = receivers.GetNumberOfTriangles();
  for (const vtkApertureSurface& occluder : occluderSurfaces)
  {
    triangles += occluder.GetNumberOfTriangles();
  }
  if (triangles == 0)
  {
    error = "Neither the input nor the occluders have polygons or triangle strips: nothing casts "
            "shadows and points have no normals.";
    return false;
  }
  return true;
}
