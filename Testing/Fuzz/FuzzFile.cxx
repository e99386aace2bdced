/*=========================================================================

  Program:   ApertureLighting
  Module:    FuzzFile.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "FuzzFile.h"

#include <unistd.h>

#include <cstdio>
#include <fstream>

//------------------------------------------------------------------------------
FuzzFile::FuzzFile(
  const std::uint8_t* data, std::size_t size, const std::vector<std::string>& extensions)
{
  if (size == 0)
  {
    return;
  }
  this->Extension = extensions[data[0] % extensions.size()];
  this->Name =
    "/tmp/aperture-fuzz-" + std::to_string(static_cast<long>(getpid())) + this->Extension;
  std::ofstream file(this->Name, std::ios::binary);
  file.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
}

//------------------------------------------------------------------------------
FuzzFile::~FuzzFile()
{
  if (!this->Name.empty())
  {
    std::remove(this->Name.c_str());
  }
}
