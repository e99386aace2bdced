/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureRayPacket.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureRayPacket
 * @brief   sixteen occlusion rays from receiving points, traced with the shared rules (private)
 *
 * The one place where a caster's rays meet Embree. Set() places a ray where every caster places
 * it: from a receiving point of the source surface, starting at the point's Start (Offset above
 * it, see vtkApertureRayOffsets), traced from vtkApertureRayOffsets::PullBack offsets
 * behind that start (the scene's filter then applies the contact and self-hit rules near it),
 * up to a distance. Trace() casts the
 * packet with rtcOccluded16; Visible() tells which rays got through.
 *
 * One packet per thread; it keeps denormals flushed to zero while it exists.
 */

#ifndef vtkApertureRayPacket_h
#define vtkApertureRayPacket_h

#include "vtkApertureLightingCoreModule.h" // For export macro
#include "vtkApertureRayOffsets.h"         // For PullBack
#include "vtkApertureRayScene.h"           // For the context and FlushToZero
#include "vtkType.h"

#include <cstdint>

class vtkApertureSurface;

class VTKAPERTURELIGHTINGCORE_EXPORT vtkApertureRayPacket
{
public:
  static constexpr int Lanes = 16;

  /**
   * Rays from the points of `source`, one of the surfaces added to `scene`. `coherent`: the
   * rays of a packet start close together and point the same way (a hint to Embree).
   */
  vtkApertureRayPacket(
    const vtkApertureRayScene& scene, const vtkApertureSurface& source, bool coherent = false);

  /**
   * Lane `lane` casts from receiving point `point` along the unit `direction`, up to `tfar`
   * from its start.
   */
  void Set(int lane, vtkIdType point, const float direction[3], float tfar)
  {
    const float* o = this->Starts + 3 * point;
    const float back = vtkApertureRayOffsets::PullBack * this->Offsets[point];
    this->Ray.org_x[lane] = o[0] - back * direction[0];
    this->Ray.org_y[lane] = o[1] - back * direction[1];
    this->Ray.org_z[lane] = o[2] - back * direction[2];
    this->Ray.dir_x[lane] = direction[0];
    this->Ray.dir_y[lane] = direction[1];
    this->Ray.dir_z[lane] = direction[2];
    this->Ray.tnear[lane] = 0.0f;
    this->Ray.tfar[lane] = tfar + back;
    this->Ray.id[lane] = static_cast<unsigned int>(point);
    this->Valid[lane] = -1;
  }

  /**
   * Lanes 0 .. count - 1 cast from receiving point `point` along the unit directions written
   * into DirectionsX(), DirectionsY(), DirectionsZ(), up to `tfar`; the other lanes nothing.
   */
  void SetFan(vtkIdType point, int count, float tfar)
  {
    const float* o = this->Starts + 3 * point;
    const float back = vtkApertureRayOffsets::PullBack * this->Offsets[point];
    for (int lane = 0; lane < Lanes; ++lane)
    {
      this->Ray.org_x[lane] = o[0] - back * this->Ray.dir_x[lane];
      this->Ray.org_y[lane] = o[1] - back * this->Ray.dir_y[lane];
      this->Ray.org_z[lane] = o[2] - back * this->Ray.dir_z[lane];
      this->Ray.tnear[lane] = 0.0f;
      this->Ray.tfar[lane] = tfar + back;
      this->Ray.id[lane] = static_cast<unsigned int>(point);
      this->Valid[lane] = lane < count ? -1 : 0;
    }
  }

  ///@{
  /**
   * Where SetFan() takes its directions from.
   */
  float* DirectionsX() { return this->Ray.dir_x; }
  float* DirectionsY() { return this->Ray.dir_y; }
  float* DirectionsZ() { return this->Ray.dir_z; }
  ///@}

  /**
   * Lane `lane` casts nothing.
   */
  void Clear(int lane)
  {
    // Inactive lanes hold a finite ray too: Debian's Embree 3.13 keeps its assertions, and its
    // AVX2 coherent kernels aborted on a packet whose unused lanes were never written.
    this->Ray.org_x[lane] = this->Ray.org_y[lane] = this->Ray.org_z[lane] = 0.0f;
    this->Ray.tnear[lane] = this->Ray.tfar[lane] = 0.0f;
    this->Valid[lane] = 0;
  }

  /**
   * Casts the packet.
   */
  void Trace();

  /**
   * Whether lane `lane`'s ray, from where it is traced to its end, passes through one of the
   * `count` boxes (6 values each: lower x, y, z, upper x, y, z).
   */
  bool Crosses(int lane, const float* boxes, int count) const;

  /**
   * Whether lane `lane` cast a ray and nothing blocked it.
   */
  bool Visible(int lane) const { return this->Valid[lane] && this->Ray.tfar[lane] >= 0.0f; }

  ///@{
  /**
   * The direction of lane `lane`.
   */
  float DirectionX(int lane) const { return this->Ray.dir_x[lane]; }
  float DirectionY(int lane) const { return this->Ray.dir_y[lane]; }
  float DirectionZ(int lane) const { return this->Ray.dir_z[lane]; }
  ///@}

private:
  alignas(64) RTCRay16 Ray;
  alignas(64) int Valid[Lanes];
  vtkApertureRayScene::Context Context;
  RTCScene Scene;
  // The source surface's ray starts and offsets.
  const float* Starts;
  const float* Offsets;
  vtkApertureRayScene::FlushToZero FTZ;
};

#endif
// VTK-HeaderTest-Exclude: vtkApertureRayPacket.h
