/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureVolumeRepresentation.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureVolumeRepresentation.h"

#include "vtkApertureSkyFile.h"
#include "vtkApertureVolumeMapper.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkVolumeAperturePrecompute.h"
#include "vtkVolumeProperty.h"

#include <algorithm>

vtkStandardNewMacro(vtkApertureVolumeRepresentation);

//------------------------------------------------------------------------------
vtkApertureVolumeRepresentation::vtkApertureVolumeRepresentation()
  : Sky(new vtkApertureSkyFile)
{
  // The superclass hands its mapper to the volume at every render (UpdateMapperParameters), so
  // replacing it here is enough. It samples as the Volume representation's mapper does for a
  // still frame: at a distance locked to the input's spacing, not adjusted to the frame time.
  auto mapper = vtkSmartPointer<vtkApertureVolumeMapper>::New();
  mapper->AutoAdjustSampleDistancesOff();
  mapper->LockSampleDistanceToInputSpacingOn();
  this->VolumeMapper = mapper;
}

//------------------------------------------------------------------------------
vtkApertureVolumeRepresentation::~vtkApertureVolumeRepresentation() = default;

//------------------------------------------------------------------------------
vtkApertureVolumeMapper* vtkApertureVolumeRepresentation::GetApertureVolumeMapper()
{
  return static_cast<vtkApertureVolumeMapper*>(this->VolumeMapper.Get());
}

//------------------------------------------------------------------------------
void vtkApertureVolumeRepresentation::UpdateMapperParameters()
{
  this->Superclass::UpdateMapperParameters();
  this->Property->ShadeOn();
}

//------------------------------------------------------------------------------
int vtkApertureVolumeRepresentation::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestUpdateExtent(request, inputVector, outputVector))
  {
    return 0;
  }
  // The superclass asks for no ghost levels; a piece's apertures need the halo's occluders.
  using SDDP = vtkStreamingDemandDrivenPipeline;
  for (int i = 0; i < inputVector[0]->GetNumberOfInformationObjects(); ++i)
  {
    vtkInformation* info = inputVector[0]->GetInformationObject(i);
    if (info->Get(SDDP::UPDATE_NUMBER_OF_PIECES()) > 1 && info->Has(SDDP::WHOLE_EXTENT()))
    {
      int whole[6];
      info->Get(SDDP::WHOLE_EXTENT(), whole);
      double spacing[3] = { 1.0, 1.0, 1.0 };
      if (info->Has(vtkDataObject::SPACING()))
      {
        info->Get(vtkDataObject::SPACING(), spacing);
      }
      int halo[3];
      this->GetApertureVolumeMapper()->GetAperturePrecompute()->ComputeHalo(whole, spacing, halo);
      info->Set(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS(), std::max({ halo[0], halo[1], halo[2] }));
    }
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkApertureVolumeRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // The superclass draws the piece without its ghosts; the apertures see them.
  vtkSmartPointer<vtkImageData> source;
  int whole[6] = { 0, -1, 0, -1, 0, -1 };
  if (inputVector[0]->GetNumberOfInformationObjects() == 1)
  {
    vtkImageData* input = vtkImageData::GetData(inputVector[0], 0);
    if (input && input->HasAnyGhostCells())
    {
      source = vtkSmartPointer<vtkImageData>::New();
      source->ShallowCopy(input);
      inputVector[0]->GetInformationObject(0)->Get(
        vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
    }
  }
  this->GetApertureVolumeMapper()->SetApertureSource(source);
  this->GetApertureVolumeMapper()->SetApertureSourceWholeExtent(whole);
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
void vtkApertureVolumeRepresentation::SetShadingMode(int mode)
{
  this->GetApertureVolumeMapper()->SetShadingMode(mode);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkApertureVolumeRepresentation::SetInterpolateLight(bool interpolate)
{
  this->GetApertureVolumeMapper()->SetInterpolateLight(interpolate);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkApertureVolumeRepresentation::SetSurfaceOffset(double voxels)
{
  this->GetApertureVolumeMapper()->SetSurfaceOffset(voxels);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkApertureVolumeRepresentation::SetLightSize(double degrees)
{
  this->GetApertureVolumeMapper()->SetLightRadius(vtkMath::RadiansFromDegrees(degrees));
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkApertureVolumeRepresentation::SetSkyColor(double red, double green, double blue)
{
  this->GetApertureVolumeMapper()->SetSkyColor(red, green, blue);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkApertureVolumeRepresentation::SetSkyEnvironmentFile(const char* fileName)
{
  if (this->Sky->SetFileName(fileName, this))
  {
    this->GetApertureVolumeMapper()->SetSkyEnvironment(this->Sky->GetEnvironment());
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkApertureVolumeRepresentation::SetSkyEnvironmentUpAxis(int axis)
{
  this->Sky->GetMap()->SetUpAxis(axis);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkApertureVolumeRepresentation::SetSkyEnvironmentAzimuth(double degrees)
{
  this->Sky->GetMap()->SetAzimuth(degrees);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkApertureVolumeRepresentation::SetMaximumDistance(double distance)
{
  this->GetApertureVolumeMapper()->GetAperturePrecompute()->SetMaximumDistance(distance);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkApertureVolumeRepresentation::SetNumberOfDirections(int count)
{
  this->GetApertureVolumeMapper()->GetAperturePrecompute()->SetNumberOfDirections(count);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkApertureVolumeRepresentation::SetApertureGridStep(int step)
{
  this->GetApertureVolumeMapper()->GetAperturePrecompute()->SetApertureGridStep(step);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkApertureVolumeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  this->Sky->PrintSelf(os, indent);
  os << indent << "ApertureVolumeMapper:\n";
  this->GetApertureVolumeMapper()->PrintSelf(os, indent.GetNextIndent());
}
