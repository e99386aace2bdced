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
#include <iomanip>
#include <limits>
#include <locale>
#include <sstream>

vtkStandardNewMacro(vtkSphericalCap);

// Defined here too for C++11/14, where std::min and std::max taking it by reference need a
// definition.
constexpr double vtkSphericalCap::MinimumLightRadius;
constexpr double vtkSphericalCap::CentroidTolerance;
constexpr double vtkSphericalCap::MaximumLightRadius;

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

// A cap ready for the shading equations: unit axis, radius, and the sine and cosine of half the
// radius, from which the addition formulas give every other angle without trigonometry.
struct Cap
{
  double Axis[3];
  double Radius, HalfSin, HalfCos;

  Cap(const double axis[3], double r)
    : Radius(r)
    , HalfSin(std::sin(0.5 * r))
  {
    std::copy(axis, axis + 3, this->Axis);
    this->HalfCos = std::sqrt(std::max(0.0, 1.0 - this->HalfSin * this->HalfSin));
  }
};

// The spherical triangle (a1, a2, P), P where the two boundary circles cross, for caps c1, c2
// whose axes are d apart, given the half chord hc = sin(d/2) and half sum hs = cos(d/2): the
// angles φ1 at a1 and φ2 at a2 (half-angle formulas keep thin triangles accurate), their sines
// (algebraic, from the half-angle tangents) and the spherical excess, from the smaller radius r,
// d and the angle φ between them: tan(E/2) = tan(r/2) tan(d/2) sin φ / (1 + tan(r/2) tan(d/2)
// cos φ). The sines of the half-perimeter s and of s − r1, s − r2, s − d come from the half-angle
// sines and cosines by the addition formulas, the larger radius meeting d/2 first: with a small cap
// on the other's rim, that difference is what is left when the small radius is added back.
struct LensTriangle
{
  double Phi1, Phi2, SinPhi1, SinPhi2, Excess;

  LensTriangle(const Cap& c1, const Cap& c2, double hc, double hs)
  {
    const bool firstBig = c1.Radius >= c2.Radius;
    const Cap& big = firstBig ? c1 : c2;
    const Cap& small = firstBig ? c2 : c1;
    // e = d/2 − rBig/2, f = d/2 + rBig/2, g = (rBig − rSmall)/2.
    const double sinE = hc * big.HalfCos - hs * big.HalfSin;
    const double cosE = hs * big.HalfCos + hc * big.HalfSin;
    const double sinF = hc * big.HalfCos + hs * big.HalfSin;
    const double cosF = hs * big.HalfCos - hc * big.HalfSin;
    const double sinG = big.HalfSin * small.HalfCos - big.HalfCos * small.HalfSin;
    const double cosG = big.HalfCos * small.HalfCos + big.HalfSin * small.HalfSin;
    const double sinSmall = std::max(0.0, small.HalfSin * cosE + small.HalfCos * sinE);
    const double sinDiff = std::max(0.0, small.HalfSin * cosE - small.HalfCos * sinE);
    const double sinBig = std::max(0.0, hc * cosG + hs * sinG);
    const double sinS = std::max(0.0, small.HalfSin * cosF + small.HalfCos * sinF);
    const double sin1 = firstBig ? sinSmall : sinBig;
    const double sin2 = firstBig ? sinBig : sinSmall;
    const double y1 = std::sqrt(sin1 * sinDiff);
    const double x1 = std::sqrt(sinS * sin2);
    const double y2 = std::sqrt(sin2 * sinDiff);
    const double x2 = std::sqrt(sinS * sin1);
    this->Phi1 = 2.0 * std::atan2(y1, x1);
    this->Phi2 = 2.0 * std::atan2(y2, x2);
    const double n1 = x1 * x1 + y1 * y1;
    const double n2 = x2 * x2 + y2 * y2;
    this->SinPhi1 = n1 > 0.0 ? 2.0 * x1 * y1 / n1 : 0.0;
    this->SinPhi2 = n2 > 0.0 ? 2.0 * x2 * y2 / n2 : 0.0;
    // The excess from the smaller cap's side: tan(r/2) of the larger one may be huge.
    const double xs = firstBig ? x2 : x1;
    const double ys = firstBig ? y2 : y1;
    const double ns = xs * xs + ys * ys;
    const double sinPhi = firstBig ? this->SinPhi2 : this->SinPhi1;
    const double cosPhi = ns > 0.0 ? (xs * xs - ys * ys) / ns : 1.0;
    const double t = small.HalfSin / small.HalfCos * (hc / hs);
    this->Excess = 2.0 * std::atan2(t * sinPhi, 1.0 + t * cosPhi);
  }
};

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

// How caps of radii r1, r2 with axes d apart meet.
enum class LensCase
{
  Disjoint,
  Nested,      // one inside the other
  Complements, // the complements are disjoint: the union is the sphere
  Crossing
};

LensCase Classify(double r1, double r2, double d)
{
  const double rMin = std::min(r1, r2);
  if (rMin <= 0.0 || d >= r1 + r2)
  {
    return LensCase::Disjoint;
  }
  if (d <= std::max(r1, r2) - rMin)
  {
    return LensCase::Nested;
  }
  return r1 + r2 + d >= 2.0 * Pi ? LensCase::Complements : LensCase::Crossing;
}

// Area and first moment of the intersection of caps c1 and c2 (radii clamped, not NaN), which
// meet as lensCase, their unit axes d apart with half chord hc = sin(d/2) and half sum
// hs = cos(d/2).
double Lens(LensCase lensCase, const Cap& c1, const Cap& c2, double hc, double hs, double m[3])
{
  m[0] = m[1] = m[2] = 0.0;
  if (lensCase == LensCase::Disjoint)
  {
    return 0.0;
  }
  const double h1 = c1.HalfSin, h2 = c2.HalfSin;
  const double s1 = 2.0 * h1 * c1.HalfCos; // sin r
  const double s2 = 2.0 * h2 * c2.HalfCos;
  const double* u1 = c1.Axis;
  const double* u2 = c2.Axis;
  if (lensCase == LensCase::Nested)
  {
    // The moment of a cap (a, r) is π sin²r a.
    const bool first = c1.Radius <= c2.Radius;
    const double s = first ? s1 : s2;
    const double h = first ? h1 : h2;
    for (int i = 0; i < 3; ++i)
    {
      m[i] = Pi * s * s * (first ? u1[i] : u2[i]);
    }
    return 4.0 * Pi * h * h;
  }
  if (lensCase == LensCase::Complements)
  {
    // Whole sphere (moment 0) minus the two disjoint complements.
    for (int i = 0; i < 3; ++i)
    {
      m[i] = Pi * (s1 * s1 * u1[i] + s2 * s2 * u2[i]);
    }
    return std::max(0.0, 4.0 * Pi * (h1 * h1 + h2 * h2 - 1.0));
  }
  // Tovchigrechko & Vakser: A = 2[π − ψ − φ1 cos r1 − φ2 cos r2], rearranged as two sectors minus
  // the quadrilateral (a1, P, a2, P'), i.e. 4 φk sin²(rk/2) − 2 E, which avoids cancellation.
  const LensTriangle t(c1, c2, hc, hs);
  const double area =
    std::min(std::max(4.0 * (t.Phi1 * h1 * h1 + t.Phi2 * h2 * h2) - 2.0 * t.Excess, 0.0),
      4.0 * Pi * std::min(h1 * h1, h2 * h2));
  // M = Σk sin²rk φk uk − sin rk cos rk sin φk tk, with tk the unit tangent at uk toward the other
  // axis: t1 = (δ + k u1)/sin d and t2 = (−δ + k u2)/sin d, δ = u2 − u1, k = 1 − cos d. Grouping
  // the δ terms keeps nearby small caps accurate, and coincident axes need no special case.
  const double w1 = s1 * (1.0 - 2.0 * h1 * h1) * t.SinPhi1;
  const double w2 = s2 * (1.0 - 2.0 * h2 * h2) * t.SinPhi2;
  const double sinD = 2.0 * hc * hs;
  const double deltaScale = sinD > 0.0 ? (w1 - w2) / sinD : 0.0;
  for (int i = 0; i < 3; ++i)
  {
    const double tangents = (hc / hs) * (w1 * u1[i] + w2 * u2[i]) + deltaScale * (u2[i] - u1[i]);
    m[i] = s1 * s1 * t.Phi1 * u1[i] + s2 * s2 * t.Phi2 * u2[i] - tangents;
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
  // The lens's area does not depend on where its axes are.
  const double u1[3] = { 0.0, 0.0, 1.0 };
  const double u2[3] = { std::sin(d), 0.0, std::cos(d) };
  double m[3];
  return Lens(
    Classify(r1, r2, d), Cap(u1, r1), Cap(u2, r2), std::sin(0.5 * d), std::cos(0.5 * d), m);
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
  if (std::isnan(r1) || std::isnan(r2) || !vtkSphericalCap::UnitAxis(a1, u1) ||
    !vtkSphericalCap::UnitAxis(a2, u2))
  {
    return;
  }
  double difference[3], sum[3];
  vtkMath::Subtract(u1, u2, difference);
  vtkMath::Add(u1, u2, sum);
  const double hc = 0.5 * vtkMath::Norm(difference);
  const double hs = 0.5 * vtkMath::Norm(sum);
  Lens(Classify(r1, r2, 2.0 * std::atan2(hc, hs)), Cap(u1, r1), Cap(u2, r2), hc, hs, m);
}

//------------------------------------------------------------------------------
bool vtkSphericalCap::IntersectionCentroid(
  const double a1[3], double r1, const double a2[3], double r2, double c[3])
{
  vtkSphericalCap::IntersectionMoment(a1, r1, a2, r2, c);
  const double n = vtkMath::Norm(c);
  const double scale = std::min(SolidAngleFromCapRadius(r1), SolidAngleFromCapRadius(r2));
  if (!(n > CentroidTolerance * scale))
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
// The middle of the overlap of crossing caps, light and aperture, along the great circle through
// their axes, which are d apart with half chord hc and half sum hs: a cheap stand-in for the lens
// centroid. Crossing caps overlap from d − rp to rl along the circle, measured from the light's
// axis; the middle, t = d/2 − rp/2 + rl/2, comes from the half-angle sines by the addition
// formulas.
void OverlapMiddle(const Cap& light, const Cap& aperture, double hc, double hs, double c[3])
{
  const double* l = light.Axis;
  const double sinD = 2.0 * hc * hs;
  if (!(sinD > 1e-6))
  {
    std::copy(l, l + 3, c);
    return;
  }
  const double sinX = hc * aperture.HalfCos - hs * aperture.HalfSin; // x = d/2 − rp/2
  const double cosX = hs * aperture.HalfCos + hc * aperture.HalfSin;
  const double sinT = sinX * light.HalfCos + cosX * light.HalfSin;
  const double cosT = cosX * light.HalfCos - sinX * light.HalfSin;
  const double cosD = 1.0 - 2.0 * hc * hc;
  for (int i = 0; i < 3; ++i)
  {
    // Rotate l toward the aperture's axis by t.
    c[i] = cosT * l[i] + sinT * (aperture.Axis[i] - cosD * l[i]) / sinD;
  }
}

// LightTransfer() and LightCoverage() together, for a unit (or zero) normal un and caps whose
// radii are clamped (rp <= π/2, MinimumLightRadius <= rl <= π/2), as the GLSL twin computes them:
// everything derives from the half-angle sines and cosines of the two radii and the half chord
// between the axes, sin(d/2), which also classifies the caps (cosines near 1 cannot tell nearly
// equal small caps apart), and only crossing caps, the penumbra, need angles at all.
double Shade(int shading, int lambert, const double un[3], const Cap& aperture, const Cap& light,
  double& coverage)
{
  coverage = 0.0;
  const double* ub = aperture.Axis;
  const double* ul = light.Axis;
  const double hp = aperture.HalfSin, cp = aperture.HalfCos;
  const double hl = light.HalfSin, cl = light.HalfCos;
  const double areaP = 4.0 * Pi * hp * hp;
  const double areaL = 4.0 * Pi * hl * hl;
  if (shading == vtkSphericalCap::BENT_NORMAL)
  {
    const double open = 2.0 * hp * hp;
    coverage = open * areaL;
    return open * std::max(0.0, vtkMath::Dot(ub, ul));
  }

  // sin((rp + rl)/2) and sin(|rp − rl|/2) by the addition formulas.
  double difference[3], sum[3];
  vtkMath::Subtract(ub, ul, difference);
  vtkMath::Add(ub, ul, sum);
  const double halfChord = 0.5 * vtkMath::Norm(difference);
  const double halfSum = 0.5 * vtkMath::Norm(sum);
  const double sinHalfSum = hp * cl + cp * hl;
  const bool disjoint = aperture.Radius <= 0.0 || halfChord >= sinHalfSum;
  const bool nested = !disjoint && halfChord <= std::abs(hp * cl - cp * hl);
  if (shading == vtkSphericalCap::SIMPLIFIED)
  {
    // The ramp of SimplifiedShadowFactor(): sin((s + d)/2) sin((s − d)/2) over sin rp sin rl,
    // s = rp + rl, with sin(a + b) sin(a − b) = sin²a − sin²b.
    const double ramp =
      (sinHalfSum * sinHalfSum - halfChord * halfChord) / (4.0 * hp * cp * hl * cl);
    const double shadow = disjoint
      ? 0.0
      : std::min(1.0, areaP / areaL) * (nested ? 1.0 : std::min(std::max(ramp, 0.0), 1.0));
    coverage = shadow * std::min(areaL, areaP);
    return shadow * std::max(0.0, vtkMath::Dot(un, ul));
  }
  if (disjoint || (shading != vtkSphericalCap::EXACT && shading != vtkSphericalCap::SMOOTHSTEP))
  {
    return 0.0;
  }
  // 1/(π sin²rl), sin rl = 2 hl cl.
  const double radiance = 1.0 / (4.0 * Pi * hl * hl * cl * cl);
  if (nested)
  {
    // The smaller cap lies in the other: the lens is that cap, its centroid that cap's axis; its
    // moment is π sin²r times the axis.
    const bool lightInside = light.Radius <= aperture.Radius;
    const double h = lightInside ? hl : hp;
    const double c = lightInside ? cl : cp;
    coverage = lightInside ? areaL : areaP;
    const double factor = (shading == vtkSphericalCap::EXACT && lambert == vtkSphericalCap::MOMENT)
      ? 4.0 * Pi * h * h * c * c
      : coverage;
    return factor * std::max(0.0, vtkMath::Dot(un, lightInside ? ul : ub)) * radiance;
  }
  if (shading == vtkSphericalCap::EXACT)
  {
    double m[3];
    coverage = Lens(LensCase::Crossing, light, aperture, halfChord, halfSum, m);
    if (lambert == vtkSphericalCap::MOMENT)
    {
      return std::max(0.0, vtkMath::Dot(un, m)) * radiance;
    }
    const double length = vtkMath::Norm(m);
    return length > 0.0 ? coverage * std::max(0.0, vtkMath::Dot(un, m) / length) * radiance : 0.0;
  }
  const double d = 2.0 * std::atan2(halfChord, halfSum);
  const double rp = aperture.Radius, rl = light.Radius;
  const double x = 1.0 - (d - std::abs(rp - rl)) / (2.0 * std::min(rp, rl));
  const double t = std::min(std::max(x, 0.0), 1.0);
  coverage = std::min(areaP, areaL) * t * t * (3.0 - 2.0 * t);
  double c[3];
  OverlapMiddle(light, aperture, halfChord, halfSum, c);
  return coverage * std::max(0.0, vtkMath::Dot(un, c)) * radiance;
}

// Shade() for the public inputs: clamped radii (rp <= π/2, MinimumLightRadius <= rl <= π/2) and
// unit axes; 0 for NaN radii and unusable axes. An unusable normal gives no Lambert term
// (BENT_NORMAL does not use it).
double ShadeInputs(int shading, int lambert, const double n[3], const double bent[3], double rp,
  const double l[3], double rl, double& coverage)
{
  coverage = 0.0;
  rp = ClampAngle(rp);
  rl = ClampAngle(rl);
  double un[3], ub[3], ul[3];
  if (std::isnan(rp) || std::isnan(rl) || !vtkSphericalCap::UnitAxis(bent, ub) ||
    !vtkSphericalCap::UnitAxis(l, ul))
  {
    return 0.0;
  }
  if (!vtkSphericalCap::UnitAxis(n, un))
  {
    un[0] = un[1] = un[2] = 0.0;
  }
  const Cap aperture(ub, std::min(rp, 0.5 * Pi));
  const Cap light(ul, vtkSphericalCap::ClampLightRadius(rl));
  return Shade(shading, lambert, un, aperture, light, coverage);
}
}

//------------------------------------------------------------------------------
double vtkSphericalCap::LightTransfer(int shading, int lambert, const double n[3],
  const double bent[3], double rp, const double l[3], double rl)
{
  double coverage;
  return ShadeInputs(shading, lambert, n, bent, rp, l, rl, coverage);
}

//------------------------------------------------------------------------------
double vtkSphericalCap::LightCoverage(
  int shading, const double bent[3], double rp, const double l[3], double rl)
{
  double coverage;
  ShadeInputs(shading, CENTROID, bent, bent, rp, l, rl, coverage);
  return coverage;
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

//------------------------------------------------------------------------------
bool vtkSphericalCap::UnitAxis(const double v[3], double u[3])
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

//------------------------------------------------------------------------------
double vtkSphericalCap::ClampLightRadius(double radius)
{
  // Written so that NaN gets the smallest radius.
  return radius > MinimumLightRadius ? std::min(radius, MaximumLightRadius) : MinimumLightRadius;
}

//------------------------------------------------------------------------------
double vtkSphericalCap::LightRadiance(double rl)
{
  const double s = std::sin(ClampLightRadius(rl));
  return 1.0 / (Pi * s * s);
}

//------------------------------------------------------------------------------
std::string vtkSphericalCap::GetGLSLConstants()
{
  std::ostringstream glsl;
  glsl.imbue(std::locale::classic());
  // Floats with the digits that give GLSL back the very same float.
  glsl << std::scientific << std::setprecision(std::numeric_limits<float>::max_digits10 - 1);
  glsl << "// vtkSphericalCap's constants (vtkSphericalCap::GetGLSLConstants()).\n"
       << "const int sphericalCapExact = " << EXACT << ";\n"
       << "const int sphericalCapSmoothstep = " << SMOOTHSTEP << ";\n"
       << "const int sphericalCapSimplified = " << SIMPLIFIED << ";\n"
       << "const int sphericalCapBentNormal = " << BENT_NORMAL << ";\n"
       << "const int sphericalCapCentroid = " << CENTROID << ";\n"
       << "const int sphericalCapMoment = " << MOMENT << ";\n"
       << "const float sphericalCapMinimumLightRadius = " << static_cast<float>(MinimumLightRadius)
       << ";\n"
       << "const float sphericalCapMaximumLightRadius = " << static_cast<float>(MaximumLightRadius)
       << ";\n"
       << "const float sphericalCapCentroidTolerance = " << static_cast<float>(CentroidTolerance)
       << ";\n";
  return glsl.str();
}
