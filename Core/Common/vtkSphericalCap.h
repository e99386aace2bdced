/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkSphericalCap.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkSphericalCap
 * @brief   spherical-cap geometry shared by the precompute, the shaders and the tests
 *
 * A spherical cap on the unit sphere is the set of directions within an angular radius r of an
 * axis; its solid angle is 2π(1 − cos r). Ambient aperture lighting (Oat & Sander 2007) stores
 * the visible part of each point's hemisphere as a cap (the aperture) and treats area lights as
 * caps too, so shading reduces to cap–cap intersections. This class holds that geometry as static
 * methods; all angles are in radians.
 *
 * - IntersectionArea(): exact solid angle of the intersection of two caps (Tovchigrechko & Vakser
 *   2001), written with half-angle formulas and L'Huilier's theorem so that it keeps its relative
 *   accuracy for sun-sized caps (r ≈ 0.005) in single precision too.
 * - IntersectionAreaSmoothstep(): the paper's smoothstep approximation of it.
 * - IntersectionMoment(): the first moment ∫ω dω of the intersection region. For a light of
 *   uniform radiance L seen through the aperture, entirely above the horizon of a normal n, the
 *   irradiance is exactly L (n · moment); IntersectionCentroid() is its direction, the paper's
 *   Lambert approximation.
 * - SphereLightIrradiance(): irradiance from a uniform sphere light clipped by the horizon
 *   (Snyder), in units of the light's radiance.
 * - SimplifiedShadowFactor(): the shadow factor of the 2006 demo variant.
 *
 * Input policy, shared with the GLSL twin: radii and distances are clamped to [0, π]; a NaN
 * argument gives an empty intersection (0, or a zero vector); a zero-length or non-finite axis
 * gives an empty intersection too. No method returns NaN or infinity.
 *
 * The GLSL twin (vtkSphericalCapGLSL.h, compiled in from vtkSphericalCapGLSL.glsl) declares the
 * same functions for shaders, named sphericalCapIntersectionArea() and so on, after the constants
 * of GetGLSLConstants(); a test evaluates them on the GPU and compares them with this class.
 */

#ifndef vtkSphericalCap_h
#define vtkSphericalCap_h

#include "vtkApertureLightingCoreModule.h" // For export macro
#include "vtkObject.h"

#include <string> // For std::string

class VTKAPERTURELIGHTINGCORE_EXPORT vtkSphericalCap : public vtkObject
{
public:
  static vtkSphericalCap* New();
  vtkTypeMacro(vtkSphericalCap, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Solid angle of a cap of angular radius r, 2π(1 − cos r), and its inverse
   * r = acos(1 − A/2π) (the paper's aperture radius). The solid angle is clamped to [0, 4π].
   */
  static double SolidAngleFromCapRadius(double r);
  static double CapRadiusFromSolidAngle(double solidAngle);
  ///@}

  /**
   * Exact solid angle of the intersection of two caps of radii r1 and r2 whose axes are d apart.
   * Disjoint caps give 0, a cap inside the other gives the smaller cap's solid angle, and the
   * result is continuous across these cases.
   */
  static double IntersectionArea(double r1, double r2, double d);

  /**
   * The paper's approximation of IntersectionArea():
   * 2π(1 − cos min(r1, r2)) · smoothstep(0, 1, 1 − (d − |r1 − r2|) / (r1 + r2 − |r1 − r2|)).
   * It is exact when the caps are disjoint or nested; in between its error reaches 16% of the
   * smaller cap's solid angle (equal small caps whose axes are 0.57 r apart).
   */
  static double IntersectionAreaSmoothstep(double r1, double r2, double d);

  /**
   * First moment m = ∫ω dω over the intersection of the cap (a1, r1) and the cap (a2, r2).
   * The axes need not be unit vectors. Empty intersections give m = 0.
   */
  static void IntersectionMoment(
    const double a1[3], double r1, const double a2[3], double r2, double m[3]);

  /**
   * Unit direction of IntersectionMoment(), the intersection's centroid direction. Returns false
   * and sets c = 0 when the intersection is empty or has no centroid: a moment under
   * CentroidTolerance times the smaller cap's solid angle is rounding (caps of equal radius on
   * opposite axes meet in a band whose moment vanishes; its direction would be noise).
   */
  static bool IntersectionCentroid(
    const double a1[3], double r1, const double a2[3], double r2, double c[3]);

  /**
   * Irradiance from a sphere light of uniform radiance 1 and angular radius sigma whose centre is
   * at angle theta from the normal, counting only the part above the horizon (Snyder's formula;
   * the same as n · IntersectionMoment() with the hemisphere around n). Fully above the horizon
   * this is π sin²(sigma) cos(theta).
   */
  static double SphereLightIrradiance(double sigma, double theta);

  /**
   * Angular radius asin(min(R/D, 1)) of a sphere of radius R whose centre is at distance D;
   * π/2 when the point is inside the sphere.
   */
  static double SphereLightCapRadius(double radius, double distance);

  /**
   * Shadow factor of the simplified variant (the 2006 demo): the light is compared with the
   * aperture through the dot product of their axes, cos d, instead of intersecting the caps.
   * The demo ramps from shadow to light as cos d passes the aperture size cos rp; here the ramp is
   * linear in cos d between the light touching the aperture from outside (d = rp + rl) and lying
   * inside it (d = |rp − rl|), so its width follows the light's size, and the result is scaled by
   * min(1, Ωp/Ωl) so that an aperture smaller than the light passes only its share:
   *
   *   S = min(1, Ωp/Ωl) · clamp((cos d − cos(rp + rl)) / (cos|rp − rl| − cos(rp + rl)), 0, 1)
   *
   * For a point light (rl = 0) this is a step at d = rp. A closed aperture (rp = 0) gives 0.
   */
  static double SimplifiedShadowFactor(double rp, double rl, double d);

  /**
   * Shading models of ambient aperture lighting (see LightTransfer()).
   */
  enum Shading
  {
    EXACT = 0,      ///< exact intersection area of the light and aperture caps
    SMOOTHSTEP = 1, ///< the paper's smoothstep approximation of that area
    SIMPLIFIED = 2, ///< the 2006 demo's shadow factor times n·l
    BENT_NORMAL = 3 ///< Lambert with the bent normal, scaled by the aperture's share of the sky
  };

  /**
   * Lambert factor of the EXACT model.
   */
  enum Lambert
  {
    CENTROID = 0, ///< the paper's: intersection area × max(0, n · centroid direction)
    MOMENT = 1    ///< exact for a light above the horizon: max(0, n · first moment)
  };

  ///@{
  /**
   * Smallest and largest light radius the shading functions use (rad): smaller lights are
   * treated as the smallest, and a light is at most a hemisphere (π/2).
   */
  static constexpr double MinimumLightRadius = 1e-4;
  static constexpr double MaximumLightRadius = 1.5707963267948966;
  ///@}

  /**
   * The moment, relative to the smaller cap's solid angle, under which IntersectionCentroid()
   * finds no centroid: well above single precision's rounding.
   */
  static constexpr double CentroidTolerance = 1e-5;

  /**
   * A light radius as the shading functions use it: within [MinimumLightRadius,
   * MaximumLightRadius]. The GLSL twin is sphericalCapClampLightRadius().
   */
  static double ClampLightRadius(double radius);

  /**
   * Normalises an axis into u; false (u untouched) for a zero-length or non-finite one, which
   * this class and vtkHorizonLighting and vtkVisibilityMask treat as no axis at all.
   */
  static bool UnitAxis(const double v[3], double u[3]);

  /**
   * Radiance of a light of angular radius rl (clamped by ClampLightRadius()) and intensity 1:
   * 1/(π sin²rl), so that the unoccluded light at normal incidence gives an irradiance of 1.
   * LightTransfer() and the references use it; the shaders compute the same from half angles.
   */
  static double LightRadiance(double rl);

  /**
   * The GLSL declarations of this class's constants, which the GLSL twin needs before its own
   * source: the Shading and Lambert values (sphericalCapExact, ..., sphericalCapMoment) and the
   * light-radius bounds (sphericalCapMinimumLightRadius, sphericalCapMaximumLightRadius). Shaders
   * get them from here so that they cannot drift from the C++.
   */
  static std::string GetGLSLConstants();

  /**
   * Irradiance at a point with normal n and aperture (bent, rp) from a light of angular radius
   * rl in direction l, for a light of intensity 1. The light's radiance is 1/(π sin²rl), so an
   * unoccluded light at normal incidence, fully above the horizon, gives 1, as a VTK light of
   * intensity 1 does; this is what keeps apertures and plain VTK lighting comparable.
   *
   * - EXACT, MOMENT: max(0, n · M)/(π sin²rl), M the lens moment; exact for a light fully
   *   above the horizon seen through a circular aperture.
   * - EXACT, CENTROID: A max(0, n · c)/(π sin²rl), A the lens area and c its centroid direction
   *   (the paper's Lambert approximation; for large lights it overestimates by up to
   *   2/(1 + cos rl)).
   * - SMOOTHSTEP: the smoothstep area times max(0, n · c')/(π sin²rl), where c' is the middle of
   *   the overlap of the two caps along the great circle through their axes (a cheap centroid).
   * - SIMPLIFIED: SimplifiedShadowFactor() × max(0, n · l).
   * - BENT_NORMAL: (Ωp/2π) max(0, bent · l), Ωp the aperture's solid angle (Landis 2002).
   *
   * Directions need not be unit vectors. A zero-length or non-finite aperture or light axis, or
   * a NaN radius, gives 0; so does an unusable normal, except for BENT_NORMAL, which does not use
   * it. Lights smaller than MinimumLightRadius are treated as that size.
   */
  static double LightTransfer(int shading, int lambert, const double n[3], const double bent[3],
    double rp, const double l[3], double rl);

  /**
   * Solid angle of the aperture that a light covers under a shading model: the lens area for
   * EXACT and SMOOTHSTEP, SimplifiedShadowFactor() × min(Ωl, Ωp) for SIMPLIFIED, and
   * (Ωp/2π) Ωl for BENT_NORMAL. Divided by Ωl it is the part of the light the point sees, which
   * also dims the light's specular highlight.
   */
  static double LightCoverage(
    int shading, const double bent[3], double rp, const double l[3], double rl);

  /**
   * The sky term of the paper (§3.3): the part of the aperture the lights do not cover,
   * max(0, Ωp − covered)/2π, optionally weighted by max(0, n · bent) (cosNormalBent). An open
   * aperture under no light gives 1, so a sky of radiance L·SkyColor adds L·SkyColor.
   */
  static double SkyTransfer(double rp, double covered, double cosNormalBent, bool cosineWeighted);

protected:
  vtkSphericalCap() = default;
  ~vtkSphericalCap() override = default;

private:
  vtkSphericalCap(const vtkSphericalCap&) = delete;
  void operator=(const vtkSphericalCap&) = delete;
};

#endif
