/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkAperturePrecompute.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkAperturePrecompute
 * @brief   per-vertex or per-texel visibility caps for ambient aperture lighting
 *
 * vtkAperturePrecompute is the preprocessing stage of ambient aperture lighting (Oat & Sander
 * 2007). For every point of a surface it casts NumberOfRays rays over the hemisphere around the
 * point's normal with Embree and summarises what it sees as a spherical cap, the aperture:
 *
 * - `BentNormal` (float, 3 components, unit, world space): the normalised mean unoccluded
 *   direction V = normalize(∫ V(p, ω) ω dω), uniform over solid angle as in the paper;
 * - `ApertureRadius` (float, radians in [0, π/2]): r = acos(1 − A/2π), A the visible solid angle;
 * - optionally `AmbientOcclusion` (float in [0, 1]): the cosine-weighted visible fraction
 *   (1/π) ∫ V(p, ω) max(n·ω, 0) dω, the usual ambient occlusion, which is 1 for an open plane.
 *
 * Input port 0 takes
 * - a vtkPolyData: polygons and triangle strips cast and receive rays; vertices and lines are
 *   kept in the output but neither cast nor receive (points used only by them get an open
 *   aperture, r = π/2, around their normal, or +z without one);
 * - a vtkImageData height field (the per-texel mode): a 2D grid whose point scalars (the input
 *   array to process) are heights. Grid point (i, j) sits at the image's physical position of
 *   (i, j, 0) raised by HeightScale × height along the grid's third axis; the surface is
 *   triangulated as (i,j)(i+1,j)(i+1,j+1) and (i,j)(i+1,j+1)(i,j+1). The output is the same grid
 *   with one cap per grid point, ready to be used as a texture;
 * - a composite dataset of vtkPolyData: every leaf occludes every other and each leaf gets its
 *   arrays.
 *
 * Input port 1 (optional, repeatable, AddOccluderConnection()) takes extra vtkPolyData
 * occluders that cast shadows but get no output.
 *
 * The output has the input's type and keeps every input array; the input is never modified. When
 * the input has no usable point normals, the normals that were used are added as `Normals`
 * (unweighted sums of triangle normals, with consistent orientation, as vtkPolyDataNormals
 * computes them without splitting; the +z side of the grid for height fields).
 *
 * Sampling is deterministic: the Hammersley set of NumberOfRays points, uniform over the
 * hemisphere's solid angle, shifted per point by a Cranley-Patterson rotation derived from Seed
 * and the point id (SetSamplingToRandom() draws independent uniform samples instead, for
 * comparison). Rays start RayOffset × (mean length of the point's edges) above the point along its
 * normal, at least far enough to clear single-precision rounding, and stop at MaximumDistance.
 * Geometry is translated to a local origin before it reaches Embree, so UTM-sized coordinates
 * (1e5 to 1e7) keep their precision.
 *
 * Rays are traced in packets of 16 (rtcOccluded16) over blocks of points with vtkSMPTools, in
 * batches of about a million rays; progress is reported and AbortExecute checked between
 * batches. An aborted run produces an empty output.
 *
 * Points that are not finite, or whose normal is undefined, get a closed aperture (r = 0) with
 * BentNormal (0, 0, 1) and one warning. Empty input, input without polygons or strips, image data
 * that is not a 2D grid with one-component scalars, and Embree failures are errors.
 *
 * @sa vtkSphericalCap vtkApertureLightingMapper
 */

#ifndef vtkAperturePrecompute_h
#define vtkAperturePrecompute_h

#include "vtkApertureLightingModule.h" // For export macro
#include "vtkPassInputTypeAlgorithm.h"

#include <string> // For std::string

class VTKAPERTURELIGHTING_EXPORT vtkAperturePrecompute : public vtkPassInputTypeAlgorithm
{
public:
  static vtkAperturePrecompute* New();
  vtkTypeMacro(vtkAperturePrecompute, vtkPassInputTypeAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Extra occluders (vtkPolyData) on input port 1: they cast shadows but get no output.
   */
  void AddOccluderConnection(vtkAlgorithmOutput* output);
  void AddOccluderData(vtkDataObject* data);
  void RemoveAllOccluders();
  ///@}

  ///@{
  /**
   * Rays per point, in [1, 65536]. Default 256.
   */
  vtkSetClampMacro(NumberOfRays, int, 1, 65536);
  vtkGetMacro(NumberOfRays, int);
  ///@}

  ///@{
  /**
   * Rays ignore geometry farther than this (world units), for local occlusion. Default: no limit.
   */
  vtkSetClampMacro(MaximumDistance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumDistance, double);
  ///@}

  ///@{
  /**
   * Ray start offset along the normal, relative to the mean length of the point's edges (the
   * grid spacing for height fields), in [0, 1]. Default 0.001.
   */
  vtkSetClampMacro(RayOffset, double, 0.0, 1.0);
  vtkGetMacro(RayOffset, double);
  ///@}

  ///@{
  /**
   * Seed of the per-point sample rotations (or of the random samples). Default 0.
   */
  vtkSetMacro(Seed, int);
  vtkGetMacro(Seed, int);
  ///@}

  enum Sampling
  {
    STRATIFIED = 0,
    RANDOM = 1
  };

  ///@{
  /**
   * STRATIFIED (default): a rotated Hammersley set; RANDOM: independent uniform samples.
   */
  vtkSetClampMacro(Sampling, int, STRATIFIED, RANDOM);
  vtkGetMacro(Sampling, int);
  void SetSamplingToStratified() { this->SetSampling(STRATIFIED); }
  void SetSamplingToRandom() { this->SetSampling(RANDOM); }
  ///@}

  ///@{
  /**
   * Height field mode: heights are multiplied by this factor. Default 1.
   */
  vtkSetMacro(HeightScale, double);
  vtkGetMacro(HeightScale, double);
  ///@}

  ///@{
  /**
   * Also write the cosine-weighted visible fraction. Default off.
   */
  vtkSetMacro(ComputeAmbientOcclusion, bool);
  vtkGetMacro(ComputeAmbientOcclusion, bool);
  vtkBooleanMacro(ComputeAmbientOcclusion, bool);
  ///@}

  ///@{
  /**
   * Names of the output arrays. Defaults: "BentNormal", "ApertureRadius", "AmbientOcclusion".
   */
  vtkSetStdStringFromCharMacro(BentNormalArrayName);
  vtkGetCharFromStdStringMacro(BentNormalArrayName);
  vtkSetStdStringFromCharMacro(ApertureRadiusArrayName);
  vtkGetCharFromStdStringMacro(ApertureRadiusArrayName);
  vtkSetStdStringFromCharMacro(AmbientOcclusionArrayName);
  vtkGetCharFromStdStringMacro(AmbientOcclusionArrayName);
  ///@}

  ///@{
  /**
   * Build Embree's compact BVH (on by default): on the bunny it takes about 70% of the memory of
   * the default layout and traces at about 75% of its speed. Turn it off when speed matters more.
   */
  vtkSetMacro(CompactAccelerationStructure, bool);
  vtkGetMacro(CompactAccelerationStructure, bool);
  vtkBooleanMacro(CompactAccelerationStructure, bool);
  ///@}

  ///@{
  /**
   * Configuration string handed to rtcNewDevice() (for example "threads=2,verbose=1"); empty
   * by default. An invalid string makes the filter fail with Embree's message.
   */
  vtkSetStdStringFromCharMacro(EmbreeConfiguration);
  vtkGetCharFromStdStringMacro(EmbreeConfiguration);
  ///@}

protected:
  vtkAperturePrecompute();
  ~vtkAperturePrecompute() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  int NumberOfRays = 256;
  double MaximumDistance = VTK_DOUBLE_MAX;
  double RayOffset = 0.001;
  int Seed = 0;
  int Sampling = STRATIFIED;
  double HeightScale = 1.0;
  bool ComputeAmbientOcclusion = false;
  bool CompactAccelerationStructure = true;
  std::string BentNormalArrayName = "BentNormal";
  std::string ApertureRadiusArrayName = "ApertureRadius";
  std::string AmbientOcclusionArrayName = "AmbientOcclusion";
  std::string EmbreeConfiguration;

private:
  vtkAperturePrecompute(const vtkAperturePrecompute&) = delete;
  void operator=(const vtkAperturePrecompute&) = delete;
};

#endif
