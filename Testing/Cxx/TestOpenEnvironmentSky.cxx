/*=========================================================================

  Program:   ApertureLighting
  Module:    TestOpenEnvironmentSky.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// An HDR environment through what a point sees beyond one cap: the open wedges above horizons
// (vtkHorizonLighting::EnvironmentSkyTransfer() from vtkEnvironmentMap::NewWedgeTable()) and the
// open cells of a visibility mask (vtkVisibilityMask::EnvironmentSkyTransfer() from
// vtkEnvironmentMap::NewMeanRadianceTable()). For both: an environment of radiance 1 gives the
// uniform sky's SkyTransfer(), with and without the lights' coverage; a smooth coloured
// environment, turned against a turned and scaled frame, gives the open parts' integral summed by
// brute force; bad input gives zeros.

#include "vtkApertureTestEnvironment.h"
#include "vtkApertureTestHarness.h"
#include "vtkEnvironmentMap.h"
#include "vtkHorizonLighting.h"
#include "vtkVisibilityMask.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace
{
constexpr double Pi = vtkMath::Pi();
constexpr int Sectors = 32;
constexpr int Azimuths = 256;
constexpr int Elevations = 64;
using vtkApertureTest::Check;

// A latitude-longitude image of radiance f(direction in the environment's own frame).
vtkSmartPointer<vtkImageData> LatLong(
  int w, int h, const std::function<void(const double d[3], double rgb[3])>& f)
{
  return vtkApertureTest::LatLong(w, h,
    [&f](double u, double v, double rgb[3])
    {
      const double phi = 2.0 * Pi * (u - 0.5), theta = Pi * (v - 0.5);
      const double d[3] = { std::cos(theta) * std::cos(phi), std::cos(theta) * std::sin(phi),
        std::sin(theta) };
      f(d, rgb);
    });
}

// A sky brighter toward its zenith, a broad warm glow near its horizon and a cool floor.
void SmoothSky(const double d[3], double rgb[3])
{
  const double glow[3] = { 0.6, 0.3, 0.2 };
  const double lobe = std::exp(6.0 * (vtkMath::Dot(d, glow) / vtkMath::Norm(glow) - 1.0));
  rgb[0] = 0.3 + 0.5 * std::max(0.0, d[2]) + 4.0 * lobe;
  rgb[1] = 0.4 + 0.6 * std::max(0.0, d[2]) + 2.0 * lobe;
  rgb[2] = 0.2 + 0.9 * std::max(0.0, d[2]) + 0.5 * lobe;
}

// Smooth random horizons and a normal facing more or less up.
void RandomPoint(vtkMinimalStandardRandomSequence* random, std::vector<float>& h, double n[3])
{
  auto next = [random](double low, double high)
  {
    random->Next();
    return random->GetRangeValue(low, high);
  };
  const double level = next(-0.4, 0.6), amplitude = next(0.0, 0.5), phase = next(0.0, 2 * Pi);
  h.resize(Sectors);
  for (int k = 0; k < Sectors; ++k)
  {
    const double value = level + amplitude * std::cos(2 * Pi * (k + 0.5) / Sectors + phase);
    h[k] = static_cast<float>(std::min(0.5 * Pi, std::max(-0.5 * Pi, value)));
  }
  n[0] = next(-0.7, 0.7);
  n[1] = next(-0.7, 0.7);
  n[2] = next(0.4, 1.2);
}

// (1/π) Σ_k ∫ L(ω) n·ω dω over sector k above max(h_k, the tangent plane at its middle), by a
// fine grid of each wedge, with the frame's directions taken to world by frameToWorld.
void BruteEnvironment(vtkEnvironmentMap* environment, const double frameToWorld[9],
  const double normal[3], const std::vector<float>& h, double rgb[3])
{
  double n[3] = { normal[0], normal[1], normal[2] };
  vtkMath::Normalize(n);
  const int perSector = 24, rows = 240;
  rgb[0] = rgb[1] = rgb[2] = 0.0;
  for (int k = 0; k < Sectors; ++k)
  {
    const double middle = 2.0 * Pi * (k + 0.5) / Sectors;
    const double tangent = std::atan(-(n[0] * std::cos(middle) + n[1] * std::sin(middle)) / n[2]);
    const double bottom = std::max(double(h[k]), tangent);
    const double dphi = 2.0 * Pi / Sectors / perSector;
    for (int j = 0; j < perSector; ++j)
    {
      const double phi = 2.0 * Pi * k / Sectors + (j + 0.5) * dphi;
      for (int i = 0; i < rows; ++i)
      {
        const double e0 = bottom + (0.5 * Pi - bottom) * i / rows;
        const double e1 = bottom + (0.5 * Pi - bottom) * (i + 1) / rows;
        const double e = 0.5 * (e0 + e1);
        const double w[3] = { std::cos(e) * std::cos(phi), std::cos(e) * std::sin(phi),
          std::sin(e) };
        double world[3], radiance[3];
        for (int a = 0; a < 3; ++a)
        {
          world[a] = vtkMath::Dot(frameToWorld + 3 * a, w);
        }
        environment->Radiance(world, radiance);
        const double weight = vtkMath::Dot(n, w) * (std::sin(e1) - std::sin(e0)) * dphi / Pi;
        for (int c = 0; c < 3; ++c)
        {
          rgb[c] += radiance[c] * weight;
        }
      }
    }
  }
}

// The wedge table of an environment in a frame, as floats.
std::vector<float> WedgeTable(vtkEnvironmentMap* environment, const double frameToWorld[9])
{
  vtkSmartPointer<vtkImageData> table;
  table.TakeReference(environment->NewWedgeTable(Azimuths, Elevations, frameToWorld));
  auto* values = vtkFloatArray::SafeDownCast(table->GetPointData()->GetScalars());
  int dims[3];
  table->GetDimensions(dims);
  Check(values && dims[0] == Azimuths + 1 && dims[1] == Elevations && dims[2] == 3,
    "the wedge table has (azimuths + 1) x elevations x 3 RGB points", dims[0], Azimuths + 1);
  return values
    ? std::vector<float>(values->GetPointer(0), values->GetPointer(0) + values->GetNumberOfValues())
    : std::vector<float>();
}

// Radiance 1 everywhere: the uniform sky's values, with random coverage by lights.
void TestUniform()
{
  vtkNew<vtkEnvironmentMap> environment;
  environment->SetImage(
    LatLong(64, 32, [](const double*, double rgb[3]) { rgb[0] = rgb[1] = rgb[2] = 1.0; }));
  const double identity[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  const std::vector<float> table = WedgeTable(environment, identity);
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(3);
  double worst = 0.0;
  for (int i = 0; i < 300 && !table.empty(); ++i)
  {
    std::vector<float> h;
    double n[3];
    RandomPoint(random, h, n);
    random->Next();
    const double share = i % 3 == 0 ? 0.0 : random->GetValue();
    const double open[2] = { 2.0 * Pi *
        vtkHorizonLighting::SkyTransfer(n, h.data(), Sectors, 0.0, 0.0, false),
      Pi * vtkHorizonLighting::SkyTransfer(n, h.data(), Sectors, 0.0, 0.0, true) };
    for (int weighted = 0; weighted < 2; ++weighted)
    {
      double rgb[3];
      vtkHorizonLighting::EnvironmentSkyTransfer(n, h.data(), Sectors, table.data(), Azimuths,
        Elevations, share * open[0], share * open[1], weighted != 0, rgb);
      const double want = open[1] / Pi * (1.0 - share);
      const double error = std::abs(rgb[0] - want);
      worst = std::max(worst, error);
      Check(error <= 2e-3 && rgb[1] == rgb[0] && rgb[2] == rgb[0],
        "radiance 1 gives the uniform sky, case " + std::to_string(i) +
          (weighted ? " (cosine-weighted share)" : " (solid-angle share)"),
        rgb[0], want);
    }
  }
  std::cout << "radiance 1: max |environment - uniform sky| = " << worst << "\n";
}

// The smooth sky, turned about the y axis by 35 degrees, and a frame turned 0.8 rad about
// (1, 2, 3) against the world: the two tests of a turned sky share them.
vtkSmartPointer<vtkEnvironmentMap> TurnedSmoothSky(double rotation[3][3])
{
  auto environment = vtkSmartPointer<vtkEnvironmentMap>::New();
  environment->SetImage(LatLong(512, 256, SmoothSky));
  environment->SetUpAxisToY();
  environment->SetAzimuth(35.0);
  double axis[3] = { 1.0, 2.0, 3.0 };
  vtkMath::Normalize(axis);
  double quaternion[4] = { std::cos(0.4), std::sin(0.4) * axis[0], std::sin(0.4) * axis[1],
    std::sin(0.4) * axis[2] };
  vtkMath::QuaternionToMatrix3x3(quaternion, rotation);
  return environment;
}

// A smooth coloured environment, turned about another axis than the frame's, against brute force.
void TestSmooth()
{
  // The frame: turned, and scaled by 2.
  double rotation[3][3];
  vtkSmartPointer<vtkEnvironmentMap> environment = TurnedSmoothSky(rotation);
  double frame[9], unit[9];
  for (int i = 0; i < 9; ++i)
  {
    unit[i] = rotation[i / 3][i % 3];
    frame[i] = 2.0 * unit[i];
  }
  const std::vector<float> table = WedgeTable(environment, frame);
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(11);
  double worst = 0.0;
  for (int i = 0; i < 24 && !table.empty(); ++i)
  {
    std::vector<float> h;
    double n[3], got[3], want[3];
    RandomPoint(random, h, n);
    vtkHorizonLighting::EnvironmentSkyTransfer(
      n, h.data(), Sectors, table.data(), Azimuths, Elevations, 0.0, 0.0, true, got);
    BruteEnvironment(environment, unit, n, h, want);
    for (int c = 0; c < 3; ++c)
    {
      const double error = std::abs(got[c] - want[c]) / std::max(want[c], 0.05);
      worst = std::max(worst, error);
      Check(error <= 0.01,
        "a turned smooth sky against brute force, case " + std::to_string(i) + " channel " +
          std::to_string(c),
        got[c], want[c]);
    }
  }
  std::cout << "smooth turned sky: max relative error against brute force = " << worst << "\n";
}

// NaN or zero normals, no table, NaN coverage, a singular frame: zeros, never NaN.
void TestBadInput()
{
  vtkNew<vtkEnvironmentMap> environment;
  environment->SetImage(LatLong(64, 32, SmoothSky));
  const double singular[9] = { 1, 0, 0, 0, 0, 0, 0, 0, 1 };
  const std::vector<float> flat = WedgeTable(environment, singular);
  const double identity[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  const std::vector<float> table = WedgeTable(environment, identity);
  Check(std::all_of(flat.begin(), flat.end(), [](float v) { return v == 0.0f; }),
    "a singular frame gives an empty table", flat.empty() ? -1.0 : flat[3 * 300], 0.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<float> h(Sectors, 0.1f);
  const double normals[3][3] = { { nan, 0, 1 }, { 0, 0, 0 }, { 0, 0, 1 } };
  for (int i = 0; i < 4; ++i)
  {
    double rgb[3] = { 7, 7, 7 };
    vtkHorizonLighting::EnvironmentSkyTransfer(normals[std::min(i, 2)], h.data(), Sectors,
      i == 2 ? nullptr : table.data(), Azimuths, Elevations, i == 3 ? nan : 0.0, 0.0, true, rgb);
    Check(rgb[0] == 0.0 && rgb[1] == 0.0 && rgb[2] == 0.0,
      "bad input " + std::to_string(i) + " gives no sky", rgb[0], 0.0);
  }
}
}

namespace
{
// A random mask of `bits` cells, about `open` of them open, in runs so that it has gaps.
std::vector<unsigned char> RandomMask(
  vtkMinimalStandardRandomSequence* random, int bits, double open)
{
  std::vector<unsigned char> mask(bits / 8, 0);
  bool state = true;
  for (int cell = 0; cell < bits; ++cell)
  {
    random->Next();
    if (random->GetValue() < 0.15)
    {
      state = !state;
    }
    random->Next();
    if (state && random->GetValue() < open)
    {
      mask[cell / 8] |= static_cast<unsigned char>(1 << (cell % 8));
    }
  }
  return mask;
}

// (1/π) Σ_open ∫_cell L(ω) n·ω dω, from 64 directions on each open cell's equal-area sub-grid,
// the frame's directions taken to world by frameToWorld.
void BruteMask(vtkEnvironmentMap* environment, const double frameToWorld[9], const double normal[3],
  const std::vector<unsigned char>& mask, double rgb[3])
{
  const int bits = 8 * static_cast<int>(mask.size()), side = vtkVisibilityMask::GetSide(bits);
  double n[3] = { normal[0], normal[1], normal[2] };
  vtkMath::Normalize(n);
  std::vector<float> directions;
  vtkVisibilityMask::CellRayDirections(n, side, 8, directions);
  rgb[0] = rgb[1] = rgb[2] = 0.0;
  for (int q = 0; q < bits * 64; ++q)
  {
    const int cell = q / 64;
    if (!((mask[cell / 8] >> (cell % 8)) & 1))
    {
      continue;
    }
    const double w[3] = { directions[3 * q], directions[3 * q + 1], directions[3 * q + 2] };
    double world[3], radiance[3];
    for (int a = 0; a < 3; ++a)
    {
      world[a] = vtkMath::Dot(frameToWorld + 3 * a, w);
    }
    environment->Radiance(world, radiance);
    const double weight = vtkMath::Dot(n, w) * 2.0 * Pi / bits / 64 / Pi;
    for (int c = 0; c < 3; ++c)
    {
      rgb[c] += radiance[c] * weight;
    }
  }
}

// The table of mean radiance over a cell's cap, as floats.
std::vector<float> MeanRadianceTable(vtkEnvironmentMap* environment, int bits)
{
  vtkSmartPointer<vtkImageData> table;
  table.TakeReference(
    environment->NewMeanRadianceTable(64, 32, vtkVisibilityMask::CellCapRadius(bits)));
  auto* values = vtkFloatArray::SafeDownCast(table->GetPointData()->GetScalars());
  return std::vector<float>(
    values->GetPointer(0), values->GetPointer(0) + values->GetNumberOfValues());
}

// Masks: radiance 1 against SkyTransfer(), a turned smooth sky against brute force, bad input.
void TestMasks()
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(7);
  vtkNew<vtkEnvironmentMap> uniform;
  uniform->SetImage(
    LatLong(64, 32, [](const double*, double rgb[3]) { rgb[0] = rgb[1] = rgb[2] = 1.0; }));
  // Model to environment: turned, scaled by 2, then the sky's frame.
  double rotation[3][3], toSky[3][3], toEnvironment[3][3], unit[9], scaled[9];
  vtkSmartPointer<vtkEnvironmentMap> smooth = TurnedSmoothSky(rotation);
  smooth->GetWorldToEnvironment(&toSky[0][0]);
  vtkMath::Multiply3x3(toSky, rotation, toEnvironment);
  for (int i = 0; i < 9; ++i)
  {
    unit[i] = rotation[i / 3][i % 3];
    scaled[i] = 2.0 * toEnvironment[i / 3][i % 3];
  }
  const double identity[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  double worst[2] = { 0.0, 0.0 };
  for (int bits : { 64, 256, 1024 })
  {
    worst[1] = 0.0;
    const std::vector<float> flat = MeanRadianceTable(uniform, bits);
    const std::vector<float> table = MeanRadianceTable(smooth, bits);
    for (int i = 0; i < 12; ++i)
    {
      const std::vector<unsigned char> mask = RandomMask(random, bits, 0.6);
      double n[3] = { 0.3, -0.2, 1.0 }, got[3], want[3], open[2];
      random->Next();
      n[0] = random->GetRangeValue(-1.0, 1.0);
      vtkVisibilityMask::OpenSums(mask.data(), bits, open);
      const double share = i % 2 ? 0.4 : 0.0;
      vtkVisibilityMask::EnvironmentSkyTransfer(n, mask.data(), bits, flat.data(), 64, 32, identity,
        share * open[0], share * open[1], i % 4 < 2, got);
      const double sky = vtkVisibilityMask::SkyTransfer(n, mask.data(), bits, 0.0, 0.0, true);
      worst[0] = std::max(worst[0], std::abs(got[0] - sky * (1.0 - share)));
      Check(std::abs(got[0] - sky * (1.0 - share)) <= 1e-5,
        "radiance 1 through a mask gives the uniform sky, " + std::to_string(bits) + " bits",
        got[0], sky * (1.0 - share));
      vtkVisibilityMask::EnvironmentSkyTransfer(
        n, mask.data(), bits, table.data(), 64, 32, scaled, 0.0, 0.0, true, got);
      BruteMask(smooth, unit, n, mask, want);
      for (int c = 0; c < 3; ++c)
      {
        const double error = std::abs(got[c] - want[c]) / std::max(want[c], 0.05);
        worst[1] = std::max(worst[1], error);
        // A cell takes its middle's mean radiance over a cap of its size: within 3% of the
        // cell's integral for 64 bits (cells of 14 degrees), finer cells do better.
        Check(error <= 0.03,
          "a turned smooth sky through a mask of " + std::to_string(bits) + " bits, case " +
            std::to_string(i) + " channel " + std::to_string(c),
          got[c], want[c]);
      }
    }
    std::cout << "mask of " << bits << " bits, smooth turned sky: max relative error against "
              << "brute force = " << worst[1] << "\n";
  }
  std::cout << "masks, radiance 1: max |environment - uniform sky| = " << worst[0] << "\n";
  const std::vector<float> table = MeanRadianceTable(smooth, 256);
  const std::vector<unsigned char> mask(32, 255);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double good[3] = { 0, 0, 1 }, bad[3] = { nan, 0, 1 }, zero[9] = { 0 };
  for (int i = 0; i < 5; ++i)
  {
    double rgb[3] = { 7, 7, 7 };
    vtkVisibilityMask::EnvironmentSkyTransfer(i == 0 ? bad : good, mask.data(), i == 1 ? 100 : 256,
      i == 2 ? nullptr : table.data(), 64, 32, i == 3 ? zero : identity, i == 4 ? nan : 0.0, 0.0,
      true, rgb);
    Check(rgb[0] == 0.0 && rgb[1] == 0.0 && rgb[2] == 0.0,
      "bad input " + std::to_string(i) + " gives no sky through a mask", rgb[0], 0.0);
  }
}
}

int TestOpenEnvironmentSky(int, char*[])
{
  TestUniform();
  TestSmooth();
  TestBadInput();
  TestMasks();
  return vtkApertureTest::Result();
}
