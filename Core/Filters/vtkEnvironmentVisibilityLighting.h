/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkEnvironmentVisibilityLighting.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkEnvironmentVisibilityLighting
 * @brief   relights a visibility matrix under an HDR environment (Sattler et al. 2004, §5)
 *
 * Input port 0 is the output of vtkOcclusionQueryVisibility: point data `Visibility` (or
 * `VisibilityBits` with the point normals) and field data `LightDirections` and
 * `LightWeights`. Port 1 is a latitude-longitude environment (vtkOpenEXRReader's output), set
 * with SetEnvironmentConnection() or SetEnvironmentData().
 *
 * Each point gets the radiance it would reflect with albedo 1, linear RGB:
 *
 *   c_i = (1/π) Σ_j M_ij L_j w_j
 *
 * where L_j is the environment's mean radiance over direction j's lightsphere cell
 * (vtkEnvironmentMap::CellRadiance()), so an open point under a uniform environment of
 * radiance 1 gets 1. The output is the input with two point arrays added:
 * `EnvironmentLighting` (float RGB, c_i) and `EnvironmentColors` (unsigned char RGB,
 * 255 (c_i 2^Exposure)^(1/Gamma), clamped), ready for a mapper's direct colours
 * (ScalarModeToUsePointFieldData, SelectColorArray("EnvironmentColors"),
 * ColorModeToDirectScalars).
 *
 * Turning the environment (Azimuth, Orientation) or changing it needs no new visibility, only
 * a new pass of this filter, which keeps its filtered environment between updates. A change
 * of Exposure or Gamma only recomputes the colours. Nor does a rigid motion of the object
 * (Sattler et al. 2004, §6): the visibility stays in the object's coordinates and
 * ObjectRotation turns its directions into the world before the environment is looked up;
 * translations do not matter for a distant environment. An Azimuth, Exposure, Orientation or
 * ObjectRotation that is not finite is an error.
 *
 * @sa vtkOcclusionQueryVisibility vtkEnvironmentMap vtkOpenEXRReader
 */

#ifndef vtkEnvironmentVisibilityLighting_h
#define vtkEnvironmentVisibilityLighting_h

#include "vtkApertureLightingCoreModule.h" // For export macro
#include "vtkEnvironmentMap.h"             // For vtkNew<vtkEnvironmentMap>
#include "vtkNew.h"                        // For vtkNew
#include "vtkPolyDataAlgorithm.h"

#include <vector> // For std::vector

class vtkImageData;

class VTKAPERTURELIGHTINGCORE_EXPORT vtkEnvironmentVisibilityLighting : public vtkPolyDataAlgorithm
{
public:
  static vtkEnvironmentVisibilityLighting* New();
  vtkTypeMacro(vtkEnvironmentVisibilityLighting, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The latitude-longitude environment (port 1).
   */
  void SetEnvironmentConnection(vtkAlgorithmOutput* environment);
  void SetEnvironmentData(vtkImageData* environment);
  ///@}

  ///@{
  /**
   * How the environment sits in the world: its up axis, a clockwise turn about it in degrees,
   * a further rotation (row-major 3 × 3), and an optional Gaussian blur on the sphere, in
   * radians (see vtkEnvironmentMap). Defaults: Z, 0, identity, 0.
   */
  vtkSetClampMacro(UpAxis, int, 0, 2);
  vtkGetMacro(UpAxis, int);
  void SetUpAxisToX() { this->SetUpAxis(0); }
  void SetUpAxisToY() { this->SetUpAxis(1); }
  void SetUpAxisToZ() { this->SetUpAxis(2); }
  vtkSetMacro(Azimuth, double);
  vtkGetMacro(Azimuth, double);
  vtkSetVectorMacro(Orientation, double, 9);
  vtkGetVectorMacro(Orientation, double, 9);
  vtkSetClampMacro(BlurAngle, double, 0.0, 1.0);
  vtkGetMacro(BlurAngle, double);
  ///@}

  ///@{
  /**
   * The rotation (row-major 3 × 3) that takes the input's coordinates to the world, as the
   * rotation part of the object's actor matrix: lightsphere direction l_j is looked up in the
   * environment as R l_j. Default identity.
   */
  vtkSetVectorMacro(ObjectRotation, double, 9);
  vtkGetVectorMacro(ObjectRotation, double, 9);
  ///@}

  ///@{
  /**
   * Exposure in stops (the colours are c 2^Exposure) and the display gamma. Defaults 0 and 2.2.
   */
  vtkSetMacro(Exposure, double);
  vtkGetMacro(Exposure, double);
  vtkSetClampMacro(Gamma, double, 0.1, 10.0);
  vtkGetMacro(Gamma, double);
  ///@}

  /**
   * The environment, as the filter samples it (for inspection; set it up through this filter).
   */
  vtkEnvironmentMap* GetEnvironmentMap() { return this->Environment; }

protected:
  vtkEnvironmentVisibilityLighting();
  ~vtkEnvironmentVisibilityLighting() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  // The whole environment, whatever piece of the surface is asked for.
  int RequestUpdateExtent(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  int UpAxis = 2;
  double Azimuth = 0.0;
  double Orientation[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  double BlurAngle = 0.0;
  double ObjectRotation[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  double Exposure = 0.0;
  double Gamma = 2.2;

private:
  vtkEnvironmentVisibilityLighting(const vtkEnvironmentVisibilityLighting&) = delete;
  void operator=(const vtkEnvironmentVisibilityLighting&) = delete;

  vtkNew<vtkEnvironmentMap> Environment;
  // The linear result and what it was computed from, so that exposure and gamma alone only
  // redo the colours.
  std::vector<float> Linear;
  std::vector<double> LinearFor;
};

#endif
