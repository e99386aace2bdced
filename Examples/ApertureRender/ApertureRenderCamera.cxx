/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderCamera.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "ApertureRenderCamera.h"

#include "vtkApertureMeshSurface.h"
#include "vtkApertureSurface.h"
#include "vtkCellArray.h"
#include "vtkMath.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace ApertureRender
{
namespace
{
// A mesh's triangles as area-weighted normals and centroids.
struct Faces
{
  std::vector<std::array<double, 3>> Normals, Centroids; // normals are area x unit normal
  double Area = 0.0;
  double Bounds[6];
};

Faces FacesOf(vtkPolyData* mesh)
{
  Faces faces;
  vtkApertureSurface::InitializeBounds(faces.Bounds);
  vtkApertureSurface::ExpandBounds(mesh, faces.Bounds);
  std::vector<vtkIdType> local;
  vtkApertureMeshSurface::ForEachPolygonOrStrip(mesh,
    [&](vtkIdType npts, const vtkIdType* ids, bool strip)
    {
      local.clear();
      vtkApertureMeshSurface::Triangulate(npts, ids, strip, nullptr, nullptr, local);
      for (size_t t = 0; t < local.size(); t += 3)
      {
        double p[3][3], e1[3], e2[3], n[3];
        for (int k = 0; k < 3; ++k)
        {
          mesh->GetPoint(ids[local[t + k]], p[k]);
        }
        vtkMath::Subtract(p[1], p[0], e1);
        vtkMath::Subtract(p[2], p[0], e2);
        vtkMath::Cross(e1, e2, n);
        const double area = 0.5 * vtkMath::Norm(n);
        if (!(area > 0.0) || !std::isfinite(area))
        {
          continue;
        }
        faces.Normals.push_back({ 0.5 * n[0], 0.5 * n[1], 0.5 * n[2] });
        faces.Centroids.push_back({ (p[0][0] + p[1][0] + p[2][0]) / 3.0,
          (p[0][1] + p[1][1] + p[2][1]) / 3.0, (p[0][2] + p[1][2] + p[2][2]) / 3.0 });
        faces.Area += area;
      }
    });
  return faces;
}

// The area of faces looking down along -axis*sign within 2% of the extent of the bottom.
double BaseArea(const Faces& faces, int axis, double sign)
{
  const double lo = faces.Bounds[2 * axis], hi = faces.Bounds[2 * axis + 1];
  const double bottom = sign > 0.0 ? lo : hi;
  const double margin = 0.02 * (hi - lo);
  double area = 0.0;
  for (size_t f = 0; f < faces.Normals.size(); ++f)
  {
    const double size = vtkMath::Norm(faces.Normals[f].data());
    const double down = -sign * faces.Normals[f][axis] / size;
    if (down > std::cos(vtkMath::RadiansFromDegrees(10.0)) &&
      std::abs(faces.Centroids[f][axis] - bottom) <= margin)
    {
      area += size;
    }
  }
  return area;
}

std::string AxisName(int axis, double sign)
{
  return std::string(sign > 0.0 ? "+" : "-") + static_cast<char>('x' + axis);
}
}

double CompassAzimuth(double azimuth)
{
  const double turned = std::fmod(azimuth, 360.0);
  return turned < 0.0 ? turned + 360.0 : turned;
}

std::string CompassName(double azimuth)
{
  static const char* const names[] = { "N", "NNE", "NE", "ENE", "E", "ESE", "SE", "SSE", "S", "SSW",
    "SW", "WSW", "W", "WNW", "NW", "NNW" };
  const double turned = CompassAzimuth(azimuth + 11.25);
  return names[std::min(15, static_cast<int>(turned / 22.5))];
}

void CompassOf(const std::string& up, double east[3], double north[3], double upward[3])
{
  const int axis = up[1] - 'x';
  const double sign = up[0] == '-' ? -1.0 : 1.0;
  for (int k = 0; k < 3; ++k)
  {
    upward[k] = k == axis ? sign : 0.0;
    east[k] = k == (axis == 0 ? 1 : 0) ? 1.0 : 0.0;
  }
  vtkMath::Cross(upward, east, north);
}

MeshView ChooseView(vtkPolyData* mesh, const std::string& up)
{
  const Faces faces = FacesOf(mesh);
  MeshView view{ up.empty() ? "+y" : up, 180.0,
    up.empty() ? "no flat base found, so +y, the OBJ convention; --up +z for z-up scans and CAD"
               : "given with --up" };
  if (up.empty())
  {
    // A flat base of at least 0.5% of the area, in the order y, z, x of conventions.
    double best = 0.005 * faces.Area;
    for (const int axis : { 1, 2, 0 })
    {
      for (const double sign : { 1.0, -1.0 })
      {
        const double area = BaseArea(faces, axis, sign);
        if (area > best)
        {
          best = area;
          view.Up = AxisName(axis, sign);
          view.UpReason = "opposite the flat base it stands on; --up to change";
        }
      }
    }
  }
  // Look along the thinner of the two horizontal axes, from the side the surface faces most.
  const int upAxis = view.Up[1] - 'x';
  const int a = (upAxis + 1) % 3, b = (upAxis + 2) % 3;
  const double extentA = faces.Bounds[2 * a + 1] - faces.Bounds[2 * a];
  const double extentB = faces.Bounds[2 * b + 1] - faces.Bounds[2 * b];
  const int along = extentA < extentB ? a : b;
  double facing = 0.0;
  for (const auto& n : faces.Normals)
  {
    facing += n[along];
  }
  double sign = 0.0;
  if (std::abs(facing) > 0.05 * faces.Area)
  {
    sign = facing > 0.0 ? 1.0 : -1.0;
  }
  else
  {
    // The conventional fronts: +z for y up (OBJ, ParaView), -y for z up (scanners, CAD).
    sign = (along == 1 && upAxis == 2) ? -1.0 : 1.0;
  }
  double east[3], north[3], upward[3], eye[3] = { 0.0, 0.0, 0.0 };
  CompassOf(view.Up, east, north, upward);
  eye[along] = sign;
  view.Azimuth = CompassAzimuth(
    vtkMath::DegreesFromRadians(std::atan2(vtkMath::Dot(eye, east), vtkMath::Dot(eye, north))));
  return view;
}
}
