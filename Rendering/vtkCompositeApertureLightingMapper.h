/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkCompositeApertureLightingMapper.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkCompositeApertureLightingMapper
 * @brief   ambient aperture lighting for composite data (multiblock of polydata)
 *
 * vtkCompositePolyDataMapper2 with the shading of vtkApertureLightingMapper, for composite
 * datasets such as the output of vtkAperturePrecompute on a multiblock input, and for ParaView,
 * which draws surfaces with vtkCompositePolyDataMapper2. Per-block colours, opacities and
 * visibilities work as in the superclass. The settings are in GetApertureLighting(); apertures are
 * read per vertex (the per-texel mode is vtkApertureLightingMapper's).
 *
 * Blocks without usable aperture arrays are drawn with VTK's standard lighting, after one
 * warning.
 *
 * @sa vtkApertureLightingMapper vtkApertureLightingInterface
 */

#ifndef vtkCompositeApertureLightingMapper_h
#define vtkCompositeApertureLightingMapper_h

#include "vtkApertureLightingRenderingModule.h" // For export macro
#include "vtkCompositePolyDataMapper2.h"
#include "vtkNew.h" // For vtkNew

class vtkApertureLightingInterface;

class VTKAPERTURELIGHTINGRENDERING_EXPORT vtkCompositeApertureLightingMapper
  : public vtkCompositePolyDataMapper2
{
public:
  static vtkCompositeApertureLightingMapper* New();
  vtkTypeMacro(vtkCompositeApertureLightingMapper, vtkCompositePolyDataMapper2);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * All settings of the aperture lighting (shading model, arrays, sky, light size).
   */
  vtkApertureLightingInterface* GetApertureLighting();

  /**
   * Draws nothing, with an error naming the block, when a block's cells use point ids outside
   * its points (VTK's buffer code reads through them unchecked).
   */
  void Render(vtkRenderer* renderer, vtkActor* actor) override;

protected:
  vtkCompositeApertureLightingMapper();
  ~vtkCompositeApertureLightingMapper() override;

  vtkCompositeMapperHelper2* CreateHelper() override;
  // VTK's bounds read through the cells' point ids: bad ones give the points' bounds.
  void ComputeBounds() override;
  void CopyMapperValuesToHelper(vtkCompositeMapperHelper2* helper) override;

  vtkNew<vtkApertureLightingInterface> Lighting;

private:
  // Whether every block's cells name only its points (checked when the input changes).
  bool CheckCells();
  vtkMTimeType CheckedCellsTime = 0;
  bool CellsGood = false;

  vtkCompositeApertureLightingMapper(const vtkCompositeApertureLightingMapper&) = delete;
  void operator=(const vtkCompositeApertureLightingMapper&) = delete;
};

#endif
