/*=========================================================================

  Program:   ApertureLighting
  Module:    BenchmarkAperturePrecompute.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Speed and memory of vtkAperturePrecompute, measured side by side in one run:
//  - peak memory of the filter against the size of the input mesh and the outputs;
//  - the filter's throughput on the Stanford bunny against a bare Embree loop tracing the same
//    origins and directions (same scene, packets and threads; rays generated beforehand);
//  - 1 -> 2 thread scaling;
//  - a 1M-point height field with 64 rays per point.
//
// Usage: BenchmarkAperturePrecompute <Testing/Data folder> [--quick]
// --quick runs a few points only (a smoke test that the benchmark still works).

#include "vtkApertureHemisphereSampler.h"
#include "vtkAperturePrecompute.h"
#include "vtkApertureRayScene.h"
#include "vtkApertureSurface.h"
#include "vtkTerrainRGBReader.h"

#include "vtkImageData.h"
#include "vtkImageResize.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <string>
#include <vector>

namespace
{
constexpr int Lanes = vtkApertureHemisphereSampler::Lanes;

// Resident memory figures of this process, in KiB: "VmRSS" or "VmHWM" (peak).
long StatusKiB(const char* field)
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

// Restarts the peak-RSS counter (Linux 4.0+).
bool ResetPeak()
{
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  return static_cast<bool>(clear);
}

double Seconds(const std::function<void()>& work, int repeats)
{
  double best = 1e300;
  for (int r = 0; r < repeats; ++r)
  {
    const auto start = std::chrono::steady_clock::now();
    work();
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    best = std::min(best, elapsed.count());
  }
  return best;
}

double RunFilter(vtkDataObject* input, int rays, bool compact, int repeats)
{
  return Seconds(
    [&]()
    {
      vtkNew<vtkAperturePrecompute> filter;
      filter->SetInputData(input);
      filter->SetNumberOfRays(rays);
      filter->SetCompactAccelerationStructure(compact);
      filter->Update();
    },
    repeats);
}

// Peak resident memory a run adds, in KiB (-1 where it cannot be measured); and the sizes of
// the input mesh and of the outputs.
long PeakOfRun(vtkPolyData* input, int rays, bool compact, double& inputKiB, double& outputKiB)
{
  vtkNew<vtkAperturePrecompute> filter;
  filter->SetInputData(input);
  filter->SetNumberOfRays(rays);
  filter->SetCompactAccelerationStructure(compact);
#ifdef __GLIBC__
  malloc_trim(0);
#endif
  const long before = StatusKiB("VmRSS:");
  const bool reset = ResetPeak();
  filter->Update();
  const long peak = StatusKiB("VmHWM:") - before;
  inputKiB = input->GetActualMemorySize();
  outputKiB = 0.0;
  vtkPointData* pd = filter->GetPolyDataOutput()->GetPointData();
  for (const char* name : { "BentNormal", "ApertureRadius", "Normals" })
  {
    outputKiB += pd->GetArray(name)->GetActualMemorySize();
  }
  return (reset && before > 0) ? peak : -1;
}

// The filter's rays, generated beforehand: one origin per point, one direction per ray.
struct Rays
{
  std::vector<float> Origins, Directions;
  std::vector<vtkIdType> Points;
};

// Traces prepared rays with nothing else in the loop: fill a packet, rtcOccluded16, count.
class BareLoop
{
public:
  BareLoop(RTCScene scene, const Rays& rays, int perPoint, std::vector<int>& visible)
    : Scene(scene)
    , R(rays)
    , PerPoint(perPoint)
    , Visible(visible)
  {
  }
  void operator()(vtkIdType begin, vtkIdType end) const
  {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    alignas(64) RTCRay16 ray;
    alignas(64) int valid[Lanes];
    for (vtkIdType p = begin; p < end; ++p)
    {
      int count = 0;
      for (int first = 0; first < this->PerPoint; first += Lanes)
      {
        for (int lane = 0; lane < Lanes; ++lane)
        {
          const int k = std::min(first + lane, this->PerPoint - 1);
          const float* d = &this->R.Directions[3 * (p * this->PerPoint + k)];
          valid[lane] = first + lane < this->PerPoint ? -1 : 0;
          ray.org_x[lane] = this->R.Origins[3 * p];
          ray.org_y[lane] = this->R.Origins[3 * p + 1];
          ray.org_z[lane] = this->R.Origins[3 * p + 2];
          ray.dir_x[lane] = d[0];
          ray.dir_y[lane] = d[1];
          ray.dir_z[lane] = d[2];
          ray.tnear[lane] = 0.0f;
          ray.tfar[lane] = std::numeric_limits<float>::infinity();
          ray.time[lane] = 0.0f;
          ray.mask[lane] = 0xffffffffu;
          ray.id[lane] = 0;
          ray.flags[lane] = 0;
        }
        rtcOccluded16(valid, this->Scene, &context, &ray);
        for (int lane = 0; lane < Lanes; ++lane)
        {
          count += (valid[lane] && ray.tfar[lane] >= 0.0f) ? 1 : 0;
        }
      }
      this->Visible[p] = count;
    }
  }

private:
  RTCScene Scene;
  const Rays& R;
  int PerPoint;
  std::vector<int>& Visible;
};

// The bare loop on the same surface, scene and rays as the filter.
double RunBare(vtkPolyData* mesh, int perPoint, bool compact, int repeats, vtkIdType* traced)
{
  const double* b = mesh->GetBounds();
  const double origin[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
  vtkApertureSurface surface;
  std::string error;
  surface.SetPolyData(mesh, origin, error);
  vtkApertureRayScene scene;
  scene.Initialize("", compact);
  scene.AddSurface(surface);
  scene.Commit();

  vtkNew<vtkAperturePrecompute> defaults;
  const vtkApertureHemisphereSampler sampler(perPoint, defaults->GetSeed(),
    defaults->GetSampling() == vtkAperturePrecompute::RANDOM, defaults->GetRayOffset());
  Rays rays;
  alignas(64) RTCRay16 packet;
  alignas(64) int valid[Lanes];
  vtkApertureHemisphereSampler::Point point;
  for (vtkIdType id = 0; id < surface.GetNumberOfPoints(); ++id)
  {
    if (!surface.Receives[id] || !surface.Valid[id])
    {
      continue;
    }
    sampler.Begin(surface, id, point);
    rays.Points.push_back(id);
    rays.Origins.insert(rays.Origins.end(), point.Origin, point.Origin + 3);
    for (int first = 0; first < perPoint; first += Lanes)
    {
      sampler.Fill(point, first, std::numeric_limits<float>::infinity(), packet, valid);
      for (int lane = 0; lane < Lanes && first + lane < perPoint; ++lane)
      {
        rays.Directions.push_back(packet.dir_x[lane]);
        rays.Directions.push_back(packet.dir_y[lane]);
        rays.Directions.push_back(packet.dir_z[lane]);
      }
    }
  }
  const vtkIdType n = static_cast<vtkIdType>(rays.Points.size());
  std::vector<int> visible(n);
  BareLoop loop(scene.GetScene(), rays, perPoint, visible);
  *traced = n * perPoint;
  return Seconds([&]() { vtkSMPTools::For(0, n, 16, loop); }, repeats);
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
  const int repeats = quick ? 1 : 3;
  const int threads = vtkSMPTools::GetEstimatedNumberOfThreads();

  vtkNew<vtkOBJReader> obj;
  obj->SetFileName((data + "/stanford-bunny.obj").c_str());
  obj->Update();
  vtkNew<vtkPolyData> bunny;
  bunny->ShallowCopy(obj->GetOutput());
  if (bunny->GetNumberOfPoints() == 0)
  {
    std::cerr << "Cannot read " << data << "/stanford-bunny.obj\n";
    return 1;
  }
  const int rays = quick ? 16 : 256;
  const vtkIdType points = bunny->GetNumberOfPoints();
  std::cout << "## vtkAperturePrecompute benchmark\n\n"
            << "Bunny: " << points << " points, " << bunny->GetNumberOfPolys() << " triangles, "
            << rays << " rays per point, " << threads << " thread(s), best of " << repeats
            << "\n\n";
  std::cout << "| measure | value |\n|---|---|\n";

  // One small run first: Embree's and TBB's one-time set-up is not part of what is measured.
  {
    vtkNew<vtkPolyData> few;
    few->ShallowCopy(bunny);
    RunFilter(few, 1, true, 1);
  }

  for (const bool compact : { true, false })
  {
    const char* layout = compact ? "compact BVH (default)" : "fast BVH";
    // Memory first, before timing runs leave freed memory in the heap.
    double inputKiB, outputKiB;
    const long peak = PeakOfRun(bunny, rays, compact, inputKiB, outputKiB);
    if (peak >= 0)
    {
      std::printf("| %s: peak memory of a run | %ld KiB |\n", layout, peak);
      std::printf("| %s: peak / (input mesh %.0f KiB + outputs %.0f KiB) (goal <= 2) | %.2f |\n",
        layout, inputKiB, outputKiB, peak / (inputKiB + outputKiB));
    }
    else
    {
      std::printf("| %s: peak memory | not measurable here |\n", layout);
    }

    // Filter against the bare loop on the same rays and scene.
    const double filterTime = RunFilter(bunny, rays, compact, repeats);
    vtkIdType traced = 0;
    const double bareTime = RunBare(bunny, rays, compact, repeats, &traced);
    const double filterRate = points * rays / filterTime / 1e6;
    const double bareRate = traced / bareTime / 1e6;
    std::printf("| %s: filter, whole run (normals, BVH, rays) | %.3f s, %.2f Mrays/s |\n", layout,
      filterTime, filterRate);
    std::printf(
      "| %s: bare Embree loop, same rays | %.3f s, %.2f Mrays/s |\n", layout, bareTime, bareRate);
    std::printf(
      "| %s: filter / bare throughput (goal >= 0.85) | %.2f |\n", layout, filterRate / bareRate);
  }

  // Thread scaling, default layout.
  vtkSMPTools::Initialize(1);
  const double one = RunFilter(bunny, rays, true, repeats);
  vtkSMPTools::Initialize(2);
  const double two = RunFilter(bunny, rays, true, repeats);
  vtkSMPTools::Initialize(threads);
  std::printf("| compact BVH: 1 thread / 2 threads | %.3f s / %.3f s |\n", one, two);
  std::printf("| compact BVH: 1 -> 2 thread speed-up (goal >= 1.8) | %.2f |\n", one / two);

  // A 1M-point height field, 64 rays per point.
  vtkNew<vtkTerrainRGBReader> terrain;
  terrain->SetFileName((data + "/fuji-terrain-rgb.png").c_str());
  terrain->SetSpacing(60.0, 60.0);
  vtkNew<vtkImageResize> resize;
  resize->SetInputConnection(terrain->GetOutputPort());
  const int side = quick ? 64 : 1000;
  resize->SetOutputDimensions(side, side, 1);
  resize->Update();
  vtkNew<vtkImageData> field;
  field->ShallowCopy(resize->GetOutput());
  for (const bool compact : { true, false })
  {
    const double fieldTime = RunFilter(field, 64, compact, 1);
    std::printf("| %s: height field %dx%d (%lld points), 64 rays (goal <= 12 s) | %.2f s, %.2f "
                "Mrays/s |\n",
      compact ? "compact BVH" : "fast BVH", side, side,
      static_cast<long long>(field->GetNumberOfPoints()), fieldTime,
      field->GetNumberOfPoints() * 64.0 / fieldTime / 1e6);
  }
  return 0;
}
