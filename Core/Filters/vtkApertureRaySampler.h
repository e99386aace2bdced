/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureRaySampler.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureRaySampler
 * @brief   deterministic ray directions around an axis, per receiving point (private)
 *
 * The directions every caster draws: NumberOfRays of them around a unit axis, distributed
 *
 * - uniformly in solid angle over the hemisphere (vtkAperturePrecompute's apertures),
 * - by the cosine over the hemisphere (vtkApertureReference's sky and environments),
 * - uniformly in solid angle over a cap of radius CapRadius (vtkApertureReference's light).
 *
 * The stratified set is the Hammersley set (u = (i + 1/2)/n, azimuth = radical inverse of i),
 * u mapped to cos θ by the distribution, ordered by azimuth sector so that the 16 rays of a
 * packet point roughly the same way, and moved per point by a Cranley-Patterson rotation (a
 * shift of u modulo 1 and a turn in azimuth) drawn from a hash of the seed and the point's key.
 * Random sampling draws every ray from that hash instead. Either way a point's rays depend only
 * on the seed and its key (vtkApertureSurface::Key: its position and side), not on point order
 * or threads.
 *
 * The class is exported for the project's benchmarks and tests; its header is not installed.
 */

#ifndef vtkApertureRaySampler_h
#define vtkApertureRaySampler_h

#include "vtkApertureLightingCoreModule.h" // For export macro

#include <cstdint>
#include <vector>

class VTKAPERTURELIGHTINGCORE_EXPORT vtkApertureRaySampler
{
public:
  enum Distribution
  {
    UNIFORM_HEMISPHERE = 0,
    COSINE_HEMISPHERE = 1,
    UNIFORM_CAP = 2
  };

  /**
   * numberOfRays >= 1; capRadius (radians) is used by UNIFORM_CAP only.
   */
  vtkApertureRaySampler(int numberOfRays, int seed, bool random,
    int distribution = UNIFORM_HEMISPHERE, double capRadius = 0.0);

  int GetNumberOfRays() const { return static_cast<int>(this->U.size()); }

  /**
   * Per-point state: the frame around the axis and the point's rotation.
   */
  struct Point
  {
    float Axis[3], Tangent[3], Bitangent[3];
    float ShiftU, TurnCos, TurnSin;
    std::uint64_t State;
  };

  /**
   * Prepares the rays of the point with `key` around the unit `axis`.
   */
  void Begin(const float axis[3], std::uint64_t key, Point& point) const;

  /**
   * The unit direction of ray `index` (0 .. NumberOfRays - 1) of a point. Random sampling draws
   * a new direction at each call, so call it once per ray, in order.
   */
  void Direction(Point& point, int index, float direction[3]) const;

  /**
   * The unit directions of rays first .. first + count - 1 of a point, into x, y and z (the
   * same as Direction() for each, in one loop the compiler vectorises).
   */
  void Directions(Point& point, int first, int count, float* x, float* y, float* z) const;

  /**
   * splitmix64 finaliser, the hash behind the per-point rotations and the keys.
   */
  static std::uint64_t Mix(std::uint64_t x);

private:
  float CosTheta(float u) const;
  template <int D>
  void Stratified(const Point& point, int first, int count, float* x, float* y, float* z) const;

  std::vector<float> U, CosPhi, SinPhi;
  std::uint64_t Seed;
  bool Random;
  int Distribution;
  float CapCos;
};

#endif
// VTK-HeaderTest-Exclude: vtkApertureRaySampler.h
