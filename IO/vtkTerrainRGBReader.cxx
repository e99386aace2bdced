/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkTerrainRGBReader.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkTerrainRGBReader.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPNGReader.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"
#include "vtksys/SystemTools.hxx"

vtkStandardNewMacro(vtkTerrainRGBReader);

//------------------------------------------------------------------------------
vtkTerrainRGBReader::vtkTerrainRGBReader()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
int vtkTerrainRGBReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  if (this->FileName.empty() || !vtksys::SystemTools::FileExists(this->FileName, true))
  {
    vtkErrorMacro("Terrain-RGB file '" << this->FileName << "' does not exist.");
    return 0;
  }
  vtkNew<vtkPNGReader> png;
  if (!png->CanReadFile(this->FileName.c_str()))
  {
    vtkErrorMacro("'" << this->FileName << "' is not a PNG file.");
    return 0;
  }
  png->SetFileName(this->FileName.c_str());
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
  vtkNew<vtkPNGReader> png;
  png->SetFileName(this->FileName.c_str());
  png->Update();
  vtkImageData* image = png->GetOutput();
  auto* rgb = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  if (!rgb || rgb->GetNumberOfComponents() < 3)
  {
    vtkErrorMacro("'" << this->FileName
                      << "' is not a Terrain-RGB tile: it needs at least three 8-bit channels.");
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
  os << indent << "Spacing: " << this->Spacing[0] << ", " << this->Spacing[1] << "\n";
  os << indent << "Origin: " << this->Origin[0] << ", " << this->Origin[1] << ", "
     << this->Origin[2] << "\n";
}
