/*=========================================================================

  Program:   ApertureLighting
  Module:    GDALFuzzSeeds.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Small DEMs, written in memory with GDAL, to start fuzzing from: GeoTIFFs of Int16 (projected,
// with no-data), UInt16 (no CRS), Float32 (geographic, DEFLATE, tiled) and Float64 (Web
// Mercator, LZW, a band scale and offset). Not ESRI ASCII grids: GDAL 3.6's reader of them
// recurses without end on some damaged headers (`nrows 399 7 8 ...`), a bug of GDAL's that
// no caller can guard against.

#ifndef GDALFuzzSeeds_h
#define GDALFuzzSeeds_h

#include "FuzzReplay.h"

#include <vector>

std::vector<FuzzSeed> GDALFuzzSeeds();

#endif
