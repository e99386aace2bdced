/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderOptions.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// aperture-render's command line: what it accepts, checked, with its help text.

#ifndef ApertureRenderOptions_h
#define ApertureRenderOptions_h

#include <string>
#include <vector>

namespace ApertureRender
{
// A sun: compass azimuth and elevation above the horizon, angular radius, all in degrees.
struct Sun
{
  double Azimuth, Elevation, Radius;
};

// A sphere light: centre, world radius, and intensity (the irradiance it gives an unoccluded
// surface facing it, as for any VTK light).
struct SphereLight
{
  double Position[3];
  double Radius, Intensity;
};

struct Options
{
  std::string Input; // empty: the embedded Mount Fuji tile
  std::string Output;
  int Width = 1280;
  int Height = 800;
  bool Interactive = false;
  std::string Mode = "exact"; // a shading mode, or "all" for a row of every mode
  bool ShowApertures = false; // colour by the aperture radius instead of shading
  std::vector<Sun> Suns;
  bool NoSun = false; // --sun none: not even the default sun
  std::vector<SphereLight> SphereLights;
  double Sky[3] = { 0.24, 0.27, 0.34 };
  bool SkyGiven = false;
  std::string Environment;         // an OpenEXR latitude-longitude sky; empty: the uniform sky
  double EnvironmentAzimuth = 0.0; // compass turn of the environment, degrees clockwise
  // Stops by which the environment is brightened; NaN: automatic (an open level surface at 0.8).
  double EnvironmentExposure;
  int Rays = 256;
  // Height fields cast Rays only when --rays is given; else horizon sweeps in Sectors sectors.
  bool RaysGiven = false;
  int Sectors = 32;
  // Creases: normals and apertures split where faces meet at more than this (degrees).
  double Crease = 60.0;
  // Meshes: refine to edges of at most this length; NaN: automatically, 0: never.
  double MaximumEdge;
  std::string Cache;
  std::string SaveData;
  // Camera: compass azimuth and elevation of the eye as seen from the data; NaN: the default view.
  double CameraAzimuth;
  double CameraElevation;
  double Zoom = 1.0;
  std::string Up; // "+x" ... "-z"; empty: +z for height fields, see ChooseView for meshes
  // Height fields: ground spacing (0: from the file, else 30 m) and vertical scale (0: 1, or 1.5
  // for the embedded tile).
  double Spacing = 0.0;
  double HeightScale = 0.0;
  int MaximumGrid = 1024; // larger grids: a mesh of at most this many samples a side
  // Volumes: an opacity preset (ct-bone, ct-skin, mr) or ramp LOW:HIGH; empty: by the data.
  std::string VolumePreset;
  double Iso; // volumes: the isosurface at this value through the mesh pipeline; NaN: none
  double Background[3] = { 0.09, 0.1, 0.12 };
  bool Help = false;
  bool Version = false;

  Options();
};

// The shading modes by their command-line names, in vtkApertureLightingInterface's order.
const std::vector<std::string>& ModeNames();

// Whether a height field's horizons are to be kept: for the modes that can show them (horizon,
// all, and the window's m key).
bool WantsHorizons(const Options& options);

// Whether a mesh's visibility masks are to be kept: for the modes that can show them (mask, all,
// and the window's m key).
bool WantsMasks(const Options& options);

// Parses argv into options. Returns 0 on success, otherwise the exit code (2) with one sentence
// in `error`.
int ParseOptions(int argc, char* argv[], Options& options, std::string& error);

// The --help text.
std::string HelpText();
}

#endif
