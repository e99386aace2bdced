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
 * same functions for shaders, named sphericalCapIntersectionArea() and so on; a test evaluates
 * them on the GPU and compares them with this class.
 */

#ifndef vtkSphericalCap_h
#define vtkSphericalCap_h

#include "vtkApertureLightingModule.h" // For export macro
#include "vtkObject.h"

class VTKAPERTURELIGHTING_EXPORT vtkSphericalCap : public vtkObject
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
   * and sets c = 0 when the intersection is empty.
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

protected:
  vtkSphericalCap() = default;
  ~vtkSphericalCap() override = default;

private:
  vtkSphericalCap(const vtkSphericalCap&) = delete;
  void operator=(const vtkSphericalCap&) = delete;
};

#endif
