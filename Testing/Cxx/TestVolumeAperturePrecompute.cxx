/*=========================================================================

  Program:   ApertureLighting
  Module:    TestVolumeAperturePrecompute.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkVolumeAperturePrecompute on volumes whose answer is known: free space, an opaque half-space,
// an opaque shell with one round opening, against vtkVolumeApertureReference's marched rays on a
// cloud of soft balls (whole grid and a coarser one), the reference's nearest cap, pieces against
// the whole, and bad input.

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkSphericalCap.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTestErrorObserver.h"
#include "vtkVolumeAperturePrecompute.h"
#include "vtkVolumeApertureReference.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>

namespace
{
constexpr double Pi = 3.14159265358979323846;

// A float volume of n^3 voxels, spacing 1, origin 0, scalars from f(x, y, z).
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
        scalars->SetValue(i + n * (j + vtkIdType(n) * k), static_cast<float>(f(i, j, k)));
      }
    }
  }
  image->GetPointData()->SetScalars(scalars);
  return image;
}

// Opacity 0 at 0 and 1 at 1 (opaque), per voxel.
vtkSmartPointer<vtkVolumeProperty> MakeProperty()
{
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(1.0, 1.0);
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(1.0);
  return property;
}

vtkSmartPointer<vtkImageData> Apertures(
  vtkImageData* volume, vtkVolumeProperty* property, double distance, int directions, int step = 1)
{
  vtkNew<vtkVolumeAperturePrecompute> precompute;
  precompute->SetInputData(volume);
  precompute->SetVolumeProperty(property);
  precompute->SetMaximumDistance(distance);
  precompute->SetNumberOfDirections(directions);
  precompute->SetApertureGridStep(step);
  precompute->Update();
  auto result = vtkSmartPointer<vtkImageData>::New();
  result->ShallowCopy(precompute->GetOutput());
  return result;
}

// The radius at (i, j, k); `prefix` "Reference" reads vtkVolumeApertureReference's output.
double RadiusAt(vtkImageData* apertures, int i, int j, int k, const std::string& prefix = "")
{
  int ijk[3] = { i, j, k };
  return apertures->GetPointData()
    ->GetArray((prefix + "ApertureRadius").c_str())
    ->GetTuple1(apertures->ComputePointId(ijk));
}

// Angle in degrees between the bent normal at (i, j, k) and unit `axis`.
double BentAngle(vtkImageData* apertures, int i, int j, int k, const double axis[3],
  const std::string& prefix = "")
{
  int ijk[3] = { i, j, k };
  double bent[3];
  apertures->GetPointData()
    ->GetArray((prefix + "BentNormal").c_str())
    ->GetTuple(apertures->ComputePointId(ijk), bent);
  return vtkMath::DegreesFromRadians(std::acos(std::min(1.0, vtkMath::Dot(bent, axis))));
}

bool Check(bool ok, const char* what, double value)
{
  std::printf("%-62s %10.4f %s\n", what, value, ok ? "ok" : "FAILED");
  return ok;
}

// Opaque below z = 20 (48^3).
vtkSmartPointer<vtkImageData> HalfSpace()
{
  return MakeVolume(48, [](double, double, double z) { return z < 20 ? 1.0 : 0.0; });
}

// A shell 3 voxels thick about (32, 32, 32) (65^3), open within alpha of unit `axis`.
vtkSmartPointer<vtkImageData> Shell(double alpha, const double axis[3])
{
  return MakeVolume(65,
    [&](double x, double y, double z)
    {
      const double d[3] = { x - 32, y - 32, z - 32 };
      const double rho = vtkMath::Norm(d);
      const bool open = rho > 0 && vtkMath::Dot(d, axis) / rho > std::cos(alpha);
      return rho >= 22 && rho <= 25 && !open ? 1.0 : 0.0;
    });
}

bool TestAnalytic(vtkVolumeProperty* property)
{
  bool ok = true;
  // Free space: the whole sphere.
  auto empty = MakeVolume(16, [](double, double, double) { return 0.0; });
  auto free = Apertures(empty, property, 0.0, 64);
  double range[2];
  free->GetPointData()->GetArray("ApertureRadius")->GetRange(range);
  ok &= Check(range[0] > Pi - 1e-3, "free space: smallest radius (pi)", range[0]);

  // Opaque below z = 20: the first empty layer sees half the sphere, about +z.
  auto half = HalfSpace();
  const double up[3] = { 0.0, 0.0, 1.0 };
  for (int directions : { 64, 256 })
  {
    auto apertures = Apertures(half, property, 40.0, directions);
    const double r = RadiusAt(apertures, 24, 24, 20);
    const double angle = BentAngle(apertures, 24, 24, 20, up);
    std::printf("half-space, %d directions:\n", directions);
    ok &= Check(std::abs(r - 0.5 * Pi) <= 0.05, "  radius on the surface (pi/2 +- 0.05)", r);
    ok &= Check(angle <= 3.0, "  bent normal from the normal, degrees (<= 3)", angle);
    ok &= Check(RadiusAt(apertures, 24, 24, 10) < 0.05, "  radius deep inside (0)",
      RadiusAt(apertures, 24, 24, 10));
  }

  double axis[3] = { 0.3, -0.5, 0.81 };
  vtkMath::Normalize(axis);
  for (double alpha : { 0.35, 0.6, 1.0 })
  {
    auto apertures = Apertures(Shell(alpha, axis), property, 60.0, 1024);
    const double r = RadiusAt(apertures, 32, 32, 32);
    const double angle = BentAngle(apertures, 32, 32, 32, axis);
    std::printf("shell open by %.2f rad, 1024 directions:\n", alpha);
    ok &= Check(std::abs(r - alpha) <= 0.05, "  radius at the centre (alpha +- 0.05)", r);
    ok &= Check(angle <= 3.0, "  bent normal from the opening's axis, degrees (<= 3)", angle);
  }
  return ok;
}

// vtkVolumeApertureReference on voxel ijk alone: SPHERE by `fit`, or LIGHT from unit `light`.
vtkSmartPointer<vtkImageData> ReferenceAt(vtkImageData* volume, vtkVolumeProperty* property,
  const int ijk[3], double distance, int fit, const double* light = nullptr)
{
  vtkNew<vtkVolumeApertureReference> reference;
  reference->SetInputData(volume);
  reference->SetVolumeProperty(property);
  reference->SetMaximumDistance(distance);
  reference->SetSampleStep(1);
  reference->SetNumberOfSamples(light ? 256 : 4096);
  reference->SetSource(
    light ? vtkVolumeApertureReference::LIGHT : vtkVolumeApertureReference::SPHERE);
  reference->SetCapFit(fit);
  if (light)
  {
    reference->SetLightDirection(light[0], light[1], light[2]);
    reference->SetLightRadius(0.1);
  }
  const int extent[6] = { ijk[0], ijk[0], ijk[1], ijk[1], ijk[2], ijk[2] };
  reference->UpdateExtent(extent);
  auto result = vtkSmartPointer<vtkImageData>::New();
  result->ShallowCopy(reference->GetOutput());
  return result;
}

// The nearest cap of the reference's marched rays: the known caps where one cap is exact, and
// nearer a light's truth than the moments' cap where it is not (a ring of sky about a ball
// overhead, whose moments' cap shrinks about the zenith where the nearest keeps the hemisphere).
bool TestNearestCap(vtkVolumeProperty* property)
{
  bool ok = true;
  const int centre[3] = { 32, 32, 32 };
  double axis[3] = { 0.3, -0.5, 0.81 };
  vtkMath::Normalize(axis);
  for (double alpha : { 0.35, 1.0 })
  {
    auto cap =
      ReferenceAt(Shell(alpha, axis), property, centre, 60.0, vtkVolumeApertureReference::NEAREST);
    std::printf("reference's nearest cap, shell open by %.2f rad:\n", alpha);
    const double r = RadiusAt(cap, 32, 32, 32, "Reference");
    ok &= Check(std::abs(r - alpha) <= 0.05, "  radius at the centre (alpha +- 0.05)", r);
    const double angle = BentAngle(cap, 32, 32, 32, axis, "Reference");
    ok &= Check(angle <= 3.0, "  axis from the opening's axis, degrees (<= 3)", angle);
  }
  const int surface[3] = { 24, 24, 20 };
  const double up[3] = { 0.0, 0.0, 1.0 };
  auto half =
    ReferenceAt(HalfSpace(), property, surface, 40.0, vtkVolumeApertureReference::NEAREST);
  std::printf("reference's nearest cap, half-space:\n");
  ok &= Check(std::abs(RadiusAt(half, 24, 24, 20, "Reference") - 0.5 * Pi) <= 0.05,
    "  radius on the surface (pi/2 +- 0.05)", RadiusAt(half, 24, 24, 20, "Reference"));
  ok &= Check(BentAngle(half, 24, 24, 20, up, "Reference") <= 3.0,
    "  axis from the normal, degrees (<= 3)", BentAngle(half, 24, 24, 20, up, "Reference"));

  // The half-space with a ball of radius 6 centred 12 above the voxel: 30 degrees of it.
  auto ring = MakeVolume(48,
    [](double x, double y, double z)
    {
      const double d[3] = { x - 24, y - 24, z - 32 };
      return z < 20 || vtkMath::Norm(d) <= 6.0 ? 1.0 : 0.0;
    });
  vtkSmartPointer<vtkImageData> caps[2];
  for (int fit : { vtkVolumeApertureReference::MOMENTS, vtkVolumeApertureReference::NEAREST })
  {
    caps[fit] = ReferenceAt(ring, property, surface, 40.0, fit);
  }
  double errors[2] = { 0.0, 0.0 };
  const int lights = 24;
  for (int l = 0; l < lights; ++l)
  {
    // Lights spread over the upper hemisphere (elevations 7.5 to 82.5 degrees).
    const double z = (l + 0.5) / lights, phi = 2.39996323 * l, rho = std::sqrt(1.0 - z * z);
    const double light[3] = { rho * std::cos(phi), rho * std::sin(phi), z };
    auto truth =
      ReferenceAt(ring, property, surface, 40.0, vtkVolumeApertureReference::MOMENTS, light);
    const double value = truth->GetPointData()->GetArray("ReferenceIrradiance")->GetTuple1(0);
    for (int fit = 0; fit < 2; ++fit)
    {
      const double d =
        vtkMath::RadiansFromDegrees(BentAngle(caps[fit], 24, 24, 20, light, "Reference"));
      const double share =
        vtkSphericalCap::IntersectionArea(RadiusAt(caps[fit], 24, 24, 20, "Reference"), 0.1, d) /
        vtkSphericalCap::SolidAngleFromCapRadius(0.1);
      errors[fit] += std::abs(share - value) / lights;
    }
  }
  std::printf("ring of sky about a ball overhead, %d lights of 0.1 rad, mean |share - truth|:\n"
              "  moments' cap %.4f\n",
    lights, errors[0]);
  ok &= Check(errors[1] < 0.75 * errors[0], "  nearest cap (< 3/4 of the moments')", errors[1]);
  return ok;
}

// Soft balls of random size and density in a box.
vtkSmartPointer<vtkImageData> Cloud(int n)
{
  vtkMath::RandomSeed(7);
  std::vector<double> balls;
  for (int b = 0; b < 14; ++b)
  {
    balls.push_back(vtkMath::Random(0.15, 0.85) * n);
    balls.push_back(vtkMath::Random(0.15, 0.85) * n);
    balls.push_back(vtkMath::Random(0.15, 0.85) * n);
    balls.push_back(vtkMath::Random(0.05, 0.15) * n);
    balls.push_back(vtkMath::Random(0.2, 1.0));
  }
  return MakeVolume(n,
    [&](double x, double y, double z)
    {
      double density = 0.0;
      for (size_t b = 0; b < balls.size(); b += 5)
      {
        const double d[3] = { x - balls[b], y - balls[b + 1], z - balls[b + 2] };
        if (vtkMath::Norm(d) < balls[b + 3])
        {
          density = std::max(density, balls[b + 4]);
        }
      }
      return density;
    });
}

// Mean and largest |radius - reference| and mean bent-normal angle over the reference's points.
bool CompareWithReference(
  vtkImageData* volume, vtkVolumeProperty* property, int step, double meanLimit)
{
  const double distance = 16.0;
  auto apertures = Apertures(volume, property, distance, 64, step);
  vtkNew<vtkVolumeApertureReference> reference;
  reference->SetInputData(volume);
  reference->SetVolumeProperty(property);
  reference->SetSource(vtkVolumeApertureReference::SPHERE);
  reference->SetMaximumDistance(distance);
  reference->SetApertureGridStep(step);
  reference->SetSampleStep(4 / step);
  reference->SetNumberOfSamples(1024);
  reference->Update();
  vtkImageData* truth = reference->GetOutput();
  vtkDataArray* radius = truth->GetPointData()->GetArray("ReferenceApertureRadius");
  vtkDataArray* bent = truth->GetPointData()->GetArray("ReferenceBentNormal");
  double sum = 0.0, largest = 0.0, angles = 0.0;
  vtkIdType counted = 0, bentCounted = 0;
  for (vtkIdType p = 0; p < truth->GetNumberOfPoints(); ++p)
  {
    double x[3], pcoords[3];
    truth->GetPoint(p, x);
    int index[3];
    apertures->ComputeStructuredCoordinates(x, index, pcoords);
    for (int a = 0; a < 3; ++a)
    {
      index[a] += pcoords[a] > 0.5 ? 1 : 0;
    }
    const double r = RadiusAt(apertures, index[0], index[1], index[2]);
    const double delta = std::abs(r - radius->GetTuple1(p));
    sum += delta;
    largest = std::max(largest, delta);
    ++counted;
    if (radius->GetTuple1(p) > 0.3 && radius->GetTuple1(p) < 2.8)
    {
      double axis[3];
      bent->GetTuple(p, axis);
      angles += BentAngle(apertures, index[0], index[1], index[2], axis);
      ++bentCounted;
    }
  }
  std::printf(
    "cloud, aperture grid step %d, %lld points:\n", step, static_cast<long long>(counted));
  bool ok = Check(sum / counted <= meanLimit, "  mean |radius - reference|", sum / counted);
  std::printf("  largest |radius - reference| %.4f\n", largest);
  ok &= Check(angles / bentCounted <= 10.0, "  mean bent-normal angle, degrees (<= 10)",
    angles / bentCounted);
  return ok;
}

// Two pieces of the output against the whole.
bool TestPieces(vtkImageData* volume, vtkVolumeProperty* property)
{
  vtkNew<vtkVolumeAperturePrecompute> precompute;
  precompute->SetInputData(volume);
  precompute->SetVolumeProperty(property);
  precompute->SetMaximumDistance(6.0);
  precompute->Update();
  vtkNew<vtkImageData> whole;
  whole->DeepCopy(precompute->GetOutput());
  bool ok = Check(whole->GetPointData()->GetArray("density") != nullptr,
    "the input's arrays are kept on its grid", 1.0);
  double largest = 0.0;
  vtkIdType parts = 0;
  for (int piece = 0; piece < 2; ++piece)
  {
    precompute->UpdatePiece(piece, 2, 0);
    vtkImageData* part = precompute->GetOutput();
    parts += part->GetNumberOfPoints();
    vtkDataArray* r = part->GetPointData()->GetArray("ApertureRadius");
    for (vtkIdType p = 0; p < part->GetNumberOfPoints(); ++p)
    {
      double x[3];
      part->GetPoint(p, x);
      const vtkIdType q = whole->FindPoint(x);
      largest = std::max(largest,
        std::abs(
          r->GetTuple1(p) - whole->GetPointData()->GetArray("ApertureRadius")->GetTuple1(q)));
    }
  }
  ok &=
    Check(parts < whole->GetNumberOfPoints() + 48 * 48 * 2 && parts >= whole->GetNumberOfPoints(),
      "two pieces cover the whole (points, over the whole's)",
      static_cast<double>(parts) / whole->GetNumberOfPoints());
  return ok &&
    Check(largest <= 0.01, "two pieces against the whole: largest |delta radius|", largest);
}

bool ExpectError(vtkImageData* volume, vtkVolumeProperty* property, const char* what)
{
  vtkNew<vtkTest::ErrorObserver> errors, executive;
  vtkNew<vtkVolumeAperturePrecompute> precompute;
  precompute->AddObserver(vtkCommand::ErrorEvent, errors);
  precompute->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executive);
  precompute->SetInputData(volume);
  precompute->SetVolumeProperty(property);
  precompute->Update();
  const bool ok = errors->GetError() &&
    precompute->GetOutput()->GetPointData()->GetArray("ApertureRadius") == nullptr;
  // The message without VTK's "ERROR: In file, line" header.
  const std::string message = errors->GetErrorMessage();
  const size_t start = message.find("): ");
  std::printf("bad input, %-44s %s: %s", what, ok ? "ok" : "FAILED",
    start == std::string::npos ? "(no error)\n" : message.substr(start + 3).c_str());
  return ok;
}

bool TestBadInput(vtkVolumeProperty* property)
{
  bool ok = true;
  auto good = MakeVolume(8, [](double, double, double) { return 0.5; });
  ok &= ExpectError(good, nullptr, "no volume property");
  auto nan = MakeVolume(8,
    [](double x, double, double)
    { return x == 3 ? std::numeric_limits<double>::quiet_NaN() : 0.5; });
  ok &= ExpectError(nan, property, "a NaN voxel");
  auto one = MakeVolume(1, [](double, double, double) { return 1.0; });
  ok &= ExpectError(one, property, "one voxel");
  vtkNew<vtkImageData> vectors;
  vectors->SetDimensions(4, 4, 4);
  vectors->AllocateScalars(VTK_FLOAT, 3);
  ok &= ExpectError(vectors, property, "three components");
  vtkNew<vtkImageData> flat;
  flat->DeepCopy(good);
  flat->SetSpacing(1.0, 0.0, 1.0);
  ok &= ExpectError(flat, property, "zero spacing");
  vtkNew<vtkImageData> none;
  none->SetDimensions(4, 4, 4);
  ok &= ExpectError(none, property, "no scalars");
  vtkNew<vtkVolumeProperty> noOpacity;
  noOpacity->SetScalarOpacity(nullptr);
  // A property always has a default opacity: it is usable, so no error is expected there.
  vtkNew<vtkVolumeAperturePrecompute> precompute;
  precompute->SetInputData(good);
  precompute->SetVolumeProperty(noOpacity);
  precompute->Update();
  ok &= Check(precompute->GetOutput()->GetPointData()->GetArray("ApertureRadius") != nullptr,
    "a property with VTK's default opacity computes", 1.0);
  return ok;
}
}

int TestVolumeAperturePrecompute(int, char*[])
{
  auto property = MakeProperty();
  bool ok = TestAnalytic(property);
  auto cloud = Cloud(48);
  ok &= CompareWithReference(cloud, property, 1, 0.06);
  ok &= CompareWithReference(cloud, property, 2, 0.10);
  ok &= TestNearestCap(property);
  ok &= TestPieces(cloud, property);
  ok &= TestBadInput(property);
  return ok ? 0 : 1;
}
