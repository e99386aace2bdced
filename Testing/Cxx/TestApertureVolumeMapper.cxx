/*=========================================================================

  Program:   ApertureLighting
  Module:    TestApertureVolumeMapper.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkApertureVolumeMapper in a real OpenGL context:
//  1. the GLSL twin: an opaque volume whose apertures are all the same, so that each pixel is one
//     sample's shading, against vtkSphericalCap's intersection areas (exact and smoothstep, one
//     and two lights, apertures from nearly closed to the whole sphere);
//  2. with its own precompute: an open shell's inner wall is lit through the opening and not
//     from behind, a transfer-function change recomputes the apertures, Shade off draws as VTK;
//  3. what it cannot shade (two components, apertures that do not fit) warns and draws as VTK;
//  4. an HDR sky: pixels against vtkEnvironmentMap::CapRadiance() for turned volumes and
//     environments (the table, its look-up and the matrices), and a uniform environment of
//     radiance 1 draws what the uniform sky draws;
//  5. a piece of a volume (as an MPI rank draws it) with its halo as the aperture source draws
//     what the whole volume's apertures draw on it, on a coarser aperture grid that the piece
//     starts between two points of;
//  6. between a voxel whose cap holds the light and one whose cap misses it, the light goes
//     linearly from one's to the other's (InterpolateLight on), against vtkSphericalCap; with it
//     off, the interpolated cap holds more of the light;
//  7. the surface of opaque matter takes the light one aperture voxel toward the eye, or, with
//     SurfaceOffset 0, that of where the ray stops.

#include "vtkApertureVolumeMapper.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkEnvironmentMap.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLGPUVolumeRayCastMapper.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphericalCap.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeAperturePrecompute.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

namespace
{
constexpr double Pi = 3.14159265358979323846;

vtkSmartPointer<vtkImageData> MakeVolume(
  int n, int components, const std::function<double(double, double, double)>& f)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  image->SetSpacing(1.0 / (n - 1), 1.0 / (n - 1), 1.0 / (n - 1));
  image->AllocateScalars(VTK_FLOAT, components);
  auto* scalars = vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars());
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        for (int c = 0; c < components; ++c)
        {
          scalars->SetTypedComponent(i + n * (j + vtkIdType(n) * k), c,
            static_cast<float>(f(i / (n - 1.0), j / (n - 1.0), k / (n - 1.0))));
        }
      }
    }
  }
  return image;
}

vtkSmartPointer<vtkVolumeProperty> WhiteProperty(double unitDistance)
{
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(1.0, 1.0);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 1.0, 1.0, 1.0);
  color->AddRGBPoint(1.0, 1.0, 1.0, 1.0);
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetScalarOpacityUnitDistance(unitDistance);
  property->SetInterpolationTypeToLinear();
  property->ShadeOn();
  property->SetAmbient(0.3);
  property->SetDiffuse(0.6);
  return property;
}

// A scene: a window of 64 x 64 looking down -z at the unit cube.
struct Scene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkVolume> Volume;
  Scene(vtkVolumeMapper* mapper, vtkVolumeProperty* property)
  {
    this->Window->SetSize(64, 64);
    this->Window->SetMultiSamples(0);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->AutomaticLightCreationOff();
    this->Volume->SetMapper(mapper);
    this->Volume->SetProperty(property);
    this->Renderer->AddVolume(this->Volume);
    this->Renderer->GetActiveCamera()->SetPosition(0.5, 0.5, 4.0);
    this->Renderer->GetActiveCamera()->SetFocalPoint(0.5, 0.5, 0.5);
    this->Renderer->GetActiveCamera()->SetViewUp(0.0, 1.0, 0.0);
    this->Renderer->ResetCameraClippingRange();
  }
  // The centre pixel's red channel in [0, 1], and the mean red over the image.
  double Pixel(int x = 32, int y = 32)
  {
    this->Window->Render();
    vtkNew<vtkUnsignedCharArray> rgb;
    this->Window->GetPixelData(x, y, x, y, 0, rgb);
    return rgb->GetValue(0) / 255.0;
  }
  void AddLight(const double toward[3], double intensity)
  {
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPositional(false);
    light->SetFocalPoint(0.0, 0.0, 0.0);
    light->SetPosition(toward);
    light->SetIntensity(intensity);
    this->Renderer->AddLight(light);
  }
};

bool Report(bool ok, const char* what, double value, double limit)
{
  std::printf("%-64s %9.4f (limit %g) %s\n", what, value, limit, ok ? "ok" : "FAILED");
  return ok;
}

// A mapper of the volume whose apertures are one bent normal and radius everywhere.
vtkSmartPointer<vtkApertureVolumeMapper> ConstantMapper(
  vtkImageData* volume, const double bent[3], double radius)
{
  auto apertures = vtkSmartPointer<vtkImageData>::New();
  apertures->CopyStructure(volume);
  vtkNew<vtkFloatArray> bentArray;
  bentArray->SetName("BentNormal");
  bentArray->SetNumberOfComponents(3);
  bentArray->SetNumberOfTuples(volume->GetNumberOfPoints());
  vtkNew<vtkFloatArray> radiusArray;
  radiusArray->SetName("ApertureRadius");
  radiusArray->SetNumberOfTuples(volume->GetNumberOfPoints());
  for (vtkIdType i = 0; i < volume->GetNumberOfPoints(); ++i)
  {
    bentArray->SetTuple(i, bent);
    radiusArray->SetValue(i, static_cast<float>(radius));
  }
  apertures->GetPointData()->AddArray(bentArray);
  apertures->GetPointData()->AddArray(radiusArray);
  auto mapper = vtkSmartPointer<vtkApertureVolumeMapper>::New();
  mapper->SetInputData(volume);
  mapper->SetApertureData(apertures);
  return mapper;
}

// A radius as the texture holds it: a byte of r/pi.
double TextureRadius(double r)
{
  return std::round(r / Pi * 255.0) / 255.0 * Pi;
}

// The uniform sky's share of a cap of radius r, A/4pi.
double SkyShare(double r)
{
  return vtkSphericalCap::SolidAngleFromCapRadius(r) / (4.0 * Pi);
}

// A random unit bent normal and radius (0.05 pi to pi), and the normal as the texture holds it
// (bytes of (n + 1)/2), made unit; the radius is a byte of r/pi already.
void RandomAperture(double bent[3], double quantized[3], double& radius)
{
  for (int a = 0; a < 3; ++a)
  {
    bent[a] = vtkMath::Gaussian();
  }
  vtkMath::Normalize(bent);
  radius = TextureRadius(vtkMath::Random(0.05, 1.0) * Pi);
  for (int a = 0; a < 3; ++a)
  {
    quantized[a] = std::round(0.5 * (bent[a] + 1.0) * 255.0) / 255.0 * 2.0 - 1.0;
  }
  vtkMath::Normalize(quantized);
}

// 1. Pixels against the C++ formula, apertures constant over the volume.
bool TestTwin()
{
  auto volume = MakeVolume(8, 1, [](double, double, double) { return 1.0; });
  auto property = WhiteProperty(1e-4);
  bool ok = true;
  double worst = 0.0;
  vtkMath::RandomSeed(3);
  // One window for every case: X servers take a while to let windows go.
  vtkNew<vtkApertureVolumeMapper> first;
  Scene scene(first, property);
  for (int mode : { vtkApertureVolumeMapper::EXACT, vtkApertureVolumeMapper::SMOOTHSTEP })
  {
    for (int c = 0; c < 12; ++c)
    {
      double bent[3], quantized[3], radius;
      RandomAperture(bent, quantized, radius);
      auto mapper = ConstantMapper(volume, bent, radius);
      mapper->SetShadingMode(mode);
      const double lightRadius = c % 3 == 0 ? 0.05 : 0.4;
      mapper->SetLightRadius(lightRadius);
      scene.Volume->SetMapper(mapper);
      scene.Renderer->RemoveAllLights();
      const int lightCount = c % 2 == 0 ? 1 : 2;
      double expected = 0.3 * SkyShare(radius);
      for (int l = 0; l < lightCount; ++l)
      {
        double toward[3] = { vtkMath::Gaussian(), vtkMath::Gaussian(), vtkMath::Gaussian() };
        vtkMath::Normalize(toward);
        scene.AddLight(toward, 0.5);
        const double d = std::acos(std::max(-1.0, std::min(1.0, vtkMath::Dot(quantized, toward))));
        const double area = mode == vtkApertureVolumeMapper::EXACT
          ? vtkSphericalCap::IntersectionArea(radius, lightRadius, d)
          : vtkSphericalCap::IntersectionAreaSmoothstep(radius, lightRadius, d);
        expected += 0.6 * 0.5 * area / vtkSphericalCap::SolidAngleFromCapRadius(lightRadius);
      }
      const double pixel = scene.Pixel();
      worst = std::max(worst, std::abs(pixel - std::min(1.0, expected)));
    }
  }
  ok &= Report(worst <= 3.0 / 255.0, "twin: largest |pixel - vtkSphericalCap| over 24 cases", worst,
    3.0 / 255.0);
  return ok;
}

// A latitude-longitude environment whose radiance rises smoothly toward its up and east (grey,
// 0.4 to 2.6): every axis sees another amount of it.
vtkSmartPointer<vtkImageData> GradientEnvironment()
{
  const int width = 128, height = 64;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_FLOAT, 3);
  auto* rgb = vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars());
  for (int j = 0; j < height; ++j)
  {
    const double elevation = Pi * ((j + 0.5) / height - 0.5);
    for (int i = 0; i < width; ++i)
    {
      const double azimuth = 2.0 * Pi * ((i + 0.5) / width - 0.5);
      const double value =
        1.5 + 0.8 * std::sin(elevation) + 0.3 * std::cos(elevation) * std::sin(azimuth);
      for (int c = 0; c < 3; ++c)
      {
        rgb->SetTypedComponent(i + width * j, c, static_cast<float>(value));
      }
    }
  }
  return image;
}

// 4. The HDR sky: a light of intensity 0 (VTK shades only with a light on), the sky alone.
bool TestEnvironmentSky()
{
  auto volume = MakeVolume(8, 1, [](double, double, double) { return 1.0; });
  auto property = WhiteProperty(1e-4);
  vtkNew<vtkEnvironmentMap> environment;
  environment->SetImage(GradientEnvironment());
  vtkNew<vtkApertureVolumeMapper> first;
  Scene scene(first, property);
  const double dark[3] = { 0.0, 0.0, 1.0 };
  scene.AddLight(dark, 0.0);
  scene.Volume->SetOrigin(0.5, 0.5, 0.5); // turned about the cube's centre
  vtkMath::RandomSeed(5);
  double worst = 0.0;
  for (int c = 0; c < 12; ++c)
  {
    // Turned environments (Y or Z up, an azimuth) and volumes: a transposed matrix shows.
    environment->SetUpAxis(c % 2 ? vtkEnvironmentMap::Y : vtkEnvironmentMap::Z);
    environment->SetAzimuth(30.0 * c);
    scene.Volume->SetOrientation(0.0, 0.0, c % 3 ? 25.0 * c : 0.0);
    double bent[3], quantized[3], radius;
    RandomAperture(bent, quantized, radius);
    auto mapper = ConstantMapper(volume, bent, radius);
    mapper->SetSkyEnvironment(environment);
    scene.Volume->SetMapper(mapper);
    double axis[4] = { quantized[0], quantized[1], quantized[2], 0.0 }, world[4];
    scene.Volume->GetMatrix()->MultiplyPoint(axis, world);
    vtkMath::Normalize(world);
    double radiance[3];
    environment->CapRadiance(world, radius, radiance);
    const double expected = 0.3 * radiance[0] / (4.0 * Pi);
    worst = std::max(worst, std::abs(scene.Pixel() - std::min(1.0, expected)));
  }
  bool ok = Report(worst <= 3.0 / 255.0,
    "HDR sky: largest |pixel - CapRadiance/4pi| over 12 turned cases", worst, 3.0 / 255.0);

  // A uniform environment of radiance 1 against the uniform sky.
  scene.Volume->SetOrientation(0.0, 0.0, 0.0);
  auto uniform = GradientEnvironment();
  uniform->GetPointData()->GetScalars()->Fill(1.0);
  environment->SetImage(uniform);
  double bent[3], quantized[3], radius;
  RandomAperture(bent, quantized, radius);
  auto withEnvironment = ConstantMapper(volume, bent, radius);
  withEnvironment->SetSkyEnvironment(environment);
  scene.Volume->SetMapper(withEnvironment);
  const double lit = scene.Pixel();
  withEnvironment->SetSkyEnvironment(nullptr);
  const double difference = std::abs(scene.Pixel() - lit);
  ok &= Report(difference <= 2.0 / 255.0 && lit > 0.05,
    "a uniform environment of 1: |pixel - uniform sky's|", difference, 2.0 / 255.0);
  return ok;
}

// An opaque shell open toward -y, where the camera is.
double OpenShell(double x, double y, double z)
{
  const double d[3] = { x - 0.5, y - 0.5, z - 0.5 };
  const double rho = vtkMath::Norm(d);
  const bool open = rho > 0.0 && -d[1] / rho > std::cos(0.6);
  return rho > 0.3 && rho < 0.4 && !open ? 1.0 : 0.0;
}

// 2. Light through the opening against light from behind, a transfer-function change, and Shade
// off as VTK draws it.
bool TestShell()
{
  bool ok = true;
  auto volume = MakeVolume(40, 1, OpenShell);
  auto property = WhiteProperty(0.02);
  vtkNew<vtkApertureVolumeMapper> mapper;
  mapper->SetInputData(volume);
  mapper->AutoAdjustSampleDistancesOff();
  mapper->SetSampleDistance(0.01);
  mapper->GetAperturePrecompute()->SetMaximumDistance(1.0);
  Scene scene(mapper, property);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetPosition(0.5, -3.0, 0.5);
  camera->SetViewUp(0.0, 0.0, 1.0);
  scene.Renderer->ResetCamera();
  // The inner wall opposite the opening, lit through it and from behind the shell.
  const double front[3] = { 0.0, -1.0, 0.2 };
  const double back[3] = { 0.0, 1.0, 0.2 };
  scene.AddLight(front, 1.0);
  const double through = scene.Pixel();
  scene.Renderer->RemoveAllLights();
  scene.AddLight(back, 1.0);
  const double behind = scene.Pixel();
  std::printf("inner wall: %.3f lit through the opening, %.3f from behind\n", through, behind);
  ok &= Report(behind < 0.5 * through, "inner wall lit from behind over through the opening",
    behind / through, 0.5);

  // A transfer-function change recomputes the apertures.
  const vtkMTimeType time = mapper->GetAperturePrecompute()->GetOutput()->GetMTime();
  property->GetScalarOpacity()->AddPoint(0.5, 0.2);
  scene.Pixel();
  ok &= Report(mapper->GetAperturePrecompute()->GetOutput()->GetMTime() > time,
    "a transfer-function change recomputes the apertures", 1.0, 1.0);

  // Shade off draws VTK's picture, and VTK's mapper on the volume this mapper drew draws as on a
  // volume of its own: nothing of this mapper's stays in the volume's shader property.
  vtkNew<vtkOpenGLGPUVolumeRayCastMapper> plain;
  plain->SetInputData(volume);
  plain->AutoAdjustSampleDistancesOff();
  plain->SetSampleDistance(0.01);
  vtkNew<vtkVolume> other;
  other->SetProperty(property);
  auto picture = [&](vtkVolume* shown, vtkVolumeMapper* drawer)
  {
    scene.Renderer->RemoveAllViewProps();
    shown->SetMapper(drawer);
    scene.Renderer->AddVolume(shown);
    scene.Window->Render();
    auto rgb = vtkSmartPointer<vtkUnsignedCharArray>::New();
    scene.Window->GetPixelData(0, 0, 63, 63, 0, rgb);
    return rgb;
  };
  auto differing = [](vtkUnsignedCharArray* a, vtkUnsignedCharArray* b)
  {
    int count = 0;
    for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
    {
      count += std::abs(a->GetValue(i) - b->GetValue(i)) > 1;
    }
    return count;
  };
  auto vtkOnSame = picture(scene.Volume, plain);
  auto vtkOnOther = picture(other, plain);
  ok &= Report(differing(vtkOnSame, vtkOnOther) == 0,
    "VTK's mapper after this one on the same volume: values that differ",
    differing(vtkOnSame, vtkOnOther), 0);
  property->ShadeOff();
  auto ours = picture(scene.Volume, mapper);
  auto vtks = picture(other, plain);
  ok &= Report(differing(ours, vtks) == 0, "Shade off: values that differ from VTK's mapper",
    differing(ours, vtks), 0);
  return ok;
}

// A slab (z < 0.25) and a roof over its half x < 0.7 (z from 0.5 to 0.65): the slab's middle
// sees the sky toward +x only (a cap that one bent normal and radius hold).
double RoofOverSlab(double x, double, double z)
{
  return z < 0.25 || (x < 0.7 && z > 0.5 && z < 0.65) ? 1.0 : 0.0;
}

// 5. The slab's piece of the volume (without the roof) drawn with the whole volume's apertures,
// with those of the piece and its halo, and with its own alone.
bool TestPiece()
{
  bool ok = true;
  const int n = 40;
  auto whole = MakeVolume(n, 1, RoofOverSlab);
  auto property = WhiteProperty(0.02);
  const int pieceExtent[6] = { 0, n - 1, 0, n - 1, 3, 17 };
  auto piece = vtkSmartPointer<vtkImageData>::New();
  piece->ShallowCopy(whole);
  piece->Crop(pieceExtent);
  auto render = [&](vtkImageData* apertures, vtkImageData* source)
  {
    vtkNew<vtkApertureVolumeMapper> mapper;
    mapper->SetInputData(piece);
    mapper->AutoAdjustSampleDistancesOff();
    mapper->SetSampleDistance(0.01);
    mapper->GetAperturePrecompute()->SetMaximumDistance(0.6);
    mapper->GetAperturePrecompute()->SetApertureGridStep(2);
    mapper->SetApertureData(apertures);
    mapper->SetApertureSource(source);
    mapper->SetApertureSourceWholeExtent(whole->GetExtent());
    Scene scene(mapper, property);
    const double light[3] = { 0.0, 0.3, 1.0 };
    scene.AddLight(light, 1.0);
    scene.Window->Render();
    auto rgb = vtkSmartPointer<vtkUnsignedCharArray>::New();
    scene.Window->GetPixelData(0, 0, 63, 63, 0, rgb);
    return rgb;
  };

  vtkNew<vtkVolumeAperturePrecompute> precompute;
  precompute->SetInputData(whole);
  precompute->SetVolumeProperty(property);
  precompute->SetMaximumDistance(0.6);
  precompute->SetApertureGridStep(2);
  precompute->Update();
  auto reference = render(precompute->GetOutput(), nullptr);

  int halo[3];
  const double spacing[3] = { 1.0 / (n - 1), 1.0 / (n - 1), 1.0 / (n - 1) };
  precompute->ComputeHalo(whole->GetExtent(), spacing, halo);
  int haloExtent[6];
  for (int a = 0; a < 6; ++a)
  {
    haloExtent[a] = std::min(n - 1, std::max(0, pieceExtent[a] + (a % 2 ? 1 : -1) * halo[a / 2]));
  }
  auto source = vtkSmartPointer<vtkImageData>::New();
  source->ShallowCopy(whole);
  source->Crop(haloExtent);
  auto withHalo = render(nullptr, source);
  auto alone = render(nullptr, nullptr);

  auto largest = [](vtkUnsignedCharArray* a, vtkUnsignedCharArray* b)
  {
    int most = 0;
    for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
    {
      most = std::max(most, std::abs(a->GetValue(i) - b->GetValue(i)));
    }
    return most;
  };
  // The centre pixel: the slab under the roof, in its shadow when the roof is known.
  const vtkIdType centre = 3 * (32 * 64 + 32);
  std::printf("slab under the roof: %d with the whole volume's apertures, %d with the halo's, "
              "%d alone\n",
    reference->GetValue(centre), withHalo->GetValue(centre), alone->GetValue(centre));
  ok &= Report(largest(reference, withHalo) <= 2,
    "piece and halo vs the whole volume's apertures: largest difference /255",
    largest(reference, withHalo), 2);
  ok &= Report(alone->GetValue(centre) - reference->GetValue(centre) >= 10,
    "the piece alone misses the roof's shadow: brighter by /255",
    alone->GetValue(centre) - reference->GetValue(centre), 10);
  return ok;
}

// 3. What the mapper cannot shade.
bool TestUnusable()
{
  bool ok = true;
  int warnings = 0;
  vtkNew<vtkCallbackCommand> count;
  count->SetClientData(&warnings);
  count->SetCallback(
    [](vtkObject*, unsigned long, void* data, void*) { ++*static_cast<int*>(data); });
  auto rgb = MakeVolume(8, 2, [](double x, double, double) { return x; });
  auto property = WhiteProperty(0.1);
  property->IndependentComponentsOff();
  vtkNew<vtkApertureVolumeMapper> mapper;
  mapper->AddObserver(vtkCommand::WarningEvent, count);
  mapper->SetInputData(rgb);
  Scene scene(mapper, property);
  scene.Pixel();
  scene.Pixel();
  ok &= Report(warnings == 1, "two components: warnings (one)", warnings, 1);

  warnings = 0;
  auto volume = MakeVolume(8, 1, [](double, double, double) { return 1.0; });
  vtkNew<vtkImageData> wrong;
  wrong->SetDimensions(5, 5, 5);
  vtkNew<vtkApertureVolumeMapper> mismatched;
  mismatched->AddObserver(vtkCommand::WarningEvent, count);
  mismatched->SetInputData(volume);
  mismatched->SetApertureData(wrong);
  Scene other(mismatched, WhiteProperty(0.1));
  other.Pixel();
  other.Pixel();
  ok &= Report(warnings == 1, "apertures that do not fit: warnings (one)", warnings, 1);
  return ok;
}

// The light, by vtkSphericalCap, of an aperture about +z of radius r (as the texture's byte holds
// it) under a sky of 0.3 and a light of 0.6 at 60 degrees from +z, of radius 0.3.
double SlantedLight(double r)
{
  r = TextureRadius(r);
  const double lightRadius = 0.3;
  return 0.3 * SkyShare(r) +
    0.6 * vtkSphericalCap::IntersectionArea(r, lightRadius, Pi / 3.0) /
    vtkSphericalCap::SolidAngleFromCapRadius(lightRadius);
}

// A mapper of the volume whose apertures are about +z, of radius radiusAt(i) at x index i, under
// a light of radius 0.3.
vtkSmartPointer<vtkApertureVolumeMapper> SlantedMapper(
  vtkImageData* volume, const std::function<double(int)>& radiusAt)
{
  const double up[3] = { 0.0, 0.0, 1.0 };
  auto mapper = ConstantMapper(volume, up, 0.0);
  auto* radius = mapper->GetApertureData()->GetPointData()->GetArray("ApertureRadius");
  const int n = volume->GetDimensions()[0];
  for (vtkIdType i = 0; i < volume->GetNumberOfPoints(); ++i)
  {
    radius->SetTuple1(i, radiusAt(static_cast<int>(i % n)));
  }
  radius->Modified();
  mapper->SetLightRadius(0.3);
  return mapper;
}

// The scene's light at 60 degrees from +z toward +x and its camera in parallel projection.
void SlantedScene(Scene& scene)
{
  const double toward[3] = { std::sin(Pi / 3.0), 0.0, std::cos(Pi / 3.0) };
  scene.AddLight(toward, 1.0);
  scene.Renderer->GetActiveCamera()->ParallelProjectionOn();
  scene.Renderer->GetActiveCamera()->SetParallelScale(0.5);
}

// 6. Apertures about +z, wide (2 rad: the light whole) and narrow (0.3 rad: none of it) by turns
// along x, seen along -z in parallel projection: each pixel of a row is one sample between two
// voxels (texture x = 7 data x on a grid of 8).
bool TestLightInterpolation()
{
  const int n = 8;
  const double radii[2] = { 2.0, 0.3 };
  auto volume = MakeVolume(n, 1, [](double, double, double) { return 1.0; });
  auto mapper = SlantedMapper(volume, [&](int i) { return radii[i % 2]; });
  Scene scene(mapper, WhiteProperty(1e-4));
  SlantedScene(scene);
  bool ok = true;
  for (bool interpolate : { true, false })
  {
    mapper->SetInterpolateLight(interpolate);
    scene.Window->Render();
    vtkNew<vtkUnsignedCharArray> row;
    scene.Window->GetPixelData(0, 32, 63, 32, 0, row);
    double worst = 0.0, brightest = -1.0;
    for (int x = 0; x < 64; ++x)
    {
      const double u = (x + 0.5) / 64.0 * (n - 1);
      const double w = u - std::floor(u);
      const int even = static_cast<int>(std::floor(u)) % 2 == 0;
      const double expected =
        (1.0 - w) * SlantedLight(radii[1 - even]) + w * SlantedLight(radii[even]);
      const double above = row->GetValue(3 * x) / 255.0 - expected;
      worst = std::max(worst, std::abs(above));
      brightest = std::max(brightest, above);
    }
    ok &= interpolate
      ? Report(worst <= 3.0 / 255.0, "light interpolated: largest |pixel - blend of lights|", worst,
          3.0 / 255.0)
      : Report(brightest >= 0.1, "caps interpolated: largest pixel - blend of lights (at least)",
          brightest, 0.1);
  }
  return ok;
}

// 7. Matter up to x = 4/7 on a grid of 8, seen from +x; apertures narrow up to x index 4 and wide
// beyond: read in place, the surface gets the narrow caps' light, read one voxel toward the eye
// mostly the wide ones'.
bool TestSurfaceOffset()
{
  const int n = 8;
  auto volume = MakeVolume(n, 1, [](double x, double, double) { return x < 0.5 ? 1.0 : 0.0; });
  auto mapper = SlantedMapper(volume, [](int i) { return i <= 4 ? 0.3 : 2.0; });
  Scene scene(mapper, WhiteProperty(1e-4));
  SlantedScene(scene);
  scene.Renderer->GetActiveCamera()->SetPosition(4.0, 0.5, 0.5);
  scene.Renderer->GetActiveCamera()->SetViewUp(0.0, 0.0, 1.0);
  scene.Renderer->ResetCameraClippingRange();
  mapper->AutoAdjustSampleDistancesOff();
  mapper->SetSampleDistance(0.01); // the ray stops within a tenth of a voxel of the surface
  mapper->SetSurfaceOffset(0.0);
  const double inPlace = scene.Pixel();
  mapper->SetSurfaceOffset(1.0);
  const double outside = scene.Pixel();
  bool ok = Report(std::abs(inPlace - SlantedLight(0.3)) <= 3.0 / 255.0,
    "read in place: |pixel - the narrow caps' light|", std::abs(inPlace - SlantedLight(0.3)),
    3.0 / 255.0);
  const double middle = 0.5 * (SlantedLight(0.3) + SlantedLight(2.0));
  ok &= Report(outside > middle, "read a voxel toward the eye: pixel (above)", outside, middle);
  return ok;
}
}

int TestApertureVolumeMapper(int, char*[])
{
  // A window held open for the whole test: Xvfb resets when its last client leaves, and a window
  // opened during the reset fails (VTK 9.1 then aborts).
  vtkNew<vtkRenderWindow> keeper;
  keeper->SetSize(1, 1);
  keeper->SetOffScreenRendering(1);
  keeper->Render();
  bool ok = TestTwin();
  ok &= TestShell();
  ok &= TestUnusable();
  ok &= TestEnvironmentSky();
  ok &= TestPiece();
  ok &= TestLightInterpolation();
  ok &= TestSurfaceOffset();
  return ok ? 0 : 1;
}
