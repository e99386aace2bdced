/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureReference.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureReference.h"

#include "vtkApertureHemisphereSampler.h"
#include "vtkApertureRayScene.h"
#include "vtkApertureSurface.h"
#include "vtkEnvironmentMap.h"
#include "vtkSphericalCap.h"

#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkApertureReference);
vtkCxxSetObjectMacro(vtkApertureReference, Environment, vtkEnvironmentMap);

namespace
{
constexpr double Pi = vtkMath::Pi();
constexpr int Lanes = 16;
// Points handled between two progress events.
constexpr vtkIdType Batch = 4096;

// Radical inverse in base 2: the second Hammersley coordinate.
double RadicalInverse(std::uint32_t i)
{
  i = (i << 16) | (i >> 16);
  i = ((i & 0x55555555u) << 1) | ((i & 0xAAAAAAAAu) >> 1);
  i = ((i & 0x33333333u) << 2) | ((i & 0xCCCCCCCCu) >> 2);
  i = ((i & 0x0F0F0F0Fu) << 4) | ((i & 0xF0F0F0F0u) >> 4);
  i = ((i & 0x00FF00FFu) << 8) | ((i & 0xFF00FF00u) >> 8);
  return i * (1.0 / 4294967296.0);
}

// Two unit vectors completing a unit axis to an orthonormal frame.
void Frame(const double a[3], double t[3], double b[3])
{
  const double helper[3] = { std::abs(a[0]) < 0.6 ? 1.0 : 0.0, std::abs(a[0]) < 0.6 ? 0.0 : 1.0,
    0.0 };
  vtkMath::Cross(a, helper, t);
  vtkMath::Normalize(t);
  vtkMath::Cross(a, t, b);
}

class Estimate
{
public:
  Estimate(vtkApertureReference* self, const vtkApertureSurface& surface, RTCScene scene,
    const double light[3], vtkEnvironmentMap* environment, float* irradiance, float* noise)
    : Surface(surface)
    , Scene(scene)
    , Environment(environment)
    , Irradiance(irradiance)
    , Noise(noise)
  {
    std::copy(light, light + 3, this->Light);
    this->Source = self->GetSource();
    this->Samples = self->GetNumberOfSamples();
    this->Seed = static_cast<std::uint64_t>(static_cast<std::int64_t>(self->GetSeed()));
    this->Offset = self->GetRayOffset();
    const double r = self->GetLightRadius();
    this->CosRadius = std::cos(r);
    // Cap solid angle over π sin² r: the light's radiance times the cap.
    this->LightScale =
      vtkSphericalCap::SolidAngleFromCapRadius(r) / (Pi * std::sin(r) * std::sin(r));
    this->Components = this->Source == vtkApertureReference::ENVIRONMENT ? 3 : 1;
  }

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    vtkApertureRayScene::FlushToZero ftz;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    alignas(64) RTCRay16 ray;
    alignas(64) int valid[Lanes];
    std::vector<double> weight(Lanes * 3);
    for (vtkIdType id = begin; id < end; ++id)
    {
      this->Point(id, context, ray, valid, weight);
    }
  }

private:
  void Point(vtkIdType id, RTCIntersectContext& context, RTCRay16& ray, int* valid,
    std::vector<double>& weight) const
  {
    const int c = this->Components;
    float* out = this->Irradiance + c * id;
    float* spread = this->Noise + c * id;
    if (!this->Surface.Valid[id] || !this->Surface.Receives[id])
    {
      std::fill(out, out + c, std::numeric_limits<float>::quiet_NaN());
      std::fill(spread, spread + c, std::numeric_limits<float>::quiet_NaN());
      return;
    }
    const float* nf = this->Surface.GetNormal(id);
    const double n[3] = { nf[0], nf[1], nf[2] };
    const bool light = this->Source == vtkApertureReference::LIGHT;
    double axis[3], t[3], b[3];
    std::copy(light ? this->Light : n, (light ? this->Light : n) + 3, axis);
    Frame(axis, t, b);
    // The point's Cranley-Patterson rotation.
    const std::uint64_t h1 = vtkApertureHemisphereSampler::Mix(
      this->Seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(id));
    const std::uint64_t h2 = vtkApertureHemisphereSampler::Mix(h1);
    const double shift = (h1 >> 11) * (1.0 / 9007199254740992.0);
    const double turn = 2.0 * Pi * ((h2 >> 11) * (1.0 / 9007199254740992.0));
    const float* p = &this->Surface.Points[3 * id];
    const float lift = static_cast<float>(this->Offset * this->Surface.EdgeLength[id]);
    double sum[3] = { 0, 0, 0 }, squares[3] = { 0, 0, 0 };
    for (int first = 0; first < this->Samples; first += Lanes)
    {
      for (int lane = 0; lane < Lanes; ++lane)
      {
        const int i = first + lane;
        valid[lane] = 0;
        if (i >= this->Samples)
        {
          continue;
        }
        double u = (i + 0.5) / this->Samples + shift;
        u -= std::floor(u);
        const double phi = 2.0 * Pi * RadicalInverse(static_cast<std::uint32_t>(i)) + turn;
        // Uniform over the light's cap, or cosine-weighted over the hemisphere.
        const double cosTheta = light ? 1.0 - u * (1.0 - this->CosRadius) : std::sqrt(1.0 - u);
        const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
        double d[3];
        for (int k = 0; k < 3; ++k)
        {
          d[k] = cosTheta * axis[k] + sinTheta * (std::cos(phi) * t[k] + std::sin(phi) * b[k]);
        }
        const double cosine = vtkMath::Dot(n, d);
        if (cosine <= 0.0)
        {
          continue; // below the horizon: contributes nothing
        }
        double* w = &weight[3 * lane];
        if (light)
        {
          w[0] = cosine * this->LightScale;
        }
        else if (this->Source == vtkApertureReference::SKY)
        {
          w[0] = 1.0;
        }
        else
        {
          this->Environment->Radiance(d, w);
        }
        valid[lane] = -1;
        ray.org_x[lane] = p[0] + lift * nf[0];
        ray.org_y[lane] = p[1] + lift * nf[1];
        ray.org_z[lane] = p[2] + lift * nf[2];
        ray.dir_x[lane] = static_cast<float>(d[0]);
        ray.dir_y[lane] = static_cast<float>(d[1]);
        ray.dir_z[lane] = static_cast<float>(d[2]);
        ray.tnear[lane] = 0.0f;
        ray.tfar[lane] = std::numeric_limits<float>::infinity();
        ray.time[lane] = 0.0f;
        ray.mask[lane] = 0xFFFFFFFF;
        ray.id[lane] = 0;
        ray.flags[lane] = 0;
      }
      rtcOccluded16(valid, this->Scene, &context, &ray);
      for (int lane = 0; lane < Lanes; ++lane)
      {
        // Occluded rays come back with tfar = -inf.
        if (valid[lane] && ray.tfar[lane] >= 0.0f)
        {
          for (int k = 0; k < c; ++k)
          {
            const double x = weight[3 * lane + k];
            sum[k] += x;
            squares[k] += x * x;
          }
        }
      }
    }
    const double count = this->Samples;
    for (int k = 0; k < c; ++k)
    {
      const double mean = sum[k] / count;
      out[k] = static_cast<float>(mean);
      spread[k] =
        static_cast<float>(std::sqrt(std::max(0.0, squares[k] / count - mean * mean) / count));
    }
  }

  const vtkApertureSurface& Surface;
  RTCScene Scene;
  double Light[3];
  vtkEnvironmentMap* Environment;
  float* Irradiance;
  float* Noise;
  int Source, Samples, Components;
  std::uint64_t Seed;
  double Offset, CosRadius, LightScale;
};
}

//------------------------------------------------------------------------------
vtkApertureReference::vtkApertureReference()
{
  this->SetNumberOfInputPorts(2);
  this->SetIrradianceArrayName("ReferenceIrradiance");
  this->SetNoiseArrayName("ReferenceNoise");
}

//------------------------------------------------------------------------------
vtkApertureReference::~vtkApertureReference()
{
  this->SetEnvironment(nullptr);
  this->SetIrradianceArrayName(nullptr);
  this->SetNoiseArrayName(nullptr);
}

//------------------------------------------------------------------------------
void vtkApertureReference::AddOccluderConnection(vtkAlgorithmOutput* occluder)
{
  this->AddInputConnection(1, occluder);
}

//------------------------------------------------------------------------------
int vtkApertureReference::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  }
  return 1;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkApertureReference::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  if (this->Environment)
  {
    time = std::max(time, this->Environment->GetMTime());
  }
  return time;
}

//------------------------------------------------------------------------------
int vtkApertureReference::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!input || input->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro("The input is empty: there are no points to compute a reference for.");
    return 0;
  }
  double light[3] = { this->LightDirection[0], this->LightDirection[1], this->LightDirection[2] };
  if (this->Source == LIGHT &&
    !(std::isfinite(vtkMath::Norm(light)) && vtkMath::Normalize(light) > 0.0))
  {
    vtkErrorMacro("LightDirection (" << this->LightDirection[0] << ", " << this->LightDirection[1]
                                     << ", " << this->LightDirection[2]
                                     << ") is not a direction: it must be finite and not zero.");
    return 0;
  }
  if (this->Source == ENVIRONMENT && (!this->Environment || !this->Environment->GetImage()))
  {
    vtkErrorMacro("The ENVIRONMENT source needs an environment with an image (SetEnvironment()).");
    return 0;
  }
  if (!this->IrradianceArrayName || !*this->IrradianceArrayName || !this->NoiseArrayName ||
    !*this->NoiseArrayName)
  {
    vtkErrorMacro("The output arrays need names (IrradianceArrayName, NoiseArrayName).");
    return 0;
  }

  std::vector<vtkPolyData*> occluders;
  for (int i = 0; i < inputVector[1]->GetNumberOfInformationObjects(); ++i)
  {
    if (auto* occluder = vtkPolyData::GetData(inputVector[1], i))
    {
      occluders.push_back(occluder);
    }
  }
  std::string error;
  vtkApertureSurface receivers;
  std::vector<vtkApertureSurface> occluderSurfaces;
  if (!vtkApertureSurface::SetScene(input, occluders, receivers, occluderSurfaces, error))
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  vtkApertureRayScene scene;
  if (!scene.Build(receivers, occluderSurfaces))
  {
    vtkErrorMacro("Embree failed: " << scene.GetError());
    return 0;
  }

  const vtkIdType n = receivers.GetNumberOfPoints();
  const int components = this->Source == ENVIRONMENT ? 3 : 1;
  vtkNew<vtkFloatArray> irradiance;
  irradiance->SetName(this->IrradianceArrayName);
  irradiance->SetNumberOfComponents(components);
  irradiance->SetNumberOfTuples(n);
  vtkNew<vtkFloatArray> noise;
  noise->SetName(this->NoiseArrayName);
  noise->SetNumberOfComponents(components);
  noise->SetNumberOfTuples(n);
  if (this->Source == ENVIRONMENT)
  {
    // Looking one direction up builds the environment's working image before threads share it.
    double probe[3];
    const double up[3] = { 0.0, 0.0, 1.0 };
    this->Environment->Radiance(up, probe);
  }
  const Estimate estimate(this, receivers, scene.GetScene(), light, this->Environment,
    irradiance->GetPointer(0), noise->GetPointer(0));
  this->UpdateProgress(0.0);
  for (vtkIdType first = 0; first < n; first += Batch)
  {
    vtkSMPTools::For(first, std::min(n, first + Batch), 64, estimate);
    this->UpdateProgress(static_cast<double>(std::min(n, first + Batch)) / n);
    if (this->GetAbortExecute())
    {
      output->Initialize();
      return 1;
    }
  }
  const std::string embreeError = scene.GetError();
  if (!embreeError.empty())
  {
    vtkErrorMacro("Embree failed while tracing: " << embreeError);
    return 0;
  }

  output->ShallowCopy(input);
  vtkPointData* pd = output->GetPointData();
  if (receivers.NormalsComputed)
  {
    pd->SetNormals(receivers.Normals);
  }
  pd->AddArray(irradiance);
  pd->AddArray(noise);
  return 1;
}

//------------------------------------------------------------------------------
void vtkApertureReference::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  static const char* const names[] = { "LIGHT", "SKY", "ENVIRONMENT" };
  os << indent << "Source: " << names[this->Source] << "\n";
  os << indent << "LightDirection: (" << this->LightDirection[0] << ", " << this->LightDirection[1]
     << ", " << this->LightDirection[2] << ")\n";
  os << indent << "LightRadius: " << this->LightRadius << "\n";
  os << indent << "Environment: " << this->Environment << "\n";
  os << indent << "NumberOfSamples: " << this->NumberOfSamples << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "RayOffset: " << this->RayOffset << "\n";
  os << indent << "IrradianceArrayName: "
     << (this->IrradianceArrayName ? this->IrradianceArrayName : "(none)") << "\n";
  os << indent << "NoiseArrayName: " << (this->NoiseArrayName ? this->NoiseArrayName : "(none)")
     << "\n";
}
