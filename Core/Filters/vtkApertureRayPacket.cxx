/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureRayPacket.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureRayPacket.h"

#include "vtkApertureSurface.h"

#include <algorithm>

//------------------------------------------------------------------------------
vtkApertureRayPacket::vtkApertureRayPacket(
  const vtkApertureRayScene& scene, const vtkApertureSurface& source, bool coherent)
  : Scene(scene.GetScene())
  , Starts(source.Start.data())
  , Offsets(source.Offset.data())
{
  rtcInitIntersectContext(&this->Context.Base);
  if (coherent)
  {
    this->Context.Base.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  }
  this->Context.Source = &source;
  for (int lane = 0; lane < Lanes; ++lane)
  {
    this->Ray.time[lane] = 0.0f;
    this->Ray.mask[lane] = 0xffffffffu;
    this->Ray.flags[lane] = 0;
    this->Ray.id[lane] = 0;
    this->Ray.dir_x[lane] = this->Ray.dir_y[lane] = this->Ray.dir_z[lane] = 0.0f;
    this->Clear(lane);
  }
}

//------------------------------------------------------------------------------
void vtkApertureRayPacket::Trace()
{
  rtcOccluded16(this->Valid, this->Scene, &this->Context.Base, &this->Ray);
}

//------------------------------------------------------------------------------
bool vtkApertureRayPacket::Crosses(int lane, const float* boxes, int count) const
{
  const float o[3] = { this->Ray.org_x[lane], this->Ray.org_y[lane], this->Ray.org_z[lane] };
  const float d[3] = { this->Ray.dir_x[lane], this->Ray.dir_y[lane], this->Ray.dir_z[lane] };
  for (int b = 0; b < count; ++b)
  {
    // The part of the ray within each slab of the box.
    const float* box = boxes + 6 * b;
    float t0 = this->Ray.tnear[lane], t1 = this->Ray.tfar[lane];
    for (int k = 0; k < 3 && t0 <= t1; ++k)
    {
      if (d[k] != 0.0f)
      {
        const float a = (box[k] - o[k]) / d[k], c = (box[k + 3] - o[k]) / d[k];
        t0 = std::max(t0, std::min(a, c));
        t1 = std::min(t1, std::max(a, c));
      }
      else if (o[k] < box[k] || o[k] > box[k + 3])
      {
        t1 = -1.0f;
      }
    }
    if (t0 <= t1)
    {
      return true;
    }
  }
  return false;
}
