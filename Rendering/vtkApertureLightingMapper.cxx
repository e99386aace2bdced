/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureLightingMapper.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureLightingMapper.h"

#include "vtkActor.h"
#include "vtkApertureCellCheck.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkApertureLightingMapper);

namespace
{
// What a render shades with; the packed layout (horizons' sectors, masks' bits), if any, above
// these bits.
enum StateBits
{
  Apertures = 1,    // apertures are usable and the model is not standard
  PerTexel = 2,     // read from the aperture image
  InputTCoords = 4, // with the input's texture coordinates
  LayoutShift = 3,
};
}

//------------------------------------------------------------------------------
bool vtkApertureLightingMapper::CheckCells(vtkPolyData* input)
{
  if (!input)
  {
    return true;
  }
  if (input->GetMTime() != this->CheckedCellsTime)
  {
    this->CheckedCellsTime = input->GetMTime();
    const std::string problem = vtkApertureCellCheck::FindBadCell(input);
    this->CellsGood = problem.empty();
    if (!this->CellsGood)
    {
      vtkErrorMacro("Cannot draw the input: " << problem << ".");
    }
  }
  return this->CellsGood;
}

//------------------------------------------------------------------------------
void vtkApertureLightingMapper::ComputeBounds()
{
  vtkPolyData* input = this->GetInput();
  if (this->CheckCells(input))
  {
    this->Superclass::ComputeBounds();
    return;
  }
  input->GetPoints()->GetBounds(this->Bounds);
}

//------------------------------------------------------------------------------
void vtkApertureLightingMapper::RenderPiece(vtkRenderer* renderer, vtkActor* actor)
{
  vtkPolyData* input = this->GetInput();
  if (!this->CheckCells(input))
  {
    return;
  }
  int state = 0;
  if (input && this->Lighting->GetShadingMode() != vtkApertureLightingInterface::STANDARD)
  {
    vtkImageData* image = this->Lighting->GetApertureImage();
    vtkDataArray* tcoords = input->GetPointData()->GetTCoords();
    const bool inputTCoords =
      image && tcoords && tcoords->GetNumberOfComponents() == 2 && tcoords->GetName();
    if (image ? this->Lighting->CheckApertureImage(renderer)
              : this->Lighting->CheckApertures(input))
    {
      state = Apertures | (image ? PerTexel : 0) | (inputTCoords ? InputTCoords : 0);
    }
  }
  this->PackedLayout = (state & Apertures)
    ? this->Lighting->CheckPackedLayout(
        (state & PerTexel) ? static_cast<vtkDataSet*>(this->Lighting->GetApertureImage()) : input)
    : 0;
  this->State = state | (this->PackedLayout << LayoutShift);
  this->Lighting->UpdateVertexEnvironment(actor);
  this->MapApertureAttributes(input);
  this->Superclass::RenderPiece(renderer, actor);
}

//------------------------------------------------------------------------------
void vtkApertureLightingMapper::MapApertureAttributes(vtkPolyData* input)
{
  const bool perVertex = (this->State & Apertures) && !(this->State & PerTexel);
  std::vector<std::pair<std::string, std::string>> wanted = {
    { "bentNormalMC", perVertex ? this->Lighting->GetBentNormalArrayName() : "" },
    { "apertureRadiusMC", perVertex ? this->Lighting->GetApertureRadiusArrayName() : "" },
    { "apertureTCoordMC",
      (this->State & InputTCoords) ? input->GetPointData()->GetTCoords()->GetName() : "" },
  };
  // The packed horizons or masks are named as their attributes (in the packed copy only).
  for (int i = 0; i < vtkApertureLightingInterface::GetMaximumPackedAttributes(); ++i)
  {
    const std::string name = vtkApertureLightingInterface::GetPackedAttributeName(i);
    const bool used = perVertex && this->PackedLayout > 0 &&
      i < this->Lighting->GetNumberOfVertexAttributes(this->PackedLayout);
    wanted.emplace_back(name, used ? name : "");
  }
  for (const auto& attribute : wanted)
  {
    // Mapping modifies the mapper (and so rebuilds its buffers): only on change.
    auto current = this->ExtraAttributes.find(attribute.first);
    const std::string mapped =
      current == this->ExtraAttributes.end() ? "" : current->second.DataArrayName;
    if (mapped == attribute.second)
    {
      continue;
    }
    if (attribute.second.empty())
    {
      this->RemoveVertexAttributeMapping(attribute.first.c_str());
    }
    else
    {
      this->MapDataArrayToVertexAttribute(attribute.first.c_str(), attribute.second.c_str(),
        vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
    }
  }
}

//------------------------------------------------------------------------------
vtkPolyData* vtkApertureLightingMapper::GetPackedInput(vtkPolyData* input)
{
  vtkPointData* pd = input->GetPointData();
  vtkDataArray* horizons = pd->GetArray(this->Lighting->GetHorizonAnglesArrayName());
  vtkDataArray* masks = pd->GetArray(this->Lighting->GetVisibilityMaskArrayName());
  const vtkMTimeType time = std::max(
    { input->GetMTime(), horizons ? horizons->GetMTime() : 0, masks ? masks->GetMTime() : 0 });
  // Horizons' layouts (sectors, at most 32) and masks' (bits, at least 64) never meet.
  if (!this->PackedInput || input != this->PackedSource || time > this->PackedTime ||
    this->PackedInputLayout != this->PackedLayout ||
    this->PackedBufferTime < this->Lighting->GetBufferMTime())
  {
    std::vector<vtkSmartPointer<vtkFloatArray>> attributes;
    this->Lighting->PackAttributes(input, this->PackedLayout, attributes);
    this->PackedInput = vtkSmartPointer<vtkPolyData>::New();
    this->PackedInput->ShallowCopy(input);
    for (size_t i = 0; i < attributes.size(); ++i)
    {
      attributes[i]->SetName(
        vtkApertureLightingInterface::GetPackedAttributeName(static_cast<int>(i)).c_str());
      this->PackedInput->GetPointData()->AddArray(attributes[i]);
    }
    this->PackedTime = time;
    this->PackedInputLayout = this->PackedLayout;
    this->PackedSource = input;
    this->PackedBufferTime = this->Lighting->GetBufferMTime();
  }
  return this->PackedInput;
}

//------------------------------------------------------------------------------
bool vtkApertureLightingMapper::GetNeedToRebuildBufferObjects(
  vtkRenderer* renderer, vtkActor* actor)
{
  // The packed attributes keep their names from one layout (or array name) to another.
  return this->Superclass::GetNeedToRebuildBufferObjects(renderer, actor) ||
    this->BufferLayout != this->PackedLayout || this->BufferTime < this->Lighting->GetBufferMTime();
}

//------------------------------------------------------------------------------
void vtkApertureLightingMapper::BuildBufferObjects(vtkRenderer* renderer, vtkActor* actor)
{
  this->BufferLayout = this->PackedLayout;
  this->BufferTime = this->Lighting->GetBufferMTime();
  const bool packed =
    this->PackedLayout > 0 && (this->State & Apertures) && !(this->State & PerTexel);
  if (!packed || !this->CurrentInput)
  {
    this->PackedInput = nullptr;
    this->Superclass::BuildBufferObjects(renderer, actor);
    return;
  }
  vtkPolyData* input = this->CurrentInput;
  this->CurrentInput = this->GetPackedInput(input);
  this->Superclass::BuildBufferObjects(renderer, actor);
  this->CurrentInput = input;
}

//------------------------------------------------------------------------------
bool vtkApertureLightingMapper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* renderer, vtkActor* actor)
{
  // The superclass first: it also records the light complexity.
  const bool rebuild = this->Superclass::GetNeedToRebuildShaders(cellBO, renderer, actor);
  int& last = this->ShaderState[&cellBO];
  const bool changed = last != this->State;
  last = this->State;
  return rebuild || changed || cellBO.ShaderSourceTime < this->Lighting->GetShaderMTime();
}

//------------------------------------------------------------------------------
void vtkApertureLightingMapper::ReplaceShaderLight(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* renderer, vtkActor* actor)
{
  const auto& info = this->PrimitiveInfo[this->LastBoundBO];
  if (!(this->State & Apertures) || this->DrawingTubesOrSpheres(*this->LastBoundBO, actor) ||
    !this->Lighting->ReplaceShaderLight(shaders, actor, renderer, info.LastLightComplexity,
      info.LastLightCount, (this->State & PerTexel) != 0, (this->State & InputTCoords) != 0,
      this->PackedLayout))
  {
    this->Superclass::ReplaceShaderLight(shaders, renderer, actor);
  }
}

//------------------------------------------------------------------------------
void vtkApertureLightingMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* renderer, vtkActor* actor)
{
  this->Superclass::SetMapperShaderParameters(cellBO, renderer, actor);
  if (this->State & Apertures)
  {
    vtkNew<vtkMatrix3x3> normalMatrix;
    vtkApertureLightingInterface::ComputeNormalMatrix(renderer, actor, normalMatrix);
    double shift[3] = { 0.0, 0.0, 0.0 }, scale[3] = { 1.0, 1.0, 1.0 };
    vtkOpenGLVertexBufferObject* points = this->VBOs->GetVBO("vertexMC");
    if (points && points->GetCoordShiftAndScaleEnabled())
    {
      for (int k = 0; k < 3; ++k)
      {
        shift[k] = points->GetShift()[k];
        scale[k] = points->GetScale()[k];
      }
    }
    this->Lighting->SetShaderParameters(
      cellBO.Program, renderer, normalMatrix, (this->State & InputTCoords) != 0, shift, scale);
  }
}

//------------------------------------------------------------------------------
void vtkApertureLightingMapper::RenderPieceFinish(vtkRenderer* renderer, vtkActor* actor)
{
  this->Lighting->DeactivateTexture();
  this->Superclass::RenderPieceFinish(renderer, actor);
}

//------------------------------------------------------------------------------
void vtkApertureLightingMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Lighting->ReleaseGraphicsResources(window);
  this->ShaderState.clear();
  this->PackedInput = nullptr;
  this->Superclass::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void vtkApertureLightingMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ApertureLighting:\n";
  this->Lighting->PrintSelf(os, indent.GetNextIndent());
}
