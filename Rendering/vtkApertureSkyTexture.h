/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureSkyTexture.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureSkyTexture
 * @brief   an environment's cap table as the 3D texture the shaders read (private)
 *
 * vtkEnvironmentMap tables its cap integrals by the axis's azimuth and polar angle and by the
 * cap's radius (NewCapTable() for surfaces, NewCapRadianceTable() for volumes), and over wedges
 * of a model's sky for horizons (NewWedgeTable(), whose shader reads no closer than half a texel
 * to its seam). Both mappers read them through one kind of texture: repeated around the seam in
 * azimuth, clamped at the poles and at the radii's ends, filtered linearly.
 */

#ifndef vtkApertureSkyTexture_h
#define vtkApertureSkyTexture_h

#include "vtkApertureLightingRenderingModule.h" // For export macro

class vtkImageData;
class vtkOpenGLRenderWindow;
class vtkTextureObject;

class VTKAPERTURELIGHTINGRENDERING_EXPORT vtkApertureSkyTexture
{
public:
  /**
   * Uploads `table` (three float components a point) into `texture` in `window`; false when
   * the table is not that or OpenGL refuses the texture.
   */
  static bool Upload(vtkImageData* table, vtkTextureObject* texture, vtkOpenGLRenderWindow* window);
};

#endif
// VTK-HeaderTest-Exclude: vtkApertureSkyTexture.h
