/*=========================================================================

  Program:   ApertureLighting
  Module:    TestHorizonApertures.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkHorizonApertures against known answers:
// - a sector's deficit (solid angle, ∫ω dω) equals numerical integration over the sector;
// - open planes, flat and tilted by 20°, see A = 2π; their bent normal is their normal and
//   their AO 1, exactly when flat, within the O(Δφ²) of one elevation per sector when tilted;
// - an infinite wall at d of height H blocks ∫ sin atan(H cos ψ / d) dψ = 2 atan(H / d) (1%);
// - the bottom of a V-shaped valley sees the lune between the walls, 2 (π − 2 atan s) (2%),
//   and a pit's bottom centre the cap of half-angle atan(R0 / H) (2%), both bent vertically;
// - MaximumDistance: a wall farther than it does not occlude, a nearer one does;
// - tiles with a halo and their Origin give what the whole DEM gives (1e-6); no-data neither
//   occludes nor receives; results do not depend on runs or threads;
// - the hulls give what marching every sample of the same lines gives (1e-4), and how far
//   rays through the texels themselves would differ (printed);
// - bad input and aborts fail; and a speed figure for a 2000 × 2000 DEM.

#include "vtkHorizonApertures.h"

#include "vtkApertureTestHarness.h"

#include "vtkMath.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

using vtkApertureTest::Check;

namespace
{
constexpr double Pi = vtkMath::Pi();

struct Terrain
{
  vtkIdType Nx = 0, Ny = 0;
  double Dx = 1.0, Dy = 1.0;
  std::vector<float> Z;
  std::vector<unsigned char> Valid; // empty: all valid

  Terrain(vtkIdType nx, vtkIdType ny, double dx = 1.0, double dy = 1.0)
    : Nx(nx)
    , Ny(ny)
    , Dx(dx)
    , Dy(dy)
    , Z(nx * ny, 0.0f)
  {
  }

  float& At(vtkIdType i, vtkIdType j) { return this->Z[i + j * this->Nx]; }

  vtkHorizonApertures::Grid Grid(
    int sectors, double maximumDistance = VTK_DOUBLE_MAX, double earthRadius = 0.0) const
  {
    vtkHorizonApertures::Grid g;
    g.Heights = this->Z.data();
    g.Valid = this->Valid.empty() ? nullptr : this->Valid.data();
    g.Nx = this->Nx;
    g.Ny = this->Ny;
    g.Dx = this->Dx;
    g.Dy = this->Dy;
    g.Sectors = sectors;
    g.MaximumDistance = maximumDistance;
    g.EarthRadius = earthRadius;
    return g;
  }
};

vtkHorizonApertures::Apertures Run(const vtkHorizonApertures::Grid& grid)
{
  vtkHorizonApertures::Apertures out;
  std::string error;
  const bool ok = vtkHorizonApertures::Compute(grid, out, error);
  Check(ok, "Compute() fails: " + error);
  return out;
}

double SolidAngle(const vtkHorizonApertures::Apertures& out, vtkIdType o)
{
  return 2.0 * Pi * (1.0 - std::cos(double(out.ApertureRadius[o])));
}

// A deterministic value in [-1, 1] per integer pair.
double Noise(std::int64_t i, std::int64_t j)
{
  std::uint64_t h = static_cast<std::uint64_t>(i) * 0x9E3779B97F4A7C15ull ^
    (static_cast<std::uint64_t>(j) + 0x632BE59BD9B4E019ull) * 0xC2B2AE3D27D4EB4Full;
  h ^= h >> 29;
  h *= 0xBF58476D1CE4E5B9ull;
  h ^= h >> 32;
  return double(h >> 11) / double(1ull << 52) - 1.0;
}

// Rough terrain: sines of several scales and texel noise.
Terrain Rough(vtkIdType nx, vtkIdType ny, double dx, double dy)
{
  Terrain t(nx, ny, dx, dy);
  for (vtkIdType j = 0; j < ny; ++j)
  {
    for (vtkIdType i = 0; i < nx; ++i)
    {
      const double x = i * dx, y = j * dy;
      t.At(i, j) = static_cast<float>(8.0 * std::sin(0.05 * x) * std::cos(0.07 * y) +
        3.0 * std::sin(0.31 * x + 0.17 * y) + 1.5 * std::cos(0.9 * y - 0.4 * x) +
        0.8 * Noise(i, j));
    }
  }
  return t;
}

// The deficit formulas against a midpoint rule over the sector and elevations 0 … a.
void TestSectorFormulas()
{
  const double cases[][3] = { { 0.3, 1.1, 0.7 }, { 2.0, 2.4, -0.4 }, { 4.0, 5.5, 1.3 } };
  double worst = 0.0;
  for (const auto& c : cases)
  {
    double formula[4] = { 0.0, 0.0, 0.0, 0.0 }, numeric[4] = { 0.0, 0.0, 0.0, 0.0 };
    vtkHorizonApertures::AddSectorDeficit(c[0], c[1], c[2], formula);
    const int n = 600;
    const double dphi = (c[1] - c[0]) / n, de = c[2] / n;
    for (int p = 0; p < n; ++p)
    {
      for (int q = 0; q < n; ++q)
      {
        const double phi = c[0] + (p + 0.5) * dphi, e = (q + 0.5) * de;
        const double w = std::cos(e) * dphi * de;
        const double omega[4] = { 1.0, std::cos(e) * std::cos(phi), std::cos(e) * std::sin(phi),
          std::sin(e) };
        for (int k = 0; k < 4; ++k)
        {
          numeric[k] += w * omega[k];
        }
      }
    }
    for (int k = 0; k < 4; ++k)
    {
      worst = std::max(worst, std::abs(formula[k] - numeric[k]));
    }
  }
  std::cout << "sector formulas: largest difference from numerical integration " << worst << "\n";
  Check(worst < 1e-6, "sector deficit formulas", worst, 0.0);
}

// A plane z = slope (x cos ψ + y sin ψ) around the grid's middle.
Terrain Plane(vtkIdType n, double tilt, double azimuth)
{
  Terrain t(n, n);
  for (vtkIdType j = 0; j < n; ++j)
  {
    for (vtkIdType i = 0; i < n; ++i)
    {
      const double x = i - 0.5 * (n - 1), y = j - 0.5 * (n - 1);
      t.At(i, j) =
        static_cast<float>(std::tan(tilt) * (x * std::cos(azimuth) + y * std::sin(azimuth)));
    }
  }
  return t;
}

// The angle between two unit vectors, exact near 0 (acos of their dot product is not).
double Angle(const float a[3], const double b[3])
{
  const double d[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
  return 2.0 * std::asin(std::min(1.0, 0.5 * std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2])));
}

// Largest deviations of an open plane's outputs over its valid texels: r from π/2, A from 2π,
// the bent normal's angle from the normal, AO from 1, the normal's angle from `normal`.
void PlaneDeviations(
  const vtkHorizonApertures::Apertures& out, const double normal[3], double deviation[5])
{
  std::fill(deviation, deviation + 5, 0.0);
  for (vtkIdType o = 0; o < out.Nx * out.Ny; ++o)
  {
    if (!out.Valid[o])
    {
      continue;
    }
    const double n[3] = { out.Normals[3 * o], out.Normals[3 * o + 1], out.Normals[3 * o + 2] };
    deviation[0] = std::max(deviation[0], std::abs(out.ApertureRadius[o] - 0.5 * Pi));
    deviation[1] = std::max(deviation[1], std::abs(SolidAngle(out, o) - 2.0 * Pi));
    deviation[2] = std::max(deviation[2], Angle(&out.BentNormals[3 * o], n));
    deviation[3] = std::max(deviation[3], std::abs(out.AmbientOcclusion[o] - 1.0));
    deviation[4] = std::max(deviation[4], Angle(&out.Normals[3 * o], normal));
  }
}

// Checks a plane's deviations; the tilted plane's bent normal and AO carry the error of
// taking one elevation per sector, O(Δφ²), its A the rounding of float heights.
void CheckPlane(const vtkHorizonApertures::Apertures& out, const double normal[3], bool flat,
  int sectors, const std::string& what)
{
  const double dphi2 = std::pow(2.0 * Pi / sectors, 2);
  double d[5];
  PlaneDeviations(out, normal, d);
  std::cout << what << ": |r - π/2| " << d[0] << ", |A - 2π| " << d[1] << ", bent-normal angle "
            << d[2] << " rad, |AO - 1| " << d[3] << ", normal error " << d[4] << " rad\n";
  Check(d[0] <= 1e-6, what + ": r", d[0], 0.0);
  Check(d[1] <= (flat ? 1e-6 : 3e-6), what + ": A", d[1], 0.0);
  Check(d[4] <= 1e-6, what + ": normal", d[4], 0.0);
  Check(d[2] <= (flat ? 1e-7 : 0.02 * dphi2), what + ": bent normal", d[2], 0.0);
  Check(d[3] <= (flat ? 1e-7 : 0.0075 * dphi2), what + ": AO", d[3], 0.0);
}

// 1. Open planes.
void TestPlanes()
{
  const double tilt = vtkMath::RadiansFromDegrees(20.0), azimuth = 0.6;
  for (const double t : { 0.0, tilt })
  {
    for (const int sectors : { 15, 16, 64 })
    {
      const Terrain plane = Plane(24, t, azimuth);
      const double normal[3] = { -std::sin(t) * std::cos(azimuth), -std::sin(t) * std::sin(azimuth),
        std::cos(t) };
      CheckPlane(Run(plane.Grid(sectors)), normal, t == 0.0, sectors,
        "plane tilted " + std::to_string(int(vtkMath::DegreesFromRadians(t) + 0.5)) +
          "°, D = " + std::to_string(sectors));
    }
  }
}

// The output index of texel (i, j) of a whole-grid run.
vtkIdType Index(const vtkHorizonApertures::Apertures& out, vtkIdType i, vtkIdType j)
{
  return i + j * out.Nx;
}

// Flat ground with a cliff of height h from i = 10 + d on, 401 texels long: the receiver at
// (10, 200) is d from the foot of a wall that is infinite as far as the grid allows, and sits
// on its lines (Origin), so that only the wall's texels are sampled.
Terrain Wall(vtkIdType d, double h, vtkHorizonApertures::Grid& grid, int sectors, double radius)
{
  Terrain t(10 + d + 40, 401);
  for (vtkIdType j = 0; j < t.Ny; ++j)
  {
    for (vtkIdType i = 10 + d; i < t.Nx; ++i)
    {
      t.At(i, j) = static_cast<float>(h);
    }
  }
  grid = t.Grid(sectors, radius);
  grid.Origin[0] = -10;
  grid.Origin[1] = -200;
  return t;
}

// ∫ over the azimuths toward a wall (ψ from its normal) of sin h, h = atan(H cos ψ / d), for
// the walls |ψ| < limit: the solid angle it blocks. The infinite wall's closed form is 2 atan(H/d).
double WallBlocked(double d, double h, double limit)
{
  const int n = 200000;
  double sum = 0.0;
  for (int k = 0; k < n; ++k)
  {
    const double psi = -limit + (k + 0.5) * 2.0 * limit / n;
    sum += std::sin(std::atan(h * std::cos(psi) / d));
  }
  return sum * 2.0 * limit / n;
}

// 2. An infinite wall, and 5. MaximumDistance on it.
void TestWall()
{
  const double d = 20.0, h = 20.0;
  const double exact = 2.0 * Pi - WallBlocked(d, h, 0.5 * Pi);
  const double grid = 2.0 * Pi - WallBlocked(d, h, std::atan(200.0 / d));
  vtkHorizonApertures::Grid g;
  const Terrain t = Wall(20, h, g, 64, VTK_DOUBLE_MAX);
  const auto out = Run(g);
  const double a = SolidAngle(out, Index(out, 10, 200));
  std::cout << "wall d = 20, H = 20: A " << a << ", infinite wall " << exact << " (closed form "
            << 2.0 * Pi - 2.0 * std::atan(h / d) << "), as long as the grid " << grid << "; error "
            << 100.0 * (a / exact - 1.0) << "%\n";
  Check(std::abs(a / exact - 1.0) <= 0.01, "wall: A", a, exact);

  g.MaximumDistance = 15.0; // nearer than the wall
  const auto shorter = Run(g);
  const double open = SolidAngle(shorter, Index(shorter, 10, 200));
  g.MaximumDistance = 30.0; // the wall's top within reach where cos ψ >= 2/3
  const auto longer = Run(g);
  const double partial = SolidAngle(longer, Index(longer, 10, 200));
  const double expected = 2.0 * Pi - WallBlocked(d, h, std::acos(d / 30.0));
  std::cout << "wall beyond MaximumDistance 15: A " << open << "; within 30: A " << partial
            << " (expected " << expected << ")\n";
  Check(std::abs(shorter.ApertureRadius[Index(shorter, 10, 200)] - 0.5 * Pi) <= 1e-6,
    "a wall beyond MaximumDistance occludes", open, 2.0 * Pi);
  Check(
    std::abs(partial / expected - 1.0) <= 0.02, "a wall within MaximumDistance", partial, expected);
}

// A square grid of 2c + 1 texels with z(x, y) around its centre, which sits on its lines.
template <typename Height>
Terrain Centred(vtkIdType c, Height z, vtkHorizonApertures::Grid& grid, int sectors)
{
  Terrain t(2 * c + 1, 2 * c + 1);
  for (vtkIdType j = 0; j < t.Ny; ++j)
  {
    for (vtkIdType i = 0; i < t.Nx; ++i)
    {
      t.At(i, j) = static_cast<float>(z(double(i - c), double(j - c)));
    }
  }
  grid = t.Grid(sectors);
  grid.Origin[0] = grid.Origin[1] = -c;
  return t;
}

// Checks the centre's solid angle and that its bent normal is +z.
void CheckCentre(const vtkHorizonApertures::Apertures& out, vtkIdType c, double expected,
  double tolerance, const std::string& what)
{
  const vtkIdType o = Index(out, c, c);
  const double a = SolidAngle(out, o);
  const float* b = &out.BentNormals[3 * o];
  const double up[3] = { 0.0, 0.0, 1.0 };
  std::cout << what << ": A " << a << ", expected " << expected << ", error "
            << 100.0 * (a / expected - 1.0) << "%; bent normal (" << b[0] << ", " << b[1] << ", "
            << b[2] << ")\n";
  Check(std::abs(a / expected - 1.0) <= tolerance, what + ": A", a, expected);
  Check(Angle(b, up) <= 1e-4, what + ": bent normal vertical", Angle(b, up), 0.0);
}

// 3. A V-shaped valley z = s |x|, and 4. a cylindrical pit.
void TestValleyAndPit()
{
  for (const double s : { 0.7, 2.0 })
  {
    vtkHorizonApertures::Grid g;
    const Terrain t = Centred(
      100, [s](double x, double) { return s * std::abs(x); }, g, 64);
    CheckCentre(Run(g), 100, 2.0 * (Pi - 2.0 * std::atan(s)), 0.02,
      "valley, walls of slope " + std::to_string(s));
  }
  const double r0 = 60.0, depth = 60.0;
  vtkHorizonApertures::Grid g;
  const Terrain t = Centred(
    120, [=](double x, double y) { return x * x + y * y < r0 * r0 ? -depth : 0.0; }, g, 64);
  CheckCentre(
    Run(g), 120, 2.0 * Pi * (1.0 - std::cos(std::atan(r0 / depth))), 0.02, "pit R0 = 60, H = 60");
}

// Largest difference between two runs' outputs over the texels of `b`, which covers texels
// [i0, ...] × [j0, ...] of `a`; false flags count as a difference of 1.
double Difference(const vtkHorizonApertures::Apertures& a, const vtkHorizonApertures::Apertures& b,
  vtkIdType i0 = 0, vtkIdType j0 = 0)
{
  double worst = 0.0;
  for (vtkIdType j = 0; j < b.Ny; ++j)
  {
    for (vtkIdType i = 0; i < b.Nx; ++i)
    {
      const vtkIdType p = (i + i0) + (j + j0) * a.Nx, q = i + j * b.Nx;
      worst = std::max(worst, a.Valid[p] == b.Valid[q] ? 0.0 : 1.0);
      worst = std::max(worst, std::abs(double(a.ApertureRadius[p]) - b.ApertureRadius[q]));
      worst = std::max(worst, std::abs(double(a.AmbientOcclusion[p]) - b.AmbientOcclusion[q]));
      for (int c = 0; c < 3; ++c)
      {
        worst =
          std::max(worst, std::abs(double(a.BentNormals[3 * p + c]) - b.BentNormals[3 * q + c]));
        worst = std::max(worst, std::abs(double(a.Normals[3 * p + c]) - b.Normals[3 * q + c]));
      }
    }
  }
  return worst;
}

bool Identical(const vtkHorizonApertures::Apertures& a, const vtkHorizonApertures::Apertures& b)
{
  auto same = [](const std::vector<float>& x, const std::vector<float>& y)
  { return x.size() == y.size() && std::memcmp(x.data(), y.data(), 4 * x.size()) == 0; };
  return same(a.ApertureRadius, b.ApertureRadius) && same(a.BentNormals, b.BentNormals) &&
    same(a.AmbientOcclusion, b.AmbientOcclusion) && same(a.Normals, b.Normals) &&
    a.Valid == b.Valid;
}

// Rough terrain of 300 × 250 with a no-data patch.
Terrain RoughWithHole()
{
  Terrain t = Rough(300, 250, 1.0, 1.25);
  t.Valid.assign(t.Z.size(), 1);
  for (vtkIdType j = 100; j < 106; ++j)
  {
    for (vtkIdType i = 60; i < 64; ++i)
    {
      t.Valid[i + j * t.Nx] = 0;
    }
  }
  return t;
}

// Texels [x0, x0 + nx) × [y0, y0 + ny) of a terrain, as a terrain of their own.
Terrain Crop(const Terrain& t, vtkIdType x0, vtkIdType y0, vtkIdType nx, vtkIdType ny)
{
  Terrain c(nx, ny, t.Dx, t.Dy);
  c.Valid.resize(nx * ny);
  for (vtkIdType j = 0; j < ny; ++j)
  {
    for (vtkIdType i = 0; i < nx; ++i)
    {
      c.Z[i + j * nx] = t.Z[(x0 + i) + (y0 + j) * t.Nx];
      c.Valid[i + j * nx] = t.Valid[(x0 + i) + (y0 + j) * t.Nx];
    }
  }
  return c;
}

// One tile of 64 × 64 at (tx, ty) computed from itself and its halo; `anchored`: with Origin.
vtkHorizonApertures::Apertures Tile(const Terrain& t, double radius, vtkIdType tx, vtkIdType ty,
  vtkIdType halo, bool anchored, double earthRadius)
{
  const vtkIdType x0 = std::max<vtkIdType>(0, tx - halo), y0 = std::max<vtkIdType>(0, ty - halo);
  const vtkIdType x1 = std::min(t.Nx, tx + 64 + halo), y1 = std::min(t.Ny, ty + 64 + halo);
  const Terrain c = Crop(t, x0, y0, x1 - x0, y1 - y0);
  vtkHorizonApertures::Grid g = c.Grid(16, radius, earthRadius);
  g.Origin[0] = anchored ? x0 : 0;
  g.Origin[1] = anchored ? y0 : 0;
  const vtkIdType extent[4] = { tx - x0, std::min(tx + 64, t.Nx) - 1 - x0, ty - y0,
    std::min(ty + 64, t.Ny) - 1 - y0 };
  std::copy(extent, extent + 4, g.OutputExtent);
  return Run(g);
}

// 6. Tiles of 64 × 64 with a halo of ceil(MaximumDistance / spacing) + 2 texels, on flat or
// curved ground (the curvature's heights and slopes depend on where a sample is in the DEM).
void TestTiles(double earthRadius)
{
  const Terrain t = RoughWithHole();
  const double radius = 20.0;
  const auto whole = Run(t.Grid(16, radius, earthRadius));
  const vtkIdType halo = static_cast<vtkIdType>(std::ceil(radius / std::min(t.Dx, t.Dy))) + 2;
  double worst = 0.0;
  for (vtkIdType ty = 0; ty < t.Ny; ty += 64)
  {
    for (vtkIdType tx = 0; tx < t.Nx; tx += 64)
    {
      worst = std::max(
        worst, Difference(whole, Tile(t, radius, tx, ty, halo, true, earthRadius), tx, ty));
    }
  }
  const double unanchored =
    Difference(whole, Tile(t, radius, 128, 128, halo, false, earthRadius), 128, 128);
  std::cout << "tiles 64 x 64, halo " << halo << ", Earth radius " << earthRadius
            << ": largest difference from the whole grid " << worst
            << " (a tile without its Origin: " << unanchored << ")\n";
  Check(worst <= 1e-6, "tiled == untiled", worst, 0.0);
}

// 7. No-data: a tilted plane with a patch of no-data (at great heights) and a NaN height.
void TestNoData()
{
  const double tilt = vtkMath::RadiansFromDegrees(20.0), azimuth = 2.0;
  Terrain t = Plane(40, tilt, azimuth);
  t.Valid.assign(t.Z.size(), 1);
  for (vtkIdType j = 20; j < 26; ++j)
  {
    for (vtkIdType i = 10; i < 16; ++i)
    {
      t.Valid[i + j * t.Nx] = 0;
      t.At(i, j) = 1e4f;
    }
  }
  t.At(30, 8) = std::numeric_limits<float>::quiet_NaN();
  const auto out = Run(t.Grid(16));
  int invalid = 0, wrong = 0;
  for (vtkIdType o = 0; o < out.Nx * out.Ny; ++o)
  {
    const float* b = &out.BentNormals[3 * o];
    invalid += out.Valid[o] ? 0 : 1;
    wrong += !out.Valid[o] &&
        (out.ApertureRadius[o] != 0.0f || out.AmbientOcclusion[o] != 0.0f || b[0] != 0.0f ||
          b[1] != 0.0f || b[2] != 1.0f)
      ? 1
      : 0;
  }
  std::cout << "no-data: " << invalid << " texels flagged (37 expected), " << wrong
            << " of them with other outputs than r = 0, bent (0, 0, 1), AO = 0\n";
  Check(invalid == 37 && wrong == 0, "no-data texels flagged and closed");
  const double normal[3] = { -std::sin(tilt) * std::cos(azimuth),
    -std::sin(tilt) * std::sin(azimuth), std::cos(tilt) };
  CheckPlane(out, normal, false, 16, "tilted plane around no-data");
}

// 8. Two runs, and one thread against two, give the same bits.
void TestDeterminism()
{
  const Terrain t = RoughWithHole();
  for (const double radius : { 20.0, VTK_DOUBLE_MAX })
  {
    const auto first = Run(t.Grid(16, radius));
    const auto second = Run(t.Grid(16, radius));
    vtkSMPTools::Initialize(1);
    const auto one = Run(t.Grid(16, radius));
    vtkSMPTools::Initialize(2);
    const auto two = Run(t.Grid(16, radius));
    vtkSMPTools::Initialize(0);
    const bool same = Identical(first, second), threads = Identical(one, two);
    std::cout << "MaximumDistance " << radius << ": two runs identical " << same
              << ", 1 thread == 2 threads " << threads << "\n";
    Check(same && threads && Identical(first, two), "deterministic");
  }
}

// 9. Without a normals buffer the sweeps keep each normal packed in 4 bytes (in AO's array, or
// one of their own without AO): every output within 2e-4 of the float normals' (radians, unit
// vectors, fractions; openness in degrees scaled to radians), the no-data flags the same and
// no-data texels' bent normals still exactly +z; a tile of rough terrain by a hole, with horizons
// and terrain products. Planes steeper than the packing resolves stay open.
void TestWithoutNormals()
{
  const Terrain t = RoughWithHole();
  vtkHorizonApertures::Grid g = t.Grid(16);
  const vtkIdType extent[4] = { 40, 139, 80, 179 };
  std::copy(extent, extent + 4, g.OutputExtent);
  const vtkIdType n = 100 * 100;
  // Per texel: bent normal, radius, AO, normals, 16 horizons, the four products.
  const int offsets[] = { 0, 3, 4, 5, 8, 24, 25, 26, 27, 28 };
  struct Outputs
  {
    std::vector<float> Floats;
    std::vector<unsigned char> Valid;
  };
  auto run = [&](bool normals, bool occlusion)
  {
    Outputs o{ std::vector<float>(n * offsets[9]), std::vector<unsigned char>(n) };
    float* p = o.Floats.data();
    vtkHorizonApertures::Buffers b{ p, p + 3 * n, occlusion ? p + 4 * n : nullptr,
      normals ? p + 5 * n : nullptr, o.Valid.data(), p + 8 * n };
    b.SkyViewFactor = p + 24 * n;
    b.SkyViewFactorCosine = p + 25 * n;
    b.PositiveOpenness = p + 26 * n;
    b.NegativeOpenness = p + 27 * n;
    std::string error;
    Check(vtkHorizonApertures::Compute(g, b, error), "Compute() fails: " + error);
    return o;
  };
  for (const bool occlusion : { true, false })
  {
    const Outputs kept = run(true, occlusion), packed = run(false, occlusion);
    double worst = 0.0;
    for (int r = 0; r < 9; ++r)
    {
      const double scale = r >= 7 ? Pi / 180.0 : 1.0; // openness: degrees
      for (vtkIdType v = offsets[r] * n; r != 3 && v < offsets[r + 1] * n; ++v)
      {
        const double a = kept.Floats[v], b = packed.Floats[v];
        const double d = std::isnan(a) && std::isnan(b) ? 0.0 : scale * std::abs(a - b);
        worst = std::max(worst, std::isnan(d) ? 1.0 : d); // NaN on one side only
      }
    }
    int notUp = 0;
    for (vtkIdType o = 0; o < n; ++o)
    {
      const float* bent = &packed.Floats[3 * o];
      notUp += !packed.Valid[o] && (bent[0] != 0.0f || bent[1] != 0.0f || bent[2] != 1.0f);
    }
    std::cout << "normals packed (AO " << occlusion << "): largest output difference " << worst
              << ", no-data texels not bent to +z " << notUp << "\n";
    Check(worst <= 2e-4 && kept.Valid == packed.Valid && notUp == 0,
      "packed normals give the float normals' outputs", worst, 2e-4);
  }
  // Planes from tan 89.99° (resolved) to 1e7 (too steep for 16 bits a coordinate): open.
  for (const double slope : { 5.7e3, 1e5, 1e7 })
  {
    const Terrain plane = Plane(16, std::atan(slope), 0.3);
    std::vector<float> floats(5 * 16 * 16);
    std::vector<unsigned char> valid(16 * 16);
    float* p = floats.data();
    const vtkHorizonApertures::Buffers b{ p, p + 3 * 256, p + 4 * 256, nullptr, valid.data() };
    std::string error;
    Check(vtkHorizonApertures::Compute(plane.Grid(16), b, error), "Compute() fails: " + error);
    double worst = 0.0;
    for (vtkIdType o = 0; o < 256; ++o)
    {
      const double d = std::abs(b.ApertureRadius[o] - 0.5 * Pi);
      worst = std::max(worst, std::isnan(d) ? 10.0 : d);
    }
    std::cout << "packed normals, plane of slope " << slope << ": |r - π/2| " << worst << "\n";
    Check(worst <= 1e-6, "a steep plane with packed normals is open", worst, 1e-6);
  }
}

// A sector's lines as vtkHorizonApertures defines them (see its class comment).
struct Direction
{
  double Cos, Sin, Tau, Delta;
  int Major, Step;

  Direction(int sector, int sectors, double dx, double dy)
  {
    const double phi = (sector + 0.5) * 2.0 * Pi / sectors, spacing[2] = { dx, dy };
    this->Cos = std::cos(phi);
    this->Sin = std::sin(phi);
    this->Major = std::abs(this->Cos) / dx >= std::abs(this->Sin) / dy ? 0 : 1;
    const double along = this->Major == 0 ? this->Cos : this->Sin;
    const double across = this->Major == 0 ? this->Sin : this->Cos;
    this->Tau = (across * spacing[this->Major]) / (along * spacing[1 - this->Major]);
    this->Delta = spacing[this->Major] / std::abs(along);
    this->Step = along > 0.0 ? 1 : -1;
  }
};

// The height at major index m, minor coordinate y, interpolated between the two texels around
// y; false where one it needs is no-data or off the grid.
bool HeightAt(const Terrain& t, const Direction& d, vtkIdType m, double y, double& z)
{
  const vtkIdType minor = d.Major == 0 ? t.Ny : t.Nx, major = d.Major == 0 ? t.Nx : t.Ny;
  // On a texel up to rounding (1e-9), as vtkHorizonApertures takes it: that texel alone.
  const double nearest = std::floor(y + 0.5);
  const bool onTexel = std::abs(y - nearest) < 1e-9;
  const vtkIdType j0 = static_cast<vtkIdType>(onTexel ? nearest : std::floor(y));
  const double w = onTexel ? 0.0 : y - j0;
  auto texel = [&](vtkIdType n) { return d.Major == 0 ? m + n * t.Nx : n + m * t.Nx; };
  auto usable = [&](vtkIdType n)
  {
    return m >= 0 && m < major && n >= 0 && n < minor && (t.Valid.empty() || t.Valid[texel(n)]) &&
      std::isfinite(t.Z[texel(n)]);
  };
  if (!usable(j0) || (w > 0.0 && !usable(j0 + 1)))
  {
    return false;
  }
  z = (1.0 - w) * t.Z[texel(j0)] + (w > 0.0 ? w * t.Z[texel(j0 + 1)] : 0.0);
  return true;
}

// The steepest slope from texel (i, j) over the samples of its ray within the radius, marched
// one by one: from its nearest line sample, as vtkHorizonApertures samples, or (`fromTexel`)
// from the texel itself along a line through it; on a sphere of `earthRadius` (0: flat), a
// sample at distance s lies s²/2R lower.
double MarchedSlope(const Terrain& t, const Direction& d, const vtkIdType origin[2], vtkIdType i,
  vtkIdType j, const float* normal, double radius, bool fromTexel, double earthRadius)
{
  const vtkIdType major = d.Major == 0 ? i : j, minor = d.Major == 0 ? j : i;
  const double x = double(major + origin[d.Major]) * d.Tau;
  const double offset =
    fromTexel || std::abs(x - std::floor(x + 0.5)) < 1e-9 ? 0.0 : x - std::floor(x + 0.5);
  double zr;
  if (!HeightAt(t, d, major, minor + offset, zr)) // the texel's tangent plane
  {
    const double spacing = d.Major == 0 ? t.Dy : t.Dx;
    zr = t.Z[i + j * t.Nx] - offset * normal[1 - d.Major] / normal[2] * spacing;
  }
  double best = -std::numeric_limits<double>::infinity();
  for (vtkIdType m = 1; double(m) * d.Delta <= radius; ++m)
  {
    const vtkIdType at = major + m * d.Step;
    if (at < 0 || at >= (d.Major == 0 ? t.Nx : t.Ny))
    {
      break;
    }
    double z;
    if (HeightAt(t, d, at, minor + offset + double(m * d.Step) * d.Tau, z))
    {
      const double s = double(m) * d.Delta;
      best = std::max(best, (z - zr - (earthRadius > 0.0 ? s * s / (2.0 * earthRadius) : 0.0)) / s);
    }
  }
  return best;
}

// 9. The hulls against marching: horizons per sector and A per texel, on rough terrain with
// texel noise of the given amplitude besides, on flat or curved ground.
void TestAgainstMarching(double dx, double dy, double radius, vtkIdType ox, vtkIdType oy,
  int sectors, double noise, double earthRadius = 0.0)
{
  Terrain t = Rough(64, 64, dx, dy);
  for (vtkIdType k = 0; k < 64 * 64; ++k)
  {
    t.Z[k] += static_cast<float>(noise * Noise(k, 7));
  }
  t.Valid.assign(t.Z.size(), 1);
  std::fill(t.Valid.begin() + 30 * 64 + 20, t.Valid.begin() + 30 * 64 + 24, 0);
  vtkHorizonApertures::Grid g = t.Grid(sectors, radius, earthRadius);
  g.Origin[0] = ox;
  g.Origin[1] = oy;
  const auto out = Run(g);
  std::vector<double> reference(out.Nx * out.Ny, 0.0), throughTexel(reference);
  double worstH = 0.0;
  for (int sector = 0; sector < g.Sectors; ++sector)
  {
    const Direction d(sector, g.Sectors, dx, dy);
    std::vector<float> horizons;
    std::string error;
    Check(vtkHorizonApertures::ComputeHorizons(g, sector, horizons, error), "horizons: " + error);
    for (vtkIdType o = 0; o < out.Nx * out.Ny; ++o)
    {
      if (!out.Valid[o])
      {
        Check(std::isnan(horizons[o]), "no horizon for no-data");
        continue;
      }
      const float* n = &out.Normals[3 * o];
      const double tangent = std::atan(-(n[0] * d.Cos + n[1] * d.Sin) / n[2]);
      const double h =
        std::atan(MarchedSlope(t, d, g.Origin, o % 64, o / 64, n, radius, false, earthRadius));
      const double h2 =
        std::atan(MarchedSlope(t, d, g.Origin, o % 64, o / 64, n, radius, true, earthRadius));
      worstH = std::max(worstH, std::abs(h - horizons[o]));
      reference[o] += 2.0 * Pi / g.Sectors * (1.0 - std::sin(std::max(h, tangent)));
      throughTexel[o] += 2.0 * Pi / g.Sectors * (1.0 - std::sin(std::max(h2, tangent)));
    }
  }
  double worstA = 0.0, worstTexel = 0.0, meanTexel = 0.0;
  for (vtkIdType o = 0; o < out.Nx * out.Ny; ++o)
  {
    if (out.Valid[o])
    {
      worstA = std::max(worstA, std::abs(SolidAngle(out, o) - reference[o]));
      worstTexel = std::max(worstTexel, std::abs(SolidAngle(out, o) - throughTexel[o]));
      meanTexel += std::abs(SolidAngle(out, o) - throughTexel[o]) / (out.Nx * out.Ny);
    }
  }
  std::cout << "64 x 64 against marching (Dx " << dx << ", Dy " << dy << ", MaximumDistance "
            << radius << ", D = " << sectors << ", noise " << noise << ", Earth radius "
            << earthRadius << "): horizons within " << worstH << " rad, A within " << worstA
            << "; rays through the texels instead of their nearest line samples: A within "
            << worstTexel << " (mean " << meanTexel << ")\n";
  Check(worstH <= 1e-5, "horizons against marching", worstH, 0.0);
  Check(worstA <= 1e-4, "A against marching", worstA, 0.0);
}

// Bad input and aborts fail with a sentence; progress reaches 1 (8 sectors: 4 passes).
void TestFailures()
{
  const Terrain t = Plane(16, 0.2, 0.0);
  vtkHorizonApertures::Apertures out;
  std::string error;
  vtkHorizonApertures::Grid g = t.Grid(8);
  g.Heights = nullptr;
  Check(!vtkHorizonApertures::Compute(g, out, error) && !error.empty(), "no heights fail");
  g = t.Grid(8);
  const vtkIdType outside[4] = { 0, 16, 0, 15 };
  std::copy(outside, outside + 4, g.OutputExtent);
  Check(!vtkHorizonApertures::Compute(g, out, error), "an extent off the grid fails");
  g = t.Grid(0);
  Check(!vtkHorizonApertures::Compute(g, out, error), "no sectors fail");
  g = t.Grid(8);
  g.Dy = 0.0;
  Check(!vtkHorizonApertures::Compute(g, out, error), "zero spacing fails");
  g = t.Grid(8);
  std::vector<float> h;
  Check(!vtkHorizonApertures::ComputeHorizons(g, 8, h, error), "a sector out of range fails");
  std::vector<double> fractions;
  auto record = [&](double f)
  {
    fractions.push_back(f);
    return true;
  };
  Check(vtkHorizonApertures::Compute(g, out, error, record) && fractions.size() == 4 &&
      fractions.back() == 1.0 && std::is_sorted(fractions.begin(), fractions.end()),
    "progress after each pair of opposite sectors");
  error.clear();
  auto stop = [](double f) { return f < 0.3; };
  Check(!vtkHorizonApertures::Compute(g, out, error, stop) && !error.empty() &&
      out.ApertureRadius.empty(),
    "an abort fails and leaves no outputs");
}

// Speed on a 2000 × 2000 DEM with 16 sectors (printed, not checked).
void TestSpeed()
{
  const Terrain t = Rough(2000, 2000, 1.0, 1.0);
  for (const double radius : { VTK_DOUBLE_MAX, 100.0 })
  {
    const auto start = std::chrono::steady_clock::now();
    const auto out = Run(t.Grid(16, radius));
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << "2000 x 2000, D = 16, MaximumDistance " << radius << ": " << seconds << " s, "
              << 1e9 * seconds / (16.0 * 2000 * 2000) << " ns per texel-sector ("
              << vtkSMPTools::GetEstimatedNumberOfThreads() << " threads)\n";
  }
}
}

// 10. The horizons kept by Compute() (written sector-major in blocks of texels, then turned
// into records) against each sector swept alone, on a grid of several blocks and a part one,
// paired and unpaired sectors, with no-data texels (closed: π/2).
void TestKeptHorizons()
{
  Terrain t = Rough(53, 47, 1.0, 1.0);
  t.Valid.assign(t.Z.size(), 1);
  std::fill(t.Valid.begin() + 20 * 53 + 5, t.Valid.begin() + 20 * 53 + 9, 0);
  for (const int sectors : { 15, 16 })
  {
    const vtkHorizonApertures::Grid g = t.Grid(sectors, 12.0);
    const vtkIdType texels = 53 * 47;
    std::vector<float> bent(3 * texels), radius(texels), normals(3 * texels);
    std::vector<float> horizons(sectors * texels);
    std::vector<unsigned char> valid(texels);
    vtkHorizonApertures::Buffers out{ bent.data(), radius.data(), nullptr, normals.data(),
      valid.data(), horizons.data() };
    std::string error;
    Check(vtkHorizonApertures::Compute(g, out, error), "kept horizons: " + error);
    double worst = 0.0;
    for (int sector = 0; sector < sectors; ++sector)
    {
      std::vector<float> alone;
      Check(vtkHorizonApertures::ComputeHorizons(g, sector, alone, error), "horizons: " + error);
      for (vtkIdType o = 0; o < texels; ++o)
      {
        const double kept = horizons[o * sectors + sector];
        worst = std::max(worst, std::abs(kept - (valid[o] ? alone[o] : 0.5 * Pi)));
      }
    }
    Check(worst <= 1e-6, "kept horizons, D = " + std::to_string(sectors) + ", as swept alone",
      worst, 1e-6);
  }
}

int TestHorizonApertures(int, char*[])
{
  TestSectorFormulas();
  TestPlanes();
  TestWall();
  TestValleyAndPit();
  TestTiles(0.0);
  TestTiles(150.0);
  TestNoData();
  TestDeterminism();
  TestWithoutNormals();
  TestAgainstMarching(1.0, 1.0, 10.0, 3, -7, 16, 4.0);
  TestAgainstMarching(1.0, 0.8, VTK_DOUBLE_MAX, 0, 0, 16, 4.0);
  TestAgainstMarching(1.3, 1.0, 7.5, 1000, 20, 15, 4.0);
  TestAgainstMarching(1.0, 1.0, VTK_DOUBLE_MAX, 0, 0, 16, 0.0);
  // A sphere so small that the ground falls 13 units over the grid: beside the hills' heights.
  TestAgainstMarching(1.0, 0.8, VTK_DOUBLE_MAX, 500, -40, 16, 4.0, 150.0);
  TestAgainstMarching(1.3, 1.0, 7.5, 1000, 20, 15, 4.0, 150.0);
  TestKeptHorizons();
  TestFailures();
  TestSpeed();
  return vtkApertureTest::Result();
}
