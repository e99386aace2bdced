/*=========================================================================

  Program:   ApertureLighting
  Module:    FuzzReplay.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Runs a libFuzzer target (LLVMFuzzerTestOneInput, linked in) without libFuzzer, for builds with
// any compiler:
//   <driver> [--iterations N] [FILE...]
// checks that every seed is good input, then feeds the target the seeds and N damaged copies
// (deterministic mutations: bit flips, bytes and 32-bit fields set to edge values, truncation,
// copied and inserted blocks, splices of two seeds), then FILEs (e.g. crash files a libFuzzer run
// left). A crash fails the test; with APERTURE_FUZZ_LAST=FILE set, each input is written to FILE
// before it is fed, so that FILE holds the one that crashed, to replay as a FILE argument.
//   <driver> --write-seeds DIR
// writes the seeds as DIR/<name><extension>, the corpus `make fuzz` starts from.

#ifndef FuzzReplay_h
#define FuzzReplay_h

#include <functional>
#include <string>
#include <vector>

struct FuzzSeed
{
  std::string Name;
  std::vector<char> Bytes;
};

// The driver's main. `checkSeed` says what is wrong with a seed (empty: it is good input).
int RunFuzzReplay(int argc, char* argv[], const std::vector<FuzzSeed>& seeds,
  const std::string& extension, const std::function<std::string(const FuzzSeed&)>& checkSeed);

#endif
