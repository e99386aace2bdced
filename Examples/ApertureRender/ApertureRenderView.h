/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderView.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// aperture-render's picture: the shaded surface, its lights and camera, written to a PNG or
// shown in a window.

#ifndef ApertureRenderView_h
#define ApertureRenderView_h

#include "ApertureRenderCamera.h" // For MeshView
#include "ApertureRenderOptions.h"

#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkActor;
class vtkApertureLightingMapper;
class vtkDataObject;
class vtkEnvironmentMap;
class vtkImageData;
class vtkLight;
class vtkObject;
class vtkPolyData;
class vtkRenderWindow;
class vtkRenderer;
class vtkScalarBarActor;
class vtkTextActor;

namespace ApertureRender
{
struct Input;
class MessageCapture;

class View
{
public:
  // The surface of `apertures` (the precompute's output for `input`) in a window of the
  // options' size, not yet shown.
  View(const Options& options, const Input& input, vtkDataObject* apertures);
  ~View();
  View(const View&) = delete;
  View& operator=(const View&) = delete;

  // Opens the OpenGL context; false with one sentence in `error` when there is no X display or
  // the OpenGL it offers is too old.
  bool Open(std::string& error);

  // Writes the picture (a row of panels for --mode all) as a PNG.
  bool WritePicture(const std::string& path, MessageCapture& messages, std::string& error);

  // Writes the data with its arrays: .vtp the surface, .vti a height field's grid.
  bool WriteData(const std::string& path, MessageCapture& messages, std::string& error);

  // Runs the window until the user closes it.
  void Interact();

  // One line saying where the eye, the up axis and the sun are, and why: "view: eye from the E
  // (azimuth 90, 15 deg up), up +y (...); sun ...".
  std::string Description() const;

private:
  void MakeSurface(const Input& input);
  void SetUpMapper(const Input& input);
  void AddOverlays();
  // Stops that show the environment well: see --env-exposure.
  double AutomaticExposure() const;
  // Turns the environment to a compass azimuth about the data's up axis.
  void TurnEnvironment(double azimuth);
  void Direction(double azimuth, double elevation, double direction[3]) const;
  // The eye's compass azimuth and elevation: the options', else the default view's.
  void EyeAngles(double& azimuth, double& elevation) const;
  void AddLights();
  void PlaceCamera();
  void SetMode(int mode);
  // The modes this data can show: Horizon only where the apertures hold horizons, Visibility
  // mask only where they hold masks.
  bool ModeAvailable(int mode) const;
  int NextMode(int mode) const;
  void ShowApertureData(bool show);
  void UpdateStatus();
  vtkSmartPointer<vtkImageData> Grab();
  static void OnKey(vtkObject* caller, unsigned long, void* clientData, void*);

  Options Settings;
  void* Display = nullptr; // the X11 connection, see ApertureRenderDisplay.h
  bool HeightField;
  vtkSmartPointer<vtkDataObject> Apertures;
  vtkSmartPointer<vtkPolyData> Surface;
  vtkSmartPointer<vtkPolyData> Drawn; // Surface without cells that use points not finite
  MeshView Chosen;                    // the default view: up axis (and why), the eye's azimuth
  bool DefaultSun = false;            // the sun was placed by the view, not given
  double Center[3];
  double East[3], North[3], Up[3];
  int Mode = 0;
  double EnvironmentAzimuth = 0.0;
  double SkyIntensity = 1.0; // what the s key turns the sky back on to
  bool DataShown = false;
  std::vector<vtkSmartPointer<vtkLight>> Suns;
  std::vector<Sun> SunAngles;
  std::vector<vtkSmartPointer<vtkLight>> Lamps;
  vtkNew<vtkEnvironmentMap> Environment; // the --env sky, when there is one
  vtkNew<vtkApertureLightingMapper> Mapper;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkTextActor> Label;
  vtkNew<vtkTextActor> Status;
  vtkNew<vtkScalarBarActor> Legend;
};
}

#endif
