/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureRayScene.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureRayScene
 * @brief   Embree device and scene over vtkApertureSurface triangles (private)
 *
 * Owns an Embree device and one scene, shares the surfaces' vertex and index buffers with Embree
 * (the surfaces must outlive the scene), and records the first error Embree reports through its
 * device callback, so that the filter can turn it into a vtkErrorMacro on the main thread.
 * After Commit() the scene may be queried from any number of threads.
 */

#ifndef vtkApertureRayScene_h
#define vtkApertureRayScene_h

#include "vtkApertureLightingModule.h" // For export macro

#include <embree3/rtcore.h>

#include <mutex>
#include <string>
#include <vector>

#if defined(__SSE__) || defined(_M_X64)
#include <xmmintrin.h>
#endif

class vtkApertureSurface;

class VTKAPERTURELIGHTING_EXPORT vtkApertureRayScene
{
public:
  vtkApertureRayScene() = default;
  ~vtkApertureRayScene();
  vtkApertureRayScene(const vtkApertureRayScene&) = delete;
  vtkApertureRayScene& operator=(const vtkApertureRayScene&) = delete;

  /**
   * Creates the device (with an rtcNewDevice() configuration string) and an empty scene, with
   * Embree's compact BVH layout or its faster default one.
   */
  bool Initialize(const std::string& configuration, bool compact);

  /**
   * Adds the surface's triangles as one geometry; surfaces without triangles are skipped.
   */
  bool AddSurface(const vtkApertureSurface& surface);

  /**
   * Builds the acceleration structure.
   */
  bool Commit();

  /**
   * Initialize() with the default device and BVH, every surface added, and Commit().
   */
  bool Build(const vtkApertureSurface& receivers, const std::vector<vtkApertureSurface>& occluders);

  RTCScene GetScene() const { return this->Scene; }

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

private:
  static void ReportError(void* self, RTCError code, const char* message);
  bool Failed();

  RTCDevice Device = nullptr;
  RTCScene Scene = nullptr;
  std::mutex ErrorMutex;
  std::string Error;
};

#endif
// VTK-HeaderTest-Exclude: vtkApertureRayScene.h
