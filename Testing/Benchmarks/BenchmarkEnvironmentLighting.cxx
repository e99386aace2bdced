/*=========================================================================

  Program:   ApertureLighting
  Module:    BenchmarkEnvironmentLighting.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Relighting the bunny (35,947 vertices) under the forest environment with
// vtkEnvironmentVisibilityLighting, once its visibility matrix is known: the first pass (which
// resamples the environment), a pass after each turn of the environment (the median over a full
// turn in 10 degree steps), and a pass after an exposure change, for k = 66, 258 and 1026; next
// to the time the visibility itself took (RayCast), which none of these passes repeats.
//
// Usage: BenchmarkEnvironmentLighting <Testing/Data folder> [--quick]

#include "vtkEnvironmentVisibilityLighting.h"
#include "vtkOcclusionQueryVisibility.h"
#include "vtkOpenEXRReader.h"

#include "vtkNew.h"
#include "vtkOBJReader.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

namespace
{
double Milliseconds(const std::chrono::steady_clock::time_point& start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
    .count();
}

double Median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}
}

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "Usage: " << argv[0] << " <Testing/Data folder> [--quick]\n";
    return 2;
  }
  const std::string data = argv[1];
  const bool quick = argc > 2 && std::string(argv[2]) == "--quick";
  vtkNew<vtkOBJReader> bunny;
  bunny->SetFileName((data + "/stanford-bunny.obj").c_str());
  vtkNew<vtkOpenEXRReader> forest;
  forest->SetFileName((data + "/env/forest.exr").c_str());
  forest->Update();

  std::printf("## vtkEnvironmentVisibilityLighting: relighting the bunny under forest.exr\n\n"
              "| k | visibility (RayCast) | first pass | after a turn (median) | after an "
              "exposure change |\n|---|---|---|---|---|\n");
  for (int level : quick ? std::vector<int>{ 1 } : std::vector<int>{ 2, 3, 4 })
  {
    vtkNew<vtkOcclusionQueryVisibility> visibility;
    visibility->SetInputConnection(bunny->GetOutputPort());
    visibility->SetBackendToRayCast();
    visibility->SetLevel(level);
    auto start = std::chrono::steady_clock::now();
    visibility->Update();
    const double visibilityTime = Milliseconds(start);

    vtkNew<vtkEnvironmentVisibilityLighting> lighting;
    lighting->SetInputConnection(visibility->GetOutputPort());
    lighting->SetEnvironmentConnection(forest->GetOutputPort());
    lighting->SetUpAxisToY();
    start = std::chrono::steady_clock::now();
    lighting->Update();
    const double first = Milliseconds(start);
    std::vector<double> turns, exposures;
    for (int degrees = 10; degrees <= 360; degrees += 10)
    {
      lighting->SetAzimuth(degrees);
      start = std::chrono::steady_clock::now();
      lighting->Update();
      turns.push_back(Milliseconds(start));
    }
    for (int stop = 1; stop <= 10; ++stop)
    {
      lighting->SetExposure(0.1 * stop);
      start = std::chrono::steady_clock::now();
      lighting->Update();
      exposures.push_back(Milliseconds(start));
    }
    std::printf("| %d | %.0f ms | %.1f ms | %.1f ms | %.1f ms |\n", 4 * (1 << (2 * level)) + 2,
      visibilityTime, first, Median(turns), Median(exposures));
  }
  std::printf("\nGoal: k = 258, a pass after a turn within 30 ms.\n");
  return 0;
}
