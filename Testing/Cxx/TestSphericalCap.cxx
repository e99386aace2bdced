/*=========================================================================

  Program:   ApertureLighting
  Module:    TestSphericalCap.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// Checks vtkSphericalCap against numerical integration on the sphere, over a dense grid of radii
// r1, r2 in (0, pi/2] and distances d in [0, pi], plus the edge cases and the bad-input policy.
// It also measures the smoothstep approximation's error envelope and prints it.

#include "vtkApertureTestHarness.h"
#include "vtkMath.h"
#include "vtkSphericalCap.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>
#include <vector>

namespace
{
constexpr double Pi = vtkMath::Pi();
using vtkApertureTest::Check;

// The harness's Check with the radii and distance of the case in its message.
void Check(bool ok, const char* what, double r1, double r2, double d, double got, double want)
{
  if (!ok)
  {
    std::ostringstream message;
    message << what << " r1=" << r1 << " r2=" << r2 << " d=" << d;
    vtkApertureTest::Check(ok, message.str(), got, want);
  }
}

// Composite Gauss-Legendre quadrature (16 nodes per panel) between break points, where the
// integrands below have square-root kinks. Each segment is mapped by t = lo + (hi - lo)(1 - cos
// u)/2, which makes those endpoint kinks smooth.
class Quadrature
{
public:
  Quadrature()
  {
    const int n = 16;
    for (int i = 0; i < n; ++i)
    {
      double x = std::cos(Pi * (i + 0.75) / (n + 0.5));
      double dp = 0.0;
      for (int it = 0; it < 100; ++it)
      {
        double p0 = 1.0, p1 = x;
        for (int k = 2; k <= n; ++k)
        {
          const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (x * p1 - p0) / (x * x - 1.0);
        const double dx = p1 / dp;
        x -= dx;
        if (std::abs(dx) < 1e-16)
        {
          break;
        }
      }
      this->Nodes.push_back(x);
      this->Weights.push_back(2.0 / ((1.0 - x * x) * dp * dp));
    }
  }

  template <typename F>
  void Integrate(
    F f, double a, double b, std::vector<double> breaks, int panels, int count, double* sums) const
  {
    breaks.push_back(a);
    breaks.push_back(b);
    std::sort(breaks.begin(), breaks.end());
    std::fill(sums, sums + count, 0.0);
    std::vector<double> values(count);
    for (size_t s = 0; s + 1 < breaks.size(); ++s)
    {
      const double lo = std::max(a, breaks[s]);
      const double hi = std::min(b, breaks[s + 1]);
      if (hi <= lo)
      {
        continue;
      }
      const int n = std::max(8, static_cast<int>(panels * (hi - lo) / (b - a)));
      const double h = Pi / n;
      for (int p = 0; p < n; ++p)
      {
        for (size_t q = 0; q < this->Nodes.size(); ++q)
        {
          const double u = h * (p + 0.5 * (this->Nodes[q] + 1.0));
          const double x = lo + 0.5 * (hi - lo) * (1.0 - std::cos(u));
          const double jacobian = 0.5 * (hi - lo) * std::sin(u);
          f(x, values.data());
          for (int c = 0; c < count; ++c)
          {
            sums[c] += 0.5 * h * this->Weights[q] * jacobian * values[c];
          }
        }
      }
    }
  }

private:
  std::vector<double> Nodes;
  std::vector<double> Weights;
};

const Quadrature GaussLegendre;

// Reference area and moment of cap (z, r1) intersected with cap (a2, r2), a2 at angle d from z in
// the xz-plane. Around z, the circle at polar angle t lies inside cap 2 for azimuths |phi| <= Phi
// with cos Phi = (cos r2 - cos t cos d) / (sin t sin d); integrating over t gives the area
// (2 Phi sin t), and the moment's z (2 Phi sin t cos t) and x (2 sin Phi sin^2 t) components.
void ReferenceLens(double r1, double r2, double d, double& area, double moment[3])
{
  auto f = [&](double t, double* v)
  {
    const double st = std::sin(t), ct = std::cos(t);
    const double den = st * std::sin(d);
    double phi;
    if (den <= 0.0)
    {
      phi = ct * std::cos(d) >= std::cos(r2) ? Pi : 0.0;
    }
    else
    {
      const double c = (std::cos(r2) - ct * std::cos(d)) / den;
      phi = std::acos(std::min(1.0, std::max(-1.0, c)));
    }
    v[0] = 2.0 * phi * st;
    v[1] = 2.0 * phi * st * ct;
    v[2] = 2.0 * std::sin(phi) * st * st;
  };
  double sums[3];
  GaussLegendre.Integrate(
    f, 0.0, r1, { std::abs(d - r2), d + r2, 2.0 * Pi - d - r2 }, 200, 3, sums);
  area = sums[0];
  moment[0] = sums[2];
  moment[1] = 0.0;
  moment[2] = sums[1];
}

// Reference irradiance of a sphere light of radius sigma at angle theta from the normal: around
// the light's centre, the azimuthal integral of max(n . w, 0) over a circle is analytic.
double ReferenceSphereLight(double sigma, double theta)
{
  auto f = [&](double t, double* v)
  {
    const double a = std::cos(t) * std::cos(theta);
    const double b = std::sin(t) * std::sin(theta);
    if (a >= b)
    {
      v[0] = 2.0 * Pi * a * std::sin(t);
    }
    else if (a <= -b)
    {
      v[0] = 0.0;
    }
    else
    {
      const double phi0 = std::acos(-a / b);
      v[0] = 2.0 * (a * phi0 + b * std::sin(phi0)) * std::sin(t);
    }
  };
  double e;
  GaussLegendre.Integrate(
    f, 0.0, sigma, { std::abs(0.5 * Pi - theta), theta - 0.5 * Pi }, 400, 1, &e);
  return e;
}

std::vector<double> RadiusGrid()
{
  std::vector<double> r = { 1e-3, 4.7e-3, 0.01, 0.064, 0.314, 0.785, 0.5 * Pi };
  for (int i = 1; i <= 16; ++i)
  {
    r.push_back(0.5 * Pi * i / 17.0);
  }
  return r;
}

std::vector<double> DistanceGrid(double r1, double r2)
{
  std::vector<double> d;
  for (int i = 0; i <= 48; ++i)
  {
    d.push_back(Pi * i / 48.0);
  }
  // Both sides of every case boundary.
  for (double edge : { r1 + r2, std::abs(r1 - r2) })
  {
    for (double eps : { -1e-7, 0.0, 1e-7, 1e-3 })
    {
      if (edge + eps >= 0.0 && edge + eps <= Pi)
      {
        d.push_back(edge + eps);
      }
    }
  }
  return d;
}

void TestAgainstIntegration()
{
  double worstArea = 0.0, worstRelativeSmall = 0.0, worstMoment = 0.0;
  double worstSmooth = 0.0, worstSmoothAt[3] = { 0, 0, 0 };
  size_t cases = 0;
  for (double r1 : RadiusGrid())
  {
    for (double r2 : RadiusGrid())
    {
      for (double d : DistanceGrid(r1, r2))
      {
        double area, moment[3];
        ReferenceLens(r1, r2, d, area, moment);
        const double got = vtkSphericalCap::IntersectionArea(r1, r2, d);
        const double err = std::abs(got - area);
        worstArea = std::max(worstArea, err);
        Check(err <= 1e-4, "area vs integration", r1, r2, d, got, area);

        // Relative to the smaller cap: the accuracy that matters for sun-sized lights.
        const double small = vtkSphericalCap::SolidAngleFromCapRadius(std::min(r1, r2));
        worstRelativeSmall = std::max(worstRelativeSmall, err / small);
        Check(
          err <= 1e-6 * small + 1e-12, "area relative to the smaller cap", r1, r2, d, got, area);

        const double a1[3] = { 0.0, 0.0, 1.0 };
        const double a2[3] = { std::sin(d), 0.0, std::cos(d) };
        double m[3];
        vtkSphericalCap::IntersectionMoment(a1, r1, a2, r2, m);
        const double merr = std::sqrt(vtkMath::Distance2BetweenPoints(m, moment));
        worstMoment = std::max(worstMoment, merr);
        Check(merr <= 1e-3, "moment vs integration", r1, r2, d, merr, 0.0);

        const double smooth = vtkSphericalCap::IntersectionAreaSmoothstep(r1, r2, d);
        const double serr = std::abs(smooth - got) / small;
        if (serr > worstSmooth)
        {
          worstSmooth = serr;
          worstSmoothAt[0] = r1;
          worstSmoothAt[1] = r2;
          worstSmoothAt[2] = d;
        }
        ++cases;
      }
    }
  }
  std::cout << "Exact area vs integration over " << cases << " cases: max error " << worstArea
            << " sr, max " << worstRelativeSmall << " of the smaller cap\n";
  std::cout << "Moment vs integration: max error " << worstMoment << "\n";
  std::cout << "Smoothstep error envelope (r1, r2 in (0, pi/2]): max " << 100.0 * worstSmooth
            << "% of the smaller cap, at r1=" << worstSmoothAt[0] << " r2=" << worstSmoothAt[1]
            << " d=" << worstSmoothAt[2] << "\n";
  // Equal small caps at d = 0.57 r are the worst case: 16.05% in the planar limit.
  Check(worstSmooth > 0.10 && worstSmooth < 0.1606, "smoothstep envelope (about 16%)", 0, 0, 0,
    worstSmooth, 0.1605);
}

// Caps larger than a hemisphere, including the case where their union covers the sphere.
void TestLargeCaps()
{
  const double radii[] = { 0.3, 1.2, 2.0, 2.6, 3.0 };
  double worst = 0.0;
  for (double r1 : radii)
  {
    for (double r2 : radii)
    {
      for (int i = 0; i <= 24; ++i)
      {
        const double d = Pi * i / 24.0;
        double area, moment[3];
        ReferenceLens(r1, r2, d, area, moment);
        const double got = vtkSphericalCap::IntersectionArea(r1, r2, d);
        worst = std::max(worst, std::abs(got - area));
        Check(std::abs(got - area) <= 1e-4, "large caps: area", r1, r2, d, got, area);
        const double a1[3] = { 0.0, 0.0, 1.0 };
        const double a2[3] = { std::sin(d), 0.0, std::cos(d) };
        double m[3];
        vtkSphericalCap::IntersectionMoment(a1, r1, a2, r2, m);
        Check(std::sqrt(vtkMath::Distance2BetweenPoints(m, moment)) <= 1e-3, "large caps: moment",
          r1, r2, d, m[0], moment[0]);
      }
    }
  }
  std::cout << "Caps up to r = 3.0: max area error " << worst << " sr\n";
}

void TestSphereLight()
{
  double worst = 0.0;
  for (double sigma : { 1e-3, 4.7e-3, 0.064, 0.314, 0.785, 1.2, 0.5 * Pi })
  {
    for (int i = 0; i <= 72; ++i)
    {
      const double theta = Pi * i / 72.0;
      const double scale = Pi * std::sin(sigma) * std::sin(sigma);
      const double ref = ReferenceSphereLight(sigma, theta);
      const double got = vtkSphericalCap::SphereLightIrradiance(sigma, theta);
      worst = std::max(worst, std::abs(got - ref) / scale);
      Check(std::abs(got - ref) <= 1e-3 * scale, "sphere light vs integration", sigma, 0, theta,
        got, ref);

      // Same quantity through the lens moment with the hemisphere around n.
      const double n[3] = { 0.0, 0.0, 1.0 };
      const double l[3] = { std::sin(theta), 0.0, std::cos(theta) };
      double m[3];
      vtkSphericalCap::IntersectionMoment(l, sigma, n, 0.5 * Pi, m);
      Check(std::abs(m[2] - got) <= 1e-6 * scale + 1e-12, "sphere light vs lens moment", sigma, 0,
        theta, m[2], got);
    }
  }
  std::cout << "Sphere light vs integration: max error " << worst << " of pi sin^2(sigma)\n";
}

// Brute-force check of the reference itself on a few cases: a Fibonacci lattice of directions.
void TestReferenceAgainstLattice()
{
  const int n = 2000000;
  const double cases[][3] = { { 0.5, 0.7, 0.9 }, { 1.2, 0.3, 1.3 }, { 0.8, 0.8, 0.05 } };
  for (const auto& c : cases)
  {
    const double a2[3] = { std::sin(c[2]), 0.0, std::cos(c[2]) };
    double area = 0.0, m[3] = { 0.0, 0.0, 0.0 };
    const double golden = Pi * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i)
    {
      const double z = 1.0 - (2.0 * i + 1.0) / n;
      const double rho = std::sqrt(1.0 - z * z);
      const double w[3] = { rho * std::cos(golden * i), rho * std::sin(golden * i), z };
      if (z >= std::cos(c[0]) && vtkMath::Dot(w, a2) >= std::cos(c[1]))
      {
        area += 1.0;
        vtkMath::Add(m, w, m);
      }
    }
    area *= 4.0 * Pi / n;
    vtkMath::MultiplyScalar(m, 4.0 * Pi / n);
    double refArea, refMoment[3];
    ReferenceLens(c[0], c[1], c[2], refArea, refMoment);
    Check(std::abs(area - refArea) <= 2e-4, "reference vs lattice: area", c[0], c[1], c[2], area,
      refArea);
    Check(std::sqrt(vtkMath::Distance2BetweenPoints(m, refMoment)) <= 2e-4,
      "reference vs lattice: moment", c[0], c[1], c[2], m[2], refMoment[2]);
  }
}

void TestEdgeCases()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();

  // Continuity across the case boundaries.
  for (double r1 : { 0.2, 0.9, 1.5 })
  {
    for (double r2 : { 0.1, 0.9, 1.4 })
    {
      for (double edge : { r1 + r2, std::abs(r1 - r2) })
      {
        const double below = vtkSphericalCap::IntersectionArea(r1, r2, edge - 1e-9);
        const double above = vtkSphericalCap::IntersectionArea(r1, r2, edge + 1e-9);
        Check(std::abs(below - above) <= 1e-6, "continuity at a case boundary", r1, r2, edge, below,
          above);
      }
    }
  }

  // d -> 0 and r -> 0 stay finite and right.
  const double tiny = 1e-300;
  Check(std::abs(vtkSphericalCap::IntersectionArea(0.7, 0.7, tiny) -
          vtkSphericalCap::SolidAngleFromCapRadius(0.7)) <= 1e-12,
    "equal caps, d -> 0", 0.7, 0.7, tiny, 0, 0);
  Check(std::abs(vtkSphericalCap::IntersectionArea(0.7, 0.7, 1e-9) -
          vtkSphericalCap::SolidAngleFromCapRadius(0.7)) <= 1e-8,
    "equal caps, d = 1e-9", 0.7, 0.7, 1e-9, 0, 0);
  Check(vtkSphericalCap::IntersectionArea(tiny, 0.5, 0.2) >= 0.0, "r -> 0", tiny, 0.5, 0.2, 0, 0);
  {
    const double a[3] = { 0.0, 0.0, 1.0 };
    const double b[3] = { 1e-10, 0.0, 1.0 };
    double m[3];
    vtkSphericalCap::IntersectionMoment(a, 0.6, b, 0.6, m);
    const double want = Pi * std::sin(0.6) * std::sin(0.6);
    Check(std::abs(m[2] - want) <= 1e-8 && std::abs(m[0]) <= 1e-8, "moment, coincident axes", 0.6,
      0.6, 1e-10, m[2], want);
  }

  // Round trip between cap radius and solid angle.
  for (double r : { 1e-6, 4.7e-3, 0.3, 1.0, 0.5 * Pi, 2.5, Pi })
  {
    const double back =
      vtkSphericalCap::CapRadiusFromSolidAngle(vtkSphericalCap::SolidAngleFromCapRadius(r));
    Check(std::abs(back - r) <= 1e-9 * std::max(1.0, r), "radius round trip", r, 0, 0, back, r);
  }
  Check(std::abs(vtkSphericalCap::SolidAngleFromCapRadius(0.5 * Pi) - 2.0 * Pi) < 1e-14,
    "hemisphere", 0.5 * Pi, 0, 0, vtkSphericalCap::SolidAngleFromCapRadius(0.5 * Pi), 2.0 * Pi);

  // Sphere light: small lights follow the cosine law; the horizon clips.
  Check(std::abs(vtkSphericalCap::SphereLightIrradiance(1e-4, 0.7) / (Pi * 1e-8) - std::cos(0.7)) <
      1e-6,
    "small sphere light, cosine law", 1e-4, 0, 0.7, 0, 0);
  Check(vtkSphericalCap::SphereLightIrradiance(0.3, 0.5 * Pi + 0.31) == 0.0,
    "sphere light below the horizon", 0.3, 0, 0.5 * Pi + 0.31, 0, 0);
  Check(std::abs(vtkSphericalCap::SphereLightIrradiance(0.5 * Pi, 0.0) - Pi) < 1e-12,
    "hemisphere light", 0.5 * Pi, 0, 0, vtkSphericalCap::SphereLightIrradiance(0.5 * Pi, 0.0), Pi);

  // Sphere light cap radius.
  Check(std::abs(vtkSphericalCap::SphereLightCapRadius(1.0, 2.0) - Pi / 6.0) < 1e-12,
    "sphere light cap radius", 1, 2, 0, 0, 0);
  Check(vtkSphericalCap::SphereLightCapRadius(1.0, 0.5) == 0.5 * Pi, "inside a sphere light", 1,
    0.5, 0, 0, 0);

  // Simplified shadow factor.
  Check(vtkSphericalCap::SimplifiedShadowFactor(0.8, 0.01, 0.5) == 1.0, "simplified: inside", 0.8,
    0.01, 0.5, 0, 1);
  Check(vtkSphericalCap::SimplifiedShadowFactor(0.8, 0.01, 0.9) == 0.0, "simplified: outside", 0.8,
    0.01, 0.9, 0, 0);
  Check(std::abs(vtkSphericalCap::SimplifiedShadowFactor(0.8, 0.01, 0.8) - 0.5) < 1e-2,
    "simplified: half-way", 0.8, 0.01, 0.8, 0, 0.5);
  Check(vtkSphericalCap::SimplifiedShadowFactor(0.8, 0.0, 0.79) == 1.0 &&
      vtkSphericalCap::SimplifiedShadowFactor(0.8, 0.0, 0.81) == 0.0,
    "simplified: point light step", 0.8, 0, 0.8, 0, 0);
  Check(vtkSphericalCap::SimplifiedShadowFactor(0.0, 0.1, 0.0) == 0.0,
    "simplified: closed aperture", 0, 0.1, 0, 0, 0);
  {
    const double share =
      vtkSphericalCap::SolidAngleFromCapRadius(0.1) / vtkSphericalCap::SolidAngleFromCapRadius(0.3);
    Check(std::abs(vtkSphericalCap::SimplifiedShadowFactor(0.1, 0.3, 0.0) - share) < 1e-12,
      "simplified: aperture smaller than the light", 0.1, 0.3, 0, 0, share);
  }
  double previous = 1.0;
  for (int i = 0; i <= 100; ++i)
  {
    const double s = vtkSphericalCap::SimplifiedShadowFactor(0.7, 0.2, Pi * i / 100.0);
    Check(s <= previous, "simplified: monotone in d", 0.7, 0.2, Pi * i / 100.0, s, previous);
    previous = s;
  }

  // Bad input: defined results, never NaN.
  struct Args
  {
    double r1, r2, d;
  };
  const Args bad[] = { { nan, 0.5, 0.3 }, { 0.5, nan, 0.3 }, { 0.5, 0.5, nan }, { -0.5, 0.5, 0.3 },
    { 0.5, -0.5, 0.3 }, { inf, 0.5, 0.3 }, { 0.5, 0.5, -inf }, { -inf, -inf, -inf } };
  for (const auto& a : bad)
  {
    for (double v : { vtkSphericalCap::IntersectionArea(a.r1, a.r2, a.d),
           vtkSphericalCap::IntersectionAreaSmoothstep(a.r1, a.r2, a.d),
           vtkSphericalCap::SimplifiedShadowFactor(a.r1, a.r2, a.d),
           vtkSphericalCap::SphereLightIrradiance(a.r1, a.d),
           vtkSphericalCap::SolidAngleFromCapRadius(a.r1),
           vtkSphericalCap::CapRadiusFromSolidAngle(a.r1) })
    {
      Check(std::isfinite(v) && v >= 0.0, "bad input gives a finite value", a.r1, a.r2, a.d, v, 0);
    }
  }
  Check(vtkSphericalCap::IntersectionArea(nan, 0.5, 0.3) == 0.0, "NaN radius: empty", nan, 0.5, 0.3,
    0, 0);
  Check(vtkSphericalCap::IntersectionArea(-0.5, 0.5, 0.0) == 0.0, "negative radius: empty", -0.5,
    0.5, 0, 0, 0);
  Check(vtkSphericalCap::IntersectionArea(0.5, 0.4, -1.0) ==
      vtkSphericalCap::IntersectionArea(0.5, 0.4, 0.0),
    "d < 0 clamps to 0", 0.5, 0.4, -1.0, 0, 0);
  Check(vtkSphericalCap::IntersectionArea(2.0, 2.0, 7.0) ==
      vtkSphericalCap::IntersectionArea(2.0, 2.0, Pi),
    "d > pi clamps to pi", 2, 2, 7, 0, 0);
  Check(vtkSphericalCap::IntersectionArea(5.0, 0.3, 1.0) ==
      vtkSphericalCap::SolidAngleFromCapRadius(0.3),
    "r > pi clamps to pi (the whole sphere)", 5, 0.3, 1, 0, 0);
  Check(
    vtkSphericalCap::CapRadiusFromSolidAngle(100.0) == Pi, "solid angle > 4 pi", 100, 0, 0, 0, 0);

  const double zero[3] = { 0.0, 0.0, 0.0 };
  const double up[3] = { 0.0, 0.0, 2.0 };
  const double nanAxis[3] = { nan, 0.0, 1.0 };
  const double infAxis[3] = { inf, 0.0, 1.0 };
  for (const double* axis : { zero, nanAxis, infAxis })
  {
    double m[3] = { 1.0, 1.0, 1.0 }, c[3] = { 1.0, 1.0, 1.0 };
    vtkSphericalCap::IntersectionMoment(axis, 0.5, up, 0.5, m);
    const bool found = vtkSphericalCap::IntersectionCentroid(up, 0.5, axis, 0.5, c);
    Check(m[0] == 0.0 && m[1] == 0.0 && m[2] == 0.0 && !found && c[0] == 0.0 && c[2] == 0.0,
      "bad axis: empty intersection", 0.5, 0.5, 0, m[2], 0);
  }
  {
    double m[3];
    vtkSphericalCap::IntersectionMoment(up, nan, up, 0.5, m);
    Check(
      m[0] == 0.0 && m[1] == 0.0 && m[2] == 0.0, "NaN radius: zero moment", nan, 0.5, 0, m[2], 0);
  }
  // Axes need not be unit vectors; the centroid of nested caps is the inner axis.
  {
    const double a[3] = { 0.0, 3.0, 0.0 };
    double c[3];
    const bool found = vtkSphericalCap::IntersectionCentroid(a, 0.2, up, 1.8, c);
    Check(found && std::abs(c[1] - 1.0) < 1e-12, "centroid of nested caps", 0.2, 1.8, 0, c[1], 1);
  }
  // Equal caps on opposite axes meet in a band about the equator: no centroid, whatever the
  // rounding of the axes (sin(pi) is not 0), while a band reaching further down has one, down.
  for (const double r : { 1.7, 2.0, 3.0 })
  {
    const double down[3] = { std::sin(Pi), 0.0, std::cos(Pi) };
    double c[3] = { 1.0, 1.0, 1.0 };
    const bool found = vtkSphericalCap::IntersectionCentroid(up, r, down, r, c);
    Check(
      !found && c[0] == 0.0 && c[1] == 0.0 && c[2] == 0.0, "band: no centroid", r, r, Pi, c[0], 0);
    const bool offCentre = vtkSphericalCap::IntersectionCentroid(up, r, down, r - 0.01, c);
    Check(offCentre && std::abs(c[2] + 1.0) < 1e-9, "off-centre band: centroid down", r, r - 0.01,
      Pi, c[2], -1);
  }
}

// The moment turns with the caps.
void TestRotation()
{
  vtkMath::RandomSeed(7);
  for (int i = 0; i < 200; ++i)
  {
    const double r1 = vtkMath::Random(0.01, 0.5 * Pi);
    const double r2 = vtkMath::Random(0.01, 0.5 * Pi);
    const double d = vtkMath::Random(0.0, Pi);
    const double a1[3] = { 0.0, 0.0, 1.0 };
    const double a2[3] = { std::sin(d), 0.0, std::cos(d) };
    double m[3];
    vtkSphericalCap::IntersectionMoment(a1, r1, a2, r2, m);

    double axis[3] = { vtkMath::Gaussian(), vtkMath::Gaussian(), vtkMath::Gaussian() };
    vtkMath::Normalize(axis);
    const double angle = vtkMath::Random(0.0, 2.0 * Pi);
    double q[4] = { std::cos(0.5 * angle), 0, 0, 0 };
    for (int k = 0; k < 3; ++k)
    {
      q[k + 1] = std::sin(0.5 * angle) * axis[k];
    }
    double rot[3][3];
    vtkMath::QuaternionToMatrix3x3(q, rot);
    double b1[3], b2[3], rm[3], mb[3];
    vtkMath::Multiply3x3(rot, a1, b1);
    vtkMath::Multiply3x3(rot, a2, b2);
    vtkMath::Multiply3x3(rot, m, rm);
    vtkSphericalCap::IntersectionMoment(b1, r1, b2, r2, mb);
    Check(std::sqrt(vtkMath::Distance2BetweenPoints(rm, mb)) < 1e-9, "moment is rotation-covariant",
      r1, r2, d, mb[0], rm[0]);
    // |m| cannot exceed the area, and is symmetric in the two caps.
    double swapped[3];
    vtkSphericalCap::IntersectionMoment(a2, r2, a1, r1, swapped);
    Check(vtkMath::Norm(m) <= vtkSphericalCap::IntersectionArea(r1, r2, d) + 1e-12 &&
        std::sqrt(vtkMath::Distance2BetweenPoints(m, swapped)) < 1e-12,
      "moment bound and symmetry", r1, r2, d, vtkMath::Norm(m), 0);
  }
}
}

// The shading functions: analytic limits and their relation to the other functions.
void TestShading()
{
  const int cap = vtkSphericalCap::EXACT, smooth = vtkSphericalCap::SMOOTHSTEP,
            simple = vtkSphericalCap::SIMPLIFIED, bentMode = vtkSphericalCap::BENT_NORMAL;
  const int centroid = vtkSphericalCap::CENTROID, moment = vtkSphericalCap::MOMENT;
  const double n[3] = { 0.0, 0.0, 1.0 };
  double worst = 0.0;
  for (double rl : { 4.7e-3, 0.064, 0.314, 0.785 })
  {
    const double scale = Pi * std::sin(rl) * std::sin(rl);
    for (int i = 0; i <= 36; ++i)
    {
      const double theta = Pi * i / 36.0;
      const double l[3] = { std::sin(theta), 0.0, std::cos(theta) };
      // An open aperture is the hemisphere: the exact moment model is Snyder's formula.
      const double t = vtkSphericalCap::LightTransfer(cap, moment, n, n, 0.5 * Pi, l, rl);
      const double want = vtkSphericalCap::SphereLightIrradiance(rl, theta) / scale;
      worst = std::max(worst, std::abs(t - want));
      Check(std::abs(t - want) < 1e-9, "open aperture: exact moment = horizon-clipped sphere light",
        0.5 * Pi, rl, theta, t, want);
    }
    // Inside an open aperture and above the horizon: moment gives n.l exactly, the centroid
    // overestimates by 2/(1 + cos rl).
    const double l[3] = { std::sin(0.3), 0.0, std::cos(0.3) };
    const double cosT = std::cos(0.3);
    if (0.3 + rl < 0.5 * Pi)
    {
      Check(
        std::abs(vtkSphericalCap::LightTransfer(cap, moment, n, n, 0.5 * Pi, l, rl) - cosT) < 1e-12,
        "unoccluded light: exact moment gives n.l", 0.5 * Pi, rl, 0.3, 0, cosT);
      const double c = vtkSphericalCap::LightTransfer(cap, centroid, n, n, 0.5 * Pi, l, rl);
      Check(std::abs(c - cosT * 2.0 / (1.0 + std::cos(rl))) < 1e-9,
        "unoccluded light: centroid overestimates by 2/(1 + cos rl)", 0.5 * Pi, rl, 0.3, c, cosT);
    }
    // A closed aperture lets no light through; the coverage is the lens area.
    for (int mode : { cap, smooth, simple })
    {
      Check(vtkSphericalCap::LightTransfer(mode, centroid, n, n, 0.0, l, rl) == 0.0,
        "closed aperture: dark", 0, rl, mode, 0, 0);
    }
    const double bent[3] = { std::sin(0.5), 0.0, std::cos(0.5) };
    Check(std::abs(vtkSphericalCap::LightCoverage(cap, bent, 0.6, l, rl) -
            vtkSphericalCap::IntersectionArea(0.6, rl, 0.2)) < 1e-12,
      "coverage is the lens area", 0.6, rl, 0.2, 0, 0);
  }
  std::cout << "Open aperture, exact moment vs Snyder: max difference " << worst << "\n";

  // Sun-sized lights in an open aperture: every model gives VTK's n.l.
  for (int mode : { cap, smooth, simple, bentMode })
  {
    for (int lambert : { centroid, moment })
    {
      const double l[3] = { 0.6, 0.0, 0.8 };
      const double t = vtkSphericalCap::LightTransfer(mode, lambert, n, n, 0.5 * Pi, l, 4.7e-3);
      Check(std::abs(t - 0.8) < 1e-4, "sun in an open aperture: n.l", mode, lambert, 0, t, 0.8);
    }
  }
  // LightTransfer's own ramp for SIMPLIFIED agrees with SimplifiedShadowFactor() times n.l.
  vtkMath::RandomSeed(3);
  double worstSimplified = 0.0;
  for (int i = 0; i < 2000; ++i)
  {
    const double rp = vtkMath::Random(0.0, 0.5 * Pi), rl = vtkMath::Random(1e-4, 0.8);
    const double d = vtkMath::Random(0.0, Pi), tilt = vtkMath::Random(0.0, 1.5);
    const double bent[3] = { 0.0, 0.0, 1.0 };
    const double l[3] = { std::sin(d), 0.0, std::cos(d) };
    const double normal[3] = { 0.0, std::sin(tilt), std::cos(tilt) };
    const double want =
      vtkSphericalCap::SimplifiedShadowFactor(rp, rl, d) * std::max(0.0, vtkMath::Dot(normal, l));
    const double got = vtkSphericalCap::LightTransfer(simple, centroid, normal, bent, rp, l, rl);
    worstSimplified = std::max(worstSimplified, std::abs(got - want));
  }
  std::cout << "SIMPLIFIED transfer vs SimplifiedShadowFactor * n.l: max difference "
            << worstSimplified << "\n";
  Check(worstSimplified < 1e-9, "simplified transfer = shadow factor times n.l", 0, 0, 0,
    worstSimplified, 0);

  // The sky fills what the light leaves of the aperture.
  Check(std::abs(vtkSphericalCap::SkyTransfer(0.5 * Pi, 0.0, 1.0, true) - 1.0) < 1e-12,
    "open sky: 1", 0, 0, 0, 0, 1);
  Check(std::abs(vtkSphericalCap::SkyTransfer(0.5 * Pi, Pi, 1.0, false) - 0.5) < 1e-12,
    "half the aperture covered: 1/2", 0, 0, 0, 0, 0.5);
  Check(std::abs(vtkSphericalCap::SkyTransfer(1.0, 0.0, 0.5, true) -
          0.5 * vtkSphericalCap::SolidAngleFromCapRadius(1.0) / (2.0 * Pi)) < 1e-12,
    "cosine-weighted sky", 1, 0, 0, 0, 0);
  // Bad input gives 0.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double zero[3] = { 0.0, 0.0, 0.0 };
  const double l[3] = { 0.0, 0.0, 1.0 };
  Check(vtkSphericalCap::LightTransfer(cap, moment, n, n, nan, l, 0.1) == 0.0 &&
      vtkSphericalCap::LightTransfer(cap, moment, zero, n, 1.0, l, 0.1) == 0.0 &&
      vtkSphericalCap::LightCoverage(cap, n, 1.0, zero, 0.1) == 0.0 &&
      vtkSphericalCap::SkyTransfer(nan, 0.0, 1.0, true) == 0.0,
    "shading with bad input: 0", 0, 0, 0, 0, 0);
  Check(vtkSphericalCap::ClampLightRadius(nan) == vtkSphericalCap::MinimumLightRadius &&
      std::isfinite(vtkSphericalCap::LightTransfer(cap, moment, n, n, 1.0, l, nan)),
    "a NaN light radius: the smallest one", 0, 0, 0, 0, 0);
}

int TestSphericalCap(int, char*[])
{
  TestReferenceAgainstLattice();
  TestAgainstIntegration();
  TestLargeCaps();
  TestSphereLight();
  TestEdgeCases();
  TestRotation();
  TestShading();
  return vtkApertureTest::Result();
}
