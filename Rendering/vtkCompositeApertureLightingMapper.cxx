/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkCompositeApertureLightingMapper.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkCompositeApertureLightingMapper.h"

#include "vtkApertureLightingInterface.h"
#include "vtkCompositeApertureLightingMapperHelper.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkCompositeApertureLightingMapper);

//------------------------------------------------------------------------------
vtkCompositeApertureLightingMapper::vtkCompositeApertureLightingMapper() = default;

//------------------------------------------------------------------------------
vtkCompositeApertureLightingMapper::~vtkCompositeApertureLightingMapper() = default;

//------------------------------------------------------------------------------
vtkApertureLightingInterface* vtkCompositeApertureLightingMapper::GetApertureLighting()
{
  return this->Lighting;
}

//------------------------------------------------------------------------------
vtkCompositeMapperHelper2* vtkCompositeApertureLightingMapper::CreateHelper()
{
  return vtkCompositeApertureLightingMapperHelper::New();
}

//------------------------------------------------------------------------------
void vtkCompositeApertureLightingMapper::CopyMapperValuesToHelper(vtkCompositeMapperHelper2* helper)
{
  this->Superclass::CopyMapperValuesToHelper(helper);
  static_cast<vtkCompositeApertureLightingMapperHelper*>(helper)->SetLighting(this->Lighting);
}

//------------------------------------------------------------------------------
void vtkCompositeApertureLightingMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ApertureLighting:\n";
  this->Lighting->PrintSelf(os, indent.GetNextIndent());
}
