/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureBenchmarkMemory.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The resident memory of the benchmark's own process (Linux), for peak-memory figures.

#ifndef vtkApertureBenchmarkMemory_h
#define vtkApertureBenchmarkMemory_h

#include <cstring>
#include <fstream>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <string>

namespace vtkApertureBenchmark
{
// Resident memory figures of this process, in KiB: "VmRSS:" or "VmHWM:" (the peak); -1 where
// /proc does not tell.
inline long StatusKiB(const char* field)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
  {
    if (line.compare(0, std::strlen(field), field) == 0)
    {
      return std::stol(line.substr(std::strlen(field) + 1));
    }
  }
  return -1;
}

// Returns freed memory to the system and restarts the peak counter (Linux 4.0+); false where the
// counter cannot be restarted.
inline bool ResetPeak()
{
#ifdef __GLIBC__
  malloc_trim(0);
#endif
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  return static_cast<bool>(clear);
}
}

#endif
// VTK-HeaderTest-Exclude: vtkApertureBenchmarkMemory.h
