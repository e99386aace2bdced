/*=========================================================================

  Program:   ApertureLighting
  Module:    aperture-precompute.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// aperture-precompute: the apertures of a DEM too big to render, from a GeoTIFF (or any raster
// GDAL reads) to a GeoTIFF with the same georeferencing, a tile at a time.
//
//   aperture-precompute DEM.tif -o apertures.tif [--max-distance M] [--sectors D] ...
//
// Options in PrecomputeOptions.cxx. Exit status: 0 on success, 1 when the input cannot be used or
// the output cannot be written, 2 for a bad command line. Every failure is one line on stderr.

#include "ApertureRenderMessages.h"
#include "PrecomputeOptions.h"

#include "vtkAperturePrecompute.h"
#include "vtkApertureText.h"
#include "vtkGDALDEMReader.h"
#include "vtkGDALGridWriter.h"

#include "vtkDataObject.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using namespace AperturePrecompute;

// The decimals of GRASS's step 360/D ("11.25": 2), which its raster names carry.
int GrassStepDecimals(int sectors)
{
  int decimals = 0;
  for (long long scaled = 360; scaled % sectors != 0; scaled *= 10)
  {
    ++decimals;
  }
  return decimals;
}

// r.horizon's name of the raster for direction k: PREFIX_011_25 (integer degrees in three
// digits, then the step's decimals).
std::string GrassHorizonName(const std::string& prefix, int k, int sectors)
{
  const int decimals = GrassStepDecimals(sectors);
  long long scale = 1;
  for (int d = 0; d < decimals; ++d)
  {
    scale *= 10;
  }
  const long long fixed = 360LL * scale * k / sectors; // exact: the step divides 360 × scale
  std::ostringstream name;
  name << prefix << "_" << std::setw(3) << std::setfill('0') << fixed / scale;
  if (decimals > 0)
  {
    name << "_" << std::setw(decimals) << std::setfill('0') << fixed % scale;
  }
  return name.str();
}

// The filter for the options' outputs; `convergence` turns the grid's azimuths into true ones.
void Configure(vtkAperturePrecompute* filter, const Options& o, double convergence)
{
  filter->SetMethodToHorizons();
  filter->SetNumberOfSectors(o.Sectors);
  filter->SetComputeAmbientOcclusion(o.What.Apertures);
  filter->ComputeNormalsOff(); // not written: 1.2 GB less on a 10,000² DEM
  filter->SetComputeHorizonAngles(o.What.Horizons);
  filter->SetComputeSkyViewFactor(o.What.SkyViewFactor);
  filter->SetComputeSkyViewFactorCosine(o.What.SkyViewFactorCosine);
  filter->SetComputePositiveOpenness(o.What.PositiveOpenness);
  filter->SetComputeNegativeOpenness(o.What.NegativeOpenness);
  filter->SetNoDataAs(o.NoDataAs);
  filter->SetEarthRadius(o.EarthRadius);
  if (!o.GrassHorizons.empty()) // r.horizon's true directions 0, 360/D, ... as sector middles
  {
    filter->SetSectorRotation(convergence - 180.0 / o.Sectors);
  }
  else if (!std::isnan(o.SectorRotation))
  {
    filter->SetSectorRotation(o.SectorRotation);
  }
  if (o.MaximumDistance > 0.0)
  {
    filter->LimitDistanceOn();
    filter->SetMaximumDistance(o.MaximumDistance);
  }
}

// The writer's arrays, in the order of the bands; returns the bands before the horizons', which
// come last.
int ChooseArrays(vtkGDALGridWriter* writer, const Outputs& what)
{
  struct Array
  {
    bool Wanted;
    const char* Name;
    int Bands;
  };
  const Array arrays[] = { { what.Apertures, "BentNormal", 3 },
    { what.Apertures, "ApertureRadius", 1 }, { what.Apertures, "AmbientOcclusion", 1 },
    { what.SkyViewFactor, "SkyViewFactor", 1 },
    { what.SkyViewFactorCosine, "SkyViewFactorCosine", 1 },
    { what.PositiveOpenness, "PositiveOpenness", 1 },
    { what.NegativeOpenness, "NegativeOpenness", 1 } };
  int bands = 0;
  for (const auto& array : arrays)
  {
    if (array.Wanted)
    {
      writer->AddArrayName(array.Name);
      bands += array.Bands;
    }
  }
  if (what.Horizons)
  {
    writer->AddArrayName("HorizonAngles");
  }
  return bands;
}

// Copies the horizon bands, after the first `before`, into r.horizon's rasters; the file names
// written.
bool WriteGrassHorizons(
  vtkGDALGridWriter* writer, const Options& o, int before, std::vector<std::string>& written)
{
  for (int k = 0; k < o.Sectors; ++k)
  {
    written.push_back(GrassHorizonName(o.GrassHorizons, k, o.Sectors) + ".tif");
    if (!writer->WriteBandCopy(before + 1 + k, written.back().c_str()))
    {
      return false;
    }
  }
  return true;
}

// What was written, and the warnings on the way.
void PrintSummary(const Options& o, vtkGDALDEMReader* reader, const int whole[6], double seconds,
  const std::vector<std::string>& grass, const ApertureRender::MessageCapture& messages)
{
  const double* spacing = reader->GetOutput()->GetSpacing();
  std::cout << "Wrote " << vtkApertureText::QuoteName(o.Output) << ": " << whole[1] + 1 << " x "
            << whole[3] + 1 << " texels, " << o.Sectors << " sectors, spacing " << spacing[0]
            << " x " << spacing[1] << " m (" << reader->GetGroundSpacingNote() << "), ";
  if (o.EarthRadius > 0.0)
  {
    std::cout << "Earth radius " << o.EarthRadius / 1000.0 << " km, ";
  }
  std::cout << seconds << " s\n";
  if (!grass.empty())
  {
    std::cout << "Wrote " << grass.size() << " horizon rasters for r.sun, "
              << vtkApertureText::QuoteName(grass.front()) << " to "
              << vtkApertureText::QuoteName(grass.back())
              << " (horizon_step=" << std::setprecision(GrassStepDecimals(o.Sectors) + 3)
              << 360.0 / o.Sectors << "; grid north " << std::setprecision(3)
              << reader->GetGridConvergence() << " degrees from true north)\n";
  }
  for (const auto& warning : messages.Warnings())
  {
    std::cout << "note: " << vtkApertureText::Line(warning) << "\n";
  }
}
}

int main(int argc, char* argv[])
{
  int status = 1;
  Options o;
  if (!Parse(argc - 1, argv + 1, o, status))
  {
    return status;
  }
  ApertureRender::MessageCapture messages;
  vtkNew<vtkGDALDEMReader> reader;
  reader->SetFileName(o.Input.c_str());
  reader->SetVerticalScale(o.VerticalScale);
  reader->UpdateInformation();
  if (!messages.FirstError().empty())
  {
    return Fail(messages.FirstError(), status, 1), status;
  }
  vtkNew<vtkAperturePrecompute> filter;
  filter->SetInputConnection(reader->GetOutputPort());
  Configure(filter, o, reader->GetGridConvergence());
  double range[2];
  if (o.NoDataAs == vtkAperturePrecompute::NO_DATA_WALL) // tiles must agree on the walls' height
  {
    if (!reader->ComputeHeightRange(range))
    {
      return Fail(messages.FirstErrorOr("cannot read the DEM's heights"), status, 1), status;
    }
    filter->SetNoDataWallHeight(range[1]);
  }
  // Tiles when the search radius leaves room for them (each tile reads its radius around it).
  int whole[6];
  reader->GetOutputInformation(0)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
  const double* spacing = reader->GetOutputInformation(0)->Get(vtkDataObject::SPACING());
  const double side = std::max((whole[1] + 1) * spacing[0], (whole[3] + 1) * spacing[1]);
  const int tile = o.MaximumDistance > 0.0 && o.MaximumDistance < side ? o.TileSize : 0;
  vtkNew<vtkGDALGridWriter> writer;
  writer->SetInputConnection(filter->GetOutputPort());
  writer->SetFileName(o.Output.c_str());
  writer->SetTileRows(tile);
  writer->SetTileColumns(tile);
  writer->SetCompress(o.Compress);
  writer->SetCloudOptimized(o.CloudOptimized);
  const int beforeHorizons = ChooseArrays(writer, o.What);

  const auto start = std::chrono::steady_clock::now();
  int ok = 0;
  {
    // Tiles report through the writer; a whole DEM through the filter.
    vtkAlgorithm* reporter = tile > 0 ? static_cast<vtkAlgorithm*>(writer) : filter.Get();
    std::unique_ptr<ApertureRender::ProgressBar> bar(
      o.Quiet ? nullptr : new ApertureRender::ProgressBar(reporter, "Horizons"));
    ok = writer->Write();
  }
  std::vector<std::string> grass;
  if (ok && !o.GrassHorizons.empty() && !WriteGrassHorizons(writer, o, beforeHorizons, grass))
  {
    ok = 0; // a run that fails leaves no file behind
    grass.push_back(o.Output);
    std::for_each(grass.begin(), grass.end(), [](const std::string& f) { std::remove(f.c_str()); });
  }
  if (!ok || !messages.FirstError().empty())
  {
    return Fail(messages.FirstErrorOr("cannot write " + vtkApertureText::QuoteName(o.Output)),
             status, 1),
           status;
  }
  if (!o.Quiet)
  {
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    PrintSummary(o, reader, whole, seconds, grass, messages);
  }
  return 0;
}
