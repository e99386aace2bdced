/*=========================================================================

  Program:   ApertureLighting
  Module:    TestApertureRayScene.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkApertureRayScene gives Embree the triangles without the hit filter either as runs over the
// surface's own index buffer (one geometry each) or copied into one geometry. Both must block
// the same rays, ray by ray: on a rough surface, whose filtered triangles are scattered into
// thousands of runs (which the default copies), and on a smooth one (which the default shares).
// Also which BVH AUTOMATIC builds for a number of triangles.

#include "vtkApertureRayPacket.h"
#include "vtkApertureRaySampler.h"
#include "vtkApertureRayScene.h"
#include "vtkApertureSceneSurfaces.h"
#include "vtkApertureSurface.h"

#include "vtkCellArray.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <iostream>
#include <limits>
#include <string>
#include <unistd.h>
#include <vector>

namespace
{
constexpr int Rays = 32;

// n x n quads over a unit spacing, heights uniform in [0, amplitude] from a seeded sequence.
vtkSmartPointer<vtkPolyData> Grid(int n, double amplitude)
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(7);
  vtkNew<vtkPoints> points;
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      random->Next();
      points->InsertNextPoint(i, j, amplitude * random->GetValue());
    }
  }
  vtkNew<vtkCellArray> quads;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const vtkIdType a = j * (n + 1) + i;
      const vtkIdType quad[4] = { a, a + 1, a + n + 2, a + n + 1 };
      quads->InsertNextCell(4, quad);
    }
  }
  auto grid = vtkSmartPointer<vtkPolyData>::New();
  grid->SetPoints(points);
  grid->SetPolys(quads);
  return grid;
}

struct Traced
{
  std::vector<char> Visible; // per ray of each valid point
  vtkIdType Filtered = 0;
  vtkIdType Shared = 0;
};

// The rays of every valid point whose x lies in [xmin, xmax], of length `tfar`, in a scene that
// shares up to `maximumSharedRuns` runs and holds the triangles in `keep` (all if empty).
bool Trace(const vtkApertureSurface& surface, vtkIdType maximumSharedRuns, Traced& traced,
  const std::vector<unsigned char>& keep = {}, float tfar = std::numeric_limits<float>::infinity(),
  double xmin = -1e300, double xmax = 1e300)
{
  vtkApertureRayScene scene;
  scene.SetMaximumSharedRuns(maximumSharedRuns);
  if (!keep.empty())
  {
    scene.KeepOnly(surface, keep);
  }
  if (!scene.Build(surface, {}))
  {
    std::cerr << "FAIL Embree: " << scene.GetError() << "\n";
    return false;
  }
  traced.Filtered = scene.GetNumberOfFilteredTriangles();
  traced.Shared = scene.GetNumberOfSharedRuns();
  const vtkApertureRaySampler sampler(Rays, 1, false);
  vtkApertureRayPacket packet(scene, surface);
  vtkApertureRaySampler::Point point;
  for (vtkIdType id = 0; id < surface.GetNumberOfPoints(); ++id)
  {
    const double x = surface.Vertices[3 * size_t(surface.PointVertex[id])] + surface.Origin[0];
    if (!surface.Valid[id] || x < xmin || x > xmax)
    {
      continue;
    }
    sampler.Begin(surface.GetNormal(id), surface.Key[id], point);
    for (int first = 0; first < Rays; first += vtkApertureRayPacket::Lanes)
    {
      for (int lane = 0; lane < vtkApertureRayPacket::Lanes; ++lane)
      {
        float d[3];
        sampler.Direction(point, first + lane, d);
        packet.Set(lane, id, d, tfar);
      }
      packet.Trace();
      for (int lane = 0; lane < vtkApertureRayPacket::Lanes; ++lane)
      {
        traced.Visible.push_back(packet.Visible(lane) ? 1 : 0);
      }
    }
  }
  return true;
}

// Shared and copied runs block the same rays; the default shares them or not as `shares` says.
bool Compare(const char* name, vtkPolyData* grid, bool shares)
{
  vtkApertureSceneSurfaces::Settings settings;
  vtkApertureSurface surface;
  std::vector<vtkApertureSurface> none;
  std::string error;
  if (!vtkApertureSceneSurfaces::Build(grid, nullptr, {}, settings, surface, none, error))
  {
    std::cerr << "FAIL " << name << ": " << error << "\n";
    return false;
  }
  Traced shared, copied, automatic;
  if (!Trace(surface, std::numeric_limits<vtkIdType>::max(), shared) ||
    !Trace(surface, 0, copied) || !Trace(surface, 1024, automatic))
  {
    return false;
  }
  const double blocked = 1.0 -
    static_cast<double>(std::count(shared.Visible.begin(), shared.Visible.end(), 1)) /
      std::max<size_t>(1, shared.Visible.size());
  std::cout << name << ": " << shared.Filtered << " of " << surface.GetNumberOfTriangles()
            << " triangles filtered, " << shared.Shared << " runs, " << shared.Visible.size()
            << " rays, " << blocked << " blocked; the default shares " << automatic.Shared << "\n";
  bool ok = true;
  auto check = [&ok, name](bool condition, const char* what)
  {
    if (!condition)
    {
      std::cerr << "FAIL " << name << ": " << what << "\n";
      ok = false;
    }
  };
  check(shared.Visible == copied.Visible, "shared and copied runs block different rays");
  check(automatic.Visible == copied.Visible, "the default blocks other rays");
  check(copied.Shared == 0 && shared.Shared > 0, "the runs were not shared, or not copied");
  check((automatic.Shared > 0) == shares, "the default shares where it should copy, or not");
  check(blocked > 0.05 && blocked < 0.95, "too few rays blocked, or too few visible");
  check(shared.Filtered > 0, "no triangle got the hit filter");
  return ok;
}

// A scene of only the triangles within reach of some points answers those points' rays of that
// reach as the whole scene does, and lets through rays that only left-out triangles blocked.
bool KeepOnlyReachable(vtkPolyData* grid)
{
  vtkApertureSceneSurfaces::Settings settings;
  vtkApertureSurface surface;
  std::vector<vtkApertureSurface> none;
  std::string error;
  if (!vtkApertureSceneSurfaces::Build(grid, nullptr, {}, settings, surface, none, error))
  {
    std::cerr << "FAIL keep only: " << error << "\n";
    return false;
  }
  // The points with x <= 20 and rays of 5 spacings (the offsets are far below a spacing): every
  // triangle they can hit has a corner with x < 26.
  const float reach = 5.0f;
  std::vector<unsigned char> keep(surface.GetNumberOfTriangles());
  for (size_t t = 0; t < keep.size(); ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      const size_t v = surface.Triangles[3 * t + c];
      keep[t] = keep[t] || surface.Vertices[3 * v] + surface.Origin[0] < 26.0;
    }
  }
  Traced all, kept, allFar, keptFar;
  if (!Trace(surface, 1024, all, {}, reach, -1.0, 20.0) ||
    !Trace(surface, 1024, kept, keep, reach, -1.0, 20.0) ||
    !Trace(surface, 1024, allFar, {}, std::numeric_limits<float>::infinity(), 40.0) ||
    !Trace(surface, 1024, keptFar, keep, std::numeric_limits<float>::infinity(), 40.0))
  {
    return false;
  }
  auto blocked = [](const Traced& t) { return std::count(t.Visible.begin(), t.Visible.end(), 0); };
  std::cout << "keep only: " << std::count(keep.begin(), keep.end(), 1) << " of " << keep.size()
            << " triangles; near rays blocked " << blocked(all) << " / " << blocked(kept)
            << ", far rays blocked " << blocked(allFar) << " / " << blocked(keptFar) << "\n";
  bool ok = all.Visible == kept.Visible && blocked(all) > 0;
  ok = ok && blocked(keptFar) < blocked(allFar) && kept.Filtered < all.Filtered;
  if (!ok)
  {
    std::cerr << "FAIL keep only: the rays within reach differ, or nothing was left out\n";
  }
  return ok;
}

// AUTOMATIC builds the fast BVH while about 128 bytes a triangle stay under an eighth of this
// machine's memory (or less, a container's limit), the compact one above; COMPACT and FAST are
// what they say.
bool ChooseStructure()
{
  using Scene = vtkApertureRayScene;
  const vtkIdType threshold = Scene::GetCompactThreshold();
  const double memory = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGESIZE));
  const double bytes = memory / 8.0 / static_cast<double>(threshold);
  std::cout << "compact BVH above " << threshold << " triangles (" << memory / (1 << 30)
            << " GiB: " << bytes << " bytes a triangle in an eighth)\n";
  const bool ok = bytes > 127.0 && threshold >= 1000000 &&
    !Scene::IsCompact(Scene::AUTOMATIC, threshold) &&
    Scene::IsCompact(Scene::AUTOMATIC, threshold + 1) && Scene::IsCompact(Scene::COMPACT, 1) &&
    !Scene::IsCompact(Scene::FAST, 4 * threshold);
  if (!ok)
  {
    std::cerr << "FAIL the BVH chosen for a number of triangles\n";
  }
  return ok;
}
}

int TestApertureRayScene(int, char*[])
{
  // Heights of 3 spacings: steep folds everywhere, the filtered triangles in thousands of runs.
  bool ok = Compare("rough", Grid(80, 3.0), false);
  // Heights of 1 spacing: a gentler surface, whose few filtered triangles leave long runs.
  ok = Compare("smooth", Grid(80, 1.0), true) && ok;
  ok = KeepOnlyReachable(Grid(80, 3.0)) && ok;
  ok = ChooseStructure() && ok;
  return ok ? 0 : 1;
}
