/*=========================================================================

  Program:   ApertureLighting
  Module:    FuzzVolumeReaders.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The volume fuzz target's input: a format byte (0: .vti, 1: .mha, 2: .nrrd, 3: .nii,
// 4: .nii.gz, modulo 5), then the file.

#ifndef FuzzVolumeReaders_h
#define FuzzVolumeReaders_h

#include <cstddef>
#include <cstdint>
#include <string>

namespace ApertureRender
{
struct Input;
}

// Reads `data` as aperture-render reads a volume file (through a file of this process's own,
// since VTK's readers read files). False with one sentence in `error` when it is not a usable
// volume or height field.
bool ReadFuzzVolume(
  const std::uint8_t* data, std::size_t size, ApertureRender::Input& input, std::string& error);

#endif
