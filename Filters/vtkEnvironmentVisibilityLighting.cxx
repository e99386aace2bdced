/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkEnvironmentVisibilityLighting.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkEnvironmentVisibilityLighting.h"
#include "vtkApertureDistributedOccluders.h"

#include "vtkBitArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
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
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkEnvironmentVisibilityLighting);

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
  if (!input || input->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro("The input is empty: there are no points to light.");
    return 0;
  }
  vtkPointData* pd = input->GetPointData();
  auto* values = vtkFloatArray::SafeDownCast(pd->GetArray("Visibility"));
  auto* bits = vtkBitArray::SafeDownCast(pd->GetAbstractArray("VisibilityBits"));
  vtkDataArray* directions = input->GetFieldData()->GetArray("LightDirections");
  vtkDataArray* weights = input->GetFieldData()->GetArray("LightWeights");
  const vtkIdType n = input->GetNumberOfPoints();
  const int k = directions ? static_cast<int>(directions->GetNumberOfTuples()) : 0;
  if (!directions || !weights || directions->GetNumberOfComponents() != 3 ||
    weights->GetNumberOfTuples() != k || k == 0)
  {
    vtkErrorMacro("The input has no lightsphere: it needs the field data LightDirections (k x 3) "
                  "and LightWeights (k) of vtkOcclusionQueryVisibility.");
    return 0;
  }
  if (values && (values->GetNumberOfComponents() != k || values->GetNumberOfTuples() != n))
  {
    vtkErrorMacro("The Visibility array has " << values->GetNumberOfComponents() << " x "
                                              << values->GetNumberOfTuples() << " values; " << k
                                              << " x " << n << " were expected.");
    return 0;
  }
  vtkDataArray* normals = pd->GetNormals();
  if (!values &&
    (!bits || bits->GetNumberOfComponents() != k || bits->GetNumberOfTuples() != n || !normals ||
      normals->GetNumberOfTuples() != n))
  {
    vtkErrorMacro("The input has no visibility: it needs Visibility (k components), or "
                  "VisibilityBits (k components) with point normals, of "
                  "vtkOcclusionQueryVisibility.");
    return 0;
  }
  int dims[3] = { 0, 0, 0 };
  if (environment)
  {
    environment->GetDimensions(dims);
  }
  if (!environment || !environment->GetPointData()->GetScalars() || dims[0] < 2 || dims[1] < 2)
  {
    vtkErrorMacro("No environment: port 1 needs a latitude-longitude image (see "
                  "SetEnvironmentConnection()).");
    return 0;
  }
  if (dims[0] != 2 * dims[1])
  {
    vtkWarningMacro("The environment is " << dims[0] << " x " << dims[1]
                                          << ", not 2:1 as a latitude-longitude map is.");
  }

  // The linear radiance, unless only the exposure or the gamma changed.
  std::vector<double> key = { static_cast<double>(input->GetMTime()),
    static_cast<double>(environment->GetMTime()), static_cast<double>(this->UpAxis), this->Azimuth,
    this->BlurAngle };
  key.insert(key.end(), this->Orientation, this->Orientation + 9);
  key.insert(key.end(), this->ObjectRotation, this->ObjectRotation + 9);
  if (key != this->LinearFor || this->Linear.size() != static_cast<size_t>(3 * n))
  {
    this->Environment->SetImage(environment);
    this->Environment->SetUpAxis(this->UpAxis);
    this->Environment->SetAzimuth(this->Azimuth);
    this->Environment->SetOrientation(this->Orientation);
    this->Environment->SetBlurAngle(this->BlurAngle);
    // The directions in the world, where the environment is.
    vtkNew<vtkDoubleArray> lightDirections, cells;
    lightDirections->SetNumberOfComponents(3);
    lightDirections->SetNumberOfTuples(k);
    for (int j = 0; j < k; ++j)
    {
      double l[3], world[3];
      directions->GetTuple(j, l);
      for (int r = 0; r < 3; ++r)
      {
        world[r] = this->ObjectRotation[3 * r] * l[0] + this->ObjectRotation[3 * r + 1] * l[1] +
          this->ObjectRotation[3 * r + 2] * l[2];
      }
      lightDirections->SetTuple(j, world);
    }
    this->Environment->CellRadiance(lightDirections, cells);
    // Each direction's radiance times its solid angle, over pi.
    std::vector<float> radiance(3 * k);
    for (int j = 0; j < k; ++j)
    {
      for (int c = 0; c < 3; ++c)
      {
        radiance[3 * j + c] =
          static_cast<float>(cells->GetComponent(j, c) * weights->GetTuple1(j) / vtkMath::Pi());
      }
    }
    std::vector<float> cosines;
    if (!values)
    {
      cosines.resize(3 * k);
      for (int j = 0; j < k; ++j)
      {
        double l[3];
        directions->GetTuple(j, l);
        vtkMath::Normalize(l);
        std::copy(l, l + 3, &cosines[3 * j]);
      }
    }
    this->Linear.assign(3 * n, 0.0f);
    float* out = this->Linear.data();
    vtkSMPTools::For(0, n,
      [&](vtkIdType first, vtkIdType last)
      {
        std::vector<float> row(k);
        for (vtkIdType i = first; i < last; ++i)
        {
          if (values)
          {
            std::copy_n(values->GetPointer(i * k), k, row.data());
          }
          else
          {
            double normal[3];
            normals->GetTuple(i, normal);
            for (int j = 0; j < k; ++j)
            {
              const double c = normal[0] * cosines[3 * j] + normal[1] * cosines[3 * j + 1] +
                normal[2] * cosines[3 * j + 2];
              row[j] = bits->GetValue(i * k + j) && c > 0.0 ? static_cast<float>(c) : 0.0f;
            }
          }
          float sum[3] = { 0.0f, 0.0f, 0.0f };
          for (int j = 0; j < k; ++j)
          {
            sum[0] += row[j] * radiance[3 * j];
            sum[1] += row[j] * radiance[3 * j + 1];
            sum[2] += row[j] * radiance[3 * j + 2];
          }
          std::copy(sum, sum + 3, out + 3 * i);
        }
      });
    this->LinearFor = key;
  }

  output->ShallowCopy(input);
  vtkNew<vtkFloatArray> lighting;
  lighting->SetName("EnvironmentLighting");
  lighting->SetNumberOfComponents(3);
  lighting->SetNumberOfTuples(n);
  std::copy(this->Linear.begin(), this->Linear.end(), lighting->GetPointer(0));
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetName("EnvironmentColors");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(n);
  const double scale = std::pow(2.0, this->Exposure), inverseGamma = 1.0 / this->Gamma;
  unsigned char* rgb = colors->GetPointer(0);
  vtkSMPTools::For(0, 3 * n,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType v = first; v < last; ++v)
      {
        const double display = std::pow(std::max(0.0, this->Linear[v] * scale), inverseGamma);
        rgb[v] = static_cast<unsigned char>(std::min(255.0, 255.0 * display + 0.5));
      }
    });
  output->GetPointData()->AddArray(lighting);
  output->GetPointData()->AddArray(colors);
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
