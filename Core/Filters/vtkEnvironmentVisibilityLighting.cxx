/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkEnvironmentVisibilityLighting.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkEnvironmentVisibilityLighting.h"
#include "vtkApertureDistributedOccluders.h"

#include "vtkApertureSMP.h"
#include "vtkBitArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkEnvironmentMap.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkEnvironmentVisibilityLighting);

namespace
{
// What the input brings: a visibility matrix (values, or bits with normals) over a lightsphere.
struct Visibility
{
  vtkFloatArray* Values = nullptr;
  vtkBitArray* Bits = nullptr;
  vtkDataArray* Normals = nullptr;
  vtkDataArray* Directions = nullptr;
  vtkDataArray* Weights = nullptr;
  vtkIdType N = 0;
  int K = 0;
};

// The input's visibility matrix and lightsphere; false with an error.
bool FindVisibility(vtkObject* self, vtkPolyData* input, Visibility& v)
{
  if (!input || input->GetNumberOfPoints() == 0)
  {
    vtkErrorWithObjectMacro(self, "The input is empty: there are no points to light.");
    return false;
  }
  vtkPointData* pd = input->GetPointData();
  v.Values = vtkFloatArray::SafeDownCast(pd->GetArray("Visibility"));
  v.Bits = vtkBitArray::SafeDownCast(pd->GetAbstractArray("VisibilityBits"));
  v.Normals = pd->GetNormals();
  v.Directions = input->GetFieldData()->GetArray("LightDirections");
  v.Weights = input->GetFieldData()->GetArray("LightWeights");
  v.N = input->GetNumberOfPoints();
  v.K = v.Directions ? static_cast<int>(v.Directions->GetNumberOfTuples()) : 0;
  if (!v.Directions || !v.Weights || v.Directions->GetNumberOfComponents() != 3 ||
    v.Weights->GetNumberOfTuples() != v.K || v.K == 0)
  {
    vtkErrorWithObjectMacro(self,
      "The input has no lightsphere: it needs the field data LightDirections (k x 3) and "
      "LightWeights (k) of vtkOcclusionQueryVisibility.");
    return false;
  }
  if (v.Values &&
    (v.Values->GetNumberOfComponents() != v.K || v.Values->GetNumberOfTuples() != v.N))
  {
    vtkErrorWithObjectMacro(self,
      "The Visibility array has " << v.Values->GetNumberOfComponents() << " x "
                                  << v.Values->GetNumberOfTuples() << " values; " << v.K << " x "
                                  << v.N << " were expected.");
    return false;
  }
  if (!v.Values &&
    (!v.Bits || v.Bits->GetNumberOfComponents() != v.K || v.Bits->GetNumberOfTuples() != v.N ||
      !v.Normals || v.Normals->GetNumberOfTuples() != v.N))
  {
    vtkErrorWithObjectMacro(self,
      "The input has no visibility: it needs Visibility (k components), or VisibilityBits (k "
      "components) with point normals, of vtkOcclusionQueryVisibility.");
    return false;
  }
  return true;
}

// A latitude-longitude image on port 1; false with an error (a warning when not 2:1).
bool CheckEnvironment(vtkObject* self, vtkImageData* environment)
{
  int dims[3] = { 0, 0, 0 };
  if (environment)
  {
    environment->GetDimensions(dims);
  }
  if (!environment || !environment->GetPointData()->GetScalars() || dims[0] < 2 || dims[1] < 2)
  {
    vtkErrorWithObjectMacro(self,
      "No environment: port 1 needs a latitude-longitude image (see SetEnvironmentConnection()).");
    return false;
  }
  if (dims[0] != 2 * dims[1])
  {
    vtkWarningWithObjectMacro(self,
      "The environment is " << dims[0] << " x " << dims[1]
                            << ", not 2:1 as a latitude-longitude map is.");
  }
  return true;
}

// The turns and the exposure are finite; false with an error (NaN would light every point NaN).
bool CheckSettings(vtkEnvironmentVisibilityLighting* self)
{
  std::vector<double> values = { self->GetAzimuth(), self->GetExposure() };
  values.insert(values.end(), self->GetOrientation(), self->GetOrientation() + 9);
  values.insert(values.end(), self->GetObjectRotation(), self->GetObjectRotation() + 9);
  if (!std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); }))
  {
    vtkErrorWithObjectMacro(
      self, "Azimuth, Exposure, Orientation and ObjectRotation must be finite.");
    return false;
  }
  return true;
}

// L_j w_j / pi for every direction j: the environment's mean radiance over the direction's cell
// (the directions turned into the world by `rotation`, where the environment is).
std::vector<float> DirectionRadiance(
  vtkEnvironmentMap* environment, const double rotation[9], const Visibility& v)
{
  vtkNew<vtkDoubleArray> world, cells;
  world->SetNumberOfComponents(3);
  world->SetNumberOfTuples(v.K);
  for (int j = 0; j < v.K; ++j)
  {
    double l[3], w[3];
    v.Directions->GetTuple(j, l);
    for (int r = 0; r < 3; ++r)
    {
      w[r] = rotation[3 * r] * l[0] + rotation[3 * r + 1] * l[1] + rotation[3 * r + 2] * l[2];
    }
    world->SetTuple(j, w);
  }
  environment->CellRadiance(world, cells);
  std::vector<float> radiance(3 * v.K);
  for (int j = 0; j < v.K; ++j)
  {
    for (int c = 0; c < 3; ++c)
    {
      radiance[3 * j + c] =
        static_cast<float>(cells->GetComponent(j, c) * v.Weights->GetTuple1(j) / vtkMath::Pi());
    }
  }
  return radiance;
}

// Row i of the matrix: the stored M_ij, or max(n_i . l_j, 0) where bit (i, j) says visible
// (`unit` holds the unit directions).
void MatrixRow(const Visibility& v, const std::vector<float>& unit, vtkIdType i, float* row)
{
  if (v.Values)
  {
    std::copy_n(v.Values->GetPointer(i * v.K), v.K, row);
    return;
  }
  double normal[3];
  v.Normals->GetTuple(i, normal);
  for (int j = 0; j < v.K; ++j)
  {
    const double c =
      normal[0] * unit[3 * j] + normal[1] * unit[3 * j + 1] + normal[2] * unit[3 * j + 2];
    row[j] = v.Bits->GetValue(i * v.K + j) && c > 0.0 ? static_cast<float>(c) : 0.0f;
  }
}

// c_i = sum_j M_ij L_j w_j / pi for every point, RGB.
void Relight(const Visibility& v, const std::vector<float>& radiance, std::vector<float>& linear)
{
  std::vector<float> unit(3 * v.K);
  for (int j = 0; j < v.K; ++j)
  {
    double l[3];
    v.Directions->GetTuple(j, l);
    vtkMath::Normalize(l);
    std::copy(l, l + 3, &unit[3 * j]);
  }
  linear.assign(3 * v.N, 0.0f);
  vtkApertureSMP::For(0, v.N,
    [&](vtkIdType first, vtkIdType last)
    {
      std::vector<float> row(v.K);
      for (vtkIdType i = first; i < last; ++i)
      {
        MatrixRow(v, unit, i, row.data());
        float* sum = &linear[3 * i];
        for (int j = 0; j < v.K; ++j)
        {
          sum[0] += row[j] * radiance[3 * j];
          sum[1] += row[j] * radiance[3 * j + 1];
          sum[2] += row[j] * radiance[3 * j + 2];
        }
      }
    });
}

vtkSmartPointer<vtkFloatArray> LinearArray(const std::vector<float>& linear)
{
  auto lighting = vtkSmartPointer<vtkFloatArray>::New();
  lighting->SetName("EnvironmentLighting");
  lighting->SetNumberOfComponents(3);
  lighting->SetNumberOfTuples(static_cast<vtkIdType>(linear.size() / 3));
  std::copy(linear.begin(), linear.end(), lighting->GetPointer(0));
  return lighting;
}

// Display colours: 2^exposure times the linear values, gamma-encoded, clamped to 8 bits.
vtkSmartPointer<vtkUnsignedCharArray> ToneMap(
  const std::vector<float>& linear, double exposure, double gamma)
{
  auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colors->SetName("EnvironmentColors");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(static_cast<vtkIdType>(linear.size() / 3));
  const double scale = std::pow(2.0, exposure), inverseGamma = 1.0 / gamma;
  unsigned char* rgb = colors->GetPointer(0);
  vtkApertureSMP::For(0, static_cast<vtkIdType>(linear.size()),
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType v = first; v < last; ++v)
      {
        const double display = std::pow(std::max(0.0, linear[v] * scale), inverseGamma);
        rgb[v] = static_cast<unsigned char>(std::min(255.0, 255.0 * display + 0.5));
      }
    });
  return colors;
}
}

//------------------------------------------------------------------------------
vtkEnvironmentVisibilityLighting::vtkEnvironmentVisibilityLighting()
{
  this->SetNumberOfInputPorts(2);
}

//------------------------------------------------------------------------------
vtkEnvironmentVisibilityLighting::~vtkEnvironmentVisibilityLighting() = default;

//------------------------------------------------------------------------------
void vtkEnvironmentVisibilityLighting::SetEnvironmentConnection(vtkAlgorithmOutput* environment)
{
  this->SetInputConnection(1, environment);
}

//------------------------------------------------------------------------------
void vtkEnvironmentVisibilityLighting::SetEnvironmentData(vtkImageData* environment)
{
  this->SetInputData(1, environment);
}

//------------------------------------------------------------------------------
int vtkEnvironmentVisibilityLighting::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 0 ? "vtkPolyData" : "vtkImageData");
  if (port == 1)
  {
    // Checked in RequestData, so that a missing environment gets a clear error.
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkEnvironmentVisibilityLighting::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestUpdateExtent(request, inputVector, outputVector))
  {
    return 0;
  }
  using SDDP = vtkStreamingDemandDrivenPipeline;
  vtkInformation* environment = inputVector[1]->GetInformationObject(0);
  if (environment && environment->Has(SDDP::WHOLE_EXTENT()))
  {
    environment->Set(SDDP::UPDATE_PIECE_NUMBER(), 0);
    environment->Set(SDDP::UPDATE_NUMBER_OF_PIECES(), 1);
    environment->Set(SDDP::UPDATE_EXTENT(), environment->Get(SDDP::WHOLE_EXTENT()), 6);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkEnvironmentVisibilityLighting::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkImageData* environment = inputVector[1]->GetNumberOfInformationObjects()
    ? vtkImageData::GetData(inputVector[1])
    : nullptr;
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  const bool piece = vtkApertureDistributedOccluders::IsDistributed(
    vtkMultiProcessController::GetGlobalController(), outputVector->GetInformationObject(0));
  if (piece && (!input || input->GetNumberOfPoints() == 0))
  {
    output->Initialize(); // an empty piece of a distributed surface
    return 1;
  }
  // 1. The visibility matrix and the environment, checked.
  Visibility visibility;
  if (!CheckSettings(this) || !FindVisibility(this, input, visibility) ||
    !CheckEnvironment(this, environment))
  {
    return 0;
  }
  // 2. The linear radiance, unless only the exposure or the gamma changed.
  std::vector<double> key = { static_cast<double>(input->GetMTime()),
    static_cast<double>(environment->GetMTime()), static_cast<double>(this->UpAxis), this->Azimuth,
    this->BlurAngle };
  key.insert(key.end(), this->Orientation, this->Orientation + 9);
  key.insert(key.end(), this->ObjectRotation, this->ObjectRotation + 9);
  if (key != this->LinearFor || this->Linear.size() != static_cast<size_t>(3 * visibility.N))
  {
    this->Environment->SetImage(environment);
    this->Environment->SetUpAxis(this->UpAxis);
    this->Environment->SetAzimuth(this->Azimuth);
    this->Environment->SetOrientation(this->Orientation);
    this->Environment->SetBlurAngle(this->BlurAngle);
    Relight(visibility, DirectionRadiance(this->Environment, this->ObjectRotation, visibility),
      this->Linear);
    this->LinearFor = key;
  }
  // 3. The outputs: the input, the linear lighting and its tone-mapped colours.
  output->ShallowCopy(input);
  output->GetPointData()->AddArray(LinearArray(this->Linear));
  output->GetPointData()->AddArray(ToneMap(this->Linear, this->Exposure, this->Gamma));
  return 1;
}

//------------------------------------------------------------------------------
void vtkEnvironmentVisibilityLighting::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "UpAxis: "
     << "XYZ"[this->UpAxis] << "\n";
  os << indent << "Azimuth: " << this->Azimuth << "\n";
  os << indent << "Orientation: " << this->Orientation[0];
  for (int i = 1; i < 9; ++i)
  {
    os << ", " << this->Orientation[i];
  }
  os << "\n";
  os << indent << "BlurAngle: " << this->BlurAngle << "\n";
  os << indent << "ObjectRotation: " << this->ObjectRotation[0];
  for (int i = 1; i < 9; ++i)
  {
    os << ", " << this->ObjectRotation[i];
  }
  os << "\n";
  os << indent << "Exposure: " << this->Exposure << "\n";
  os << indent << "Gamma: " << this->Gamma << "\n";
}
