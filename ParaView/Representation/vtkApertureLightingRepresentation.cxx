/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureLightingRepresentation.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureLightingRepresentation.h"

#include "vtkApertureLightingInterface.h"
#include "vtkApertureSkyFile.h"
#include "vtkCompositeApertureLightingMapper.h"
#include "vtkEnvironmentMap.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkApertureLightingRepresentation);

//------------------------------------------------------------------------------
vtkApertureLightingRepresentation::vtkApertureLightingRepresentation()
  : Sky(new vtkApertureSkyFile)
{
  // The superclass made its mappers; ours replace them, and SetupDefaults() connects them again.
  this->Mapper->Delete();
  this->LODMapper->Delete();
  this->Mapper = vtkCompositeApertureLightingMapper::New();
  this->LODMapper = vtkCompositeApertureLightingMapper::New();
  this->SetupDefaults();
}

//------------------------------------------------------------------------------
vtkApertureLightingRepresentation::~vtkApertureLightingRepresentation() = default;

//------------------------------------------------------------------------------
vtkApertureLightingInterface* vtkApertureLightingRepresentation::GetApertureLighting(int lod)
{
  return static_cast<vtkCompositeApertureLightingMapper*>(lod ? this->LODMapper : this->Mapper)
    ->GetApertureLighting();
}

//------------------------------------------------------------------------------
template <typename Setter>
void vtkApertureLightingRepresentation::SetOnBoth(Setter set)
{
  set(this->GetApertureLighting(0));
  set(this->GetApertureLighting(1));
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkApertureLightingRepresentation::SetShadingMode(int mode)
{
  this->SetOnBoth([mode](vtkApertureLightingInterface* l) { l->SetShadingMode(mode); });
}

//------------------------------------------------------------------------------
void vtkApertureLightingRepresentation::SetLightSize(double degrees)
{
  const double radius = vtkMath::RadiansFromDegrees(degrees);
  this->SetOnBoth([radius](vtkApertureLightingInterface* l) { l->SetDefaultLightRadius(radius); });
}

//------------------------------------------------------------------------------
void vtkApertureLightingRepresentation::SetSkyColor(double red, double green, double blue)
{
  this->SetOnBoth([=](vtkApertureLightingInterface* l) { l->SetSkyColor(red, green, blue); });
}

//------------------------------------------------------------------------------
void vtkApertureLightingRepresentation::SetSkyIntensity(double intensity)
{
  this->SetOnBoth([intensity](vtkApertureLightingInterface* l) { l->SetSkyIntensity(intensity); });
}

//------------------------------------------------------------------------------
void vtkApertureLightingRepresentation::SetSkyEnvironmentFile(const char* fileName)
{
  if (this->Sky->SetFileName(fileName, this))
  {
    vtkEnvironmentMap* sky = this->Sky->GetEnvironment();
    this->SetOnBoth([sky](vtkApertureLightingInterface* l) { l->SetSkyEnvironment(sky); });
  }
}

//------------------------------------------------------------------------------
void vtkApertureLightingRepresentation::SetSkyEnvironmentUpAxis(int axis)
{
  this->Sky->GetMap()->SetUpAxis(axis);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkApertureLightingRepresentation::SetSkyEnvironmentAzimuth(double degrees)
{
  this->Sky->GetMap()->SetAzimuth(degrees);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkApertureLightingRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  this->Sky->PrintSelf(os, indent);
  os << indent << "ApertureLighting:\n";
  this->GetApertureLighting(0)->PrintSelf(os, indent.GetNextIndent());
}
