/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureReference.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureReference
 * @brief   Monte-Carlo ground truth of the irradiance at each point, with Embree
 *
 * The reference the shading models are measured against: for every point of the input,
 *
 *   E = ∫ L(ω) V(p, ω) max(n · ω, 0) dω
 *
 * estimated with NumberOfSamples occlusion rays (Embree, the input and the occluders of port 1
 * cast shadows), normalised as the shading models are:
 *
 * - LIGHT: a distant light of angular radius LightRadius toward LightDirection, of radiance
 *   1/(π sin² r), so that an unoccluded light at normal incidence gives 1, as
 *   vtkSphericalCap::LightTransfer() and a VTK light of intensity 1 do. Samples are stratified
 *   uniformly over the light's cap.
 * - SKY: a uniform sky of radiance 1, divided by π: an open plane gets 1, as
 *   vtkSphericalCap::SkyTransfer() does. Samples are cosine-weighted over the hemisphere, so the
 *   estimate is the visible fraction of the samples.
 * - ENVIRONMENT: the radiance of a vtkEnvironmentMap (RGB), divided by π: the radiance
 *   reflected with albedo 1, as vtkEnvironmentVisibilityLighting's EnvironmentLighting.
 *   Cosine-weighted samples.
 *
 * Output: the input with point arrays `ReferenceIrradiance` (1 component, or 3 for an
 * environment) and `ReferenceNoise`, the standard error of each estimate computed from its
 * samples as if they were independent (the stratified sets do better, so it is an upper bound).
 * Points that are not finite, have no normal or belong to no polygon get NaN. `Normals` are added
 * when the input had none. The surface is taken as vtkAperturePrecompute takes it (welded, split
 * at creases, with its contact and self-hit rules and its ray offsets), so that the two can be
 * compared point by point; the output splits points the same way.
 *
 * Each point's samples depend only on Seed and its position (a per-point Cranley-Patterson
 * rotation of a Hammersley set), so results do not depend on the number of threads.
 *
 * @sa vtkAperturePrecompute vtkSphericalCap vtkOcclusionQueryVisibility
 */

#ifndef vtkApertureReference_h
#define vtkApertureReference_h

#include "vtkApertureLightingCoreModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"
#include "vtkSphericalCap.h" // For the light-radius bounds

class vtkEnvironmentMap;

class vtkMultiProcessController;

class VTKAPERTURELIGHTINGCORE_EXPORT vtkApertureReference : public vtkPolyDataAlgorithm
{
public:
  static vtkApertureReference* New();
  vtkTypeMacro(vtkApertureReference, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Occluders (port 1, repeatable): polydata that cast shadows but get no output.
   */
  void AddOccluderConnection(vtkAlgorithmOutput* occluder);

  enum Sources
  {
    LIGHT = 0,
    SKY = 1,
    ENVIRONMENT = 2
  };

  ///@{
  /**
   * What lights the points. Default LIGHT.
   */
  vtkSetClampMacro(Source, int, LIGHT, ENVIRONMENT);
  vtkGetMacro(Source, int);
  void SetSourceToLight() { this->SetSource(LIGHT); }
  void SetSourceToSky() { this->SetSource(SKY); }
  void SetSourceToEnvironment() { this->SetSource(ENVIRONMENT); }
  ///@}

  ///@{
  /**
   * The light: the world direction toward its centre (need not be unit) and its angular radius
   * in radians, from vtkSphericalCap::MinimumLightRadius (1e-4) to MaximumLightRadius (π/2).
   * Defaults (0, 0, 1) and 0.0047, the sun.
   */
  vtkSetVector3Macro(LightDirection, double);
  vtkGetVector3Macro(LightDirection, double);
  vtkSetClampMacro(
    LightRadius, double, vtkSphericalCap::MinimumLightRadius, vtkSphericalCap::MaximumLightRadius);
  vtkGetMacro(LightRadius, double);
  ///@}

  ///@{
  /**
   * The environment for the ENVIRONMENT source.
   */
  void SetEnvironment(vtkEnvironmentMap* environment);
  vtkGetObjectMacro(Environment, vtkEnvironmentMap);
  ///@}

  ///@{
  /**
   * Samples (rays) per point. Default 1024.
   */
  vtkSetClampMacro(NumberOfSamples, int, 16, 1 << 20);
  vtkGetMacro(NumberOfSamples, int);
  ///@}

  ///@{
  /**
   * Seed of the per-point sample rotations. Default 0.
   */
  vtkSetMacro(Seed, int);
  vtkGetMacro(Seed, int);
  ///@}

  ///@{
  /**
   * Ray origins are lifted along the normal by RayOffset × the point's mean edge length, as in
   * vtkAperturePrecompute. Default 0.001.
   */
  vtkSetClampMacro(RayOffset, double, 0.0, 1.0);
  vtkGetMacro(RayOffset, double);
  ///@}

  ///@{
  /**
   * Creases split normals and estimates above this angle (degrees), as in
   * vtkAperturePrecompute. Default 60.
   */
  vtkSetClampMacro(FeatureAngle, double, 0.0, 180.0);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /**
   * Names of the output arrays. Defaults `ReferenceIrradiance` and `ReferenceNoise`.
   */
  vtkSetStringMacro(IrradianceArrayName);
  vtkGetStringMacro(IrradianceArrayName);
  vtkSetStringMacro(NoiseArrayName);
  vtkGetStringMacro(NoiseArrayName);
  ///@}

  /**
   * Includes the environment's modification time.
   */
  vtkMTimeType GetMTime() override;

  ///@{
  /**
   * The controller of a distributed run (default: the global one). When the update asks for one
   * of several pieces and the controller has several processes, every other rank's polygons and
   * strips occlude this rank's points too, so that each piece gets the serial answer; every rank
   * must then update the filter, and an empty piece gives an empty output.
   */
  virtual void SetController(vtkMultiProcessController* controller);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

protected:
  vtkApertureReference();
  ~vtkApertureReference() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  int Source = LIGHT;
  double LightDirection[3] = { 0.0, 0.0, 1.0 };
  double LightRadius = 0.0047;
  vtkEnvironmentMap* Environment = nullptr;
  int NumberOfSamples = 1024;
  int Seed = 0;
  double RayOffset = 0.001;
  double FeatureAngle = 60.0;
  char* IrradianceArrayName = nullptr;
  char* NoiseArrayName = nullptr;
  vtkMultiProcessController* Controller = nullptr;

private:
  vtkApertureReference(const vtkApertureReference&) = delete;
  void operator=(const vtkApertureReference&) = delete;
};

#endif
