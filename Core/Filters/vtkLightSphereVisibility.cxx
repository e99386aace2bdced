/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkLightSphereVisibility.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkLightSphereVisibility.h"

#include "vtkApertureDistributedOccluders.h"
#include "vtkApertureSceneSurfaces.h"
#include "vtkApertureSurface.h"
#include "vtkApertureSurfaceOutput.h"
#include "vtkLightSphere.h"
#include "vtkRayCastVisibility.h"

#include "vtkApertureSMP.h"
#include "vtkBitArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cstring>

vtkStandardNewMacro(vtkLightSphereVisibility);
vtkCxxSetObjectMacro(vtkLightSphereVisibility, Controller, vtkMultiProcessController);

//------------------------------------------------------------------------------
class vtkLightSphereVisibility::vtkInternals
{
public:
  // What everything below was computed for: the geometry and the settings.
  std::vector<vtkMTimeType> Key;
  vtkApertureSurface Receivers;
  std::vector<vtkApertureSurface> Occluders;
  // One bit set of points per direction, in lightsphere order; point i's bits hold for its first
  // Done[i] directions.
  std::vector<Bits> Computed;
  std::vector<int> Done;
  // The receiving points that need visibility in this update.
  std::vector<unsigned char> Needed;
  // The Embree scene lasts as long as the geometry: later updates (a higher level, vertex
  // filtering) reuse it.
  vtkRayCastVisibility RayCast;
};

//------------------------------------------------------------------------------
vtkLightSphereVisibility::vtkLightSphereVisibility()
  : Internals(new vtkInternals)
{
  this->SetNumberOfInputPorts(2);
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

//------------------------------------------------------------------------------
vtkLightSphereVisibility::~vtkLightSphereVisibility()
{
  this->SetController(nullptr);
}

//------------------------------------------------------------------------------
void vtkLightSphereVisibility::AddOccluderConnection(vtkAlgorithmOutput* occluder)
{
  this->AddInputConnection(1, occluder);
}

//------------------------------------------------------------------------------
void vtkLightSphereVisibility::RemoveAllOccluders()
{
  this->SetInputConnection(1, nullptr);
}

//------------------------------------------------------------------------------
int vtkLightSphereVisibility::FillInputPortInformation(int port, vtkInformation* info)
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
const vtkApertureSurface& vtkLightSphereVisibility::GetReceivers() const
{
  return this->Internals->Receivers;
}

//------------------------------------------------------------------------------
const std::vector<vtkApertureSurface>& vtkLightSphereVisibility::GetOccluders() const
{
  return this->Internals->Occluders;
}

//------------------------------------------------------------------------------
std::vector<unsigned char>& vtkLightSphereVisibility::GetNeededPoints()
{
  return this->Internals->Needed;
}

//------------------------------------------------------------------------------
void vtkLightSphereVisibility::ForgetComputed()
{
  this->Internals->Key.clear();
}

//------------------------------------------------------------------------------
bool vtkLightSphereVisibility::CheckSettings(std::string&)
{
  return true;
}

//------------------------------------------------------------------------------
void vtkLightSphereVisibility::AppendCacheKey(std::vector<vtkMTimeType>& key)
{
  auto bitsOf = [](double value)
  {
    vtkMTimeType bits = 0;
    std::memcpy(&bits, &value, std::min(sizeof(bits), sizeof(value)));
    return bits;
  };
  key.push_back(bitsOf(this->RayOffset));
  key.push_back(bitsOf(this->FeatureAngle));
}

//------------------------------------------------------------------------------
bool vtkLightSphereVisibility::SelectPoints(std::string&)
{
  return true;
}

//------------------------------------------------------------------------------
bool vtkLightSphereVisibility::LeavesPointsOut()
{
  return false;
}

//------------------------------------------------------------------------------
bool vtkLightSphereVisibility::ComputeDirections(const Directions& directions,
  const std::vector<std::uint32_t>& points, std::vector<Bits>& visible,
  const std::function<bool(size_t)>& progress, std::string& error)
{
  vtkInternals& in = *this->Internals;
  if (!in.RayCast.HasScene() && !in.RayCast.SetScene(in.Receivers, in.Occluders, error))
  {
    return false;
  }
  return in.RayCast.Cast(directions, points, visible, progress, error);
}

//------------------------------------------------------------------------------
// Visibility computed before for the same geometry and settings is kept: a higher level adds its
// new directions, a backend's point selection adds the points it newly needs.
bool vtkLightSphereVisibility::UpdateCache(vtkPolyData* input, vtkPolyData* ghosts,
  const std::vector<vtkPolyData*>& occluders, std::string& error)
{
  vtkInternals& in = *this->Internals;
  std::vector<vtkMTimeType> key = { input->GetMTime() };
  this->AppendCacheKey(key);
  for (vtkPolyData* occluder : occluders)
  {
    key.push_back(occluder->GetMTime());
  }
  if (key == in.Key)
  {
    return true;
  }
  in.Key.clear();
  vtkApertureSceneSurfaces::Settings settings;
  settings.FeatureAngle = this->FeatureAngle;
  settings.RayOffset = this->RayOffset;
  if (!vtkApertureSceneSurfaces::Build(
        input, ghosts, occluders, settings, in.Receivers, in.Occluders, error))
  {
    return false;
  }
  const vtkIdType n = in.Receivers.GetNumberOfPoints();
  in.RayCast.ReleaseScene();
  in.Computed.clear();
  in.Done.assign(n, 0);
  in.Needed.assign(n, 1);
  this->SurfacesChanged();
  in.Key = key;
  return true;
}

//------------------------------------------------------------------------------
bool vtkLightSphereVisibility::ComputeMissing(
  const Directions& directions, bool& aborted, std::string& error)
{
  vtkInternals& in = *this->Internals;
  const vtkIdType n = in.Receivers.GetNumberOfPoints();
  const int k = static_cast<int>(directions.size());
  if (in.Computed.size() < directions.size())
  {
    in.Computed.resize(k, Bits((n + 63) / 64, 0));
  }
  // The points that need directions, and the first direction one of them lacks.
  std::vector<std::uint32_t> todo;
  int first = k;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (in.Needed[i] && in.Done[i] < k)
    {
      todo.push_back(static_cast<std::uint32_t>(i));
      first = std::min(first, in.Done[i]);
    }
  }
  aborted = false;
  if (todo.empty())
  {
    return true;
  }
  const Directions missing(directions.begin() + first, directions.end());
  auto progress = [&](size_t done)
  {
    this->UpdateProgress(static_cast<double>(done) / missing.size());
    return !this->GetAbortExecute();
  };
  std::vector<Bits> fresh;
  const bool ok = this->ComputeDirections(missing, todo, fresh, progress, error);
  aborted = this->GetAbortExecute() != 0;
  if (!ok || aborted)
  {
    return aborted;
  }
  // New bits are or-ed in: a point given a direction again gets the same bit.
  for (size_t j = 0; j < fresh.size(); ++j)
  {
    Bits& bits = in.Computed[first + j];
    for (size_t w = 0; w < bits.size(); ++w)
    {
      bits[w] |= fresh[j][w];
    }
  }
  for (std::uint32_t i : todo)
  {
    in.Done[i] = k;
  }
  this->NumberOfComputedPoints = static_cast<vtkIdType>(todo.size());
  return true;
}

namespace
{
using Bits = std::vector<std::uint64_t>;

// Output point o sees direction j when its receiving point is above its tangent plane and has
// its bit set; `cosine` gets n . l.
struct Sees
{
  const vtkApertureSurface& Receivers;
  const std::vector<vtkIdType>& Points; // each output point's receiving point, or -1
  const std::vector<int>& Done;         // directions computed per receiving point
  const std::vector<Bits>& Computed;
  const std::vector<std::array<double, 3>>& Directions;

  bool operator()(vtkIdType o, int j, double& cosine) const
  {
    const vtkIdType i = this->Points[o];
    if (i < 0 || !this->Receivers.Valid[i] || j >= this->Done[i])
    {
      return false;
    }
    const float* n = this->Receivers.GetNormal(i);
    const auto& l = this->Directions[j];
    cosine = n[0] * l[0] + n[1] * l[1] + n[2] * l[2];
    return cosine > 0.0 && ((this->Computed[j][i / 64] >> (i % 64)) & 1u);
  }
};

// M_oj = max(n . l_j, 0) where output point o sees direction j.
vtkSmartPointer<vtkFloatArray> VisibilityArray(const Sees& sees, vtkIdType m, int k)
{
  auto visibility = vtkSmartPointer<vtkFloatArray>::New();
  visibility->SetName("Visibility");
  visibility->SetNumberOfComponents(k);
  visibility->SetNumberOfTuples(m);
  float* values = visibility->GetPointer(0);
  vtkApertureSMP::For(0, m,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType o = begin; o < end; ++o)
      {
        for (int j = 0; j < k; ++j)
        {
          double c = 0.0;
          values[o * k + j] = sees(o, j, c) ? static_cast<float>(c) : 0.0f;
        }
      }
    });
  return visibility;
}

// The raw visibility, one bit per output point and direction, a byte at a time on every core
// (vtkBitArray's order: value v is bit 0x80 >> v % 8 of byte v / 8; the last byte's unused bits
// 0).
vtkSmartPointer<vtkBitArray> VisibilityBitsArray(const Sees& sees, vtkIdType m, int k)
{
  auto bits = vtkSmartPointer<vtkBitArray>::New();
  bits->SetName("VisibilityBits");
  bits->SetNumberOfComponents(k);
  bits->SetNumberOfTuples(m);
  const vtkIdType values = m * k;
  unsigned char* bytes = bits->GetPointer(0);
  vtkApertureSMP::For(0, (values + 7) / 8,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType b = begin; b < end; ++b)
      {
        unsigned char byte = 0;
        for (vtkIdType v = 8 * b; v < std::min(8 * b + 8, values); ++v)
        {
          double c = 0.0;
          byte |= sees(v / k, static_cast<int>(v % k), c) ? 0x80 >> (v % 8) : 0;
        }
        bytes[b] = byte;
      }
    });
  bits->DataChanged();
  return bits;
}

// Which output points have their visibility yet (points a backend left out have none).
vtkSmartPointer<vtkUnsignedCharArray> ComputedArray(const Sees& sees, vtkIdType m, int k)
{
  auto done = vtkSmartPointer<vtkUnsignedCharArray>::New();
  done->SetName("VisibilityComputed");
  done->SetNumberOfTuples(m);
  for (vtkIdType o = 0; o < m; ++o)
  {
    done->SetValue(o, sees.Points[o] >= 0 && sees.Done[sees.Points[o]] >= k ? 1 : 0);
  }
  return done;
}
}

//------------------------------------------------------------------------------
// The output: the input's points (split where creases split them) with the arrays, and the
// lightsphere in the field data.
void vtkLightSphereVisibility::WriteOutputs(
  vtkPolyData* input, vtkPolyData* output, vtkLightSphere* sphere, const Directions& directions)
{
  vtkInternals& in = *this->Internals;
  const int k = static_cast<int>(directions.size());
  std::vector<vtkIdType> points;
  vtkApertureSurfaceOutput::Make(in.Receivers, input, output, points);
  const vtkIdType m = static_cast<vtkIdType>(points.size());
  vtkPointData* pd = output->GetPointData();
  vtkApertureSurfaceOutput::AddComputedNormals(in.Receivers, pd, points);
  const Sees sees{ in.Receivers, points, in.Done, in.Computed, directions };
  if (this->ComputeVisibility)
  {
    pd->AddArray(VisibilityArray(sees, m, k));
  }
  if (this->ComputeVisibilityBits)
  {
    pd->AddArray(VisibilityBitsArray(sees, m, k));
  }
  if (this->LeavesPointsOut())
  {
    pd->AddArray(ComputedArray(sees, m, k));
  }
  vtkSmartPointer<vtkDoubleArray> lightDirections;
  lightDirections.TakeReference(sphere->NewDirections());
  vtkSmartPointer<vtkDoubleArray> lightWeights;
  lightWeights.TakeReference(sphere->NewWeights());
  vtkNew<vtkFieldData> fields;
  fields->ShallowCopy(input->GetFieldData());
  fields->AddArray(lightDirections);
  fields->AddArray(lightWeights);
  output->SetFieldData(fields);
}

//------------------------------------------------------------------------------
int vtkLightSphereVisibility::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->NumberOfComputedPoints = 0;
  // A distributed run: the other ranks' surfaces occlude too (collective, before any check).
  vtkSmartPointer<vtkPolyData> remote, ghosts;
  if (vtkApertureDistributedOccluders::GatherForPiece(
        this->Controller, outputVector->GetInformationObject(0), input, remote, ghosts) &&
    (!input || input->GetNumberOfPoints() == 0))
  {
    output->Initialize(); // an empty piece
    return 1;
  }
  if (!input || input->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro("The input is empty: there are no points to compute visibility for.");
    return 0;
  }
  std::string error;
  // 1. The settings, the surfaces, and what is kept of earlier updates; 2. the points needed.
  if (!this->CheckSettings(error) ||
    !this->UpdateCache(
      input, ghosts, vtkApertureDistributedOccluders::Occluders(inputVector[1], remote), error))
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  if (!this->SelectPoints(error))
  {
    vtkErrorMacro(<< error);
    this->ForgetComputed();
    return 0;
  }
  // 3. The directions of the level that points lack.
  vtkNew<vtkLightSphere> sphere;
  sphere->SetLevel(this->Level);
  Directions directions(sphere->GetNumberOfDirections());
  for (size_t j = 0; j < directions.size(); ++j)
  {
    sphere->GetDirection(static_cast<int>(j), directions[j].data());
  }
  this->UpdateProgress(0.0);
  bool aborted = false;
  if (!this->ComputeMissing(directions, aborted, error))
  {
    vtkErrorMacro(<< error);
    this->ForgetComputed();
    return 0;
  }
  if (aborted)
  {
    output->Initialize();
    return 1;
  }
  // 4. The output, and a word on points left out.
  this->WriteOutputs(input, output, sphere, directions);
  if (this->Internals->Receivers.UnusablePoints > 0)
  {
    vtkWarningMacro(
      << this->Internals->Receivers.UnusablePoints
      << " point(s) are not finite (NaN, infinite or larger than 1e16); they see nothing, and no "
         "cell that uses them casts shadows.");
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkLightSphereVisibility::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Level: " << this->Level << "\n";
  os << indent << "RayOffset: " << this->RayOffset << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "ComputeVisibility: " << (this->ComputeVisibility ? "On" : "Off") << "\n";
  os << indent << "ComputeVisibilityBits: " << (this->ComputeVisibilityBits ? "On" : "Off") << "\n";
  os << indent << "Controller: " << this->Controller << "\n";
  os << indent << "NumberOfComputedPoints: " << this->NumberOfComputedPoints << "\n";
}
