/*=========================================================================

  Program:   ApertureLighting
  Module:    BenchmarkOcclusionQueryVisibility.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Table 1 of Sattler, Sarlette and Klein (2004) on this machine: the time to compute the
// visibility matrix of the Stanford bunny (35,947 vertices) for k = 6, 18, 66, 258, 1026
// lightsphere directions, for each backend of vtkOcclusionQueryVisibility, next to the paper's
// times on a Radeon 9800 XT. The backends take turns at each k in one run, so that a noisy
// machine affects them alike; each has its OpenGL context and shaders ready before it is timed,
// as the paper's times do not include them. Wall-clock time and the process's CPU time are both
// measured: llvmpipe's threads are the process's own, and CPU time does not count what other
// processes take. Also the memory per vertex of the two arrays.
//
// Usage: BenchmarkOcclusionQueryVisibility <Testing/Data folder> [--quick] [--max-level L]
//          [--resolution N]
// --quick stops at k = 18 with a 256^2 depth texture (a smoke test that the benchmark works);
// --max-level the last level (0 to 4); --resolution the side of the depth texture (default 1024).

#include "vtkOcclusionQueryVisibility.h"

#include "vtkBitArray.h"
#include "vtkDataArray.h"
#include "vtkLightSphere.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

namespace
{
// CPU time of this process (all threads), in milliseconds.
double ProcessMilliseconds()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return 1000.0 * (usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
    1e-3 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}
}

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "Usage: " << argv[0] << " <Testing/Data folder> [--quick] [--max-level L] "
              << "[--resolution N]\n";
    return 2;
  }
  int maxLevel = 4, resolution = 1024;
  for (int i = 2; i < argc; ++i)
  {
    const std::string option = argv[i];
    if (option == "--quick")
    {
      maxLevel = 1;
      resolution = 256;
    }
    else if (option == "--max-level" && i + 1 < argc)
    {
      maxLevel = std::min(4, std::max(0, std::atoi(argv[++i])));
    }
    else if (option == "--resolution" && i + 1 < argc)
    {
      resolution = std::atoi(argv[++i]);
    }
  }

  vtkNew<vtkOBJReader> reader;
  reader->SetFileName((std::string(argv[1]) + "/stanford-bunny.obj").c_str());
  reader->Update();
  vtkNew<vtkPolyData> bunny;
  bunny->ShallowCopy(reader->GetOutput());
  const vtkIdType n = bunny->GetNumberOfPoints();
  if (n == 0)
  {
    std::cerr << "Cannot read the bunny from " << argv[1] << "\n";
    return 1;
  }

  const char* names[] = { "OcclusionQuery", "DepthCompare", "RayCast" };
  vtkNew<vtkOcclusionQueryVisibility> filters[3];
  for (int b = 0; b < 3; ++b)
  {
    filters[b]->SetInputData(bunny);
    filters[b]->SetBackend(b);
    filters[b]->SetDepthResolution(resolution);
    filters[b]->SetLevel(0);
    filters[b]->Update(); // context, shaders and Embree ready
  }
  const double paper[] = { 445, 1082, 3606, 13715, 60304 };

  std::printf(
    "## vtkOcclusionQueryVisibility: Table 1 on the bunny\n\n"
    "%lld vertices, depth texture %d x %d; milliseconds to compute the visibility "
    "matrix (all k directions), the paper's on a Radeon 9800 XT next to this machine's\n\n"
    "| k | paper, occlusion queries | OcclusionQuery | DepthCompare | RayCast | "
    "OcclusionQuery / DepthCompare, wall | CPU |\n|---|---|---|---|---|---|---|\n",
    static_cast<long long>(n), resolution, resolution);
  std::fflush(stdout);
  double visibilityBytes[5] = { 0 }, bitBytes[5] = { 0 };
  for (int level = 0; level <= maxLevel; ++level)
  {
    double ms[3], cpu[3];
    for (int b = 0; b < 3; ++b)
    {
      std::cerr << "k = " << vtkLightSphere::GetNumberOfDirections(level) << ", " << names[b]
                << "...\n";
      bunny->Modified(); // every direction again
      filters[b]->SetLevel(level);
      filters[b]->SetComputeVisibilityBits(b == 2);
      const double cpuStart = ProcessMilliseconds();
      const auto start = std::chrono::steady_clock::now();
      filters[b]->Update();
      ms[b] =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      cpu[b] = ProcessMilliseconds() - cpuStart;
    }
    // Bytes of the arrays' values: 4 per float, one bit per entry of the bit array.
    vtkPointData* pd = filters[2]->GetOutput()->GetPointData();
    visibilityBytes[level] = 4.0 * pd->GetArray("Visibility")->GetNumberOfValues() / n;
    bitBytes[level] = pd->GetAbstractArray("VisibilityBits")->GetNumberOfValues() / 8.0 / n;
    std::printf("| %d | %.0f | %.0f | %.0f | %.0f | %.1f | %.1f |\n",
      vtkLightSphere::GetNumberOfDirections(level), paper[level], ms[0], ms[1], ms[2],
      ms[0] / ms[1], cpu[0] / cpu[1]);
    std::fflush(stdout);
  }
  std::printf("\nMemory per vertex:\n\n"
              "| k | Visibility (float) | VisibilityBits | ratio |\n|---|---|---|---|\n");
  for (int level = 0; level <= maxLevel; ++level)
  {
    std::printf("| %d | %.0f bytes | %.2f bytes | %.0f |\n",
      vtkLightSphere::GetNumberOfDirections(level), visibilityBytes[level], bitBytes[level],
      visibilityBytes[level] / bitBytes[level]);
  }
  return 0;
}
