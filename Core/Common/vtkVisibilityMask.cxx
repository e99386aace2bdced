/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkVisibilityMask.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkVisibilityMask.h"

#include "vtkDataArray.h"
#include "vtkEnvironmentMap.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkSphericalCap.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkVisibilityMask);

namespace
{
constexpr double Pi = vtkMath::Pi();
constexpr double QuarterPi = 0.25 * vtkMath::Pi();

// Shirley and Chiu's concentric map from the square [-1, 1]² to the unit disk, and back.
void SquareToDisk(double a, double b, double& x, double& y)
{
  if (a == 0.0 && b == 0.0)
  {
    x = y = 0.0;
    return;
  }
  const bool wide = std::abs(a) > std::abs(b);
  const double r = wide ? a : b;
  const double phi = wide ? QuarterPi * (b / a) : 2.0 * QuarterPi - QuarterPi * (a / b);
  x = r * std::cos(phi);
  y = r * std::sin(phi);
}

// The inverse, with one arctangent within ±π/4 (as the GLSL twin, where it is the cost of a
// light's sample): the larger coordinate's sign gives the square's side, the angle from it the
// position along that side.
void DiskToSquare(double x, double y, double& a, double& b)
{
  const bool wide = std::abs(x) >= std::abs(y);
  const double big = wide ? x : y, small = wide ? y : x;
  const double r = std::sqrt(x * x + y * y);
  const double major = big > 0.0 ? r : big < 0.0 ? -r : 0.0;
  const double minor = big != 0.0 ? r * std::atan(small / std::abs(big)) / QuarterPi : 0.0;
  a = wide ? major : minor;
  b = wide ? minor : major;
}

// ∫ n·ω dω per cell of a side × side grid, by a fine midpoint rule in the square (the maps are
// area-preserving, and n·ω = z = 1 − ρ² with ρ = max(|a|, |b|) the disk radius); computed once
// per grid.
const std::vector<double>& CellCosines(int side)
{
  static std::mutex lock;
  static std::vector<double> tables[33];
  std::lock_guard<std::mutex> guard(lock);
  std::vector<double>& table = tables[side];
  if (table.empty())
  {
    const int fine = 64, cells = side * side;
    table.resize(cells);
    for (int cell = 0; cell < cells; ++cell)
    {
      double sum = 0.0;
      for (int q = 0; q < fine * fine; ++q)
      {
        const double u = (cell % side + (q % fine + 0.5) / fine) / side;
        const double v = (cell / side + (q / fine + 0.5) / fine) / side;
        const double rho = std::max(std::abs(2.0 * u - 1.0), std::abs(2.0 * v - 1.0));
        sum += 1.0 - rho * rho;
      }
      table[cell] = 2.0 * Pi / cells * sum / (fine * fine);
    }
  }
  return table;
}

// The cell of unit w in the frame (t, b, n) of a side × side grid, or -1 below its plane.
int CellInFrame(
  const double t[3], const double b[3], const double n[3], const double w[3], int side)
{
  const double z = vtkMath::Dot(w, n);
  if (!(z >= 0.0) || side < 1)
  {
    return -1;
  }
  const double s = 1.0 / std::sqrt(1.0 + std::min(1.0, z));
  double a, c;
  DiskToSquare(vtkMath::Dot(w, t) * s, vtkMath::Dot(w, b) * s, a, c);
  const int i = std::min(side - 1, std::max(0, static_cast<int>(0.5 * (a + 1.0) * side)));
  const int j = std::min(side - 1, std::max(0, static_cast<int>(0.5 * (c + 1.0) * side)));
  return i + side * j;
}

// The direction at square coordinates (u, v) in the frame (t, b, n).
void DirectionInFrame(
  const double t[3], const double b[3], const double n[3], double u, double v, double w[3])
{
  double x, y;
  SquareToDisk(2.0 * u - 1.0, 2.0 * v - 1.0, x, y);
  const double rho2 = std::min(1.0, x * x + y * y), s = std::sqrt(2.0 - rho2);
  for (int k = 0; k < 3; ++k)
  {
    w[k] = x * s * t[k] + y * s * b[k] + (1.0 - rho2) * n[k];
  }
}

bool IsOpen(const unsigned char* mask, int cell)
{
  return (mask[cell / 8] >> (cell % 8)) & 1;
}

// The light's cap (unit l, radius rl) in open cells above the tangent plane of unit n: its
// solid angle and ∫ n·ω dω, from a Fibonacci spiral of directions uniform over the cap.
void LightSums(const double n[3], const unsigned char* mask, int side, const double l[3], double rl,
  double sums[2])
{
  const int samples = vtkVisibilityMask::LightSamples(rl, side * side);
  double t[3], b[3], nt[3], nb[3]; // the light's frame, the normal's
  vtkVisibilityMask::Frame(l, t, b);
  vtkVisibilityMask::Frame(n, nt, nb);
  const double halfSin = std::sin(0.5 * rl), capArea = 4.0 * Pi * halfSin * halfSin;
  // The spiral turns by the golden angle a sample, by rotation (as the GLSL twin, which saves
  // its sines so).
  const double golden = Pi * (3.0 - std::sqrt(5.0));
  const double turnC = std::cos(golden), turnS = std::sin(golden);
  double c = 1.0, s = 0.0;
  for (int i = 0; i < samples; ++i)
  {
    // 1 − cos θ uniform in [0, 1 − cos rl], formed from the half angle for sun-sized caps.
    const double down = 2.0 * halfSin * halfSin * (i + 0.5) / samples;
    const double cosT = 1.0 - down, sinT = std::sqrt(std::max(0.0, down * (2.0 - down)));
    double w[3];
    for (int k = 0; k < 3; ++k)
    {
      w[k] = cosT * l[k] + sinT * (c * t[k] + s * b[k]);
    }
    const double z = vtkMath::Dot(n, w);
    const int cell = CellInFrame(nt, nb, n, w, side);
    if (z > 0.0 && cell >= 0 && IsOpen(mask, cell))
    {
      sums[0] += capArea / samples;
      sums[1] += capArea / samples * z;
    }
    const double next = c * turnC - s * turnS;
    s = s * turnC + c * turnS;
    c = next;
  }
}

// A point's mask from an array; empty when unusable.
std::vector<unsigned char> PointMask(vtkDataArray* mask, vtkIdType point)
{
  std::vector<unsigned char> bytes;
  if (!mask || point < 0 || point >= mask->GetNumberOfTuples() ||
    !vtkVisibilityMask::IsValidBitCount(8 * mask->GetNumberOfComponents()))
  {
    return bytes;
  }
  bytes.resize(mask->GetNumberOfComponents());
  for (size_t k = 0; k < bytes.size(); ++k)
  {
    bytes[k] = static_cast<unsigned char>(mask->GetComponent(point, static_cast<int>(k)));
  }
  return bytes;
}
}

//------------------------------------------------------------------------------
bool vtkVisibilityMask::IsValidBitCount(int bits)
{
  return GetSide(bits) > 0;
}

//------------------------------------------------------------------------------
int vtkVisibilityMask::GetSide(int bits)
{
  const int side = static_cast<int>(std::lround(std::sqrt(std::max(0, bits))));
  return bits >= 64 && bits <= 1024 && side * side == bits && bits % 8 == 0 ? side : 0;
}

//------------------------------------------------------------------------------
void vtkVisibilityMask::Frame(const double n[3], double t[3], double b[3])
{
  const double sign = n[2] >= 0.0 ? 1.0 : -1.0; // as the GLSL twin decides it
  const double a = -1.0 / (sign + n[2]);
  const double c = n[0] * n[1] * a;
  t[0] = 1.0 + sign * n[0] * n[0] * a;
  t[1] = sign * c;
  t[2] = -sign * n[0];
  b[0] = c;
  b[1] = sign + n[1] * n[1] * a;
  b[2] = -n[1];
}

//------------------------------------------------------------------------------
int vtkVisibilityMask::CellOf(const double n[3], const double w[3], int side)
{
  double t[3], b[3];
  Frame(n, t, b);
  return CellInFrame(t, b, n, w, side);
}

//------------------------------------------------------------------------------
void vtkVisibilityMask::Direction(const double n[3], double u, double v, double w[3])
{
  double t[3], b[3];
  Frame(n, t, b);
  DirectionInFrame(t, b, n, u, v, w);
}

//------------------------------------------------------------------------------
void vtkVisibilityMask::CellRayDirections(
  const double n[3], int side, int raysSide, std::vector<float>& directions)
{
  double t[3], b[3];
  Frame(n, t, b);
  const int perCell = raysSide * raysSide, rays = side * side * perCell;
  directions.resize(3 * static_cast<size_t>(rays));
  for (int q = 0; q < rays; ++q)
  {
    const int cell = q / perCell, sub = q % perCell;
    double w[3];
    DirectionInFrame(t, b, n, (cell % side + (sub % raysSide + 0.5) / raysSide) / side,
      (cell / side + (sub / raysSide + 0.5) / raysSide) / side, w);
    std::copy(w, w + 3, &directions[3 * q]);
  }
}

//------------------------------------------------------------------------------
int vtkVisibilityMask::LightSamples(double rl, int bits)
{
  const double halfSin = std::sin(0.5 * rl);
  const double eighths = 8.0 * 4.0 * Pi * halfSin * halfSin / (2.0 * Pi / std::max(1, bits));
  return 8 * static_cast<int>(std::min(8.0, std::max(1.0, std::ceil(eighths))));
}

//------------------------------------------------------------------------------
void vtkVisibilityMask::OpenSums(const unsigned char* mask, int bits, double sums[2])
{
  sums[0] = sums[1] = 0.0;
  const int side = GetSide(bits);
  if (!mask || side == 0)
  {
    return;
  }
  const std::vector<double>& cosines = CellCosines(side); // once: it takes a lock
  for (int cell = 0; cell < bits; ++cell)
  {
    if (IsOpen(mask, cell))
    {
      sums[0] += 2.0 * Pi / bits;
      sums[1] += cosines[cell];
    }
  }
}

//------------------------------------------------------------------------------
double vtkVisibilityMask::CellCosine(int cell, int side)
{
  if (side < 1 || side > 32 || cell < 0 || cell >= side * side)
  {
    return 0.0;
  }
  return CellCosines(side)[cell];
}

//------------------------------------------------------------------------------
double vtkVisibilityMask::LightTransfer(const double normal[3], const unsigned char* mask, int bits,
  const double direction[3], double rl, double* coverage, double* cosineCoverage)
{
  double n[3], l[3];
  double sums[2] = { 0.0, 0.0 };
  const int side = GetSide(bits);
  const bool usable = side > 0 && mask && !std::isnan(rl) && vtkSphericalCap::UnitAxis(normal, n) &&
    vtkSphericalCap::UnitAxis(direction, l);
  if (usable)
  {
    rl = vtkSphericalCap::ClampLightRadius(rl);
    LightSums(n, mask, side, l, rl, sums);
  }
  if (coverage)
  {
    *coverage = sums[0];
  }
  if (cosineCoverage)
  {
    *cosineCoverage = sums[1];
  }
  return usable ? sums[1] * vtkSphericalCap::LightRadiance(rl) : 0.0;
}

//------------------------------------------------------------------------------
double vtkVisibilityMask::SkyTransfer(const double normal[3], const unsigned char* mask, int bits,
  double coverage, double cosineCoverage, bool cosineWeighted)
{
  double n[3], open[2];
  if (GetSide(bits) == 0 || !mask || std::isnan(coverage) || std::isnan(cosineCoverage) ||
    !vtkSphericalCap::UnitAxis(normal, n))
  {
    return 0.0;
  }
  OpenSums(mask, bits, open);
  return cosineWeighted ? std::max(0.0, open[1] - cosineCoverage) / Pi
                        : std::max(0.0, open[0] - coverage) / (2.0 * Pi);
}

//------------------------------------------------------------------------------
double vtkVisibilityMask::CellCapRadius(int bits)
{
  return std::acos(1.0 - 1.0 / std::max(1, bits));
}

//------------------------------------------------------------------------------
void vtkVisibilityMask::EnvironmentSkyTransfer(const double normal[3], const unsigned char* mask,
  int bits, const float* table, int columns, int rows, const double toEnvironment[9],
  double coverage, double cosineCoverage, bool cosineWeighted, double rgb[3])
{
  double n[3], t[3], b[3], open[2];
  rgb[0] = rgb[1] = rgb[2] = 0.0;
  const int side = GetSide(bits);
  const double determinant = toEnvironment
    ? vtkMath::Determinant3x3(toEnvironment, toEnvironment + 3, toEnvironment + 6)
    : 0.0;
  if (side == 0 || !mask || !table || columns < 1 || rows < 1 || std::isnan(coverage) ||
    std::isnan(cosineCoverage) || !vtkSphericalCap::UnitAxis(normal, n) ||
    !std::isfinite(determinant) || determinant == 0.0)
  {
    return;
  }
  Frame(n, t, b);
  const std::vector<double>& cosines = CellCosines(side); // once: it takes a lock
  for (int cell = 0; cell < bits; ++cell)
  {
    if (!IsOpen(mask, cell))
    {
      continue;
    }
    double w[3], local[3], radiance[3];
    DirectionInFrame(t, b, n, (cell % side + 0.5) / side, (cell / side + 0.5) / side, w);
    for (int i = 0; i < 3; ++i)
    {
      local[i] = vtkMath::Dot(toEnvironment + 3 * i, w);
    }
    vtkMath::Normalize(local);
    vtkEnvironmentMap::SampleTable(table, columns, rows, local, radiance);
    for (int k = 0; k < 3; ++k)
    {
      rgb[k] += radiance[k] * cosines[cell];
    }
  }
  OpenSums(mask, bits, open);
  const double all = cosineWeighted ? open[1] : open[0];
  const double lost = cosineWeighted ? cosineCoverage : coverage;
  const double share = all > 0.0 ? std::max(0.0, 1.0 - lost / all) : 0.0;
  for (int k = 0; k < 3; ++k)
  {
    rgb[k] = std::max(0.0, rgb[k]) * share / Pi;
  }
}

//------------------------------------------------------------------------------
double vtkVisibilityMask::LightTransfer(
  vtkDataArray* mask, vtkIdType point, const double n[3], const double l[3], double rl)
{
  const std::vector<unsigned char> bytes = PointMask(mask, point);
  return bytes.empty() ? 0.0
                       : LightTransfer(n, bytes.data(), 8 * static_cast<int>(bytes.size()), l, rl);
}

//------------------------------------------------------------------------------
double vtkVisibilityMask::SkyTransfer(
  vtkDataArray* mask, vtkIdType point, const double n[3], bool cosineWeighted)
{
  const std::vector<unsigned char> bytes = PointMask(mask, point);
  return bytes.empty()
    ? 0.0
    : SkyTransfer(n, bytes.data(), 8 * static_cast<int>(bytes.size()), 0.0, 0.0, cosineWeighted);
}

//------------------------------------------------------------------------------
std::string vtkVisibilityMask::GetGLSLConstants()
{
  // LightSamples(): 8 to 64, in steps of 8; the spiral's turn by the golden angle.
  const double golden = Pi * (3.0 - std::sqrt(5.0));
  std::ostringstream constants;
  constants.precision(17);
  constants << "// vtkVisibilityMask's constants (vtkVisibilityMask::GetGLSLConstants()).\n"
            << "const int visibilityMaskSampleStep = 8;\n"
            << "const int visibilityMaskMaximumSamples = 64;\n"
            << "const vec2 visibilityMaskGoldenTurn = vec2(" << std::cos(golden) << ", "
            << std::sin(golden) << ");\n";
  return constants.str();
}

//------------------------------------------------------------------------------
void vtkVisibilityMask::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LightSamples: 8 to 64, with the light's size\n";
}
