/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkVolumeApertureReference.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkVolumeApertureReference.h"

#include "vtkApertureSMP.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkSphericalCap.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkVolumeExtinction.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

vtkStandardNewMacro(vtkVolumeApertureReference);
vtkCxxSetObjectMacro(vtkVolumeApertureReference, VolumeProperty, vtkVolumeProperty);

namespace
{
constexpr double Pi = 3.14159265358979323846;

// A number in [0, 1) from an index and a stream (SplitMix64).
double Hash(uint64_t index, uint64_t stream)
{
  uint64_t z = index * 0x9E3779B97F4A7C15ull + stream * 0xBF58476D1CE4E5B9ull + 1;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * (1.0 / 9007199254740992.0);
}

// Two unit vectors completing unit `axis` to an orthonormal frame.
void Frame(const double axis[3], double u[3], double v[3])
{
  const double other[3] = { std::abs(axis[0]) < 0.9 ? 1.0 : 0.0,
    std::abs(axis[0]) < 0.9 ? 0.0 : 1.0, 0.0 };
  u[0] = axis[1] * other[2] - axis[2] * other[1];
  u[1] = axis[2] * other[0] - axis[0] * other[2];
  u[2] = axis[0] * other[1] - axis[1] * other[0];
  const double n = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  for (int a = 0; a < 3; ++a)
  {
    u[a] /= n;
  }
  v[0] = axis[1] * u[2] - axis[2] * u[1];
  v[1] = axis[2] * u[0] - axis[0] * u[2];
  v[2] = axis[0] * u[1] - axis[1] * u[0];
}

// The i-th of n directions spread evenly over the cap (axis, cos r) by a spherical Fibonacci
// spiral, turned by `turn` (a fraction of a whole turn) and shifted by `jitter` within its ring.
void CapDirection(
  const double axis[3], double cosRadius, int i, int n, double turn, double jitter, double w[3])
{
  double u[3], v[3];
  Frame(axis, u, v);
  const double z = 1.0 - (1.0 - cosRadius) * (i + jitter) / n;
  const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double phi = Pi * (3.0 - std::sqrt(5.0)) * i + 2.0 * Pi * turn;
  for (int a = 0; a < 3; ++a)
  {
    w[a] = z * axis[a] + rho * (std::cos(phi) * u[a] + std::sin(phi) * v[a]);
  }
}

// One marched ray: its transmittance and unit direction.
struct Ray
{
  double T;
  double Omega[3];
};

// The transmittance along unit `omega` (image axes) from voxel `start`.
struct Marcher
{
  const float* Sigma;
  int Dims[3];
  double Spacing[3];     // the input's, σ's grid
  double GridSpacing[3]; // the aperture grid's, where rays start
  double Falloff;
  double Step;

  double Transmittance(const int start[3], const double omega[3]) const
  {
    const double reach = 2.0 * vtkVolumeExtinction::FalloffsPerDistance * this->Falloff;
    double tau = 0.0;
    for (double s = vtkVolumeExtinction::StepLength(omega, this->GridSpacing);
         s < reach && tau < 30.0; s += this->Step)
    {
      // The midpoint of [s, s + Step].
      const double m = s + 0.5 * this->Step;
      double x[3];
      for (int a = 0; a < 3; ++a)
      {
        x[a] = start[a] + m * omega[a] / this->Spacing[a];
      }
      if (x[0] < -1.0 || x[1] < -1.0 || x[2] < -1.0 || x[0] > this->Dims[0] ||
        x[1] > this->Dims[1] || x[2] > this->Dims[2])
      {
        break; // outside is empty, and convex: the ray does not come back
      }
      tau += vtkVolumeExtinction::Sample(this->Sigma, this->Dims, x[0], x[1], x[2]) *
        std::exp(-m / this->Falloff) * this->Step;
    }
    return std::exp(-tau);
  }

  // Sums T and T ω over `samples` directions spread over the cap (axis, cos r), turned by a
  // rotation drawn from the voxel's index; each ray into `rays` when it is given.
  void Integrate(const int start[3], const double axis[3], double cosRadius, int samples,
    double& sum, double moment[3], std::vector<Ray>* rays) const
  {
    const uint64_t key = static_cast<uint64_t>(
      start[0] + this->Dims[0] * (start[1] + uint64_t(this->Dims[1]) * start[2]));
    const double turn = Hash(key, 1);
    for (int s = 0; s < samples; ++s)
    {
      double w[3];
      CapDirection(axis, cosRadius, s, samples, turn, Hash(key * 4096 + s, 2), w);
      const double t = this->Transmittance(start, w);
      if (rays)
      {
        rays->push_back({ t, { w[0], w[1], w[2] } });
      }
      sum += t;
      for (int a = 0; a < 3; ++a)
      {
        moment[a] += t * w[a];
      }
    }
  }
};

// The radius about unit `axis` of least Σ |T − cap| over `rays`, and that sum. Opening the cap
// past a ray changes the sum by 1 − 2T, so the best radius closes where the running change is
// lowest, halfway between two rays.
double NearestRadius(const std::vector<Ray>& rays, const double axis[3],
  std::vector<std::pair<double, double>>& order, double& error)
{
  order.clear();
  error = 0.0;
  for (const Ray& ray : rays)
  {
    order.emplace_back(-vtkMath::Dot(ray.Omega, axis), ray.T);
    error += ray.T; // an empty cap misses every ray's T
  }
  std::sort(order.begin(), order.end());
  double running = error;
  size_t inside = 0;
  for (size_t k = 0; k < order.size(); ++k)
  {
    running += 1.0 - 2.0 * order[k].second;
    if (running < error)
    {
      error = running;
      inside = k + 1;
    }
  }
  if (inside == 0 || inside == order.size())
  {
    return inside == 0 ? 0.0 : Pi;
  }
  const double cosine = -0.5 * (order[inside - 1].first + order[inside].first);
  return std::acos(std::max(-1.0, std::min(1.0, cosine)));
}

// The cap nearest `rays`: from `axis` (in: a start, out: the cap's), steps of falling angle
// toward whichever of eight neighbours lowers the error, each with its best radius.
double NearestCap(
  const std::vector<Ray>& rays, double axis[3], std::vector<std::pair<double, double>>& order)
{
  double error;
  double radius = NearestRadius(rays, axis, order, error);
  for (double step = 0.4; step > 0.004; step *= 0.5)
  {
    for (bool moved = true; moved;)
    {
      moved = false;
      double u[3], v[3], best[3];
      Frame(axis, u, v);
      for (int k = 0; k < 8; ++k)
      {
        const double phi = 0.25 * Pi * k;
        double w[3];
        for (int a = 0; a < 3; ++a)
        {
          w[a] = std::cos(step) * axis[a] +
            std::sin(step) * (std::cos(phi) * u[a] + std::sin(phi) * v[a]);
        }
        double e;
        const double r = NearestRadius(rays, w, order, e);
        if (e < error - 1e-9)
        {
          error = e;
          radius = r;
          std::copy(w, w + 3, best);
          moved = true;
        }
      }
      if (moved)
      {
        std::copy(best, best + 3, axis);
      }
    }
  }
  return radius;
}

// The cap (radius, image-axes unit axis) of a voxel's `samples` rays over the whole sphere: of
// their moments, or nearest `rays` (kept for NEAREST only).
double SphereCap(int fit, int samples, const std::vector<Ray>& rays, double sum,
  const double moment[3], std::vector<std::pair<double, double>>& order, double axis[3])
{
  vtkVolumeExtinction::MeanDirection(sum, moment, axis);
  if (fit == vtkVolumeApertureReference::NEAREST)
  {
    return NearestCap(rays, axis, order);
  }
  return vtkSphericalCap::CapRadiusFromSolidAngle(4.0 * Pi * sum / samples);
}

// A float array of `count` tuples of `components`.
vtkSmartPointer<vtkFloatArray> NewValues(const char* name, int components, vtkIdType count)
{
  auto values = vtkSmartPointer<vtkFloatArray>::New();
  values->SetName(name);
  values->SetNumberOfComponents(components);
  values->SetNumberOfTuples(count);
  return values;
}

// The marcher of `input`'s σ, for an aperture grid of every gridStep-th voxel.
Marcher MakeMarcher(vtkImageData* input, const float* sigma, int gridStep, double maximumDistance)
{
  Marcher marcher;
  marcher.Sigma = sigma;
  input->GetDimensions(marcher.Dims);
  input->GetSpacing(marcher.Spacing);
  double bounds[6];
  int extent[6];
  input->GetExtent(extent);
  for (int a = 0; a < 3; ++a)
  {
    marcher.GridSpacing[a] = marcher.Spacing[a] * gridStep;
    bounds[2 * a] = 0.0;
    bounds[2 * a + 1] = (extent[2 * a + 1] - extent[2 * a]) * marcher.Spacing[a];
  }
  const double smallest = std::min({ marcher.Spacing[0], marcher.Spacing[1], marcher.Spacing[2] });
  const double distance =
    maximumDistance > 0.0 ? maximumDistance : vtkVolumeExtinction::DefaultMaximumDistance(bounds);
  marcher.Falloff =
    std::max(distance, smallest * gridStep) / vtkVolumeExtinction::FalloffsPerDistance;
  marcher.Step = 0.25 * smallest;
  return marcher;
}
}

//------------------------------------------------------------------------------
vtkVolumeApertureReference::vtkVolumeApertureReference()
{
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
}

//------------------------------------------------------------------------------
vtkVolumeApertureReference::~vtkVolumeApertureReference()
{
  this->SetVolumeProperty(nullptr);
}

//------------------------------------------------------------------------------
vtkMTimeType vtkVolumeApertureReference::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  return this->VolumeProperty ? std::max(time, this->VolumeProperty->GetMTime()) : time;
}

//------------------------------------------------------------------------------
int vtkVolumeApertureReference::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int whole[6];
  inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
  const int step = this->ApertureGridStep * this->SampleStep;
  int out[6];
  double spacing[3] = { 1.0, 1.0, 1.0 };
  if (inInfo->Has(vtkDataObject::SPACING()))
  {
    inInfo->Get(vtkDataObject::SPACING(), spacing);
  }
  for (int a = 0; a < 3; ++a)
  {
    out[2 * a] = static_cast<int>(std::ceil(whole[2 * a] / static_cast<double>(step)));
    out[2 * a + 1] = static_cast<int>(std::floor(whole[2 * a + 1] / static_cast<double>(step)));
    spacing[a] *= step;
  }
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), out, 6);
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  return 1;
}

//------------------------------------------------------------------------------
int vtkVolumeApertureReference::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Rays cross the whole volume.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  int whole[6];
  inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), whole, 6);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkVolumeApertureReference::LightAxis(vtkMatrix3x3* rotation, double axis[3]) const
{
  const double* l = this->LightDirection;
  const double n = std::sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
  if (!(n > 0.0) || !std::isfinite(n))
  {
    return false;
  }
  vtkNew<vtkMatrix3x3> inverse;
  vtkMatrix3x3::Transpose(rotation, inverse);
  const double unit[3] = { l[0] / n, l[1] / n, l[2] / n };
  inverse->MultiplyPoint(unit, axis);
  return true;
}

//------------------------------------------------------------------------------
int vtkVolumeApertureReference::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0]);
  vtkImageData* output = vtkImageData::GetData(outputVector);
  vtkDataArray* scalars = input ? this->GetInputArrayToProcess(0, inputVector) : nullptr;
  const std::string problem = vtkVolumeExtinction::Check(input, scalars, this->VolumeProperty);
  if (!problem.empty())
  {
    vtkErrorMacro("Cannot compute the volume reference: " << problem << ".");
    return 0;
  }
  const std::vector<float> sigma =
    vtkVolumeExtinction::Compute(input, scalars, this->VolumeProperty);
  const Marcher marcher =
    MakeMarcher(input, sigma.data(), this->ApertureGridStep, this->MaximumDistance);
  int extent[6];
  input->GetExtent(extent);

  const int step = this->ApertureGridStep * this->SampleStep;
  int outExt[6];
  vtkStreamingDemandDrivenPipeline::GetUpdateExtent(this->GetOutputInformation(0), outExt);
  output->SetExtent(outExt);
  output->SetSpacing(
    marcher.Spacing[0] * step, marcher.Spacing[1] * step, marcher.Spacing[2] * step);
  output->SetOrigin(input->GetOrigin());
  output->SetDirectionMatrix(input->GetDirectionMatrix());
  const vtkIdType count = output->GetNumberOfPoints();
  const bool sphere = this->Source == SPHERE;
  auto values = NewValues(sphere ? "ReferenceApertureRadius" : "ReferenceIrradiance", 1, count);
  auto bent = NewValues("ReferenceBentNormal", 3, sphere ? count : 0);

  // The light's axis in image axes.
  vtkMatrix3x3* rotation = input->GetDirectionMatrix();
  double axis[3] = { 0.0, 0.0, 1.0 };
  const double cosRadius = sphere ? -1.0 : std::cos(this->LightRadius);
  if (!sphere && !this->LightAxis(rotation, axis))
  {
    vtkErrorMacro("Cannot compute the volume reference: the light direction is not a direction.");
    return 0;
  }
  const int samples = this->NumberOfSamples;
  vtkApertureSMP::For(0, count,
    [&](vtkIdType begin, vtkIdType end)
    {
      const bool keep = sphere && this->CapFit == NEAREST;
      std::vector<Ray> rays;
      std::vector<std::pair<double, double>> order;
      rays.reserve(keep ? samples : 0);
      for (vtkIdType i = begin; i < end; ++i)
      {
        int start[3];
        vtkVolumeExtinction::ExtentPoint(outExt, i, start);
        for (int a = 0; a < 3; ++a)
        {
          start[a] = start[a] * step - extent[2 * a];
        }
        double sum = 0.0;
        double moment[3] = { 0.0, 0.0, 0.0 };
        rays.clear();
        marcher.Integrate(start, axis, cosRadius, samples, sum, moment, keep ? &rays : nullptr);
        if (!sphere)
        {
          values->SetValue(i, static_cast<float>(sum / samples));
          continue;
        }
        double capAxis[3], world[3];
        const double radius = SphereCap(this->CapFit, samples, rays, sum, moment, order, capAxis);
        values->SetValue(i, static_cast<float>(radius));
        rotation->MultiplyPoint(capAxis, world);
        bent->SetTuple(i, world);
      }
    });
  output->GetPointData()->AddArray(values);
  if (sphere)
  {
    output->GetPointData()->AddArray(bent);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkVolumeApertureReference::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Source: " << (this->Source == SPHERE ? "SPHERE" : "LIGHT") << "\n";
  os << indent << "CapFit: " << (this->CapFit == NEAREST ? "NEAREST" : "MOMENTS") << "\n";
  os << indent << "VolumeProperty: " << this->VolumeProperty << "\n";
  os << indent << "MaximumDistance: " << this->MaximumDistance << "\n";
  os << indent << "ApertureGridStep: " << this->ApertureGridStep << "\n";
  os << indent << "SampleStep: " << this->SampleStep << "\n";
  os << indent << "NumberOfSamples: " << this->NumberOfSamples << "\n";
  os << indent << "LightDirection: (" << this->LightDirection[0] << ", " << this->LightDirection[1]
     << ", " << this->LightDirection[2] << ")\n";
  os << indent << "LightRadius: " << this->LightRadius << "\n";
}
