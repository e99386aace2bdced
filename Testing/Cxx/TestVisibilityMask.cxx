/*=========================================================================

  Program:   ApertureLighting
  Module:    TestVisibilityMask.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkVisibilityMask: its frame, its cells (equal in solid angle, each direction in the cell it
// comes from), the light and the sky through open cells against numerical integration, bad
// input; and vtkAperturePrecompute's masks at the foot of a wall against the wall's geometry.

#include "vtkAperturePrecompute.h"
#include "vtkApertureTestHarness.h"
#include "vtkSphericalCap.h"
#include "vtkVisibilityMask.h"

#include "vtkAppendPolyData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkTestErrorObserver.h"
#include "vtkTriangleFilter.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <vector>

namespace
{
constexpr double Pi = vtkMath::Pi();
using vtkApertureTest::Check;

class Random
{
public:
  explicit Random(int seed) { this->Sequence->SetSeed(seed); }
  double Next(double low, double high)
  {
    this->Sequence->Next();
    return this->Sequence->GetRangeValue(low, high);
  }
  void Normal(double n[3])
  {
    const double z = this->Next(-1.0, 1.0), phi = this->Next(0.0, 2.0 * Pi);
    const double s = std::sqrt(1.0 - z * z);
    n[0] = s * std::cos(phi);
    n[1] = s * std::sin(phi);
    n[2] = z;
  }

private:
  vtkNew<vtkMinimalStandardRandomSequence> Sequence;
};

void TestCells()
{
  Check(vtkVisibilityMask::IsValidBitCount(256) && vtkVisibilityMask::IsValidBitCount(64) &&
      vtkVisibilityMask::IsValidBitCount(1024) && vtkVisibilityMask::IsValidBitCount(144),
    "64, 144, 256 and 1024 cells are masks");
  Check(!vtkVisibilityMask::IsValidBitCount(100) && !vtkVisibilityMask::IsValidBitCount(2048) &&
      !vtkVisibilityMask::IsValidBitCount(32) && !vtkVisibilityMask::IsValidBitCount(-64),
    "100, 2048, 32 and -64 cells are not");
  Random random(3);
  int wrongFrames = 0, wrongCells = 0;
  for (int trial = 0; trial < 200; ++trial)
  {
    double n[3], t[3], b[3], cross[3];
    random.Normal(n);
    if (trial < 2)
    {
      n[0] = n[1] = 0.0;
      n[2] = trial == 0 ? 1.0 : -1.0;
    }
    vtkVisibilityMask::Frame(n, t, b);
    vtkMath::Cross(t, b, cross);
    wrongFrames += std::abs(vtkMath::Dot(t, b)) > 1e-12 || std::abs(vtkMath::Norm(t) - 1) > 1e-12 ||
      std::abs(vtkMath::Norm(b) - 1) > 1e-12 || vtkMath::Distance2BetweenPoints(cross, n) > 1e-20;
    for (int cell = 0; cell < 256; ++cell)
    {
      double w[3];
      vtkVisibilityMask::Direction(n, (cell % 16 + 0.5) / 16, (cell / 16 + 0.5) / 16, w);
      wrongCells += vtkVisibilityMask::CellOf(n, w, 16) != cell || vtkMath::Dot(w, n) < 0.0;
    }
  }
  Check(wrongFrames == 0, "frames are orthonormal and right-handed", wrongFrames, 0);
  Check(wrongCells == 0, "a cell's middle direction falls in that cell", wrongCells, 0);

  // Uniform directions over the hemisphere land equally in the 64 cells (5 sigma).
  const int samples = 1 << 21;
  std::vector<int> counts(64, 0);
  const double n[3] = { 0.3, -0.2, 0.9 };
  double unit[3] = { n[0], n[1], n[2] };
  vtkMath::Normalize(unit);
  for (int i = 0; i < samples; ++i)
  {
    double w[3];
    random.Normal(w);
    if (vtkMath::Dot(w, unit) < 0.0)
    {
      vtkMath::MultiplyScalar(w, -1.0);
    }
    ++counts[vtkVisibilityMask::CellOf(unit, w, 8)];
  }
  const double expected = samples / 64.0, sigma = std::sqrt(expected);
  double worst = 0.0;
  for (int c : counts)
  {
    worst = std::max(worst, std::abs(c - expected) / sigma);
  }
  std::cout << "64 cells, 2M uniform directions: largest deviation " << worst << " sigma\n";
  Check(worst < 5.0, "cells have equal solid angles", worst, 5.0);
  double sum = 0.0;
  for (int cell = 0; cell < 256; ++cell)
  {
    sum += vtkVisibilityMask::CellCosine(cell, 16);
  }
  Check(std::abs(sum - Pi) < 1e-4, "the cells' cosine integrals sum to pi", sum, Pi);
}

// ∫ max(0, n·ω) over the part of the cap in open cells, by a fine polar grid, times the
// light's radiance.
double BruteLight(
  const double n[3], const std::vector<unsigned char>& mask, const double l[3], double rl)
{
  const int rings = 400, spokes = 400, side = vtkVisibilityMask::GetSide(8 * int(mask.size()));
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
      const int cell = vtkVisibilityMask::CellOf(n, w, side);
      if (cell >= 0 && ((mask[cell / 8] >> (cell % 8)) & 1) && vtkMath::Dot(n, w) > 0.0)
      {
        sum += vtkMath::Dot(n, w) * area;
      }
    }
  }
  return sum * vtkSphericalCap::LightRadiance(rl);
}

// Masks with a structure, as occluders make them: open above an elevation that varies with
// azimuth in the frame.
std::vector<unsigned char> WallMask(const double n[3], double level, double phase, int side)
{
  std::vector<unsigned char> mask(side * side / 8, 0);
  for (int cell = 0; cell < side * side; ++cell)
  {
    double w[3], t[3], b[3];
    vtkVisibilityMask::Direction(n, (cell % side + 0.5) / side, (cell / side + 0.5) / side, w);
    vtkVisibilityMask::Frame(n, t, b);
    const double azimuth = std::atan2(vtkMath::Dot(w, b), vtkMath::Dot(w, t));
    if (vtkMath::Dot(w, n) > level + 0.4 * std::cos(azimuth - phase))
    {
      mask[cell / 8] |= 1 << (cell % 8);
    }
  }
  return mask;
}

void TestLights()
{
  Random random(5);
  const double radii[] = { 0.001, 0.0047, 0.064, 0.314, 0.785 };
  double worst[5] = { 0, 0, 0, 0, 0 }, worstOpen = 0.0;
  const std::vector<unsigned char> open(32, 255);
  for (int i = 0; i < 100; ++i)
  {
    double n[3], l[3];
    random.Normal(n);
    random.Normal(l);
    if (vtkMath::Dot(n, l) < 0.0)
    {
      vtkMath::MultiplyScalar(l, -1.0);
    }
    const double rl = radii[i % 5];
    const auto mask = WallMask(n, random.Next(-0.2, 0.6), random.Next(0.0, 2.0 * Pi), 16);
    const double got = vtkVisibilityMask::LightTransfer(n, mask.data(), 256, l, rl);
    const double want = BruteLight(n, mask, l, rl);
    worst[i % 5] = std::max(worst[i % 5], std::abs(got - want));
    Check(std::abs(got - want) <= 0.04, "a light through open cells", got, want);
    // Every cell open: the light's own Lambert term where it is above the tangent plane.
    if (vtkMath::Dot(n, l) >= std::sin(rl))
    {
      const double all = vtkVisibilityMask::LightTransfer(n, open.data(), 256, l, rl);
      worstOpen = std::max(worstOpen, std::abs(all - vtkMath::Dot(n, l)));
    }
  }
  for (int r = 0; r < 5; ++r)
  {
    std::cout << "LightTransfer, r = " << radii[r] << ": max |samples - grid| = " << worst[r]
              << "\n";
  }
  std::cout << "every cell open: max |transfer - n . l| = " << worstOpen << "\n";
  Check(worstOpen < 0.01, "an open mask gives the unoccluded light", worstOpen, 0.01);
}

void TestSky()
{
  const double n[3] = { 0.0, 0.6, 0.8 };
  const std::vector<unsigned char> open(32, 255), closed(32, 0);
  Check(std::abs(vtkVisibilityMask::SkyTransfer(n, open.data(), 256, 0, 0, true) - 1.0) < 1e-4 &&
      std::abs(vtkVisibilityMask::SkyTransfer(n, open.data(), 256, 0, 0, false) - 1.0) < 1e-12,
    "an open mask sees the whole sky");
  Check(vtkVisibilityMask::SkyTransfer(n, closed.data(), 256, 0, 0, true) == 0.0,
    "a closed mask sees none");
  // Half the cells (i < 8): half the solid angle, and the cosine integral of those cells.
  std::vector<unsigned char> half(32, 0);
  double cosine = 0.0;
  for (int cell = 0; cell < 256; ++cell)
  {
    if (cell % 16 < 8)
    {
      half[cell / 8] |= 1 << (cell % 8);
      cosine += vtkVisibilityMask::CellCosine(cell, 16);
    }
  }
  Check(std::abs(vtkVisibilityMask::SkyTransfer(n, half.data(), 256, 0, 0, false) - 0.5) < 1e-12,
    "half the cells: half the sky");
  Check(std::abs(vtkVisibilityMask::SkyTransfer(n, half.data(), 256, 0, 0, true) - 0.5) < 1e-4 &&
      std::abs(cosine / Pi - 0.5) < 1e-4,
    "half the cells, symmetric: half the cosine-weighted sky");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double bad[3] = { nan, 0.0, 1.0 }, l[3] = { 0, 0, 1 };
  Check(vtkVisibilityMask::LightTransfer(bad, open.data(), 256, l, 0.1) == 0.0 &&
      vtkVisibilityMask::LightTransfer(n, open.data(), 100, l, 0.1) == 0.0 &&
      vtkVisibilityMask::LightTransfer(n, nullptr, 256, l, 0.1) == 0.0 &&
      vtkVisibilityMask::SkyTransfer(bad, open.data(), 256, 0, 0, true) == 0.0,
    "bad input gives 0");
}

// The share of cells of ground points by the wall whose bit disagrees with the wall's geometry
// along the cell's middle direction; -1 without masks.
double WallMismatch(vtkPolyData* out)
{
  vtkDataArray* mask = out->GetPointData()->GetArray("VisibilityMask");
  Check(mask && mask->GetNumberOfComponents() == 32 && mask->GetDataType() == VTK_UNSIGNED_CHAR,
    "VisibilityMask: 32 unsigned chars a point");
  if (!mask)
  {
    return -1.0;
  }
  int tested = 0, wrong = 0;
  for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
  {
    double x[3], n[3];
    out->GetPoint(p, x);
    out->GetPointData()->GetNormals()->GetTuple(p, n);
    if (!(x[2] == 0.0 && x[0] > 0.4 && x[0] < 3.0 && std::abs(x[1]) < 5.0 && n[2] > 0.99))
    {
      continue;
    }
    ++tested;
    for (int cell = 0; cell < 256; ++cell)
    {
      double w[3];
      vtkVisibilityMask::Direction(n, (cell % 16 + 0.5) / 16, (cell / 16 + 0.5) / 16, w);
      const double t = w[0] < 0.0 ? -x[0] / w[0] : -1.0;
      const bool hits = t > 0.0 && std::abs(x[1] + t * w[1]) <= 10.0 && x[2] + t * w[2] <= 10.0;
      const bool open = (static_cast<int>(mask->GetComponent(p, cell / 8)) >> (cell % 8)) & 1;
      wrong += open == hits;
    }
  }
  Check(tested > 20, "ground points by the wall", tested, 20);
  return double(wrong) / std::max(1, 256 * tested);
}

// Ground points at the foot of a wall 10 high: a cell is open where its middle direction misses
// the wall (cells on the wall's silhouette may go either way).
void TestPrecomputedMasks()
{
  vtkNew<vtkPlaneSource> ground, wall;
  ground->SetOrigin(-20, -20, 0);
  ground->SetPoint1(20, -20, 0);
  ground->SetPoint2(-20, 20, 0);
  ground->SetResolution(80, 80);
  wall->SetOrigin(0, -10, 0);
  wall->SetPoint1(0, 10, 0);
  wall->SetPoint2(0, -10, 10);
  wall->SetResolution(8, 8);
  vtkNew<vtkAppendPolyData> both;
  both->AddInputConnection(ground->GetOutputPort());
  both->AddInputConnection(wall->GetOutputPort());
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(both->GetOutputPort());
  vtkNew<vtkAperturePrecompute> precompute;
  precompute->SetInputConnection(triangles->GetOutputPort());
  precompute->SetNumberOfRays(16);
  precompute->ComputeVisibilityMaskOn();
  // One ray a cell: its middle, exactly the wall's answer; four: the majority of a sub-grid,
  // which may differ on the wall's silhouette.
  for (const int rays : { 1, 4 })
  {
    precompute->SetVisibilityMaskRaysPerCell(rays);
    precompute->Update();
    const double share = WallMismatch(precompute->GetPolyDataOutput());
    std::cout << rays << " rays a cell: " << 100.0 * share
              << "% of cells by the wall differ from its geometry\n";
    Check(share >= 0.0 && share < (rays == 1 ? 0.002 : 0.05), "masks at the foot of a wall", share,
      rays == 1 ? 0.002 : 0.05);
  }
  vtkNew<vtkTest::ErrorObserver> observer;
  precompute->AddObserver(vtkCommand::ErrorEvent, observer);
  precompute->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, observer);
  precompute->SetVisibilityMaskBits(100);
  precompute->Update();
  Check(observer->GetError() && precompute->GetPolyDataOutput()->GetNumberOfPoints() == 0,
    "100 cells are refused with an error");
}
}

int TestVisibilityMask(int, char*[])
{
  TestCells();
  TestLights();
  TestSky();
  TestPrecomputedMasks();
  return vtkApertureTest::Result();
}
