/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureRayPacket.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureRayPacket.h"

#include "vtkApertureSurface.h"

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
