/*=========================================================================

  Program:   ApertureLighting
  Module:    TestEnvironmentMap.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkEnvironmentMap: the latitude-longitude conventions (where a bright spot's direction is, for
// each up axis and after a turn), a uniform environment (cells 1, irradiance pi, a cap of radius
// r gives pi sin^2 r), order-2 harmonics against direct integration on the forest map, the
// Gaussian blur at the pole and across the seam (energy kept, centre kept, symmetric), cell
// averages that add up to the environment's total, turning the environment against turning the
// directions, and the cap table against CapIrradiance().

#include "vtkApertureTestHarness.h"
#include "vtkEnvironmentMap.h"

#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLightSphere.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkOpenEXRReader.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTestUtilities.h"

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace
{
const double Pi = vtkMath::Pi();

using vtkApertureTest::Check;

// A w x h RGB map, 0 except `value` at pixel (i, j) and its right and upper neighbours.
vtkSmartPointer<vtkImageData> Spot(int w, int h, int i, int j, double value = 1000.0)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  vtkNew<vtkFloatArray> radiance;
  radiance->SetNumberOfComponents(3);
  radiance->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  radiance->Fill(0.0);
  for (int dj = 0; dj < 2; ++dj)
  {
    for (int di = 0; di < 2; ++di)
    {
      const vtkIdType id = static_cast<vtkIdType>(std::min(h - 1, j + dj)) * w + (i + di) % w;
      for (int k = 0; k < 3; ++k)
      {
        radiance->SetComponent(id, k, value);
      }
    }
  }
  image->GetPointData()->SetScalars(radiance);
  return image;
}

vtkSmartPointer<vtkImageData> Uniform(int w, int h, double value)
{
  auto image = Spot(w, h, 0, 0, 0.0);
  image->GetPointData()->GetScalars()->Fill(value);
  return image;
}

double Angle(const double a[3], const double b[3])
{
  return std::acos(
    std::min(1.0, std::max(-1.0, vtkMath::Dot(a, b) / (vtkMath::Norm(a) * vtkMath::Norm(b)))));
}

// The radiance-weighted mean direction and the total radiant energy (sum of L dw) of an
// environment, from a fine sampling of the sphere.
void Moments(vtkEnvironmentMap* map, double mean[3], double& energy)
{
  mean[0] = mean[1] = mean[2] = 0.0;
  energy = 0.0;
  const int n = 720, m = 360;
  for (int j = 0; j < m; ++j)
  {
    const double v = (j + 0.5) / m;
    const double area = (2 * Pi / n) * (Pi / m) * std::cos(Pi * (v - 0.5));
    for (int i = 0; i < n; ++i)
    {
      double d[3], rgb[3];
      map->DirectionOf((i + 0.5) / n, v, d);
      map->Radiance(d, rgb);
      energy += rgb[0] * area;
      for (int k = 0; k < 3; ++k)
      {
        mean[k] += rgb[0] * area * d[k];
      }
    }
  }
}
}

int TestEnvironmentMap(int argc, char* argv[])
{
  // Conventions: a spot at u = 0.75, v = 0.75 looks east, 45 degrees up.
  vtkNew<vtkEnvironmentMap> map;
  map->SetImage(Spot(256, 128, 191, 95));
  struct Case
  {
    int Up;
    double Azimuth;
    double Expected[3];
    const char* What;
  };
  const double h = std::sqrt(0.5);
  for (const Case& c : { Case{ vtkEnvironmentMap::Z, 0.0, { h, 0, h }, "Z up: east is +x" },
         Case{ vtkEnvironmentMap::Y, 0.0, { h, h, 0 }, "Y up: east is +x, up +y" },
         Case{ vtkEnvironmentMap::Z, 90.0, { 0, -h, h }, "Z up, turned 90: east goes south" } })
  {
    map->SetUpAxis(c.Up);
    map->SetAzimuth(c.Azimuth);
    double rgb[3], u, v, zenith[3];
    map->Radiance(c.Expected, rgb);
    map->ImagePointOf(c.Expected, u, v);
    map->DirectionOf(0.5, 1.0, zenith);
    const double up[3] = { c.Up == 0 ? 1.0 : 0.0, c.Up == 1 ? 1.0 : 0.0, c.Up == 2 ? 1.0 : 0.0 };
    std::cout << c.What << ": radiance " << rgb[0] << " at the expected direction, image point ("
              << u << ", " << v << ")\n";
    Check(rgb[0] > 500.0 && std::abs(u - 0.75) < 1e-9 && std::abs(v - 0.75) < 1e-9 &&
        Angle(zenith, up) < 1e-9,
      c.What);
  }
  map->SetUpAxis(vtkEnvironmentMap::Z);
  map->SetAzimuth(0.0);

  // A uniform environment of radiance 1.
  map->SetImage(Uniform(200, 100, 1.0));
  vtkNew<vtkLightSphere> sphere;
  sphere->SetLevel(3);
  vtkSmartPointer<vtkDoubleArray> directions;
  directions.TakeReference(sphere->NewDirections());
  vtkNew<vtkDoubleArray> cells;
  map->CellRadiance(directions, cells);
  double worstCell = 0.0;
  for (vtkIdType j = 0; j < cells->GetNumberOfTuples(); ++j)
  {
    worstCell = std::max(worstCell, std::abs(cells->GetComponent(j, 1) - 1.0));
  }
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(3);
  double worstIrradiance = 0.0, worstCap = 0.0, worstRadiance = 0.0;
  for (int t = 0; t < 20; ++t)
  {
    double n[3] = { random->GetNextValue() - 0.5, random->GetNextValue() - 0.5,
      random->GetNextValue() - 0.5 };
    vtkMath::Normalize(n);
    double e[3], cap[3];
    map->Irradiance(n, e);
    worstIrradiance = std::max(worstIrradiance, std::abs(e[0] - Pi) / Pi);
    const double r = 0.1 + 1.4 * random->GetNextValue();
    map->CapIrradiance(n, r, cap);
    const double exact = Pi * std::sin(r) * std::sin(r);
    worstCap = std::max(worstCap, std::abs(cap[0] - exact) / exact);
    // Unweighted, any radius up to pi: the cap's solid angle 2 pi (1 - cos R).
    const double big = 0.1 + (Pi - 0.1) * random->GetNextValue();
    map->CapRadiance(n, big, cap);
    const double area = 2.0 * Pi * (1.0 - std::cos(big));
    worstRadiance = std::max(worstRadiance, std::abs(cap[0] - area) / area);
  }
  std::cout << "uniform: worst cell " << worstCell << ", irradiance " << worstIrradiance
            << " of pi, cap " << worstCap << " of pi sin^2 r, cap radiance " << worstRadiance
            << " of 2 pi (1 - cos r)\n";
  Check(worstCell < 1e-6 && worstIrradiance < 1e-4 && worstCap < 0.03 && worstRadiance < 0.03,
    "a uniform environment: cells 1, irradiance pi, caps pi sin^2 r and 2 pi (1 - cos r)");

  // Harmonics against direct integration: exact for a sky that brightens linearly toward the
  // zenith (order 1), and what order 2 makes of the forest map, whose sun it cannot resolve.
  auto gradient = Uniform(256, 128, 1.0);
  for (int j = 0; j < 128; ++j)
  {
    for (int i = 0; i < 256; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        gradient->GetPointData()->GetScalars()->SetComponent(
          j * 256 + i, k, 1.0 + 0.5 * std::sin(Pi * ((j + 0.5) / 128 - 0.5)));
      }
    }
  }
  char* forestName = vtkTestUtilities::ExpandDataFileName(argc, argv, "Data/env/forest.exr");
  vtkNew<vtkOpenEXRReader> reader;
  reader->SetFileName(forestName);
  delete[] forestName;
  reader->Update();
  for (int which = 0; which < 2; ++which)
  {
    map->SetImage(which == 0 ? gradient.GetPointer() : reader->GetOutput());
    double sumError = 0.0, worstError = 0.0;
    for (int t = 0; t < 40; ++t)
    {
      double n[3] = { random->GetNextValue() - 0.5, random->GetNextValue() - 0.5,
        random->GetNextValue() - 0.5 };
      vtkMath::Normalize(n);
      double sh[3], direct[3];
      map->Irradiance(n, sh);
      map->CapIrradiance(n, 0.5 * Pi, direct);
      const double error = std::abs(sh[1] - direct[1]) / direct[1];
      sumError += error / 40;
      worstError = std::max(worstError, error);
    }
    std::cout << (which == 0 ? "linear sky" : "forest")
              << ": order-2 irradiance against direct integration, mean error " << 100 * sumError
              << "%, worst " << 100 * worstError << "%\n";
    Check(which == 0 ? worstError < 0.01 : sumError < 0.08,
      which == 0 ? "order-2 irradiance of a linear sky" : "order-2 irradiance of the forest");
  }

  // Cell averages add up to the environment's total; turning the environment and the directions
  // together changes nothing.
  vtkSmartPointer<vtkDoubleArray> weights;
  weights.TakeReference(sphere->NewWeights());
  map->CellRadiance(directions, cells);
  double cellTotal = 0.0, mean[3], energy;
  for (vtkIdType j = 0; j < cells->GetNumberOfTuples(); ++j)
  {
    cellTotal += cells->GetComponent(j, 0) * weights->GetValue(j);
  }
  Moments(map, mean, energy);
  std::cout << "forest: cells add up to " << cellTotal << ", the environment's total is " << energy
            << "\n";
  Check(std::abs(cellTotal - energy) < 0.01 * energy, "cells add up to the total");
  map->SetAzimuth(90.0);
  vtkNew<vtkDoubleArray> turned, turnedCells;
  turned->SetNumberOfComponents(3);
  for (vtkIdType j = 0; j < directions->GetNumberOfTuples(); ++j)
  {
    // Clockwise 90 degrees about z: north (+y) to east (+x), east to south.
    double d[3];
    directions->GetTuple(j, d);
    const double rotated[3] = { d[1], -d[0], d[2] };
    turned->InsertNextTuple(rotated);
  }
  map->CellRadiance(turned, turnedCells);
  double worstTurn = 0.0;
  for (vtkIdType j = 0; j < cells->GetNumberOfTuples(); ++j)
  {
    worstTurn = std::max(worstTurn,
      std::abs(turnedCells->GetComponent(j, 1) - cells->GetComponent(j, 1)) /
        (cells->GetComponent(j, 1) + 0.05));
  }
  std::cout << "forest turned 90 degrees with its directions: worst cell change " << worstTurn
            << "\n";
  Check(worstTurn < 0.05, "turning the environment with the directions changes nothing");
  map->SetAzimuth(0.0);

  // The cap tables hold CapIrradiance() (radii to pi/2) and CapRadiance() (radii to pi).
  for (bool cosine : { true, false })
  {
    vtkSmartPointer<vtkImageData> table;
    table.TakeReference(cosine ? map->NewCapTable(16, 8, 5) : map->NewCapRadianceTable(16, 8, 5));
    double worstTable = 0.0;
    for (int k = 1; k < 5; ++k)
    {
      for (int j = 0; j < 8; j += 3)
      {
        for (int i = 0; i < 16; i += 5)
        {
          double axis[3], direct[3];
          map->DirectionOf((i + 0.5) / 16, (j + 0.5) / 8, axis);
          const double r = k * (cosine ? 0.5 * Pi : Pi) / 4;
          cosine ? map->CapIrradiance(axis, r, direct) : map->CapRadiance(axis, r, direct);
          const double stored =
            table->GetPointData()->GetScalars()->GetComponent((k * 8 + j) * 16 + i, 2);
          worstTable = std::max(worstTable, std::abs(stored - direct[2]) / (direct[2] + 1e-9));
        }
      }
    }
    std::cout << (cosine ? "cap table against CapIrradiance" : "cap table against CapRadiance")
              << ": worst relative difference " << worstTable << "\n";
    Check(worstTable < 1e-3,
      cosine ? "the cap table holds CapIrradiance()" : "the radiance table holds CapRadiance()");
  }

  // The blur on the sphere: a spot near the north pole and one across the seam keep their energy
  // and centre, and spread evenly.
  for (int spot = 0; spot < 2; ++spot)
  {
    const int i = spot == 0 ? 40 : 255, j = spot == 0 ? 125 : 70;
    map->SetImage(Spot(256, 128, i, j));
    map->SetBlurAngle(0.0);
    double sharpMean[3], sampledEnergy;
    Moments(map, sharpMean, sampledEnergy);
    // The spot's energy from its pixels' solid angles (the sampling above blurs a sharp spot).
    double sharpEnergy = 0.0;
    for (int row = j; row <= std::min(127, j + 1); ++row)
    {
      sharpEnergy += 2 * 1000.0 * (2 * Pi / 256) *
        (std::sin(Pi * ((row + 1.0) / 128 - 0.5)) - std::sin(Pi * (double(row) / 128 - 0.5)));
    }
    map->SetBlurAngle(0.1);
    double blurMean[3], blurEnergy;
    Moments(map, blurMean, blurEnergy);
    // Radiance 0.1 rad from the spot's centre, in four directions around it.
    double centre[3];
    std::copy(sharpMean, sharpMean + 3, centre);
    vtkMath::Normalize(centre);
    double side[3] = { 0.0, 0.0, 1.0 };
    if (std::abs(centre[2]) > 0.9)
    {
      side[0] = 1.0;
      side[2] = 0.0;
    }
    double a[3], b[3];
    vtkMath::Cross(centre, side, a);
    vtkMath::Normalize(a);
    vtkMath::Cross(centre, a, b);
    double lo = 1e300, hi = 0.0;
    for (int q = 0; q < 4; ++q)
    {
      const double angle = q * Pi / 2;
      double d[3], rgb[3];
      for (int k = 0; k < 3; ++k)
      {
        d[k] = std::cos(0.1) * centre[k] +
          std::sin(0.1) * (std::cos(angle) * a[k] + std::sin(angle) * b[k]);
      }
      map->Radiance(d, rgb);
      lo = std::min(lo, rgb[0]);
      hi = std::max(hi, rgb[0]);
    }
    const double moved = vtkMath::DegreesFromRadians(Angle(sharpMean, blurMean));
    std::cout << (spot == 0 ? "spot by the pole" : "spot on the seam") << ": energy " << sharpEnergy
              << " -> " << blurEnergy << ", centre moved " << moved
              << " deg, radiance around it from " << lo << " to " << hi << "\n";
    Check(std::abs(blurEnergy - sharpEnergy) < 0.02 * sharpEnergy && moved < 1.0 &&
        (hi - lo) < 0.1 * hi,
      spot == 0 ? "blur by the pole" : "blur across the seam");
  }

  // Queries from many threads on a fresh map (the first one prepares the working image) give what
  // one thread gets: the working image and harmonics are built once, not by several threads over
  // each other.
  for (int trial = 0; trial < 4; ++trial)
  {
    vtkNew<vtkEnvironmentMap> serial, shared;
    serial->SetImage(reader->GetOutput());
    shared->SetImage(reader->GetOutput());
    serial->SetBlurAngle(0.05);
    shared->SetBlurAngle(0.05);
    const int queries = 4096;
    std::vector<double> expected(3 * queries), got(3 * queries);
    auto direction = [](int q, double d[3])
    {
      const double z = 1.0 - 2.0 * (q + 0.5) / queries, phi = 2.399963 * q;
      const double r = std::sqrt(1.0 - z * z);
      d[0] = r * std::cos(phi);
      d[1] = r * std::sin(phi);
      d[2] = z;
    };
    for (int q = 0; q < queries; ++q)
    {
      double d[3];
      direction(q, d);
      serial->Radiance(d, &expected[3 * q]);
    }
    vtkSMPTools::For(0, queries, 1,
      [&](vtkIdType first, vtkIdType last)
      {
        for (vtkIdType q = first; q < last; ++q)
        {
          double d[3];
          direction(static_cast<int>(q), d);
          shared->Radiance(d, &got[3 * q]);
        }
      });
    const double n[3] = { 0.0, 0.0, 1.0 };
    double a[3], b[3];
    serial->Irradiance(n, a);
    shared->Irradiance(n, b);
    Check(expected == got && a[0] == b[0] && a[1] == b[1] && a[2] == b[2],
      "queries from several threads on a fresh map");
  }
  return vtkApertureTest::Result();
}
