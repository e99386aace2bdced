/*=========================================================================

  Program:   ApertureLighting
  Module:    TestHorizonLighting.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkHorizonLighting against numerical integration: lights of every size over random horizons
// and normals, the sky through the sectors' wedges, the 8-bit code, and bad input.

#include "vtkApertureTestHarness.h"
#include "vtkHorizonLighting.h"
#include "vtkSphericalCap.h"

#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <vector>

namespace
{
constexpr double Pi = vtkMath::Pi();
using vtkApertureTest::Check;

// The elevation and azimuth of a direction.
void Angles(const double w[3], double& elevation, double& azimuth)
{
  elevation = std::asin(std::min(1.0, std::max(-1.0, w[2])));
  azimuth = std::atan2(w[1], w[0]);
}

// ∫ max(0, n·ω) over the part of the cap above the interpolated horizon, by a polar grid of
// rings × spokes around the light's axis, times the light's radiance.
double BruteLight(const double n[3], const std::vector<float>& h, const double l[3], double rl)
{
  const int rings = 600, spokes = 600;
  double t[3], b[3];
  vtkMath::Perpendiculars(l, t, b, 0.0);
  double sum = 0.0;
  for (int i = 0; i < rings; ++i)
  {
    const double theta0 = rl * i / rings, theta1 = rl * (i + 1) / rings;
    const double theta = 0.5 * (theta0 + theta1);
    const double area = (std::cos(theta0) - std::cos(theta1)) * 2.0 * Pi / spokes;
    for (int j = 0; j < spokes; ++j)
    {
      const double psi = 2.0 * Pi * (j + 0.5) / spokes;
      double w[3];
      for (int k = 0; k < 3; ++k)
      {
        w[k] =
          std::cos(theta) * l[k] + std::sin(theta) * (std::cos(psi) * t[k] + std::sin(psi) * b[k]);
      }
      double e, a;
      Angles(w, e, a);
      const double cosine = vtkMath::Dot(n, w);
      if (e > vtkHorizonLighting::HorizonAt(h.data(), static_cast<int>(h.size()), a) &&
        cosine > 0.0)
      {
        sum += cosine * area;
      }
    }
  }
  return sum * vtkSphericalCap::LightRadiance(rl);
}

// The sky as SkyTransfer() defines it, summed over a fine grid of each sector's wedge above
// max(h_k, the tangent plane at its middle): (1/π) ∫ n·ω and Ω / 2π.
void BruteSky(const double n[3], const std::vector<float>& h, double& cosine, double& open)
{
  const int sectors = static_cast<int>(h.size()), perSector = 64, elevations = 2000;
  cosine = open = 0.0;
  for (int k = 0; k < sectors; ++k)
  {
    const double middle = 2.0 * Pi * (k + 0.5) / sectors;
    const double tangent = std::atan(-(n[0] * std::cos(middle) + n[1] * std::sin(middle)) / n[2]);
    const double bottom = std::max(double(h[k]), tangent);
    for (int j = 0; j < perSector; ++j)
    {
      const double phi = 2.0 * Pi * (k + (j + 0.5) / perSector) / sectors;
      const double dphi = 2.0 * Pi / sectors / perSector;
      for (int i = 0; i < elevations; ++i)
      {
        const double e0 = bottom + (0.5 * Pi - bottom) * i / elevations;
        const double e1 = bottom + (0.5 * Pi - bottom) * (i + 1) / elevations;
        const double e = 0.5 * (e0 + e1);
        const double w[3] = { std::cos(e) * std::cos(phi), std::cos(e) * std::sin(phi),
          std::sin(e) };
        const double area = (std::sin(e1) - std::sin(e0)) * dphi;
        cosine += vtkMath::Dot(n, w) * area;
        open += area;
      }
    }
  }
  cosine /= Pi;
  open /= 2.0 * Pi;
}

// Smooth random horizons: a few harmonics around a level, within [-pi/2, pi/2].
std::vector<float> RandomHorizons(vtkMinimalStandardRandomSequence* random, int sectors)
{
  auto next = [random](double low, double high)
  {
    random->Next();
    return random->GetRangeValue(low, high);
  };
  const double level = next(-0.3, 0.5);
  double amplitude[3], phase[3];
  for (int m = 0; m < 3; ++m)
  {
    amplitude[m] = next(0.0, 0.3 / (m + 1));
    phase[m] = next(0.0, 2.0 * Pi);
  }
  std::vector<float> h(sectors);
  for (int k = 0; k < sectors; ++k)
  {
    double value = level;
    for (int m = 0; m < 3; ++m)
    {
      value += amplitude[m] * std::cos((m + 1) * 2.0 * Pi * (k + 0.5) / sectors + phase[m]);
    }
    h[k] = static_cast<float>(std::min(0.5 * Pi, std::max(-0.5 * Pi, value)));
  }
  return h;
}

void TestCode()
{
  int previous = -1;
  double worst = 0.0;
  for (int i = 0; i <= 2000; ++i)
  {
    const double h = -0.5 * Pi + Pi * i / 2000.0;
    const int code = vtkHorizonLighting::EncodeAngle(h);
    Check(code >= previous && code >= 0 && code <= 255, "codes rise with the angle", code, h);
    previous = code;
    const double back = vtkHorizonLighting::DecodeAngle(code);
    // Half a step of t = sign(h) sqrt(|h| / (pi/2)): pi |t| / 255 + the step's own curvature.
    const double t = std::sqrt(std::abs(h) / (0.5 * Pi));
    const double bound = 0.5 * Pi * (2.0 * t + 1.0 / 127.5) / 255.0 + 1e-12;
    Check(std::abs(back - h) <= bound, "a decoded angle within half a code's step", back, h);
    if (std::abs(h) < 0.2)
    {
      worst = std::max(worst, std::abs(back - h));
    }
  }
  std::cout << "8-bit horizons: max error within 0.2 rad of the horizontal plane " << worst
            << " rad\n";
  Check(worst < 0.0055, "steps near the horizontal plane are fine", worst, 0.0055);
  Check(vtkHorizonLighting::DecodeAngle(0) == -0.5 * Pi, "code 0 is -pi/2");
  Check(vtkHorizonLighting::DecodeAngle(255) == 0.5 * Pi, "code 255 is pi/2");
  Check(vtkHorizonLighting::EncodeAngle(std::numeric_limits<double>::quiet_NaN()) == 255,
    "NaN encodes as closed");
  Check(vtkHorizonLighting::EncodeAngle(9.0) == 255 && vtkHorizonLighting::EncodeAngle(-9.0) == 0,
    "angles past the poles are clamped");
}

void TestHorizonAt()
{
  const std::vector<float> h = { 0.1f, 0.3f, -0.2f, 0.5f };
  for (int k = 0; k < 4; ++k)
  {
    const double middle = 2.0 * Pi * (k + 0.5) / 4.0;
    Check(std::abs(vtkHorizonLighting::HorizonAt(h.data(), 4, middle) - h[k]) < 1e-6,
      "the horizon at a sector's middle is the sector's");
    Check(std::abs(vtkHorizonLighting::HorizonAt(h.data(), 4, middle - 2.0 * Pi) - h[k]) < 1e-6,
      "azimuths wrap around");
  }
  // Halfway between the last sector's middle and the first's, across 0.
  Check(std::abs(vtkHorizonLighting::HorizonAt(h.data(), 4, 0.0) - 0.3) < 1e-6,
    "linear between sector middles across azimuth 0");
}

// Every light size and elevation over random horizons and normals.
void TestLights()
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(7);
  auto next = [&random](double low, double high)
  {
    random->Next();
    return random->GetRangeValue(low, high);
  };
  const double radii[] = { 0.001, 0.0047, 0.064, 0.314, 0.785 };
  double worst[5] = { 0, 0, 0, 0, 0 };
  for (int i = 0; i < 150; ++i)
  {
    const int sectors = i % 3 == 0 ? 8 : 32;
    const std::vector<float> h = RandomHorizons(random, sectors);
    double n[3] = { next(-0.5, 0.5), next(-0.5, 0.5), 1.0 };
    vtkMath::Normalize(n);
    const int r = i % 5;
    const double rl = radii[r];
    // Lights near the horizons half the time, anywhere above the plane otherwise.
    const double azimuth = next(0.0, 2.0 * Pi);
    const double base = vtkHorizonLighting::HorizonAt(h.data(), sectors, azimuth);
    const double elevation = i % 2 == 0
      ? std::min(0.5 * Pi, std::max(-0.2, base + next(-1.5, 1.5) * rl))
      : next(-0.1, 0.5 * Pi);
    const double l[3] = { std::cos(elevation) * std::cos(azimuth),
      std::cos(elevation) * std::sin(azimuth), std::sin(elevation) };
    const double got = vtkHorizonLighting::LightTransfer(n, h.data(), sectors, l, rl);
    const double want = BruteLight(n, h, l, rl);
    worst[r] = std::max(worst[r], std::abs(got - want));
    Check(std::abs(got - want) <= 0.005, "a light above the horizons", got, want);
  }
  for (int r = 0; r < 5; ++r)
  {
    std::cout << "LightTransfer, r = " << radii[r] << ": max |closed form - grid| = " << worst[r]
              << "\n";
  }
}

void TestSky()
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(3);
  for (int i = 0; i < 12; ++i)
  {
    const int sectors = i % 2 == 0 ? 16 : 32;
    const std::vector<float> h = RandomHorizons(random, sectors);
    random->Next();
    const double tilt = random->GetRangeValue(0.0, 0.7);
    double n[3] = { std::sin(tilt), 0.2 * std::sin(tilt), std::cos(tilt) };
    vtkMath::Normalize(n);
    double cosine, open;
    BruteSky(n, h, cosine, open);
    const double got = vtkHorizonLighting::SkyTransfer(n, h.data(), sectors, 0.0, 0.0, true);
    const double gotOpen = vtkHorizonLighting::SkyTransfer(n, h.data(), sectors, 0.0, 0.0, false);
    Check(std::abs(got - cosine) < 1e-4, "the cosine-weighted sky through the wedges", got, cosine);
    Check(std::abs(gotOpen - open) < 1e-4, "the open fraction of the hemisphere", gotOpen, open);
  }
  // An open plane: the whole sky, and a light takes its own share.
  const std::vector<float> flat(32, static_cast<float>(-0.5 * Pi));
  const double up[3] = { 0.0, 0.0, 2.0 };
  Check(
    std::abs(vtkHorizonLighting::SkyTransfer(up, flat.data(), 32, 0.0, 0.0, true) - 1.0) < 1e-12,
    "an open plane sees the whole sky");
  const double l[3] = { 0.3, 0.1, 0.9 };
  double coverage, cosineCoverage;
  const double light =
    vtkHorizonLighting::LightTransfer(up, flat.data(), 32, l, 0.3, &coverage, &cosineCoverage);
  double unit[3] = { l[0], l[1], l[2] };
  vtkMath::Normalize(unit);
  Check(std::abs(light - unit[2]) < 1e-12, "an unoccluded light gives n . l", light, unit[2]);
  Check(std::abs(coverage - vtkSphericalCap::SolidAngleFromCapRadius(0.3)) < 1e-12,
    "an unoccluded light covers its cap");
  const double sky =
    vtkHorizonLighting::SkyTransfer(up, flat.data(), 32, coverage, cosineCoverage, true);
  Check(std::abs(sky - (1.0 - cosineCoverage / Pi)) < 1e-12, "the sky less the light's share");
}

void TestBadInput()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<float> h(8, 0.1f);
  const double n[3] = { 0.0, 0.0, 1.0 }, l[3] = { 0.0, 0.6, 0.8 }, zero[3] = { 0, 0, 0 };
  const double bad[3] = { nan, 0.0, 1.0 };
  double coverage = -1.0;
  Check(vtkHorizonLighting::LightTransfer(bad, h.data(), 8, l, 0.1, &coverage) == 0.0 &&
      coverage == 0.0,
    "a NaN normal gives 0");
  Check(vtkHorizonLighting::LightTransfer(n, h.data(), 8, zero, 0.1) == 0.0, "no light axis");
  Check(vtkHorizonLighting::LightTransfer(n, h.data(), 0, l, 0.1) == 0.0, "no sectors");
  Check(vtkHorizonLighting::LightTransfer(n, h.data(), 8, l, nan) == 0.0, "a NaN radius");
  Check(vtkHorizonLighting::SkyTransfer(bad, h.data(), 8, 0.0, 0.0, true) == 0.0, "a NaN sky");
  const double huge = vtkHorizonLighting::LightTransfer(n, h.data(), 8, l, 50.0);
  Check(std::isfinite(huge) && huge >= 0.0, "an oversized light is clamped", huge, 0.0);
}
}

int TestHorizonLighting(int, char*[])
{
  TestCode();
  TestHorizonAt();
  TestLights();
  TestSky();
  TestBadInput();
  return vtkApertureTest::Result();
}
