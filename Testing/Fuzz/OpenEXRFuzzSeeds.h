/*=========================================================================

  Program:   ApertureLighting
  Module:    OpenEXRFuzzSeeds.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Small EXR files, written in memory with the OpenEXR library, to start fuzzing from: every
// compression, scanline and tiled, half and float, RGB, RGBA, Y and luminance-chroma, and a data
// window inside the display window.

#ifndef OpenEXRFuzzSeeds_h
#define OpenEXRFuzzSeeds_h

#include "FuzzReplay.h"

#include <vector>

std::vector<FuzzSeed> OpenEXRFuzzSeeds();

#endif
