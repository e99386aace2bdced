/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkLightSphereVisibility.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkLightSphereVisibility
 * @brief   per-vertex visibility of a lightsphere of directions, by rays (no OpenGL)
 *
 * For each direction l_j of a vtkLightSphere (level 0 to 4: k = 6 to 1026) and each point i of
 * the input, whether the point sees the far-away sky in that direction: the direction is above
 * the point's tangent plane (n_i · l_j > 0) and nothing blocks it. The result is the visibility
 * matrix of Sattler et al. (2004), stored as point data:
 *
 * - `Visibility` (float, k components): M_ij = max(n_i · l_j, 0) when point i sees direction j,
 *   else 0, so that the irradiance from an environment of radiance L_j is Σ_j M_ij L_j w_j;
 * - `VisibilityBits` (optional, a vtkBitArray of k components): the raw visibility, 32 times
 *   smaller than `Visibility`;
 * - field data `LightDirections` (k × 3) and `LightWeights` (k solid angles, summing to 4π).
 *
 * The output is the input with these arrays added (and `Normals` when the input had none); the
 * input is never modified. The surface is taken as vtkAperturePrecompute takes it: points at the
 * same position welded, creases above FeatureAngle splitting normals (and the output's points,
 * where the input shares one across a crease), and its contact and self-hit rules. Input port 1
 * takes occluders (repeatable): polydata that cast shadows but get no output.
 *
 * This filter casts Embree rays from each point (offset along its normal by RayOffset times its
 * mean edge length, as vtkAperturePrecompute casts them), 16 neighbours to a packet, on every
 * core. It needs no display and no OpenGL: it is the headless path, and the reference of
 * vtkOcclusionQueryVisibility, which adds OpenGL backends and vertex filtering to it.
 *
 * What an update computed is kept while the geometry and the settings stay the same: the
 * directions of a level are a prefix of those of the next, so raising the level only casts the
 * new directions. Progress events fire between directions and an abort stops there (the output
 * is then empty). In a distributed run every other rank's surface occludes too.
 *
 * @sa vtkLightSphere vtkOcclusionQueryVisibility vtkEnvironmentVisibilityLighting
 */

#ifndef vtkLightSphereVisibility_h
#define vtkLightSphereVisibility_h

#include "vtkApertureLightingCoreModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <array>      // For std::array
#include <cstdint>    // For std::uint64_t
#include <functional> // For std::function
#include <memory>     // For std::unique_ptr
#include <string>     // For std::string
#include <vector>     // For std::vector

class vtkApertureSurface;
class vtkLightSphere;
class vtkMultiProcessController;

class VTKAPERTURELIGHTINGCORE_EXPORT vtkLightSphereVisibility : public vtkPolyDataAlgorithm
{
public:
  static vtkLightSphereVisibility* New();
  vtkTypeMacro(vtkLightSphereVisibility, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Lightsphere level, clamped to [0, 4]: k = 6, 18, 66, 258, 1026 directions. Default 2.
   */
  vtkSetClampMacro(Level, int, 0, 4);
  vtkGetMacro(Level, int);
  ///@}

  ///@{
  /**
   * Rays start this many mean edge lengths above their point, along its normal. Clamped to
   * [0, 1]. Default 0.001.
   */
  vtkSetClampMacro(RayOffset, double, 0.0, 1.0);
  vtkGetMacro(RayOffset, double);
  ///@}

  ///@{
  /**
   * Creases split the points' normals and visibility above this angle (degrees), as in
   * vtkAperturePrecompute. Default 60.
   */
  vtkSetClampMacro(FeatureAngle, double, 0.0, 180.0);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /**
   * Which arrays to produce: `Visibility` (default on) and `VisibilityBits` (default off).
   */
  vtkSetMacro(ComputeVisibility, bool);
  vtkGetMacro(ComputeVisibility, bool);
  vtkBooleanMacro(ComputeVisibility, bool);
  vtkSetMacro(ComputeVisibilityBits, bool);
  vtkGetMacro(ComputeVisibilityBits, bool);
  vtkBooleanMacro(ComputeVisibilityBits, bool);
  ///@}

  ///@{
  /**
   * Occluders on port 1: they cast shadows but get no visibility.
   */
  void AddOccluderConnection(vtkAlgorithmOutput* occluder);
  void RemoveAllOccluders();
  ///@}

  /**
   * Points given new directions in the last update (all of them, when anything was computed).
   */
  vtkGetMacro(NumberOfComputedPoints, vtkIdType);

  ///@{
  /**
   * The controller of a distributed run (default: the global one). When the update asks for one
   * of several pieces and the controller has several processes, every other rank's polygons and
   * strips occlude this rank's points too, so that each piece gets the serial matrix; every rank
   * must then update the filter, and an empty piece gives an empty output.
   */
  virtual void SetController(vtkMultiProcessController* controller);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

protected:
  vtkLightSphereVisibility();
  ~vtkLightSphereVisibility() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  using Directions = std::vector<std::array<double, 3>>;
  using Bits = std::vector<std::uint64_t>;

  ///@{
  /**
   * What a backend adds (vtkOcclusionQueryVisibility). CheckSettings() runs before anything is
   * computed; AppendCacheKey() adds the settings whose change drops what was computed;
   * SurfacesChanged() follows a rebuild of the surfaces; SelectPoints() may clear entries of
   * GetNeededPoints() (all set after a rebuild) to leave points without visibility for now;
   * ComputeDirections() gives each direction's bit set over the receiving points (bits of points
   * not listed 0), calling `progress(done)` between directions and stopping when it returns
   * false; LeavesPointsOut() adds the `VisibilityComputed` array to the output.
   */
  virtual bool CheckSettings(std::string& error);
  virtual void AppendCacheKey(std::vector<vtkMTimeType>& key);
  virtual void SurfacesChanged() {}
  virtual bool SelectPoints(std::string& error);
  virtual bool ComputeDirections(const Directions& directions,
    const std::vector<std::uint32_t>& points, std::vector<Bits>& visible,
    const std::function<bool(size_t done)>& progress, std::string& error);
  virtual bool LeavesPointsOut();
  ///@}

  ///@{
  /**
   * The surfaces of the current update (receivers: the input; occluders: port 1 and the other
   * ranks), and which receiving points need visibility.
   */
  const vtkApertureSurface& GetReceivers() const;
  const std::vector<vtkApertureSurface>& GetOccluders() const;
  std::vector<unsigned char>& GetNeededPoints();
  ///@}

  /**
   * Drops what was computed: the next update starts again.
   */
  void ForgetComputed();

  int Level = 2;
  double RayOffset = 0.001;
  double FeatureAngle = 60.0;
  bool ComputeVisibility = true;
  bool ComputeVisibilityBits = false;
  vtkIdType NumberOfComputedPoints = 0;

private:
  vtkLightSphereVisibility(const vtkLightSphereVisibility&) = delete;
  void operator=(const vtkLightSphereVisibility&) = delete;

  // The surfaces of this update (with a distributed piece's ghost cells), keeping what earlier
  // ones computed for the same geometry.
  bool UpdateCache(vtkPolyData* input, vtkPolyData* ghosts,
    const std::vector<vtkPolyData*>& occluders, std::string& error);
  // The directions of the level that needed points lack.
  bool ComputeMissing(const Directions& directions, bool& aborted, std::string& error);
  void WriteOutputs(
    vtkPolyData* input, vtkPolyData* output, vtkLightSphere* sphere, const Directions& directions);

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
  vtkMultiProcessController* Controller = nullptr;
};

#endif
