/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureLightingRepresentation.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureLightingRepresentation.h"

#include "vtkApertureLightingInterface.h"
#include "vtkApertureText.h"
#include "vtkCompositeApertureLightingMapper.h"
#include "vtkEnvironmentMap.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkOpenEXRReader.h"

vtkStandardNewMacro(vtkApertureLightingRepresentation);

//------------------------------------------------------------------------------
vtkApertureLightingRepresentation::vtkApertureLightingRepresentation()
{
  // The superclass made its mappers; ours replace them, and SetupDefaults() connects them again.
  this->Mapper->Delete();
  this->LODMapper->Delete();
  this->Mapper = vtkCompositeApertureLightingMapper::New();
  this->LODMapper = vtkCompositeApertureLightingMapper::New();
  this->SetupDefaults();
  this->SkyEnvironment->SetUpAxisToY();
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
  const std::string name = fileName ? fileName : "";
  if (name == this->SkyEnvironmentFile)
  {
    return;
  }
  this->SkyEnvironmentFile = name;
  this->SkyEnvironmentLoaded = false;
  if (!name.empty())
  {
    vtkNew<vtkOpenEXRReader> reader;
    reader->SetFileName(name.c_str());
    reader->Update();
    vtkImageData* image = reader->GetOutput();
    this->SkyEnvironmentLoaded = reader->GetErrorCode() == 0 && image->GetNumberOfPoints() > 0;
    if (this->SkyEnvironmentLoaded)
    {
      this->SkyEnvironment->SetImage(image);
    }
    else
    {
      vtkErrorMacro("Cannot read the sky environment " << vtkApertureText::QuoteName(name)
                                                       << "; the sky stays uniform.");
    }
  }
  vtkEnvironmentMap* sky = this->SkyEnvironmentLoaded ? this->SkyEnvironment.Get() : nullptr;
  this->SetOnBoth([sky](vtkApertureLightingInterface* l) { l->SetSkyEnvironment(sky); });
}

//------------------------------------------------------------------------------
void vtkApertureLightingRepresentation::SetSkyEnvironmentUpAxis(int axis)
{
  this->SkyEnvironment->SetUpAxis(axis);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkApertureLightingRepresentation::SetSkyEnvironmentAzimuth(double degrees)
{
  this->SkyEnvironment->SetAzimuth(degrees);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkApertureLightingRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SkyEnvironmentFile: \"" << this->SkyEnvironmentFile << "\""
     << (this->SkyEnvironmentLoaded ? "" : " (not in use)") << "\n";
  os << indent << "SkyEnvironment:\n";
  this->SkyEnvironment->PrintSelf(os, indent.GetNextIndent());
  os << indent << "ApertureLighting:\n";
  this->GetApertureLighting(0)->PrintSelf(os, indent.GetNextIndent());
}
