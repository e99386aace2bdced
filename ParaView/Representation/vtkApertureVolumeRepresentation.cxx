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
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkVolumeAperturePrecompute.h"
#include "vtkVolumeProperty.h"

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
void vtkApertureVolumeRepresentation::SetShadingMode(int mode)
{
  this->GetApertureVolumeMapper()->SetShadingMode(mode);
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
