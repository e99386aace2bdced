/*=========================================================================

  Program:   ApertureLighting
  Module:    BenchmarkTerrain.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Terrain at scale, measured side by side in one run (Markdown on stdout):
//  1. accuracy on the Mount Fuji tile (512 x 512, 30 m): horizon sweeps (16, 32, 64 sectors) and
//     rays (64 ... 1024) against 4096 rays per texel: visible-fraction RMS, mean bent-normal
//     angle, mean |AO difference|; the ray count that matches the horizons' visible fraction;
//  2. speed at 4096 x 4096 (the tile resampled): horizons against rays, the rays timed at two
//     counts and their time at the matching count from the straight line through them (a
//     run's time is BVH build plus rays, linear in the count);
//  3. a 10,000 x 10,000 DEM from a GeoTIFF on disk to a GeoTIFF of apertures, tiled with a search
//     radius: wall time and peak resident memory;
//  4. scaling: time per texel-sector over grid sizes and sector counts;
//  5. the peak memory of the tiled GeoTIFF path over DEM sizes;
//  6. keeping the horizons against apertures only;
//  7. normals kept as floats (the filter's default) against packed in 4 bytes in the AO array
//     (ComputeNormals off, as aperture-precompute runs): time and peak memory.
//
// Usage: BenchmarkTerrain <Testing/Data folder> <scratch folder> [--quick | --section N]
// --quick shrinks every size (a smoke test that the benchmark still works); --section N runs
// only section N (2 with the matching ray count of section 1's full run, 256).

#include "vtkApertureBenchmarkMemory.h"
#include "vtkAperturePrecompute.h"
#include "vtkGDALDEMReader.h"
#include "vtkGDALGridWriter.h"
#include "vtkTerrainRGBReader.h"

#include "vtkDataArray.h"
#include "vtkImageChangeInformation.h"
#include "vtkImageData.h"
#include "vtkImageResize.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace
{
using vtkApertureBenchmark::ResetPeak;
using vtkApertureBenchmark::StatusKiB;

double Since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The Fuji tile (30 m texels) resampled to side x side over the same ground.
vtkSmartPointer<vtkImageData> Fuji(const std::string& data, int side)
{
  vtkNew<vtkTerrainRGBReader> reader;
  reader->SetFileName((data + "/fuji-terrain-rgb.png").c_str());
  reader->SetSpacing(30.0, 30.0);
  vtkNew<vtkImageResize> resize;
  resize->SetInputConnection(reader->GetOutputPort());
  resize->SetOutputDimensions(side, side, 1);
  resize->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->ShallowCopy(resize->GetOutput());
  const double spacing = 30.0 * 511.0 / (side - 1);
  image->SetSpacing(spacing, spacing, 1.0);
  return image;
}

struct Caps
{
  vtkSmartPointer<vtkDataArray> Radius, Bent, Occlusion;
  double Seconds = 0.0;
};

// rays > 0: that many rays per texel; else -rays sectors.
Caps Run(vtkImageData* image, int rays)
{
  vtkNew<vtkAperturePrecompute> filter;
  filter->SetInputData(image);
  filter->ComputeAmbientOcclusionOn();
  if (rays > 0)
  {
    filter->SetMethodToRays();
    filter->SetNumberOfRays(rays);
  }
  else
  {
    filter->SetMethodToHorizons();
    filter->SetNumberOfSectors(-rays);
  }
  const auto start = std::chrono::steady_clock::now();
  filter->Update();
  Caps caps;
  caps.Seconds = Since(start);
  vtkPointData* pd = filter->GetImageDataOutput()->GetPointData();
  caps.Radius = pd->GetArray("ApertureRadius");
  caps.Bent = pd->GetArray("BentNormal");
  caps.Occlusion = pd->GetArray("AmbientOcclusion");
  return caps;
}

struct Errors
{
  double Fraction = 0.0, Degrees = 0.0, Occlusion = 0.0;
};

Errors Compare(const Caps& a, const Caps& reference)
{
  Errors e;
  const vtkIdType n = reference.Radius->GetNumberOfTuples();
  for (vtkIdType t = 0; t < n; ++t)
  {
    const double d = std::cos(reference.Radius->GetTuple1(t)) - std::cos(a.Radius->GetTuple1(t));
    e.Fraction += d * d;
    double u[3], v[3];
    a.Bent->GetTuple(t, u);
    reference.Bent->GetTuple(t, v);
    e.Degrees += vtkMath::DegreesFromRadians(vtkMath::AngleBetweenVectors(u, v));
    e.Occlusion += std::abs(a.Occlusion->GetTuple1(t) - reference.Occlusion->GetTuple1(t));
  }
  e.Fraction = std::sqrt(e.Fraction / n);
  e.Degrees /= n;
  e.Occlusion /= n;
  return e;
}

// Section 1; returns the smallest ray count whose visible fraction is as close to the reference
// as 32 sectors' (or the largest tried).
int Accuracy(const std::string& data, bool quick)
{
  const int side = quick ? 64 : 512, referenceRays = 4096;
  auto fuji = Fuji(data, side);
  const Caps reference = Run(fuji, referenceRays);
  std::printf(
    "\n### 1. Accuracy on the Fuji tile (%d x %d), against %d rays per texel (%.1f s)\n\n", side,
    side, referenceRays, reference.Seconds);
  std::printf(
    "| method | time (s) | visible fraction RMS (goal <= 0.01) | bent normal, mean "
    "(goal <= 2 deg) | AO, mean abs. difference (goal <= 0.01) |\n|---|---|---|---|---|\n");
  double horizons = 0.0;
  for (const int sectors : { 16, 32, 64 })
  {
    const Caps caps = Run(fuji, -sectors);
    const Errors e = Compare(caps, reference);
    horizons = sectors == 32 ? e.Fraction : horizons;
    std::printf("| horizons, %d sectors | %.2f | %.4f | %.2f deg | %.4f |\n", sectors, caps.Seconds,
      e.Fraction, e.Degrees, e.Occlusion);
  }
  int matching = 0;
  for (const int rays : { 64, 128, 256, 512, 1024 })
  {
    const Caps caps = Run(fuji, rays);
    const Errors e = Compare(caps, reference);
    std::printf("| rays, %d per texel | %.2f | %.4f | %.2f deg | %.4f |\n", rays, caps.Seconds,
      e.Fraction, e.Degrees, e.Occlusion);
    matching = matching == 0 && (e.Fraction <= horizons || rays == 1024) ? rays : matching;
  }
  std::printf("\nRays per texel whose visible fraction is as close as 32 sectors': %d\n", matching);
  return matching;
}

// Section 2.
void Speed(const std::string& data, bool quick, int matching)
{
  const int side = quick ? 256 : 4096;
  auto fuji = Fuji(data, side);
  const Caps horizons = Run(fuji, -32);
  const int low = 8, high = 32;
  const double tLow = Run(fuji, low).Seconds, tHigh = Run(fuji, high).Seconds;
  const double perRay = (tHigh - tLow) / (high - low);
  const double atMatching = tLow + perRay * (matching - low);
  std::printf("\n### 2. Speed at %d x %d\n\n| measure | value |\n|---|---|\n", side, side);
  std::printf("| horizons, 32 sectors | %.2f s |\n", horizons.Seconds);
  std::printf("| rays, %d and %d per texel | %.2f s, %.2f s |\n", low, high, tLow, tHigh);
  std::printf("| rays, %d per texel (equal accuracy; from the line through those) | %.1f s |\n",
    matching, atMatching);
  std::printf(
    "| rays at equal accuracy / horizons (goal >= 20) | %.1f |\n", atMatching / horizons.Seconds);
  std::printf(
    "| rays, %d per texel (less accurate) / horizons | %.1f |\n", high, tHigh / horizons.Seconds);
}

// Writes the Fuji tile resampled to side x side as a Float32 GeoTIFF, a tile at a time.
std::string WriteDEM(const std::string& data, const std::string& scratch, int side)
{
  vtkNew<vtkTerrainRGBReader> reader;
  reader->SetFileName((data + "/fuji-terrain-rgb.png").c_str());
  vtkNew<vtkImageResize> resize;
  resize->SetInputConnection(reader->GetOutputPort());
  resize->SetOutputDimensions(side, side, 1);
  vtkNew<vtkImageChangeInformation> ground;
  ground->SetInputConnection(resize->GetOutputPort());
  const double spacing = 30.0 * 511.0 / (side - 1);
  ground->SetOutputSpacing(spacing, spacing, 1.0);
  const std::string name = scratch + "/dem-" + std::to_string(side) + ".tif";
  vtkNew<vtkGDALGridWriter> writer;
  writer->SetInputConnection(ground->GetOutputPort());
  writer->SetFileName(name.c_str());
  writer->SetTileRows(512);
  writer->Write();
  return name;
}

struct Batch
{
  double Seconds;
  long PeakMiB;
};

// aperture-precompute's pipeline: GeoTIFF -> horizons -> GeoTIFF, tiled.
Batch Precompute(
  const std::string& dem, const std::string& out, double radius, int tile, int sectors = 32)
{
  ResetPeak();
  const auto start = std::chrono::steady_clock::now();
  {
    vtkNew<vtkGDALDEMReader> reader;
    reader->SetFileName(dem.c_str());
    vtkNew<vtkAperturePrecompute> filter;
    filter->SetInputConnection(reader->GetOutputPort());
    filter->SetMethodToHorizons();
    filter->SetNumberOfSectors(sectors);
    filter->ComputeAmbientOcclusionOn();
    filter->LimitDistanceOn();
    filter->SetMaximumDistance(radius);
    vtkNew<vtkGDALGridWriter> writer;
    writer->SetInputConnection(filter->GetOutputPort());
    writer->SetFileName(out.c_str());
    writer->SetTileRows(tile);
    writer->SetTileColumns(tile);
    writer->Write();
  }
  return { Since(start), StatusKiB("VmHWM:") / 1024 };
}

// Section 3.
void BigDEM(const std::string& data, const std::string& scratch, bool quick)
{
  const int big = quick ? 1000 : 10000, tile = quick ? 256 : 5120, halo = quick ? 50 : 500;
  const double spacing = 30.0 * 511.0 / (big - 1), radius = halo * spacing;
  std::printf("\n### 3. %d x %d DEM, GeoTIFF to GeoTIFF\n\n", big, big);
  const std::string dem = WriteDEM(data, scratch, big);
  std::printf("Fuji resampled, %.3f m texels, search radius %.0f m (%d texels), tiles of %d x %d, "
              "%d threads.\n\n| sectors | wall time, read + horizons + write (goal <= 60 s) | "
              "peak resident memory (goal <= 4 GB) |\n|---|---|---|\n",
    spacing, radius, halo, tile, tile, vtkSMPTools::GetEstimatedNumberOfThreads());
  for (const int sectors : { 16, 32 })
  {
    const Batch run = Precompute(dem, scratch + "/apertures.tif", radius, tile, sectors);
    std::printf("| %d | %.1f s | %ld MiB |\n", sectors, run.Seconds, run.PeakMiB);
  }
  std::remove(dem.c_str());
  std::remove((scratch + "/apertures.tif").c_str());
}

// Section 5.
void MemoryOverSizes(const std::string& data, const std::string& scratch, bool quick)
{
  const int tile = quick ? 128 : 1024;
  std::printf("\n### 5. Peak memory of the tiled GeoTIFF path over DEM sizes (radius 100 texels, "
              "tiles of %d x %d)\n\n| DEM | time (s) | peak (MiB) |\n|---|---|---|\n",
    tile, tile);
  for (const int side : quick ? std::vector<int>{ 200, 400 } : std::vector<int>{ 2500, 5000, 7500 })
  {
    const std::string file = WriteDEM(data, scratch, side);
    const double s = 30.0 * 511.0 / (side - 1);
    const Batch b = Precompute(file, scratch + "/apertures.tif", 100.0 * s, tile);
    std::printf("| %d x %d | %.1f | %ld |\n", side, side, b.Seconds, b.PeakMiB);
    std::remove(file.c_str());
  }
  std::remove((scratch + "/apertures.tif").c_str());
}

// Section 4.
void Scaling(const std::string& data, bool quick)
{
  std::printf("\n### 4. Horizon time per texel-sector (whole grid, no radius)\n\n| grid | "
              "sectors | time (s) | ns per texel-sector |\n|---|---|---|---|\n");
  for (const int side : quick ? std::vector<int>{ 64, 128 } : std::vector<int>{ 1024, 2048, 4096 })
  {
    auto fuji = Fuji(data, side);
    for (const int sectors : { 8, 16, 32, 64 })
    {
      const double seconds = Run(fuji, -sectors).Seconds;
      std::printf("| %d x %d | %d | %.2f | %.1f |\n", side, side, sectors, seconds,
        1e9 * seconds / (double(side) * side * sectors));
    }
  }
}
}

// Section 6.
void KeptHorizons(const std::string& data, bool quick)
{
  const int side = quick ? 256 : 2048, rounds = quick ? 2 : 5;
  auto fuji = Fuji(data, side);
  // Alternating runs, so that the machine's noise falls on both alike.
  std::vector<double> plain, kept;
  for (int round = 0; round < rounds; ++round)
  {
    for (const bool keep : { false, true })
    {
      vtkNew<vtkAperturePrecompute> filter;
      filter->SetInputData(fuji);
      filter->SetMethodToHorizons();
      filter->SetComputeHorizonAngles(keep);
      const auto start = std::chrono::steady_clock::now();
      filter->Update();
      (keep ? kept : plain).push_back(Since(start));
    }
  }
  std::sort(plain.begin(), plain.end());
  std::sort(kept.begin(), kept.end());
  const double a = plain[plain.size() / 2], b = kept[kept.size() / 2];
  std::printf("\n### 6. Keeping the horizons (%d x %d, 32 sectors, median of %d alternating runs)"
              "\n\n| sweep | time (s) |\n|---|---|\n| apertures only | %.2f |\n"
              "| apertures and HorizonAngles | %.2f |\n| ratio (goal <= 1.15) | %.2f |\n",
    side, side, rounds, a, b, b / a);
}

// Section 7.
void RecomputedNormals(const std::string& data, bool quick)
{
  const int side = quick ? 256 : 4096, rounds = quick ? 2 : 3;
  auto fuji = Fuji(data, side);
  std::vector<double> seconds[2]; // [kept]
  long peak[2] = { 0, 0 };
  for (int round = 0; round < rounds; ++round) // alternating, as in section 6
  {
    for (const bool keep : { true, false })
    {
      ResetPeak();
      const auto start = std::chrono::steady_clock::now();
      {
        vtkNew<vtkAperturePrecompute> filter;
        filter->SetInputData(fuji);
        filter->SetMethodToHorizons();
        filter->ComputeAmbientOcclusionOn();
        filter->SetComputeNormals(keep);
        filter->Update();
      }
      seconds[keep].push_back(Since(start));
      peak[keep] = std::max(peak[keep], StatusKiB("VmHWM:") / 1024);
    }
  }
  for (auto& s : seconds)
  {
    std::sort(s.begin(), s.end());
  }
  const double kept = seconds[1][rounds / 2], packed = seconds[0][rounds / 2];
  std::printf(
    "\n### 7. Normals kept or packed (%d x %d, 32 sectors, no radius, AO, "
    "median of %d alternating runs)\n\n| normals | time (s) | peak (MiB) |\n"
    "|---|---|---|\n| kept (default) | %.2f | %ld |\n| packed in AO's array (ComputeNormals "
    "off) | %.2f | %ld |\n| ratio | %.2f | %.2f |\n",
    side, side, rounds, kept, peak[1], packed, peak[0], packed / kept, double(peak[0]) / peak[1]);
}

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::fprintf(stderr,
      "usage: BenchmarkTerrain <Testing/Data folder> <scratch folder> "
      "[--quick]\n");
    return 2;
  }
  const std::string data = argv[1], scratch = argv[2];
  const bool quick = argc > 3 && std::strcmp(argv[3], "--quick") == 0;
  const int only = argc > 4 && std::strcmp(argv[3], "--section") == 0 ? std::atoi(argv[4]) : 0;
  std::setvbuf(stdout, nullptr, _IOLBF, 0); // lines as they come: the full run takes minutes
  std::printf("## Terrain benchmark (%d threads)\n", vtkSMPTools::GetEstimatedNumberOfThreads());
  const int matching = only == 0 || only == 1 ? Accuracy(data, quick) : 256;
  if (only == 0 || only == 2)
  {
    Speed(data, quick, matching);
  }
  if (only == 0 || only == 3)
  {
    BigDEM(data, scratch, quick);
  }
  if (only == 0 || only == 4)
  {
    Scaling(data, quick);
  }
  if (only == 0 || only == 5)
  {
    MemoryOverSizes(data, scratch, quick);
  }
  if (only == 0 || only == 6)
  {
    KeptHorizons(data, quick);
  }
  if (only == 0 || only == 7)
  {
    RecomputedNormals(data, quick);
  }
  return 0;
}
