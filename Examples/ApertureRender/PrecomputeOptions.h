/*=========================================================================

  Program:   ApertureLighting
  Module:    PrecomputeOptions.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// aperture-precompute's command line: what it accepts, checked, with its help text.

#ifndef PrecomputeOptions_h
#define PrecomputeOptions_h

#include <cmath>
#include <string>

namespace AperturePrecompute
{
// What to write: vtkAperturePrecompute's arrays, chosen by --outputs.
struct Outputs
{
  bool Apertures = true; // BentNormal, ApertureRadius, AmbientOcclusion
  bool Horizons = false;
  bool SkyViewFactor = false;
  bool SkyViewFactorCosine = false;
  bool PositiveOpenness = false;
  bool NegativeOpenness = false;
};

struct Options
{
  std::string Input, Output;
  double MaximumDistance = 0.0; // 0: no limit
  int Sectors = 32;
  int TileSize = 5120;
  double VerticalScale = 1.0;
  bool Compress = false, Quiet = false, CloudOptimized = false;
  Outputs What;
  std::string GrassHorizons;            // prefix of r.sun's horizon rasters; empty: none
  double SectorRotation = std::nan(""); // degrees; NaN: not given
  int NoDataAs = 0;                     // vtkAperturePrecompute's NoDataAs
  double EarthRadius = 0.0;             // metres; 0: flat ground
};

// Parses the arguments (without the program's name). False when the program should stop: with
// `status` 0 after --help, else 2 after one line on stderr.
bool Parse(int argc, const char* const* argv, Options& options, int& status);

// Prints one line on stderr and sets `status`; returns false.
bool Fail(const std::string& message, int& status, int code);
}

#endif
