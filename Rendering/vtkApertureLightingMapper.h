/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureLightingMapper.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureLightingMapper
 * @brief   shades polydata with ambient aperture lighting from dynamic area lights
 *
 * The render-time half of ambient aperture lighting (Oat & Sander 2007): a polydata mapper whose
 * fragment shader intersects each point's visibility cap (the `BentNormal` and `ApertureRadius`
 * arrays of vtkAperturePrecompute) with the cap of every light of the renderer, in one pass.
 * Directional lights are suns with an angular radius, positional lights sphere lights with a
 * world-space radius (SetLightRadius()); several lights at once, and a sky that fills the part
 * of each aperture the lights leave uncovered.
 *
 * Shading models, switchable at run time: exact intersection area (with the paper's centroid
 * Lambert factor, or the exact lens moment), the paper's smoothstep approximation, the 2006 demo's
 * simplified variant, bent normal only, VTK's standard lighting, and Horizon, which shades from
 * the per-sector horizons that vtkAperturePrecompute keeps for height fields
 * (ComputeHorizonAngles; see vtkHorizonLighting), where one cap is wrong under a low sun, and
 * Visibility mask, which shades from the per-point masks it keeps for meshes
 * (ComputeVisibilityMask; see vtkVisibilityMask), where one cap is wrong under a small light;
 * both fall back to the exact cap, with one warning, on data without their arrays. For an
 * unoccluded point a light of intensity I gives the same irradiance as in VTK's own lighting, so
 * the models and standard shading stay comparable.
 *
 * Apertures come per vertex (vertex attributes from point data) or, in the per-texel mode, from
 * the grid of vtkAperturePrecompute's height-field output as a texture (SetApertureImage()).
 * The settings live in a vtkApertureLightingInterface (GetApertureLighting()), shared with
 * vtkCompositeApertureLightingMapper; the setters here forward to it. Shaders are rebuilt only
 * when the model, the arrays or the set of lights changes. Missing or malformed arrays give one
 * warning and standard shading.
 *
 * @sa vtkAperturePrecompute vtkApertureLightingInterface vtkCompositeApertureLightingMapper
 */

#ifndef vtkApertureLightingMapper_h
#define vtkApertureLightingMapper_h

#include "vtkApertureLightingInterface.h"       // For the forwarded settings
#include "vtkApertureLightingRenderingModule.h" // For export macro
#include "vtkNew.h"                             // For vtkNew
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <map> // For std::map

class VTKAPERTURELIGHTINGRENDERING_EXPORT vtkApertureLightingMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkApertureLightingMapper* New();
  vtkTypeMacro(vtkApertureLightingMapper, vtkOpenGLPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * All settings of the aperture lighting.
   */
  vtkApertureLightingInterface* GetApertureLighting() { return this->Lighting; }

  ///@{
  /**
   * Shading model (see vtkApertureLightingInterface). Default Exact.
   */
  void SetShadingMode(int mode) { this->Lighting->SetShadingMode(mode); }
  int GetShadingMode() { return this->Lighting->GetShadingMode(); }
  void SetShadingModeToExact() { this->Lighting->SetShadingModeToExact(); }
  void SetShadingModeToSmoothstep() { this->Lighting->SetShadingModeToSmoothstep(); }
  void SetShadingModeToSimplified() { this->Lighting->SetShadingModeToSimplified(); }
  void SetShadingModeToBentNormal() { this->Lighting->SetShadingModeToBentNormal(); }
  void SetShadingModeToStandard() { this->Lighting->SetShadingModeToStandard(); }
  void SetShadingModeToHorizon() { this->Lighting->SetShadingModeToHorizon(); }
  void SetShadingModeToVisibilityMask() { this->Lighting->SetShadingModeToVisibilityMask(); }
  ///@}

  ///@{
  /**
   * Lambert factor of the exact model: the paper's centroid (default) or the exact lens moment.
   */
  void SetLambertModeToCentroid() { this->Lighting->SetLambertModeToCentroid(); }
  void SetLambertModeToMoment() { this->Lighting->SetLambertModeToMoment(); }
  int GetLambertMode() { return this->Lighting->GetLambertMode(); }
  ///@}

  ///@{
  /**
   * Names of the aperture arrays. Defaults: "BentNormal", "ApertureRadius", "HorizonAngles",
   * "VisibilityMask".
   */
  void SetBentNormalArrayName(const char* name) { this->Lighting->SetBentNormalArrayName(name); }
  const char* GetBentNormalArrayName() { return this->Lighting->GetBentNormalArrayName(); }
  void SetApertureRadiusArrayName(const char* name)
  {
    this->Lighting->SetApertureRadiusArrayName(name);
  }
  const char* GetApertureRadiusArrayName() { return this->Lighting->GetApertureRadiusArrayName(); }
  void SetHorizonAnglesArrayName(const char* name)
  {
    this->Lighting->SetHorizonAnglesArrayName(name);
  }
  const char* GetHorizonAnglesArrayName() { return this->Lighting->GetHorizonAnglesArrayName(); }
  void SetVisibilityMaskArrayName(const char* name)
  {
    this->Lighting->SetVisibilityMaskArrayName(name);
  }
  const char* GetVisibilityMaskArrayName() { return this->Lighting->GetVisibilityMaskArrayName(); }
  ///@}

  ///@{
  /**
   * Sky colour and intensity (default white, 0: no sky).
   */
  void SetSkyColor(double r, double g, double b) { this->Lighting->SetSkyColor(r, g, b); }
  double* GetSkyColor() VTK_SIZEHINT(3) { return this->Lighting->GetSkyColor(); }
  void SetSkyIntensity(double intensity) { this->Lighting->SetSkyIntensity(intensity); }
  double GetSkyIntensity() { return this->Lighting->GetSkyIntensity(); }
  ///@}

  ///@{
  /**
   * A sky from an HDR environment (see vtkApertureLightingInterface::SetSkyEnvironment()).
   */
  void SetSkyEnvironment(vtkEnvironmentMap* environment)
  {
    this->Lighting->SetSkyEnvironment(environment);
  }
  vtkEnvironmentMap* GetSkyEnvironment() { return this->Lighting->GetSkyEnvironment(); }
  ///@}

  ///@{
  /**
   * Angular radius of lights without a radius of their own. Default 0.0047 rad (the sun).
   */
  void SetDefaultLightRadius(double radius) { this->Lighting->SetDefaultLightRadius(radius); }
  double GetDefaultLightRadius() { return this->Lighting->GetDefaultLightRadius(); }
  ///@}

  ///@{
  /**
   * Per-texel mode: the aperture grid from vtkAperturePrecompute (nullptr: per vertex).
   */
  void SetApertureImage(vtkImageData* image) { this->Lighting->SetApertureImage(image); }
  vtkImageData* GetApertureImage() { return this->Lighting->GetApertureImage(); }
  ///@}

  ///@{
  /**
   * The size of a light, carried by the light: angular radius (rad) of a directional light,
   * world radius of a positional one. GetLightRadius() returns -1 for a light without one.
   */
  static void SetLightRadius(vtkLight* light, double radius)
  {
    vtkApertureLightingInterface::SetLightRadius(light, radius);
  }
  static double GetLightRadius(vtkLight* light)
  {
    return vtkApertureLightingInterface::GetLightRadius(light);
  }
  ///@}

  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkApertureLightingMapper() = default;
  ~vtkApertureLightingMapper() override = default;

  void RenderPiece(vtkRenderer* renderer, vtkActor* actor) override;
  // VTK's bounds read through the cells' point ids: bad ones give the points' bounds.
  void ComputeBounds() override;
  void RenderPieceFinish(vtkRenderer* renderer, vtkActor* actor) override;
  bool GetNeedToRebuildShaders(
    vtkOpenGLHelper& cellBO, vtkRenderer* renderer, vtkActor* actor) override;
  void ReplaceShaderLight(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* renderer, vtkActor* actor) override;
  void SetMapperShaderParameters(
    vtkOpenGLHelper& cellBO, vtkRenderer* renderer, vtkActor* actor) override;
  // Horizons and masks per vertex reach the buffers from a shallow copy of the input that holds
  // them packed, so that the input keeps its arrays.
  void BuildBufferObjects(vtkRenderer* renderer, vtkActor* actor) override;
  bool GetNeedToRebuildBufferObjects(vtkRenderer* renderer, vtkActor* actor) override;

  vtkNew<vtkApertureLightingInterface> Lighting;

private:
  vtkApertureLightingMapper(const vtkApertureLightingMapper&) = delete;
  void operator=(const vtkApertureLightingMapper&) = delete;

  // Maps the aperture arrays (or texture coordinates) to vertex attributes when they change.
  void MapApertureAttributes(vtkPolyData* input);
  // The input with its horizons or masks packed (vtkApertureLightingInterface::PackAttributes()),
  // remade when the input, the layout or what the interface's buffers depend on changes.
  vtkPolyData* GetPackedInput(vtkPolyData* input);
  vtkSmartPointer<vtkPolyData> PackedInput;
  vtkMTimeType PackedTime = 0;
  vtkMTimeType PackedBufferTime = 0;
  int PackedInputLayout = 0;
  vtkPolyData* PackedSource = nullptr; // compared, never dereferenced
  int PackedLayout = 0;
  // What the vertex buffers were built with.
  int BufferLayout = 0;
  vtkMTimeType BufferTime = 0;

  // Whether the input's cells name only its points (checked when the input changes): VTK's
  // buffer code reads through them unchecked.
  bool CheckCells(vtkPolyData* input);
  vtkMTimeType CheckedCellsTime = 0;
  bool CellsGood = false;

  // What this render shades with; a change rebuilds the shaders.
  int State = 0;
  std::map<const vtkOpenGLHelper*, int> ShaderState;
};

#endif
