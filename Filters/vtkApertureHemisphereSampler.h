/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureHemisphereSampler.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureHemisphereSampler
 * @brief   deterministic hemisphere rays of a surface point, in Embree packets (private)
 *
 * The rays vtkAperturePrecompute casts from a point of a vtkApertureSurface: uniform in solid
 * angle over the hemisphere around the point's normal, starting RayOffset × (mean edge length)
 * above the point, or farther where single-precision rounding needs it.
 *
 * The stratified set is the Hammersley set (cos θ = (i + 1/2)/n, azimuth = radical inverse of i),
 * ordered by azimuth sector so that the 16 rays of a packet point roughly the same way, and moved
 * per point by a Cranley-Patterson rotation (a shift of cos θ modulo 1 and a turn in azimuth)
 * drawn from a hash of the seed and the point id. Random sampling draws every ray from that
 * hash instead. Either way a point's rays depend only on the seed and its id.
 *
 * The class is exported for the project's benchmarks; its header is not installed.
 */

#ifndef vtkApertureHemisphereSampler_h
#define vtkApertureHemisphereSampler_h

#include "vtkApertureLightingModule.h" // For export macro
#include "vtkType.h"

#include <embree3/rtcore.h>

#include <cstdint>
#include <vector>

class vtkApertureSurface;

class VTKAPERTURELIGHTING_EXPORT vtkApertureHemisphereSampler
{
public:
  static constexpr int Lanes = 16;

  vtkApertureHemisphereSampler(int numberOfRays, int seed, bool random, double rayOffset);

  int GetNumberOfRays() const { return static_cast<int>(this->CosTheta.size()); }

  /**
   * Per-point state: the frame around the normal, the ray origin and the point's rotation.
   */
  struct Point
  {
    float Normal[3], Tangent[3], Bitangent[3], Origin[3];
    float ShiftCosTheta, TurnCos, TurnSin;
    std::uint64_t State;
  };

  /**
   * Prepares the rays of point `id` of the surface (a valid receiving point).
   */
  void Begin(const vtkApertureSurface& surface, vtkIdType id, Point& point) const;

  /**
   * Fills the packet of rays first .. first + 15 of a point; lanes past the last ray are
   * invalid (valid[lane] = 0). Rays run from tnear = 0 to tfar.
   */
  void Fill(Point& point, int first, float tfar, RTCRay16& ray, int valid[Lanes]) const;

  /**
   * splitmix64 finaliser, the hash behind the per-point rotations.
   */
  static std::uint64_t Mix(std::uint64_t x);

private:
  std::vector<float> CosTheta, CosPhi, SinPhi;
  std::uint64_t Seed;
  bool Random;
  float RayOffset;
};

#endif
// VTK-HeaderTest-Exclude: vtkApertureHemisphereSampler.h
