/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkHorizonLighting.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkHorizonLighting
 * @brief   lights and sky seen above a point's horizons, shared by the precompute's users,
 *          the shaders and the tests
 *
 * One cap per point cannot hold what a point of a terrain sees under a low sun (a ridge to the
 * west, open sky to the east). vtkAperturePrecompute keeps the horizon of each azimuth sector
 * when asked (`HorizonAngles`); this class shades from them.
 *
 * Convention (the precompute's, the GeoTIFF bands' and the shaders'): a frame with x and y along
 * the height field's grid axes i and j and z up; S sectors, sector k covering the azimuths
 * [2πk/S, 2π(k+1)/S) measured from +x toward +y (counter-clockwise from east on a north-up
 * DEM); h_k the elevation (radians above the horizontal plane, in [−π/2, π/2]) of the highest
 * sample seen along the sector's middle direction φ_k = 2π(k + 1/2)/S; −π/2 where nothing is
 * in range. Between sector middles the horizon is interpolated linearly in azimuth (HorizonAt()).
 *
 * - LightTransfer(): the irradiance from a light cap of angular radius rl, normalised as
 *   vtkSphericalCap::LightTransfer() is (1 for an unoccluded light at normal incidence): the
 *   light's radiance 1/(π sin²rl) times ∫ max(0, n·ω) dω over the part of the cap above both the
 *   interpolated horizon and the tangent plane. Per azimuth φ the cap covers an interval of
 *   elevations, found in closed form, and the cosine integral over elevations is closed form
 *   too; azimuths are summed over LightSamples() points spread as x = cos θ (θ evenly spaced),
 *   which integrates the cap's √(1 − x²) profile exactly, so that wide lights cross several
 *   sectors and a tiny sun is still resolved. A light fully above every horizon and the tangent
 *   plane takes the closed form max(0, n·l).
 * - SkyTransfer(): a uniform sky through the sectors' open wedges above max(h_k, tangent plane)
 *   (exact per sector, as the sweep integrates its apertures), less what the lights cover:
 *   cosine-weighted, (1/π)(∫ n·ω dω − the lights' cosine integrals), 1 for an open plane; or
 *   as the visible fraction of the hemisphere, (Ω − the lights' solid angles)/2π.
 * - EnvironmentSkyTransfer(): an HDR environment through the same wedges, from a table of its
 *   radiance integrated over wedges (vtkEnvironmentMap::NewWedgeTable()).
 * - EncodeAngle() / DecodeAngle(): 8 bits per sector for the GPU. The code c stores
 *   t = sign(h) √(|h|/(π/2)) as c = round(127.5 (t + 1)), so steps are finest near the horizontal
 *   plane where low lights set: 0.0074 rad at 8°, 0.017 rad at 45°, 0.025 rad at the zenith.
 *
 * The GLSL twin (vtkHorizonLightingGLSL.glsl, in the rendering module) declares the same
 * functions as horizonLighting...(); a test evaluates both on the same inputs. All functions
 * take non-unit directions; a NaN or zero-length direction, or no sectors, gives 0.
 *
 * @sa vtkSphericalCap vtkAperturePrecompute
 */

#ifndef vtkHorizonLighting_h
#define vtkHorizonLighting_h

#include "vtkApertureLightingCoreModule.h" // For export macro
#include "vtkObject.h"
#include "vtkWrappingHints.h" // For VTK_WRAPEXCLUDE

#include <string> // For std::string

class vtkDataArray;

class VTKAPERTURELIGHTINGCORE_EXPORT vtkHorizonLighting : public vtkObject
{
public:
  static vtkHorizonLighting* New();
  vtkTypeMacro(vtkHorizonLighting, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The 8-bit code of a horizon angle (NaN encodes as π/2, closed) and back.
   */
  static int EncodeAngle(double h);
  static double DecodeAngle(int code);
  ///@}

  /**
   * The horizon at an azimuth, linear between sector middles (around the circle).
   */
  VTK_WRAPEXCLUDE static double HorizonAt(const float* horizons, int sectors, double azimuth);

  /**
   * The middle azimuth of sector k of `sectors` in degrees counter-clockwise from the grid's i
   * axis, in [0, 360), with sector 0 starting at `rotation` degrees (vtkAperturePrecompute's
   * SectorRotation; the shading here expects 0). vtkAperturePrecompute names the components of
   * `HorizonAngles` "Az" and this.
   */
  static double SectorAzimuth(int k, int sectors, double rotation = 0.0);

  /**
   * Azimuth samples of LightTransfer() for a light whose cap spans an interval of azimuths, and
   * for one around the zenith or nadir (all azimuths).
   */
  static int LightSamples() { return 8; }
  static int PolarLightSamples() { return 16; }

  /**
   * The GLSL declarations of the sample counts, which the GLSL twin needs before its source.
   */
  static std::string GetGLSLConstants();

  /**
   * Irradiance at a point with normal n and horizons from a light of angular radius rl
   * (vtkSphericalCap::ClampLightRadius()) in direction l, for a light of intensity 1. Optionally
   * returns the solid angle of the light above the horizons (coverage, which dims the specular
   * highlight) and the light's ∫ max(0, n·ω) dω there (cosineCoverage), which the sky loses.
   */
  VTK_WRAPEXCLUDE static double LightTransfer(const double n[3], const float* horizons, int sectors,
    const double l[3], double rl, double* coverage = nullptr, double* cosineCoverage = nullptr);

  /**
   * The sky through the open wedges, less the lights' coverage (their sums over the lights).
   */
  VTK_WRAPEXCLUDE static double SkyTransfer(const double n[3], const float* horizons, int sectors,
    double coverage, double cosineCoverage, bool cosineWeighted);

  /**
   * An environment sky through the open wedges (RGB, as reflected radiance with albedo 1):
   * (1/π) Σ_k n·W_k, W_k = ∫ L(ω) ω dω over sector k's wedge above its floor (as SkyTransfer()
   * has it), read from a wedge table in the horizons' frame (vtkEnvironmentMap::NewWedgeTable(),
   * `azimuths` + 1 columns × `elevations` rows × 3 axes of RGB, bilinear) as the difference of
   * the sector's two bounding azimuths; then scaled by the share of the open wedges the lights
   * leave (of their cosine integral, or of their solid angle without cosineWeighted). An
   * environment of radiance 1 gives the cosine-weighted SkyTransfer() (to the table's
   * quadrature). Zeros for unusable input.
   */
  VTK_WRAPEXCLUDE static void EnvironmentSkyTransfer(const double n[3], const float* horizons,
    int sectors, const float* table, int azimuths, int elevations, double coverage,
    double cosineCoverage, bool cosineWeighted, double rgb[3]);

  /**
   * The share of the open wedges the lights leave: 1 − their cosine integrals over the wedges'
   * (or their solid angles over the wedges' without cosineWeighted), in [0, 1]; 0 where nothing
   * is open or for unusable input. EnvironmentSkyTransfer() scales by it, and so do the shaders
   * that take an environment sky computed without the lights.
   */
  VTK_WRAPEXCLUDE static double OpenShare(const double n[3], const float* horizons, int sectors,
    double coverage, double cosineCoverage, bool cosineWeighted);

  /**
   * The open wedges' solid angle (sums[0]) and ∫ n·ω dω over them (sums[1]), which do not
   * depend on the lights (the mappers pack them per vertex); zeros for unusable input.
   */
  VTK_WRAPEXCLUDE static void OpenSums(
    const double n[3], const float* horizons, int sectors, double sums[2]);

  ///@{
  /**
   * The same for point `point` of a `HorizonAngles` array (one component per sector), for
   * scripts and evaluations. quantized uses the angles as the GPU gets them (8 bits).
   */
  static double LightTransfer(vtkDataArray* horizons, vtkIdType point, const double n[3],
    const double l[3], double rl, bool quantized);
  static double SkyTransfer(
    vtkDataArray* horizons, vtkIdType point, const double n[3], bool cosineWeighted);
  ///@}

protected:
  vtkHorizonLighting() = default;
  ~vtkHorizonLighting() override = default;

private:
  vtkHorizonLighting(const vtkHorizonLighting&) = delete;
  void operator=(const vtkHorizonLighting&) = delete;
};

#endif
