/*=========================================================================

  Program:   ApertureLighting
  Module:    FuzzFile.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// A fuzz input as the file VTK's readers want: its first byte picks the format (the extension),
// the rest is the file's content, written where only this process writes.

#ifndef FuzzFile_h
#define FuzzFile_h

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

class FuzzFile
{
public:
  // Writes the file for `data` (nothing when it is empty); `extensions` are the formats the first
  // byte picks from, modulo their count.
  FuzzFile(const std::uint8_t* data, std::size_t size, const std::vector<std::string>& extensions);
  // Removes the file.
  ~FuzzFile();
  FuzzFile(const FuzzFile&) = delete;
  FuzzFile& operator=(const FuzzFile&) = delete;

  // Empty when the input had no format byte.
  const std::string& GetName() const { return this->Name; }
  const std::string& GetExtension() const { return this->Extension; }

private:
  std::string Name, Extension;
};

#endif
