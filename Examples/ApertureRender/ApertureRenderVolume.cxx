/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderVolume.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "ApertureRenderVolume.h"

#include "ApertureRenderDisplay.h"
#include "ApertureRenderInput.h"
#include "ApertureRenderMessages.h"
#include "ApertureRenderOptions.h"

#include "vtkApertureText.h"
#include "vtkApertureVolumeMapper.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkEnvironmentMap.h"
#include "vtkFlyingEdges3D.h"
#include "vtkImageAppend.h"
#include "vtkImageData.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOpenGLGPUVolumeRayCastMapper.h"
#include "vtkPNGWriter.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"

#include <vtksys/SystemTools.hxx>

#include <cmath>
#include <iostream>
#include <sstream>

namespace ApertureRender
{
namespace
{
// Adds the opacity and colour of a preset over scalars of `range` to `property`; false for an
// unknown preset.
bool ApplyPreset(const std::string& preset, const double range[2], vtkVolumeProperty* property)
{
  vtkNew<vtkPiecewiseFunction> opacity;
  vtkNew<vtkColorTransferFunction> color;
  double low = 0.0, high = 0.0;
  if (preset == "ct-bone")
  {
    opacity->AddPoint(150.0, 0.0);
    opacity->AddPoint(400.0, 0.6);
    opacity->AddPoint(1500.0, 0.9);
    color->AddRGBPoint(150.0, 0.75, 0.55, 0.4);
    color->AddRGBPoint(400.0, 0.95, 0.88, 0.75);
    color->AddRGBPoint(1500.0, 1.0, 1.0, 0.95);
  }
  else if (preset == "ct-skin")
  {
    opacity->AddPoint(-600.0, 0.0);
    opacity->AddPoint(-300.0, 0.8);
    opacity->AddPoint(300.0, 0.8);
    color->AddRGBPoint(-600.0, 0.85, 0.6, 0.5);
    color->AddRGBPoint(300.0, 0.95, 0.78, 0.68);
  }
  else if (preset == "mr")
  {
    const double span = range[1] - range[0];
    opacity->AddPoint(range[0] + 0.12 * span, 0.0);
    opacity->AddPoint(range[0] + 0.3 * span, 0.5);
    opacity->AddPoint(range[1], 0.8);
    color->AddRGBPoint(range[0], 0.7, 0.66, 0.62);
    color->AddRGBPoint(range[1], 1.0, 0.97, 0.94);
  }
  else if (std::sscanf(preset.c_str(), "%lf:%lf", &low, &high) == 2 && std::isfinite(low) &&
    std::isfinite(high) && high > low)
  {
    opacity->AddPoint(low, 0.0);
    opacity->AddPoint(high, 1.0);
    color->AddRGBPoint(low, 0.85, 0.8, 0.75);
    color->AddRGBPoint(high, 1.0, 1.0, 1.0);
  }
  else
  {
    return false;
  }
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  return true;
}

// The preset when none is given: CT holds air (Hounsfield units down to -1000), MR does not.
std::string DefaultPreset(const double range[2])
{
  return range[0] < -500.0 ? "ct-skin" : "mr";
}

// A unit vector toward compass azimuth `az` (0 north = +y, 90 east = +x) and elevation `el`.
void Toward(double az, double el, double v[3])
{
  const double a = vtkMath::RadiansFromDegrees(az);
  const double e = vtkMath::RadiansFromDegrees(el);
  v[0] = std::cos(e) * std::sin(a);
  v[1] = std::cos(e) * std::cos(a);
  v[2] = std::sin(e);
}

// One picture: the volume drawn by `mapper` in `window`.
vtkSmartPointer<vtkImageData> Grab(vtkRenderWindow* window)
{
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(grab->GetOutput());
  return image;
}

// The scene: renderer, lights, camera (by default from `frontAzimuth`, 15 degrees up).
void SetUpScene(
  const Options& options, vtkImageData* volume, double frontAzimuth, vtkRenderer* renderer)
{
  renderer->SetBackground(options.Background);
  renderer->AutomaticLightCreationOff();
  const double eyeAzimuth =
    std::isnan(options.CameraAzimuth) ? frontAzimuth : options.CameraAzimuth;
  const double eyeElevation = std::isnan(options.CameraElevation) ? 15.0 : options.CameraElevation;
  std::vector<Sun> suns = options.Suns;
  if (suns.empty() && !options.NoSun && options.Environment.empty())
  {
    suns.push_back({ eyeAzimuth - 45.0, eyeElevation + 30.0, 6.0 });
  }
  if (suns.empty())
  {
    // VTK shades a volume only with a light switched on: one of intensity 0 for the sky alone.
    vtkNew<vtkLight> dark;
    dark->SetLightTypeToSceneLight();
    dark->SetIntensity(0.0);
    renderer->AddLight(dark);
  }
  for (const Sun& sun : suns)
  {
    double toward[3];
    Toward(sun.Azimuth, sun.Elevation, toward);
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPositional(false);
    light->SetFocalPoint(0.0, 0.0, 0.0);
    light->SetPosition(toward);
    renderer->AddLight(light);
  }
  double bounds[6], center[3], eye[3];
  volume->GetBounds(bounds);
  volume->GetCenter(center);
  Toward(eyeAzimuth, eyeElevation, eye);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(center);
  camera->SetPosition(center[0] + eye[0], center[1] + eye[1], center[2] + eye[2]);
  camera->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCamera(bounds);
  camera->Zoom(options.Zoom);
}

// The volume property: the preset, the lighting that suits aperture shading (a bright sky,
// as the shadows are what shows the shape).
vtkSmartPointer<vtkVolumeProperty> MakeProperty(
  const Options& options, vtkImageData* volume, std::string& error)
{
  double range[2];
  volume->GetPointData()->GetScalars()->GetRange(range);
  const std::string preset =
    options.VolumePreset.empty() ? DefaultPreset(range) : options.VolumePreset;
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  if (!ApplyPreset(preset, range, property))
  {
    error = "--volume " + vtkApertureText::Quote(preset) +
      " is not ct-bone, ct-skin, mr or an opacity ramp LOW:HIGH";
    return nullptr;
  }
  const double* spacing = volume->GetSpacing();
  property->SetScalarOpacityUnitDistance(std::min({ spacing[0], spacing[1], spacing[2] }));
  property->SetInterpolationTypeToLinear();
  property->ShadeOn();
  property->SetAmbient(1.0);
  property->SetDiffuse(0.6);
  property->SetSpecular(0.2);
  return property;
}

// The environment as the volume's sky: zenith up (+z), turned by --env-azimuth, and the factor
// on its radiance: 2^--env-exposure, or (auto) the one that makes its mean radiance 1, the
// uniform sky's.
vtkSmartPointer<vtkEnvironmentMap> MakeEnvironment(
  const Options& options, vtkImageData* image, double& scale)
{
  auto environment = vtkSmartPointer<vtkEnvironmentMap>::New();
  environment->SetImage(image);
  environment->SetUpAxisToZ();
  environment->SetAzimuth(options.EnvironmentAzimuth);
  scale = std::exp2(options.EnvironmentExposure);
  if (std::isnan(options.EnvironmentExposure))
  {
    const double up[3] = { 0.0, 0.0, 1.0 };
    double whole[3];
    environment->CapRadiance(up, vtkMath::Pi(), whole);
    const double mean =
      (0.2126 * whole[0] + 0.7152 * whole[1] + 0.0722 * whole[2]) / (4.0 * vtkMath::Pi());
    scale = mean > 0.0 ? 1.0 / mean : 1.0;
  }
  return environment;
}

vtkSmartPointer<vtkVolumeMapper> MakeMapper(const std::string& mode, const Options& options,
  vtkImageData* volume, vtkEnvironmentMap* environment, double environmentScale)
{
  vtkSmartPointer<vtkOpenGLGPUVolumeRayCastMapper> mapper;
  if (mode == "standard")
  {
    mapper = vtkSmartPointer<vtkOpenGLGPUVolumeRayCastMapper>::New();
  }
  else
  {
    auto apertures = vtkSmartPointer<vtkApertureVolumeMapper>::New();
    apertures->SetShadingMode(
      mode == "smoothstep" ? vtkApertureVolumeMapper::SMOOTHSTEP : vtkApertureVolumeMapper::EXACT);
    apertures->SetLightRadius(vtkMath::RadiansFromDegrees(
      options.Suns.empty() ? 6.0 : std::max(options.Suns[0].Radius, 0.01)));
    const double sky = 1.5 * (environment ? environmentScale : 1.0);
    apertures->SetSkyColor(options.Sky[0] * sky, options.Sky[1] * sky, options.Sky[2] * sky);
    apertures->SetSkyEnvironment(environment);
    mapper = apertures;
  }
  mapper->SetInputData(volume);
  mapper->LockSampleDistanceToInputSpacingOn();
  mapper->SetAutoAdjustSampleDistances(options.Interactive);
  return mapper;
}
}

//------------------------------------------------------------------------------
bool ContourVolume(const Options& options, Input& input, std::string& error)
{
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputData(input.Volume);
  contour->SetValue(0, options.Iso);
  contour->ComputeNormalsOff();
  contour->Update();
  if (contour->GetOutput()->GetNumberOfPolys() == 0)
  {
    double range[2];
    input.Volume->GetPointData()->GetScalars()->GetRange(range);
    std::ostringstream why;
    why << "--iso " << options.Iso << " gives no surface (the scalars run from " << range[0]
        << " to " << range[1] << ")";
    error = why.str();
    return false;
  }
  input.Mesh = contour->GetOutput();
  input.Notes.push_back("--iso " + std::to_string(options.Iso) + ": an isosurface of " +
    std::to_string(input.Mesh->GetNumberOfPolys()) + " triangles");
  input.Volume = nullptr;
  return true;
}

//------------------------------------------------------------------------------
int ShowVolume(const Options& options, const Input& input, MessageCapture& messages)
{
  if (options.Mode != "exact" && options.Mode != "smoothstep" && options.Mode != "standard" &&
    options.Mode != "all")
  {
    std::cerr << "aperture-render: --mode " << options.Mode
              << " is for surfaces; volumes take exact, smoothstep, standard or all\n";
    return 2;
  }
  std::string error;
  vtkSmartPointer<vtkVolumeProperty> property = MakeProperty(options, input.Volume, error);
  vtkNew<vtkRenderWindow> window;
  void* display = nullptr;
  if (!property || !AttachDisplay(window, display, error))
  {
    std::cerr << "aperture-render: " << error << "\n";
    return property ? 1 : 2;
  }
  window->SetSize(options.Width, options.Height);
  window->SetOffScreenRendering(!options.Interactive);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  SetUpScene(options, input.Volume, input.FrontAzimuth, renderer);
  vtkNew<vtkVolume> volume;
  volume->SetProperty(property);
  renderer->AddVolume(volume);
  std::vector<std::string> modes = { options.Mode };
  if (options.Mode == "all")
  {
    modes = { "standard", "exact", "smoothstep" };
  }
  vtkNew<vtkImageAppend> row;
  row->SetAppendAxis(0);
  double environmentScale = 1.0;
  vtkSmartPointer<vtkEnvironmentMap> environment =
    input.Environment ? MakeEnvironment(options, input.Environment, environmentScale) : nullptr;
  messages.Clear();
  for (const std::string& mode : modes)
  {
    volume->SetMapper(MakeMapper(mode, options, input.Volume, environment, environmentScale));
    row->AddInputData(Grab(window));
  }
  int status = 0;
  if (!messages.FirstError().empty())
  {
    std::cerr << "aperture-render: rendering failed: " << messages.FirstError() << "\n";
    status = 1;
  }
  else if (!options.Output.empty())
  {
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputConnection(row->GetOutputPort());
    writer->SetFileName(options.Output.c_str());
    writer->Write();
    std::cout << "wrote " << vtksys::SystemTools::CollapseFullPath(options.Output) << "\n";
  }
  if (status == 0 && options.Interactive)
  {
    vtkNew<vtkRenderWindowInteractor> interactor;
    vtkNew<vtkInteractorStyleTrackballCamera> style;
    interactor->SetInteractorStyle(style);
    interactor->SetRenderWindow(window);
    interactor->Start();
  }
  window->Finalize();
  CloseDisplay(display);
  return status;
}
}
