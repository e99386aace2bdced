/*=========================================================================

  Program:   ApertureLighting
  Module:    TestApertureLightingMapperPixels.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkApertureLightingMapper, pixel by pixel: camera-facing quads, each with its own normal, bent
// normal and aperture radius, lit by directional lights of several sizes and by a sphere light,
// with and without sky, in every shading model. Every tested pixel must match the CPU
// evaluation of the same shading equation (vtkSphericalCap) within 1/255.

#include "vtkApertureLightingMapper.h"
#include "vtkApertureTestHarness.h"
#include "vtkSphericalCap.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkEnvironmentMap.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

namespace
{
using vtkApertureTest::Check;

constexpr double Pi = vtkMath::Pi();
constexpr int Grid = 11; // quads per side
constexpr int Size = 30; // pixels per quad side
constexpr int Window = Grid * Size;

struct Quad
{
  double Normal[3], Bent[3], Radius;
};

// Random apertures: normals tilted up to 60 degrees toward the camera's side, bent normals up to
// 80 degrees from the normal, radii over [0, pi/2].
std::vector<Quad> MakeQuads()
{
  vtkMath::RandomSeed(5);
  std::vector<Quad> quads(Grid * Grid);
  for (Quad& q : quads)
  {
    const double tilt = vtkMath::Random(0.0, 1.05), turn = vtkMath::Random(0.0, 2.0 * Pi);
    const double n[3] = { std::sin(tilt) * std::cos(turn), std::sin(tilt) * std::sin(turn),
      std::cos(tilt) };
    double t[3], b[3];
    vtkMath::Perpendiculars(n, t, b, vtkMath::Random(0.0, 2.0 * Pi));
    const double bendAngle = vtkMath::Random(0.0, 1.4);
    for (int k = 0; k < 3; ++k)
    {
      q.Normal[k] = n[k];
      q.Bent[k] = std::cos(bendAngle) * n[k] + std::sin(bendAngle) * t[k];
    }
    q.Radius = vtkMath::Random(0.0, 0.5 * Pi);
  }
  return quads;
}

// One polydata of Grid x Grid quads filling the window, 4 points each with the quad's data.
vtkSmartPointer<vtkPolyData> MakeMesh(const std::vector<Quad>& quads)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkFloatArray> normals, bent, radius;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  bent->SetName("BentNormal");
  bent->SetNumberOfComponents(3);
  radius->SetName("ApertureRadius");
  for (int j = 0; j < Grid; ++j)
  {
    for (int i = 0; i < Grid; ++i)
    {
      const Quad& q = quads[i + Grid * j];
      const double x0 = -0.5 * Window + Size * i, y0 = -0.5 * Window + Size * j;
      const vtkIdType first = points->GetNumberOfPoints();
      const double corners[4][2] = { { x0, y0 }, { x0 + Size, y0 }, { x0 + Size, y0 + Size },
        { x0, y0 + Size } };
      for (const auto& c : corners)
      {
        points->InsertNextPoint(c[0], c[1], 0.0);
        normals->InsertNextTuple(q.Normal);
        bent->InsertNextTuple(q.Bent);
        radius->InsertNextValue(q.Radius);
      }
      const vtkIdType quad[4] = { first, first + 1, first + 2, first + 3 };
      cells->InsertNextCell(4, quad);
    }
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(cells);
  mesh->GetPointData()->SetNormals(normals);
  mesh->GetPointData()->AddArray(bent);
  mesh->GetPointData()->AddArray(radius);
  return mesh;
}

struct Scene
{
  int Shading;     // vtkSphericalCap::Shading
  int Lambert;     // vtkSphericalCap::Lambert
  double Light[3]; // direction toward a directional light, or a sphere light's centre
  double Radius;   // angular radius (directional) or world radius (positional)
  bool Positional;
  double Sky;
  vtkEnvironmentMap* Environment; // the sky's, or nullptr for a uniform sky
};

// The expected 0..1 value of a pixel at world position p (z = 0) of quad q.
double Expected(const Scene& s, const Quad& q, const double p[3], double intensity)
{
  double l[3] = { s.Light[0], s.Light[1], s.Light[2] };
  double rl = s.Radius;
  if (s.Positional)
  {
    vtkMath::Subtract(s.Light, p, l);
    rl = vtkSphericalCap::SphereLightCapRadius(s.Radius, vtkMath::Norm(l));
  }
  const double t =
    vtkSphericalCap::LightTransfer(s.Shading, s.Lambert, q.Normal, q.Bent, q.Radius, l, rl);
  const double covered = vtkSphericalCap::LightCoverage(s.Shading, q.Bent, q.Radius, l, rl);
  double bent[3] = { q.Bent[0], q.Bent[1], q.Bent[2] };
  vtkMath::Normalize(bent);
  double sky = vtkSphericalCap::SkyTransfer(q.Radius, covered, vtkMath::Dot(q.Normal, bent), true);
  if (s.Environment)
  {
    // The environment's radiance over the aperture, cosine-weighted around the bent normal, over
    // pi, less the share the light covers (red, the channel compared).
    const double rp = std::min(q.Radius, 0.5 * Pi);
    double e[3];
    s.Environment->CapIrradiance(bent, rp, e);
    const double area = vtkSphericalCap::SolidAngleFromCapRadius(rp);
    sky = e[0] / Pi * (area > 0.0 ? std::max(0.0, 1.0 - covered / area) : 0.0) *
      std::min(1.0, std::max(0.0, vtkMath::Dot(q.Normal, bent)));
  }
  return std::min(1.0, intensity * t + s.Sky * sky);
}
}

int TestApertureLightingMapperPixels(int, char*[])
{
  const std::vector<Quad> quads = MakeQuads();
  auto mesh = MakeMesh(quads);

  vtkNew<vtkApertureLightingMapper> mapper;
  mapper->SetInputData(mesh);
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetAmbient(0.0);
  actor->GetProperty()->SetDiffuse(1.0);
  actor->GetProperty()->SetSpecular(0.0);
  actor->GetProperty()->SetColor(1.0, 1.0, 1.0);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.0, 0.0, 0.0);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetParallelScale(0.5 * Window);
  camera->SetPosition(0, 0, 1000);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetClippingRange(500, 1500);
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetColor(1.0, 1.0, 1.0);
  const double intensity = 0.8;
  light->SetIntensity(intensity);
  renderer->AddLight(light);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(Window, Window);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);

  const double tilted[3] = { 0.45, -0.3, 0.84 };
  const double grazing[3] = { 0.9, 0.1, 0.2 };
  std::vector<Scene> scenes;
  for (int shading : { vtkSphericalCap::EXACT, vtkSphericalCap::SMOOTHSTEP,
         vtkSphericalCap::SIMPLIFIED, vtkSphericalCap::BENT_NORMAL })
  {
    for (double radius : { 0.0047, 0.1, 0.5 })
    {
      scenes.push_back({ shading, vtkSphericalCap::CENTROID, { tilted[0], tilted[1], tilted[2] },
        radius, false, 0.0, nullptr });
    }
    scenes.push_back({ shading, vtkSphericalCap::CENTROID, { grazing[0], grazing[1], grazing[2] },
      0.2, false, 0.25, nullptr });
    scenes.push_back(
      { shading, vtkSphericalCap::CENTROID, { 60.0, -40.0, 150.0 }, 40.0, true, 0.0, nullptr });
  }
  for (double radius : { 0.0047, 0.3 })
  {
    scenes.push_back({ vtkSphericalCap::EXACT, vtkSphericalCap::MOMENT,
      { tilted[0], tilted[1], tilted[2] }, radius, false, 0.25, nullptr });
  }
  // A sky from an environment: a smooth synthetic one (brighter toward the zenith, with a broad
  // warm glow), turned 40 degrees, under a dimmed sun.
  vtkNew<vtkImageData> glow;
  glow->SetDimensions(256, 128, 1);
  vtkNew<vtkFloatArray> radiance;
  radiance->SetNumberOfComponents(3);
  radiance->SetNumberOfTuples(256 * 128);
  for (int j = 0; j < 128; ++j)
  {
    for (int i = 0; i < 256; ++i)
    {
      const double u = (i + 0.5) / 256, v = (j + 0.5) / 128;
      const double blob = std::exp(-(std::pow(u - 0.3, 2) + std::pow(v - 0.7, 2)) / 0.01);
      radiance->SetTuple3(j * 256 + i, 0.2 + 0.8 * v * v + 1.5 * blob, 0.3 + 0.5 * v, 0.5);
    }
  }
  glow->GetPointData()->SetScalars(radiance);
  vtkNew<vtkEnvironmentMap> environment;
  environment->SetImage(glow);
  environment->SetUpAxisToY();
  environment->SetAzimuth(40.0);
  for (int shading : { vtkSphericalCap::EXACT, vtkSphericalCap::SMOOTHSTEP })
  {
    scenes.push_back({ shading, vtkSphericalCap::CENTROID, { tilted[0], tilted[1], tilted[2] }, 0.3,
      false, 0.8, environment });
  }

  vtkNew<vtkUnsignedCharArray> pixels;
  for (const Scene& s : scenes)
  {
    mapper->SetShadingMode(s.Shading);
    if (s.Lambert == vtkSphericalCap::MOMENT)
    {
      mapper->SetLambertModeToMoment();
    }
    else
    {
      mapper->SetLambertModeToCentroid();
    }
    mapper->SetSkyIntensity(s.Sky);
    mapper->SetSkyColor(1.0, 1.0, 1.0);
    mapper->SetSkyEnvironment(s.Environment);
    light->SetPositional(s.Positional);
    light->SetConeAngle(180.0);
    if (s.Positional)
    {
      light->SetPosition(s.Light);
      light->SetFocalPoint(0, 0, 0);
    }
    else
    {
      light->SetPosition(s.Light);
      light->SetFocalPoint(0, 0, 0);
    }
    vtkApertureLightingMapper::SetLightRadius(light, s.Radius);
    window->Render();
    window->GetPixelData(0, 0, Window - 1, Window - 1, 1, pixels, 0);

    // Interior pixels of every quad, away from its edges.
    double worst = 0.0;
    int tested = 0;
    for (int j = 0; j < Grid; ++j)
    {
      for (int i = 0; i < Grid; ++i)
      {
        for (int py = Size * j + 3; py < Size * (j + 1) - 3; py += 4)
        {
          for (int px = Size * i + 3; px < Size * (i + 1) - 3; px += 4)
          {
            const double p[3] = { -0.5 * Window + px + 0.5, -0.5 * Window + py + 0.5, 0.0 };
            const double want = 255.0 * Expected(s, quads[i + Grid * j], p, intensity);
            const double got = pixels->GetValue(3 * (px + Window * py));
            worst = std::max(worst, std::abs(got - want));
            ++tested;
          }
        }
      }
    }
    std::cout << "model " << s.Shading << (s.Lambert ? " moment" : "")
              << (s.Positional ? ", sphere light R=" : ", sun r=") << s.Radius << ", sky " << s.Sky
              << (s.Environment ? " from an environment" : "") << ": " << tested
              << " pixels, max |GPU - CPU| = " << worst << "/255\n";
    // 0.5 for the 8-bit rounding, 0.5 for single precision; the environment sky is looked up in a
    // table of 64 x 32 axes and 16 radii, against exact quadrature on the CPU.
    const double tolerance = s.Environment ? 1.5 : 1.0;
    Check(worst <= tolerance,
      "pixels differ from the CPU shading by more than the tolerance (/255)", worst, tolerance);
  }
  return vtkApertureTest::Result();
}
