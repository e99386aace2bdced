/*=========================================================================

  Program:   ApertureLighting
  Module:    PrecomputeOptions.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "PrecomputeOptions.h"

#include "vtkApertureText.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <vector>

namespace AperturePrecompute
{
namespace
{
const char* const Usage = R"(usage: aperture-precompute DEM -o OUTPUT.tif [options]

Computes, by horizon sweeps, what every texel of a single-band DEM (GeoTIFF, or any raster GDAL
reads) sees of the sky, and writes it as a Float32 GeoTIFF with the DEM's georeferencing, one
band per value, each band named and with its unit. By default the visibility caps: bands
BentNormal_X/_Y/_Z, ApertureRadius (radian), AmbientOcclusion (1). No-data texels are NaN.

options:
  -o, --output FILE      the GeoTIFF to write (required)
  --outputs LIST         what to write, comma-separated (default: apertures):
                           apertures          BentNormal, ApertureRadius, AmbientOcclusion
                           svf                SkyViewFactor: visible fraction of the sky above
                                              the horizontal plane (Zakšek; SAGA's VISIBLE
                                              measures angles, not solid angle)
                           svf-cosine         SkyViewFactorCosine: cosine-weighted (Häntzschel;
                                              SAGA's SVF)
                           positive-openness  PositiveOpenness, degrees (Yokoyama)
                           negative-openness  NegativeOpenness, degrees
                           openness           both openness rasters
                           horizons           HorizonAngles_Az<azimuth>: each sector's horizon,
                                              radians above the horizontal plane, -pi/2 where
                                              nothing is in range, along the sector's middle
                                              azimuth (degrees counter-clockwise from east)
  --horizons             the same as adding horizons to --outputs
  --grass-horizons PREFIX  also write each sector's horizon as a raster of its own for GRASS's
                         r.sun: PREFIX_<angle>.tif, named and oriented as r.horizon names them
                         (directions 0, 360/D, ... counter-clockwise from east; the sectors are
                         turned so that these are their middles); then
                         r.sun horizon_basename=PREFIX horizon_step=<360/D>
  --max-distance M       limit the horizon search to M metres (default: none, the whole DEM;
                         also --max-distance none). With a limit the DEM is read and computed
                         in tiles, in bounded memory; openness is defined within this radius
  --sectors D            azimuth sectors, 4 to 1024 (default 32)
  --sector-rotation A    where sector 0 starts, degrees counter-clockwise from the DEM's
                         columns (default 0: sector k covers [360k/D, 360(k+1)/D)); -180/D puts
                         the middles on the axes, as SAGA's directions are
  --tile-size N          tiles of N x N texels with --max-distance (default 5120)
  --earth-curvature      count the Earth's curvature, radius 6371 km as GRASS's r.horizon and
                         r.sun take it: a sample d away lies d^2/2R lower (7.8 m at 10 km)
  --earth-radius R       the same on a sphere of R metres (R/(1 - k) counts refraction k)
  --vertical-scale S     factor from the DEM's height unit to metres (default 1; 0.3048: feet)
  --nodata-as MODE       what no-data texels are (they get NaN, unless filled):
                           open  neither occlude nor receive (default)
                           wall  block like a cliff as high as the DEM's highest texel
                           fill  heights interpolated between the valid texels within 64
                                 texels along rows, columns and diagonals, then computed
                                 like the others
  --compress             DEFLATE-compress the output
  --cog                  write a cloud-optimised GeoTIFF with overviews
  -q, --quiet            no progress bar or summary
  -h, --help             this text

examples:
  aperture-precompute N35E138.tif -o apertures.tif
  aperture-precompute lidar-1m.tif -o relief.tif --outputs svf,openness --max-distance 50
  aperture-precompute dem.tif -o caps.tif --grass-horizons hz --sectors 24
)";

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
    std::ostringstream range;
    range << flag << " takes a number from " << low << " to " << high << ", not "
          << vtkApertureText::Quote(args[k]);
    return Fail(range.str(), status, 2);
  }
  return true;
}

// The names of --outputs, each turning on what it names.
bool ParseOutputs(const std::string& list, Outputs& what, int& status)
{
  what = Outputs();
  what.Apertures = false;
  std::istringstream items(list);
  std::string item;
  bool any = false;
  while (std::getline(items, item, ','))
  {
    const bool openness = item == "openness";
    bool* flag = item == "apertures"            ? &what.Apertures
      : item == "horizons"                      ? &what.Horizons
      : item == "svf"                           ? &what.SkyViewFactor
      : item == "svf-cosine"                    ? &what.SkyViewFactorCosine
      : item == "positive-openness" || openness ? &what.PositiveOpenness
      : item == "negative-openness"             ? &what.NegativeOpenness
                                                : nullptr;
    if (!flag)
    {
      return Fail("unknown output " + vtkApertureText::Quote(item) +
          " (apertures, svf, svf-cosine, positive-openness, negative-openness, openness, "
          "horizons)",
        status, 2);
    }
    *flag = true;
    what.NegativeOpenness = what.NegativeOpenness || openness;
    any = true;
  }
  return any || Fail("--outputs names nothing", status, 2);
}

// Options that take a value; false when `a` is none of them.
bool ParseValue(const std::vector<std::string>& args, size_t& k, Options& o, int& status, bool& ok)
{
  const std::string& a = args[k];
  double v = 0.0;
  ok = true;
  if (a == "-o" || a == "--output" || a == "--outputs" || a == "--grass-horizons")
  {
    if (++k >= args.size())
    {
      ok = Fail(a + " needs a value", status, 2);
    }
    else if (a == "--outputs")
    {
      ok = ParseOutputs(args[k], o.What, status);
    }
    else
    {
      (a == "--grass-horizons" ? o.GrassHorizons : o.Output) = args[k];
    }
  }
  else if (a == "--max-distance" && k + 1 < args.size() && args[k + 1] == "none")
  {
    o.MaximumDistance = 0.0;
    ++k;
  }
  else if (a == "--max-distance" || a == "--vertical-scale" || a == "--earth-radius")
  {
    ok = Number(args, k, 1e-9, 1e12, v, status);
    (a == "--max-distance"      ? o.MaximumDistance
        : a == "--earth-radius" ? o.EarthRadius
                                : o.VerticalScale) = v;
  }
  else if (a == "--nodata-as")
  {
    const std::string mode = ++k < args.size() ? args[k] : "";
    o.NoDataAs = mode == "open" ? 0 : mode == "wall" ? 1 : mode == "fill" ? 2 : -1;
    ok = o.NoDataAs >= 0 ||
      Fail("--nodata-as takes open, wall or fill, not " + vtkApertureText::Quote(mode), status, 2);
  }
  else if (a == "--sector-rotation")
  {
    ok = Number(args, k, -360.0, 360.0, v, status);
    o.SectorRotation = v;
  }
  else if (a == "--sectors" || a == "--tile-size")
  {
    const bool sectors = a == "--sectors";
    ok = Number(args, k, sectors ? 4 : 1, sectors ? 1024 : 1e9, v, status);
    (sectors ? o.Sectors : o.TileSize) = static_cast<int>(v);
  }
  else
  {
    return false;
  }
  return true;
}

// What the options must agree on once all are read.
bool Check(Options& o, int& status)
{
  if (o.Input.empty() || o.Output.empty())
  {
    return Fail(
      o.Input.empty() ? "no DEM given (see --help)" : "no output given: -o FILE.tif", status, 2);
  }
  // GRASS names a direction's raster by the step's decimals: 360/D must have few.
  if (!o.GrassHorizons.empty() && 360000000 % o.Sectors != 0)
  {
    return Fail("--grass-horizons needs sectors whose step 360/D has at most 6 decimals (D = 8, "
                "16, 24, 32, 36, 64, ...), not " +
        std::to_string(o.Sectors),
      status, 2);
  }
  if (!o.GrassHorizons.empty() && !std::isnan(o.SectorRotation))
  {
    return Fail("--grass-horizons turns the sectors onto r.horizon's directions itself; leave out "
                "--sector-rotation",
      status, 2);
  }
  o.What.Horizons = o.What.Horizons || !o.GrassHorizons.empty();
  return true;
}
}

//------------------------------------------------------------------------------
bool Fail(const std::string& message, int& status, int code)
{
  std::cerr << "aperture-precompute: " << vtkApertureText::Line(message) << "\n";
  status = code;
  return false;
}

//------------------------------------------------------------------------------
bool Parse(int argc, const char* const* argv, Options& o, int& status)
{
  const std::vector<std::string> args(argv, argv + argc);
  bool horizons = false;
  for (size_t k = 0; k < args.size(); ++k)
  {
    const std::string& a = args[k];
    bool ok = true;
    if (a == "-h" || a == "--help")
    {
      std::cout << Usage;
      status = 0;
      return false;
    }
    else if (ParseValue(args, k, o, status, ok))
    {
      if (!ok)
      {
        return false;
      }
    }
    else if (a == "--earth-curvature")
    {
      o.EarthRadius = 6371000.0;
    }
    else if (a == "--compress" || a == "-q" || a == "--quiet" || a == "--horizons" || a == "--cog")
    {
      (a == "--compress"      ? o.Compress
          : a == "--horizons" ? horizons
          : a == "--cog"      ? o.CloudOptimized
                              : o.Quiet) = true;
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
  o.What.Horizons = o.What.Horizons || horizons;
  return Check(o, status);
}
}
