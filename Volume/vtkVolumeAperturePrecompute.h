/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkVolumeAperturePrecompute.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkVolumeAperturePrecompute
 * @brief   a visibility cap per voxel of a scalar volume, through its opacity transfer function
 *
 * The volume counterpart of vtkAperturePrecompute. Input: a vtkImageData with point scalars of
 * one component (the active scalars, or the array set with SetInputArrayToProcess(0, ...)) and a
 * vtkVolumeProperty whose scalar opacity function and unit distance say how much light each
 * voxel stops, as VTK's ray casters draw it (see vtkVolumeExtinction: σ = −ln(1 − α)/u).
 * Output: an image on the aperture grid (every ApertureGridStep-th voxel of the input; the input's
 * grid by default) with point arrays
 *
 * - `BentNormal` (3 floats, unit, world axes): normalize(∫ T(ω) ω dω),
 * - `ApertureRadius` (float, radians in [0, π]): r = acos(1 − A/2π), A = ∫ T(ω) dω over the whole
 *   sphere: π in free space, π/2 on an opaque half-space's surface, 0 deep inside opaque matter,
 *
 * where T(ω) = exp(−τ(ω)) is the transmittance from the voxel's centre along ω. Where
 * ∫ T ω dω is shorter than 1e-4 of A (free space, a voxel inside a closed shell), the bent normal
 * is the image's third axis (its direction matrix's +k): any direction is then right. On the
 * input's grid the output keeps every input array.
 *
 * What a ray sees: τ(ω) = ∫ σ(x + sω) e^{−s/λ} ds from s = δ on, σ trilinear: the ray starts
 * where it reaches the next slice of the aperture grid across it (δ, one to √3 voxels; see
 * vtkVolumeExtinction::StepLength()), what lies nearer being the voxel's own: a voxel does not
 * shade itself, its neighbours do. Matter farther away weighs less: λ = MaximumDistance/3, so
 * that matter at MaximumDistance counts 5% of what it would nearby (an opaque wall a voxel thick,
 * τ = 13.8, stops shading at about half of it). Outside the volume is empty.
 *
 * How: for each of NumberOfDirections directions (a spherical Fibonacci set, equal solid angles,
 * the same for every voxel), one sweep of the aperture grid slice by slice against the direction
 * carries the transmittance from each slice to the next (the step δ crosses one slice),
 * interpolating it bilinearly within the slice: every voxel's T costs two bilinear samples,
 * whatever MaximumDistance is. Interpolating T rather than τ keeps openings open: a ray beside an
 * opaque wall gets the average of its neighbours' light, not the light through their average depth.
 * A coarser aperture grid first averages σ with a tent filter, which keeps the optical depth of
 * thin walls. Time and error against vtkVolumeApertureReference: BenchmarkVolumeAperture.
 *
 * Streaming: the filter produces any sub-extent of its output and asks for the input around it
 * grown by a halo of 1.5 MaximumDistance (rays farther out count less than e^-4.5), so that
 * pieces, streaming and MPI ranks work as for surfaces.
 *
 * Bad input (no property, no or multi-component scalars, NaN voxels, fewer than 2 voxels along an
 * axis, absurd spacing): one error and no output.
 *
 * @sa vtkAperturePrecompute vtkVolumeApertureReference vtkApertureVolumeMapper
 */

#ifndef vtkVolumeAperturePrecompute_h
#define vtkVolumeAperturePrecompute_h

#include "vtkApertureLightingVolumeModule.h" // For export macro
#include "vtkImageAlgorithm.h"

class vtkVolumeProperty;

class VTKAPERTURELIGHTINGVOLUME_EXPORT vtkVolumeAperturePrecompute : public vtkImageAlgorithm
{
public:
  static vtkVolumeAperturePrecompute* New();
  vtkTypeMacro(vtkVolumeAperturePrecompute, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The transfer function the apertures see (its scalar opacity and unit distance). Required.
   */
  void SetVolumeProperty(vtkVolumeProperty* property);
  vtkGetObjectMacro(VolumeProperty, vtkVolumeProperty);
  ///@}

  ///@{
  /**
   * How far occluders reach, in world units (see the class documentation). 0, the default,
   * takes a fifth of the input's diagonal. At least one voxel of the aperture grid is used.
   */
  vtkSetClampMacro(MaximumDistance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumDistance, double);
  ///@}

  ///@{
  /**
   * Directions over the whole sphere. Default 64; the cap radius moves by about
   * 2/(NumberOfDirections sin r) when one direction opens, so small openings want more.
   */
  vtkSetClampMacro(NumberOfDirections, int, 8, 4096);
  vtkGetMacro(NumberOfDirections, int);
  ///@}

  ///@{
  /**
   * Apertures on every n-th voxel of the input along each axis. Default 1 (the input's grid);
   * 2 computes 8 times fewer voxels, apertures being smooth where the volume is not.
   */
  vtkSetClampMacro(ApertureGridStep, int, 1, 64);
  vtkGetMacro(ApertureGridStep, int);
  ///@}

  /**
   * The distance actually used for an input of these bounds (MaximumDistance or its default).
   */
  double GetEffectiveMaximumDistance(const double bounds[6]) const;

  /**
   * How many input voxels a piece of the output needs on each side along each axis (its halo,
   * and one step of the aperture grid), for an input of this whole extent and spacing: what a
   * pipeline that hands out pieces with ghost levels (ParaView's) asks its source for.
   */
  void ComputeHalo(const int wholeExtent[6], const double spacing[3], int halo[3]) const;

  /**
   * Includes the volume property's time.
   */
  vtkMTimeType GetMTime() override;

protected:
  vtkVolumeAperturePrecompute();
  ~vtkVolumeAperturePrecompute() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkVolumeProperty* VolumeProperty = nullptr;
  double MaximumDistance = 0.0;
  int NumberOfDirections = 64;
  int ApertureGridStep = 1;

private:
  vtkVolumeAperturePrecompute(const vtkVolumeAperturePrecompute&) = delete;
  void operator=(const vtkVolumeAperturePrecompute&) = delete;
};

#endif
