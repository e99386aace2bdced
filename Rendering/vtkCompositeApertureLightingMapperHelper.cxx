/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkCompositeApertureLightingMapperHelper.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkCompositeApertureLightingMapperHelper.h"

#include "vtkApertureLightingInterface.h"

#include "vtkFloatArray.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <vector>

vtkStandardNewMacro(vtkCompositeApertureLightingMapperHelper);

namespace
{
// Stand-ins for a block without usable arrays: a negative radius marks points without an
// aperture, which the shader lights as standard lighting does.
void NoApertures(
  vtkPolyData* block, vtkSmartPointer<vtkFloatArray>& bent, vtkSmartPointer<vtkFloatArray>& radius)
{
  const vtkIdType n = block->GetNumberOfPoints();
  bent = vtkSmartPointer<vtkFloatArray>::New();
  bent->SetNumberOfComponents(3);
  bent->SetNumberOfTuples(n);
  bent->Fill(0.0);
  radius = vtkSmartPointer<vtkFloatArray>::New();
  radius->SetNumberOfTuples(n);
  radius->Fill(-1.0);
}
}

//------------------------------------------------------------------------------
vtkCompositeApertureLightingMapperHelper::vtkCompositeApertureLightingMapperHelper() = default;

//------------------------------------------------------------------------------
vtkCompositeApertureLightingMapperHelper::~vtkCompositeApertureLightingMapperHelper() = default;

//------------------------------------------------------------------------------
void vtkCompositeApertureLightingMapperHelper::SetLighting(vtkApertureLightingInterface* lighting)
{
  this->Lighting = lighting;
}

//------------------------------------------------------------------------------
void vtkCompositeApertureLightingMapperHelper::RenderPiece(vtkRenderer* renderer, vtkActor* actor)
{
  // Shade with apertures when the model asks for them and at least one block has them; with
  // horizons or masks, the finest layout of any block's (the others' are resampled, or open).
  this->Apertures = false;
  this->PackedLayout = 0;
  if (this->Lighting && this->Lighting->GetShadingMode() != vtkApertureLightingInterface::STANDARD)
  {
    for (const auto& block : this->Data)
    {
      this->Apertures = this->Apertures || this->Lighting->CheckApertures(block.first);
      this->PackedLayout =
        std::max(this->PackedLayout, this->Lighting->CheckPackedLayout(block.first));
    }
  }
  this->PackedLayout = this->Apertures ? this->PackedLayout : 0;
  if (this->Lighting)
  {
    this->Lighting->UpdateVertexEnvironment(actor);
  }
  this->Superclass::RenderPiece(renderer, actor);
}

//------------------------------------------------------------------------------
bool vtkCompositeApertureLightingMapperHelper::GetNeedToRebuildBufferObjects(
  vtkRenderer* renderer, vtkActor* actor)
{
  return this->Superclass::GetNeedToRebuildBufferObjects(renderer, actor) ||
    this->Apertures != this->BuffersHaveApertures || this->PackedLayout != this->BufferLayout ||
    (this->Lighting && this->BufferTime < this->Lighting->GetBufferMTime());
}

//------------------------------------------------------------------------------
void vtkCompositeApertureLightingMapperHelper::BuildBufferObjects(
  vtkRenderer* renderer, vtkActor* actor)
{
  this->BuffersHaveApertures = this->Apertures;
  this->BufferLayout = this->PackedLayout;
  this->BufferTime = this->Lighting ? this->Lighting->GetBufferMTime() : 0;
  this->Superclass::BuildBufferObjects(renderer, actor);
}

//------------------------------------------------------------------------------
void vtkCompositeApertureLightingMapperHelper::AppendOneBufferObject(vtkRenderer* renderer,
  vtkActor* actor, vtkCompositeMapperHelperData* data, vtkIdType& offset,
  std::vector<unsigned char>& colors, std::vector<float>& normals)
{
  vtkPolyData* block = data->Data;
  vtkIdType before = 0, unused = 0;
  if (block->GetPoints())
  {
    this->VBOs->ArrayExists("vertexMC", block->GetPoints()->GetData(), unused, before);
  }
  this->Superclass::AppendOneBufferObject(renderer, actor, data, offset, colors, normals);

  // The superclass skips empty blocks and reuses the arrays of blocks already appended; the
  // aperture arrays follow the points only where they were appended afresh.
  if (!this->BuffersHaveApertures || !block->GetPoints() || block->GetNumberOfPoints() == 0 ||
    offset != before)
  {
    return;
  }
  vtkPointData* pd = block->GetPointData();
  vtkSmartPointer<vtkFloatArray> standInBent, standInRadius;
  vtkDataArray* bent = pd->GetArray(this->Lighting->GetBentNormalArrayName());
  vtkDataArray* radius = pd->GetArray(this->Lighting->GetApertureRadiusArrayName());
  if (!this->Lighting->CheckApertures(block))
  {
    NoApertures(block, standInBent, standInRadius);
    bent = standInBent;
    radius = standInRadius;
  }
  // The group keeps a reference to what it appends.
  this->VBOs->AppendDataArray("bentNormalMC", bent, VTK_FLOAT);
  this->VBOs->AppendDataArray("apertureRadiusMC", radius, VTK_FLOAT);
  if (this->BufferLayout > 0)
  {
    std::vector<vtkSmartPointer<vtkFloatArray>> packed;
    this->Lighting->PackAttributes(block, this->BufferLayout, packed);
    for (size_t i = 0; i < packed.size(); ++i)
    {
      this->VBOs->AppendDataArray(
        vtkApertureLightingInterface::GetPackedAttributeName(static_cast<int>(i)).c_str(),
        packed[i], VTK_FLOAT);
    }
  }
}

//------------------------------------------------------------------------------
bool vtkCompositeApertureLightingMapperHelper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* renderer, vtkActor* actor)
{
  const bool rebuild = this->Superclass::GetNeedToRebuildShaders(cellBO, renderer, actor);
  int& last = this->ShaderState[&cellBO];
  const int state = (this->Apertures ? 1 : 0) | (this->PackedLayout << 1);
  const bool changed = last != state;
  last = state;
  return rebuild || changed ||
    (this->Lighting && cellBO.ShaderSourceTime < this->Lighting->GetShaderMTime());
}

//------------------------------------------------------------------------------
void vtkCompositeApertureLightingMapperHelper::ReplaceShaderLight(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* renderer, vtkActor* actor)
{
  const auto& info = this->PrimitiveInfo[this->LastBoundBO];
  if (!this->Apertures || this->DrawingTubesOrSpheres(*this->LastBoundBO, actor) ||
    !this->Lighting->ReplaceShaderLight(shaders, actor, renderer, info.LastLightComplexity,
      info.LastLightCount, false, false, this->PackedLayout))
  {
    this->Superclass::ReplaceShaderLight(shaders, renderer, actor);
  }
}

//------------------------------------------------------------------------------
void vtkCompositeApertureLightingMapperHelper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* renderer, vtkActor* actor)
{
  this->Superclass::SetMapperShaderParameters(cellBO, renderer, actor);
  if (this->Apertures)
  {
    vtkNew<vtkMatrix3x3> normalMatrix;
    vtkApertureLightingInterface::ComputeNormalMatrix(renderer, actor, normalMatrix);
    // Per vertex only: no texture coordinates to generate.
    const double shift[3] = { 0.0, 0.0, 0.0 }, scale[3] = { 1.0, 1.0, 1.0 };
    this->Lighting->SetShaderParameters(
      cellBO.Program, renderer, normalMatrix, false, shift, scale);
  }
}

//------------------------------------------------------------------------------
void vtkCompositeApertureLightingMapperHelper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->ShaderState.clear();
  this->Superclass::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void vtkCompositeApertureLightingMapperHelper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Apertures: " << this->Apertures << "\n";
  os << indent << "PackedLayout: " << this->PackedLayout << "\n";
}
