/*=========================================================================

  Program:   ApertureLighting
  Module:    BenchmarkAperturePrecompute.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Speed and memory of vtkAperturePrecompute, measured side by side in one run:
//  - peak memory of the filter against the size of the input mesh and the outputs;
//  - the filter's throughput on the Stanford bunny (default settings, whole Update) against a
//    bare Embree loop tracing the same origins and directions with the fast BVH in a scene of
//    its own (same packets and threads; rays generated beforehand, BVH build not counted);
//  - the cost of the contact and self-hit rules (the bare loop with and without them) and of the
//    surface intake;
//  - 1 -> 2 thread scaling;
//  - a moving surface: an update in which a tenth of the bunny's points moved, and one in which
//    every point moved, against a cold run on the same step (rays of a twentieth of its size);
//  - a 1M-point height field with 64 rays per point.
//
// Usage: BenchmarkAperturePrecompute <Testing/Data folder>
//          [--quick | --large TRIANGLES | --visibility POINTS]
// --quick runs a few points only (a smoke test that the benchmark still works); --large
// measures memory and throughput on the bunny split and copied to at least TRIANGLES instead,
// and what of the filter's time is not rays (its surface intake, its scene);
// --visibility the time and memory of vtkLightSphereVisibility's bit-packed matrix at k = 1026
// on such a surface of at least POINTS points.

#include "vtkApertureBenchmarkMemory.h"
#include "vtkApertureMeshSurface.h"
#include "vtkAperturePrecompute.h"
#include "vtkApertureRayOffsets.h"
#include "vtkApertureRayPacket.h"
#include "vtkApertureRaySampler.h"
#include "vtkApertureRayScene.h"
#include "vtkApertureSurface.h"
#include "vtkTerrainRGBReader.h"

#include "vtkAppendPolyData.h"
#include "vtkBitArray.h"
#include "vtkImageData.h"
#include "vtkImageResize.h"
#include "vtkLightSphere.h"
#include "vtkLightSphereVisibility.h"
#include "vtkLinearSubdivisionFilter.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <chrono>
#include <cmath>
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
constexpr int Lanes = vtkApertureRayPacket::Lanes;

using vtkApertureBenchmark::ResetPeak;
using vtkApertureBenchmark::StatusKiB;

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

// Rays, also for height fields (whose default is horizon sweeps: BenchmarkTerrain).
double RunFilter(vtkDataObject* input, int rays, int structure, int repeats)
{
  return Seconds(
    [&]()
    {
      vtkNew<vtkAperturePrecompute> filter;
      filter->SetInputData(input);
      filter->SetMethodToRays();
      filter->SetNumberOfRays(rays);
      filter->SetAccelerationStructure(structure);
      filter->Update();
    },
    repeats);
}

// Peak resident memory a run adds, in KiB (-1 where it cannot be measured); and the sizes of
// the input mesh and of the outputs.
long PeakOfRun(vtkPolyData* input, int rays, int structure, double& inputKiB, double& outputKiB)
{
  vtkNew<vtkAperturePrecompute> filter;
  filter->SetInputData(input);
  filter->SetNumberOfRays(rays);
  filter->SetAccelerationStructure(structure);
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

// The filter's rays, generated beforehand: one origin (the point lifted by its offset) and the
// offset per point, one direction per ray.
struct Rays
{
  std::vector<float> Origins, Offsets, Directions;
  std::vector<vtkIdType> Points;
};

// Traces prepared rays with nothing else in the loop: fill a packet, rtcOccluded16, count. With
// the hit rules, rays start PullBack offsets behind their origin and carry their point, as
// vtkApertureRayPacket casts them, in a scene with the filter.
class BareLoop
{
public:
  BareLoop(RTCScene scene, const vtkApertureSurface* rules, const Rays& rays, int perPoint,
    std::vector<int>& visible)
    : Scene(scene)
    , Rules(rules)
    , R(rays)
    , PerPoint(perPoint)
    , Visible(visible)
  {
  }
  void operator()(vtkIdType begin, vtkIdType end) const
  {
    vtkApertureRayScene::Context context;
    rtcInitIntersectContext(&context.Base);
    context.Source = this->Rules;
    alignas(64) RTCRay16 ray;
    alignas(64) int valid[Lanes];
    for (vtkIdType p = begin; p < end; ++p)
    {
      int count = 0;
      const float back = this->Rules ? vtkApertureRayOffsets::PullBack * this->R.Offsets[p] : 0.0f;
      for (int first = 0; first < this->PerPoint; first += Lanes)
      {
        for (int lane = 0; lane < Lanes; ++lane)
        {
          const int k = std::min(first + lane, this->PerPoint - 1);
          const float* d = &this->R.Directions[3 * (p * this->PerPoint + k)];
          valid[lane] = first + lane < this->PerPoint ? -1 : 0;
          ray.org_x[lane] = this->R.Origins[3 * p] - back * d[0];
          ray.org_y[lane] = this->R.Origins[3 * p + 1] - back * d[1];
          ray.org_z[lane] = this->R.Origins[3 * p + 2] - back * d[2];
          ray.dir_x[lane] = d[0];
          ray.dir_y[lane] = d[1];
          ray.dir_z[lane] = d[2];
          ray.tnear[lane] = 0.0f;
          ray.tfar[lane] = std::numeric_limits<float>::infinity();
          ray.time[lane] = 0.0f;
          ray.mask[lane] = 0xffffffffu;
          ray.id[lane] = static_cast<unsigned int>(this->R.Points[p]);
          ray.flags[lane] = 0;
        }
        rtcOccluded16(valid, this->Scene, &context.Base, &ray);
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
  const vtkApertureSurface* Rules;
  const Rays& R;
  int PerPoint;
  std::vector<int>& Visible;
};

// A bare Embree scene of the surface's triangles: no filter, nothing shared with the module.
struct BareScene
{
  RTCDevice Device = rtcNewDevice(nullptr);
  RTCScene Scene = nullptr;
  BareScene(const vtkApertureSurface& surface, bool compact)
  {
    this->Scene = rtcNewScene(this->Device);
    rtcSetSceneFlags(this->Scene,
      static_cast<RTCSceneFlags>(RTC_SCENE_FLAG_ROBUST | (compact ? RTC_SCENE_FLAG_COMPACT : 0)));
    rtcSetSceneBuildQuality(this->Scene, RTC_BUILD_QUALITY_MEDIUM);
    RTCGeometry geometry = rtcNewGeometry(this->Device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
      surface.Vertices.data(), 0, 3 * sizeof(float), surface.GetNumberOfVertices());
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
      surface.Triangles.data(), 0, 3 * sizeof(std::uint32_t), surface.GetNumberOfTriangles());
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(this->Scene, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(this->Scene);
  }
  ~BareScene()
  {
    rtcReleaseScene(this->Scene);
    rtcReleaseDevice(this->Device);
  }
};

// The filter's surface and rays for a mesh, with its default settings.
Rays PrepareRays(vtkPolyData* mesh, int perPoint, vtkApertureSurface& surface)
{
  vtkNew<vtkAperturePrecompute> defaults;
  const double* b = mesh->GetBounds();
  const double origin[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
  std::string error;
  vtkApertureMeshSurface::Set(surface, mesh, origin, defaults->GetFeatureAngle(), error);
  vtkApertureRayOffsets::Set(surface, defaults->GetRayOffset());
  const vtkApertureRaySampler sampler(perPoint, defaults->GetSeed(), false);
  Rays rays;
  vtkApertureRaySampler::Point point;
  for (vtkIdType id = 0; id < surface.GetNumberOfPoints(); ++id)
  {
    if (!surface.Valid[id])
    {
      continue;
    }
    const float* n = surface.GetNormal(id);
    sampler.Begin(n, surface.Key[id], point);
    rays.Points.push_back(id);
    rays.Offsets.push_back(surface.Offset[id]);
    rays.Origins.insert(rays.Origins.end(), &surface.Start[3 * id], &surface.Start[3 * id + 3]);
    float d[3];
    for (int r = 0; r < perPoint; ++r)
    {
      sampler.Direction(point, r, d);
      rays.Directions.insert(rays.Directions.end(), d, d + 3);
    }
  }
  return rays;
}

// The bare loop on the filter's surface and rays: in a bare scene, or with the hit rules.
double RunBare(const vtkApertureSurface& surface, const Rays& rays, int perPoint, bool compact,
  bool rules, int repeats, vtkIdType* traced)
{
  const vtkIdType n = static_cast<vtkIdType>(rays.Points.size());
  std::vector<int> visible(n);
  *traced = n * perPoint;
  if (rules)
  {
    vtkApertureRayScene scene;
    scene.Build(
      { &surface }, {}, compact ? vtkApertureRayScene::COMPACT : vtkApertureRayScene::FAST);
    std::printf("| triangles with the hit filter (contact and self-hit risks) | %lld of %lld |\n",
      static_cast<long long>(scene.GetNumberOfFilteredTriangles()),
      static_cast<long long>(surface.GetNumberOfTriangles()));
    BareLoop loop(scene.GetScene(), &surface, rays, perPoint, visible);
    return Seconds([&]() { vtkSMPTools::For(0, n, 16, loop); }, repeats);
  }
  BareScene scene(surface, compact);
  BareLoop loop(scene.Scene, nullptr, rays, perPoint, visible);
  return Seconds([&]() { vtkSMPTools::For(0, n, 16, loop); }, repeats);
}

// Seconds of the filter's scene alone: the choice of the triangles with the hit filter, and
// Embree's BVH.
double RunScene(const vtkApertureSurface& surface, int structure, int repeats)
{
  return Seconds(
    [&]()
    {
      vtkApertureRayScene scene;
      scene.Build({ &surface }, {}, structure);
    },
    repeats);
}

// Seconds of the filter's surface intake alone (validation, welding, winding, creases, normals).
double RunIntake(vtkPolyData* mesh, int repeats)
{
  vtkNew<vtkAperturePrecompute> defaults;
  return Seconds(
    [&]()
    {
      vtkApertureSurface surface;
      const double origin[3] = { 0.0, 0.0, 0.0 };
      std::string error;
      vtkApertureMeshSurface::Set(surface, mesh, origin, defaults->GetFeatureAngle(), error);
      vtkApertureRayOffsets::Set(surface, defaults->GetRayOffset());
    },
    repeats);
}

// A copy of `mesh` whose points within `radius` of `centre` (all when radius < 0) rise by
// `lift` along +y.
vtkSmartPointer<vtkPolyData> Moved(
  vtkPolyData* mesh, const double centre[3], double radius, double lift, vtkIdType& count)
{
  auto moved = vtkSmartPointer<vtkPolyData>::New();
  moved->ShallowCopy(mesh);
  vtkNew<vtkPoints> points;
  points->DeepCopy(mesh->GetPoints());
  count = 0;
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    if (radius < 0.0 || vtkMath::Distance2BetweenPoints(p, centre) < radius * radius)
    {
      p[1] += lift;
      points->SetPoint(i, p);
      ++count;
    }
  }
  moved->SetPoints(points);
  return moved;
}

// A moving surface: an update on `after` by a filter that computed `before`, against a cold
// filter's update on `after` (best of `repeats` each); prints their ratio, and the `goal` for it
// where there is one (> 0).
void MovingSurface(
  vtkPolyData* before, vtkPolyData* after, int rays, int repeats, const char* what, double goal)
{
  const double distance = 0.05 * before->GetLength();
  auto configure = [&](vtkAperturePrecompute* filter)
  {
    filter->SetNumberOfRays(rays);
    filter->LimitDistanceOn();
    filter->SetMaximumDistance(distance);
    filter->ReuseUnmovedPointsOn();
  };
  double warm = 1e300;
  vtkIdType cast = 0, all = 0, traced = 0;
  for (int r = 0; r < repeats; ++r)
  {
    vtkNew<vtkAperturePrecompute> filter;
    configure(filter);
    filter->SetInputData(before);
    filter->Update();
    filter->SetInputData(after);
    warm = std::min(warm, Seconds([&]() { filter->Update(); }, 1));
    cast = filter->GetNumberOfSurfacePoints();
    all = cast + filter->GetNumberOfReusedPoints();
    traced = filter->GetNumberOfRaysTraced();
  }
  const double cold = Seconds(
    [&]()
    {
      vtkNew<vtkAperturePrecompute> filter;
      configure(filter);
      filter->SetInputData(after);
      filter->Update();
    },
    repeats);
  char target[32] = "";
  if (goal > 0.0)
  {
    std::snprintf(target, sizeof(target), " (goal <= %.1f)", goal);
  }
  std::printf("| moving surface, %s: update / cold run%s | %.3f s / %.3f s = %.2f; "
              "%lld of %lld points cast rays, %.0f%% of their rays traced |\n",
    what, target, warm, cold, warm / cold, static_cast<long long>(cast),
    static_cast<long long>(all), 100.0 * traced / std::max<double>(1.0, double(cast) * rays));
}

// A surface of at least `triangles`: the bunny split into 4^k triangles each
// (vtkLinearSubdivisionFilter), then copies of it side by side.
vtkSmartPointer<vtkPolyData> LargeSurface(vtkPolyData* bunny, vtkIdType triangles)
{
  vtkSmartPointer<vtkPolyData> mesh = bunny;
  while (4 * mesh->GetNumberOfPolys() <= triangles)
  {
    vtkNew<vtkLinearSubdivisionFilter> split;
    split->SetInputData(mesh);
    split->SetNumberOfSubdivisions(1);
    split->Update();
    mesh = split->GetOutput();
  }
  vtkNew<vtkAppendPolyData> copies;
  const vtkIdType count = (triangles + mesh->GetNumberOfPolys() - 1) / mesh->GetNumberOfPolys();
  for (vtkIdType c = 0; c < count; ++c)
  {
    vtkNew<vtkPoints> points;
    points->DeepCopy(mesh->GetPoints());
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
    {
      double p[3];
      points->GetPoint(i, p);
      p[0] += 1.2 * mesh->GetLength() * c;
      points->SetPoint(i, p);
    }
    vtkNew<vtkPolyData> copy;
    copy->SetPoints(points);
    copy->SetPolys(mesh->GetPolys());
    copies->AddInputData(copy);
  }
  copies->Update();
  return copies->GetOutput();
}

// Issue 25's large surfaces: peak memory against the input and the outputs, and throughput
// against the bare fast-BVH loop, for the BVH the default picks and for both, 64 rays a point
// (the bare loop's rays are made beforehand, 12 bytes each).
void LargeMesh(vtkPolyData* bunny, vtkIdType triangles)
{
  const vtkSmartPointer<vtkPolyData> mesh = LargeSurface(bunny, triangles);
  const int rays = 64;
  std::printf("## vtkAperturePrecompute on a large surface\n\n%lld points, %lld triangles, %d "
              "rays a point, %d thread(s)\n\n| measure | value |\n|---|---|\n",
    static_cast<long long>(mesh->GetNumberOfPoints()),
    static_cast<long long>(mesh->GetNumberOfPolys()), rays,
    vtkSMPTools::GetEstimatedNumberOfThreads());
  for (const int structure : { vtkAperturePrecompute::AUTOMATIC, vtkAperturePrecompute::FAST })
  {
    double inputKiB, outputKiB;
    const long peak = PeakOfRun(mesh, rays, structure, inputKiB, outputKiB);
    std::printf("| %s: peak / (input %.0f MiB + outputs %.0f MiB) (goal <= 1.5) | %.2f (%.0f "
                "MiB) |\n",
      structure == vtkAperturePrecompute::AUTOMATIC ? "default" : "fast BVH", inputKiB / 1024,
      outputKiB / 1024, peak / (inputKiB + outputKiB), peak / 1024.0);
  }
  vtkApertureSurface surface;
  const Rays prepared = PrepareRays(mesh, rays, surface);
  vtkIdType traced = 0;
  const double bare = RunBare(surface, prepared, rays, false, false, 1, &traced);
  for (const int structure : { vtkAperturePrecompute::AUTOMATIC, vtkAperturePrecompute::FAST })
  {
    const double filter = RunFilter(mesh, rays, structure, 1);
    std::printf("| %s: filter %.1f s / bare fast-BVH loop %.1f s: throughput ratio (goal >= "
                "0.85) | %.2f |\n",
      structure == vtkAperturePrecompute::AUTOMATIC ? "default" : "fast BVH", filter, bare,
      bare / filter);
  }
  // What the filter does beside the rays, one run each.
  std::printf(
    "| surface intake (ids, welding, winding, creases, normals) | %.1f s |\n", RunIntake(mesh, 1));
  std::printf("| scene: hit-filter choice and BVH, default / fast BVH | %.1f s / %.1f s |\n",
    RunScene(surface, vtkApertureRayScene::AUTOMATIC, 1),
    RunScene(surface, vtkApertureRayScene::FAST, 1));
}

// Issue 25's visibility matrix for a million vertices: vtkLightSphereVisibility at k = 1026 with
// only the bit-packed `VisibilityBits` (the float matrix would take 4 bytes an entry), its time
// and its peak memory against the input and that array. False when the filter failed.
bool LargeVisibility(vtkPolyData* bunny, vtkIdType points)
{
  const vtkSmartPointer<vtkPolyData> mesh = LargeSurface(bunny, 2 * points);
  const vtkIdType n = mesh->GetNumberOfPoints();
  const int k = vtkLightSphere::GetNumberOfDirections(4);
  vtkNew<vtkLightSphereVisibility> filter;
  filter->SetInputData(mesh);
  filter->SetLevel(4);
  filter->ComputeVisibilityOff();
  filter->ComputeVisibilityBitsOn();
#ifdef __GLIBC__
  malloc_trim(0);
#endif
  const long before = StatusKiB("VmRSS:");
  const bool reset = ResetPeak();
  const double seconds = Seconds([&]() { filter->Update(); }, 1);
  const long peak = reset && before > 0 ? StatusKiB("VmHWM:") - before : -1;
  auto* bits = vtkBitArray::SafeDownCast(
    filter->GetOutput()->GetPointData()->GetAbstractArray("VisibilityBits"));
  if (!bits)
  {
    std::cerr << "vtkLightSphereVisibility gave no VisibilityBits\n";
    return false;
  }
  vtkIdType visible = 0;
  for (vtkIdType v = 0; v < bits->GetNumberOfValues(); ++v)
  {
    visible += bits->GetValue(v);
  }
  // vtkBitArray reports no memory size of its own: one bit a value.
  const double inputKiB = mesh->GetActualMemorySize();
  const double bitsKiB = (bits->GetNumberOfValues() + 7) / 8 / 1024.0;
  std::printf("## vtkLightSphereVisibility on a large surface\n\n%lld points, %lld triangles, k = "
              "%d, bits only, %d thread(s)\n\n| measure | value |\n|---|---|\n",
    static_cast<long long>(n), static_cast<long long>(mesh->GetNumberOfPolys()), k,
    vtkSMPTools::GetEstimatedNumberOfThreads());
  std::printf("| time | %.1f s (%.1f M point-directions/s) |\n", seconds, 1e-6 * n * k / seconds);
  std::printf("| VisibilityBits | %.0f MiB (%.0f bytes a point; the float matrix: %.0f MiB) |\n",
    bitsKiB / 1024, 1024.0 * bitsKiB / n, 4.0 * n * k / (1 << 20));
  std::printf("| peak / (input %.0f MiB + VisibilityBits) | %.2f (%.0f MiB) |\n", inputKiB / 1024,
    peak / (inputKiB + bitsKiB), peak / 1024.0);
  std::printf("| directions visible, mean | %.3f |\n", double(visible) / (double(n) * k));
  return true;
}
}

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "Usage: " << argv[0]
              << " <Testing/Data folder> [--quick | --large TRIANGLES | --visibility POINTS]\n";
    return 2;
  }
  const std::string data = argv[1];
  const bool quick = argc > 2 && std::string(argv[2]) == "--quick";
  const bool large = argc > 3 && std::string(argv[2]) == "--large";
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
  if (large)
  {
    LargeMesh(bunny, std::stoll(argv[3]));
    return 0;
  }
  if (argc > 3 && std::string(argv[2]) == "--visibility")
  {
    return LargeVisibility(bunny, std::stoll(argv[3])) ? 0 : 1;
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
    RunFilter(few, 1, vtkAperturePrecompute::AUTOMATIC, 1);
  }

  // The bare loops: the filter's own rays, prepared beforehand, without and with the hit rules.
  vtkApertureSurface surface;
  const Rays prepared = PrepareRays(bunny, rays, surface);
  vtkIdType traced = 0;
  const double bareFast = RunBare(surface, prepared, rays, false, false, repeats, &traced);
  const double bareCompact = RunBare(surface, prepared, rays, true, false, repeats, &traced);
  const double rulesFast = RunBare(surface, prepared, rays, false, true, repeats, &traced);
  const double bareRate = traced / bareFast / 1e6;
  std::printf("| bare Embree loop, fast BVH, same rays (build not counted) | %.3f s, %.2f "
              "Mrays/s |\n",
    bareFast, bareRate);
  std::printf("| bare Embree loop, compact BVH | %.3f s, %.2f Mrays/s |\n", bareCompact,
    traced / bareCompact / 1e6);
  std::printf("| contact and self-hit rules: bare loop with / without them (goal <= 1.10) | "
              "%.3f |\n",
    rulesFast / bareFast);

  for (const int structure : { vtkAperturePrecompute::AUTOMATIC, vtkAperturePrecompute::COMPACT })
  {
    const bool compact = vtkApertureRayScene::IsCompact(structure, surface.GetNumberOfTriangles());
    const std::string name = structure == vtkAperturePrecompute::AUTOMATIC
      ? std::string("default (") + (compact ? "compact" : "fast") + " BVH)"
      : std::string("compact BVH");
    const char* layout = name.c_str();
    // Memory first, before timing runs leave freed memory in the heap.
    double inputKiB, outputKiB;
    const long peak = PeakOfRun(bunny, rays, structure, inputKiB, outputKiB);
    if (peak >= 0)
    {
      std::printf("| %s: peak memory of a run | %ld KiB |\n", layout, peak);
      std::printf("| %s: peak / (input mesh %.0f KiB + outputs %.0f KiB) | %.2f |\n", layout,
        inputKiB, outputKiB, peak / (inputKiB + outputKiB));
    }
    else
    {
      std::printf("| %s: peak memory | not measurable here |\n", layout);
    }
    const double filterTime = RunFilter(bunny, rays, structure, repeats);
    const double filterRate = traced / filterTime / 1e6;
    std::printf("| %s: filter, whole run (intake, BVH, rays) | %.3f s, %.2f Mrays/s |\n", layout,
      filterTime, filterRate);
    std::printf("| %s: filter / bare fast-BVH loop throughput%s | %.2f |\n", layout,
      structure == vtkAperturePrecompute::AUTOMATIC ? " (goal >= 0.85)" : "",
      filterRate / bareRate);
  }
  const double intake = RunIntake(bunny, repeats);
  std::printf("| surface intake (ids, welding, winding, creases, normals) | %.3f s, %.1f%% of a "
              "default run |\n",
    intake, 100.0 * intake / RunFilter(bunny, rays, vtkAperturePrecompute::AUTOMATIC, repeats));

  // Thread scaling, default settings.
  vtkSMPTools::Initialize(1);
  const double one = RunFilter(bunny, rays, vtkAperturePrecompute::AUTOMATIC, repeats);
  vtkSMPTools::Initialize(2);
  const double two = RunFilter(bunny, rays, vtkAperturePrecompute::AUTOMATIC, repeats);
  vtkSMPTools::Initialize(threads);
  std::printf("| default: 1 thread / 2 threads | %.3f s / %.3f s |\n", one, two);
  std::printf("| default: 1 -> 2 thread speed-up (goal >= 1.8) | %.2f |\n", one / two);

  // A moving surface: a tenth of the bunny's points (those nearest its highest point) rise by
  // a hundredth of its size, then every point does.
  {
    double bounds[6];
    bunny->GetBounds(bounds);
    double top[3] = { 0.0, bounds[2], 0.0 };
    for (vtkIdType i = 0; i < points; ++i)
    {
      double p[3];
      bunny->GetPoint(i, p);
      if (p[1] >= top[1])
      {
        std::copy_n(p, 3, top);
      }
    }
    // The radius around the top that holds a tenth of the points.
    std::vector<double> distances(points);
    for (vtkIdType i = 0; i < points; ++i)
    {
      distances[i] = std::sqrt(vtkMath::Distance2BetweenPoints(bunny->GetPoint(i), top));
    }
    std::nth_element(distances.begin(), distances.begin() + points / 10, distances.end());
    const double lift = 0.01 * bunny->GetLength();
    vtkIdType count;
    const auto tenth = Moved(bunny, top, distances[points / 10], lift, count);
    MovingSurface(bunny, tenth, rays, repeats, "a tenth of the points moved", 0.3);
    const auto every = Moved(bunny, top, -1.0, lift, count);
    MovingSurface(bunny, every, rays, repeats, "every point moved", 1.0);
    const auto still = Moved(bunny, top, 0.0, lift, count);
    MovingSurface(bunny, still, rays, repeats, "nothing moved", 0.0);
  }

  // A 1M-point height field, 64 rays per point (rays, not the default horizon sweeps).
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
  for (const int structure : { vtkAperturePrecompute::AUTOMATIC, vtkAperturePrecompute::COMPACT })
  {
    const double fieldTime = RunFilter(field, 64, structure, 1);
    std::printf("| %s: height field %dx%d (%lld points), 64 rays (goal <= 12 s) | %.2f s, %.2f "
                "Mrays/s |\n",
      structure == vtkAperturePrecompute::AUTOMATIC ? "default" : "compact BVH", side, side,
      static_cast<long long>(field->GetNumberOfPoints()), fieldTime,
      field->GetNumberOfPoints() * 64.0 / fieldTime / 1e6);
  }
  return 0;
}
