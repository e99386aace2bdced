/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkHorizonLighting.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkHorizonLighting.h"

#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkSphericalCap.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkHorizonLighting);

namespace
{
constexpr double Pi = vtkMath::Pi();
constexpr double HalfPi = 0.5 * vtkMath::Pi();

// The elevation of the tangent plane of normal n along azimuth (cos φ, sin φ); normals are taken
// as facing up, as a height field's are.
double TangentElevation(const double n[3], double c, double s)
{
  return std::atan(-(n[0] * c + n[1] * s) / std::max(n[2], 1e-4));
}

// What one azimuth of a light cap adds: the cap's elevations there [eLow, eHigh] above the
// horizon h and the tangent plane, in solid angle and in ∫ n·ω, times the weight w.
void AddMeridian(
  const double n[3], double phi, double eLow, double eHigh, double h, double w, double sums[2])
{
  const double c = std::cos(phi), s = std::sin(phi);
  const double lit = std::max(std::max(eLow, h), TangentElevation(n, c, s));
  if (eHigh > lit)
  {
    // ∫ cos e, ∫ cos²e and ∫ sin e cos e over [lit, eHigh], in forms that keep tiny intervals.
    const double width = eHigh - lit, sinWidth = std::sin(width);
    const double horizontal = 0.5 * width + 0.5 * std::cos(eHigh + lit) * sinWidth;
    const double vertical = 0.5 * std::sin(eHigh + lit) * sinWidth;
    sums[0] += w * 2.0 * std::cos(0.5 * (eHigh + lit)) * std::sin(0.5 * width);
    sums[1] += w * ((n[0] * c + n[1] * s) * horizontal + n[2] * vertical);
  }
}

// The lowest and highest horizon that HorizonAt() takes over azimuths [phi0, phi1]: those of the
// sectors whose middles bracket them.
void HorizonRange(const float* horizons, int sectors, double phi0, double phi1, double range[2])
{
  const double first = std::floor(phi0 * sectors / (2.0 * Pi) - 0.5);
  const double last = std::floor(phi1 * sectors / (2.0 * Pi) - 0.5) + 1.0;
  const int count = static_cast<int>(std::min(double(sectors), last - first + 1.0));
  const int k0 = static_cast<int>(first - sectors * std::floor(first / sectors));
  range[0] = range[1] = horizons[k0];
  for (int i = 1; i < count; ++i)
  {
    const double h = horizons[(k0 + i) % sectors];
    range[0] = std::min(range[0], h);
    range[1] = std::max(range[1], h);
  }
}
}

//------------------------------------------------------------------------------
int vtkHorizonLighting::EncodeAngle(double h)
{
  if (std::isnan(h))
  {
    return 255;
  }
  const double a = std::min(1.0, std::abs(h) / HalfPi);
  const double t = std::copysign(std::sqrt(a), h);
  return static_cast<int>(std::lround(127.5 * (t + 1.0)));
}

//------------------------------------------------------------------------------
double vtkHorizonLighting::DecodeAngle(int code)
{
  const double t = std::min(std::max(code, 0), 255) / 127.5 - 1.0;
  return HalfPi * t * std::abs(t);
}

//------------------------------------------------------------------------------
double vtkHorizonLighting::HorizonAt(const float* horizons, int sectors, double azimuth)
{
  const double u = azimuth * sectors / (2.0 * Pi) - 0.5;
  const double k = std::floor(u);
  const double f = u - k;
  const int k0 = static_cast<int>(k - sectors * std::floor(k / sectors));
  const int k1 = k0 + 1 == sectors ? 0 : k0 + 1;
  return horizons[k0] + f * (double(horizons[k1]) - horizons[k0]);
}

//------------------------------------------------------------------------------
namespace
{
// A light cap (unit axis l, radius rl) above the horizons and the tangent plane of unit normal
// n: its solid angle and ∫ n·ω dω, summed over azimuths.
void LightSums(const double n[3], const float* horizons, int sectors, const double l[3], double rl,
  double sums[2])
{
  const double beta = std::asin(std::min(1.0, std::max(-1.0, l[2])));
  const double psi = std::atan2(l[1], l[0]);
  const double sinR = std::sin(rl), halfSin = std::sin(0.5 * rl);
  const bool polar = std::abs(beta) + rl >= HalfPi;
  const double cosB = std::cos(beta), sinB = std::sin(beta);
  const double span = polar ? Pi : std::asin(std::min(1.0, sinR / cosB));
  double range[2];
  HorizonRange(horizons, sectors, psi - span, psi + span, range);
  const double facing = vtkMath::Dot(n, l);
  if (beta + rl <= range[0] || facing <= -sinR)
  {
    return; // below the horizons or the tangent plane all over its span
  }
  if (beta - rl >= range[1] && facing >= sinR)
  {
    // Above the horizons and the tangent plane all over its span: the whole cap, closed form.
    sums[0] = 4.0 * Pi * halfSin * halfSin;
    sums[1] = Pi * sinR * sinR * facing;
    return;
  }
  const int count =
    polar ? vtkHorizonLighting::PolarLightSamples() : vtkHorizonLighting::LightSamples();
  for (int q = 0; q < count; ++q)
  {
    const double theta = Pi * (q + 0.5) / count;
    // Evenly over all azimuths around a pole; else x = cos θ across the cap's span.
    const double offset = polar ? 2.0 * theta - Pi : span * std::cos(theta);
    const double weight = polar ? 2.0 * Pi / count : span * std::sin(theta) * Pi / count;
    // The cap's elevations along this azimuth: |e − δ| <= γ, with cos γ = cos rl / R, and
    // 1 − cos γ from half angles so that a sun-sized cap keeps its precision.
    const double a = cosB * std::cos(offset), sinOffset = std::sin(offset);
    const double r = std::sqrt(a * a + sinB * sinB);
    const double lift = 2.0 * halfSin * halfSin - cosB * cosB * sinOffset * sinOffset / (1.0 + r);
    if (!(lift > 0.0))
    {
      continue;
    }
    const double gamma = 2.0 * std::asin(std::min(1.0, std::sqrt(lift / (2.0 * r))));
    const double delta = std::atan2(sinB, a);
    const double phi = psi + offset;
    AddMeridian(n, phi, std::max(delta - gamma, -HalfPi), std::min(delta + gamma, HalfPi),
      vtkHorizonLighting::HorizonAt(horizons, sectors, phi), weight, sums);
  }
  sums[1] = std::max(0.0, sums[1]);
}
}

//------------------------------------------------------------------------------
double vtkHorizonLighting::LightTransfer(const double normal[3], const float* horizons, int sectors,
  const double direction[3], double rl, double* coverage, double* cosineCoverage)
{
  double n[3], l[3];
  double sums[2] = { 0.0, 0.0 }; // solid angle, ∫ n·ω dω
  const bool usable = sectors >= 1 && !std::isnan(rl) && vtkSphericalCap::UnitAxis(normal, n) &&
    vtkSphericalCap::UnitAxis(direction, l);
  if (usable)
  {
    rl = vtkSphericalCap::ClampLightRadius(rl);
    LightSums(n, horizons, sectors, l, rl, sums);
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
double vtkHorizonLighting::SkyTransfer(const double normal[3], const float* horizons, int sectors,
  double coverage, double cosineCoverage, bool cosineWeighted)
{
  double n[3], open[2];
  if (sectors < 1 || std::isnan(coverage) || std::isnan(cosineCoverage) ||
    !vtkSphericalCap::UnitAxis(normal, n))
  {
    return 0.0;
  }
  OpenSums(n, horizons, sectors, open);
  return cosineWeighted ? std::max(0.0, open[1] - cosineCoverage) / Pi
                        : std::max(0.0, open[0] - coverage) / (2.0 * Pi);
}

//------------------------------------------------------------------------------
namespace
{
// A sector's wedge floor (elevation e, its sine and cosine): the horizon h, or the tangent plane
// of the unit normal n along the sector's middle (cos, sin) where that is higher.
void WedgeFloor(
  const double n[3], double h, const double middle[2], double& e, double& sinE, double& cosE)
{
  h = std::min(HalfPi, std::max(-HalfPi, h));
  const double t = -(n[0] * middle[0] + n[1] * middle[1]) / std::max(n[2], 1e-4);
  e = h;
  sinE = std::sin(h);
  cosE = std::cos(h);
  if (sinE < t * cosE)
  {
    cosE = 1.0 / std::sqrt(1.0 + t * t);
    sinE = t * cosE;
    e = std::atan(t);
  }
}

// Adds n · (a wedge table's value at azimuth phi and elevation e, bilinear) times sign to rgb.
void AddWedgeTable(const float* table, int azimuths, int elevations, double phi, double e,
  const double n[3], double sign, double rgb[3])
{
  const double x = std::min(double(azimuths), std::max(0.0, phi / (2.0 * Pi) * azimuths));
  const double y = std::min(elevations - 1.0, std::max(0.0, (e + HalfPi) / Pi * (elevations - 1)));
  const int i = std::min(azimuths - 1, static_cast<int>(x));
  const int j = std::min(elevations - 2, static_cast<int>(y));
  const double fx = x - i, fy = y - j;
  const size_t row = static_cast<size_t>(azimuths) + 1;
  const size_t plane = row * elevations;
  for (int a = 0; a < 3; ++a)
  {
    const float* p = table + 3 * (a * plane + j * row + i);
    for (int k = 0; k < 3; ++k)
    {
      const double low = (1.0 - fx) * p[k] + fx * p[3 + k];
      const double high = (1.0 - fx) * p[3 * row + k] + fx * p[3 * row + 3 + k];
      rgb[k] += sign * n[a] * ((1.0 - fy) * low + fy * high);
    }
  }
}
}

//------------------------------------------------------------------------------
void vtkHorizonLighting::EnvironmentSkyTransfer(const double normal[3], const float* horizons,
  int sectors, const float* table, int azimuths, int elevations, double coverage,
  double cosineCoverage, bool cosineWeighted, double rgb[3])
{
  double n[3], open[2];
  rgb[0] = rgb[1] = rgb[2] = 0.0;
  if (sectors < 1 || !horizons || !table || azimuths < 1 || elevations < 2 ||
    std::isnan(coverage) || std::isnan(cosineCoverage) || !vtkSphericalCap::UnitAxis(normal, n))
  {
    return;
  }
  const double width = 2.0 * Pi / sectors;
  for (int k = 0; k < sectors; ++k)
  {
    const double middle[2] = { std::cos((k + 0.5) * width), std::sin((k + 0.5) * width) };
    double e, sinE, cosE;
    WedgeFloor(n, horizons[k], middle, e, sinE, cosE);
    AddWedgeTable(table, azimuths, elevations, (k + 1) * width, e, n, 1.0, rgb);
    AddWedgeTable(table, azimuths, elevations, k * width, e, n, -1.0, rgb);
  }
  const double share = OpenShare(n, horizons, sectors, coverage, cosineCoverage, cosineWeighted);
  for (int k = 0; k < 3; ++k)
  {
    rgb[k] = std::max(0.0, rgb[k]) * share / Pi;
  }
}

//------------------------------------------------------------------------------
double vtkHorizonLighting::OpenShare(const double normal[3], const float* horizons, int sectors,
  double coverage, double cosineCoverage, bool cosineWeighted)
{
  double n[3], open[2];
  if (sectors < 1 || !horizons || std::isnan(coverage) || std::isnan(cosineCoverage) ||
    !vtkSphericalCap::UnitAxis(normal, n))
  {
    return 0.0;
  }
  OpenSums(n, horizons, sectors, open);
  const double all = cosineWeighted ? open[1] : open[0];
  const double lost = cosineWeighted ? cosineCoverage : coverage;
  return all > 0.0 ? std::max(0.0, 1.0 - lost / all) : 0.0;
}

//------------------------------------------------------------------------------
void vtkHorizonLighting::OpenSums(
  const double normal[3], const float* horizons, int sectors, double sums[2])
{
  double n[3];
  sums[0] = sums[1] = 0.0;
  if (sectors < 1 || !horizons || !vtkSphericalCap::UnitAxis(normal, n))
  {
    return;
  }
  const double width = 2.0 * Pi / sectors;
  // The sectors' bounds and middles by rotation, without trigonometry per sector.
  const double step[2] = { std::cos(width), std::sin(width) };
  const double halfStep[2] = { std::cos(0.5 * width), std::sin(0.5 * width) };
  double bound[2] = { 1.0, 0.0 }; // cos, sin of the sector's first azimuth
  for (int k = 0; k < sectors; ++k)
  {
    const double next[2] = { bound[0] * step[0] - bound[1] * step[1],
      bound[1] * step[0] + bound[0] * step[1] };
    const double middle[2] = { bound[0] * halfStep[0] - bound[1] * halfStep[1],
      bound[1] * halfStep[0] + bound[0] * halfStep[1] };
    double e, sinE, cosE;
    WedgeFloor(n, horizons[k], middle, e, sinE, cosE);
    // Over elevations e … π/2: solid angle, ∫ cos²e de and ∫ sin e cos e de.
    const double horizontal = 0.25 * Pi - 0.5 * (e + sinE * cosE);
    sums[0] += width * (1.0 - sinE);
    sums[1] += (n[0] * (next[1] - bound[1]) + n[1] * (bound[0] - next[0])) * horizontal +
      n[2] * width * 0.5 * cosE * cosE;
    bound[0] = next[0];
    bound[1] = next[1];
  }
}

//------------------------------------------------------------------------------
namespace
{
// A point's horizons from an array, optionally as the GPU decodes them; empty when unusable.
std::vector<float> PointHorizons(vtkDataArray* horizons, vtkIdType point, bool quantized)
{
  std::vector<float> h;
  if (!horizons || point < 0 || point >= horizons->GetNumberOfTuples())
  {
    return h;
  }
  h.resize(horizons->GetNumberOfComponents());
  for (size_t k = 0; k < h.size(); ++k)
  {
    const double value = horizons->GetComponent(point, static_cast<int>(k));
    h[k] = static_cast<float>(
      quantized ? vtkHorizonLighting::DecodeAngle(vtkHorizonLighting::EncodeAngle(value)) : value);
  }
  return h;
}
}

//------------------------------------------------------------------------------
double vtkHorizonLighting::LightTransfer(vtkDataArray* horizons, vtkIdType point, const double n[3],
  const double l[3], double rl, bool quantized)
{
  const std::vector<float> h = PointHorizons(horizons, point, quantized);
  return h.empty() ? 0.0 : LightTransfer(n, h.data(), static_cast<int>(h.size()), l, rl);
}

//------------------------------------------------------------------------------
double vtkHorizonLighting::SkyTransfer(
  vtkDataArray* horizons, vtkIdType point, const double n[3], bool cosineWeighted)
{
  const std::vector<float> h = PointHorizons(horizons, point, false);
  return h.empty() ? 0.0
                   : SkyTransfer(n, h.data(), static_cast<int>(h.size()), 0.0, 0.0, cosineWeighted);
}

//------------------------------------------------------------------------------
std::string vtkHorizonLighting::GetGLSLConstants()
{
  std::ostringstream glsl;
  glsl << "// vtkHorizonLighting's constants (vtkHorizonLighting::GetGLSLConstants()).\n"
       << "const int horizonLightingSamples = " << LightSamples() << ";\n"
       << "const int horizonLightingPolarSamples = " << PolarLightSamples() << ";\n";
  return glsl.str();
}

//------------------------------------------------------------------------------
void vtkHorizonLighting::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LightSamples: " << LightSamples() << "\n";
  os << indent << "PolarLightSamples: " << PolarLightSamples() << "\n";
}

//------------------------------------------------------------------------------
double vtkHorizonLighting::SectorAzimuth(int k, int sectors, double rotation)
{
  const double azimuth = std::fmod(rotation + 360.0 * (k + 0.5) / sectors, 360.0);
  return azimuth < 0.0 ? azimuth + 360.0 : azimuth;
}
