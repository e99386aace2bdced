/*=========================================================================

  Program:   ApertureLighting
  Module:    BenchmarkVolumeAperture.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Volume apertures, measured in one run (Markdown on stdout):
//  1. speed: vtkVolumeAperturePrecompute on a 256^3 volume (the first computation, on the
//     volume's grid), then after a transfer-function change on a 128^3 aperture grid, against
//     the marched rays of vtkVolumeApertureReference (timed on a sample of voxels, scaled);
//  2. accuracy: the light a voxel gets under one light (cap radius r, elevation e), the cap of
//     the precompute intersected with the light's cap (vtkSphericalCap, exact and smoothstep)
//     against vtkVolumeApertureReference's Monte-Carlo irradiance, over the visible voxels (those
//     of opacity >= 0.05 that are translucent or touch a translucent voxel): mean |error| over
//     the mean reference, for an opaque ball over a slab, a hollow shell with a hole, and a
//     volume from a file when one is given; and what one cap can do, the caps of the reference's
//     own marched rays over the whole sphere: by moments (what the precompute approximates) and
//     the nearest cap (the best any one cap can do, up to the reference's sampling).
//
//  3. frame cost: vtkApertureVolumeMapper against VTK's shaded vtkOpenGLGPUVolumeRayCastMapper,
//     same volume, view, light and sample distance, frames alternated, median times and their
//     ratio (at 800 x 600, the phantom at 128^3 or the first file given).
//
// Usage: BenchmarkVolumeAperture [--quick] [--accuracy | --frames] [volume.vti|.mha|.nii ...]
// --quick shrinks every size (a smoke test that the benchmark still works); --accuracy and
// --frames run only section 2 or 3.

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkImageReader2.h"
#include "vtkImageReader2Factory.h"
#include "vtkMath.h"
#include "vtkMetaImageReader.h"
#include "vtkNIFTIImageReader.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkSphericalCap.h"
#include "vtkVolumeAperturePrecompute.h"
#include "vtkVolumeApertureReference.h"
#include "vtkVolumeProperty.h"
#include "vtkXMLImageDataReader.h"

#include "vtkApertureVolumeMapper.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkLight.h"
#include "vtkOpenGLGPUVolumeRayCastMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace
{
double Since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

vtkSmartPointer<vtkImageData> MakeVolume(
  int n, const std::function<double(double, double, double)>& f)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  vtkNew<vtkFloatArray> scalars;
  scalars->SetName("density");
  scalars->SetNumberOfTuples(vtkIdType(n) * n * n);
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        scalars->SetValue(i + n * (j + vtkIdType(n) * k),
          static_cast<float>(f(i / (n - 1.0), j / (n - 1.0), k / (n - 1.0))));
      }
    }
  }
  image->GetPointData()->SetScalars(scalars);
  return image;
}

// A head-like phantom on [0, 1]^3: a translucent ellipsoid of "tissue" in a shell of "bone".
double Phantom(double x, double y, double z)
{
  const double e =
    std::pow((x - 0.5) / 0.42, 2) + std::pow((y - 0.5) / 0.36, 2) + std::pow((z - 0.5) / 0.45, 2);
  if (e > 1.0)
  {
    return 0.0;
  }
  return e > 0.8 ? 1.0 : 0.3 + 0.05 * std::sin(40.0 * x) * std::sin(30.0 * y);
}

// Density 1 inside, 0 outside, over a ramp two voxels of 64 wide at the boundary (at distance
// `inside` within it), as a scanner's partial volume blurs a boundary.
double Edge(double inside)
{
  return std::min(1.0, std::max(0.0, 0.5 + inside * 64.0 / 2.0));
}

double BallOverSlab(double x, double y, double z)
{
  const double d = std::sqrt(std::pow(x - 0.5, 2) + std::pow(y - 0.5, 2) + std::pow(z - 0.55, 2));
  return std::max(Edge(0.05 - std::abs(z - 0.2)), Edge(0.18 - d));
}

double ShellWithHole(double x, double y, double z)
{
  const double d[3] = { x - 0.5, y - 0.5, z - 0.5 };
  const double rho = vtkMath::Norm(d);
  const double angle = rho > 0.0 ? std::acos(std::min(1.0, d[2] / rho)) : 3.0;
  return std::min(Edge(0.03 - std::abs(rho - 0.33)), Edge(rho * (angle - 0.5)));
}

vtkSmartPointer<vtkVolumeProperty> Ramp(double low, double high, double unit)
{
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(low, 0.0);
  opacity->AddPoint(high, 1.0);
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(unit);
  return property;
}

void Speed(bool quick)
{
  const int n = quick ? 64 : 256;
  auto volume = MakeVolume(n, Phantom);
  auto property = Ramp(0.0, 1.0, 1.0);
  vtkNew<vtkVolumeAperturePrecompute> precompute;
  precompute->SetInputData(volume);
  precompute->SetVolumeProperty(property);
  auto start = std::chrono::steady_clock::now();
  precompute->Update();
  const double first = Since(start);
  property->GetScalarOpacity()->AddPoint(0.5, 0.1); // a transfer-function change
  precompute->SetApertureGridStep(2);
  start = std::chrono::steady_clock::now();
  precompute->Update();
  const double change = Since(start);

  vtkNew<vtkVolumeApertureReference> reference;
  reference->SetInputData(volume);
  reference->SetVolumeProperty(property);
  reference->SetSource(vtkVolumeApertureReference::SPHERE);
  reference->SetNumberOfSamples(64);
  reference->SetSampleStep(quick ? 16 : 32);
  start = std::chrono::steady_clock::now();
  reference->Update();
  const double marched = Since(start) * std::pow(reference->GetSampleStep(), 3);

  std::printf(
    "## Speed (%d^3 phantom, 64 directions, 2 threads or as many as vtkSMPTools has)\n\n", n);
  std::printf("| run | seconds | goal |\n|---|---|---|\n");
  std::printf("| first computation, %d^3 aperture grid | %.2f | <= 30 at 256^3 |\n", n, first);
  std::printf("| after a transfer-function change, %d^3 aperture grid | %.2f | <= 2 at 128^3 |\n",
    n / 2, change);
  std::printf("| marched rays (the reference's loop, 64 directions), %d^3, scaled from a sample "
              "| %.0f | |\n\n",
    n, marched);
}

// Whether voxel v is visible: opaque enough to show and not buried in opaque matter.
std::vector<char> VisibleVoxels(vtkImageData* volume, vtkVolumeProperty* property)
{
  int dims[3];
  volume->GetDimensions(dims);
  vtkDataArray* s = volume->GetPointData()->GetScalars();
  vtkPiecewiseFunction* f = property->GetScalarOpacity();
  const vtkIdType count = volume->GetNumberOfPoints();
  std::vector<double> alpha(count);
  for (vtkIdType v = 0; v < count; ++v)
  {
    alpha[v] = f->GetValue(s->GetTuple1(v));
  }
  std::vector<char> visible(count, 0);
  const vtkIdType strides[3] = { 1, dims[0], vtkIdType(dims[0]) * dims[1] };
  for (vtkIdType v = 0; v < count; ++v)
  {
    if (alpha[v] < 0.05)
    {
      continue;
    }
    bool show = alpha[v] < 0.5;
    const int ijk[3] = { int(v % dims[0]), int((v / dims[0]) % dims[1]), int(v / strides[2]) };
    for (int a = 0; a < 3 && !show; ++a)
    {
      show = (ijk[a] > 0 && alpha[v - strides[a]] < 0.5) ||
        (ijk[a] + 1 < dims[a] && alpha[v + strides[a]] < 0.5);
    }
    visible[v] = show;
  }
  return visible;
}

// The angle between the unit vector of `normals` at `id` and unit `light`.
double AngleTo(vtkDataArray* normals, vtkIdType id, const double light[3])
{
  double n[3];
  normals->GetTuple(id, n);
  return vtkMath::AngleBetweenVectors(n, light);
}

// Mean |estimate - reference| / mean reference over the visible voxels the reference samples.
void Accuracy(const char* name, vtkImageData* volume, vtkVolumeProperty* property, bool quick)
{
  vtkNew<vtkVolumeAperturePrecompute> precompute;
  precompute->SetInputData(volume);
  precompute->SetVolumeProperty(property);
  precompute->Update();
  vtkImageData* apertures = precompute->GetOutput();
  vtkDataArray* bent = apertures->GetPointData()->GetArray("BentNormal");
  vtkDataArray* radius = apertures->GetPointData()->GetArray("ApertureRadius");
  const std::vector<char> visible = VisibleVoxels(volume, property);
  // What one cap can do: the caps of the marched rays, by moments and nearest.
  vtkSmartPointer<vtkImageData> marched[2];
  for (int fit : { vtkVolumeApertureReference::MOMENTS, vtkVolumeApertureReference::NEAREST })
  {
    vtkNew<vtkVolumeApertureReference> sphere;
    sphere->SetInputData(volume);
    sphere->SetVolumeProperty(property);
    sphere->SetSource(vtkVolumeApertureReference::SPHERE);
    sphere->SetCapFit(fit);
    sphere->SetSampleStep(quick ? 4 : 2);
    sphere->SetNumberOfSamples(quick ? 64 : 256);
    sphere->Update();
    marched[fit] = sphere->GetOutput();
  }
  for (double r : { 0.064, 0.25 })
  {
    for (double elevation : { 30.0, 45.0, 60.0 })
    {
      const double e = vtkMath::RadiansFromDegrees(elevation);
      const double light[3] = { std::cos(e) * 0.8, std::cos(e) * 0.6, std::sin(e) };
      vtkNew<vtkVolumeApertureReference> reference;
      reference->SetInputData(volume);
      reference->SetVolumeProperty(property);
      reference->SetLightDirection(light[0], light[1], light[2]);
      reference->SetLightRadius(r);
      reference->SetSampleStep(quick ? 4 : 2);
      reference->SetNumberOfSamples(quick ? 32 : 128);
      reference->Update();
      vtkImageData* truth = reference->GetOutput();
      vtkDataArray* irradiance = truth->GetPointData()->GetArray("ReferenceIrradiance");
      const double area = vtkSphericalCap::SolidAngleFromCapRadius(r);
      double errors[4] = { 0.0, 0.0, 0.0, 0.0 }, sum = 0.0;
      vtkIdType counted = 0;
      for (vtkIdType p = 0; p < truth->GetNumberOfPoints(); ++p)
      {
        double x[3];
        truth->GetPoint(p, x);
        const vtkIdType v = apertures->FindPoint(x);
        if (v < 0 || !visible[v])
        {
          continue;
        }
        const double d = AngleTo(bent, v, light);
        const double rp = radius->GetTuple1(v);
        const double truthValue = irradiance->GetTuple1(p);
        errors[0] += std::abs(vtkSphericalCap::IntersectionArea(rp, r, d) / area - truthValue);
        errors[1] +=
          std::abs(vtkSphericalCap::IntersectionAreaSmoothstep(rp, r, d) / area - truthValue);
        for (int fit = 0; fit < 2; ++fit)
        {
          vtkPointData* caps = marched[fit]->GetPointData();
          const double marchedD = AngleTo(caps->GetArray("ReferenceBentNormal"), p, light);
          const double share = vtkSphericalCap::IntersectionArea(
            caps->GetArray("ReferenceApertureRadius")->GetTuple1(p), r, marchedD);
          errors[2 + fit] += std::abs(share / area - truthValue);
        }
        sum += truthValue;
        ++counted;
      }
      std::printf("| %s | %.3f | %.0f | %lld | %.1f%% | %.1f%% | %.1f%% | %.1f%% |\n", name, r,
        elevation, static_cast<long long>(counted), 100.0 * errors[0] / sum,
        100.0 * errors[1] / sum, 100.0 * errors[2] / sum, 100.0 * errors[3] / sum);
    }
  }
}

// Whether the window's last frame holds anything but the black background: a mapper whose
// shader does not compile draws nothing, and would be timed as the fastest.
bool ShowsVolume(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ShouldRerenderOff(); // the frame as drawn, not a new one
  grab->ReadFrontBufferOff();
  grab->Update();
  double range[2];
  grab->GetOutput()->GetPointData()->GetScalars()->GetRange(range, -1); // the pixels' norms
  return range[1] > 0.0;
}

// The median of `frames` renders of `window`, seconds; exits when the mapper draws nothing.
double MedianFrame(vtkRenderWindow* window, vtkVolume* volume, vtkVolumeMapper* mapper, int frames)
{
  volume->SetMapper(mapper);
  window->Render(); // the first frame builds shaders and textures (and computes apertures)
  if (!ShowsVolume(window))
  {
    std::fprintf(stderr, "%s drew nothing (a shader that does not compile?): not timed.\n",
      mapper->GetClassName());
    std::exit(EXIT_FAILURE);
  }
  std::vector<double> times;
  for (int f = 0; f < frames; ++f)
  {
    volume->RotateZ(2.0);
    const auto start = std::chrono::steady_clock::now();
    window->Render();
    times.push_back(Since(start));
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

void FrameCost(vtkImageData* volume, bool quick)
{
  double range[2];
  volume->GetScalarRange(range);
  auto property = Ramp(range[0] + 0.3 * (range[1] - range[0]), range[1], volume->GetSpacing()[0]);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(range[0], 0.9, 0.8, 0.7);
  color->AddRGBPoint(range[1], 1.0, 1.0, 1.0);
  property->SetColor(color);
  property->ShadeOn();
  property->SetInterpolationTypeToLinear();
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(quick ? 200 : 800, quick ? 150 : 600);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkVolume> actor;
  actor->SetProperty(property);
  renderer->AddVolume(actor);
  vtkNew<vtkOpenGLGPUVolumeRayCastMapper> plain;
  vtkNew<vtkApertureVolumeMapper> ours;
  vtkNew<vtkApertureVolumeMapper> blendedLight;
  blendedLight->InterpolateLightOn();
  vtkOpenGLGPUVolumeRayCastMapper* mappers[3] = { plain, ours, blendedLight };
  for (auto* mapper : mappers)
  {
    mapper->SetInputData(volume);
    mapper->AutoAdjustSampleDistancesOff();
    mapper->SetSampleDistance(0.5 * volume->GetSpacing()[0]);
  }
  actor->SetMapper(plain);
  renderer->ResetCamera();
  const int frames = quick ? 3 : 9;
  double times[3] = { 0.0, 0.0, 0.0 };
  for (int round = 0; round < 2; ++round) // alternated, so that all see the same machine
  {
    for (int m = 0; m < 3; ++m)
    {
      times[m] += MedianFrame(window, actor, mappers[m], frames);
    }
  }
  std::printf("## Frame cost (%d x %d, median of %d frames, two rounds)\n\n", window->GetSize()[0],
    window->GetSize()[1], frames);
  std::printf("| mapper | seconds a frame | ratio |\n|---|---|---|\n");
  std::printf("| VTK, gradient Phong | %.3f | 1 |\n", times[0] / 2);
  std::printf("| vtkApertureVolumeMapper, exact | %.3f | %.2f (goal <= 1.5) |\n", times[1] / 2,
    times[1] / times[0]);
  std::printf(
    "| vtkApertureVolumeMapper, exact, InterpolateLight on | %.3f | %.2f (goal <= 1.5) |\n\n",
    times[2] / 2, times[2] / times[0]);
}

vtkSmartPointer<vtkImageData> ReadVolume(const std::string& name)
{
  vtkSmartPointer<vtkImageReader2> reader;
  if (name.size() > 4 && name.substr(name.size() - 4) == ".vti")
  {
    vtkNew<vtkXMLImageDataReader> xml;
    xml->SetFileName(name.c_str());
    xml->Update();
    return xml->GetOutput();
  }
  if (name.find(".nii") != std::string::npos)
  {
    reader = vtkSmartPointer<vtkNIFTIImageReader>::New();
  }
  else
  {
    reader = vtkSmartPointer<vtkMetaImageReader>::New();
  }
  reader->SetFileName(name.c_str());
  reader->Update();
  return reader->GetOutput();
}
}

int main(int argc, char* argv[])
{
  bool quick = false;
  bool speed = true, accuracy = true, frames = true;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i)
  {
    if (std::strcmp(argv[i], "--quick") == 0)
    {
      quick = true;
    }
    else if (std::strcmp(argv[i], "--accuracy") == 0)
    {
      speed = frames = false;
    }
    else if (std::strcmp(argv[i], "--frames") == 0)
    {
      speed = accuracy = false;
    }
    else
    {
      files.emplace_back(argv[i]);
    }
  }
  if (speed)
  {
    Speed(quick);
  }
  if (frames)
  {
    FrameCost(files.empty() ? MakeVolume(quick ? 32 : 128, Phantom) : ReadVolume(files[0]), quick);
  }
  if (!accuracy)
  {
    return 0;
  }
  std::printf("## Accuracy: one light, the cap against marched rays (visible voxels)\n\n");
  std::printf("| scene | light radius | elevation | voxels | cap, exact | cap, smoothstep | "
              "marched rays' cap, moments | marched rays' nearest cap |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  const int n = quick ? 32 : 64;
  Accuracy("opaque ball over a slab", MakeVolume(n, BallOverSlab), Ramp(0.0, 1.0, 1.0), quick);
  Accuracy("hollow shell with a hole", MakeVolume(n, ShellWithHole), Ramp(0.0, 1.0, 1.0), quick);
  for (const std::string& file : files)
  {
    auto volume = ReadVolume(file);
    double range[2];
    volume->GetScalarRange(range);
    double spacing[3];
    volume->GetSpacing(spacing);
    // Opaque above the middle of the range, over one voxel.
    Accuracy(file.c_str(), volume,
      Ramp(range[0] + 0.3 * (range[1] - range[0]), range[0] + 0.6 * (range[1] - range[0]),
        std::min({ spacing[0], spacing[1], spacing[2] })),
      quick);
  }
  return 0;
}
