/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureRayScene.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureRayScene
 * @brief   Embree device and scene over vtkApertureSurface triangles, with the casters' hit
 *          rules (private)
 *
 * Owns an Embree device and one scene, shares the surfaces' vertex and index buffers with
 * Embree (the surfaces must outlive the scene), and records the first error Embree reports
 * through its device callback, so that the filters can turn it into a vtkErrorMacro on the main
 * thread.
 * After Build() the scene may be queried from any number of threads, through
 * vtkApertureRayPacket.
 *
 * The rules all casters share. A ray from a receiving point starts Offset above it along its
 * normal, but is traced from PullBack offsets behind that start (vtkApertureRayOffsets); hits up
 * to the point's Near distance from where it is traced are near. A hit
 *
 * - near blocks the ray only if the ray goes into the triangle's front: a point lying on another
 *   surface (the foot of a wall standing on the ground) is closed by that surface's front (the
 *   half of its hemisphere that goes into the ground), not by its back (contact). Tracing from
 *   behind the start finds such a surface through the start robustly;
 * - farther blocks unless it is on the back of one of the point's own triangles (those at its
 *   vertex): a folded or sliver triangle of a scan's one-ring, whose back faces the point, does
 *   not close it, while the walls of a real crevice, whose fronts face it, still do (self-hits).
 *
 * Embree calls an occlusion filter for every hit it finds on a geometry that has one, which
 * costs on every occluded ray. Only where the rules can reject a hit do triangles get it: those
 * whose normal is within acos(PullBack) of 90 degrees from, or against, the normal of a
 * receiving point at one of their vertices, and those that pass within the Near distance of some
 * receiving point's ray start. Every other hit blocks: those triangles are geometries without
 * a filter, over runs of the surface's own index buffer (SetMaximumSharedRuns()).
 */

#ifndef vtkApertureRayScene_h
#define vtkApertureRayScene_h

#include "vtkApertureLightingCoreModule.h" // For export macro
#include "vtkApertureSMP.h"                // For TraceInBatches()
#include "vtkType.h"

#include <embree3/rtcore.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#if defined(__SSE__) || defined(_M_X64)
#include <xmmintrin.h>
#endif

class vtkApertureSurface;

class VTKAPERTURELIGHTINGCORE_EXPORT vtkApertureRayScene
{
public:
  vtkApertureRayScene() = default;
  ~vtkApertureRayScene();
  vtkApertureRayScene(const vtkApertureRayScene&) = delete;
  vtkApertureRayScene& operator=(const vtkApertureRayScene&) = delete;

  /// Embree's acceleration structures.
  enum Structures
  {
    AUTOMATIC = 0, ///< FAST up to GetCompactThreshold() triangles, COMPACT above
    COMPACT = 1,   ///< about 70% of the memory, about 75% of the speed
    FAST = 2
  };

  /**
   * Triangles above which AUTOMATIC builds the compact structure: where the fast one, about 128
   * bytes a triangle with its build arrays, would take more than an eighth of the machine's
   * physical memory, or of its container's limit where lower (8 million triangles on 8 GiB, 25
   * million on 24 GiB).
   */
  static vtkIdType GetCompactThreshold();

  /**
   * Whether a structure setting builds the compact BVH for this many triangles.
   */
  static bool IsCompact(int structure, vtkIdType triangles);

  /**
   * Builds the scene of the receivers (whose points cast rays; their ray offsets must be set)
   * and the occluders, with an rtcNewDevice() configuration string and a structure setting.
   * False when Embree fails (GetError() says why).
   */
  bool Build(const std::vector<const vtkApertureSurface*>& receivers,
    const std::vector<const vtkApertureSurface*>& occluders, int structure = AUTOMATIC,
    const std::string& configuration = std::string());

  /**
   * Before Build(): only the triangles of `surface` flagged in `triangles` enter the scene (an
   * update that traces the rays of a few points leaves out what they cannot reach; a left-out
   * triangle changes no answer of a ray that could not have hit it).
   */
  void KeepOnly(const vtkApertureSurface& surface, std::vector<unsigned char> triangles);

  /**
   * Build() for one receiver and its occluders.
   */
  bool Build(const vtkApertureSurface& receivers, const std::vector<vtkApertureSurface>& occluders,
    int structure = AUTOMATIC);

  /**
   * Triangles that got the hit filter in the last Build(), of all.
   */
  vtkIdType GetNumberOfFilteredTriangles() const { return this->FilteredTriangles; }

  ///@{
  /**
   * The triangles without the hit filter are mostly long runs between filtered ones. Up to
   * this many runs a surface (default 1024), each run is a geometry over the surface's own
   * index buffer; more are copied into one geometry (0: always copied). Set before Build().
   */
  void SetMaximumSharedRuns(vtkIdType runs) { this->MaximumSharedRuns = runs; }
  vtkIdType GetMaximumSharedRuns() const { return this->MaximumSharedRuns; }
  ///@}

  /**
   * Runs of triangles shared with the surfaces in the last Build().
   */
  vtkIdType GetNumberOfSharedRuns() const { return this->SharedRuns; }

  RTCScene GetScene() const { return this->Scene; }

  /**
   * What the occlusion filter learns of a ray's source: the intersect context of the query,
   * the surface its points belong to. Rays carry their receiving point in RTCRay::id.
   */
  struct Context
  {
    RTCIntersectContext Base; // first: Embree sees this
    const vtkApertureSurface* Source;
  };

  /**
   * Keeps denormals out of Embree's traversal, as Embree recommends, for the calling thread
   * while it exists.
   */
  class FlushToZero
  {
  public:
#if defined(__SSE__) || defined(_M_X64)
    FlushToZero()
      : Saved(_mm_getcsr())
    {
      _mm_setcsr(this->Saved | 0x8040); // FTZ and DAZ
    }
    ~FlushToZero()
    {
      _mm_setcsr(this->Saved);
    }

  private:
    unsigned int Saved;
#endif
  };

  /**
   * The first error Embree reported, empty if none.
   */
  std::string GetError();

  /**
   * The batched loop every caster traces with: runs `trace` (a vtkSMPTools functor over a range
   * of its receiving points) on points 0 .. n - 1, `batch` points at a time on all cores, `grain`
   * points to a task, and calls `progress(done)` after each batch; returning false stops the
   * loop (an abort). False with `error` when Embree failed while tracing.
   */
  template <typename Trace>
  bool TraceInBatches(vtkIdType n, vtkIdType batch, vtkIdType grain, const Trace& trace,
    const std::function<bool(vtkIdType done)>& progress, std::string& error)
  {
    for (vtkIdType first = 0; first < n; first += batch)
    {
      const vtkIdType last = first + batch < n ? first + batch : n;
      vtkApertureSMP::For(first, last, grain, trace);
      if (!progress(last))
      {
        break;
      }
    }
    error = this->GetError();
    return error.empty();
  }

  /**
   * What a filtered geometry tells its filter: its surface, and which of the surface's
   * triangles its primitives are.
   */
  struct Filtered
  {
    const vtkApertureSurface* Surface;
    std::vector<std::uint32_t> Triangles; // ids into Surface->Triangles
    std::vector<std::uint32_t> Indices;   // their vertex ids, for Embree
  };

private:
  static void ReportError(void* self, RTCError code, const char* message);
  static void Filter(const RTCFilterFunctionNArguments* args);
  bool Failed();
  // Adds a surface's triangles (those in `keep`, or all where it is empty) as a geometry without
  // filter and one with it (`risky`: per triangle).
  bool AddSurface(const vtkApertureSurface& surface, const std::vector<unsigned char>& risky,
    const std::vector<unsigned char>& keep);
  // A triangle geometry over `triangles` index triples the surface or the scene owns.
  bool AddGeometry(const vtkApertureSurface& surface, const std::uint32_t* indices,
    size_t triangles, Filtered* filtered);

  RTCDevice Device = nullptr;
  RTCScene Scene = nullptr;
  std::mutex ErrorMutex;
  std::string Error;
  // Index buffers Embree shares beside the surfaces': unfiltered triangles copied when their
  // runs are many, and the filtered ones.
  std::vector<std::vector<std::uint32_t>> Plain;
  std::vector<std::unique_ptr<Filtered>> Risky;
  const vtkApertureSurface* KeptSurface = nullptr;
  std::vector<unsigned char> Kept; // KeepOnly()'s triangles
  vtkIdType FilteredTriangles = 0;
  vtkIdType MaximumSharedRuns = 1024;
  vtkIdType SharedRuns = 0;
};

#endif
// VTK-HeaderTest-Exclude: vtkApertureRayScene.h
