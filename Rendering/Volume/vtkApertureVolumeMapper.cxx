/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureVolumeMapper.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureVolumeMapper.h"

#include "vtkApertureSkyTexture.h"
#include "vtkApertureVolumeFS.h"
#include "vtkDataArray.h"
#include "vtkEnvironmentMap.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderProperty.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkShaderProperty.h"
#include "vtkSphericalCap.h"
#include "vtkSphericalCapGLSL.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTextureObject.h"
#include "vtkTrivialProducer.h"
#include "vtkUniforms.h"
#include "vtkVolume.h"
#include "vtkVolumeAperturePrecompute.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkApertureVolumeMapper);
vtkCxxSetObjectMacro(vtkApertureVolumeMapper, ApertureData, vtkImageData);
vtkCxxSetObjectMacro(vtkApertureVolumeMapper, ApertureSource, vtkImageData);
vtkCxxSetObjectMacro(vtkApertureVolumeMapper, SkyEnvironment, vtkEnvironmentMap);

namespace
{
constexpr int MaximumLights = 8;
constexpr double Pi = 3.14159265358979323846;
const char* const LightingTag = "//VTK::ComputeLighting::Dec";
// Custom uniforms are declared by type; the aperture texture's int becomes a sampler.
const char* const SamplerAsInt = "uniform int apertureVolume;";
const char* const SamplerDeclaration = "uniform sampler3D apertureVolume;";
const char* const SkySamplerAsInt = "uniform int apertureSkyTable;";
const char* const SkySamplerDeclaration = "uniform sampler3D apertureSkyTable;";

unsigned char ToByte(double unit)
{
  return static_cast<unsigned char>(std::lround(std::min(1.0, std::max(0.0, unit)) * 255.0));
}

// The step (a whole number of input voxels) of an aperture grid along each axis and where the
// input's first voxel lies from the grid's first point (in input voxels, above -step), or
// false when `apertures` is not a grid of every n-th voxel of `input` with the two arrays that
// covers it to within a step.
bool ApertureGridSteps(vtkImageData* input, vtkImageData* apertures, int steps[3], int offsets[3])
{
  vtkDataArray* bent = apertures->GetPointData()->GetArray("BentNormal");
  vtkDataArray* radius = apertures->GetPointData()->GetArray("ApertureRadius");
  if (!bent || !radius || bent->GetNumberOfComponents() != 3 ||
    radius->GetNumberOfComponents() != 1)
  {
    return false;
  }
  int n[3], m[3];
  input->GetDimensions(n);
  apertures->GetDimensions(m);
  const double* s = input->GetSpacing();
  const double* a = apertures->GetSpacing();
  const double* o = input->GetOrigin();
  const double* p = apertures->GetOrigin();
  int e[6], f[6];
  input->GetExtent(e);
  apertures->GetExtent(f);
  for (int i = 0; i < 3; ++i)
  {
    const double ratio = a[i] / s[i];
    steps[i] = static_cast<int>(std::lround(ratio));
    // The first and last points of each, in input voxels from the aperture grid's first.
    const double start = (o[i] + e[2 * i] * s[i] - (p[i] + f[2 * i] * a[i])) / s[i];
    const double end = start + (n[i] - 1);
    const double last = (m[i] - 1) * ratio;
    offsets[i] = static_cast<int>(std::lround(start));
    if (steps[i] < 1 || std::abs(ratio - steps[i]) > 1e-3 || std::abs(start - offsets[i]) > 1e-3 ||
      start <= -steps[i] || end >= last + steps[i])
    {
      return false;
    }
  }
  return true;
}
}

//------------------------------------------------------------------------------
vtkApertureVolumeMapper::vtkApertureVolumeMapper() = default;

//------------------------------------------------------------------------------
vtkApertureVolumeMapper::~vtkApertureVolumeMapper()
{
  this->SetApertureData(nullptr);
  this->SetApertureSource(nullptr);
  this->SetSkyEnvironment(nullptr);
}

//------------------------------------------------------------------------------
vtkVolumeAperturePrecompute* vtkApertureVolumeMapper::GetAperturePrecompute()
{
  if (!this->Precompute)
  {
    this->Precompute = vtkSmartPointer<vtkVolumeAperturePrecompute>::New();
  }
  return this->Precompute;
}

//------------------------------------------------------------------------------
void vtkApertureVolumeMapper::WarnOnce(const std::string& problem)
{
  if (problem != this->LastWarning)
  {
    this->LastWarning = problem;
    vtkWarningMacro("Aperture lighting does not apply, VTK's shading is used: " << problem << ".");
  }
}

//------------------------------------------------------------------------------
std::string vtkApertureVolumeMapper::Unusable(vtkVolume* vol)
{
  vtkVolumeProperty* property = vol->GetProperty();
  vtkImageData* input = vtkImageData::SafeDownCast(this->GetInput());
  if (!property->GetShade() || this->GetBlendMode() != vtkVolumeMapper::COMPOSITE_BLEND || !input)
  {
    return "-";
  }
  if (this->GetInputCount() > 1)
  {
    return "the mapper draws several inputs";
  }
  int cellFlag = 0;
  vtkDataArray* scalars = this->GetScalars(
    input, this->ScalarMode, this->ArrayAccessMode, this->ArrayId, this->ArrayName, cellFlag);
  if (!scalars || scalars->GetNumberOfComponents() != 1 || cellFlag)
  {
    return "the volume's scalars are not point scalars of one component";
  }
  if (property->GetTransferFunctionMode() != vtkVolumeProperty::TF_1D)
  {
    return "the volume property has a 2D transfer function";
  }
  return "";
}

//------------------------------------------------------------------------------
vtkImageData* vtkApertureVolumeMapper::CurrentApertures(vtkVolume* vol)
{
  vtkImageData* input = vtkImageData::SafeDownCast(this->GetInput());
  vtkImageData* apertures =
    this->ApertureData ? this->ApertureData : this->ComputedApertures(vol, input);
  int steps[3], offsets[3];
  if (!ApertureGridSteps(input, apertures, steps, offsets))
  {
    this->WarnOnce("no apertures on every n-th voxel of the input, with BentNormal (3 "
                   "components) and ApertureRadius");
    return nullptr;
  }
  int n[3], m[3];
  input->GetDimensions(n);
  apertures->GetDimensions(m);
  for (int a = 0; a < 3; ++a)
  {
    // Point p of the input sits at texture coordinate (p + 1/2)/n, aperture point
    // (p + offset)/step at ((p + offset)/step + 1/2)/m.
    this->TextureScale[a] = static_cast<float>(n[a] / (double(steps[a]) * m[a]));
    this->TextureShift[a] = static_cast<float>((0.5 + (offsets[a] - 0.5) / steps[a]) / m[a]);
    this->GridSize[a] = static_cast<float>(m[a]);
  }
  return apertures;
}

//------------------------------------------------------------------------------
vtkImageData* vtkApertureVolumeMapper::ComputedApertures(vtkVolume* vol, vtkImageData* input)
{
  vtkVolumeAperturePrecompute* precompute = this->GetAperturePrecompute();
  if (!this->PrecomputeInput)
  {
    this->PrecomputeInput = vtkSmartPointer<vtkTrivialProducer>::New();
  }
  vtkImageData* source = this->ApertureSource ? this->ApertureSource : input;
  this->PrecomputeInput->SetOutput(source);
  if (this->ApertureSource)
  {
    this->PrecomputeInput->SetWholeExtent(this->ApertureSourceWholeExtent);
  }
  else
  {
    this->PrecomputeInput->SetWholeExtent(0, -1, 0, -1, 0, -1);
  }
  precompute->SetInputConnection(this->PrecomputeInput->GetOutputPort());
  precompute->SetVolumeProperty(vol->GetProperty());
  int cellFlag = 0;
  vtkDataArray* scalars = this->GetScalars(
    input, this->ScalarMode, this->ArrayAccessMode, this->ArrayId, this->ArrayName, cellFlag);
  if (scalars->GetName())
  {
    precompute->SetInputArrayToProcess(
      0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, scalars->GetName());
  }
  // A failed precompute runs again at every Update: try once per change of what it reads.
  const vtkMTimeType changed =
    std::max({ precompute->GetMTime(), this->PrecomputeInput->GetMTime(), source->GetMTime() });
  if (changed > this->PrecomputeTried)
  {
    this->PrecomputeTried = changed;
    // Only the aperture grid's points over the input (and one beyond where it ends between two).
    const int step = precompute->GetApertureGridStep();
    int extent[6];
    input->GetExtent(extent);
    for (int a = 0; a < 3; ++a)
    {
      extent[2 * a] = static_cast<int>(std::floor(extent[2 * a] / double(step)));
      extent[2 * a + 1] = static_cast<int>(std::ceil(extent[2 * a + 1] / double(step)));
    }
    precompute->UpdateInformation();
    int whole[6];
    precompute->GetOutputInformation(0)->Get(
      vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
    for (int a = 0; a < 3; ++a)
    {
      extent[2 * a] = std::max(extent[2 * a], whole[2 * a]);
      extent[2 * a + 1] = std::min(extent[2 * a + 1], whole[2 * a + 1]);
    }
    precompute->UpdateExtent(extent);
  }
  return precompute->GetOutput();
}

//------------------------------------------------------------------------------
bool vtkApertureVolumeMapper::UploadApertures(vtkRenderer* ren, vtkImageData* apertures)
{
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!this->Texture)
  {
    this->Texture = vtkSmartPointer<vtkTextureObject>::New();
  }
  if (this->Texture->GetContext() != window || !this->Texture->GetHandle())
  {
    this->UploadedApertures = nullptr;
  }
  if (apertures == this->UploadedApertures && apertures->GetMTime() <= this->UploadedTime)
  {
    return true;
  }
  this->Texture->SetContext(window);
  int m[3];
  apertures->GetDimensions(m);
  vtkDataArray* bent = apertures->GetPointData()->GetArray("BentNormal");
  vtkDataArray* radius = apertures->GetPointData()->GetArray("ApertureRadius");
  const vtkIdType count = apertures->GetNumberOfPoints();
  std::vector<unsigned char> packed(4 * static_cast<size_t>(count));
  for (vtkIdType i = 0; i < count; ++i)
  {
    double b[3];
    bent->GetTuple(i, b);
    for (int a = 0; a < 3; ++a)
    {
      packed[4 * i + a] = ToByte(0.5 * (b[a] + 1.0));
    }
    packed[4 * i + 3] = ToByte(radius->GetTuple1(i) / Pi);
  }
  this->Texture->SetWrapS(vtkTextureObject::ClampToEdge);
  this->Texture->SetWrapT(vtkTextureObject::ClampToEdge);
  this->Texture->SetWrapR(vtkTextureObject::ClampToEdge);
  this->Texture->SetMinificationFilter(vtkTextureObject::Linear);
  this->Texture->SetMagnificationFilter(vtkTextureObject::Linear);
  if (!this->Texture->Create3DFromRaw(m[0], m[1], m[2], 4, VTK_UNSIGNED_CHAR, packed.data()))
  {
    this->WarnOnce("the apertures' 3D texture could not be created");
    return false;
  }
  this->UploadedApertures = apertures;
  this->UploadedTime = apertures->GetMTime();
  return true;
}

//------------------------------------------------------------------------------
vtkOpenGLShaderProperty* vtkApertureVolumeMapper::ShaderPropertyFor(vtkVolume* vol)
{
  std::ostringstream code;
  code << vtkSphericalCap::GetGLSLConstants() << vtkSphericalCapGLSL
       << "\n#define APERTURE_SHADING "
       << (this->ShadingMode == SMOOTHSTEP ? "sphericalCapSmoothstep" : "sphericalCapExact") << "\n"
       << (vol->GetProperty()->HasGradientOpacity() ? "#define APERTURE_GRADIENT_OPACITY\n" : "")
       << (this->SkyEnvironment ? "#define APERTURE_SKY_ENVIRONMENT\n" : "")
       << (this->InterpolateLight ? "#define APERTURE_INTERPOLATE_LIGHT\n" : "")
       << vtkApertureVolumeFS;
  auto* user = vtkOpenGLShaderProperty::SafeDownCast(vol->GetShaderProperty());
  if (!this->Shaders)
  {
    this->Shaders = vtkSmartPointer<vtkOpenGLShaderProperty>::New();
  }
  if (code.str() != this->InstalledCode || user->GetShaderMTime() > this->CopiedTime)
  {
    // The user's code and replacements, then this mapper's.
    this->Shaders->DeepCopy(user);
    this->InstalledCode = code.str();
    this->CopiedTime = user->GetShaderMTime();
    this->Shaders->AddFragmentShaderReplacement(LightingTag, true, this->InstalledCode, false);
    this->Shaders->AddFragmentShaderReplacement(SamplerAsInt, false, SamplerDeclaration, false);
    this->Shaders->AddFragmentShaderReplacement(
      SkySamplerAsInt, false, SkySamplerDeclaration, false);
  }
  return this->Shaders;
}

//------------------------------------------------------------------------------
void vtkApertureVolumeMapper::SetLightUniforms(vtkRenderer* ren, vtkVolume* vol)
{
  vtkUniforms* uniforms = this->Shaders->GetFragmentCustomUniforms();
  uniforms->SetUniformi("apertureVolume", this->Texture->GetTextureUnit());
  uniforms->SetUniform3f("apertureTextureScale", this->TextureScale);
  uniforms->SetUniform3f("apertureTextureShift", this->TextureShift);
  uniforms->SetUniform3f("apertureGridSize", this->GridSize);
  uniforms->SetUniformf("apertureSurfaceOffset", static_cast<float>(this->SurfaceOffset));

  // World directions to the volume's data axes: the inverse of its matrix, made unit.
  vtkNew<vtkMatrix4x4> inverse;
  vtkMatrix4x4::Invert(vol->GetMatrix(), inverse);
  const double* center = vol->GetCenter();
  vtkVolumeProperty* property = vol->GetProperty();
  const double r = vtkSphericalCap::ClampLightRadius(this->LightRadius);
  float axes[MaximumLights][3] = {}, caps[MaximumLights][3] = {}, colors[MaximumLights][3] = {};
  int count = 0;
  vtkLightCollection* lights = ren->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  for (vtkLight* light = lights->GetNextLight(it); light && count < MaximumLights;
       light = lights->GetNextLight(it))
  {
    if (!light->GetSwitch())
    {
      continue;
    }
    double position[3], focal[3], toward[4] = { 0.0, 0.0, 0.0, 0.0 }, data[4];
    light->GetTransformedPosition(position);
    light->GetTransformedFocalPoint(focal);
    const double* from = light->GetPositional() ? center : focal;
    for (int a = 0; a < 3; ++a)
    {
      toward[a] = position[a] - from[a];
    }
    inverse->MultiplyPoint(toward, data);
    const double length = std::sqrt(data[0] * data[0] + data[1] * data[1] + data[2] * data[2]);
    if (!(length > 0.0))
    {
      continue;
    }
    const double* diffuse = light->GetDiffuseColor();
    for (int a = 0; a < 3; ++a)
    {
      axes[count][a] = static_cast<float>(data[a] / length);
      colors[count][a] =
        static_cast<float>(diffuse[a] * light->GetIntensity() * property->GetDiffuse(0));
    }
    caps[count][0] = static_cast<float>(r);
    caps[count][1] = static_cast<float>(std::sin(0.5 * r));
    caps[count][2] = static_cast<float>(std::cos(0.5 * r));
    ++count;
  }
  uniforms->SetUniformi("apertureLightCount", count);
  uniforms->SetUniform3fv("apertureLightAxis", MaximumLights, axes);
  uniforms->SetUniform3fv("apertureLightCap", MaximumLights, caps);
  uniforms->SetUniform3fv("apertureLightColor", MaximumLights, colors);
  const float sky[3] = { static_cast<float>(this->SkyColor[0] * property->GetAmbient(0)),
    static_cast<float>(this->SkyColor[1] * property->GetAmbient(0)),
    static_cast<float>(this->SkyColor[2] * property->GetAmbient(0)) };
  uniforms->SetUniform3f("apertureSkyColor", sky);
  if (this->SkyEnvironment)
  {
    float matrix[9];
    this->SkyMatrix(vol, matrix);
    uniforms->SetUniformi("apertureSkyTable", this->SkyTable->GetTextureUnit());
    uniforms->SetUniformMatrix3x3("apertureSkyMatrix", matrix);
  }
}

//------------------------------------------------------------------------------
void vtkApertureVolumeMapper::SkyMatrix(vtkVolume* vol, float matrix[9])
{
  // Data axes to world (the volume's matrix; the shader makes the axis unit again), then world
  // to the environment's frame; column-major for GLSL.
  double toEnvironment[3][3], toWorld[3][3], product[3][3];
  this->SkyEnvironment->GetWorldToEnvironment(toEnvironment[0]);
  for (int row = 0; row < 3; ++row)
  {
    for (int column = 0; column < 3; ++column)
    {
      toWorld[row][column] = vol->GetMatrix()->GetElement(row, column);
    }
  }
  vtkMath::Multiply3x3(toEnvironment, toWorld, product);
  for (int row = 0; row < 3; ++row)
  {
    for (int column = 0; column < 3; ++column)
    {
      matrix[3 * column + row] = static_cast<float>(product[row][column]);
    }
  }
}

//------------------------------------------------------------------------------
bool vtkApertureVolumeMapper::UploadSkyTable(vtkRenderer* ren)
{
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  const vtkMTimeType time = this->SkyEnvironment->GetImageMTime();
  if (!this->SkyTable)
  {
    this->SkyTable = vtkSmartPointer<vtkTextureObject>::New();
  }
  if (this->SkyTableTime == time && this->SkyTable->GetContext() == window &&
    this->SkyTable->GetHandle())
  {
    return true;
  }
  vtkSmartPointer<vtkImageData> table;
  table.TakeReference(this->SkyEnvironment->NewCapRadianceTable(64, 32, 32));
  if (!vtkApertureSkyTexture::Upload(table, this->SkyTable, window))
  {
    this->WarnOnce("the sky environment's 3D texture could not be created");
    return false;
  }
  this->SkyTableTime = time;
  return true;
}

//------------------------------------------------------------------------------
void vtkApertureVolumeMapper::GPURender(vtkRenderer* ren, vtkVolume* vol)
{
  const std::string problem = this->Unusable(vol);
  if (!problem.empty() && problem != "-")
  {
    this->WarnOnce(problem);
  }
  vtkImageData* apertures = problem.empty() ? this->CurrentApertures(vol) : nullptr;
  if (!apertures || !this->UploadApertures(ren, apertures) ||
    (this->SkyEnvironment && !this->UploadSkyTable(ren)))
  {
    this->Superclass::GPURender(ren, vol);
    return;
  }
  // The volume draws with a shader property of this mapper's for the frame, so that its own
  // keeps nothing of this mapper's (another mapper on the same volume draws as it would).
  vtkSmartPointer<vtkShaderProperty> user = vol->GetShaderProperty();
  vol->SetShaderProperty(this->ShaderPropertyFor(vol));
  this->Texture->Activate();
  if (this->SkyEnvironment)
  {
    this->SkyTable->Activate();
  }
  this->SetLightUniforms(ren, vol);
  this->Superclass::GPURender(ren, vol);
  if (this->SkyEnvironment)
  {
    this->SkyTable->Deactivate();
  }
  this->Texture->Deactivate();
  vol->SetShaderProperty(user);
}

//------------------------------------------------------------------------------
void vtkApertureVolumeMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->Texture)
  {
    this->Texture->ReleaseGraphicsResources(window);
  }
  if (this->SkyTable)
  {
    this->SkyTable->ReleaseGraphicsResources(window);
  }
  this->UploadedApertures = nullptr;
  this->Superclass::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void vtkApertureVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ShadingMode: " << (this->ShadingMode == SMOOTHSTEP ? "SMOOTHSTEP" : "EXACT")
     << "\n";
  os << indent << "InterpolateLight: " << (this->InterpolateLight ? "On" : "Off") << "\n";
  os << indent << "SurfaceOffset: " << this->SurfaceOffset << "\n";
  os << indent << "LightRadius: " << this->LightRadius << "\n";
  os << indent << "SkyColor: (" << this->SkyColor[0] << ", " << this->SkyColor[1] << ", "
     << this->SkyColor[2] << ")\n";
  os << indent << "SkyEnvironment: " << this->SkyEnvironment << "\n";
  os << indent << "ApertureData: " << this->ApertureData << "\n";
  os << indent << "ApertureSource: " << this->ApertureSource << "\n";
  os << indent << "ApertureSourceWholeExtent: (" << this->ApertureSourceWholeExtent[0];
  for (int i = 1; i < 6; ++i)
  {
    os << ", " << this->ApertureSourceWholeExtent[i];
  }
  os << ")\n";
  os << indent << "AperturePrecompute: " << this->Precompute.Get() << "\n";
}
