/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureLightingRepresentation.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureLightingRepresentation
 * @brief   ParaView's "Aperture Lighting" representation: a surface with soft area-light shadows
 *
 * ParaView's surface representation with its two mappers (full and level-of-detail) replaced by
 * vtkCompositeApertureLightingMapper: the surface is shaded from the BentNormal and
 * ApertureRadius point arrays of vtkAperturePrecompute, against ParaView's own lights (the light
 * kit, the headlight and added lights, each with the angular size set here), under an optional
 * uniform or HDR sky. Colouring by arrays, opacity and the rest of the surface representation
 * work unchanged; blocks without the arrays are drawn with VTK's standard lighting.
 *
 * The settings go to both mappers; see vtkApertureLightingInterface for what each means.
 */

#ifndef vtkApertureLightingRepresentation_h
#define vtkApertureLightingRepresentation_h

#include "vtkApertureLightingRepresentationModule.h" // For export macro
#include "vtkGeometryRepresentationWithFaces.h"

#include <memory> // For std::unique_ptr

class vtkApertureLightingInterface;
class vtkApertureSkyFile;

class VTKAPERTURELIGHTINGREPRESENTATION_EXPORT vtkApertureLightingRepresentation
  : public vtkGeometryRepresentationWithFaces
{
public:
  static vtkApertureLightingRepresentation* New();
  vtkTypeMacro(vtkApertureLightingRepresentation, vtkGeometryRepresentationWithFaces);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Shading model (vtkApertureLightingInterface::ShadingModes). Default EXACT.
   */
  void SetShadingMode(int mode);

  /**
   * Angular radius of lights that carry no size of their own, in degrees (ParaView's light kit,
   * headlight and added lights). Default 0.27, the sun's.
   */
  void SetLightSize(double degrees);

  ///@{
  /**
   * A uniform sky: colour and intensity (0, the default, for none).
   */
  void SetSkyColor(double red, double green, double blue);
  void SetSkyIntensity(double intensity);
  ///@}

  /**
   * An HDR environment (a latitude-longitude OpenEXR file) as the sky, scaled by the sky's
   * colour and intensity; empty (the default) for the uniform sky. A file that cannot be read is
   * reported and leaves the uniform sky.
   */
  void SetSkyEnvironmentFile(const char* fileName);

  /**
   * The environment's up axis: 0, 1 or 2 for X, Y (the default, ParaView's view up) or Z.
   */
  void SetSkyEnvironmentUpAxis(int axis);

  /**
   * The environment's turn about the up axis, in degrees. Default 0.
   */
  void SetSkyEnvironmentAzimuth(double degrees);

  /**
   * The settings the mappers share (both mappers get every change).
   */
  vtkApertureLightingInterface* GetApertureLighting(int lod = 0);

protected:
  vtkApertureLightingRepresentation();
  ~vtkApertureLightingRepresentation() override;

private:
  // Applies `set` to the lighting of both mappers, then marks the representation modified.
  template <typename Setter>
  void SetOnBoth(Setter set);

  std::unique_ptr<vtkApertureSkyFile> Sky;

  vtkApertureLightingRepresentation(const vtkApertureLightingRepresentation&) = delete;
  void operator=(const vtkApertureLightingRepresentation&) = delete;
};

#endif
