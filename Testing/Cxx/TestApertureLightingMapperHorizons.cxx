/*=========================================================================

  Program:   ApertureLighting
  Module:    TestApertureLightingMapperHorizons.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The Horizon mode of vtkApertureLightingMapper, pixel by pixel: camera-facing squares of two
// triangles (the model's +z toward the camera is "up"), each with its own normal and horizons,
// lit by suns of several sizes low over the horizons, by a sphere light and by the sky, uniform
// or from an HDR environment through the horizons' wedges. Every
// tested pixel must match vtkHorizonLighting on the 8-bit horizons within 1/255: per vertex (24
// sectors in vertex attributes, through vtkApertureLightingMapper and through
// vtkCompositeApertureLightingMapper with the squares in two blocks) at the triangle's vertices,
// interpolated, as the vertex shader evaluates them; per texel (48 sectors, resampled to 32 in a
// texture array) at the pixel, and per fragment from interpolated angles where the points have
// no normals. Data without horizons, or with bad ones (NaN, too few sectors, sectors turned by
// SectorRotation), warn once and get the exact cap.

#include "vtkApertureLightingMapper.h"
#include "vtkApertureTestEnvironment.h"
#include "vtkApertureTestHarness.h"
#include "vtkCompositeApertureLightingMapper.h"
#include "vtkEnvironmentMap.h"
#include "vtkHorizonLighting.h"
#include "vtkSphericalCap.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTestErrorObserver.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <vector>

namespace
{
using vtkApertureTest::Check;

constexpr double Pi = vtkMath::Pi();
constexpr int Grid = 9;           // quads per side
constexpr int Size = 30;          // pixels per quad side
constexpr int Side = Grid * Size; // the window's, in pixels

struct Quad
{
  double Normal[3];
  std::vector<float> Horizons;
};

// Smooth horizons with a ridge toward azimuth `ridge`, as the 8-bit codes decode them after
// resampling to `gpu` sectors.
std::vector<float> Horizons(int sectors, double level, double ridge)
{
  std::vector<float> h(sectors);
  for (int k = 0; k < sectors; ++k)
  {
    const double phi = 2.0 * Pi * (k + 0.5) / sectors;
    h[k] = static_cast<float>(level + 0.25 * std::cos(phi - ridge));
  }
  return h;
}

std::vector<float> AsTheGPUSees(const std::vector<float>& h, int gpu)
{
  std::vector<float> out(gpu);
  for (int k = 0; k < gpu; ++k)
  {
    const double middle = 2.0 * Pi * (k + 0.5) / gpu;
    const double value = static_cast<int>(h.size()) == gpu
      ? h[k]
      : vtkHorizonLighting::HorizonAt(h.data(), static_cast<int>(h.size()), middle);
    out[k] =
      static_cast<float>(vtkHorizonLighting::DecodeAngle(vtkHorizonLighting::EncodeAngle(value)));
  }
  return out;
}

std::vector<Quad> MakeQuads(int sectors)
{
  vtkMath::RandomSeed(9);
  std::vector<Quad> quads(Grid * Grid);
  for (Quad& q : quads)
  {
    const double tilt = vtkMath::Random(0.0, 0.6), turn = vtkMath::Random(0.0, 2.0 * Pi);
    q.Normal[0] = std::sin(tilt) * std::cos(turn);
    q.Normal[1] = std::sin(tilt) * std::sin(turn);
    q.Normal[2] = std::cos(tilt);
    q.Horizons = Horizons(sectors, vtkMath::Random(-0.1, 0.3), vtkMath::Random(0.0, 2.0 * Pi));
  }
  return quads;
}

// Grid x Grid quads filling the window, 4 points each with the quad's normal and horizons, and a
// cap (bent normal = normal, radius 1) for the arrays every aperture needs.
vtkSmartPointer<vtkPolyData> MakeMesh(const std::vector<Quad>& quads)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkFloatArray> normals, bent, radius, horizons;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  bent->SetName("BentNormal");
  bent->SetNumberOfComponents(3);
  radius->SetName("ApertureRadius");
  horizons->SetName("HorizonAngles");
  horizons->SetNumberOfComponents(static_cast<int>(quads[0].Horizons.size()));
  for (int j = 0; j < Grid; ++j)
  {
    for (int i = 0; i < Grid; ++i)
    {
      const Quad& q = quads[i + Grid * j];
      const double x0 = -0.5 * Side + Size * i, y0 = -0.5 * Side + Size * j;
      const vtkIdType first = points->GetNumberOfPoints();
      const double corners[4][2] = { { x0, y0 }, { x0 + Size, y0 }, { x0 + Size, y0 + Size },
        { x0, y0 + Size } };
      for (const auto& c : corners)
      {
        points->InsertNextPoint(c[0], c[1], 0.0);
        normals->InsertNextTuple(q.Normal);
        bent->InsertNextTuple(q.Normal);
        radius->InsertNextValue(1.0);
        std::vector<double> h(q.Horizons.begin(), q.Horizons.end());
        horizons->InsertNextTuple(h.data());
      }
      const vtkIdType lower[3] = { first, first + 1, first + 2 };
      const vtkIdType upper[3] = { first, first + 2, first + 3 };
      cells->InsertNextCell(3, lower);
      cells->InsertNextCell(3, upper);
    }
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(cells);
  mesh->GetPointData()->SetNormals(normals);
  mesh->GetPointData()->AddArray(bent);
  mesh->GetPointData()->AddArray(radius);
  mesh->GetPointData()->AddArray(horizons);
  return mesh;
}

struct Scene
{
  double Light[3]; // toward a directional light, or a sphere light's centre
  double Radius;   // angular (directional) or world (positional)
  bool Positional;
  double Sky;
  bool Environment = false; // the sky from Bench's environment, else uniform
};

// An environment whose red channel (the one the pixels are read from) is brightest low in the
// north-east (vtkApertureTest::GlowSky()), and the wedge table of the model's frame (the world's
// here) that the mapper builds from it.
constexpr int WedgeAzimuths = 256;
constexpr int WedgeElevations = 64;
vtkSmartPointer<vtkEnvironmentMap> MakeEnvironment(std::vector<float>& wedges)
{
  auto environment = vtkSmartPointer<vtkEnvironmentMap>::New();
  environment->SetImage(vtkApertureTest::GlowSky());
  const double identity[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  vtkSmartPointer<vtkImageData> table;
  table.TakeReference(environment->NewWedgeTable(WedgeAzimuths, WedgeElevations, identity));
  auto* values = vtkFloatArray::SafeDownCast(table->GetPointData()->GetScalars());
  wedges.assign(values->GetPointer(0), values->GetPointer(0) + values->GetNumberOfValues());
  return environment;
}

// What an environment sky is expected from: the wedge table the mapper builds, and the aperture
// image's normal where it has normals (the sky per texel then comes from the CPU around it, and
// the fragment only takes away the lights' share).
struct SkyExpectation
{
  std::vector<float> Wedges;
  const double* TexelNormal = nullptr;
};

// The expected value at world position p of a quad with these horizons (as the GPU sees them),
// or of the exact cap where `cap` is set; unclamped, as the vertex shader hands it on (the
// fragments clamp what they interpolate).
double Expected(const Scene& s, const double n[3], const std::vector<float>& h, const double p[3],
  double intensity, bool cap, const SkyExpectation& expectation)
{
  double l[3] = { s.Light[0], s.Light[1], s.Light[2] };
  double rl = s.Radius;
  if (s.Positional)
  {
    vtkMath::Subtract(s.Light, p, l);
    rl = vtkSphericalCap::SphereLightCapRadius(s.Radius, vtkMath::Norm(l));
  }
  if (cap)
  {
    const double t = vtkSphericalCap::LightTransfer(
      vtkSphericalCap::EXACT, vtkSphericalCap::CENTROID, n, n, 1.0, l, rl);
    const double covered = vtkSphericalCap::LightCoverage(vtkSphericalCap::EXACT, n, 1.0, l, rl);
    return intensity * t + s.Sky * vtkSphericalCap::SkyTransfer(1.0, covered, 1.0, true);
  }
  const int sectors = static_cast<int>(h.size());
  double coverage, cosine;
  const double t =
    vtkHorizonLighting::LightTransfer(n, h.data(), sectors, l, rl, &coverage, &cosine);
  double sky[3] = { vtkHorizonLighting::SkyTransfer(n, h.data(), sectors, coverage, cosine, true) };
  const float* wedges = expectation.Wedges.data();
  if (s.Environment && expectation.TexelNormal)
  {
    vtkHorizonLighting::EnvironmentSkyTransfer(expectation.TexelNormal, h.data(), sectors, wedges,
      WedgeAzimuths, WedgeElevations, 0.0, 0.0, true, sky);
    sky[0] *= vtkHorizonLighting::OpenShare(n, h.data(), sectors, coverage, cosine, true);
  }
  else if (s.Environment)
  {
    vtkHorizonLighting::EnvironmentSkyTransfer(
      n, h.data(), sectors, wedges, WedgeAzimuths, WedgeElevations, coverage, cosine, true, sky);
  }
  return intensity * t + s.Sky * sky[0];
}

class Bench
{
public:
  Bench()
  {
    this->Mapper->ScalarVisibilityOff();
    this->Mapper->SetShadingModeToHorizon();
    this->Actor->SetMapper(this->Mapper);
    this->Actor->GetProperty()->SetAmbient(0.0);
    this->Actor->GetProperty()->SetDiffuse(1.0);
    this->Actor->GetProperty()->SetSpecular(0.0);
    this->Renderer->AddActor(this->Actor);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    camera->SetParallelScale(0.5 * Side);
    camera->SetPosition(0, 0, 1000);
    camera->SetFocalPoint(0, 0, 0);
    camera->SetViewUp(0, 1, 0);
    camera->SetClippingRange(500, 1500);
    this->Light->SetLightTypeToSceneLight();
    this->Light->SetIntensity(this->Intensity);
    this->Light->SetConeAngle(180.0);
    this->Renderer->AddLight(this->Light);
    this->Window->SetSize(Side, Side);
    this->Window->SetMultiSamples(0);
    this->Window->AddRenderer(this->Renderer);
    this->Mapper->GetApertureLighting()->AddObserver(vtkCommand::WarningEvent, this->Observer);
  }

  // Renders a scene and returns the largest difference (/255) from the expected pixels: at the
  // pixel, or per vertex, at the vertices of the pixel's triangle, interpolated.
  double Run(
    const Scene& s, const std::vector<Quad>& quads, int gpuSectors, bool cap, bool perVertex)
  {
    this->Mapper->SetSkyIntensity(s.Sky);
    this->Mapper->SetSkyEnvironment(s.Environment ? this->Environment : nullptr);
    this->Light->SetPositional(s.Positional);
    this->Light->SetPosition(s.Light);
    this->Light->SetFocalPoint(0, 0, 0);
    vtkApertureLightingMapper::SetLightRadius(this->Light, s.Radius);
    this->Window->Render();
    vtkNew<vtkUnsignedCharArray> pixels;
    this->Window->GetPixelData(0, 0, Side - 1, Side - 1, 1, pixels, 0);
    double worst = 0.0;
    for (int j = 0; j < Grid; ++j)
    {
      for (int i = 0; i < Grid; ++i)
      {
        const Quad& q = quads[i + Grid * j];
        const std::vector<float> h = AsTheGPUSees(q.Horizons, gpuSectors);
        const double x0 = -0.5 * Side + Size * i, y0 = -0.5 * Side + Size * j;
        double corner[4];
        const double offsets[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
        for (int c = 0; c < 4; ++c)
        {
          const double p[3] = { x0 + Size * offsets[c][0], y0 + Size * offsets[c][1], 0.0 };
          corner[c] = Expected(s, q.Normal, h, p, this->Intensity, cap, this->Sky);
        }
        for (int py = Size * j + 3; py < Size * (j + 1) - 3; py += 4)
        {
          for (int px = Size * i + 3; px < Size * (i + 1) - 3; px += 4)
          {
            const double p[3] = { -0.5 * Side + px + 0.5, -0.5 * Side + py + 0.5, 0.0 };
            // Barycentric in the lower (0, 1, 2) or upper (0, 2, 3) triangle.
            const double u = (p[0] - x0) / Size, v = (p[1] - y0) / Size;
            const double interpolated = u >= v
              ? (1.0 - u) * corner[0] + (u - v) * corner[1] + v * corner[2]
              : (1.0 - v) * corner[0] + u * corner[2] + (v - u) * corner[3];
            const double want = 255.0 *
              std::min(1.0,
                perVertex ? interpolated
                          : Expected(s, q.Normal, h, p, this->Intensity, cap, this->Sky));
            const double d = std::abs(pixels->GetValue(3 * (px + Side * py)) - want);
            worst = std::max(worst, d);
          }
        }
      }
    }
    return worst;
  }

  const double Intensity = 0.8;
  SkyExpectation Sky;
  vtkSmartPointer<vtkEnvironmentMap> Environment = MakeEnvironment(this->Sky.Wedges);
  vtkNew<vtkApertureLightingMapper> Mapper;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkLight> Light;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkTest::ErrorObserver> Observer;
};

std::vector<Scene> Scenes()
{
  // Suns low over the horizons (elevations about 8 and 20 degrees) and a high one, a sphere
  // light, and the sky.
  std::vector<Scene> scenes;
  for (double radius : { 0.0047, 0.064, 0.4 })
  {
    scenes.push_back({ { 0.98, 0.1, 0.14 }, radius, false, 0.0 });
    scenes.push_back({ { -0.5, 0.8, 0.35 }, radius, false, 0.3 });
  }
  scenes.push_back({ { 0.2, 0.3, 0.9 }, 0.1, false, 0.3 });
  scenes.push_back({ { 80.0, -60.0, 40.0 }, 30.0, true, 0.2 });
  scenes.push_back({ { 0.98, 0.1, 0.14 }, 0.064, false, 0.4, true });
  scenes.push_back({ { 80.0, -60.0, 40.0 }, 30.0, true, 0.3, true });
  return scenes;
}

void TestPerVertex(Bench& bench)
{
  const std::vector<Quad> quads = MakeQuads(24);
  auto mesh = MakeMesh(quads);
  bench.Mapper->SetInputData(mesh);
  for (const Scene& s : Scenes())
  {
    const double worst = bench.Run(s, quads, 24, false, true);
    std::cout << "per vertex, 24 sectors, " << (s.Positional ? "sphere light R=" : "sun r=")
              << s.Radius << ", sky " << s.Sky << (s.Environment ? " (environment)" : "")
              << ": max |GPU - CPU| = " << worst << "/255\n";
    // 0.5 for the 8-bit rounding, 0.5 for single precision.
    Check(
      worst <= 1.0, "Horizon pixels per vertex differ from vtkHorizonLighting (/255)", worst, 1.0);
  }
  Check(!bench.Observer->GetWarning(), "good horizons shade without a warning");
  bench.Observer->Clear();

  // Without point normals the horizons interpolate as angles and shade per fragment, around
  // the facets' normal (the view's +z).
  std::vector<Quad> facets = quads;
  for (Quad& q : facets)
  {
    q.Normal[0] = q.Normal[1] = 0.0;
    q.Normal[2] = 1.0;
  }
  auto bare = MakeMesh(quads);
  bare->GetPointData()->SetNormals(nullptr);
  bench.Mapper->SetInputData(bare);
  for (const Scene& s : Scenes())
  {
    const double worst = bench.Run(s, facets, 24, false, false);
    std::cout << "per fragment (no normals), 24 sectors: max |GPU - CPU| = " << worst << "/255\n";
    Check(worst <= 1.0, "Horizon pixels per fragment differ from vtkHorizonLighting (/255)", worst,
      1.0);
  }
  bench.Mapper->SetInputData(mesh);

  // Bad horizons, then none: one warning each, and the exact cap.
  vtkDataArray* horizons = mesh->GetPointData()->GetArray("HorizonAngles");
  horizons->SetComponent(7, 3, std::numeric_limits<double>::quiet_NaN());
  horizons->Modified();
  const Scene s = Scenes()[1];
  double worst = bench.Run(s, quads, 24, true, true);
  Check(worst <= 1.0, "NaN horizons give the exact cap (/255)", worst, 1.0);
  Check(bench.Observer->GetWarningMessage().find("not angles") != std::string::npos,
    "NaN horizons warn");
  bench.Observer->Clear();
  bench.Run(s, quads, 24, true, true);
  Check(!bench.Observer->GetWarning(), "a persisting problem warns once");
  vtkNew<vtkFloatArray> three;
  three->SetName("HorizonAngles");
  three->SetNumberOfComponents(3);
  three->SetNumberOfTuples(mesh->GetNumberOfPoints());
  three->Fill(0.1);
  mesh->GetPointData()->AddArray(three);
  worst = bench.Run(s, quads, 24, true, true);
  Check(worst <= 1.0, "horizons of 3 sectors give the exact cap (/255)", worst, 1.0);
  Check(bench.Observer->GetWarningMessage().find("3 components") != std::string::npos,
    "horizons of 3 sectors warn");
  bench.Observer->Clear();
  vtkNew<vtkFloatArray> turned; // vtkAperturePrecompute's names with SectorRotation -2.8125
  turned->SetName("HorizonAngles");
  turned->SetNumberOfComponents(32);
  turned->SetNumberOfTuples(mesh->GetNumberOfPoints());
  turned->Fill(0.1);
  turned->SetComponentName(0, "Az2.8125");
  mesh->GetPointData()->AddArray(turned);
  worst = bench.Run(s, quads, 24, true, true);
  Check(worst <= 1.0, "turned sectors give the exact cap (/255)", worst, 1.0);
  Check(bench.Observer->GetWarningMessage().find("SectorRotation") != std::string::npos,
    "turned sectors warn");
  bench.Observer->Clear();
  mesh->GetPointData()->RemoveArray("HorizonAngles");
  worst = bench.Run(s, quads, 24, true, true);
  Check(worst <= 1.0, "missing horizons give the exact cap (/255)", worst, 1.0);
  Check(bench.Observer->GetWarningMessage().find("ComputeHorizonAngles") != std::string::npos,
    "missing horizons warn");
  bench.Observer->Clear();
}

// The same squares in two blocks through the composite mapper.
void TestComposite(Bench& bench)
{
  const std::vector<Quad> quads = MakeQuads(24);
  auto mesh = MakeMesh(quads);
  vtkNew<vtkPolyData> low, high;
  for (vtkPolyData* half : { low.Get(), high.Get() })
  {
    half->ShallowCopy(mesh);
    vtkNew<vtkCellArray> cells;
    const vtkIdType first = half == low ? 0 : Grid * Grid / 2;
    const vtkIdType last = half == low ? Grid * Grid / 2 : Grid * Grid;
    for (vtkIdType c = first; c < last; ++c)
    {
      const vtkIdType lower[3] = { 4 * c, 4 * c + 1, 4 * c + 2 };
      const vtkIdType upper[3] = { 4 * c, 4 * c + 2, 4 * c + 3 };
      cells->InsertNextCell(3, lower);
      cells->InsertNextCell(3, upper);
    }
    half->SetPolys(cells);
  }
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, low);
  blocks->SetBlock(1, high);
  vtkNew<vtkCompositeApertureLightingMapper> composite;
  composite->SetInputDataObject(blocks);
  composite->ScalarVisibilityOff();
  composite->GetApertureLighting()->SetShadingModeToHorizon();
  vtkNew<vtkTest::ErrorObserver> observer;
  composite->GetApertureLighting()->AddObserver(vtkCommand::WarningEvent, observer);
  bench.Actor->SetMapper(composite);
  for (const Scene& s : Scenes())
  {
    composite->GetApertureLighting()->SetSkyIntensity(s.Sky);
    composite->GetApertureLighting()->SetSkyEnvironment(
      s.Environment ? bench.Environment : nullptr);
    const double worst = bench.Run(s, quads, 24, false, true);
    std::cout << "composite, two blocks: max |GPU - CPU| = " << worst << "/255\n";
    Check(worst <= 1.0, "Horizon pixels of the composite mapper differ (/255)", worst, 1.0);
  }
  Check(!observer->GetWarning(), "the composite mapper shades without a warning");
  bench.Actor->SetMapper(bench.Mapper);
}

// The aperture image holds one set of 48 horizons everywhere, so that texel filtering leaves
// them as they are; each quad keeps its own normal.
void TestPerTexel(Bench& bench)
{
  std::vector<Quad> quads = MakeQuads(48);
  for (Quad& q : quads)
  {
    q.Horizons = quads[0].Horizons;
  }
  bench.Mapper->SetInputData(MakeMesh(quads));
  vtkNew<vtkImageData> image;
  image->SetDimensions(4, 4, 1);
  image->SetOrigin(-0.5 * Side, -0.5 * Side, 0.0);
  image->SetSpacing(Side / 3.0, Side / 3.0, 1.0);
  vtkNew<vtkFloatArray> bent, radius, horizons;
  bent->SetName("BentNormal");
  bent->SetNumberOfComponents(3);
  radius->SetName("ApertureRadius");
  horizons->SetName("HorizonAngles");
  horizons->SetNumberOfComponents(48);
  std::vector<double> h(quads[0].Horizons.begin(), quads[0].Horizons.end());
  for (int t = 0; t < 16; ++t)
  {
    bent->InsertNextTuple3(0.0, 0.0, 1.0);
    radius->InsertNextValue(1.0);
    horizons->InsertNextTuple(h.data());
  }
  image->GetPointData()->AddArray(bent);
  image->GetPointData()->AddArray(radius);
  image->GetPointData()->AddArray(horizons);
  bench.Mapper->SetApertureImage(image);
  for (const Scene& s : Scenes())
  {
    const double worst = bench.Run(s, quads, 32, false, false);
    std::cout << "per texel, 48 sectors as 32, " << (s.Positional ? "sphere light R=" : "sun r=")
              << s.Radius << ", sky " << s.Sky << (s.Environment ? " (environment)" : "")
              << ": max |GPU - CPU| = " << worst << "/255\n";
    Check(
      worst <= 1.0, "Horizon pixels per texel differ from vtkHorizonLighting (/255)", worst, 1.0);
  }
  Check(!bench.Observer->GetWarning(), "good horizons in an image shade without a warning");
  // With normals in the image, the environment sky per texel comes from the CPU around them.
  vtkNew<vtkFloatArray> up;
  up->SetNumberOfComponents(3);
  up->SetNumberOfTuples(16);
  const double tilted[3] = { 0.2, -0.1, 0.97 };
  for (vtkIdType t = 0; t < 16; ++t)
  {
    up->SetTuple(t, tilted);
  }
  image->GetPointData()->SetNormals(up);
  image->Modified();
  bench.Sky.TexelNormal = tilted;
  for (const Scene& s : Scenes())
  {
    if (!s.Environment)
    {
      continue;
    }
    const double worst = bench.Run(s, quads, 32, false, false);
    std::cout << "per texel with normals, " << (s.Positional ? "sphere light R=" : "sun r=")
              << s.Radius << ", sky " << s.Sky << " (environment): max |GPU - CPU| = " << worst
              << "/255\n";
    Check(worst <= 1.0, "Horizon pixels per texel with an environment from the CPU differ (/255)",
      worst, 1.0);
  }
  bench.Sky.TexelNormal = nullptr;
  bench.Mapper->SetApertureImage(nullptr);
}
}

int TestApertureLightingMapperHorizons(int, char*[])
{
  Bench bench;
  TestPerVertex(bench);
  TestComposite(bench);
  TestPerTexel(bench);
  return vtkApertureTest::Result();
}
