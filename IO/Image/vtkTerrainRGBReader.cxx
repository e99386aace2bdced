/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkTerrainRGBReader.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTerrainRGBReader.h"

#include "vtkApertureText.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPNGReader.h"
#include "vtkPNGValidator.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

vtkStandardNewMacro(vtkTerrainRGBReader);

//------------------------------------------------------------------------------
vtkTerrainRGBReader::vtkTerrainRGBReader()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
void vtkTerrainRGBReader::SetMemoryBuffer(const void* buffer)
{
  if (this->MemoryBuffer != buffer)
  {
    this->MemoryBuffer = buffer;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPNGReader> vtkTerrainRGBReader::MakePNGReader()
{
  // vtkPNGReader crashes on PNGs that libpng cannot decode: check them first.
  const std::string problem = this->MemoryBuffer
    ? vtkPNGValidator::CheckBuffer(
        this->MemoryBuffer, static_cast<size_t>(this->MemoryBufferLength))
    : vtkPNGValidator::CheckFile(this->FileName.c_str());
  if (!problem.empty())
  {
    vtkErrorMacro(<< (this->MemoryBuffer ? "The memory buffer " : "Terrain-RGB file ") << problem
                  << ".");
    return nullptr;
  }
  auto png = vtkSmartPointer<vtkPNGReader>::New();
  if (this->MemoryBuffer)
  {
    png->SetMemoryBuffer(this->MemoryBuffer);
    png->SetMemoryBufferLength(this->MemoryBufferLength);
  }
  else
  {
    png->SetFileName(this->FileName.c_str());
  }
  return png;
}

//------------------------------------------------------------------------------
int vtkTerrainRGBReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkSmartPointer<vtkPNGReader> png = this->MakePNGReader();
  if (!png)
  {
    return 0;
  }
  png->UpdateInformation();
  int extent[6];
  png->GetDataExtent(extent);
  vtkInformation* info = outputVector->GetInformationObject(0);
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  const double spacing[3] = { this->Spacing[0], this->Spacing[1], 1.0 };
  info->Set(vtkDataObject::SPACING(), spacing, 3);
  info->Set(vtkDataObject::ORIGIN(), this->Origin, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(info, VTK_FLOAT, 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkTerrainRGBReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector);
  vtkSmartPointer<vtkPNGReader> png = this->MakePNGReader();
  if (!png)
  {
    return 0;
  }
  png->Update();
  vtkImageData* image = png->GetOutput();
  auto* rgb = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  const std::string source = this->MemoryBuffer ? std::string("The memory buffer")
                                                : vtkApertureText::QuoteName(this->FileName);
  if (!rgb || rgb->GetNumberOfComponents() < 3)
  {
    vtkErrorMacro(<< source
                  << " is not a Terrain-RGB tile: it needs at least three 8-bit channels.");
    return 0;
  }

  output->SetExtent(image->GetExtent());
  output->SetSpacing(this->Spacing[0], this->Spacing[1], 1.0);
  output->SetOrigin(this->Origin);
  const vtkIdType n = rgb->GetNumberOfTuples();
  vtkNew<vtkFloatArray> heights;
  heights->SetName("Elevation");
  heights->SetNumberOfTuples(n);
  const int components = rgb->GetNumberOfComponents();
  const unsigned char* p = rgb->GetPointer(0);
  for (vtkIdType i = 0; i < n; ++i, p += components)
  {
    heights->SetValue(i, static_cast<float>(DecodeHeight(p[0], p[1], p[2])));
  }
  output->GetPointData()->SetScalars(heights);
  return 1;
}

//------------------------------------------------------------------------------
void vtkTerrainRGBReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "MemoryBuffer: " << this->MemoryBuffer << "\n";
  os << indent << "MemoryBufferLength: " << this->MemoryBufferLength << "\n";
  os << indent << "Spacing: " << this->Spacing[0] << ", " << this->Spacing[1] << "\n";
  os << indent << "Origin: " << this->Origin[0] << ", " << this->Origin[1] << ", "
     << this->Origin[2] << "\n";
}
