/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureRaySampler.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureRaySampler.h"

#include "vtkMath.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace
{
constexpr float TwoPi = static_cast<float>(2.0 * vtkMath::Pi());

// Two independent uniforms in [0, 1) from one 64-bit hash.
void Uniforms(std::uint64_t h, float& a, float& b)
{
  a = static_cast<float>(h >> 40) * (1.0f / 16777216.0f);
  b = static_cast<float>((h >> 16) & 0xffffff) * (1.0f / 16777216.0f);
}

double RadicalInverse2(std::uint32_t bits)
{
  bits = (bits << 16) | (bits >> 16);
  bits = ((bits & 0x55555555u) << 1) | ((bits & 0xaaaaaaaau) >> 1);
  bits = ((bits & 0x33333333u) << 2) | ((bits & 0xccccccccu) >> 2);
  bits = ((bits & 0x0f0f0f0fu) << 4) | ((bits & 0xf0f0f0f0u) >> 4);
  bits = ((bits & 0x00ff00ffu) << 8) | ((bits & 0xff00ff00u) >> 8);
  return bits * (1.0 / 4294967296.0);
}
}

//------------------------------------------------------------------------------
std::uint64_t vtkApertureRaySampler::Mix(std::uint64_t x)
{
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

//------------------------------------------------------------------------------
vtkApertureRaySampler::vtkApertureRaySampler(
  int numberOfRays, int seed, bool random, int distribution, double capRadius)
  : Seed(Mix(static_cast<std::uint32_t>(seed)))
  , Random(random)
  , Distribution(distribution)
  , CapCos(static_cast<float>(std::cos(capRadius)))
{
  const int n = std::max(1, numberOfRays);
  std::vector<std::pair<double, double>> samples(n);
  for (int i = 0; i < n; ++i)
  {
    samples[i] = { (i + 0.5) / n, RadicalInverse2(static_cast<std::uint32_t>(i)) };
  }
  // Sixteen rays of a packet share an azimuth sector.
  const int sectors = (n + 15) / 16;
  std::stable_sort(samples.begin(), samples.end(),
    [sectors](const auto& a, const auto& b)
    { return static_cast<int>(a.second * sectors) < static_cast<int>(b.second * sectors); });
  for (const auto& s : samples)
  {
    this->U.push_back(static_cast<float>(s.first));
    this->CosPhi.push_back(static_cast<float>(std::cos(2.0 * vtkMath::Pi() * s.second)));
    this->SinPhi.push_back(static_cast<float>(std::sin(2.0 * vtkMath::Pi() * s.second)));
  }
}

//------------------------------------------------------------------------------
// cos θ of u under a distribution.
template <int D>
static inline float CosThetaOf(float u, float capCos)
{
  return D == vtkApertureRaySampler::COSINE_HEMISPHERE
    ? std::sqrt(std::max(0.0f, 1.0f - u))
    : (D == vtkApertureRaySampler::UNIFORM_CAP ? 1.0f - u * (1.0f - capCos) : u);
}

//------------------------------------------------------------------------------
float vtkApertureRaySampler::CosTheta(float u) const
{
  switch (this->Distribution)
  {
    case COSINE_HEMISPHERE:
      return CosThetaOf<COSINE_HEMISPHERE>(u, this->CapCos);
    case UNIFORM_CAP:
      return CosThetaOf<UNIFORM_CAP>(u, this->CapCos);
    default:
      return CosThetaOf<UNIFORM_HEMISPHERE>(u, this->CapCos);
  }
}

//------------------------------------------------------------------------------
template <int D>
void vtkApertureRaySampler::Stratified(
  const Point& point, int first, int count, float* x, float* y, float* z) const
{
  const float* u0 = &this->U[first];
  const float* c0 = &this->CosPhi[first];
  const float* s0 = &this->SinPhi[first];
  for (int i = 0; i < count; ++i)
  {
    float u = u0[i] + point.ShiftU;
    u -= u >= 1.0f ? 1.0f : 0.0f;
    const float cosPhi = c0[i] * point.TurnCos - s0[i] * point.TurnSin;
    const float sinPhi = s0[i] * point.TurnCos + c0[i] * point.TurnSin;
    const float cosTheta = CosThetaOf<D>(u, this->CapCos);
    const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    const float a = sinTheta * cosPhi, b = sinTheta * sinPhi;
    x[i] = a * point.Tangent[0] + b * point.Bitangent[0] + cosTheta * point.Axis[0];
    y[i] = a * point.Tangent[1] + b * point.Bitangent[1] + cosTheta * point.Axis[1];
    z[i] = a * point.Tangent[2] + b * point.Bitangent[2] + cosTheta * point.Axis[2];
  }
}

//------------------------------------------------------------------------------
void vtkApertureRaySampler::Directions(
  Point& point, int first, int count, float* x, float* y, float* z) const
{
  if (this->Random)
  {
    for (int i = 0; i < count; ++i)
    {
      float d[3];
      this->Direction(point, first + i, d);
      x[i] = d[0];
      y[i] = d[1];
      z[i] = d[2];
    }
    return;
  }
  switch (this->Distribution)
  {
    case COSINE_HEMISPHERE:
      this->Stratified<COSINE_HEMISPHERE>(point, first, count, x, y, z);
      break;
    case UNIFORM_CAP:
      this->Stratified<UNIFORM_CAP>(point, first, count, x, y, z);
      break;
    default:
      this->Stratified<UNIFORM_HEMISPHERE>(point, first, count, x, y, z);
  }
}

//------------------------------------------------------------------------------
void vtkApertureRaySampler::Begin(const float axis[3], std::uint64_t key, Point& point) const
{
  // Orthonormal frame around the axis (Duff et al. 2017).
  const float* n = axis;
  const float sign = std::copysign(1.0f, n[2]);
  const float a = -1.0f / (sign + n[2]);
  const float b = n[0] * n[1] * a;
  const float tangent[3] = { 1.0f + sign * n[0] * n[0] * a, sign * b, -sign * n[0] };
  const float bitangent[3] = { b, sign + n[1] * n[1] * a, -n[1] };
  for (int k = 0; k < 3; ++k)
  {
    point.Axis[k] = n[k];
    point.Tangent[k] = tangent[k];
    point.Bitangent[k] = bitangent[k];
  }
  point.State = Mix(this->Seed ^ key);
  float turn;
  Uniforms(point.State, point.ShiftU, turn);
  point.TurnCos = std::cos(TwoPi * turn);
  point.TurnSin = std::sin(TwoPi * turn);
}

//------------------------------------------------------------------------------
void vtkApertureRaySampler::Direction(Point& point, int index, float direction[3]) const
{
  float u, cosPhi, sinPhi;
  if (this->Random)
  {
    float v;
    point.State = Mix(point.State);
    Uniforms(point.State, u, v);
    cosPhi = std::cos(TwoPi * v);
    sinPhi = std::sin(TwoPi * v);
  }
  else
  {
    u = this->U[index] + point.ShiftU;
    u -= u >= 1.0f ? 1.0f : 0.0f;
    cosPhi = this->CosPhi[index] * point.TurnCos - this->SinPhi[index] * point.TurnSin;
    sinPhi = this->SinPhi[index] * point.TurnCos + this->CosPhi[index] * point.TurnSin;
  }
  const float cosTheta = this->CosTheta(u);
  const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
  const float x = sinTheta * cosPhi;
  const float y = sinTheta * sinPhi;
  for (int k = 0; k < 3; ++k)
  {
    direction[k] = x * point.Tangent[k] + y * point.Bitangent[k] + cosTheta * point.Axis[k];
  }
}
