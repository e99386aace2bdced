/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureVolumeRepresentation.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureVolumeRepresentation
 * @brief   ParaView's "Aperture Volume" representation: a volume with soft area-light shadows
 *
 * ParaView's image volume representation drawn by vtkApertureVolumeMapper instead of its own
 * volume mapper: every sample is shaded by its voxel's aperture against ParaView's lights (each
 * an area light of the angular size set here) and a sky of the Sky Color times the Lighting
 * group's Ambient, as VTK's volume ambient is: uniform, or an HDR environment from a file. The
 * apertures are computed from the volume's transfer function when it is drawn first and again after
 * the opacity changes (the mapper's vtkVolumeAperturePrecompute, with the distance, directions and
 * grid step set here). Colour and opacity transfer functions, blending, cropping and the rest work
 * as for "Volume".
 *
 * The volume samples as the Volume representation does for a still frame (at a distance locked to
 * the input's spacing), also while the view is being turned.
 *
 * The apertures are the shading, so the volume is always shaded (ParaView's Shade is not read).
 * In parallel each rank asks for its piece with as many ghost levels as the apertures' halo
 * (vtkVolumeAperturePrecompute::ComputeHalo()) and computes its piece's apertures from them, so
 * that occluders on other ranks' pieces shade it as in a serial run; the volume drawn is the
 * piece without its ghosts, as for "Volume".
 */

#ifndef vtkApertureVolumeRepresentation_h
#define vtkApertureVolumeRepresentation_h

#include "vtkApertureLightingRepresentationModule.h" // For export macro
#include "vtkImageVolumeRepresentation.h"

#include <memory> // For std::unique_ptr

class vtkApertureSkyFile;
class vtkApertureVolumeMapper;

class VTKAPERTURELIGHTINGREPRESENTATION_EXPORT vtkApertureVolumeRepresentation
  : public vtkImageVolumeRepresentation
{
public:
  static vtkApertureVolumeRepresentation* New();
  vtkTypeMacro(vtkApertureVolumeRepresentation, vtkImageVolumeRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * How a light's cap meets the aperture (vtkApertureVolumeMapper::ShadingModes). Default EXACT.
   */
  void SetShadingMode(int mode);

  /**
   * Whether a sample gets the light of its eight aperture voxels' blended cap (off, the default)
   * or the blend of their light (vtkApertureVolumeMapper::SetInterpolateLight()).
   */
  void SetInterpolateLight(bool interpolate);

  /**
   * How far toward the eye each sample reads its apertures, in aperture voxels, 0 to 2
   * (vtkApertureVolumeMapper::SetSurfaceOffset()). Default 1.
   */
  void SetSurfaceOffset(double voxels);

  /**
   * Angular radius of every light, in degrees. Default 5.73 (0.1 radian, a soft sun).
   */
  void SetLightSize(double degrees);

  /**
   * Colour of the uniform sky, times the volume's ambient. Default white.
   */
  void SetSkyColor(double red, double green, double blue);

  /**
   * An HDR environment (a latitude-longitude OpenEXR file) as the sky, scaled by the sky's
   * colour; empty (the default) for the uniform sky. A file that cannot be read is reported and
   * leaves the uniform sky.
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

  ///@{
  /**
   * The aperture computation (see vtkVolumeAperturePrecompute): how far occluders reach in world
   * units (0, the default, a fifth of the volume's diagonal), directions over the sphere (default
   * 64) and apertures on every n-th voxel (default 1).
   */
  void SetMaximumDistance(double distance);
  void SetNumberOfDirections(int count);
  void SetApertureGridStep(int step);
  ///@}

  /**
   * The mapper that draws the volume.
   */
  vtkApertureVolumeMapper* GetApertureVolumeMapper();

protected:
  vtkApertureVolumeRepresentation();
  ~vtkApertureVolumeRepresentation() override;

  void UpdateMapperParameters() override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  std::unique_ptr<vtkApertureSkyFile> Sky;

  vtkApertureVolumeRepresentation(const vtkApertureVolumeRepresentation&) = delete;
  void operator=(const vtkApertureVolumeRepresentation&) = delete;
};

#endif
