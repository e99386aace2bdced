/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkCompositeApertureLightingMapper.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkCompositeApertureLightingMapper.h"

#include "vtkApertureCellCheck.h"
#include "vtkBoundingBox.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

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
bool vtkCompositeApertureLightingMapper::CheckCells()
{
  vtkDataObject* input = this->GetInputDataObject(0, 0);
  if (!input || input->GetMTime() == this->CheckedCellsTime)
  {
    return !input || this->CellsGood;
  }
  this->CheckedCellsTime = input->GetMTime();
  this->CellsGood = true;
  auto check = [this](vtkPolyData* block, unsigned int index)
  {
    const std::string problem = block ? vtkApertureCellCheck::FindBadCell(block) : std::string();
    if (!problem.empty())
    {
      vtkErrorMacro("Cannot draw block " << index << ": " << problem << ".");
      this->CellsGood = false;
    }
  };
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(input))
  {
    auto it = vtk::TakeSmartPointer(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal() && this->CellsGood; it->GoToNextItem())
    {
      check(vtkPolyData::SafeDownCast(it->GetCurrentDataObject()), it->GetCurrentFlatIndex());
    }
  }
  else
  {
    check(vtkPolyData::SafeDownCast(input), 0);
  }
  return this->CellsGood;
}

//------------------------------------------------------------------------------
void vtkCompositeApertureLightingMapper::ComputeBounds()
{
  if (this->CheckCells())
  {
    this->Superclass::ComputeBounds();
    return;
  }
  vtkBoundingBox box;
  auto* composite = vtkCompositeDataSet::SafeDownCast(this->GetInputDataObject(0, 0));
  auto it = vtk::TakeSmartPointer(composite ? composite->NewIterator() : nullptr);
  for (it ? it->InitTraversal() : void(); it && !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    auto* block = vtkPolyData::SafeDownCast(it->GetCurrentDataObject());
    if (block && block->GetPoints())
    {
      box.AddBounds(block->GetPoints()->GetBounds());
    }
  }
  box.GetBounds(this->Bounds);
}

//------------------------------------------------------------------------------
void vtkCompositeApertureLightingMapper::Render(vtkRenderer* renderer, vtkActor* actor)
{
  if (this->CheckCells())
  {
    this->Superclass::Render(renderer, actor);
  }
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
