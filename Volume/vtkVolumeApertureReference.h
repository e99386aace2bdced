/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkVolumeApertureReference.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkVolumeApertureReference
 * @brief   Monte-Carlo ground truth for volume apertures: rays marched through the transmittance
 *
 * What vtkVolumeAperturePrecompute approximates, computed the slow and plain way, for checking it
 * and for the error tables: for voxels of its aperture grid, NumberOfSamples rays marched in steps
 * of a quarter of the smallest spacing through the input's σ (trilinear on the input's own grid,
 * see vtkVolumeExtinction), with the same definition of τ: the optical depth from where the ray
 * reaches the aperture grid's next slice across it (what lies nearer is the voxel's own),
 * weighted by e^{−3s/MaximumDistance}; outside the volume is empty.
 *
 * - LIGHT: `ReferenceIrradiance`, the mean transmittance over a light's cap (LightDirection toward
 *   the light, LightRadius in radians), samples stratified over the cap: the light a voxel gets,
 *   1 when nothing is in the way. The volume mapper's shading of a voxel under that light
 *   (vtkSphericalCap: the light cap's area within the aperture, over the light cap's area) is
 *   the estimate of it.
 * - SPHERE: `ReferenceApertureRadius` and `ReferenceBentNormal` over the whole sphere, by CapFit:
 *   from ∫ T dω and ∫ T ω dω (MOMENTS, the quantities the precompute outputs), or the cap nearest
 *   the marched visibility (NEAREST: the least ∫ |T − cap| dω, searched over axis and radius),
 *   the best any one cap can do, which says how much of an error is the cap's and how much the
 *   precompute's.
 *
 * Output: an image of every SampleStep-th voxel of the aperture grid (ApertureGridStep as in the
 * precompute), so that its points are points of the precompute's output. Each voxel's sample set
 * is a spherical Fibonacci set turned by a rotation drawn from the voxel's index: independent of
 * the precompute's fixed directions, and the same whatever the thread count.
 *
 * @sa vtkVolumeAperturePrecompute vtkApertureReference
 */

#ifndef vtkVolumeApertureReference_h
#define vtkVolumeApertureReference_h

#include "vtkApertureLightingVolumeModule.h" // For export macro
#include "vtkImageAlgorithm.h"

class vtkMatrix3x3;
class vtkVolumeProperty;

class VTKAPERTURELIGHTINGVOLUME_EXPORT vtkVolumeApertureReference : public vtkImageAlgorithm
{
public:
  static vtkVolumeApertureReference* New();
  vtkTypeMacro(vtkVolumeApertureReference, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Sources
  {
    LIGHT = 0,
    SPHERE = 1
  };

  ///@{
  /**
   * What is integrated. Default LIGHT.
   */
  vtkSetClampMacro(Source, int, LIGHT, SPHERE);
  vtkGetMacro(Source, int);
  ///@}

  enum CapFits
  {
    MOMENTS = 0,
    NEAREST = 1
  };

  ///@{
  /**
   * How SPHERE fits a cap to the marched rays (see the class description). Default MOMENTS.
   */
  vtkSetClampMacro(CapFit, int, MOMENTS, NEAREST);
  vtkGetMacro(CapFit, int);
  ///@}

  ///@{
  /**
   * As vtkVolumeAperturePrecompute's.
   */
  void SetVolumeProperty(vtkVolumeProperty* property);
  vtkGetObjectMacro(VolumeProperty, vtkVolumeProperty);
  vtkSetClampMacro(MaximumDistance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumDistance, double);
  vtkSetClampMacro(ApertureGridStep, int, 1, 64);
  vtkGetMacro(ApertureGridStep, int);
  ///@}

  ///@{
  /**
   * A reference on every SampleStep-th voxel of the aperture grid. Default 4.
   */
  vtkSetClampMacro(SampleStep, int, 1, 1024);
  vtkGetMacro(SampleStep, int);
  ///@}

  ///@{
  /**
   * Rays per voxel. Default 256.
   */
  vtkSetClampMacro(NumberOfSamples, int, 1, 1 << 20);
  vtkGetMacro(NumberOfSamples, int);
  ///@}

  ///@{
  /**
   * The light of LIGHT: the direction toward it (world axes) and its angular radius, radians.
   */
  vtkSetVector3Macro(LightDirection, double);
  vtkGetVector3Macro(LightDirection, double);
  vtkSetClampMacro(LightRadius, double, 1e-4, 1.5707963267948966);
  vtkGetMacro(LightRadius, double);
  ///@}

  /**
   * Includes the volume property's time.
   */
  vtkMTimeType GetMTime() override;

protected:
  vtkVolumeApertureReference();
  ~vtkVolumeApertureReference() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  // The light's direction in the image's axes, unit; false when it is not a direction.
  bool LightAxis(vtkMatrix3x3* rotation, double axis[3]) const;

  int Source = LIGHT;
  int CapFit = MOMENTS;
  vtkVolumeProperty* VolumeProperty = nullptr;
  double MaximumDistance = 0.0;
  int ApertureGridStep = 1;
  int SampleStep = 4;
  int NumberOfSamples = 256;
  double LightDirection[3] = { 0.0, 0.0, 1.0 };
  double LightRadius = 0.1;

private:
  vtkVolumeApertureReference(const vtkVolumeApertureReference&) = delete;
  void operator=(const vtkVolumeApertureReference&) = delete;
};

#endif
