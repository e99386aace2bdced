/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkVisibilityMask.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkVisibilityMask
 * @brief   which cells of a point's hemisphere are open, and the light and sky through them
 *
 * One cap cannot hold what a point of a detailed mesh sees (sky through two gaps between a
 * bunny's ear and leg). vtkAperturePrecompute keeps, when asked (ComputeVisibilityMask), one bit
 * per cell of the point's hemisphere: the `VisibilityMask` point array, unsigned char, bits/8
 * components, cell k at bit k % 8 of component k / 8, 1 for open.
 *
 * Cells (shared by the precompute and the shading): B = side² cells of equal solid angle 2π/B
 * in the point's tangent frame. The frame is Duff et al.'s (2017) orthonormal basis of the unit
 * normal n (x, y tangent, z = n), which any caster or shader builds from n alone. A direction's
 * frame coordinates (x, y, z ≥ 0) go to the unit disk by the Lambert equal-area projection
 * (x, y) / √(1 + z), and the disk to the square [−1, 1]² by Shirley and Chiu's concentric map,
 * both area-preserving; the square's side × side grid (i along the first square axis, cell
 * i + side j) gives the cells. B is a square in [64, 1024] that is a multiple of 8: 64, 144,
 * 256 (default: 16 × 16, 32 bytes), 400, 576, 784, 1024.
 *
 * - LightTransfer(): the irradiance from a light cap of radius rl, normalised as
 *   vtkSphericalCap::LightTransfer() is: the light's radiance 1/(π sin²rl) times ∫ max(0, n·ω)
 *   dω over the part of the cap in open cells, summed over LightSamples() stratified directions
 *   of the cap (a Fibonacci spiral, cos θ uniform), so that a light smaller than a cell takes
 *   the open share of itself, not a cell's all or nothing. The samples grow with the light: 8
 *   for each eighth of a cell the cap covers, from 8 (a sun: its share in eighths where a cell's
 *   edge crosses it) to 64 (a cap of a cell or more), so that suns, the common light, cost an
 *   eighth of the widest lights.
 * - SkyTransfer(): a uniform sky through the open cells, less what the lights cover:
 *   cosine-weighted (1/π)(Σ_open ∫_cell n·ω dω − the lights' cosine integrals), 1 for an open
 *   plane, or the open fraction (open cells / B − the lights' solid angle / 2π). The sums over
 *   the open cells do not depend on the lights (OpenSums()): shaders get them per point.
 * - EnvironmentSkyTransfer(): an HDR environment through the open cells, each cell taking the
 *   environment's mean radiance over a cap of its size about its middle direction.
 *
 * @sa vtkAperturePrecompute vtkHorizonLighting vtkSphericalCap
 */

#ifndef vtkVisibilityMask_h
#define vtkVisibilityMask_h

#include "vtkApertureLightingCoreModule.h" // For export macro
#include "vtkObject.h"
#include "vtkWrappingHints.h" // For VTK_WRAPEXCLUDE

#include <string> // For std::string
#include <vector> // For std::vector

class vtkDataArray;

class VTKAPERTURELIGHTINGCORE_EXPORT vtkVisibilityMask : public vtkObject
{
public:
  static vtkVisibilityMask* New();
  vtkTypeMacro(vtkVisibilityMask, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Whether `bits` is a cell count a mask can have; its grid's side (0 when it cannot).
   */
  static bool IsValidBitCount(int bits);
  static int GetSide(int bits);

  /**
   * Duff et al.'s tangent frame of a unit normal: n, t and b orthonormal, t × b = n.
   */
  static void Frame(const double n[3], double t[3], double b[3]);

  /**
   * The cell of unit direction `w` around unit normal `n` on a side × side grid, or −1 below the
   * tangent plane.
   */
  static int CellOf(const double n[3], const double w[3], int side);

  /**
   * The direction at square coordinates (u, v) ∈ [0, 1]² of the grid (cell i covers
   * u ∈ [i/side, (i + 1)/side)) around unit normal `n`.
   */
  static void Direction(const double n[3], double u, double v, double w[3]);

  /**
   * The directions a mask's rays take around unit normal `n`: raysSide² per cell on a
   * stratified sub-grid of the cell, cell by cell (cell q / raysSide² for ray q), 3 floats each.
   */
  VTK_WRAPEXCLUDE static void CellRayDirections(
    const double n[3], int side, int raysSide, std::vector<float>& directions);

  /**
   * ∫ n·ω dω over cell `cell` of a side × side grid (the same for every normal).
   */
  static double CellCosine(int cell, int side);

  /**
   * Stratified directions of a light cap of radius rl (vtkSphericalCap::ClampLightRadius()) that
   * LightTransfer() sums on a mask of `bits` cells: 8 per eighth of a cell the cap covers, 8 to
   * 64.
   */
  static int LightSamples(double rl, int bits);

  /**
   * The GLSL declarations of the sample counts, which the GLSL twin
   * (vtkVisibilityMaskGLSL.glsl, in the rendering module) needs before its source.
   */
  static std::string GetGLSLConstants();

  /**
   * The open cells' solid angle (sums[0]) and ∫ n·ω dω over them (sums[1]) of a mask of `bits`
   * cells (the same for every normal); zeros for an unusable mask.
   */
  VTK_WRAPEXCLUDE static void OpenSums(const unsigned char* mask, int bits, double sums[2]);

  /**
   * Irradiance at a point with normal n and mask (bits/8 bytes) from a light of angular radius
   * rl (vtkSphericalCap::ClampLightRadius()) in direction l, for a light of intensity 1.
   * Optionally returns the light's solid angle in open cells above the tangent plane (coverage)
   * and its ∫ n·ω dω there (cosineCoverage), which the sky loses.
   */
  VTK_WRAPEXCLUDE static double LightTransfer(const double n[3], const unsigned char* mask,
    int bits, const double l[3], double rl, double* coverage = nullptr,
    double* cosineCoverage = nullptr);

  /**
   * The sky through the open cells, less the lights' coverage (their sums over the lights).
   */
  VTK_WRAPEXCLUDE static double SkyTransfer(const double n[3], const unsigned char* mask, int bits,
    double coverage, double cosineCoverage, bool cosineWeighted);

  /**
   * The angular radius of a cap of one cell's solid angle (2π/bits), over which
   * EnvironmentSkyTransfer()'s environment is averaged.
   */
  static double CellCapRadius(int bits);

  /**
   * An environment sky through the open cells (RGB, as reflected radiance with albedo 1):
   * (1/π) Σ_open L_c ∫_cell n·ω dω, L_c the environment's mean radiance over a cap about the
   * cell's middle direction, read from a table (vtkEnvironmentMap::NewMeanRadianceTable(),
   * columns × rows, sampled by vtkEnvironmentMap::SampleTable()) toward the middle turned into
   * the environment's frame by toEnvironment (row-major 3 × 3, from the normal's frame: a
   * rotation, uniform scales allowed); then scaled by the share of the open cells the lights
   * leave (of their cosine integral, or of their solid angle without cosineWeighted). An
   * environment of radiance 1 gives the cosine-weighted SkyTransfer(). Zeros for unusable input.
   */
  VTK_WRAPEXCLUDE static void EnvironmentSkyTransfer(const double n[3], const unsigned char* mask,
    int bits, const float* table, int columns, int rows, const double toEnvironment[9],
    double coverage, double cosineCoverage, bool cosineWeighted, double rgb[3]);

  ///@{
  /**
   * The same for point `point` of a `VisibilityMask` array (bits/8 components), for scripts and
   * evaluations; 0 for an unusable array or point.
   */
  static double LightTransfer(
    vtkDataArray* mask, vtkIdType point, const double n[3], const double l[3], double rl);
  static double SkyTransfer(
    vtkDataArray* mask, vtkIdType point, const double n[3], bool cosineWeighted);
  ///@}

protected:
  vtkVisibilityMask() = default;
  ~vtkVisibilityMask() override = default;

private:
  vtkVisibilityMask(const vtkVisibilityMask&) = delete;
  void operator=(const vtkVisibilityMask&) = delete;
};

#endif
