/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureSceneSurfaces.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureSceneSurfaces.h"

#include "vtkApertureCellCheck.h"
#include "vtkApertureGridSurface.h"
#include "vtkApertureMeshSurface.h"
#include "vtkApertureRayOffsets.h"
#include "vtkApertureSurface.h"

#include "vtkCellArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPoints.h"
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
    if (r.Ghosts)
    {
      vtkApertureSurface::ExpandBounds(r.Ghosts, bounds);
    }
  }
  for (vtkPolyData* occluder : occluders)
  {
    vtkApertureSurface::ExpandBounds(occluder, bounds);
  }
  vtkApertureSurface::OriginOf(bounds, origin);
}

// The input's polygons and strips, then the ghosts', on the input's points and then the ghosts'
// (double precision holds both exactly).
vtkSmartPointer<vtkPolyData> WithGhosts(vtkPolyData* input, vtkPolyData* ghosts)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const vtkIdType n = input->GetNumberOfPoints();
  points->SetNumberOfPoints(n + ghosts->GetNumberOfPoints());
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    points->SetPoint(i, i < n ? input->GetPoint(i) : ghosts->GetPoint(i - n));
  }
  auto merged = vtkSmartPointer<vtkPolyData>::New();
  merged->SetPoints(points);
  vtkNew<vtkCellArray> polys, strips;
  std::vector<vtkIdType> ids;
  for (vtkPolyData* part : { input, ghosts })
  {
    const vtkIdType shift = part == input ? 0 : n;
    vtkApertureMeshSurface::ForEachPolygonOrStrip(part,
      [&](vtkIdType npts, const vtkIdType* cell, bool strip)
      {
        ids.assign(cell, cell + npts);
        for (vtkIdType& id : ids)
        {
          id += shift;
        }
        (strip ? strips : polys)->InsertNextCell(npts, ids.data());
      });
  }
  merged->SetPolys(polys);
  merged->SetStrips(strips);
  return merged;
}

// A polydata receiver's surface: with its ghost cells where it has them and no normals of its
// own (the ghosts bring none), mapping only its own points.
bool SetMesh(const Receiver& r, const double origin[3], double featureAngle, std::string& error)
{
  auto* poly = vtkPolyData::SafeDownCast(r.Input);
  if (!r.Ghosts || vtkApertureSurface::GivenNormals(poly) ||
    !vtkApertureCellCheck::FindBadCell(poly).empty())
  {
    return vtkApertureMeshSurface::Set(*r.Surface, poly, origin, featureAngle, error);
  }
  if (!vtkApertureMeshSurface::Set(
        *r.Surface, WithGhosts(poly, r.Ghosts), origin, featureAngle, error))
  {
    return false;
  }
  r.Surface->KeepInputs(poly);
  return true;
}
}

//------------------------------------------------------------------------------
bool vtkApertureSceneSurfaces::Build(const std::vector<Receiver>& receivers,
  const std::vector<vtkPolyData*>& occluders, const Settings& settings,
  std::vector<vtkApertureSurface>& occluderSurfaces, std::string& error)
{
  if (!(settings.RayOffset >= 0.0)) // the filters' setters clamp it, but let NaN through
  {
    error = "RayOffset is not a number.";
    return false;
  }
  double origin[3];
  SceneOrigin(receivers, occluders, settings.HeightScale, origin);
  std::string problem;
  for (const Receiver& r : receivers)
  {
    auto* image = vtkImageData::SafeDownCast(r.Input);
    const bool ok = image ? vtkApertureGridSurface::Set(
                              *r.Surface, image, r.Heights, settings.HeightScale, origin, problem)
                          : SetMesh(r, origin, settings.FeatureAngle, problem);
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
bool vtkApertureSceneSurfaces::Build(vtkPolyData* input, vtkPolyData* ghosts,
  const std::vector<vtkPolyData*>& occluders, const Settings& settings,
  vtkApertureSurface& receivers, std::vector<vtkApertureSurface>& occluderSurfaces,
  std::string& error)
{
  Receiver receiver;
  receiver.Input = input;
  receiver.Ghosts = ghosts;
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
