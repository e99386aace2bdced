/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureLightingInterface.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureLightingInterface
 * @brief   settings and shader code of ambient aperture lighting, shared by its mappers
 *
 * Holds what vtkApertureLightingMapper and vtkCompositeApertureLightingMapper shade with, and
 * writes their lighting code, in the way vtkSurfaceLICInterface serves the surface LIC mappers:
 * the shading model, the names of the aperture arrays, the sky, the default size of lights, and
 * for the per-texel mode the aperture image.
 *
 * Lights are the renderer's own VTK lights, with their intensity, colour, attenuation and cone;
 * headlights and light kits work unchanged. Each light is a cap: a directional light's size is
 * its angular radius, a positional light's size is a world-space radius whose cap, asin(R/D), is
 * computed per fragment. The size travels on the light (SetLightRadius()), as VTK's ray-tracing
 * backend does; lights without one use DefaultLightRadius as an angular radius (the sun's 0.0047
 * rad). The light's diffuse term is vtkSphericalCap::LightTransfer() of the chosen model, so an
 * unoccluded light of intensity I gives the irradiance of VTK's own lighting with that light.
 * Specular highlights are dimmed by the part of the light the point sees. The sky adds
 * SkyColor × SkyIntensity × vtkSphericalCap::SkyTransfer(): the part of the aperture the lights
 * leave uncovered (paper §3.3), so occluded crevices stay dark.
 *
 * Scalar colouring, lookup tables, textures and the vtkProperty's ambient, diffuse and specular
 * coefficients apply as in VTK. PBR interpolation, lighting off, and points drawn as spheres or
 * lines as tubes are drawn by VTK's standard shading.
 *
 * When the aperture arrays are missing or malformed (wrong component count, wrong size, NaN or
 * infinite values), the mappers warn once and fall back to standard shading: never black.
 * A negative ApertureRadius marks a point without an aperture, shaded by standard lighting
 * (vtkCompositeApertureLightingMapper gives it to the points of blocks without usable arrays).
 *
 * @sa vtkApertureLightingMapper vtkCompositeApertureLightingMapper vtkSphericalCap
 */

#ifndef vtkApertureLightingInterface_h
#define vtkApertureLightingInterface_h

#include "vtkApertureLightingRenderingModule.h" // For export macro
#include "vtkObject.h"
#include "vtkShader.h"       // For vtkShader::Type
#include "vtkSmartPointer.h" // For vtkSmartPointer
#include "vtkSphericalCap.h" // For the shading models

#include <map>    // For std::map
#include <string> // For std::string
#include <vector> // For std::vector

class vtkActor;
class vtkDataArray;
class vtkDataSet;
class vtkEnvironmentMap;
class vtkFloatArray;
class vtkImageData;
class vtkInformationDoubleKey;
class vtkLight;
class vtkMatrix3x3;
class vtkPolyData;
class vtkRenderer;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class VTKAPERTURELIGHTINGRENDERING_EXPORT vtkApertureLightingInterface : public vtkObject
{
public:
  static vtkApertureLightingInterface* New();
  vtkTypeMacro(vtkApertureLightingInterface, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Shading models: the first four are vtkSphericalCap's, which the shaders also get their
   * values from; STANDARD is VTK's own lighting; HORIZON shades lights and the uniform sky from
   * per-sector horizons (vtkHorizonLighting), VISIBILITY_MASK from per-point visibility masks
   * (vtkVisibilityMask), where the data hold them, the exact cap elsewhere.
   */
  enum ShadingModes
  {
    EXACT = vtkSphericalCap::EXACT,
    SMOOTHSTEP = vtkSphericalCap::SMOOTHSTEP,
    SIMPLIFIED = vtkSphericalCap::SIMPLIFIED,
    BENT_NORMAL = vtkSphericalCap::BENT_NORMAL,
    STANDARD,
    HORIZON,
    VISIBILITY_MASK
  };

  ///@{
  /**
   * The shading model. Default EXACT. Changing it rebuilds the shaders.
   */
  virtual void SetShadingMode(int mode);
  vtkGetMacro(ShadingMode, int);
  void SetShadingModeToExact() { this->SetShadingMode(EXACT); }
  void SetShadingModeToSmoothstep() { this->SetShadingMode(SMOOTHSTEP); }
  void SetShadingModeToSimplified() { this->SetShadingMode(SIMPLIFIED); }
  void SetShadingModeToBentNormal() { this->SetShadingMode(BENT_NORMAL); }
  void SetShadingModeToStandard() { this->SetShadingMode(STANDARD); }
  void SetShadingModeToHorizon() { this->SetShadingMode(HORIZON); }
  void SetShadingModeToVisibilityMask() { this->SetShadingMode(VISIBILITY_MASK); }
  const char* GetShadingModeAsString();
  ///@}

  ///@{
  /**
   * Lambert factor of the EXACT model: vtkSphericalCap::CENTROID (default, the paper's) or
   * vtkSphericalCap::MOMENT (exact for lights above the horizon).
   */
  virtual void SetLambertMode(int mode);
  vtkGetMacro(LambertMode, int);
  void SetLambertModeToCentroid() { this->SetLambertMode(vtkSphericalCap::CENTROID); }
  void SetLambertModeToMoment() { this->SetLambertMode(vtkSphericalCap::MOMENT); }
  ///@}

  ///@{
  /**
   * Point-data arrays with the apertures. Defaults: "BentNormal" and "ApertureRadius".
   */
  void SetBentNormalArrayName(const char* name);
  vtkGetCharFromStdStringMacro(BentNormalArrayName);
  void SetApertureRadiusArrayName(const char* name);
  vtkGetCharFromStdStringMacro(ApertureRadiusArrayName);
  ///@}

  ///@{
  /**
   * The point-data array of per-sector horizons that HORIZON shades from (vtkAperturePrecompute's
   * ComputeHorizonAngles). Default "HorizonAngles". Its convention is vtkHorizonLighting's, in
   * the model's frame: sectors counted from +x toward +y around +z, the way a height field made
   * from the aperture grid (vtkWarpScalar along z, or the grid itself) lies; actors may rotate and
   * scale uniformly. On the GPU each horizon takes 8 bits (vtkHorizonLighting::EncodeAngle());
   * more than 32 sectors are resampled to 32 (linear in azimuth). Per vertex they travel as
   * three vertex attributes, with their open sums around the point normals, and the vertex
   * shader shades the lights and the sky where the points have normals (the fragments
   * interpolate the results), otherwise the fragments shade from interpolated angles; per texel
   * as a 2D texture array of 4 sectors a layer (32 bytes a texel at 32 sectors), filtered
   * linearly between texels and shaded per fragment. The uniform sky is the cosine-weighted
   * sky through the sectors' open wedges (or their open fraction without SkyCosineWeighting); an
   * environment sky comes through the same wedges (vtkHorizonLighting::EnvironmentSkyTransfer(),
   * from vtkEnvironmentMap::NewWedgeTable() in the model's frame: 256 azimuths × 64 elevations):
   * per vertex computed on the CPU with the vertex buffers (PackAttributes()), per texel on the
   * CPU into a texture where the aperture image has point normals (the fragments take away the
   * lights' share: vtkHorizonLighting::OpenShare()), otherwise per fragment by the fragment shader
   * from the table as a 3D texture; computed again only when the model turns against the
   * environment.
   */
  void SetHorizonAnglesArrayName(const char* name);
  vtkGetCharFromStdStringMacro(HorizonAnglesArrayName);
  ///@}

  ///@{
  /**
   * The point-data array of visibility masks that VISIBILITY_MASK shades from
   * (vtkAperturePrecompute's ComputeVisibilityMask). Default "VisibilityMask": unsigned char,
   * bits/8 components, its cells in the tangent frame of the dataset's point normals (which the
   * mode needs, with an interpolation other than flat), in the model's frame; actors may rotate
   * and scale uniformly. Bits do not interpolate, so the mask is evaluated per vertex, in the
   * vertex shader: each light's transfer through the open cells (vtkVisibilityMask's 8 to 64
   * samples of the light's cap) and the uniform sky through them, which the fragments interpolate
   * (a mask per fragment would take the bits of one vertex of each triangle, and its facets show).
   * On the GPU a mask has at most 256 bits (32 bytes, three vertex attributes); finer masks are
   * resampled (a coarse cell is open where at least half of its 2 x 2 sub-grid falls in open
   * fine cells).
   * Both faces of a surface shade as its front. An environment sky comes through the open cells
   * (vtkVisibilityMask::EnvironmentSkyTransfer(), computed on the CPU with the vertex buffers).
   */
  void SetVisibilityMaskArrayName(const char* name);
  vtkGetCharFromStdStringMacro(VisibilityMaskArrayName);
  ///@}

  ///@{
  /**
   * Sky: colour and intensity of a uniform sky that fills the part of each aperture the lights
   * do not cover. An open aperture under a sky of intensity s gets s × SkyColor on top of its
   * lights. Defaults: white, intensity 0 (no sky).
   */
  vtkSetVector3Macro(SkyColor, double);
  vtkGetVector3Macro(SkyColor, double);
  vtkSetClampMacro(SkyIntensity, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(SkyIntensity, double);
  ///@}

  ///@{
  /**
   * A sky from an HDR environment instead of a uniform one: each aperture sees the environment's
   * radiance integrated over its cap, weighted by the cosine to the bent normal
   * (vtkEnvironmentMap::CapIrradiance(), tabulated once per environment on a 64 × 32 grid of axes
   * and 16 radii and looked up in the shader), over π, less the share the lights cover. It is
   * scaled by SkyColor × SkyIntensity: set SkyIntensity to 1 for the environment's own radiance.
   * Turning the environment (its Azimuth, Orientation) only changes a uniform. nullptr (the
   * default) for the uniform sky.
   *
   * VTK draws without any lighting when the renderer has no light switched on; for a scene lit
   * by the sky alone, add a light of intensity 0 (its cap, at the smallest radius, hides no
   * measurable part of the sky).
   */
  void SetSkyEnvironment(vtkEnvironmentMap* environment);
  vtkGetObjectMacro(SkyEnvironment, vtkEnvironmentMap);
  ///@}

  ///@{
  /**
   * Weight the sky by the cosine between the normal and the bent normal. Default on.
   */
  vtkSetMacro(SkyCosineWeighting, bool);
  vtkGetMacro(SkyCosineWeighting, bool);
  vtkBooleanMacro(SkyCosineWeighting, bool);
  ///@}

  ///@{
  /**
   * Angular radius (rad) of lights that carry no radius. Default 0.0047, the sun's.
   */
  vtkSetClampMacro(DefaultLightRadius, double, 0.0, 1.5707963267948966);
  vtkGetMacro(DefaultLightRadius, double);
  ///@}

  ///@{
  /**
   * Per-texel mode: a 2D grid from vtkAperturePrecompute's height-field mode whose point data
   * hold the aperture arrays; the mapper then reads apertures from it as a texture instead of
   * from vertex attributes. Texture coordinates are the input's point texture coordinates when
   * it has them (0..1 from the first to the last grid point), otherwise they are generated from
   * the x and y model coordinates, which suits surfaces made from the grid (vtkWarpScalar,
   * vtkImageDataGeometryFilter). Set nullptr for the per-vertex mode (default).
   */
  void SetApertureImage(vtkImageData* image);
  vtkGetObjectMacro(ApertureImage, vtkImageData);
  ///@}

  ///@{
  /**
   * The size of a light, stored on the light itself (in its vtkInformation): the angular radius
   * in radians of a directional light, the world-space radius of a positional one.
   * GetLightRadius() returns -1 for a light that carries none.
   */
  static vtkInformationDoubleKey* LIGHT_RADIUS();
  static void SetLightRadius(vtkLight* light, double radius);
  static double GetLightRadius(vtkLight* light);
  ///@}

  /**
   * Time of the last change that needs new shaders (model, arrays, per-texel mode).
   */
  vtkMTimeType GetShaderMTime() const { return this->ShaderTime.GetMTime(); }

  /**
   * For the mappers: an environment sky through horizons or masks per vertex is computed on the
   * CPU in the model's frame, as a vertex attribute. Each render tells the actor whose model it
   * is; GetBufferMTime() is the time of the last change that needs new vertex buffers (new
   * shaders, or the model turned against the environment, its image, or SkyCosineWeighting).
   */
  void UpdateVertexEnvironment(vtkActor* actor);
  vtkMTimeType GetBufferMTime() const;

  ///@{
  /**
   * For the mappers. CheckApertures() tells whether a dataset's aperture arrays (the image's, in
   * per-texel mode) can be shaded with, and warns once about each new problem. The result is
   * cached on the arrays' modification times.
   */
  bool CheckApertures(vtkDataSet* data);
  bool CheckApertures(vtkDataSet* data, std::string& problem);
  ///@}

  /**
   * For the mappers in per-texel mode: CheckApertures() on the aperture image, which must also fit
   * in the textures of the renderer's OpenGL (its context current); warns once otherwise.
   */
  bool CheckApertureImage(vtkRenderer* renderer);

  /**
   * For the mappers in HORIZON mode: the sectors the shaders get from a dataset's horizons (the
   * image's, per texel), or 0 where they cannot be used (missing, wrong component count, values
   * outside ±π/2 or not finite), with one warning per new problem: the exact cap applies then.
   * Cached on the array's modification time.
   */
  int CheckHorizons(vtkDataSet* data);

  /**
   * For the mappers in VISIBILITY_MASK mode: the bits the shaders get from a dataset's masks (at
   * most GetMaximumShaderMaskBits()), or 0 where they cannot be used (missing, not unsigned
   * char, a component count that is no mask's, no point normals), with one warning per new
   * problem: the exact cap applies then. Cached on the arrays' modification times.
   */
  int CheckVisibilityMask(vtkDataSet* data);

  /**
   * For the mappers: what the shading mode packs per vertex beside the apertures (the
   * horizons' sectors, the masks' bits; CheckHorizons() or CheckVisibilityMask()), or 0 for
   * nothing. Per texel only horizons are packed (as a texture); masks warn there.
   */
  int CheckPackedLayout(vtkDataSet* data);

  ///@{
  /**
   * For the mappers: the vertex attributes that carry a layout's values per vertex
   * (GetPackedAttributeName(i), i < GetNumberOfPackedAttributes(layout), at most 3), and their
   * values for a dataset: bytes three to a float (exact integers), four floats to an attribute.
   * Horizons are 8-bit codes resampled to `layout` sectors (at most GetMaximumShaderSectors(),
   * 32), open (−π/2) where the dataset has none usable; masks are their bytes, resampled to
   * `layout` bits, all open where the dataset has none usable. With an environment sky one
   * attribute follows (GetNumberOfVertexAttributes(), at most GetMaximumPackedAttributes()): the
   * environment through the vertex's open wedges or cells around its point normal, RGB, computed
   * without the lights (EnvironmentSkyTransfer() of vtkHorizonLighting or vtkVisibilityMask, on
   * the decoded horizons or resampled mask, in the frame of UpdateVertexEnvironment()'s actor);
   * zeros without point normals.
   */
  int GetNumberOfPackedAttributes(int layout) const;
  int GetNumberOfVertexAttributes(int layout) const;
  static int GetMaximumPackedAttributes() { return 4; }
  static int GetMaximumShaderSectors() { return 32; }
  static int GetMaximumShaderMaskBits() { return 256; }
  static std::string GetPackedAttributeName(int i);
  void PackAttributes(
    vtkDataSet* data, int layout, std::vector<vtkSmartPointer<vtkFloatArray>>& attributes);
  ///@}

  /**
   * For the mappers: writes the aperture lighting code into the shaders, or returns false where
   * standard shading applies (STANDARD, lighting off, PBR, the lighting-map pass keys).
   * perTexel selects texture lookups; inputTCoords whether their coordinates come from the
   * input's texture coordinates; packedLayout > 0 shades from the horizons or masks of that
   * layout (CheckPackedLayout()).
   */
  bool ReplaceShaderLight(std::map<vtkShader::Type, vtkShader*>& shaders, vtkActor* actor,
    vtkRenderer* renderer, int lightComplexity, int lightCount, bool perTexel, bool inputTCoords,
    int packedLayout = 0);

  /**
   * For the mappers: sets the uniforms the lighting code uses (light radii, sky, the aperture
   * texture and its coordinates). normalMatrix is the mapper's model-to-view normal matrix;
   * shift and scale are those of its point coordinates in the vertex buffer (the shader's
   * vertexMC is (x - shift) * scale), which generated texture coordinates undo.
   */
  void SetShaderParameters(vtkShaderProgram* program, vtkRenderer* renderer,
    vtkMatrix3x3* normalMatrix, bool inputTCoords, const double shift[3], const double scale[3]);

  /**
   * For the mappers: the model-to-view normal matrix of an actor, as vtkOpenGLPolyDataMapper
   * computes its normalMatrix uniform.
   */
  static void ComputeNormalMatrix(vtkRenderer* renderer, vtkActor* actor, vtkMatrix3x3* result);

  /**
   * For the mappers: after drawing, releases the texture units of the per-texel mode and of the
   * environment sky.
   */
  void DeactivateTexture();

  /**
   * Releases the textures of the per-texel mode and of the environment sky.
   */
  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkApertureLightingInterface();
  ~vtkApertureLightingInterface() override;

  int ShadingMode = EXACT;
  int LambertMode = vtkSphericalCap::CENTROID;
  std::string BentNormalArrayName = "BentNormal";
  std::string ApertureRadiusArrayName = "ApertureRadius";
  std::string HorizonAnglesArrayName = "HorizonAngles";
  std::string VisibilityMaskArrayName = "VisibilityMask";
  double SkyColor[3] = { 1.0, 1.0, 1.0 };
  double SkyIntensity = 0.0;
  bool SkyCosineWeighting = true;
  double DefaultLightRadius = 0.0047;
  vtkImageData* ApertureImage = nullptr;
  vtkEnvironmentMap* SkyEnvironment = nullptr;

private:
  vtkApertureLightingInterface(const vtkApertureLightingInterface&) = delete;
  void operator=(const vtkApertureLightingInterface&) = delete;

  // The fragment shader's declarations: VTK's lighting uniforms, the GLSL sources and the
  // defines that configure them.
  std::string GetFragmentDeclarations(
    vtkRenderer* renderer, int lightCount, bool perTexel, int horizonSectors, bool perVertex);
  // The parts of SetShaderParameters().
  void SetSkyParameters(vtkShaderProgram* program, vtkRenderer* renderer);
  void SetLightParameters(vtkShaderProgram* program, vtkRenderer* renderer);
  void SetTextureParameters(vtkShaderProgram* program, vtkRenderer* renderer, bool inputTCoords,
    const double shift[3], const double scale[3]);
  // Uploads the aperture image as a texture when it changed; false when OpenGL cannot make it.
  bool UploadTexture(vtkRenderer* renderer);
  // Uploads the aperture image's horizons as a 2D texture array when they changed.
  bool UploadHorizonTexture(vtkRenderer* renderer);
  // The fragment shader's apertureReadHorizons() and, per vertex, the vertex and geometry
  // shaders' decoding and passing of the horizons.
  static void ReplaceHorizonCode(
    std::string& vs, std::string& gs, std::string& fs, bool perTexel, int sectors);
  // The vertex shader's evaluation of the masks or horizons (the mode's declarations), per
  // light and for the sky, and the passing of the results to the fragment shader's
  // apertureReadVertexLighting().
  std::string GetVertexLightingDeclarations(int packedLayout);
  static void ReplaceVertexLightingCode(std::string& vs, std::string& gs, std::string& fs,
    vtkRenderer* renderer, int lightComplexity, int lightCount, int attributes,
    const std::string& modeDeclarations, bool environment);
  // Warns about a new problem (none when empty) once, and remembers it; the same for the masks.
  void Report(const std::string& problem);
  void ReportMask(const std::string& problem);
  // Builds the environment sky's table and uploads it as a 3D texture, when the environment's
  // image or blur changed.
  void UploadSkyTable(vtkRenderer* renderer);
  // Builds the environment's wedge table in the model's frame and uploads it as a 3D texture,
  // when the environment's image changed or the model turned against it; false when OpenGL
  // cannot make it.
  bool UploadSkyWedges(vtkRenderer* renderer, vtkMatrix3x3* normalMatrix);
  // The environment sky through the horizons or masks (`packed`, resampled to `layout`) of a
  // dataset's points, without the lights, RGB and a spare float a point: PackAttributes()'s last
  // attribute for vertices, UploadSkyTexels()'s texels for the aperture image.
  vtkSmartPointer<vtkFloatArray> ComputePointEnvironment(
    vtkDataSet* data, int layout, vtkDataArray* packed);
  // Whether the aperture image has point normals, for an environment sky per texel from the CPU.
  bool HasTexelNormals();
  // Computes and uploads that sky, as a 2D texture of the image's size, when the image, its
  // horizons or normals, or the environment changed; false when it cannot.
  bool UploadSkyTexels(vtkRenderer* renderer);

  vtkTimeStamp ShaderTime;
  vtkSmartPointer<vtkTextureObject> Texture;
  vtkTimeStamp TextureTime;
  vtkSmartPointer<vtkTextureObject> SkyTable;
  vtkSmartPointer<vtkTextureObject> HorizonTexture;
  unsigned int HorizonTextureHandle = 0;
  vtkTimeStamp HorizonTextureTime;
  int HorizonTextureSectors = 0;
  vtkDataArray* CheckedHorizons = nullptr;
  vtkMTimeType CheckedHorizonsTime = 0;
  int CheckedSectors = 0;
  std::string LastHorizonProblem;
  vtkDataArray* CheckedMask[2] = { nullptr, nullptr };
  vtkMTimeType CheckedMaskTime = 0;
  int CheckedMaskBits = 0;
  std::string LastMaskProblem;
  vtkMTimeType SkyTableTime = 0;
  vtkSmartPointer<vtkTextureObject> SkyWedges;
  vtkMTimeType SkyWedgesTime = 0;
  double SkyWedgesFrame[9] = { 0, 0, 0, 0, 0, 0, 0, 0, 0 };
  // UpdateVertexEnvironment()'s model to world, and what the environment attribute depends on.
  double VertexModelToWorld[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  vtkSmartPointer<vtkTextureObject> SkyTexels;
  bool TexelNormals = false; // HasTexelNormals() when the shaders were last asked for
  vtkMTimeType SkyTexelsTime = 0;
  int SkyTexelsSectors = 0;
  std::vector<double> VertexEnvironmentKey;
  vtkTimeStamp VertexEnvironmentTime;
  std::string LastProblem;
  vtkDataArray* CheckedArrays[2] = { nullptr, nullptr };
  vtkMTimeType CheckedTime = 0;
  bool CheckedResult = false;
};

#endif
