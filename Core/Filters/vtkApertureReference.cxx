/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureReference.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureReference.h"

#include "vtkApertureDistributedOccluders.h"
#include "vtkApertureRayPacket.h"
#include "vtkApertureRaySampler.h"
#include "vtkApertureRayScene.h"
#include "vtkApertureSceneSurfaces.h"
#include "vtkApertureSurface.h"
#include "vtkApertureSurfaceOutput.h"
#include "vtkEnvironmentMap.h"
#include "vtkSphericalCap.h"

#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkApertureReference);
vtkCxxSetObjectMacro(vtkApertureReference, Environment, vtkEnvironmentMap);

namespace
{
constexpr int Lanes = vtkApertureRayPacket::Lanes;
// Points handled between two progress events.
constexpr vtkIdType Batch = 4096;

class Estimate
{
public:
  Estimate(vtkApertureReference* self, const vtkApertureSurface& surface,
    const vtkApertureRayScene& scene, const vtkApertureRaySampler& sampler, const double light[3],
    vtkEnvironmentMap* environment, float* irradiance, float* noise)
    : Surface(surface)
    , Scene(scene)
    , Sampler(sampler)
    , Environment(environment)
    , Irradiance(irradiance)
    , Noise(noise)
  {
    std::copy(light, light + 3, this->Light);
    this->Source = self->GetSource();
    const double r = vtkSphericalCap::ClampLightRadius(self->GetLightRadius());
    // The light's radiance times the cap's solid angle.
    this->LightScale =
      vtkSphericalCap::SolidAngleFromCapRadius(r) * vtkSphericalCap::LightRadiance(r);
    this->Components = this->Source == vtkApertureReference::ENVIRONMENT ? 3 : 1;
  }

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    vtkApertureRayPacket packet(this->Scene, this->Surface);
    for (vtkIdType id = begin; id < end; ++id)
    {
      this->Point(id, packet);
    }
  }

private:
  void Point(vtkIdType id, vtkApertureRayPacket& packet) const
  {
    const int c = this->Components;
    float* out = this->Irradiance + c * id;
    float* spread = this->Noise + c * id;
    if (!this->Surface.Valid[id])
    {
      std::fill(out, out + c, std::numeric_limits<float>::quiet_NaN());
      std::fill(spread, spread + c, std::numeric_limits<float>::quiet_NaN());
      return;
    }
    const float* n = this->Surface.GetNormal(id);
    const bool light = this->Source == vtkApertureReference::LIGHT;
    const float axis[3] = { static_cast<float>(light ? this->Light[0] : n[0]),
      static_cast<float>(light ? this->Light[1] : n[1]),
      static_cast<float>(light ? this->Light[2] : n[2]) };
    vtkApertureRaySampler::Point point;
    this->Sampler.Begin(axis, this->Surface.Key[id], point);
    const int samples = this->Sampler.GetNumberOfRays();
    double sum[3] = { 0, 0, 0 }, squares[3] = { 0, 0, 0 };
    double weight[Lanes][3];
    for (int first = 0; first < samples; first += Lanes)
    {
      for (int lane = 0; lane < Lanes; ++lane)
      {
        packet.Clear(lane);
        if (first + lane >= samples)
        {
          continue;
        }
        float direction[3];
        this->Sampler.Direction(point, first + lane, direction);
        const double d[3] = { direction[0], direction[1], direction[2] };
        const double cosine = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
        if (cosine <= 0.0)
        {
          continue; // below the horizon: contributes nothing
        }
        this->Weight(d, cosine, weight[lane]);
        packet.Set(lane, id, direction, std::numeric_limits<float>::infinity());
      }
      packet.Trace();
      for (int lane = 0; lane < Lanes; ++lane)
      {
        for (int k = 0; k < c && packet.Visible(lane); ++k)
        {
          sum[k] += weight[lane][k];
          squares[k] += weight[lane][k] * weight[lane][k];
        }
      }
    }
    for (int k = 0; k < c; ++k)
    {
      const double mean = sum[k] / samples;
      out[k] = static_cast<float>(mean);
      spread[k] =
        static_cast<float>(std::sqrt(std::max(0.0, squares[k] / samples - mean * mean) / samples));
    }
  }

  // What a visible sample in direction d adds: the light's radiance times the cosine (samples
  // uniform over its cap), or the sky's or environment's radiance (cosine-weighted samples).
  void Weight(const double d[3], double cosine, double w[3]) const
  {
    if (this->Source == vtkApertureReference::LIGHT)
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
  }

  const vtkApertureSurface& Surface;
  const vtkApertureRayScene& Scene;
  const vtkApertureRaySampler& Sampler;
  double Light[3];
  vtkEnvironmentMap* Environment;
  float* Irradiance;
  float* Noise;
  int Source, Components;
  double LightScale;
};

// The settings RequestData needs, and a unit `light` direction for the LIGHT source; false with
// an error.
bool CheckSettings(vtkApertureReference* self, vtkPolyData* input, double light[3])
{
  if (!input || input->GetNumberOfPoints() == 0)
  {
    vtkErrorWithObjectMacro(
      self, "The input is empty: there are no points to compute a reference for.");
    return false;
  }
  const double* given = self->GetLightDirection();
  std::copy(given, given + 3, light);
  if (self->GetSource() == vtkApertureReference::LIGHT &&
    !(std::isfinite(vtkMath::Norm(light)) && vtkMath::Normalize(light) > 0.0))
  {
    vtkErrorWithObjectMacro(self,
      "LightDirection (" << given[0] << ", " << given[1] << ", " << given[2]
                         << ") is not a direction: it must be finite and not zero.");
    return false;
  }
  vtkEnvironmentMap* environment = self->GetEnvironment();
  if (self->GetSource() == vtkApertureReference::ENVIRONMENT &&
    (!environment || !environment->GetImage()))
  {
    vtkErrorWithObjectMacro(
      self, "The ENVIRONMENT source needs an environment with an image (SetEnvironment()).");
    return false;
  }
  const char* irradiance = self->GetIrradianceArrayName();
  const char* noise = self->GetNoiseArrayName();
  if (!irradiance || !*irradiance || !noise || !*noise)
  {
    vtkErrorWithObjectMacro(
      self, "The output arrays need names (IrradianceArrayName, NoiseArrayName).");
    return false;
  }
  return true;
}

// Every surface point's estimate and noise, in batches between progress events; false with an
// error when Embree failed, `aborted` when the filter was.
bool Trace(vtkApertureReference* self, const vtkApertureSurface& receivers,
  vtkApertureRayScene& scene, const double light[3], float* irradiance, float* noise, bool& aborted)
{
  const bool fromLight = self->GetSource() == vtkApertureReference::LIGHT;
  if (self->GetSource() == vtkApertureReference::ENVIRONMENT)
  {
    // Looking one direction up builds the environment's working image before threads share it.
    double probe[3];
    const double up[3] = { 0.0, 0.0, 1.0 };
    self->GetEnvironment()->Radiance(up, probe);
  }
  const vtkApertureRaySampler sampler(self->GetNumberOfSamples(), self->GetSeed(), false,
    fromLight ? vtkApertureRaySampler::UNIFORM_CAP : vtkApertureRaySampler::COSINE_HEMISPHERE,
    vtkSphericalCap::ClampLightRadius(self->GetLightRadius()));
  const Estimate estimate(
    self, receivers, scene, sampler, light, self->GetEnvironment(), irradiance, noise);
  const vtkIdType n = receivers.GetNumberOfPoints();
  self->UpdateProgress(0.0);
  auto progress = [&](vtkIdType traced)
  {
    self->UpdateProgress(static_cast<double>(traced) / std::max<vtkIdType>(n, 1));
    return !self->GetAbortExecute();
  };
  std::string error;
  if (!scene.TraceInBatches(n, Batch, 64, estimate, progress, error))
  {
    vtkErrorWithObjectMacro(self, "Embree failed while tracing: " << error);
    return false;
  }
  aborted = self->GetAbortExecute() != 0;
  return true;
}

// The output's arrays, per output point: NaN where there is no estimate.
void WriteArrays(vtkApertureReference* self, const vtkApertureSurface& receivers,
  const std::vector<vtkIdType>& points, int components, const std::vector<float>& irradiance,
  const std::vector<float>& noise, vtkPointData* pd)
{
  const float nan[3] = { std::numeric_limits<float>::quiet_NaN(),
    std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::quiet_NaN() };
  vtkApertureSurfaceOutput::AddComputedNormals(receivers, pd, points);
  pd->AddArray(vtkApertureSurfaceOutput::Scatter(self->GetIrradianceArrayName(), components,
    irradiance.data(), irradiance.data() + irradiance.size(), points, nan, nan));
  pd->AddArray(vtkApertureSurfaceOutput::Scatter(self->GetNoiseArrayName(), components,
    noise.data(), noise.data() + noise.size(), points, nan, nan));
}
}

//------------------------------------------------------------------------------
vtkApertureReference::vtkApertureReference()
{
  this->SetNumberOfInputPorts(2);
  this->SetIrradianceArrayName("ReferenceIrradiance");
  this->SetNoiseArrayName("ReferenceNoise");
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

//------------------------------------------------------------------------------
vtkApertureReference::~vtkApertureReference()
{
  this->SetEnvironment(nullptr);
  this->SetIrradianceArrayName(nullptr);
  this->SetNoiseArrayName(nullptr);
  this->SetController(nullptr);
}

//------------------------------------------------------------------------------
vtkCxxSetObjectMacro(vtkApertureReference, Controller, vtkMultiProcessController);

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
  // A distributed run: the other ranks' surfaces occlude too (collective, before any check).
  vtkSmartPointer<vtkPolyData> remote, ghosts;
  if (vtkApertureDistributedOccluders::GatherForPiece(
        this->Controller, outputVector->GetInformationObject(0), input, remote, ghosts) &&
    (!input || input->GetNumberOfPoints() == 0))
  {
    output->Initialize(); // an empty piece
    return 1;
  }
  // 1. The settings and the surfaces, checked; one Embree scene.
  double light[3];
  if (!CheckSettings(this, input, light))
  {
    return 0;
  }
  std::string error;
  vtkApertureSurface receivers;
  std::vector<vtkApertureSurface> occluderSurfaces;
  vtkApertureSceneSurfaces::Settings settings;
  settings.FeatureAngle = this->FeatureAngle;
  settings.RayOffset = this->RayOffset;
  if (!vtkApertureSceneSurfaces::Build(input, ghosts,
        vtkApertureDistributedOccluders::Occluders(inputVector[1], remote), settings, receivers,
        occluderSurfaces, error))
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
  // 2. The estimates of every surface point, in batches between progress events.
  const int components = this->Source == ENVIRONMENT ? 3 : 1;
  std::vector<float> irradiance(components * receivers.GetNumberOfPoints());
  std::vector<float> noise(irradiance.size());
  bool aborted = false;
  if (!Trace(this, receivers, scene, light, irradiance.data(), noise.data(), aborted) || aborted)
  {
    output->Initialize();
    return aborted ? 1 : 0;
  }
  // 3. The arrays on the output's points (split at creases).
  std::vector<vtkIdType> points;
  vtkApertureSurfaceOutput::Make(receivers, input, output, points);
  WriteArrays(this, receivers, points, components, irradiance, noise, output->GetPointData());
  return 1;
}

//------------------------------------------------------------------------------
void vtkApertureReference::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  static const char* const names[] = { "LIGHT", "SKY", "ENVIRONMENT" };
  os << indent << "Source: " << names[this->Source] << "\n";
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "LightDirection: (" << this->LightDirection[0] << ", " << this->LightDirection[1]
     << ", " << this->LightDirection[2] << ")\n";
  os << indent << "LightRadius: " << this->LightRadius << "\n";
  os << indent << "Environment: " << this->Environment << "\n";
  os << indent << "NumberOfSamples: " << this->NumberOfSamples << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "RayOffset: " << this->RayOffset << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "IrradianceArrayName: "
     << (this->IrradianceArrayName ? this->IrradianceArrayName : "(none)") << "\n";
  os << indent << "NoiseArrayName: " << (this->NoiseArrayName ? this->NoiseArrayName : "(none)")
     << "\n";
}
