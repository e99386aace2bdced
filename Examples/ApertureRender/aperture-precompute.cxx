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
// Exit status: 0 on success, 1 when the input cannot be used or the output cannot be written,
// 2 for a bad command line. Every failure is one line on stderr.

#include "ApertureRenderMessages.h"

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
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace
{
const char* const Usage = R"(usage: aperture-precompute DEM -o OUTPUT.tif [options]

Computes the visibility caps (bent normal, aperture radius, ambient occlusion) of every texel of
a single-band DEM (GeoTIFF, or any raster GDAL reads) by horizon sweeps and writes them as a
Float32 GeoTIFF with the DEM's georeferencing: bands BentNormal_X/_Y/_Z, ApertureRadius,
AmbientOcclusion, and with --horizons one band per sector, HorizonAngles_Az<azimuth>: the
horizon's elevation in radians above the horizontal plane, -pi/2 where nothing is in range,
along the sector's middle azimuth in degrees counter-clockwise from east (the DEM's columns).
No-data texels are NaN.

options:
  -o, --output FILE      the GeoTIFF to write (required)
  --max-distance M       limit the horizon search to M metres (default: none, the whole DEM;
                         also --max-distance none). With a limit the DEM is read and computed
                         in tiles, in bounded memory
  --sectors D            azimuth sectors, 4 to 1024 (default 32)
  --tile-size N          tiles of N x N texels with --max-distance (default 5120)
  --vertical-scale S     factor from the DEM's height unit to metres (default 1; 0.3048: feet)
  --horizons             also write each sector's horizon (D bands more)
  --compress             DEFLATE-compress the output
  -q, --quiet            no progress bar or summary
  -h, --help             this text

examples:
  aperture-precompute N35E138.tif -o apertures.tif
  aperture-precompute lidar-1m.tif -o apertures.tif --max-distance 500 --sectors 64
)";

struct Options
{
  std::string Input, Output;
  double MaximumDistance = 0.0; // 0: no limit
  int Sectors = 32;
  int TileSize = 5120;
  double VerticalScale = 1.0;
  bool Compress = false, Quiet = false, Horizons = false;
};

bool Fail(const std::string& message, int& status, int code)
{
  std::cerr << "aperture-precompute: " << vtkApertureText::Line(message) << "\n";
  status = code;
  return false;
}

// A number after `flag`, within [low, high].
bool Number(const std::vector<std::string>& args, size_t& k, double low, double high, double& value,
  int& status)
{
  const std::string flag = args[k];
  if (++k >= args.size())
  {
    return Fail(flag + " needs a value", status, 2);
  }
  char* end = nullptr;
  value = std::strtod(args[k].c_str(), &end);
  if (end == args[k].c_str() || *end || !(value >= low && value <= high))
  {
    return Fail(flag + " takes a number from " + std::to_string(low) + " to " +
        std::to_string(high) + ", not " + vtkApertureText::Quote(args[k]),
      status, 2);
  }
  return true;
}

bool Parse(const std::vector<std::string>& args, Options& o, int& status)
{
  for (size_t k = 0; k < args.size(); ++k)
  {
    const std::string& a = args[k];
    double v = 0.0;
    if (a == "-h" || a == "--help")
    {
      std::cout << Usage;
      status = 0;
      return false;
    }
    else if (a == "-o" || a == "--output")
    {
      if (++k >= args.size())
      {
        return Fail(a + " needs a file name", status, 2);
      }
      o.Output = args[k];
    }
    else if (a == "--max-distance" && k + 1 < args.size() && args[k + 1] == "none")
    {
      o.MaximumDistance = 0.0;
      ++k;
    }
    else if (a == "--max-distance" || a == "--vertical-scale")
    {
      if (!Number(args, k, 1e-9, 1e12, v, status))
      {
        return false;
      }
      (a == "--max-distance" ? o.MaximumDistance : o.VerticalScale) = v;
    }
    else if (a == "--sectors" || a == "--tile-size")
    {
      const bool sectors = a == "--sectors";
      if (!Number(args, k, sectors ? 4 : 1, sectors ? 1024 : 1e9, v, status))
      {
        return false;
      }
      (sectors ? o.Sectors : o.TileSize) = static_cast<int>(v);
    }
    else if (a == "--compress" || a == "-q" || a == "--quiet" || a == "--horizons")
    {
      (a == "--compress" ? o.Compress : a == "--horizons" ? o.Horizons : o.Quiet) = true;
    }
    else if (!a.empty() && a[0] == '-')
    {
      return Fail("unknown option " + vtkApertureText::Quote(a) + " (see --help)", status, 2);
    }
    else if (o.Input.empty())
    {
      o.Input = a;
    }
    else
    {
      return Fail(
        "one DEM at a time; " + vtkApertureText::QuoteName(a) + " is a second one", status, 2);
    }
  }
  if (o.Input.empty() || o.Output.empty())
  {
    return Fail(
      o.Input.empty() ? "no DEM given (see --help)" : "no output given: -o FILE.tif", status, 2);
  }
  return true;
}
}

int main(int argc, char* argv[])
{
  int status = 1;
  Options o;
  if (!Parse(std::vector<std::string>(argv + 1, argv + argc), o, status))
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
  filter->SetMethodToHorizons();
  filter->SetNumberOfSectors(o.Sectors);
  filter->ComputeAmbientOcclusionOn();
  filter->SetComputeHorizonAngles(o.Horizons);
  if (o.MaximumDistance > 0.0)
  {
    filter->LimitDistanceOn();
    filter->SetMaximumDistance(o.MaximumDistance);
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

  const auto start = std::chrono::steady_clock::now();
  int ok = 0;
  {
    // Tiles report through the writer; a whole DEM through the filter.
    vtkAlgorithm* reporter = tile > 0 ? static_cast<vtkAlgorithm*>(writer) : filter.Get();
    std::unique_ptr<ApertureRender::ProgressBar> bar(
      o.Quiet ? nullptr : new ApertureRender::ProgressBar(reporter, "Horizons"));
    ok = writer->Write();
  }
  if (!ok || !messages.FirstError().empty())
  {
    return Fail(messages.FirstErrorOr("cannot write " + vtkApertureText::QuoteName(o.Output)),
             status, 1),
           status;
  }
  if (!o.Quiet)
  {
    const int* extent = whole;
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << "Wrote " << vtkApertureText::QuoteName(o.Output) << ": " << extent[1] + 1 << " x "
              << extent[3] + 1 << " texels, " << o.Sectors << " sectors, spacing "
              << reader->GetOutput()->GetSpacing()[0] << " x "
              << reader->GetOutput()->GetSpacing()[1] << " m (" << reader->GetGroundSpacingNote()
              << "), " << seconds << " s\n";
    for (const auto& warning : messages.Warnings())
    {
      std::cout << "note: " << vtkApertureText::Line(warning) << "\n";
    }
  }
  return 0;
}
