/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureLightingInterface.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureLightingInterface.h"

#include "vtkApertureLightCapGLSL.h"
#include "vtkApertureLightingFS.h"
#include "vtkApertureSMP.h"
#include "vtkApertureSkyTexture.h"
#include "vtkApertureText.h"
#include "vtkApertureVertexLightingVS.h"
#include "vtkHorizonLighting.h"
#include "vtkHorizonLightingCodeGLSL.h"
#include "vtkHorizonLightingGLSL.h"
#include "vtkHorizonLightingVS.h"
#include "vtkSphericalCap.h"
#include "vtkSphericalCapGLSL.h"
#include "vtkVisibilityMask.h"
#include "vtkVisibilityMaskGLSL.h"
#include "vtkVisibilityMaskVS.h"

#include "vtkActor.h"
#include "vtkArrayDispatch.h"
#include "vtkCamera.h"
#include "vtkCollectionIterator.h"
#include "vtkDataArray.h"
#include "vtkDataArrayRange.h"
#include "vtkEnvironmentMap.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleKey.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLightingMapPass.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLActor.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkApertureLightingInterface);
vtkInformationKeyMacro(vtkApertureLightingInterface, LIGHT_RADIUS, Double);

namespace
{
// Why an aperture array cannot be used, or an empty string.
std::string ArrayProblem(vtkDataSet* data, const std::string& name, int components)
{
  vtkDataArray* array = data->GetPointData()->GetArray(name.c_str());
  if (!array)
  {
    return "there is no point-data array named " + vtkApertureText::Quote(name);
  }
  if (array->GetNumberOfComponents() != components)
  {
    return vtkApertureText::Quote(name) + " has " + std::to_string(array->GetNumberOfComponents()) +
      " components instead of " + std::to_string(components);
  }
  if (array->GetNumberOfTuples() != data->GetNumberOfPoints())
  {
    return vtkApertureText::Quote(name) + " has " + std::to_string(array->GetNumberOfTuples()) +
      " tuples for " + std::to_string(data->GetNumberOfPoints()) + " points";
  }
  for (vtkIdType i = 0; i < array->GetNumberOfValues(); ++i)
  {
    if (!std::isfinite(array->GetComponent(i / components, static_cast<int>(i % components))))
    {
      return vtkApertureText::Quote(name) + " has non-finite values";
    }
  }
  return std::string();
}

// Horizons of `sectors` (at most GetMaximumShaderSectors()) as the GPU gets them: 8-bit codes of
// `in`'s D values, resampled linearly in azimuth to `sectors` when D differs.
void EncodeHorizons(const std::vector<float>& in, int sectors, unsigned char* codes)
{
  const int d = static_cast<int>(in.size());
  for (int k = 0; k < sectors; ++k)
  {
    const double middle = 2.0 * vtkMath::Pi() * (k + 0.5) / sectors;
    const double h = d == sectors ? in[k] : vtkHorizonLighting::HorizonAt(in.data(), d, middle);
    codes[k] = static_cast<unsigned char>(vtkHorizonLighting::EncodeAngle(h));
  }
}

// Point p's horizons as the GPU gets them (EncodeHorizons()), read through the scratch
// `tuple` and `in`, sized for the array's components.
void EncodePoint(vtkDataArray* horizons, vtkIdType p, int sectors, std::vector<double>& tuple,
  std::vector<float>& in, unsigned char* codes)
{
  horizons->GetTuple(p, tuple.data());
  std::copy(tuple.begin(), tuple.end(), in.begin());
  EncodeHorizons(in, sectors, codes);
}

// A mask of inBits resampled to outBits (vtkVisibilityMask's grids): a coarse cell is open where
// at least half the points of its 2 x 2 sub-grid fall in open fine cells.
void ResampleMask(const unsigned char* in, int inBits, int outBits, unsigned char* out)
{
  if (inBits == outBits)
  {
    std::copy(in, in + outBits / 8, out);
    return;
  }
  const int inSide = vtkVisibilityMask::GetSide(inBits);
  const int outSide = vtkVisibilityMask::GetSide(outBits);
  std::fill(out, out + outBits / 8, 0);
  for (int cell = 0; cell < outBits; ++cell)
  {
    int open = 0;
    for (int s = 0; s < 4; ++s)
    {
      const double u = (cell % outSide + 0.25 + 0.5 * (s % 2)) / outSide;
      const double v = (cell / outSide + 0.25 + 0.5 * (s / 2)) / outSide;
      const int fine = static_cast<int>(u * inSide) + inSide * static_cast<int>(v * inSide);
      open += (in[fine / 8] >> (fine % 8)) & 1;
    }
    out[cell / 8] |= static_cast<unsigned char>(open >= 2 ? 1 << (cell % 8) : 0);
  }
}

// The vec4 attributes that carry `bytes` bytes, three to a float.
int AttributesForBytes(int bytes)
{
  const int floats = (bytes + 2) / 3; // three bytes in a float's exact integers
  return (floats + 3) / 4;
}

// Adds `count` bytes to point p's packed attributes: three to a float, four floats to an
// attribute.
void PackBytes(
  const unsigned char* bytes, int count, const std::vector<float*>& values, vtkIdType p)
{
  for (int k = 0; k < count; ++k)
  {
    const int three = k / 3;
    values[three / 4][4 * p + three % 4] += static_cast<float>(bytes[k] << (8 * (k % 3)));
  }
}

// The open sums of a point's mask or horizons (OpenSums() of vtkVisibilityMask or
// vtkHorizonLighting), which do not depend on the lights, for the last float of its attributes:
// the solid angle over 4 pi plus 4096 times the cosine integral over pi, each in 12 bits, an
// exact integer below 2^24 (vtkApertureVertexLightingVS.glsl decodes it).
float PackSums(const double sums[2])
{
  const double pi = vtkMath::Pi();
  const long open = std::lround(std::min(1.0, std::max(0.0, sums[0] / (4.0 * pi))) * 4095.0);
  const long cosine = std::lround(std::min(1.0, std::max(0.0, sums[1] / pi)) * 4095.0);
  return static_cast<float>(open + 4096 * cosine);
}

// The masks' bytes (resampled to `bits`; open where there is no mask) and open sums.
void PackMasks(vtkUnsignedCharArray* mask, vtkIdType n, int bits, const std::vector<float*>& values)
{
  std::vector<unsigned char> codes(bits / 8, 255);
  const int inBits = mask ? 8 * mask->GetNumberOfComponents() : bits;
  for (vtkIdType p = 0; p < n; ++p)
  {
    if (mask)
    {
      ResampleMask(mask->GetPointer(p * inBits / 8), inBits, bits, codes.data());
    }
    PackBytes(codes.data(), bits / 8, values, p);
    double sums[2];
    vtkVisibilityMask::OpenSums(codes.data(), bits, sums);
    values.back()[4 * p + 3] = PackSums(sums);
  }
}

// The horizons' 8-bit codes (resampled to `sectors`; open where there are none) and their open
// sums around the point normals, where there are some, as the GPU sees them.
void PackHorizons(vtkDataArray* horizons, vtkDataArray* normals, vtkIdType n, int sectors,
  const std::vector<float*>& values)
{
  std::vector<float> in(horizons ? horizons->GetNumberOfComponents() : 1, -0.5f * vtkMath::Pi());
  std::vector<double> tuple(in.size());
  std::vector<unsigned char> codes(sectors);
  std::vector<float> decoded(sectors);
  for (vtkIdType p = 0; p < n; ++p)
  {
    if (horizons)
    {
      EncodePoint(horizons, p, sectors, tuple, in, codes.data());
    }
    else
    {
      EncodeHorizons(in, sectors, codes.data());
    }
    PackBytes(codes.data(), sectors, values, p);
    if (normals)
    {
      for (int k = 0; k < sectors; ++k)
      {
        decoded[k] = static_cast<float>(vtkHorizonLighting::DecodeAngle(codes[k]));
      }
      double normal[3], sums[2];
      normals->GetTuple(p, normal);
      vtkHorizonLighting::OpenSums(normal, decoded.data(), sectors, sums);
      values.back()[4 * p + 3] = PackSums(sums);
    }
  }
}

// Apertures reach the fragment shader as varyings in view coordinates, or as texture
// coordinates in the per-texel mode (from the input's, or from the model coordinates).
void ReplaceApertureVaryings(std::string& vs, std::string& gs, bool perTexel, bool inputTCoords)
{
  if (perTexel)
  {
    vtkShaderProgram::Substitute(vs, "//VTK::Normal::Dec",
      std::string("//VTK::Normal::Dec\n") + (inputTCoords ? "in vec2 apertureTCoordMC;\n" : "") +
        "uniform vec4 apertureTexTransform;\n"
        "out vec2 apertureUVVSOutput;");
    vtkShaderProgram::Substitute(vs, "//VTK::Normal::Impl",
      std::string("//VTK::Normal::Impl\n") + "  apertureUVVSOutput = apertureTexTransform.xy * " +
        (inputTCoords ? "apertureTCoordMC" : "vertexMC.xy") + " + apertureTexTransform.zw;");
    vtkShaderProgram::Substitute(gs, "//VTK::Normal::Dec",
      "//VTK::Normal::Dec\n"
      "in vec2 apertureUVVSOutput[];\n"
      "out vec2 apertureUVGSOutput;");
    vtkShaderProgram::Substitute(gs, "//VTK::Normal::Impl",
      "//VTK::Normal::Impl\n"
      "apertureUVGSOutput = apertureUVVSOutput[i];");
    return;
  }
  vtkShaderProgram::Substitute(vs, "//VTK::Normal::Dec",
    "//VTK::Normal::Dec\n"
    "in vec3 bentNormalMC;\n"
    "in float apertureRadiusMC;\n"
    "uniform mat3 apertureNormalMatrix;\n"
    "out vec3 bentNormalVCVSOutput;\n"
    "out float apertureRadiusVSOutput;");
  vtkShaderProgram::Substitute(vs, "//VTK::Normal::Impl",
    "//VTK::Normal::Impl\n"
    "  bentNormalVCVSOutput = apertureNormalMatrix * bentNormalMC;\n"
    "  apertureRadiusVSOutput = apertureRadiusMC;");
  vtkShaderProgram::Substitute(gs, "//VTK::Normal::Dec",
    "//VTK::Normal::Dec\n"
    "in vec3 bentNormalVCVSOutput[];\n"
    "in float apertureRadiusVSOutput[];\n"
    "out vec3 bentNormalVCGSOutput;\n"
    "out float apertureRadiusGSOutput;");
  vtkShaderProgram::Substitute(gs, "//VTK::Normal::Impl",
    "//VTK::Normal::Impl\n"
    "bentNormalVCGSOutput = bentNormalVCVSOutput[i];\n"
    "apertureRadiusGSOutput = apertureRadiusVSOutput[i];");
}

// The call of vtkApertureLightingFS.glsl that adds light i, with VTK's uniforms of that light,
// which VTK names one by one (lightColor0, lightColor1, ...) rather than as arrays.
std::string LightCall(int lightComplexity, int i)
{
  const std::string n = std::to_string(i);
  const std::string cap = "apertureLightCap[" + n + "]";
  if (lightComplexity == 1)
  {
    return "  apertureHeadlight(lightColor0, " + cap + ", fragment);\n";
  }
  if (lightComplexity == 2)
  {
    return "  apertureDirectionalLight(lightDirectionVC" + n + ", lightColor" + n + ", " + cap +
      ", fragment);\n";
  }
  return "  aperturePositionalLight(lightDirectionVC" + n + ", lightColor" + n + ", " + cap +
    ", lightPositional" + n + ", lightPositionVC" + n + ", lightAttenuation" + n +
    ", lightConeAngle" + n + ", lightExponent" + n + ", apertureLightWorldRadius[" + n +
    "], fragment);\n";
}

// The cap of light i at a vertex, from the same uniforms as LightCall().
std::string VertexLightCap(int lightComplexity, int i)
{
  const std::string n = std::to_string(i);
  const std::string cap = "apertureLightCap[" + n + "]";
  if (lightComplexity == 1)
  {
    return "sphericalCapCap(vec3(0.0, 0.0, 1.0), " + cap + ".x, " + cap + ".y, " + cap + ".z)";
  }
  if (lightComplexity == 2)
  {
    return "sphericalCapCap(-lightDirectionVC" + n + ", " + cap + ".x, " + cap + ".y, " + cap +
      ".z)";
  }
  return "apertureLightCapAt(lightDirectionVC" + n + ", " + cap + ", lightPositional" + n +
    ", lightPositionVC" + n + ", apertureLightWorldRadius[" + n + "], vertexVCVSOutput.xyz)";
}

// The lighting of main(): the fragment's aperture, its lights, then its colour.
std::string FragmentImplementation(int lightComplexity, int lightCount)
{
  std::string impl = "  apertureFragment fragment =\n"
                     "    apertureBeginFragment(normalVCVSOutput, vertexVC.xyz, specularPower);\n";
  for (int i = 0; i < lightCount; ++i)
  {
    impl += LightCall(lightComplexity, i);
  }
  return impl +
    "  gl_FragData[0] =\n"
    "    apertureEndFragment(fragment, ambientColor, diffuseColor, specularColor, opacity);\n"
    "  //VTK::Light::Impl\n";
}

// The sky's matrix: view coordinates to world (the camera's rotation, transposed), then to the
// environment; transposed, as SetUniformMatrix() hands GL a row-major matrix for a column-major
// one.
void ViewToEnvironment(vtkEnvironmentMap* environment, vtkRenderer* renderer, vtkMatrix3x3* result)
{
  double toEnvironment[9];
  environment->GetWorldToEnvironment(toEnvironment);
  vtkMatrix4x4* view = renderer->GetActiveCamera()->GetModelViewTransformMatrix();
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      double sum = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        sum += toEnvironment[3 * i + k] * view->GetElement(j, k);
      }
      result->SetElement(j, i, sum);
    }
  }
}

// The model's frame to world (row-major): the normal matrix (model to view, a rotation over the
// actor's uniform scale), then the camera's rotation transposed.
void ModelToWorld(vtkRenderer* renderer, vtkMatrix3x3* normalMatrix, double frame[9])
{
  vtkMatrix4x4* view = renderer->GetActiveCamera()->GetModelViewTransformMatrix();
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      frame[3 * i + j] = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        frame[3 * i + j] += view->GetElement(k, i) * normalMatrix->GetElement(k, j);
      }
    }
  }
}

// The model's frame (ModelToWorld()'s) to the environment's, scaled to a rotation (row-major).
void ModelToEnvironment(vtkEnvironmentMap* environment, const double frame[9], double result[9])
{
  double toEnvironment[9];
  environment->GetWorldToEnvironment(toEnvironment);
  vtkMath::Multiply3x3(reinterpret_cast<const double(*)[3]>(toEnvironment),
    reinterpret_cast<const double(*)[3]>(frame), reinterpret_cast<double(*)[3]>(result));
  const double scale =
    std::cbrt(std::abs(vtkMath::Determinant3x3(reinterpret_cast<const double(*)[3]>(result))));
  for (int i = 0; i < 9; ++i)
  {
    result[i] /= scale;
  }
}
}

//------------------------------------------------------------------------------
vtkApertureLightingInterface::vtkApertureLightingInterface()
{
  this->ShaderTime.Modified();
}

//------------------------------------------------------------------------------
vtkApertureLightingInterface::~vtkApertureLightingInterface()
{
  this->SetApertureImage(nullptr);
  this->SetSkyEnvironment(nullptr);
}

//------------------------------------------------------------------------------
void vtkApertureLightingInterface::SetShadingMode(int mode)
{
  mode = std::min(std::max(mode, static_cast<int>(EXACT)), static_cast<int>(VISIBILITY_MASK));
  if (mode != this->ShadingMode)
  {
    this->ShadingMode = mode;
    this->ShaderTime.Modified();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkApertureLightingInterface::SetLambertMode(int mode)
{
  mode = std::min(std::max(mode, static_cast<int>(vtkSphericalCap::CENTROID)),
    static_cast<int>(vtkSphericalCap::MOMENT));
  if (mode != this->LambertMode)
  {
    this->LambertMode = mode;
    this->ShaderTime.Modified();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
const char* vtkApertureLightingInterface::GetShadingModeAsString()
{
  static const char* names[] = { "Exact", "Smoothstep", "Simplified", "BentNormal", "Standard",
    "Horizon", "VisibilityMask" };
  return names[this->ShadingMode];
}

//------------------------------------------------------------------------------
void vtkApertureLightingInterface::SetBentNormalArrayName(const char* name)
{
  const std::string value = name ? name : "";
  if (value != this->BentNormalArrayName)
  {
    this->BentNormalArrayName = value;
    this->CheckedTime = 0;
    this->ShaderTime.Modified();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkApertureLightingInterface::SetApertureRadiusArrayName(const char* name)
{
  const std::string value = name ? name : "";
  if (value != this->ApertureRadiusArrayName)
  {
    this->ApertureRadiusArrayName = value;
    this->CheckedTime = 0;
    this->ShaderTime.Modified();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkApertureLightingInterface::SetHorizonAnglesArrayName(const char* name)
{
  const std::string value = name ? name : "";
  if (value != this->HorizonAnglesArrayName)
  {
    this->HorizonAnglesArrayName = value;
    this->CheckedHorizonsTime = 0;
    this->ShaderTime.Modified();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkApertureLightingInterface::SetVisibilityMaskArrayName(const char* name)
{
  const std::string value = name ? name : "";
  if (value != this->VisibilityMaskArrayName)
  {
    this->VisibilityMaskArrayName = value;
    this->CheckedMaskTime = 0;
    this->ShaderTime.Modified();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkApertureLightingInterface::SetApertureImage(vtkImageData* image)
{
  if (image == this->ApertureImage)
  {
    return;
  }
  // Switching between per-vertex and per-texel apertures changes the shaders.
  if (!image != !this->ApertureImage)
  {
    this->ShaderTime.Modified();
  }
  if (this->ApertureImage)
  {
    this->ApertureImage->UnRegister(this);
  }
  this->ApertureImage = image;
  if (image)
  {
    image->Register(this);
  }
  this->CheckedTime = 0;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkApertureLightingInterface::SetSkyEnvironment(vtkEnvironmentMap* environment)
{
  if (this->SkyEnvironment == environment)
  {
    return;
  }
  // Switching between the uniform and the environment sky changes the shaders.
  if (!this->SkyEnvironment != !environment)
  {
    this->ShaderTime.Modified();
  }
  vtkEnvironmentMap* previous = this->SkyEnvironment;
  this->SkyEnvironment = environment;
  if (environment)
  {
    environment->Register(this);
  }
  if (previous)
  {
    previous->UnRegister(this);
  }
  this->SkyTableTime = 0;
  this->SkyWedgesTime = 0;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkApertureLightingInterface::SetLightRadius(vtkLight* light, double radius)
{
  if (light)
  {
    light->GetInformation()->Set(LIGHT_RADIUS(), radius);
    light->Modified();
  }
}

//------------------------------------------------------------------------------
double vtkApertureLightingInterface::GetLightRadius(vtkLight* light)
{
  vtkInformation* info = light ? light->GetInformation() : nullptr;
  return info && info->Has(LIGHT_RADIUS()) ? info->Get(LIGHT_RADIUS()) : -1.0;
}

//------------------------------------------------------------------------------
bool vtkApertureLightingInterface::CheckApertures(vtkDataSet* data)
{
  std::string problem;
  return this->CheckApertures(data, problem);
}

//------------------------------------------------------------------------------
bool vtkApertureLightingInterface::CheckApertures(vtkDataSet* data, std::string& problem)
{
  if (!data)
  {
    problem = "there is no input";
    return false;
  }
  vtkPointData* pd = data->GetPointData();
  vtkDataArray* bent = pd->GetArray(this->BentNormalArrayName.c_str());
  vtkDataArray* radius = pd->GetArray(this->ApertureRadiusArrayName.c_str());
  const vtkMTimeType time =
    std::max({ data->GetMTime(), bent ? bent->GetMTime() : 0, radius ? radius->GetMTime() : 0 });
  if (bent == this->CheckedArrays[0] && radius == this->CheckedArrays[1] &&
    time <= this->CheckedTime)
  {
    problem = this->CheckedResult ? std::string() : this->LastProblem;
    return this->CheckedResult;
  }
  problem = ArrayProblem(data, this->BentNormalArrayName, 3);
  if (problem.empty())
  {
    problem = ArrayProblem(data, this->ApertureRadiusArrayName, 1);
  }
  this->CheckedArrays[0] = bent;
  this->CheckedArrays[1] = radius;
  this->CheckedTime = time;
  this->CheckedResult = problem.empty();
  this->Report(problem);
  return this->CheckedResult;
}

//------------------------------------------------------------------------------
bool vtkApertureLightingInterface::CheckApertureImage(vtkRenderer* renderer)
{
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  const int largest = window ? vtkTextureObject::GetMaximumTextureSize(window) : -1;
  int dims[3] = { 0, 0, 0 };
  if (this->ApertureImage)
  {
    this->ApertureImage->GetDimensions(dims);
  }
  if (largest > 0 && std::max(dims[0], dims[1]) > largest)
  {
    std::ostringstream problem;
    problem << "the aperture grid of " << dims[0] << " x " << dims[1]
            << " texels is larger than this OpenGL's textures (" << largest
            << " a side); resample it (vtkImageResize) first";
    this->Report(problem.str());
    return false;
  }
  // Normals in the image decide where an environment sky per texel is computed.
  if (this->HasTexelNormals() != this->TexelNormals)
  {
    this->TexelNormals = !this->TexelNormals;
    this->ShaderTime.Modified();
  }
  return this->CheckApertures(this->ApertureImage);
}

//------------------------------------------------------------------------------
namespace
{
// Why a horizons array cannot be shaded with, or an empty string.
std::string HorizonProblem(vtkDataSet* data, const std::string& name)
{
  vtkDataArray* array = data->GetPointData()->GetArray(name.c_str());
  if (!array)
  {
    return "there is no point-data array named " + vtkApertureText::Quote(name) +
      " (vtkAperturePrecompute's ComputeHorizonAngles writes it)";
  }
  const int sectors = array->GetNumberOfComponents();
  if (sectors < 4 || sectors > 1024)
  {
    return vtkApertureText::Quote(name) + " has " + std::to_string(sectors) +
      " components; horizons need 4 to 1024 sectors";
  }
  if (array->GetNumberOfTuples() != data->GetNumberOfPoints())
  {
    return vtkApertureText::Quote(name) + " has " + std::to_string(array->GetNumberOfTuples()) +
      " tuples for " + std::to_string(data->GetNumberOfPoints()) + " points";
  }
  // vtkAperturePrecompute names components by their middle azimuths; turned sectors do not
  // start where the shading expects sector 0.
  const char* first = array->GetComponentName(0);
  if (first && std::strncmp(first, "Az", 2) == 0 &&
    std::abs(std::atof(first + 2) - vtkHorizonLighting::SectorAzimuth(0, sectors)) > 1e-3)
  {
    return vtkApertureText::Quote(name) + "'s sectors are turned (its first is " + first +
      "); the Horizon mode needs SectorRotation 0";
  }
  // Single-precision pi/2 lies just past the double one.
  const double pole = static_cast<float>(0.5 * vtkMath::Pi());
  for (vtkIdType i = 0; i < array->GetNumberOfValues(); ++i)
  {
    const double h = array->GetComponent(i / sectors, static_cast<int>(i % sectors));
    if (!(h >= -pole && h <= pole))
    {
      return vtkApertureText::Quote(name) + " has values that are not angles in [-pi/2, pi/2]";
    }
  }
  return std::string();
}
}

//------------------------------------------------------------------------------
int vtkApertureLightingInterface::CheckHorizons(vtkDataSet* data)
{
  vtkDataArray* array =
    data ? data->GetPointData()->GetArray(this->HorizonAnglesArrayName.c_str()) : nullptr;
  const vtkMTimeType time = std::max(data ? data->GetMTime() : 0, array ? array->GetMTime() : 0);
  if (array == this->CheckedHorizons && time <= this->CheckedHorizonsTime && array)
  {
    return this->CheckedSectors;
  }
  const std::string problem =
    data ? HorizonProblem(data, this->HorizonAnglesArrayName) : "there is no input";
  if (!problem.empty() && problem != this->LastHorizonProblem)
  {
    vtkWarningMacro("Cannot shade with horizons: " << problem << "; using the exact cap.");
  }
  this->LastHorizonProblem = problem;
  this->CheckedHorizons = array;
  this->CheckedHorizonsTime = time;
  this->CheckedSectors =
    problem.empty() ? std::min(array->GetNumberOfComponents(), GetMaximumShaderSectors()) : 0;
  return this->CheckedSectors;
}

//------------------------------------------------------------------------------
namespace
{
// Why a visibility mask array cannot be shaded with, or an empty string.
std::string MaskProblem(vtkDataSet* data, const std::string& name)
{
  vtkDataArray* array = data->GetPointData()->GetArray(name.c_str());
  if (!array)
  {
    return "there is no point-data array named " + vtkApertureText::Quote(name) +
      " (vtkAperturePrecompute's ComputeVisibilityMask writes it)";
  }
  if (!vtkUnsignedCharArray::SafeDownCast(array))
  {
    return vtkApertureText::Quote(name) + " is not an unsigned char array";
  }
  const int bits = 8 * array->GetNumberOfComponents();
  if (!vtkVisibilityMask::IsValidBitCount(bits))
  {
    return vtkApertureText::Quote(name) + " has " + std::to_string(bits) +
      " bits a point, which no mask has (64, 144, 256, 400, 576, 784 or 1024)";
  }
  if (array->GetNumberOfTuples() != data->GetNumberOfPoints())
  {
    return vtkApertureText::Quote(name) + " has " + std::to_string(array->GetNumberOfTuples()) +
      " tuples for " + std::to_string(data->GetNumberOfPoints()) + " points";
  }
  vtkDataArray* normals = data->GetPointData()->GetNormals();
  if (!normals || normals->GetNumberOfComponents() != 3)
  {
    return "the dataset has no point normals, which give a mask its frame";
  }
  return std::string();
}
}

//------------------------------------------------------------------------------
int vtkApertureLightingInterface::CheckVisibilityMask(vtkDataSet* data)
{
  vtkPointData* pd = data ? data->GetPointData() : nullptr;
  vtkDataArray* array = pd ? pd->GetArray(this->VisibilityMaskArrayName.c_str()) : nullptr;
  vtkDataArray* normals = pd ? pd->GetNormals() : nullptr;
  const vtkMTimeType time = std::max({ data ? data->GetMTime() : 0, array ? array->GetMTime() : 0,
    normals ? normals->GetMTime() : 0 });
  if (array && array == this->CheckedMask[0] && normals == this->CheckedMask[1] &&
    time <= this->CheckedMaskTime)
  {
    return this->CheckedMaskBits;
  }
  const std::string problem =
    data ? MaskProblem(data, this->VisibilityMaskArrayName) : "there is no input";
  this->ReportMask(problem);
  this->CheckedMask[0] = array;
  this->CheckedMask[1] = normals;
  this->CheckedMaskTime = time;
  this->CheckedMaskBits =
    problem.empty() ? std::min(8 * array->GetNumberOfComponents(), GetMaximumShaderMaskBits()) : 0;
  return this->CheckedMaskBits;
}

//------------------------------------------------------------------------------
int vtkApertureLightingInterface::CheckPackedLayout(vtkDataSet* data)
{
  if (this->ShadingMode == HORIZON)
  {
    return this->CheckHorizons(data);
  }
  if (this->ShadingMode != VISIBILITY_MASK)
  {
    return 0;
  }
  if (data && data == this->ApertureImage)
  {
    this->ReportMask("masks are per point of a mesh, not per texel of an aperture image");
    return 0;
  }
  return this->CheckVisibilityMask(data);
}

//------------------------------------------------------------------------------
void vtkApertureLightingInterface::ReportMask(const std::string& problem)
{
  if (!problem.empty() && problem != this->LastMaskProblem)
  {
    vtkWarningMacro("Cannot shade with visibility masks: " << problem << "; using the exact cap.");
  }
  this->LastMaskProblem = problem;
}

//------------------------------------------------------------------------------
int vtkApertureLightingInterface::GetNumberOfPackedAttributes(int layout) const
{
  // The bytes, and a float for the open sums.
  return AttributesForBytes((this->ShadingMode == VISIBILITY_MASK ? layout / 8 : layout) + 3);
}

//------------------------------------------------------------------------------
std::string vtkApertureLightingInterface::GetPackedAttributeName(int i)
{
  return "aperturePacked" + std::to_string(i) + "MC";
}

//------------------------------------------------------------------------------
void vtkApertureLightingInterface::PackAttributes(
  vtkDataSet* data, int layout, std::vector<vtkSmartPointer<vtkFloatArray>>& attributes)
{
  const vtkIdType n = data->GetNumberOfPoints();
  const bool masks = this->ShadingMode == VISIBILITY_MASK;
  vtkDataArray* array = nullptr;
  if (this->CheckPackedLayout(data) > 0)
  {
    array = data->GetPointData()->GetArray(
      (masks ? this->VisibilityMaskArrayName : this->HorizonAnglesArrayName).c_str());
  }
  attributes.resize(this->GetNumberOfPackedAttributes(layout));
  std::vector<float*> values;
  for (auto& attribute : attributes)
  {
    attribute = vtkSmartPointer<vtkFloatArray>::New();
    attribute->SetNumberOfComponents(4);
    attribute->SetNumberOfTuples(n);
    attribute->Fill(0.0);
    values.push_back(attribute->GetPointer(0));
  }
  vtkDataArray* normals = data->GetPointData()->GetNormals();
  const bool usable =
    normals && normals->GetNumberOfComponents() == 3 && normals->GetNumberOfTuples() == n;
  if (masks)
  {
    // CheckVisibilityMask() made sure of the array's type.
    PackMasks(static_cast<vtkUnsignedCharArray*>(array), n, layout, values);
  }
  else
  {
    PackHorizons(array, usable ? normals : nullptr, n, layout, values);
  }
  if (this->SkyEnvironment)
  {
    attributes.push_back(this->ComputePointEnvironment(data, layout, array));
  }
}

//------------------------------------------------------------------------------
int vtkApertureLightingInterface::GetNumberOfVertexAttributes(int layout) const
{
  return this->GetNumberOfPackedAttributes(layout) + (this->SkyEnvironment ? 1 : 0);
}

//------------------------------------------------------------------------------
void vtkApertureLightingInterface::UpdateVertexEnvironment(vtkActor* actor)
{
  std::vector<double> key;
  if (this->SkyEnvironment &&
    (this->ShadingMode == HORIZON || this->ShadingMode == VISIBILITY_MASK))
  {
    vtkMatrix4x4* matrix = actor->GetMatrix();
    key.resize(21);
    for (int i = 0; i < 9; ++i)
    {
      key[i] = matrix->GetElement(i / 3, i % 3);
    }
    this->SkyEnvironment->GetWorldToEnvironment(&key[9]);
    key[18] = static_cast<double>(this->SkyEnvironment->GetImageMTime());
    key[19] = this->SkyCosineWeighting ? 1.0 : 0.0;
    key[20] = this->ShadingMode;
  }
  if (key != this->VertexEnvironmentKey)
  {
    this->VertexEnvironmentKey = key;
    if (!key.empty())
    {
      std::copy(key.begin(), key.begin() + 9, this->VertexModelToWorld);
    }
    this->VertexEnvironmentTime.Modified();
  }
}

//------------------------------------------------------------------------------
vtkMTimeType vtkApertureLightingInterface::GetBufferMTime() const
{
  return std::max(this->ShaderTime.GetMTime(), this->VertexEnvironmentTime.GetMTime());
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkFloatArray> vtkApertureLightingInterface::ComputePointEnvironment(
  vtkDataSet* data, int layout, vtkDataArray* packed)
{
  const vtkIdType n = data->GetNumberOfPoints();
  auto sky = vtkSmartPointer<vtkFloatArray>::New();
  sky->SetNumberOfComponents(4);
  sky->SetNumberOfTuples(n);
  sky->Fill(0.0);
  vtkDataArray* normals = data->GetPointData()->GetNormals();
  if (!normals || normals->GetNumberOfComponents() != 3 || normals->GetNumberOfTuples() != n)
  {
    return sky;
  }
  float* out = sky->GetPointer(0);
  const bool cosine = this->SkyCosineWeighting;
  vtkSmartPointer<vtkImageData> table;
  if (this->ShadingMode == VISIBILITY_MASK)
  {
    table.TakeReference(
      this->SkyEnvironment->NewMeanRadianceTable(64, 32, vtkVisibilityMask::CellCapRadius(layout)));
    const float* mean =
      vtkFloatArray::SafeDownCast(table->GetPointData()->GetScalars())->GetPointer(0);
    double toEnvironment[9];
    ModelToEnvironment(this->SkyEnvironment, this->VertexModelToWorld, toEnvironment);
    auto* mask = static_cast<vtkUnsignedCharArray*>(packed); // CheckVisibilityMask()'s type
    const int inBits = mask ? 8 * mask->GetNumberOfComponents() : layout;
    vtkApertureSMP::For(0, n,
      [&](vtkIdType first, vtkIdType last)
      {
        std::vector<unsigned char> codes(layout / 8, 255);
        for (vtkIdType p = first; p < last; ++p)
        {
          if (mask)
          {
            ResampleMask(mask->GetPointer(p * inBits / 8), inBits, layout, codes.data());
          }
          double normal[3], rgb[3];
          normals->GetTuple(p, normal);
          vtkVisibilityMask::EnvironmentSkyTransfer(
            normal, codes.data(), layout, mean, 64, 32, toEnvironment, 0.0, 0.0, cosine, rgb);
          std::copy(rgb, rgb + 3, out + 4 * p);
        }
      });
    return sky;
  }
  table.TakeReference(this->SkyEnvironment->NewWedgeTable(256, 64, this->VertexModelToWorld));
  const float* wedges =
    vtkFloatArray::SafeDownCast(table->GetPointData()->GetScalars())->GetPointer(0);
  vtkApertureSMP::For(0, n,
    [&](vtkIdType first, vtkIdType last)
    {
      std::vector<float> in(packed ? packed->GetNumberOfComponents() : 1, -0.5f * vtkMath::Pi());
      std::vector<double> tuple(in.size());
      std::vector<unsigned char> codes(layout);
      std::vector<float> decoded(layout);
      for (vtkIdType p = first; p < last; ++p)
      {
        if (packed)
        {
          EncodePoint(packed, p, layout, tuple, in, codes.data());
        }
        else
        {
          EncodeHorizons(in, layout, codes.data());
        }
        for (int k = 0; k < layout; ++k)
        {
          decoded[k] = static_cast<float>(vtkHorizonLighting::DecodeAngle(codes[k]));
        }
        double normal[3], rgb[3];
        normals->GetTuple(p, normal);
        vtkHorizonLighting::EnvironmentSkyTransfer(
          normal, decoded.data(), layout, wedges, 256, 64, 0.0, 0.0, cosine, rgb);
        std::copy(rgb, rgb + 3, out + 4 * p);
      }
    });
  return sky;
}

//------------------------------------------------------------------------------
void vtkApertureLightingInterface::Report(const std::string& problem)
{
  if (!problem.empty() && problem != this->LastProblem)
  {
    vtkWarningMacro("Cannot shade with apertures: " << problem << "; using standard shading.");
  }
  this->LastProblem = problem;
}

//------------------------------------------------------------------------------
bool vtkApertureLightingInterface::ReplaceShaderLight(
  std::map<vtkShader::Type, vtkShader*>& shaders, vtkActor* actor, vtkRenderer* renderer,
  int lightComplexity, int lightCount, bool perTexel, bool inputTCoords, int packedLayout)
{
  vtkInformation* keys = actor->GetPropertyKeys();
  if (this->ShadingMode == STANDARD || lightComplexity < 1 || lightCount < 1 ||
    actor->GetProperty()->GetInterpolation() == VTK_PBR ||
    (keys &&
      (keys->Has(vtkLightingMapPass::RENDER_NORMALS()) ||
        keys->Has(vtkLightingMapPass::RENDER_LUMINANCE()))))
  {
    return false;
  }

  std::string vs = shaders[vtkShader::Vertex]->GetSource();
  std::string gs = shaders[vtkShader::Geometry]->GetSource();
  std::string fs = shaders[vtkShader::Fragment]->GetSource();
  // The masks need the point normals, which VTK leaves out of flat-shaded buffers.
  const bool normals = vs.find("in vec3 normalMC;") != std::string::npos;
  if (this->ShadingMode == VISIBILITY_MASK && packedLayout > 0 && !normals)
  {
    this->ReportMask("flat interpolation leaves out the point normals");
    packedLayout = 0;
  }
  // Masks, and horizons per vertex where the points have normals, are evaluated per vertex (the
  // lights and the sky vary slowly, and a varying a light costs less than the horizons'
  // eight); horizons otherwise per fragment, from their interpolated angles or their texture.
  const bool perVertex = packedLayout > 0 && !perTexel && normals;
  ReplaceApertureVaryings(vs, gs, perTexel, inputTCoords);
  vtkShaderProgram::Substitute(fs, "//VTK::Light::Dec",
    this->GetFragmentDeclarations(
      renderer, lightCount, perTexel, perVertex ? 0 : packedLayout, perVertex));
  vtkShaderProgram::Substitute(
    fs, "//VTK::Light::Impl", FragmentImplementation(lightComplexity, lightCount), false);
  if (perVertex)
  {
    ReplaceVertexLightingCode(vs, gs, fs, renderer, lightComplexity, lightCount,
      this->GetNumberOfPackedAttributes(packedLayout),
      this->GetVertexLightingDeclarations(packedLayout), this->SkyEnvironment != nullptr);
  }
  else if (packedLayout > 0)
  {
    ReplaceHorizonCode(vs, gs, fs, perTexel, packedLayout);
  }
  shaders[vtkShader::Vertex]->SetSource(vs);
  shaders[vtkShader::Geometry]->SetSource(gs);
  shaders[vtkShader::Fragment]->SetSource(fs);
  return true;
}

//------------------------------------------------------------------------------
std::string vtkApertureLightingInterface::GetFragmentDeclarations(
  vtkRenderer* renderer, int lightCount, bool perTexel, int horizonSectors, bool perVertex)
{
  // The cap's model where horizons or masks are asked for: the exact one, for the environment
  // sky and for data without them.
  const int shading = this->ShadingMode > STANDARD ? EXACT : this->ShadingMode;
  std::ostringstream dec;
  dec << static_cast<vtkOpenGLRenderer*>(renderer)->GetLightingUniforms() << "\n"
      << vtkSphericalCap::GetGLSLConstants() << "#define APERTURE_SHADING " << shading << "\n"
      << "#define APERTURE_LAMBERT " << this->LambertMode << "\n"
      << "#define APERTURE_LIGHT_COUNT " << lightCount << "\n"
      << (perTexel ? "#define APERTURE_PER_TEXEL\n" : "")
      << (this->SkyEnvironment ? "#define APERTURE_SKY_ENVIRONMENT\n" : "") << vtkSphericalCapGLSL
      << "\n"
      << vtkApertureLightCapGLSL << "\n";
  if (perVertex)
  {
    dec << "#define APERTURE_VERTEX_LIGHTING\n";
  }
  // An environment sky comes through what horizons or masks leave open: per vertex, per texel
  // from the CPU where the aperture image has normals, or per fragment above horizons.
  if (this->SkyEnvironment && perTexel && horizonSectors > 0 && this->HasTexelNormals())
  {
    dec << "#define APERTURE_TEXEL_ENVIRONMENT\n";
  }
  else if (this->SkyEnvironment && (perVertex || horizonSectors > 0))
  {
    dec << "#define APERTURE_OPEN_ENVIRONMENT\n"
        << (horizonSectors > 0 ? "#define HORIZON_LIGHTING_ENVIRONMENT\n" : "");
  }
  if (horizonSectors > 0)
  {
    dec << "#define APERTURE_HORIZONS\n"
        << "#define HORIZON_LIGHTING_SECTORS " << horizonSectors << "\n"
        << vtkHorizonLighting::GetGLSLConstants() << vtkHorizonLightingCodeGLSL << "\n"
        << vtkHorizonLightingGLSL << "\n";
  }
  dec << vtkApertureLightingFS << "\n"
      << "//VTK::Light::Dec\n";
  return dec.str();
}

//------------------------------------------------------------------------------
void vtkApertureLightingInterface::ReplaceHorizonCode(
  std::string& vs, std::string& gs, std::string& fs, bool perTexel, int sectors)
{
  const int outputs = (sectors + 3) / 4;
  std::ostringstream read;
  read << "void apertureReadHorizons()\n{\n";
  if (perTexel)
  {
    // Four 8-bit codes a layer, filtered between texels.
    vtkShaderProgram::Substitute(fs, "//APERTURE::Horizons::Dec",
      "uniform sampler2DArray apertureHorizonTexture;\n//APERTURE::Horizons::Dec");
    read << "  for (int k = 0; k < HORIZON_LIGHTING_SECTORS; ++k)\n  {\n"
         << "    vec4 codes = texture(apertureHorizonTexture, vec3(apertureUVVSOutput, "
            "float(k / 4)));\n"
         << "    horizonLightingHorizons[k] = horizonLightingDecode(codes[k % 4]);\n  }\n}\n";
    vtkShaderProgram::Substitute(fs, "//APERTURE::Horizons::Dec", read.str());
    return;
  }
  // Per vertex: the vertex shader decodes three codes a float, four floats an attribute, and
  // hands the angles on four a varying, which interpolate across the primitive.
  const int attributes = AttributesForBytes(sectors + 3); // GetNumberOfPackedAttributes()
  std::ostringstream vsDec, vsImpl, gsDec, gsImpl, fsDec;
  vsDec << "//VTK::Normal::Dec\n" << vtkHorizonLightingCodeGLSL << "\n";
  vsImpl << "//VTK::Normal::Impl\n  {\n    vec4 packedHorizons[" << attributes << "] = vec4["
         << attributes << "](";
  for (int a = 0; a < attributes; ++a)
  {
    vsDec << "in vec4 " << GetPackedAttributeName(a) << ";\n";
    vsImpl << (a ? ", " : "") << GetPackedAttributeName(a);
  }
  vsImpl << ");\n    float h[" << 4 * outputs << "];\n"
         << "    for (int k = 0; k < " << 4 * outputs << "; ++k)\n    {\n"
         << "      int j = min(k, " << sectors - 1 << ");\n"
         << "      uint word = uint(packedHorizons[j / 12][(j / 3) % 4]); // exact integers\n"
         << "      uint code = (word >> uint(8 * (j % 3))) & 255u;\n"
         << "      h[k] = horizonLightingDecode(float(code) / 255.0);\n    }\n";
  read << "  vec4 v[" << outputs << "] = vec4[" << outputs << "](";
  for (int m = 0; m < outputs; ++m)
  {
    const std::string name = "apertureHorizon" + std::to_string(m);
    vsDec << "out vec4 " << name << "VSOutput;\n";
    vsImpl << "    " << name << "VSOutput = vec4(h[" << 4 * m << "], h[" << 4 * m + 1 << "], h["
           << 4 * m + 2 << "], h[" << 4 * m + 3 << "]);\n";
    gsDec << "in vec4 " << name << "VSOutput[];\nout vec4 " << name << "GSOutput;\n";
    gsImpl << name << "GSOutput = " << name << "VSOutput[i];\n";
    fsDec << "in vec4 " << name << "VSOutput;\n";
    read << (m ? ", " : "") << name << "VSOutput";
  }
  vsImpl << "  }";
  read << ");\n  for (int k = 0; k < HORIZON_LIGHTING_SECTORS; ++k)\n  {\n"
       << "    horizonLightingHorizons[k] = v[k / 4][k % 4];\n  }\n}\n";
  vtkShaderProgram::Substitute(vs, "//VTK::Normal::Dec", vsDec.str());
  vtkShaderProgram::Substitute(vs, "//VTK::Normal::Impl", vsImpl.str());
  vtkShaderProgram::Substitute(gs, "//VTK::Normal::Dec", "//VTK::Normal::Dec\n" + gsDec.str());
  vtkShaderProgram::Substitute(gs, "//VTK::Normal::Impl", "//VTK::Normal::Impl\n" + gsImpl.str());
  vtkShaderProgram::Substitute(fs, "//APERTURE::Horizons::Dec", fsDec.str() + read.str());
}

//------------------------------------------------------------------------------
std::string vtkApertureLightingInterface::GetVertexLightingDeclarations(int packedLayout)
{
  std::ostringstream dec;
  if (this->ShadingMode == VISIBILITY_MASK)
  {
    dec << "#define VISIBILITY_MASK_SIDE " << vtkVisibilityMask::GetSide(packedLayout) << "\n"
        << vtkVisibilityMask::GetGLSLConstants() << vtkVisibilityMaskGLSL << "\n"
        << vtkVisibilityMaskVS << "\n";
    return dec.str();
  }
  dec << "#define HORIZON_LIGHTING_SECTORS " << packedLayout << "\n"
      << vtkHorizonLighting::GetGLSLConstants() << vtkHorizonLightingCodeGLSL << "\n"
      << vtkHorizonLightingGLSL << "\n"
      << vtkHorizonLightingVS << "\n";
  return dec.str();
}

//------------------------------------------------------------------------------
void vtkApertureLightingInterface::ReplaceVertexLightingCode(std::string& vs, std::string& gs,
  std::string& fs, vtkRenderer* renderer, int lightComplexity, int lightCount, int attributes,
  const std::string& modeDeclarations, bool environment)
{
  std::ostringstream vsDec, vsImpl, gsDec, gsImpl, fsDec;
  vsDec << "//VTK::Normal::Dec\n"
        << static_cast<vtkOpenGLRenderer*>(renderer)->GetLightingUniforms() << "\n"
        << vtkSphericalCap::GetGLSLConstants() << vtkSphericalCapGLSL << "\n"
        << vtkApertureLightCapGLSL << "\n"
        << "#define APERTURE_LIGHT_COUNT " << lightCount << "\n"
        << "#define APERTURE_PACKED_ATTRIBUTES " << attributes << "\n"
        << vtkApertureVertexLightingVS << "\n"
        << modeDeclarations;
  vsImpl << "  {\n    apertureVertexUnpackSums(" << GetPackedAttributeName(attributes - 1)
         << ".w);\n    apertureVertexPrepare(vec4[" << attributes << "](";
  for (int a = 0; a < attributes; ++a)
  {
    vsDec << "in vec4 " << GetPackedAttributeName(a) << ";\n";
    vsImpl << (a ? ", " : "") << GetPackedAttributeName(a);
  }
  vsImpl << "));\n    apertureVertexCoverage = vec2(0.0);\n";
  // Each light's transfer and coverage, then the sky, four to a varying.
  std::vector<std::string> results;
  for (int i = 0; i < lightCount; ++i)
  {
    const std::string light = "apertureVertexLight" + std::to_string(i);
    vsImpl << "    vec2 " << light << " = apertureVertexLight(normalMC, "
           << VertexLightCap(lightComplexity, i) << ");\n";
    results.push_back(light + ".x");
    results.push_back(light + ".y");
  }
  if (environment)
  {
    // The environment sky, computed on the CPU, rides in the attribute after the packed ones.
    const std::string sky = GetPackedAttributeName(attributes);
    vsDec << "in vec4 " << sky << ";\n";
    vsImpl << "    vec3 apertureVertexEnvironment = apertureVertexEnvironmentSky(" << sky
           << ".rgb);\n";
    results.insert(results.end(),
      { "apertureVertexEnvironment.r", "apertureVertexEnvironment.g",
        "apertureVertexEnvironment.b" });
  }
  else
  {
    results.emplace_back("apertureVertexSky()");
  }
  const int outputs = static_cast<int>(results.size() + 3) / 4;
  results.resize(4 * outputs, "0.0");
  std::ostringstream read;
  read << "void apertureReadVertexLighting()\n{\n";
  for (int m = 0; m < outputs; ++m)
  {
    const std::string name = "apertureVertexLighting" + std::to_string(m);
    vsDec << "out vec4 " << name << "VSOutput;\n";
    vsImpl << "    " << name << "VSOutput = vec4(" << results[4 * m] << ", " << results[4 * m + 1]
           << ", " << results[4 * m + 2] << ", " << results[4 * m + 3] << ");\n";
    gsDec << "in vec4 " << name << "VSOutput[];\nout vec4 " << name << "GSOutput;\n";
    gsImpl << name << "GSOutput = " << name << "VSOutput[i];\n";
    fsDec << "in vec4 " << name << "VSOutput;\n";
  }
  auto value = [](int k)
  {
    return "apertureVertexLighting" + std::to_string(k / 4) + "VSOutput[" + std::to_string(k % 4) +
      "]";
  };
  for (int i = 0; i < lightCount; ++i)
  {
    read << "  apertureVertexLights[" << i << "] = vec2(" << value(2 * i) << ", "
         << value(2 * i + 1) << ");\n";
  }
  const int sky = 2 * lightCount;
  read << "  apertureVertexSky = vec3(" << value(sky) << ", " << value(environment ? sky + 1 : sky)
       << ", " << value(environment ? sky + 2 : sky) << ");\n  apertureVertexLightIndex = 0;\n}\n";
  vsImpl << "  }\n//VTK::Light::Impl";
  vtkShaderProgram::Substitute(vs, "//VTK::Normal::Dec", vsDec.str());
  vtkShaderProgram::Substitute(vs, "//VTK::Light::Impl", vsImpl.str());
  vtkShaderProgram::Substitute(gs, "//VTK::Normal::Dec", "//VTK::Normal::Dec\n" + gsDec.str());
  vtkShaderProgram::Substitute(gs, "//VTK::Normal::Impl", "//VTK::Normal::Impl\n" + gsImpl.str());
  vtkShaderProgram::Substitute(fs, "//APERTURE::VertexLighting::Dec", fsDec.str() + read.str());
}

//------------------------------------------------------------------------------
void vtkApertureLightingInterface::ComputeNormalMatrix(
  vtkRenderer* renderer, vtkActor* actor, vtkMatrix3x3* result)
{
  vtkMatrix4x4 *wcvc, *vcdc, *wcdc;
  vtkMatrix3x3* norms;
  static_cast<vtkOpenGLCamera*>(renderer->GetActiveCamera())
    ->GetKeyMatrices(renderer, wcvc, norms, vcdc, wcdc);
  if (actor->GetIsIdentity())
  {
    result->DeepCopy(norms);
    return;
  }
  vtkMatrix4x4* mcwc;
  vtkMatrix3x3* anorms;
  static_cast<vtkOpenGLActor*>(actor)->GetKeyMatrices(mcwc, anorms);
  vtkMatrix3x3::Multiply3x3(anorms, norms, result);
}

//------------------------------------------------------------------------------
void vtkApertureLightingInterface::SetShaderParameters(vtkShaderProgram* program,
  vtkRenderer* renderer, vtkMatrix3x3* normalMatrix, bool inputTCoords, const double shift[3],
  const double scale[3])
{
  if (program->IsUniformUsed("apertureNormalMatrix"))
  {
    program->SetUniformMatrix("apertureNormalMatrix", normalMatrix);
  }
  if (program->IsUniformUsed("apertureViewToModel"))
  {
    // The normal matrix's transpose takes view directions back to the model's frame for
    // rotations and uniform scales (SetUniformMatrix() hands GL the transpose of what it gets).
    vtkNew<vtkMatrix3x3> toModel;
    vtkMatrix3x3::Transpose(normalMatrix, toModel);
    program->SetUniformMatrix("apertureViewToModel", toModel);
  }
  this->SetSkyParameters(program, renderer);
  if (program->IsUniformUsed("horizonLightingSkyWedges") && this->SkyEnvironment &&
    this->UploadSkyWedges(renderer, normalMatrix))
  {
    this->SkyWedges->Activate();
    program->SetUniformi("horizonLightingSkyWedges", this->SkyWedges->GetTextureUnit());
  }
  this->SetLightParameters(program, renderer);
  this->SetTextureParameters(program, renderer, inputTCoords, shift, scale);
}

//------------------------------------------------------------------------------
void vtkApertureLightingInterface::SetSkyParameters(
  vtkShaderProgram* program, vtkRenderer* renderer)
{
  if (program->IsUniformUsed("apertureSkyColor"))
  {
    const float sky[3] = { static_cast<float>(this->SkyColor[0] * this->SkyIntensity),
      static_cast<float>(this->SkyColor[1] * this->SkyIntensity),
      static_cast<float>(this->SkyColor[2] * this->SkyIntensity) };
    program->SetUniform3f("apertureSkyColor", sky);
  }
  if (program->IsUniformUsed("apertureSkyCosine"))
  {
    program->SetUniformi("apertureSkyCosine", this->SkyCosineWeighting ? 1 : 0);
  }
  if (program->IsUniformUsed("apertureSkyTable") && this->SkyEnvironment)
  {
    this->UploadSkyTable(renderer);
    this->SkyTable->Activate();
    program->SetUniformi("apertureSkyTable", this->SkyTable->GetTextureUnit());
  }
  if (program->IsUniformUsed("apertureSkyMatrix") && this->SkyEnvironment)
  {
    vtkNew<vtkMatrix3x3> matrix;
    ViewToEnvironment(this->SkyEnvironment, renderer, matrix);
    program->SetUniformMatrix("apertureSkyMatrix", matrix);
  }
}

//------------------------------------------------------------------------------
void vtkApertureLightingInterface::SetLightParameters(
  vtkShaderProgram* program, vtkRenderer* renderer)
{
  const bool setCaps = program->IsUniformUsed("apertureLightCap");
  const bool setWorldRadii = program->IsUniformUsed("apertureLightWorldRadius");
  if (!setCaps && !setWorldRadii)
  {
    return;
  }
  // Light sizes, in the order the renderer numbers its switched-on lights. Arrays longer than
  // the shader's lose their excess to GL.
  std::vector<float> caps;
  std::vector<float> worldRadii;
  vtkLightCollection* lights = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (light->GetSwitch() <= 0)
    {
      continue;
    }
    const double radius = GetLightRadius(light);
    const bool world = light->GetPositional() && radius >= 0.0;
    // The angular radius as the shading functions clamp it, with the sine and cosine of its half
    // computed here once rather than per fragment.
    const double r = vtkSphericalCap::ClampLightRadius(
      radius >= 0.0 && !world ? radius : this->DefaultLightRadius);
    caps.insert(caps.end(),
      { static_cast<float>(r), static_cast<float>(std::sin(0.5 * r)),
        static_cast<float>(std::cos(0.5 * r)) });
    worldRadii.push_back(static_cast<float>(world ? radius : -1.0));
  }
  const int count = static_cast<int>(worldRadii.size());
  if (setCaps && count > 0)
  {
    program->SetUniform3fv("apertureLightCap", count, caps.data());
  }
  if (setWorldRadii && count > 0)
  {
    program->SetUniform1fv("apertureLightWorldRadius", count, worldRadii.data());
  }
}

//------------------------------------------------------------------------------
void vtkApertureLightingInterface::SetTextureParameters(vtkShaderProgram* program,
  vtkRenderer* renderer, bool inputTCoords, const double shift[3], const double scale[3])
{
  if (program->IsUniformUsed("apertureHorizonTexture") && this->ApertureImage &&
    this->UploadHorizonTexture(renderer))
  {
    this->HorizonTexture->Activate();
    program->SetUniformi("apertureHorizonTexture", this->HorizonTexture->GetTextureUnit());
  }
  if (program->IsUniformUsed("apertureSkyTexels") && this->ApertureImage &&
    this->UploadSkyTexels(renderer))
  {
    this->SkyTexels->Activate();
    program->SetUniformi("apertureSkyTexels", this->SkyTexels->GetTextureUnit());
  }
  if (!program->IsUniformUsed("apertureTexture") || !this->ApertureImage)
  {
    return;
  }
  if (!this->UploadTexture(renderer))
  {
    return;
  }
  this->Texture->Activate();
  program->SetUniformi("apertureTexture", this->Texture->GetTextureUnit());
  // Texel centres hold the grid points: u = (s + 1/2)/n for grid coordinate s, and
  // s = (x - origin)/spacing for x = vertexMC/scale + shift.
  int dims[3];
  this->ApertureImage->GetDimensions(dims);
  const double* spacing = this->ApertureImage->GetSpacing();
  const double* origin = this->ApertureImage->GetOrigin();
  float transform[4];
  for (int k = 0; k < 2; ++k)
  {
    const double n = dims[k];
    if (inputTCoords)
    {
      transform[k] = static_cast<float>((n - 1.0) / n);
      transform[k + 2] = static_cast<float>(0.5 / n);
    }
    else
    {
      transform[k] = static_cast<float>(1.0 / (spacing[k] * n * scale[k]));
      transform[k + 2] = static_cast<float>((0.5 + (shift[k] - origin[k]) / spacing[k]) / n);
    }
  }
  program->SetUniform4f("apertureTexTransform", transform);
}

//------------------------------------------------------------------------------
namespace
{
// Bent normals and radii of grid points [first, first + count) as RGBA texels, read through
// array ranges (typed access for float and double arrays, no virtual call per value).
struct PackTexels
{
  template <typename BentArray, typename RadiusArray>
  void operator()(
    BentArray* bent, RadiusArray* radius, vtkIdType first, vtkIdType count, float* texels) const
  {
    const auto normals = vtk::DataArrayTupleRange<3>(bent, first, first + count);
    const auto radii = vtk::DataArrayValueRange<1>(radius, first, first + count);
    for (vtkIdType i = 0; i < count; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        texels[4 * i + k] = static_cast<float>(normals[i][k]);
      }
      texels[4 * i + 3] = static_cast<float>(radii[i]);
    }
  }
};
}

//------------------------------------------------------------------------------
// The grid goes up a band of rows at a time, so that the packed texels (16 bytes a texel, as
// much as the arrays themselves) never take the whole grid's memory beside them.
bool vtkApertureLightingInterface::UploadTexture(vtkRenderer* renderer)
{
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (this->Texture && this->TextureTime > this->ApertureImage->GetMTime() &&
    this->Texture->GetContext() == window)
  {
    return true;
  }
  // CheckApertureImage() made sure that the grid fits in a texture.
  int dims[3];
  this->ApertureImage->GetDimensions(dims);
  vtkPointData* pd = this->ApertureImage->GetPointData();
  vtkDataArray* bent = pd->GetArray(this->BentNormalArrayName.c_str());
  vtkDataArray* radius = pd->GetArray(this->ApertureRadiusArrayName.c_str());
  if (!this->Texture)
  {
    this->Texture = vtkSmartPointer<vtkTextureObject>::New();
  }
  this->Texture->SetContext(window);
  this->Texture->SetWrapS(vtkTextureObject::ClampToEdge);
  this->Texture->SetWrapT(vtkTextureObject::ClampToEdge);
  this->Texture->SetMinificationFilter(vtkTextureObject::Linear);
  this->Texture->SetMagnificationFilter(vtkTextureObject::Linear);
  if (!this->Texture->Create2DFromRaw(dims[0], dims[1], 4, VTK_FLOAT, nullptr))
  {
    this->Texture = nullptr;
    return false;
  }
  const int band = std::max(1, std::min(dims[1], (1 << 20) / std::max(1, dims[0])));
  std::vector<float> texels(4 * static_cast<size_t>(dims[0]) * band);
  using Dispatch =
    vtkArrayDispatch::Dispatch2ByValueType<vtkArrayDispatch::Reals, vtkArrayDispatch::Reals>;
  this->Texture->Activate();
  for (int row = 0; row < dims[1]; row += band)
  {
    const int rows = std::min(band, dims[1] - row);
    const vtkIdType first = static_cast<vtkIdType>(row) * dims[0];
    const vtkIdType count = static_cast<vtkIdType>(rows) * dims[0];
    if (!Dispatch::Execute(bent, radius, PackTexels{}, first, count, texels.data()))
    {
      PackTexels{}(bent, radius, first, count, texels.data());
    }
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, row, dims[0], rows, GL_RGBA, GL_FLOAT, texels.data());
  }
  this->Texture->Deactivate();
  this->TextureTime.Modified();
  return true;
}

//------------------------------------------------------------------------------
// The horizons go up as a 2D texture array (VTK 9.1's texture objects make none, so the handle
// is this class's) of four 8-bit sectors a layer, a band of rows at a time.
bool vtkApertureLightingInterface::UploadHorizonTexture(vtkRenderer* renderer)
{
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  const int sectors = this->CheckHorizons(this->ApertureImage);
  if (sectors < 1)
  {
    return false;
  }
  vtkDataArray* horizons =
    this->ApertureImage->GetPointData()->GetArray(this->HorizonAnglesArrayName.c_str());
  if (this->HorizonTexture && this->HorizonTexture->GetContext() == window &&
    this->HorizonTextureTime > std::max(this->ApertureImage->GetMTime(), horizons->GetMTime()) &&
    this->HorizonTextureSectors == sectors)
  {
    return true;
  }
  if (this->HorizonTexture && this->HorizonTexture->GetContext() != window)
  {
    this->ReleaseGraphicsResources(this->HorizonTexture->GetContext());
  }
  if (!this->HorizonTexture)
  {
    glGenTextures(1, &this->HorizonTextureHandle);
    this->HorizonTexture = vtkSmartPointer<vtkTextureObject>::New();
    this->HorizonTexture->SetContext(window);
    this->HorizonTexture->AssignToExistingTexture(this->HorizonTextureHandle, GL_TEXTURE_2D_ARRAY);
  }
  int dims[3];
  this->ApertureImage->GetDimensions(dims);
  const int layers = (sectors + 3) / 4;
  this->HorizonTexture->Activate();
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA8, dims[0], dims[1], layers, 0, GL_RGBA,
    GL_UNSIGNED_BYTE, nullptr);
  const int band = std::max(1, std::min(dims[1], (1 << 20) / std::max(1, dims[0])));
  const size_t layerSize = 4 * static_cast<size_t>(dims[0]) * band;
  std::vector<unsigned char> texels(layerSize * layers), codes(sectors);
  std::vector<float> in(horizons->GetNumberOfComponents());
  std::vector<double> tuple(in.size());
  for (int row = 0; row < dims[1]; row += band)
  {
    const int rows = std::min(band, dims[1] - row);
    std::fill(texels.begin(), texels.end(), 0);
    for (vtkIdType t = 0; t < static_cast<vtkIdType>(rows) * dims[0]; ++t)
    {
      EncodePoint(
        horizons, static_cast<vtkIdType>(row) * dims[0] + t, sectors, tuple, in, codes.data());
      for (int k = 0; k < sectors; ++k)
      {
        texels[(k / 4) * layerSize + 4 * t + k % 4] = codes[k];
      }
    }
    for (int m = 0; m < layers; ++m)
    {
      glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, row, m, dims[0], rows, 1, GL_RGBA,
        GL_UNSIGNED_BYTE, &texels[m * layerSize]);
    }
  }
  this->HorizonTexture->Deactivate();
  this->HorizonTextureTime.Modified();
  this->HorizonTextureSectors = sectors;
  return true;
}

//------------------------------------------------------------------------------
bool vtkApertureLightingInterface::HasTexelNormals()
{
  vtkDataArray* normals =
    this->ApertureImage ? this->ApertureImage->GetPointData()->GetNormals() : nullptr;
  return normals && normals->GetNumberOfComponents() == 3 &&
    normals->GetNumberOfTuples() == this->ApertureImage->GetNumberOfPoints();
}

//------------------------------------------------------------------------------
bool vtkApertureLightingInterface::UploadSkyTexels(vtkRenderer* renderer)
{
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  const int sectors = this->CheckHorizons(this->ApertureImage);
  if (sectors < 1 || !this->SkyEnvironment || !this->HasTexelNormals())
  {
    return false;
  }
  vtkPointData* pd = this->ApertureImage->GetPointData();
  vtkDataArray* horizons = pd->GetArray(this->HorizonAnglesArrayName.c_str());
  const vtkMTimeType time = std::max({ this->ApertureImage->GetMTime(), horizons->GetMTime(),
    pd->GetNormals()->GetMTime(), this->GetBufferMTime() });
  if (this->SkyTexels && this->SkyTexels->GetContext() == window && this->SkyTexelsTime >= time &&
    this->SkyTexelsSectors == sectors)
  {
    return true;
  }
  // Three floats a texel, filtered linearly as the horizons are.
  vtkSmartPointer<vtkFloatArray> sky =
    this->ComputePointEnvironment(this->ApertureImage, sectors, horizons);
  std::vector<float> rgb(3 * static_cast<size_t>(sky->GetNumberOfTuples()));
  for (vtkIdType t = 0; t < sky->GetNumberOfTuples(); ++t)
  {
    std::copy_n(sky->GetPointer(4 * t), 3, &rgb[3 * t]);
  }
  if (!this->SkyTexels)
  {
    this->SkyTexels = vtkSmartPointer<vtkTextureObject>::New();
  }
  int dims[3];
  this->ApertureImage->GetDimensions(dims);
  this->SkyTexels->SetContext(window);
  this->SkyTexels->SetWrapS(vtkTextureObject::ClampToEdge);
  this->SkyTexels->SetWrapT(vtkTextureObject::ClampToEdge);
  this->SkyTexels->SetMinificationFilter(vtkTextureObject::Linear);
  this->SkyTexels->SetMagnificationFilter(vtkTextureObject::Linear);
  if (!this->SkyTexels->Create2DFromRaw(dims[0], dims[1], 3, VTK_FLOAT, rgb.data()))
  {
    this->SkyTexelsTime = 0;
    return false;
  }
  this->SkyTexelsTime = time;
  this->SkyTexelsSectors = sectors;
  return true;
}

//------------------------------------------------------------------------------
void vtkApertureLightingInterface::UploadSkyTable(vtkRenderer* renderer)
{
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  const vtkMTimeType time = this->SkyEnvironment->GetImageMTime();
  if (this->SkyTable && this->SkyTableTime == time && this->SkyTable->GetContext() == window)
  {
    return;
  }
  vtkSmartPointer<vtkImageData> table;
  table.TakeReference(this->SkyEnvironment->NewCapTable(64, 32, 16));
  if (!this->SkyTable)
  {
    this->SkyTable = vtkSmartPointer<vtkTextureObject>::New();
  }
  vtkApertureSkyTexture::Upload(table, this->SkyTable, window);
  this->SkyTableTime = time;
}

//------------------------------------------------------------------------------
bool vtkApertureLightingInterface::UploadSkyWedges(
  vtkRenderer* renderer, vtkMatrix3x3* normalMatrix)
{
  double frame[9], key[9];
  ModelToWorld(renderer, normalMatrix, frame);
  ModelToEnvironment(this->SkyEnvironment, frame, key);
  // Cameras move the view and the normal matrix together: rebuild only when the model turns
  // against the environment (beyond rounding), or the environment's image changed.
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  const vtkMTimeType time = this->SkyEnvironment->GetImageMTime();
  bool same =
    this->SkyWedges && this->SkyWedgesTime == time && this->SkyWedges->GetContext() == window;
  for (int i = 0; i < 9 && same; ++i)
  {
    same = std::abs(key[i] - this->SkyWedgesFrame[i]) <= 1e-6;
  }
  if (same)
  {
    return true;
  }
  vtkSmartPointer<vtkImageData> table;
  table.TakeReference(this->SkyEnvironment->NewWedgeTable(256, 64, frame));
  if (!this->SkyWedges)
  {
    this->SkyWedges = vtkSmartPointer<vtkTextureObject>::New();
  }
  if (!vtkApertureSkyTexture::Upload(table, this->SkyWedges, window))
  {
    this->SkyWedgesTime = 0;
    return false;
  }
  std::copy(key, key + 9, this->SkyWedgesFrame);
  this->SkyWedgesTime = time;
  return true;
}

//------------------------------------------------------------------------------
void vtkApertureLightingInterface::DeactivateTexture()
{
  if (this->Texture)
  {
    this->Texture->Deactivate();
  }
  if (this->SkyTable)
  {
    this->SkyTable->Deactivate();
  }
  if (this->SkyWedges)
  {
    this->SkyWedges->Deactivate();
  }
  if (this->SkyTexels)
  {
    this->SkyTexels->Deactivate();
  }
  if (this->HorizonTexture)
  {
    this->HorizonTexture->Deactivate();
  }
}

//------------------------------------------------------------------------------
void vtkApertureLightingInterface::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Texture)
  {
    this->Texture->ReleaseGraphicsResources(window);
    this->Texture = nullptr;
  }
  if (this->SkyTable)
  {
    this->SkyTable->ReleaseGraphicsResources(window);
    this->SkyTable = nullptr;
  }
  if (this->SkyWedges)
  {
    this->SkyWedges->ReleaseGraphicsResources(window);
    this->SkyWedges = nullptr;
  }
  if (this->SkyTexels)
  {
    this->SkyTexels->ReleaseGraphicsResources(window);
    this->SkyTexels = nullptr;
  }
  if (this->HorizonTexture)
  {
    this->HorizonTexture->ReleaseGraphicsResources(window);
    this->HorizonTexture = nullptr;
    glDeleteTextures(1, &this->HorizonTextureHandle);
    this->HorizonTextureHandle = 0;
  }
}

//------------------------------------------------------------------------------
void vtkApertureLightingInterface::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ShadingMode: " << this->GetShadingModeAsString() << "\n";
  os << indent
     << "LambertMode: " << (this->LambertMode == vtkSphericalCap::MOMENT ? "Moment" : "Centroid")
     << "\n";
  os << indent << "BentNormalArrayName: " << this->BentNormalArrayName << "\n";
  os << indent << "ApertureRadiusArrayName: " << this->ApertureRadiusArrayName << "\n";
  os << indent << "HorizonAnglesArrayName: " << this->HorizonAnglesArrayName << "\n";
  os << indent << "VisibilityMaskArrayName: " << this->VisibilityMaskArrayName << "\n";
  os << indent << "SkyColor: " << this->SkyColor[0] << ", " << this->SkyColor[1] << ", "
     << this->SkyColor[2] << "\n";
  os << indent << "SkyIntensity: " << this->SkyIntensity << "\n";
  os << indent << "SkyCosineWeighting: " << this->SkyCosineWeighting << "\n";
  os << indent << "SkyEnvironment: " << this->SkyEnvironment << "\n";
  os << indent << "DefaultLightRadius: " << this->DefaultLightRadius << "\n";
  os << indent << "ApertureImage: " << this->ApertureImage << "\n";
}
