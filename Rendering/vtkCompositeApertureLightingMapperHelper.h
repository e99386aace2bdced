/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkCompositeApertureLightingMapperHelper.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkCompositeApertureLightingMapperHelper
 * @brief   helper of vtkCompositeApertureLightingMapper (private)
 *
 * Draws the blocks of one vtkCompositePolyDataMapper2 signature with aperture lighting: appends
 * every block's aperture arrays (or open-aperture stand-ins) next to its points in the shared
 * vertex buffers, which vtkCompositeMapperHelper2 does not do for mapped attributes, and hands
 * the lighting code and uniforms to the shared vtkApertureLightingInterface.
 */

#ifndef vtkCompositeApertureLightingMapperHelper_h
#define vtkCompositeApertureLightingMapperHelper_h

// VTK 9.1's vtkCompositeMapperHelper2.h uses these without including them.
#include "vtkColor.h"
#include "vtk_glew.h"

#include "vtkCompositeMapperHelper2.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <map> // For std::map

class vtkApertureLightingInterface;

class vtkCompositeApertureLightingMapperHelper : public vtkCompositeMapperHelper2
{
public:
  static vtkCompositeApertureLightingMapperHelper* New();
  vtkTypeMacro(vtkCompositeApertureLightingMapperHelper, vtkCompositeMapperHelper2);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void SetLighting(vtkApertureLightingInterface* lighting);

  void RenderPiece(vtkRenderer* renderer, vtkActor* actor) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkCompositeApertureLightingMapperHelper();
  ~vtkCompositeApertureLightingMapperHelper() override;

  bool GetNeedToRebuildBufferObjects(vtkRenderer* renderer, vtkActor* actor) override;
  void BuildBufferObjects(vtkRenderer* renderer, vtkActor* actor) override;
  void AppendOneBufferObject(vtkRenderer* renderer, vtkActor* actor,
    vtkCompositeMapperHelperData* data, vtkIdType& offset, std::vector<unsigned char>& colors,
    std::vector<float>& normals) override;
  bool GetNeedToRebuildShaders(
    vtkOpenGLHelper& cellBO, vtkRenderer* renderer, vtkActor* actor) override;
  void ReplaceShaderLight(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* renderer, vtkActor* actor) override;
  void SetMapperShaderParameters(
    vtkOpenGLHelper& cellBO, vtkRenderer* renderer, vtkActor* actor) override;

private:
  vtkCompositeApertureLightingMapperHelper(
    const vtkCompositeApertureLightingMapperHelper&) = delete;
  void operator=(const vtkCompositeApertureLightingMapperHelper&) = delete;

  vtkSmartPointer<vtkApertureLightingInterface> Lighting;
  // Whether the vertex buffers hold aperture arrays, and whether this render shades with them;
  // the same for packed horizons or masks (their layout, 0 for none), and the interface's buffer
  // time they were built at.
  bool BuffersHaveApertures = false;
  bool Apertures = false;
  int BufferLayout = 0;
  vtkMTimeType BufferTime = 0;
  int PackedLayout = 0;
  std::map<const vtkOpenGLHelper*, int> ShaderState;
};

#endif
// VTK-HeaderTest-Exclude: vtkCompositeApertureLightingMapperHelper.h
