/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkVolumeExtinction.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkVolumeExtinction
 * @brief   the extinction coefficient of a scalar volume under a transfer function (private)
 *
 * The one place where a volume's scalars become what light sees: the extinction coefficient
 * σ (per world unit) of each voxel, from VTK's scalar opacity transfer function α(s) and its
 * unit distance u as VTK's ray casters use them (a step of length Δ keeps 1 − (1 − α)^(Δ/u) of
 * the light), so σ = −ln(1 − α)/u. Opacity 1 is taken as 1 − 1e-6 (σ = 13.8/u): every opaque
 * voxel is then as dark as VTK draws it, and the optical depths stay finite.
 *
 * vtkVolumeAperturePrecompute and vtkVolumeApertureReference both read volumes through this class,
 * so that the two agree on what the volume is and on what they refuse, and the reference remains
 * an independent integration of the same field.
 */

#ifndef vtkVolumeExtinction_h
#define vtkVolumeExtinction_h

#include "vtkApertureLightingVolumeModule.h" // For export macro
#include "vtkType.h"                         // For vtkIdType

#include <string>
#include <vector>

class vtkDataArray;
class vtkImageData;
class vtkVolumeProperty;

class VTKAPERTURELIGHTINGVOLUME_EXPORT vtkVolumeExtinction
{
public:
  /**
   * Opacity 1 as the extinction sees it.
   */
  static constexpr double MaximumOpacity = 1.0 - 1e-6;

  /**
   * τ weighs matter at distance s by e^{−s/λ}, λ = MaximumDistance / FalloffsPerDistance.
   */
  static constexpr double FalloffsPerDistance = 3.0;

  /**
   * The MaximumDistance of a volume of these bounds when none is set: a fifth of its diagonal.
   */
  static double DefaultMaximumDistance(const double bounds[6]);

  /**
   * The world length δ of a step along unit `omega` from one slice of a grid of `spacing` to the
   * next (slices across the axis omega crosses fastest): rays start δ/2 out.
   */
  static double StepLength(const double omega[3], const double spacing[3]);

  /**
   * Checks a volume for the volume filters: point scalars of one component, finite, at least two
   * voxels along two axes, a positive finite spacing, a direction matrix that is a rotation, and
   * a volume property with a scalar opacity function. Returns "" when usable, otherwise the
   * reason, ready for a message.
   */
  static std::string Check(vtkImageData* image, vtkDataArray* scalars, vtkVolumeProperty* property);

  /**
   * σ of every voxel of `image` (checked), x fastest, per world unit.
   */
  static std::vector<float> Compute(
    vtkImageData* image, vtkDataArray* scalars, vtkVolumeProperty* property);

  /**
   * A grid of every `step`-th voxel (indices offset, offset + step, ... of dims, per axis, offset
   * below step), each the average of
   * the voxels within `step` of it under a tent weight (1 − |d|/step along each axis), with
   * nothing outside the grid: what is left of σ on a coarser aperture grid keeps the volume's
   * optical depth. outDims receives the coarse grid's dimensions.
   */
  static std::vector<float> Decimate(const std::vector<float>& sigma, const int dims[3], int step,
    const int offset[3], int outDims[3]);

  /**
   * Trilinear σ at continuous index (x, y, z) of a grid of dims; nothing outside it.
   */
  static double Sample(const float* sigma, const int dims[3], double x, double y, double z);

  /**
   * The structured index of point n of extent (x fastest), as filters that write an output
   * extent point by point need it.
   */
  static void ExtentPoint(const int extent[6], vtkIdType n, int ijk[3]);

  /**
   * The bent normal of a voxel from Σ T (`open`) and Σ T ω (`moment`): the unit direction of the
   * moment, or +z where it vanishes against Σ T (free space, a voxel open all round).
   */
  static void MeanDirection(double open, const double moment[3], double unit[3]);
};

#endif
