/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureSkyTexture.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureSkyTexture.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkTextureObject.h"

//------------------------------------------------------------------------------
bool vtkApertureSkyTexture::Upload(
  vtkImageData* table, vtkTextureObject* texture, vtkOpenGLRenderWindow* window)
{
  auto* values = vtkFloatArray::SafeDownCast(table->GetPointData()->GetScalars());
  if (!values || values->GetNumberOfComponents() != 3)
  {
    return false;
  }
  int dims[3];
  table->GetDimensions(dims);
  texture->SetContext(window);
  texture->SetWrapS(vtkTextureObject::Repeat);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetWrapR(vtkTextureObject::ClampToEdge);
  texture->SetMinificationFilter(vtkTextureObject::Linear);
  texture->SetMagnificationFilter(vtkTextureObject::Linear);
  return texture->Create3DFromRaw(dims[0], dims[1], dims[2], 3, VTK_FLOAT, values->GetPointer(0));
}
