/*=========================================================================

  Program:   ApertureLighting
  Module:    VolumeFuzzSeeds.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Small volumes to start fuzzing the volume path from, each prefixed by FuzzVolumeReaders'
// format byte: a ball in a 10 x 5 x 4 grid as VTI (ASCII, base64, raw appended), MetaImage
// (raw and zlib), NRRD (raw and ASCII), NIfTI and gzipped NIfTI, and a flat VTI (a height field).

#ifndef VolumeFuzzSeeds_h
#define VolumeFuzzSeeds_h

#include "FuzzReplay.h"

#include <vector>

std::vector<FuzzSeed> VolumeFuzzSeeds();

#endif
