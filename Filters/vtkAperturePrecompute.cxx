/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkAperturePrecompute.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkAperturePrecompute.h"

#include "vtkApertureHemisphereSampler.h"
#include "vtkApertureRayScene.h"
#include "vtkApertureSurface.h"
#include "vtkSphericalCap.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSetAttributes.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#if defined(__SSE__) || defined(_M_X64)
#endif

vtkStandardNewMacro(vtkAperturePrecompute);

namespace
{
constexpr double Pi = vtkMath::Pi();
constexpr int Lanes = vtkApertureHemisphereSampler::Lanes;

// Where the results of one receiver go.
struct Outputs
{
  float* BentNormal;
  float* ApertureRadius;
  float* AmbientOcclusion; // may be null
};

// Casts the rays of a range of points of one surface and writes their caps.
class CastRays
{
public:
  CastRays(const vtkApertureSurface& surface, RTCScene scene,
    const vtkApertureHemisphereSampler& sampler, float maximumDistance, Outputs outputs)
    : Surface(surface)
    , Scene(scene)
    , Sampler(sampler)
    , MaximumDistance(maximumDistance)
    , Out(outputs)
  {
  }

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    vtkApertureRayScene::FlushToZero ftz;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    alignas(64) RTCRay16 ray;
    alignas(64) int valid[Lanes];
    const int n = this->Sampler.GetNumberOfRays();
    vtkApertureHemisphereSampler::Point point;

    for (vtkIdType id = begin; id < end; ++id)
    {
      const float* nrm = this->Surface.GetNormal(id);
      if (!this->Surface.Receives[id] || !this->Surface.Valid[id])
      {
        // Points outside polygons are left open; invalid ones are closed.
        const bool open = !this->Surface.Receives[id];
        const bool hasNormal = this->Surface.Valid[id];
        for (int k = 0; k < 3; ++k)
        {
          this->Out.BentNormal[3 * id + k] = (open && hasNormal) ? nrm[k] : (k == 2 ? 1.0f : 0.0f);
        }
        this->Out.ApertureRadius[id] = open ? static_cast<float>(0.5 * Pi) : 0.0f;
        if (this->Out.AmbientOcclusion)
        {
          this->Out.AmbientOcclusion[id] = open ? 1.0f : 0.0f;
        }
        continue;
      }

      this->Sampler.Begin(this->Surface, id, point);
      int visible = 0;
      double sum[3] = { 0.0, 0.0, 0.0 };
      double cosSum = 0.0;
      for (int first = 0; first < n; first += Lanes)
      {
        this->Sampler.Fill(point, first, this->MaximumDistance, ray, valid);
        rtcOccluded16(valid, this->Scene, &context, &ray);
        for (int lane = 0; lane < Lanes; ++lane)
        {
          // Occluded rays come back with tfar = -inf.
          if (valid[lane] && ray.tfar[lane] >= 0.0f)
          {
            ++visible;
            sum[0] += ray.dir_x[lane];
            sum[1] += ray.dir_y[lane];
            sum[2] += ray.dir_z[lane];
            cosSum +=
              ray.dir_x[lane] * nrm[0] + ray.dir_y[lane] * nrm[1] + ray.dir_z[lane] * nrm[2];
          }
        }
      }

      const double solidAngle = 2.0 * Pi * visible / n;
      this->Out.ApertureRadius[id] =
        static_cast<float>(vtkSphericalCap::CapRadiusFromSolidAngle(solidAngle));
      const double length = vtkMath::Norm(sum);
      for (int k = 0; k < 3; ++k)
      {
        // A closed aperture keeps the normal as its (defined) axis.
        this->Out.BentNormal[3 * id + k] =
          length > 0.0 ? static_cast<float>(sum[k] / length) : nrm[k];
      }
      if (this->Out.AmbientOcclusion)
      {
        // Uniform hemisphere samples: (1/pi) * integral of V cos = (2/n) * sum of V cos.
        this->Out.AmbientOcclusion[id] = static_cast<float>(std::min(1.0, 2.0 * cosSum / n));
      }
    }
  }

private:
  const vtkApertureSurface& Surface;
  RTCScene Scene;
  const vtkApertureHemisphereSampler& Sampler;
  float MaximumDistance;
  Outputs Out;
};

// One dataset that gets caps: the input leaf, its output, and its surface.
struct Receiver
{
  vtkDataSet* Input;
  vtkDataSet* Output;
  vtkDataArray* Heights; // height fields only
  vtkApertureSurface Surface;
};

vtkSmartPointer<vtkFloatArray> NewArray(const std::string& name, int components, vtkIdType n)
{
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  array->SetName(name.c_str());
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(n);
  return array;
}
}

//------------------------------------------------------------------------------
vtkAperturePrecompute::vtkAperturePrecompute()
{
  this->SetNumberOfInputPorts(2);
  // Height fields: heights are the active point scalars unless another array is chosen.
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
}

//------------------------------------------------------------------------------
vtkAperturePrecompute::~vtkAperturePrecompute() = default;

//------------------------------------------------------------------------------
void vtkAperturePrecompute::AddOccluderConnection(vtkAlgorithmOutput* output)
{
  this->AddInputConnection(1, output);
}

//------------------------------------------------------------------------------
void vtkAperturePrecompute::AddOccluderData(vtkDataObject* data)
{
  this->AddInputDataInternal(1, data);
}

//------------------------------------------------------------------------------
void vtkAperturePrecompute::RemoveAllOccluders()
{
  this->SetInputConnection(1, nullptr);
}

//------------------------------------------------------------------------------
int vtkAperturePrecompute::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkAperturePrecompute::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkDataObject* output = vtkDataObject::GetData(outputVector, 0);
  if (!input || !output)
  {
    vtkErrorMacro("Missing input or output.");
    return 0;
  }
  auto fail = [output]()
  {
    output->Initialize();
    return 0;
  };

  // Receivers: the input itself, or every non-empty leaf of a composite input.
  std::vector<std::unique_ptr<Receiver>> receivers;
  auto addReceiver = [&](vtkDataSet* in, vtkDataSet* out) {
    receivers.emplace_back(new Receiver{ in, out, nullptr, {} });
  };
  if (auto* compositeIn = vtkCompositeDataSet::SafeDownCast(input))
  {
    auto* compositeOut = vtkCompositeDataSet::SafeDownCast(output);
    compositeOut->CopyStructure(compositeIn);
    auto it = vtk::TakeSmartPointer(compositeIn->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      auto* leaf = vtkPolyData::SafeDownCast(it->GetCurrentDataObject());
      if (!leaf)
      {
        vtkErrorMacro("Composite input must hold vtkPolyData leaves, found "
          << it->GetCurrentDataObject()->GetClassName() << ".");
        return fail();
      }
      auto copy = vtkSmartPointer<vtkPolyData>::New();
      copy->ShallowCopy(leaf);
      compositeOut->SetDataSet(it, copy);
      addReceiver(leaf, copy);
    }
  }
  else
  {
    output->ShallowCopy(input);
    addReceiver(vtkDataSet::SafeDownCast(input), vtkDataSet::SafeDownCast(output));
  }

  // Check the input before any work.
  vtkIdType surfaceCells = 0;
  vtkIdType totalPoints = 0;
  for (const auto& r : receivers)
  {
    totalPoints += r->Input->GetNumberOfPoints();
    if (auto* image = vtkImageData::SafeDownCast(r->Input))
    {
      const int* dims = image->GetDimensions();
      if (dims[2] != 1 || dims[0] < 2 || dims[1] < 2)
      {
        vtkErrorMacro("A height field must be a 2D grid of at least 2 x 2 points in the xy "
                      "plane of its index space; got dimensions "
          << dims[0] << " x " << dims[1] << " x " << dims[2] << ".");
        return fail();
      }
      r->Heights = this->GetInputArrayToProcess(0, image);
      if (!r->Heights)
      {
        vtkErrorMacro("The height field has no point scalars (or no array to process).");
        return fail();
      }
      if (r->Heights->GetNumberOfComponents() != 1 ||
        r->Heights->GetNumberOfTuples() != image->GetNumberOfPoints())
      {
        vtkErrorMacro("Height field scalars '"
          << (r->Heights->GetName() ? r->Heights->GetName() : "") << "' must have one component "
          << "and one value per point; they have " << r->Heights->GetNumberOfComponents()
          << " component(s) and " << r->Heights->GetNumberOfTuples() << " tuples.");
        return fail();
      }
      surfaceCells += image->GetNumberOfCells();
    }
    else if (auto* poly = vtkPolyData::SafeDownCast(r->Input))
    {
      surfaceCells += poly->GetNumberOfPolys() + poly->GetNumberOfStrips();
    }
  }
  if (totalPoints == 0)
  {
    vtkErrorMacro("The input is empty: there are no points to compute apertures for.");
    return fail();
  }
  if (surfaceCells == 0)
  {
    vtkErrorMacro("The input has no polygons or triangle strips: nothing casts or receives rays.");
    return fail();
  }

  // Occluders on port 1.
  std::vector<vtkPolyData*> occluders;
  for (int i = 0; i < inputVector[1]->GetNumberOfInformationObjects(); ++i)
  {
    if (auto* occluder = vtkPolyData::GetData(inputVector[1], i))
    {
      occluders.push_back(occluder);
    }
  }

  // One local origin for everything keeps single precision where the geometry is.
  double bounds[6];
  vtkApertureSurface::InitializeBounds(bounds);
  for (const auto& r : receivers)
  {
    if (auto* image = vtkImageData::SafeDownCast(r->Input))
    {
      vtkApertureSurface::ExpandBounds(image, r->Heights, this->HeightScale, bounds);
    }
    else
    {
      vtkApertureSurface::ExpandBounds(vtkPolyData::SafeDownCast(r->Input), bounds);
    }
  }
  for (vtkPolyData* occluder : occluders)
  {
    vtkApertureSurface::ExpandBounds(occluder, bounds);
  }
  double origin[3];
  vtkApertureSurface::OriginOf(bounds, origin);

  std::string error;
  for (const auto& r : receivers)
  {
    auto* image = vtkImageData::SafeDownCast(r->Input);
    const bool ok = image
      ? r->Surface.SetHeightField(image, r->Heights, this->HeightScale, origin, error)
      : r->Surface.SetPolyData(vtkPolyData::SafeDownCast(r->Input), origin, error);
    if (!ok)
    {
      vtkErrorMacro("Cannot use the input: " << error << ".");
      return fail();
    }
  }
  std::vector<vtkApertureSurface> occluderSurfaces(occluders.size());
  for (size_t i = 0; i < occluders.size(); ++i)
  {
    if (!occluderSurfaces[i].SetPolyData(occluders[i], origin, error))
    {
      vtkErrorMacro("Cannot use occluder " << i << ": " << error << ".");
      return fail();
    }
  }

  vtkApertureRayScene scene;
  bool built = scene.Initialize(this->EmbreeConfiguration, this->CompactAccelerationStructure);
  for (const auto& r : receivers)
  {
    built = built && scene.AddSurface(r->Surface);
  }
  for (const auto& s : occluderSurfaces)
  {
    built = built && scene.AddSurface(s);
  }
  built = built && scene.Commit();
  if (!built)
  {
    vtkErrorMacro("Embree failed: " << scene.GetError());
    return fail();
  }

  // Rays, in batches of about a million so that progress and aborts are seen often.
  const vtkApertureHemisphereSampler sampler(
    this->NumberOfRays, this->Seed, this->Sampling == RANDOM, this->RayOffset);
  const vtkIdType batch = std::max<vtkIdType>(64, (1 << 20) / this->NumberOfRays);
  const float maximumDistance = this->MaximumDistance >= FLT_MAX
    ? std::numeric_limits<float>::infinity()
    : static_cast<float>(this->MaximumDistance);
  vtkIdType done = 0;
  vtkIdType nonFinite = 0, undefinedNormals = 0, flipped = 0;
  this->UpdateProgress(0.0);
  for (const auto& receiver : receivers)
  {
    Receiver& r = *receiver;
    const vtkIdType n = r.Surface.GetNumberOfPoints();
    auto bent = NewArray(this->BentNormalArrayName, 3, n);
    auto radius = NewArray(this->ApertureRadiusArrayName, 1, n);
    auto occlusion =
      this->ComputeAmbientOcclusion ? NewArray(this->AmbientOcclusionArrayName, 1, n) : nullptr;
    const Outputs outputs = { bent->GetPointer(0), radius->GetPointer(0),
      occlusion ? occlusion->GetPointer(0) : nullptr };
    // Rays depend on the seed and the point id only: a leaf of a composite dataset gets the same
    // rays as the same mesh run alone.
    const CastRays cast(r.Surface, scene.GetScene(), sampler, maximumDistance, outputs);
    for (vtkIdType first = 0; first < n; first += batch)
    {
      vtkSMPTools::For(first, std::min(n, first + batch), 16, cast);
      done += std::min(batch, n - first);
      this->UpdateProgress(static_cast<double>(done) / totalPoints);
      if (this->GetAbortExecute())
      {
        output->Initialize();
        return 1;
      }
    }

    vtkPointData* pd = r.Output->GetPointData();
    pd->AddArray(bent);
    pd->AddArray(radius);
    if (occlusion)
    {
      pd->AddArray(occlusion);
    }
    if (r.Surface.NormalsComputed)
    {
      pd->SetNormals(r.Surface.Normals);
    }
    nonFinite += r.Surface.NonFinitePoints;
    undefinedNormals += r.Surface.UndefinedNormals;
    flipped += r.Surface.FlippedNormals;
  }

  const std::string embreeError = scene.GetError();
  if (!embreeError.empty())
  {
    vtkErrorMacro("Embree failed while tracing: " << embreeError);
    return fail();
  }
  if (nonFinite > 0)
  {
    vtkWarningMacro(<< nonFinite
                    << " point(s) are not finite (NaN or infinite); they get a "
                       "closed aperture and no cell that uses them casts shadows.");
  }
  if (undefinedNormals > 0)
  {
    vtkWarningMacro(<< undefinedNormals
                    << " point(s) have no defined normal (only degenerate "
                       "cells use them); they get a closed aperture.");
  }
  if (flipped > 0)
  {
    vtkWarningMacro(<< flipped
                    << " given normal(s) point against the winding of their cells; "
                       "their apertures face the way the normals do.");
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkAperturePrecompute::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfRays: " << this->NumberOfRays << "\n";
  os << indent << "MaximumDistance: " << this->MaximumDistance << "\n";
  os << indent << "RayOffset: " << this->RayOffset << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "Sampling: " << (this->Sampling == RANDOM ? "Random" : "Stratified") << "\n";
  os << indent << "HeightScale: " << this->HeightScale << "\n";
  os << indent << "ComputeAmbientOcclusion: " << this->ComputeAmbientOcclusion << "\n";
  os << indent << "BentNormalArrayName: " << this->BentNormalArrayName << "\n";
  os << indent << "ApertureRadiusArrayName: " << this->ApertureRadiusArrayName << "\n";
  os << indent << "AmbientOcclusionArrayName: " << this->AmbientOcclusionArrayName << "\n";
  os << indent << "CompactAccelerationStructure: " << this->CompactAccelerationStructure << "\n";
  os << indent << "EmbreeConfiguration: " << this->EmbreeConfiguration << "\n";
  os << indent << "NumberOfOccluders: " << this->GetNumberOfInputConnections(1) << "\n";
}
