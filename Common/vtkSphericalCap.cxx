/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkSphericalCap.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkSphericalCap.h"

#include "vtkMath.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkSphericalCap);

namespace
{
constexpr double Pi = vtkMath::Pi();

// Clamps an angle to [0, π]. NaN passes through for the caller to test.
double ClampAngle(double a)
{
  return a < 0.0 ? 0.0 : (a > Pi ? Pi : a);
}

// 2π(1 − cos r), written so that it keeps its relative accuracy for small r.
double CapArea(double r)
{
  const double s = std::sin(0.5 * r);
  return 4.0 * Pi * s * s;
}

// Angles of the spherical triangle (a1, a2, P), P a crossing point of the two boundary circles:
// phi1 at a1, phi2 at a2, and the triangle's spherical excess. Half-angle formulas and
// L'Huilier's theorem keep them accurate for the thin triangles of small caps.
void LensTriangle(double r1, double r2, double d, double& phi1, double& phi2, double& excess)
{
  // The larger radius meets d first: with a small cap on the other's rim, (r1 + r2) − d would
  // round the small radius away and the angles would no longer match the axes.
  const double rBig = std::max(r1, r2);
  const double rSmall = std::min(r1, r2);
  const double e = d - rBig;
  const double sSmall = std::max(0.0, 0.5 * (rSmall + e));
  const double sBig = 0.5 * ((rBig - rSmall) + d);
  const double sd = std::max(0.0, 0.5 * (rSmall - e));
  const double s1 = r1 >= r2 ? sSmall : sBig;
  const double s2 = r1 >= r2 ? sBig : sSmall;
  const double s = 0.5 * (r1 + r2 + d);
  const double sinS = std::sin(s);
  phi1 = 2.0 * std::atan2(std::sqrt(std::sin(s1) * std::sin(sd)), std::sqrt(sinS * std::sin(s2)));
  phi2 = 2.0 * std::atan2(std::sqrt(std::sin(s2) * std::sin(sd)), std::sqrt(sinS * std::sin(s1)));
  const double t = std::tan(0.5 * s) * std::tan(0.5 * s1) * std::tan(0.5 * s2) * std::tan(0.5 * sd);
  excess = 4.0 * std::atan(std::sqrt(std::max(0.0, t)));
}

// (cos d − cos(rp + rl)) / (cos|rp − rl| − cos(rp + rl)), clamped to [0, 1], with the cosine
// differences written as sine products so that small caps keep their precision.
double SimplifiedRamp(double rp, double rl, double d)
{
  const double sum = rp + rl;
  if (sum >= Pi)
  {
    const double c = std::cos(0.5 * d) / std::cos(0.5 * (rp - rl));
    return std::min(1.0, std::max(0.0, c * c));
  }
  const double den = std::sin(std::max(rp, rl)) * std::sin(std::min(rp, rl));
  if (!(den > 0.0))
  {
    return d < rp ? 1.0 : 0.0;
  }
  return std::min(1.0, std::max(0.0, std::sin(0.5 * (d + sum)) * std::sin(0.5 * (sum - d)) / den));
}

// Normalises v into u; false for zero-length or non-finite vectors.
bool UnitAxis(const double v[3], double u[3])
{
  const double n = vtkMath::Norm(v);
  if (!(n > 0.0) || !std::isfinite(n))
  {
    return false;
  }
  for (int i = 0; i < 3; ++i)
  {
    u[i] = v[i] / n;
  }
  return true;
}

// Angle between unit vectors, accurate for nearly parallel and nearly opposite ones.
double AngleBetween(const double u[3], const double v[3])
{
  double diff[3], sum[3];
  vtkMath::Subtract(u, v, diff);
  vtkMath::Add(u, v, sum);
  return 2.0 * std::atan2(vtkMath::Norm(diff), vtkMath::Norm(sum));
}

// Solid angle of the intersection of caps of radii r1, r2 (clamped, not NaN) whose axes are d
// apart. When the boundary circles cross, also the triangle's angles (crossing = true).
double LensArea(double r1, double r2, double d, double& phi1, double& phi2, bool& crossing)
{
  crossing = false;
  const double rMin = std::min(r1, r2);
  const double rMax = std::max(r1, r2);
  if (rMin <= 0.0 || d >= r1 + r2)
  {
    return 0.0;
  }
  if (d <= rMax - rMin)
  {
    return CapArea(rMin);
  }
  if (r1 + r2 + d >= 2.0 * Pi)
  {
    // The complements are disjoint: the union is the whole sphere.
    return std::max(0.0, CapArea(r1) + CapArea(r2) - 4.0 * Pi);
  }
  // Tovchigrechko & Vakser: A = 2[π − ψ − φ1 cos r1 − φ2 cos r2], rearranged as two sectors minus
  // the quadrilateral (a1, P, a2, P'), i.e. 4 φk sin²(rk/2) − 2 E, which avoids cancellation.
  crossing = true;
  double excess;
  LensTriangle(r1, r2, d, phi1, phi2, excess);
  const double h1 = std::sin(0.5 * r1);
  const double h2 = std::sin(0.5 * r2);
  const double area = 4.0 * (phi1 * h1 * h1 + phi2 * h2 * h2) - 2.0 * excess;
  return std::min(std::max(area, 0.0), CapArea(rMin));
}

// Area and first moment of the intersection of caps (u1, r1) and (u2, r2), unit axes d apart,
// radii clamped and not NaN.
double Lens(const double u1[3], double r1, const double u2[3], double r2, double d, double m[3])
{
  m[0] = m[1] = m[2] = 0.0;
  double phi1 = 0.0, phi2 = 0.0;
  bool crossing;
  const double area = LensArea(r1, r2, d, phi1, phi2, crossing);
  if (area <= 0.0)
  {
    return 0.0;
  }
  const double s1 = std::sin(r1);
  const double s2 = std::sin(r2);
  if (!crossing && d <= std::abs(r1 - r2))
  {
    // The moment of a cap (a, r) is π sin²r a.
    const double* axis = r1 <= r2 ? u1 : u2;
    const double s = r1 <= r2 ? s1 : s2;
    for (int i = 0; i < 3; ++i)
    {
      m[i] = Pi * s * s * axis[i];
    }
    return area;
  }
  if (!crossing)
  {
    // Whole sphere (moment 0) minus the two disjoint complements.
    for (int i = 0; i < 3; ++i)
    {
      m[i] = Pi * (s1 * s1 * u1[i] + s2 * s2 * u2[i]);
    }
    return area;
  }
  // M = Σk sin²rk φk uk − sin rk cos rk sin φk tk, with tk the unit tangent at uk toward the other
  // axis: t1 = (δ + k u1)/sin d and t2 = (−δ + k u2)/sin d, δ = u2 − u1, k = 1 − cos d. Grouping
  // the δ terms keeps nearby small caps accurate, and coincident axes need no special case.
  const double w1 = s1 * std::cos(r1) * std::sin(phi1);
  const double w2 = s2 * std::cos(r2) * std::sin(phi2);
  const double sinD = std::sin(d);
  const double halfTan = std::tan(0.5 * d);
  const double deltaScale = sinD > 0.0 ? (w1 - w2) / sinD : 0.0;
  for (int i = 0; i < 3; ++i)
  {
    const double tangents = halfTan * (w1 * u1[i] + w2 * u2[i]) + deltaScale * (u2[i] - u1[i]);
    m[i] = s1 * s1 * phi1 * u1[i] + s2 * s2 * phi2 * u2[i] - tangents;
  }
  return area;
}
}

//------------------------------------------------------------------------------
double vtkSphericalCap::SolidAngleFromCapRadius(double r)
{
  r = ClampAngle(r);
  return std::isnan(r) ? 0.0 : CapArea(r);
}

//------------------------------------------------------------------------------
double vtkSphericalCap::CapRadiusFromSolidAngle(double solidAngle)
{
  if (!(solidAngle > 0.0))
  {
    return 0.0;
  }
  // acos(1 − A/2π) = 2 asin(sqrt(A/4π)), without the cancellation for small A.
  const double x = std::min(1.0, solidAngle / (4.0 * Pi));
  return 2.0 * std::atan2(std::sqrt(x), std::sqrt(1.0 - x));
}

//------------------------------------------------------------------------------
double vtkSphericalCap::IntersectionArea(double r1, double r2, double d)
{
  r1 = ClampAngle(r1);
  r2 = ClampAngle(r2);
  d = ClampAngle(d);
  if (std::isnan(r1) || std::isnan(r2) || std::isnan(d))
  {
    return 0.0;
  }
  double phi1, phi2;
  bool crossing;
  return LensArea(r1, r2, d, phi1, phi2, crossing);
}

//------------------------------------------------------------------------------
double vtkSphericalCap::IntersectionAreaSmoothstep(double r1, double r2, double d)
{
  r1 = ClampAngle(r1);
  r2 = ClampAngle(r2);
  d = ClampAngle(d);
  if (std::isnan(r1) || std::isnan(r2) || std::isnan(d))
  {
    return 0.0;
  }
  const double rMin = std::min(r1, r2);
  if (rMin <= 0.0)
  {
    return 0.0;
  }
  // r1 + r2 − |r1 − r2| = 2 min(r1, r2).
  const double x = 1.0 - (d - std::abs(r1 - r2)) / (2.0 * rMin);
  const double t = std::min(std::max(x, 0.0), 1.0);
  return CapArea(rMin) * t * t * (3.0 - 2.0 * t);
}

//------------------------------------------------------------------------------
void vtkSphericalCap::IntersectionMoment(
  const double a1[3], double r1, const double a2[3], double r2, double m[3])
{
  m[0] = m[1] = m[2] = 0.0;
  double u1[3], u2[3];
  r1 = ClampAngle(r1);
  r2 = ClampAngle(r2);
  if (std::isnan(r1) || std::isnan(r2) || !UnitAxis(a1, u1) || !UnitAxis(a2, u2))
  {
    return;
  }
  Lens(u1, r1, u2, r2, AngleBetween(u1, u2), m);
}

//------------------------------------------------------------------------------
bool vtkSphericalCap::IntersectionCentroid(
  const double a1[3], double r1, const double a2[3], double r2, double c[3])
{
  vtkSphericalCap::IntersectionMoment(a1, r1, a2, r2, c);
  const double n = vtkMath::Norm(c);
  if (!(n > 0.0))
  {
    c[0] = c[1] = c[2] = 0.0;
    return false;
  }
  for (int i = 0; i < 3; ++i)
  {
    c[i] /= n;
  }
  return true;
}

//------------------------------------------------------------------------------
double vtkSphericalCap::SphereLightIrradiance(double sigma, double theta)
{
  sigma = ClampAngle(sigma);
  theta = ClampAngle(theta);
  if (std::isnan(sigma) || std::isnan(theta) || sigma <= 0.0)
  {
    return 0.0;
  }
  sigma = std::min(sigma, 0.5 * Pi);
  const double sinSigma = std::sin(sigma);
  const double sin2Sigma = sinSigma * sinSigma;
  const double cosTheta = std::cos(theta);
  const double sinTheta = std::sin(theta);
  if (cosTheta * cosTheta > sin2Sigma || sinTheta <= 0.0)
  {
    // Entirely above or entirely below the horizon.
    return Pi * sin2Sigma * std::max(cosTheta, 0.0);
  }
  const double x = std::cos(sigma) / sinSigma;
  const double y = std::min(1.0, std::max(-1.0, -x * cosTheta / sinTheta));
  const double root = std::sqrt(1.0 - y * y);
  const double e =
    (cosTheta * std::acos(y) - x * sinTheta * root) * sin2Sigma + std::atan2(sinTheta * root, x);
  return std::max(e, 0.0);
}

//------------------------------------------------------------------------------
double vtkSphericalCap::SphereLightCapRadius(double radius, double distance)
{
  if (!(radius > 0.0) || std::isnan(distance))
  {
    return 0.0;
  }
  if (distance <= radius)
  {
    return 0.5 * Pi;
  }
  return std::atan2(radius, std::sqrt((distance - radius) * (distance + radius)));
}

//------------------------------------------------------------------------------
double vtkSphericalCap::SimplifiedShadowFactor(double rp, double rl, double d)
{
  rp = ClampAngle(rp);
  rl = ClampAngle(rl);
  d = ClampAngle(d);
  if (std::isnan(rp) || std::isnan(rl) || std::isnan(d) || rp <= 0.0)
  {
    return 0.0;
  }
  const double ramp = SimplifiedRamp(rp, rl, d);
  const double share = rl > 0.0 ? std::min(1.0, CapArea(rp) / CapArea(rl)) : 1.0;
  return ramp * share;
}

namespace
{
// The direction halfway along the overlap of caps (l, rl) and (bent, rp) on the great circle
// through their axes, d apart: a cheap stand-in for the lens centroid.
void OverlapMiddle(
  const double l[3], double rl, const double bent[3], double rp, double d, double c[3])
{
  const double sinD = std::sin(d);
  if (!(sinD > 1e-6))
  {
    std::copy(l, l + 3, c);
    return;
  }
  const double t = 0.5 * (std::max(-rl, d - rp) + std::min(rl, d + rp));
  const double cosT = std::cos(t);
  const double sinT = std::sin(t);
  const double cosD = std::cos(d);
  for (int i = 0; i < 3; ++i)
  {
    // Rotate l toward bent by t.
    c[i] = cosT * l[i] + sinT * (bent[i] - cosD * l[i]) / sinD;
  }
}

// Unit aperture and light axes, clamped radii (rp <= π/2, MinimumLightRadius <= rl <= π/2);
// false for NaN radii and unusable axes.
bool ShadingInputs(
  const double bent[3], double& rp, const double l[3], double& rl, double ub[3], double ul[3])
{
  rp = ClampAngle(rp);
  rl = ClampAngle(rl);
  if (std::isnan(rp) || std::isnan(rl) || !UnitAxis(bent, ub) || !UnitAxis(l, ul))
  {
    return false;
  }
  rp = std::min(rp, 0.5 * Pi);
  rl = std::min(std::max(rl, vtkSphericalCap::MinimumLightRadius), 0.5 * Pi);
  return true;
}
}

//------------------------------------------------------------------------------
double vtkSphericalCap::LightTransfer(int shading, int lambert, const double n[3],
  const double bent[3], double rp, const double l[3], double rl)
{
  double un[3] = { 0.0, 0.0, 0.0 }, ub[3], ul[3];
  if (!ShadingInputs(bent, rp, l, rl, ub, ul))
  {
    return 0.0;
  }
  if (!UnitAxis(n, un))
  {
    // No Lambert term without a normal (BENT_NORMAL does not use it).
    un[0] = un[1] = un[2] = 0.0;
  }
  const double d = AngleBetween(ub, ul);
  const double sinL = std::sin(rl);
  const double radiance = 1.0 / (Pi * sinL * sinL);
  switch (shading)
  {
    case EXACT:
    {
      double m[3];
      const double area = Lens(ul, rl, ub, rp, d, m);
      if (lambert == MOMENT)
      {
        return std::max(0.0, vtkMath::Dot(un, m)) * radiance;
      }
      const double length = vtkMath::Norm(m);
      return length > 0.0 ? area * std::max(0.0, vtkMath::Dot(un, m) / length) * radiance : 0.0;
    }
    case SMOOTHSTEP:
    {
      double c[3];
      OverlapMiddle(ul, rl, ub, rp, d, c);
      return vtkSphericalCap::IntersectionAreaSmoothstep(rl, rp, d) *
        std::max(0.0, vtkMath::Dot(un, c)) * radiance;
    }
    case SIMPLIFIED:
      return vtkSphericalCap::SimplifiedShadowFactor(rp, rl, d) *
        std::max(0.0, vtkMath::Dot(un, ul));
    case BENT_NORMAL:
      return CapArea(rp) / (2.0 * Pi) * std::max(0.0, vtkMath::Dot(ub, ul));
    default:
      return 0.0;
  }
}

//------------------------------------------------------------------------------
double vtkSphericalCap::LightCoverage(
  int shading, const double bent[3], double rp, const double l[3], double rl)
{
  double ub[3], ul[3];
  if (!ShadingInputs(bent, rp, l, rl, ub, ul))
  {
    return 0.0;
  }
  const double d = AngleBetween(ub, ul);
  switch (shading)
  {
    case EXACT:
      return vtkSphericalCap::IntersectionArea(rl, rp, d);
    case SMOOTHSTEP:
      return vtkSphericalCap::IntersectionAreaSmoothstep(rl, rp, d);
    case SIMPLIFIED:
      return vtkSphericalCap::SimplifiedShadowFactor(rp, rl, d) *
        std::min(CapArea(rl), CapArea(rp));
    case BENT_NORMAL:
      return CapArea(rp) / (2.0 * Pi) * CapArea(rl);
    default:
      return 0.0;
  }
}

//------------------------------------------------------------------------------
double vtkSphericalCap::SkyTransfer(
  double rp, double covered, double cosNormalBent, bool cosineWeighted)
{
  rp = std::min(ClampAngle(rp), 0.5 * Pi);
  if (std::isnan(rp) || std::isnan(covered) || std::isnan(cosNormalBent))
  {
    return 0.0;
  }
  const double open = std::max(0.0, CapArea(rp) - std::max(0.0, covered)) / (2.0 * Pi);
  return cosineWeighted ? open * std::min(1.0, std::max(0.0, cosNormalBent)) : open;
}

//------------------------------------------------------------------------------
void vtkSphericalCap::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
