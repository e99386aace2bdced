/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureHemisphereSampler.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureHemisphereSampler.h"

#include "vtkApertureSurface.h"
#include "vtkMath.h"

#include <algorithm>
#include <cfloat>
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
std::uint64_t vtkApertureHemisphereSampler::Mix(std::uint64_t x)
{
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

//------------------------------------------------------------------------------
vtkApertureHemisphereSampler::vtkApertureHemisphereSampler(
  int numberOfRays, int seed, bool random, double rayOffset)
  : Seed(Mix(static_cast<std::uint32_t>(seed)))
  , Random(random)
  , RayOffset(static_cast<float>(rayOffset))
{
  const int n = std::max(1, numberOfRays);
  std::vector<std::pair<double, double>> samples(n);
  for (int i = 0; i < n; ++i)
  {
    samples[i] = { (i + 0.5) / n, RadicalInverse2(static_cast<std::uint32_t>(i)) };
  }
  const int sectors = (n + Lanes - 1) / Lanes;
  std::stable_sort(samples.begin(), samples.end(),
    [sectors](const auto& a, const auto& b)
    { return static_cast<int>(a.second * sectors) < static_cast<int>(b.second * sectors); });
  for (const auto& s : samples)
  {
    this->CosTheta.push_back(static_cast<float>(s.first));
    this->CosPhi.push_back(static_cast<float>(std::cos(2.0 * vtkMath::Pi() * s.second)));
    this->SinPhi.push_back(static_cast<float>(std::sin(2.0 * vtkMath::Pi() * s.second)));
  }
}

//------------------------------------------------------------------------------
void vtkApertureHemisphereSampler::Begin(
  const vtkApertureSurface& surface, vtkIdType id, Point& point) const
{
  const float* n = surface.GetNormal(id);
  // Orthonormal frame around the normal (Duff et al. 2017).
  const float sign = std::copysign(1.0f, n[2]);
  const float a = -1.0f / (sign + n[2]);
  const float b = n[0] * n[1] * a;
  const float tangent[3] = { 1.0f + sign * n[0] * n[0] * a, sign * b, -sign * n[0] };
  const float bitangent[3] = { b, sign + n[1] * n[1] * a, -n[1] };

  // Start above the surface: relative to the local edge length, and clear of the rounding of the
  // point's own coordinates.
  const float* p = &surface.Points[3 * id];
  const float magnitude = std::max({ std::abs(p[0]), std::abs(p[1]), std::abs(p[2]) });
  const float offset =
    std::max(this->RayOffset * surface.EdgeLength[id], 64.0f * FLT_EPSILON * magnitude);
  for (int k = 0; k < 3; ++k)
  {
    point.Normal[k] = n[k];
    point.Tangent[k] = tangent[k];
    point.Bitangent[k] = bitangent[k];
    point.Origin[k] = p[k] + offset * n[k];
  }

  point.State = Mix(this->Seed ^ Mix(static_cast<std::uint64_t>(id)));
  float turn;
  Uniforms(point.State, point.ShiftCosTheta, turn);
  point.TurnCos = std::cos(TwoPi * turn);
  point.TurnSin = std::sin(TwoPi * turn);
}

//------------------------------------------------------------------------------
void vtkApertureHemisphereSampler::Fill(
  Point& point, int first, float tfar, RTCRay16& ray, int valid[Lanes]) const
{
  const int n = this->GetNumberOfRays();
  for (int lane = 0; lane < Lanes; ++lane)
  {
    const int sample = std::min(first + lane, n - 1);
    valid[lane] = first + lane < n ? -1 : 0;
    float cosTheta, cosPhi, sinPhi;
    if (this->Random)
    {
      float u, v;
      point.State = Mix(point.State);
      Uniforms(point.State, u, v);
      cosTheta = u;
      cosPhi = std::cos(TwoPi * v);
      sinPhi = std::sin(TwoPi * v);
    }
    else
    {
      cosTheta = this->CosTheta[sample] + point.ShiftCosTheta;
      cosTheta -= cosTheta >= 1.0f ? 1.0f : 0.0f;
      cosPhi = this->CosPhi[sample] * point.TurnCos - this->SinPhi[sample] * point.TurnSin;
      sinPhi = this->SinPhi[sample] * point.TurnCos + this->CosPhi[sample] * point.TurnSin;
    }
    const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    const float x = sinTheta * cosPhi;
    const float y = sinTheta * sinPhi;
    ray.org_x[lane] = point.Origin[0];
    ray.org_y[lane] = point.Origin[1];
    ray.org_z[lane] = point.Origin[2];
    ray.dir_x[lane] = x * point.Tangent[0] + y * point.Bitangent[0] + cosTheta * point.Normal[0];
    ray.dir_y[lane] = x * point.Tangent[1] + y * point.Bitangent[1] + cosTheta * point.Normal[1];
    ray.dir_z[lane] = x * point.Tangent[2] + y * point.Bitangent[2] + cosTheta * point.Normal[2];
    ray.tnear[lane] = 0.0f;
    ray.tfar[lane] = tfar;
    ray.time[lane] = 0.0f;
    ray.mask[lane] = 0xffffffffu;
    ray.id[lane] = 0;
    ray.flags[lane] = 0;
  }
}
