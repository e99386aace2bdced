/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureVolumeMapper.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureVolumeMapper
 * @brief   VTK's GPU volume ray caster, each sample lit through its aperture: soft shadows
 *
 * vtkOpenGLGPUVolumeRayCastMapper with the gradient Phong term replaced, where the volume
 * property's Shade is on, by aperture lighting: each sample reads its aperture (bent normal and
 * radius, trilinear from a 3D texture of 4 bytes a voxel; or, with InterpolateLight on, the
 * eight voxels' apertures about it, their light blended) and gets
 *
 *   colour × (ambient × sky × A/4π + diffuse × Σ light × |aperture ∩ light cap| / |light cap|),
 *
 * A the aperture's solid angle: the share of each light's cap that the aperture holds (its
 * intersection exact or by the paper's smoothstep, the GLSL twin of vtkSphericalCap), 1 in free
 * space. A medium has no surface to turn toward a light, so there is no Lambert or specular term;
 * vtkVolumeApertureReference's Monte-Carlo irradiance is what this estimates. Every switched-on
 * light of the renderer (up to 8) is an area light of angular radius LightRadius toward it (a
 * positional light from its direction to the volume's centre); the sky is uniform, of SkyColor,
 * or an HDR environment (SetSkyEnvironment()), where A/4π becomes the environment's radiance over
 * the aperture over 4π.
 *
 * Everything else is VTK's: transfer functions, composite blending, cropping, clipping planes,
 * masks, the interactive sample-distance reduction, the volume's transform. Apertures come from
 * SetApertureData() (the output of a vtkVolumeAperturePrecompute on this mapper's input), or,
 * when none is set, from the mapper's own precompute (GetAperturePrecompute() for its settings),
 * rerun when the input or the volume property changes: drag the opacity curve and the shadows
 * follow (at 128³ apertures, about 2 s on two cores).
 *
 * Where aperture lighting cannot apply (Shade off, a blend mode other than composite, more than
 * one component, a 2D transfer function, several inputs, apertures that do not fit) the mapper
 * draws as VTK does, with one warning for the cases that are not VTK's own choices.
 *
 * The volume draws with a shader property of the mapper's: a copy of the volume's own (its code
 * and replacements; its custom uniforms are not carried over) with this mapper's replacement of
 * VTK's lighting declaration and custom uniforms named aperture*. The volume's own property is
 * left as it was, so another mapper on the same volume draws as it would.
 *
 * @sa vtkVolumeAperturePrecompute vtkVolumeApertureReference vtkSphericalCap
 */

#ifndef vtkApertureVolumeMapper_h
#define vtkApertureVolumeMapper_h

#include "vtkApertureLightingRenderingVolumeModule.h" // For export macro
#include "vtkOpenGLGPUVolumeRayCastMapper.h"
#include "vtkSmartPointer.h" // For members

#include <string> // For the warning key

class vtkEnvironmentMap;
class vtkImageData;
class vtkOpenGLShaderProperty;
class vtkTextureObject;
class vtkTrivialProducer;
class vtkVolumeAperturePrecompute;

class VTKAPERTURELIGHTINGRENDERINGVOLUME_EXPORT vtkApertureVolumeMapper
  : public vtkOpenGLGPUVolumeRayCastMapper
{
public:
  static vtkApertureVolumeMapper* New();
  vtkTypeMacro(vtkApertureVolumeMapper, vtkOpenGLGPUVolumeRayCastMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ShadingModes
  {
    EXACT = 0,     ///< the exact intersection of the aperture and the light cap
    SMOOTHSTEP = 1 ///< the paper's smoothstep approximation of it
  };

  ///@{
  /**
   * How a light's cap meets the aperture. Default EXACT.
   */
  vtkSetClampMacro(ShadingMode, int, EXACT, SMOOTHSTEP);
  vtkGetMacro(ShadingMode, int);
  void SetShadingModeToExact() { this->SetShadingMode(EXACT); }
  void SetShadingModeToSmoothstep() { this->SetShadingMode(SMOOTHSTEP); }
  ///@}

  ///@{
  /**
   * How a sample between aperture voxels is lit. Off (the default): the caps are interpolated
   * (one filtered read) and the sample is lit through the blended cap, which between a wide cap
   * and a narrow one still holds a small light whole, so the lit side of sharp surfaces
   * saturates. On: each of the eight voxels about the sample lights it through its own cap and
   * the sample gets the trilinear blend of their light, as vtkVolumeApertureReference's
   * irradiance is interpolated: nearer the reference, above all with SurfaceOffset 0, at eight
   * texture reads and shadings a sample (the frame costs, docs/volumes.md).
   */
  vtkSetMacro(InterpolateLight, bool);
  vtkGetMacro(InterpolateLight, bool);
  vtkBooleanMacro(InterpolateLight, bool);
  ///@}

  ///@{
  /**
   * How far toward the eye each sample reads its apertures, in aperture voxels. Default 1: the
   * surface layer of opaque matter takes the light of its outside, as the eye sees it; read in
   * place (0), what vtkVolumeApertureReference estimates, it bands with the depth each ray stops
   * at within the layer (the wood grain of volume rendering) and, with InterpolateLight on, is
   * nearer the reference (docs/volumes.md); the price of 1 is a cast shadow a voxel softer and
   * lit sides brighter. Clamped to [0, 2]: further out, a sample takes light from what is not
   * its surface.
   */
  vtkSetClampMacro(SurfaceOffset, double, 0.0, 2.0);
  vtkGetMacro(SurfaceOffset, double);
  ///@}

  ///@{
  /**
   * The angular radius of every light, radians (clamped as vtkSphericalCap clamps light radii).
   * Default 0.1: a soft sun.
   */
  vtkSetClampMacro(LightRadius, double, 1e-4, 1.5707963267948966);
  vtkGetMacro(LightRadius, double);
  ///@}

  ///@{
  /**
   * The uniform sky, times the volume property's ambient. Default white.
   */
  vtkSetVector3Macro(SkyColor, double);
  vtkGetVector3Macro(SkyColor, double);
  ///@}

  /**
   * An HDR environment as the sky instead of the uniform one: each sample gets the environment's
   * radiance over its aperture (vtkEnvironmentMap::CapRadiance(), tabulated once per image on 64
   * × 32 axes × 32 radii up to π, turned by the volume's and the environment's rotations at no
   * cost) over 4π, times SkyColor and the volume property's ambient. A uniform environment of
   * radiance 1 gives the uniform sky. nullptr (the default): the uniform sky.
   */
  void SetSkyEnvironment(vtkEnvironmentMap* environment);
  vtkGetObjectMacro(SkyEnvironment, vtkEnvironmentMap);

  ///@{
  /**
   * Apertures computed elsewhere, on this mapper's input (its grid or a coarser one over the same
   * bounds, every n-th voxel), with point arrays BentNormal and ApertureRadius. nullptr (the
   * default): the mapper computes them.
   */
  void SetApertureData(vtkImageData* apertures);
  vtkGetObjectMacro(ApertureData, vtkImageData);
  ///@}

  ///@{
  /**
   * A larger volume that the input is a piece of, to compute the apertures from (the piece and a
   * halo of vtkVolumeAperturePrecompute::ComputeHalo() voxels around it, on the same grid), and
   * that volume's whole extent, which sets the default MaximumDistance: occluders in the halo
   * then shade the piece as they would the whole volume. Pieces handed out by MPI ranks or
   * streaming need it. nullptr (the default): the apertures of the input alone. An empty whole
   * extent (the default) takes the source's own.
   */
  void SetApertureSource(vtkImageData* volume);
  vtkGetObjectMacro(ApertureSource, vtkImageData);
  vtkSetVector6Macro(ApertureSourceWholeExtent, int);
  vtkGetVector6Macro(ApertureSourceWholeExtent, int);
  ///@}

  /**
   * The precompute the mapper runs when no aperture data is set: its MaximumDistance,
   * NumberOfDirections and ApertureGridStep are the mapper's.
   */
  vtkVolumeAperturePrecompute* GetAperturePrecompute();

  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkApertureVolumeMapper();
  ~vtkApertureVolumeMapper() override;

  void GPURender(vtkRenderer* ren, vtkVolume* vol) override;

  int ShadingMode = EXACT;
  bool InterpolateLight = false;
  double SurfaceOffset = 1.0;
  double LightRadius = 0.1;
  double SkyColor[3] = { 1.0, 1.0, 1.0 };
  vtkImageData* ApertureData = nullptr;
  vtkImageData* ApertureSource = nullptr;
  int ApertureSourceWholeExtent[6] = { 0, -1, 0, -1, 0, -1 };
  vtkEnvironmentMap* SkyEnvironment = nullptr;

private:
  vtkApertureVolumeMapper(const vtkApertureVolumeMapper&) = delete;
  void operator=(const vtkApertureVolumeMapper&) = delete;

  // Why aperture lighting does not apply to this volume ("" when it does, "-" for VTK's own
  // choices: no shading, another blend mode).
  std::string Unusable(vtkVolume* vol);
  // The apertures to draw with, computed when needed; nullptr with a warning when unusable.
  vtkImageData* CurrentApertures(vtkVolume* vol);
  // The precompute's apertures over the input, from the aperture source or the input.
  vtkImageData* ComputedApertures(vtkVolume* vol, vtkImageData* input);
  bool UploadApertures(vtkRenderer* ren, vtkImageData* apertures);
  // The environment's cap-radiance table as a 3D texture, made again when its image changes.
  bool UploadSkyTable(vtkRenderer* ren);
  // The matrix (column-major, for GL) from the volume's data axes to the environment's frame.
  void SkyMatrix(vtkVolume* vol, float matrix[9]);
  // The shader property the volume draws with: its own code and replacements and this mapper's.
  vtkOpenGLShaderProperty* ShaderPropertyFor(vtkVolume* vol);
  void SetLightUniforms(vtkRenderer* ren, vtkVolume* vol);
  void WarnOnce(const std::string& problem);

  vtkSmartPointer<vtkVolumeAperturePrecompute> Precompute;
  vtkSmartPointer<vtkTrivialProducer> PrecomputeInput;
  vtkSmartPointer<vtkTextureObject> Texture;
  vtkSmartPointer<vtkTextureObject> SkyTable;
  vtkMTimeType SkyTableTime = 0;
  vtkImageData* UploadedApertures = nullptr; // identity only, never dereferenced
  vtkMTimeType UploadedTime = 0;
  vtkMTimeType PrecomputeTried = 0;
  float TextureScale[3] = { 1.0f, 1.0f, 1.0f };
  float TextureShift[3] = { 0.0f, 0.0f, 0.0f };
  float GridSize[3] = { 1.0f, 1.0f, 1.0f };
  vtkSmartPointer<vtkOpenGLShaderProperty> Shaders;
  vtkMTimeType CopiedTime = 0;
  std::string InstalledCode;
  std::string LastWarning;
};

#endif
