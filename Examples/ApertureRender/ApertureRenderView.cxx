/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderView.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "ApertureRenderView.h"

#include "ApertureRenderDisplay.h"
#include "ApertureRenderInput.h"
#include "ApertureRenderMessages.h"

#include "ApertureRenderCamera.h"

#include "vtkActor.h"
#include "vtkApertureLightingMapper.h"
#include "vtkApertureSurface.h"
#include "vtkApertureText.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkEnvironmentMap.h"
#include "vtkExtractVOI.h"
#include "vtkIdList.h"
#include "vtkImageAppend.h"
#include "vtkImageData.h"
#include "vtkImageDataGeometryFilter.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkScalarBarActor.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkWarpScalar.h"
#include "vtkWindowToImageFilter.h"
#include "vtkXMLImageDataWriter.h"
#include "vtkXMLPolyDataWriter.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>

namespace ApertureRender
{
namespace
{
const char* const ModeLabels[] = { "Exact", "Smoothstep", "Simplified", "Bent normal",
  "Standard VTK", "Horizon", "Visibility mask" };

double Radians(double degrees)
{
  return vtkMath::RadiansFromDegrees(degrees);
}

// The surface without its points that are not finite, nor the cells that use them: VTK's vertex
// buffers scale their coordinates by the points' range, which one infinite point makes useless.
vtkSmartPointer<vtkPolyData> FiniteCells(vtkPolyData* surface)
{
  vtkPoints* points = surface->GetPoints();
  std::vector<vtkIdType> kept(surface->GetNumberOfPoints(), -1);
  vtkNew<vtkPoints> finite;
  vtkNew<vtkIdList> from, to;
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    const double* p = points->GetPoint(i);
    if (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))
    {
      kept[i] = finite->InsertNextPoint(p);
      from->InsertNextId(i);
      to->InsertNextId(kept[i]);
    }
  }
  auto keep = [&](vtkCellArray* cells)
  {
    auto result = vtkSmartPointer<vtkCellArray>::New();
    vtkIdType npts;
    const vtkIdType* ids;
    std::vector<vtkIdType> renumbered;
    for (cells->InitTraversal(); cells->GetNextCell(npts, ids);)
    {
      renumbered.clear();
      for (vtkIdType k = 0; k < npts && kept[ids[k]] >= 0; ++k)
      {
        renumbered.push_back(kept[ids[k]]);
      }
      if (static_cast<vtkIdType>(renumbered.size()) == npts)
      {
        result->InsertNextCell(npts, renumbered.data());
      }
    }
    return result;
  };
  auto drawn = vtkSmartPointer<vtkPolyData>::New();
  drawn->SetPoints(finite);
  drawn->GetPointData()->CopyAllocate(surface->GetPointData(), finite->GetNumberOfPoints());
  drawn->GetPointData()->CopyData(surface->GetPointData(), from, to);
  drawn->SetVerts(keep(surface->GetVerts()));
  drawn->SetLines(keep(surface->GetLines()));
  drawn->SetPolys(keep(surface->GetPolys()));
  drawn->SetStrips(keep(surface->GetStrips()));
  return drawn;
}
}

View::View(const Options& options, const Input& input, vtkDataObject* apertures)
  : Settings(options)
  , HeightField(input.Heights != nullptr)
  , Apertures(apertures)
{
  const std::vector<std::string>& names = ModeNames();
  this->Mode = options.Mode == "all"
    ? 0
    : static_cast<int>(std::find(names.begin(), names.end(), options.Mode) - names.begin());
  this->MakeSurface(input);
  this->SetUpMapper(input);
  this->AddLights();
  this->PlaceCamera();
  this->AddOverlays();
  this->ShowApertureData(options.ShowApertures);
  this->Window->AddRenderer(this->Renderer);
  this->Window->SetSize(options.Width, options.Height);
  this->Window->SetMultiSamples(0);
  this->Window->SetWindowName("aperture-render");
}

// The surface drawn (a height field's grid raised, or the mesh without cells on non-finite
// points), its centre, and the compass of the view.
void View::MakeSurface(const Input& input)
{
  const Options& options = this->Settings;
  vtkDataObject* apertures = this->Apertures;
  if (this->HeightField)
  {
    // The grid's surface, raised as vtkAperturePrecompute raised it; point data (the apertures)
    // come along. A grid larger than --max-grid is drawn from every k-th sample and shaded per
    // texel from the whole grid's apertures.
    auto* image = vtkImageData::SafeDownCast(apertures);
    int dims[3];
    image->GetDimensions(dims);
    // (The last row and column go when the stride does not divide the grid: vtkExtractVOI
    // would place them a stride's multiple away, off the grid.)
    const int gaps = std::max(dims[0], dims[1]) - 1, most = std::max(1, options.MaximumGrid - 1);
    const int stride = std::max(1, (gaps + most - 1) / most);
    vtkNew<vtkExtractVOI> coarse;
    coarse->SetInputData(apertures);
    coarse->SetSampleRate(stride, stride, 1);
    if (stride > 1)
    {
      this->Mapper->SetApertureImage(image);
    }
    vtkNew<vtkImageDataGeometryFilter> grid;
    grid->SetInputConnection(coarse->GetOutputPort());
    vtkNew<vtkWarpScalar> warp;
    warp->SetInputConnection(grid->GetOutputPort());
    warp->SetScaleFactor(options.HeightScale);
    warp->UseNormalOn();
    warp->SetNormal(0.0, 0.0, 1.0);
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputConnection(warp->GetOutputPort());
    normals->SplittingOff();
    normals->Update();
    this->Surface = normals->GetOutput();
  }
  else
  {
    this->Surface = vtkPolyData::SafeDownCast(apertures);
  }
  this->Drawn = input.NonFinitePoints > 0 ? FiniteCells(this->Surface) : this->Surface;
  double bounds[6];
  vtkApertureSurface::InitializeBounds(bounds);
  vtkApertureSurface::ExpandBounds(this->Drawn, bounds);
  for (int k = 0; k < 3; ++k)
  {
    this->Center[k] = bounds[0] <= bounds[1] ? 0.5 * (bounds[2 * k] + bounds[2 * k + 1]) : 0.0;
  }
  // Height fields rise along +z and are seen from the south-south-west; meshes, see ChooseView.
  this->Chosen = this->HeightField ? MeshView{ options.Up.empty() ? "+z" : options.Up, 200.0,
    options.Up.empty() ? "height field" : "given with --up" }
                                   : ChooseView(this->Drawn, options.Up);
  CompassOf(this->Chosen.Up, this->East, this->North, this->Up);
}

// The mapper and actor: shading mode, sky or environment, colours.
void View::SetUpMapper(const Input& input)
{
  const Options& options = this->Settings;
  this->Mapper->SetInputData(this->Drawn);
  this->Mapper->SetShadingMode(this->Mode);
  this->Mapper->SetSkyColor(options.Sky[0], options.Sky[1], options.Sky[2]);
  this->Mapper->SetSkyIntensity(1.0);
  vtkProperty* property = this->Actor->GetProperty();
  if (this->HeightField)
  {
    property->SetColor(0.92, 0.87, 0.8);
  }
  else
  {
    property->SetColor(0.9, 0.86, 0.8);
    property->SetSpecular(0.15);
    property->SetSpecularPower(24.0);
  }
  if (input.Environment)
  {
    // The environment's zenith along the data's up axis and its north on the data's north.
    this->Environment->SetImage(input.Environment);
    this->Environment->SetUpAxis(this->Up[0] != 0.0 ? 0 : (this->Up[1] != 0.0 ? 1 : 2));
    this->TurnEnvironment(options.EnvironmentAzimuth);
    this->Mapper->SetSkyEnvironment(this->Environment);
    if (!options.SkyGiven)
    {
      this->Mapper->SetSkyColor(1.0, 1.0, 1.0);
    }
    double exposure = options.EnvironmentExposure;
    if (std::isnan(exposure))
    {
      exposure = this->AutomaticExposure();
    }
    this->SkyIntensity = std::exp2(exposure);
    this->Mapper->SetSkyIntensity(this->SkyIntensity);
  }
  // Meshes that bring their own RGB colours (PLY scans) keep them; other arrays are not colours.
  vtkDataArray* scalars = this->Drawn->GetPointData()->GetScalars();
  const bool colours = !this->HeightField && scalars &&
    scalars->GetDataType() == VTK_UNSIGNED_CHAR &&
    (scalars->GetNumberOfComponents() == 3 || scalars->GetNumberOfComponents() == 4);
  this->Mapper->SetScalarVisibility(colours);
  this->Mapper->SetColorModeToDirectScalars();
  this->Actor->SetMapper(this->Mapper);
  this->Renderer->AddActor(this->Actor);
  this->Renderer->SetBackground(options.Background);
}

// The mode label, the interactive status line and the aperture-radius legend, hidden until used.
void View::AddOverlays()
{
  const Options& options = this->Settings;
  const int fontSize = std::max(12, options.Height / 22);
  this->Label->GetTextProperty()->SetFontSize(fontSize);
  this->Label->GetTextProperty()->SetColor(0.95, 0.95, 0.95);
  this->Label->SetPosition(0.6 * fontSize, options.Height - 1.8 * fontSize);
  this->Label->SetVisibility(options.Mode == "all");
  this->Renderer->AddActor2D(this->Label);
  this->Status->GetTextProperty()->SetFontSize(std::max(12, fontSize * 2 / 3));
  this->Status->GetTextProperty()->SetColor(0.85, 0.85, 0.85);
  this->Status->SetPosition(8, 8);
  this->Status->SetVisibility(false);
  this->Renderer->AddActor2D(this->Status);
  this->Legend->SetTitle("aperture radius (rad)");
  this->Legend->SetNumberOfLabels(5);
  this->Legend->SetLabelFormat("%.2f");
  this->Legend->UnconstrainedFontSizeOn();
  this->Legend->SetMaximumWidthInPixels(std::max(60, options.Width / 10));
  for (vtkTextProperty* text :
    { this->Legend->GetLabelTextProperty(), this->Legend->GetTitleTextProperty() })
  {
    text->SetFontSize(std::max(11, options.Height / 36));
    text->ItalicOff();
    text->BoldOff();
    text->ShadowOff();
  }
  this->Legend->SetVisibility(false);
  this->Renderer->AddActor2D(this->Legend);
}

View::~View()
{
  // The window goes before the display connection it uses.
  this->Window->Finalize();
  CloseDisplay(this->Display);
}

double View::AutomaticExposure() const
{
  // HDR maps hold radiance in any unit: an open level surface at 80% white, but no open surface
  // facing any way (toward a low sun) brighter than white.
  const double* tint = this->Mapper->GetSkyColor();
  const double albedo = vtkMath::Norm(this->Actor->GetProperty()->GetColor()) / std::sqrt(3.0);
  auto luminance = [&](const double direction[3])
  {
    double open[3];
    this->Environment->CapIrradiance(direction, vtkMath::Pi() / 2.0, open);
    return (0.2126 * open[0] * tint[0] + 0.7152 * open[1] * tint[1] + 0.0722 * open[2] * tint[2]) /
      vtkMath::Pi();
  };
  const double level = luminance(this->Up);
  double brightest = level;
  const int samples = 256;
  for (int i = 0; i < samples; ++i)
  {
    // A Fibonacci sphere of directions.
    const double z = 1.0 - (2.0 * i + 1.0) / samples;
    const double phi = i * vtkMath::Pi() * (3.0 - std::sqrt(5.0));
    const double d[3] = { std::sqrt(1.0 - z * z) * std::cos(phi),
      std::sqrt(1.0 - z * z) * std::sin(phi), z };
    brightest = std::max(brightest, luminance(d));
  }
  if (!(level > 0.0) || !(brightest > 0.0))
  {
    return 0.0;
  }
  return std::min(std::log2(0.8 / level), std::log2(0.95 / (albedo * brightest)));
}

void View::TurnEnvironment(double azimuth)
{
  // vtkEnvironmentMap's frames have their zenith on a positive axis and share the data's east
  // and north there. A negative up axis is that frame turned half-way about east, which also
  // mirrors the sense of the azimuth.
  const bool down = this->Up[0] + this->Up[1] + this->Up[2] < 0.0;
  const double flip[9] = { -1, 0, 0, 0, 1, 0, 0, 0, -1 };
  const double identity[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  this->Environment->SetOrientation(down ? flip : identity);
  this->Environment->SetAzimuth(down ? -azimuth : azimuth);
  this->EnvironmentAzimuth = azimuth;
}

void View::Direction(double azimuth, double elevation, double direction[3]) const
{
  const double a = Radians(azimuth), e = Radians(elevation);
  for (int k = 0; k < 3; ++k)
  {
    direction[k] = std::cos(e) * (std::sin(a) * this->East[k] + std::cos(a) * this->North[k]) +
      std::sin(e) * this->Up[k];
  }
}

void View::AddLights()
{
  this->SunAngles = this->Settings.Suns;
  this->DefaultSun = this->SunAngles.empty() && !this->Settings.NoSun &&
    this->Settings.SphereLights.empty() && this->Settings.Environment.empty();
  if (this->DefaultSun && this->HeightField)
  {
    // The terrain convention: low from the west-north-west, the default view's left.
    this->SunAngles.push_back(Sun{ 285.0, 16.0, 0.27 });
  }
  else if (this->DefaultSun)
  {
    // A key light over the viewer's left shoulder, wherever the eye is: the side the camera
    // sees is lit and the shadows fall where it sees them.
    double azimuth, elevation;
    this->EyeAngles(azimuth, elevation);
    this->SunAngles.push_back(Sun{
      CompassAzimuth(azimuth + 45.0), std::min(85.0, std::max(-85.0, elevation + 30.0)), 0.27 });
  }
  for (const Sun& angles : this->SunAngles)
  {
    auto sun = vtkSmartPointer<vtkLight>::New();
    sun->SetLightTypeToSceneLight();
    sun->SetPositional(false);
    sun->SetColor(1.0, 0.97, 0.92);
    vtkApertureLightingMapper::SetLightRadius(sun, Radians(angles.Radius));
    this->Suns.push_back(sun);
    this->Renderer->AddLight(sun);
  }
  for (const SphereLight& sphere : this->Settings.SphereLights)
  {
    auto lamp = vtkSmartPointer<vtkLight>::New();
    lamp->SetLightTypeToSceneLight();
    lamp->SetPositional(true);
    lamp->SetConeAngle(180.0);
    lamp->SetPosition(sphere.Position[0], sphere.Position[1], sphere.Position[2]);
    lamp->SetFocalPoint(this->Center);
    lamp->SetIntensity(sphere.Intensity);
    vtkApertureLightingMapper::SetLightRadius(lamp, sphere.Radius);
    this->Lamps.push_back(lamp);
    this->Renderer->AddLight(lamp);
  }
  // Place the suns.
  for (size_t i = 0; i < this->Suns.size(); ++i)
  {
    double d[3];
    this->Direction(this->SunAngles[i].Azimuth, this->SunAngles[i].Elevation, d);
    this->Suns[i]->SetFocalPoint(this->Center);
    this->Suns[i]->SetPosition(
      this->Center[0] + d[0], this->Center[1] + d[1], this->Center[2] + d[2]);
  }
  if (this->Suns.empty() && this->Lamps.empty())
  {
    // VTK skips lighting altogether when no light is on; a dark, point-sized one keeps the
    // environment sky shaded.
    vtkNew<vtkLight> placeholder;
    placeholder->SetLightTypeToSceneLight();
    placeholder->SetIntensity(0.0);
    vtkApertureLightingMapper::SetLightRadius(placeholder, 0.0);
    this->Renderer->AddLight(placeholder);
  }
}

void View::EyeAngles(double& azimuth, double& elevation) const
{
  azimuth =
    std::isnan(this->Settings.CameraAzimuth) ? this->Chosen.Azimuth : this->Settings.CameraAzimuth;
  elevation = std::isnan(this->Settings.CameraElevation) ? (this->HeightField ? 28.0 : 15.0)
                                                         : this->Settings.CameraElevation;
}

std::string View::Description() const
{
  double azimuth, elevation;
  this->EyeAngles(azimuth, elevation);
  std::ostringstream line;
  line << "view: eye from the " << CompassName(azimuth) << " (azimuth " << azimuth << ", "
       << elevation << " deg up), up " << this->Chosen.Up << " (" << this->Chosen.UpReason << "); ";
  if (this->SunAngles.empty())
  {
    line << "no sun";
  }
  else
  {
    const Sun& sun = this->SunAngles[0];
    line << "sun from the " << CompassName(sun.Azimuth) << " (azimuth " << sun.Azimuth << ", "
         << sun.Elevation << " deg up, "
         << (!this->DefaultSun      ? "given"
                : this->HeightField ? "the terrain default"
                                    : "over the viewer's left shoulder")
         << "; --sun to place it)";
  }
  return line.str();
}

void View::PlaceCamera()
{
  const bool field = this->HeightField;
  double azimuth, elevation;
  this->EyeAngles(azimuth, elevation);
  double d[3];
  this->Direction(azimuth, elevation, d);
  vtkCamera* camera = this->Renderer->GetActiveCamera();
  camera->SetFocalPoint(this->Center);
  camera->SetPosition(this->Center[0] + d[0], this->Center[1] + d[1], this->Center[2] + d[2]);
  camera->SetViewUp(this->Up);
  this->Renderer->ResetCamera();
  camera->Zoom((field ? 2.1 : 1.15) * this->Settings.Zoom);
  this->Renderer->ResetCameraClippingRange();
}

bool View::Open(std::string& error)
{
  if (!AttachDisplay(this->Window, this->Display, error))
  {
    return false;
  }
  this->Window->SetOffScreenRendering(!this->Settings.Interactive);
  if (!this->Window->SupportsOpenGL())
  {
    error = "the OpenGL of this display is too old: vtkApertureLightingMapper needs OpenGL 3.2";
    return false;
  }
  return true;
}

vtkSmartPointer<vtkImageData> View::Grab()
{
  this->Window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(this->Window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(grab->GetOutput());
  return image;
}

bool View::WritePicture(const std::string& path, MessageCapture& messages, std::string& error)
{
  messages.Clear();
  vtkNew<vtkPNGWriter> writer;
  vtkNew<vtkImageAppend> row;
  if (this->Settings.Mode == "all")
  {
    row->SetAppendAxis(0);
    for (int mode = 0; mode < static_cast<int>(ModeNames().size()); ++mode)
    {
      if (!this->ModeAvailable(mode))
      {
        continue;
      }
      this->SetMode(mode);
      this->Label->SetInput(ModeLabels[mode]);
      row->AddInputData(this->Grab());
    }
    row->Update();
    writer->SetInputConnection(row->GetOutputPort());
  }
  else
  {
    writer->SetInputData(this->Grab());
  }
  if (!messages.FirstError().empty())
  {
    error = "rendering failed: " + messages.FirstError();
    return false;
  }
  writer->SetFileName(path.c_str());
  writer->Write();
  if (!messages.FirstError().empty() || !vtksys::SystemTools::FileExists(path, true))
  {
    error = "cannot write " + vtkApertureText::QuoteName(path) +
      (messages.FirstError().empty() ? std::string() : ": " + messages.FirstError());
    return false;
  }
  return true;
}

bool View::WriteData(const std::string& path, MessageCapture& messages, std::string& error)
{
  const std::string extension =
    vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(path));
  messages.Clear();
  int written = 0;
  if (extension == ".vti")
  {
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetInputData(this->Apertures);
    writer->SetFileName(path.c_str());
    written = writer->Write();
  }
  else
  {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(this->Surface);
    writer->SetFileName(path.c_str());
    written = writer->Write();
  }
  if (!written || !messages.FirstError().empty())
  {
    error = "cannot write " + vtkApertureText::QuoteName(path) +
      (messages.FirstError().empty() ? std::string() : ": " + messages.FirstError());
    return false;
  }
  return true;
}

bool View::ModeAvailable(int mode) const
{
  auto* data = vtkDataSet::SafeDownCast(this->Apertures);
  const char* needs = mode == vtkApertureLightingInterface::HORIZON ? "HorizonAngles"
    : mode == vtkApertureLightingInterface::VISIBILITY_MASK         ? "VisibilityMask"
                                                                    : nullptr;
  return !needs || (data && data->GetPointData()->GetArray(needs));
}

int View::NextMode(int mode) const
{
  const int count = static_cast<int>(ModeNames().size());
  do
  {
    mode = (mode + 1) % count;
  } while (!this->ModeAvailable(mode));
  return mode;
}

void View::SetMode(int mode)
{
  this->Mode = mode;
  this->Mapper->SetShadingMode(this->DataShown ? vtkApertureLightingInterface::STANDARD : mode);
}

void View::ShowApertureData(bool show)
{
  // The aperture radius as a colour map, from closed (dark blue) to a whole hemisphere (yellow),
  // over standard lighting so that the colours read true.
  this->DataShown = show;
  if (show)
  {
    vtkNew<vtkColorTransferFunction> colours;
    colours->AddRGBPoint(0.0, 0.27, 0.0, 0.33);
    colours->AddRGBPoint(0.4, 0.23, 0.32, 0.55);
    colours->AddRGBPoint(0.8, 0.13, 0.57, 0.55);
    colours->AddRGBPoint(1.2, 0.37, 0.79, 0.38);
    colours->AddRGBPoint(0.5 * vtkMath::Pi(), 0.99, 0.91, 0.14);
    this->Mapper->SetLookupTable(colours);
    this->Mapper->SetScalarModeToUsePointFieldData();
    this->Mapper->SelectColorArray("ApertureRadius");
    this->Mapper->SetColorModeToMapScalars();
    this->Mapper->SetScalarRange(0.0, 0.5 * vtkMath::Pi());
    this->Mapper->ScalarVisibilityOn();
    this->Legend->SetLookupTable(colours);
    // Mostly ambient, so that the colours read true under any sun.
    this->Actor->GetProperty()->SetAmbient(0.6);
    this->Actor->GetProperty()->SetDiffuse(0.5);
  }
  else
  {
    this->Actor->GetProperty()->SetAmbient(0.0);
    this->Actor->GetProperty()->SetDiffuse(1.0);
    this->Mapper->SetScalarModeToDefault();
    this->Mapper->SetColorModeToDirectScalars();
    vtkDataArray* scalars = this->Drawn->GetPointData()->GetScalars();
    this->Mapper->SetScalarVisibility(!this->HeightField && scalars &&
      scalars->GetDataType() == VTK_UNSIGNED_CHAR && scalars->GetNumberOfComponents() >= 3);
  }
  this->Legend->SetVisibility(show);
  this->SetMode(this->Mode);
}

void View::UpdateStatus()
{
  std::ostringstream status;
  status << (this->DataShown ? "aperture radius" : ModeLabels[this->Mode]);
  if (!this->SunAngles.empty())
  {
    status << "  |  sun " << this->SunAngles[0].Azimuth << " deg, " << this->SunAngles[0].Elevation
           << " deg up, radius " << this->SunAngles[0].Radius << " deg";
  }
  if (this->Mapper->GetSkyEnvironment())
  {
    status << "  |  environment turned " << this->EnvironmentAzimuth << " deg (e/E)";
  }
  status << "  |  keys: arrows sun, m mode, a apertures, [ ] light size, s sky, h help";
  this->Status->SetInput(status.str().c_str());
}

void View::OnKey(vtkObject* caller, unsigned long, void* clientData, void*)
{
  auto* view = static_cast<View*>(clientData);
  const std::string key = static_cast<vtkRenderWindowInteractor*>(caller)->GetKeySym();
  Sun* sun = view->SunAngles.empty() ? nullptr : &view->SunAngles[0];
  if (sun && (key == "Left" || key == "Right"))
  {
    sun->Azimuth = CompassAzimuth(sun->Azimuth + (key == "Left" ? -10.0 : 10.0));
  }
  else if (sun && (key == "Up" || key == "Down"))
  {
    sun->Elevation = std::min(90.0, std::max(-10.0, sun->Elevation + (key == "Up" ? 3.0 : -3.0)));
  }
  else if (key == "m")
  {
    view->SetMode(view->NextMode(view->Mode));
  }
  else if (key == "a")
  {
    view->ShowApertureData(!view->DataShown);
  }
  else if (key == "bracketleft" || key == "bracketright")
  {
    const double factor = key == "bracketleft" ? 1.0 / 1.5 : 1.5;
    for (Sun& s : view->SunAngles)
    {
      s.Radius = std::min(60.0, s.Radius * factor);
    }
    for (vtkLight* lamp : view->Lamps)
    {
      vtkApertureLightingMapper::SetLightRadius(
        lamp, vtkApertureLightingMapper::GetLightRadius(lamp) * factor);
    }
  }
  else if ((key == "e" || key == "E") && view->Mapper->GetSkyEnvironment())
  {
    view->TurnEnvironment(CompassAzimuth(view->EnvironmentAzimuth + (key == "e" ? 15.0 : -15.0)));
  }
  else if (key == "s")
  {
    view->Mapper->SetSkyIntensity(view->Mapper->GetSkyIntensity() > 0.0 ? 0.0 : view->SkyIntensity);
  }
  else if (key == "h")
  {
    std::cout << "Keys: Left/Right turn the first sun, Up/Down raise or lower it; m next shading "
                 "mode; a aperture radius as colours; [ and ] shrink or grow the lights; s sky "
                 "on or off; e/E turn the environment; r reset the camera; q quit.\n";
  }
  else
  {
    return;
  }
  for (size_t i = 0; i < view->Suns.size(); ++i)
  {
    double d[3];
    view->Direction(view->SunAngles[i].Azimuth, view->SunAngles[i].Elevation, d);
    view->Suns[i]->SetPosition(
      view->Center[0] + d[0], view->Center[1] + d[1], view->Center[2] + d[2]);
    vtkApertureLightingMapper::SetLightRadius(view->Suns[i], Radians(view->SunAngles[i].Radius));
  }
  view->UpdateStatus();
  view->Window->Render();
}

void View::Interact()
{
  this->Label->SetVisibility(false);
  this->Status->SetVisibility(true);
  this->UpdateStatus();
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(this->Window);
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  interactor->SetInteractorStyle(style);
  vtkNew<vtkCallbackCommand> keys;
  keys->SetClientData(this);
  keys->SetCallback(&View::OnKey);
  interactor->AddObserver(vtkCommand::KeyPressEvent, keys);
  this->Window->Render();
  interactor->Start();
}
}
