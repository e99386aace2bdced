/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureRayOffsets.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureRayOffsets
 * @brief   where each receiving point's rays start, and which hits are near it (private)
 *
 * Every caster starts a point's rays off the surface, so that they do not hit the triangles
 * around the point, and traces them from a little behind that start, so that a neighbour's
 * triangle a hair above the point (a scan's reconstruction) still counts: the contact and
 * self-hit rules of vtkApertureRayScene and vtkApertureRayRisks read these constants and the
 * surface's Offset, Start and Near.
 *
 * @sa vtkApertureSurface vtkApertureRayScene vtkApertureRayPacket
 */

#ifndef vtkApertureRayOffsets_h
#define vtkApertureRayOffsets_h

#include "vtkApertureLightingCoreModule.h" // For export macro

class vtkApertureSurface;

class VTKAPERTURELIGHTINGCORE_EXPORT vtkApertureRayOffsets
{
public:
  ///@{
  /// Rays are traced from PullBack offsets behind their start. Hits up to a point's Near
  /// distance from there are near: NearZone offsets, or ContactTolerance of the mean length of
  /// its vertex's edges, whichever is more. The tolerance takes a scan's vertex that
  /// reconstruction left a hair under its neighbour's triangle for a point on the surface, as it
  /// is.
  static constexpr float PullBack = 0.25f;
  static constexpr float NearZone = 2.0f;
  static constexpr float ContactTolerance = 0.05f;
  ///@}

  /**
   * Sets where the surface's rays start: Offset = rayOffset × (mean length of the vertex's edges)
   * above the point along its normal, at least far enough to clear single-precision rounding;
   * and moved along the surface toward the middle of its side's triangles by up to Offset, so
   * that a point on a crease or a corner does not start its rays on the planes of the faces
   * beyond it (Start). Points inside a regular fan are not moved along the surface. Near as
   * above.
   */
  static void Set(vtkApertureSurface& surface, double rayOffset);
};

#endif
// VTK-HeaderTest-Exclude: vtkApertureRayOffsets.h
