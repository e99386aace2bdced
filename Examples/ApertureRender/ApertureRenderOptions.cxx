/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderOptions.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "ApertureRenderOptions.h"

#include "ApertureRenderMessages.h"

#include "vtkApertureText.h"
#include "vtksys/CommandLineArguments.hxx"
#include "vtksys/SystemTools.hxx"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <set>
#include <sstream>

namespace ApertureRender
{
namespace
{
// A whole string as a finite number, or false.
bool ToNumber(const std::string& text, double& value)
{
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0])))
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  return errno == 0 && end == text.c_str() + text.size() && std::isfinite(value);
}

// "a,b,c" as between `least` and `most` numbers.
bool ToNumbers(const std::string& text, size_t least, size_t most, std::vector<double>& values)
{
  values.clear();
  std::string item;
  std::istringstream in(text);
  while (std::getline(in, item, ','))
  {
    double value;
    if (!ToNumber(item, value))
    {
      return false;
    }
    values.push_back(value);
  }
  if (!text.empty() && text.back() == ',')
  {
    return false;
  }
  return values.size() >= least && values.size() <= most;
}
}

Options::Options()
  : MaximumEdge(std::numeric_limits<double>::quiet_NaN())
  , CameraAzimuth(std::numeric_limits<double>::quiet_NaN())
  , CameraElevation(std::numeric_limits<double>::quiet_NaN())
  , EnvironmentExposure(std::numeric_limits<double>::quiet_NaN())
{
}

const std::vector<std::string>& ModeNames()
{
  static const std::vector<std::string> names = { "exact", "smoothstep", "simplified", "bentnormal",
    "standard" };
  return names;
}

int ParseOptions(int argc, char* argv[], Options& options, std::string& error)
{
  std::string output, size, mode, show, sky, rays, sectors, cache, saveData, azimuth, elevation,
    zoom, up, spacing, heightScale, maximumGrid, background, environment, environmentAzimuth,
    environmentExposure, crease, maximumEdge;
  std::vector<std::string> suns, sphereLights;
  bool interactive = false, help = false, version = false;

  using Arguments = vtksys::CommandLineArguments;
  Arguments arguments;
  arguments.Initialize(argc, argv);
  arguments.StoreUnusedArguments(true);
  const auto value = Arguments::SPACE_ARGUMENT;
  arguments.AddArgument("-o", value, &output, "");
  arguments.AddArgument("--output", value, &output, "");
  arguments.AddArgument("--size", value, &size, "");
  arguments.AddBooleanArgument("--interactive", &interactive, "");
  arguments.AddArgument("--mode", value, &mode, "");
  arguments.AddArgument("--show", value, &show, "");
  arguments.AddArgument("--sun", value, &suns, "");
  arguments.AddArgument("--sphere-light", value, &sphereLights, "");
  arguments.AddArgument("--sky", value, &sky, "");
  arguments.AddArgument("--env", value, &environment, "");
  arguments.AddArgument("--env-azimuth", value, &environmentAzimuth, "");
  arguments.AddArgument("--env-exposure", value, &environmentExposure, "");
  arguments.AddArgument("--rays", value, &rays, "");
  arguments.AddArgument("--sectors", value, &sectors, "");
  arguments.AddArgument("--crease", value, &crease, "");
  arguments.AddArgument("--max-edge", value, &maximumEdge, "");
  arguments.AddArgument("--cache", value, &cache, "");
  arguments.AddArgument("--save-data", value, &saveData, "");
  arguments.AddArgument("--azimuth", value, &azimuth, "");
  arguments.AddArgument("--elevation", value, &elevation, "");
  arguments.AddArgument("--zoom", value, &zoom, "");
  arguments.AddArgument("--up", value, &up, "");
  arguments.AddArgument("--spacing", value, &spacing, "");
  arguments.AddArgument("--height-scale", value, &heightScale, "");
  arguments.AddArgument("--max-grid", value, &maximumGrid, "");
  arguments.AddArgument("--background", value, &background, "");
  arguments.AddBooleanArgument("--help", &help, "");
  arguments.AddBooleanArgument("-h", &help, "");
  arguments.AddBooleanArgument("--version", &version, "");

  // An option that takes a value cannot be the last word.
  static const std::set<std::string> takesValue = { "-o", "--output", "--size", "--mode", "--show",
    "--sun", "--sphere-light", "--sky", "--env", "--env-azimuth", "--env-exposure", "--rays",
    "--sectors", "--crease", "--max-edge", "--cache", "--save-data", "--azimuth", "--elevation",
    "--zoom", "--up", "--spacing", "--height-scale", "--max-grid", "--background" };
  if (argc > 1 && takesValue.count(argv[argc - 1]))
  {
    error = std::string("option ") + argv[argc - 1] + " needs a value (see --help)";
    return 2;
  }
  if (!arguments.Parse())
  {
    error = "the command line could not be parsed (see --help)";
    return 2;
  }
  int unusedCount = 0;
  char** unused = nullptr;
  arguments.GetUnusedArguments(&unusedCount, &unused);
  std::vector<std::string> positional;
  for (int i = 1; i < unusedCount; ++i) // unused[0] is the program
  {
    positional.emplace_back(unused[i]);
  }
  arguments.DeleteRemainingArguments(unusedCount, &unused);

  options.Help = help;
  options.Version = version;
  if (help || version)
  {
    return 0;
  }
  for (const std::string& word : positional)
  {
    if (word.size() > 1 && word[0] == '-')
    {
      error = "unknown option " + vtkApertureText::Quote(word) + " (see --help)";
      return 2;
    }
  }
  if (positional.size() > 1)
  {
    error = "one input at a time, got " + vtkApertureText::QuoteName(positional[0]) + " and " +
      vtkApertureText::QuoteName(positional[1]);
    return 2;
  }
  options.Input = positional.empty() ? "" : positional[0];
  options.Output = output;
  options.Interactive = interactive;
  if (output.empty() && !interactive)
  {
    error = "say where the picture goes (-o picture.png) or ask for a window (--interactive)";
    return 2;
  }

  std::vector<double> numbers;
  if (!size.empty())
  {
    const size_t x = size.find('x');
    double w, h;
    if (x == std::string::npos || !ToNumber(size.substr(0, x), w) ||
      !ToNumber(size.substr(x + 1), h) || w != std::floor(w) || h != std::floor(h) || w < 16 ||
      h < 16 || w > 8192 || h > 8192)
    {
      error = "--size " + vtkApertureText::Quote(size) +
        " is not WIDTHxHEIGHT in pixels (16 to 8192 each)";
      return 2;
    }
    options.Width = static_cast<int>(w);
    options.Height = static_cast<int>(h);
  }
  if (mode == "all" && size.empty())
  {
    // A row of five panels.
    options.Width = 640;
    options.Height = 400;
  }
  if (!mode.empty())
  {
    bool known = mode == "all";
    for (const std::string& name : ModeNames())
    {
      known = known || mode == name;
    }
    if (!known)
    {
      error = "--mode " + vtkApertureText::Quote(mode) +
        " is not one of exact, smoothstep, simplified, bentnormal, standard, all";
      return 2;
    }
    options.Mode = mode;
  }
  if (!show.empty())
  {
    if (show != "shading" && show != "apertures")
    {
      error = "--show " + vtkApertureText::Quote(show) + " is not shading or apertures";
      return 2;
    }
    options.ShowApertures = show == "apertures";
  }
  for (const std::string& sun : suns)
  {
    if (sun == "none")
    {
      options.NoSun = true;
      continue;
    }
    if (!ToNumbers(sun, 2, 3, numbers) || numbers[1] < -90.0 || numbers[1] > 90.0 ||
      (numbers.size() == 3 && (numbers[2] < 0.0 || numbers[2] > 90.0)))
    {
      error = "--sun " + vtkApertureText::Quote(sun) +
        " is not AZIMUTH,ELEVATION[,ANGULAR_RADIUS] in degrees (elevation -90 to 90, radius 0 to "
        "90)";
      return 2;
    }
    options.Suns.push_back({ numbers[0], numbers[1], numbers.size() == 3 ? numbers[2] : 0.27 });
  }
  for (const std::string& light : sphereLights)
  {
    if (!ToNumbers(light, 4, 5, numbers) || numbers[3] <= 0.0 ||
      (numbers.size() == 5 && numbers[4] < 0.0))
    {
      error = "--sphere-light " + vtkApertureText::Quote(light) +
        " is not X,Y,Z,RADIUS[,INTENSITY] (radius > 0, intensity >= 0)";
      return 2;
    }
    options.SphereLights.push_back({ { numbers[0], numbers[1], numbers[2] }, numbers[3],
      numbers.size() == 5 ? numbers[4] : 1.0 });
  }
  if (!sky.empty())
  {
    if (!ToNumbers(sky, 3, 3, numbers) || numbers[0] < 0.0 || numbers[1] < 0.0 || numbers[2] < 0.0)
    {
      error = "--sky " + vtkApertureText::Quote(sky) + " is not R,G,B (each >= 0)";
      return 2;
    }
    std::copy(numbers.begin(), numbers.end(), options.Sky);
    options.SkyGiven = true;
  }
  if (!environment.empty())
  {
    const std::string extension =
      vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(environment));
    if (extension != ".exr")
    {
      error = "--env " + vtkApertureText::QuoteName(environment) + " is not an OpenEXR file (.exr)";
      return 2;
    }
    options.Environment = environment;
  }
  if ((!environmentAzimuth.empty() || !environmentExposure.empty()) && environment.empty())
  {
    error = std::string(environmentAzimuth.empty() ? "--env-exposure" : "--env-azimuth") +
      " applies to an environment: give one with --env";
    return 2;
  }
  if (!environmentExposure.empty() && environmentExposure != "auto" &&
    (!ToNumber(environmentExposure, options.EnvironmentExposure) ||
      std::abs(options.EnvironmentExposure) > 64.0))
  {
    error = "--env-exposure " + vtkApertureText::Quote(environmentExposure) +
      " is not 'auto' or a number of stops from -64 to 64";
    return 2;
  }
  if (!environmentAzimuth.empty())
  {
    if (!ToNumber(environmentAzimuth, options.EnvironmentAzimuth))
    {
      error = "--env-azimuth " + vtkApertureText::Quote(environmentAzimuth) +
        " is not a number of degrees";
      return 2;
    }
  }
  if (!background.empty())
  {
    if (!ToNumbers(background, 3, 3, numbers) || numbers[0] < 0.0 || numbers[1] < 0.0 ||
      numbers[2] < 0.0 || numbers[0] > 1.0 || numbers[1] > 1.0 || numbers[2] > 1.0)
    {
      error = "--background " + vtkApertureText::Quote(background) + " is not R,G,B (each 0 to 1)";
      return 2;
    }
    std::copy(numbers.begin(), numbers.end(), options.Background);
  }
  double number;
  if (!rays.empty())
  {
    if (!ToNumber(rays, number) || number != std::floor(number) || number < 1 || number > 65536)
    {
      error = "--rays " + vtkApertureText::Quote(rays) + " is not a whole number from 1 to 65536";
      return 2;
    }
    options.Rays = static_cast<int>(number);
    options.RaysGiven = true;
  }
  if (!sectors.empty())
  {
    if (!ToNumber(sectors, number) || number != std::floor(number) || number < 4 || number > 1024)
    {
      error =
        "--sectors " + vtkApertureText::Quote(sectors) + " is not a whole number from 4 to 1024";
      return 2;
    }
    options.Sectors = static_cast<int>(number);
  }
  if (!crease.empty() &&
    (!ToNumber(crease, options.Crease) || options.Crease < 0.0 || options.Crease > 180.0))
  {
    error = "--crease " + vtkApertureText::Quote(crease) + " is not an angle from 0 to 180 degrees";
    return 2;
  }
  if (!maximumEdge.empty() && maximumEdge != "auto")
  {
    if (maximumEdge == "none")
    {
      options.MaximumEdge = 0.0;
    }
    else if (!ToNumber(maximumEdge, options.MaximumEdge) || options.MaximumEdge <= 0.0)
    {
      error = "--max-edge " + vtkApertureText::Quote(maximumEdge) +
        " is not auto, none or a positive length";
      return 2;
    }
  }
  if (!maximumGrid.empty())
  {
    if (!ToNumber(maximumGrid, number) || number != std::floor(number) || number < 2 ||
      number > 16384)
    {
      error = "--max-grid " + vtkApertureText::Quote(maximumGrid) +
        " is not a whole number from 2 to 16384";
      return 2;
    }
    options.MaximumGrid = static_cast<int>(number);
  }
  if (!azimuth.empty() && !ToNumber(azimuth, options.CameraAzimuth))
  {
    error = "--azimuth " + vtkApertureText::Quote(azimuth) + " is not a number of degrees";
    return 2;
  }
  if (!elevation.empty() &&
    (!ToNumber(elevation, options.CameraElevation) || std::abs(options.CameraElevation) > 89.0))
  {
    error = "--elevation " + vtkApertureText::Quote(elevation) +
      " is not a number of degrees from -89 to 89";
    return 2;
  }
  if (!zoom.empty() && (!ToNumber(zoom, options.Zoom) || options.Zoom <= 0.0))
  {
    error = "--zoom " + vtkApertureText::Quote(zoom) + " is not a positive number";
    return 2;
  }
  if (!spacing.empty() && (!ToNumber(spacing, options.Spacing) || options.Spacing <= 0.0))
  {
    error = "--spacing " + vtkApertureText::Quote(spacing) + " is not a positive number of metres";
    return 2;
  }
  if (!heightScale.empty() &&
    (!ToNumber(heightScale, options.HeightScale) || options.HeightScale <= 0.0))
  {
    error = "--height-scale " + vtkApertureText::Quote(heightScale) + " is not a positive number";
    return 2;
  }
  if (!up.empty())
  {
    static const std::set<std::string> axes = { "+x", "-x", "+y", "-y", "+z", "-z", "x", "y", "z" };
    if (!axes.count(up))
    {
      error = "--up " + vtkApertureText::Quote(up) + " is not one of +x, -x, +y, -y, +z, -z";
      return 2;
    }
    options.Up = up.size() == 1 ? "+" + up : up;
  }
  if (options.HeightScale == 0.0)
  {
    options.HeightScale = options.Input.empty() ? 1.5 : 1.0;
  }
  options.Cache = cache;
  options.SaveData = saveData;
  return 0;
}

std::string HelpText()
{
  return R"(aperture-render: soft shadows from area lights with ambient aperture lighting.

Usage: aperture-render [INPUT] (-o PICTURE.png | --interactive) [options]

Computes, for every point, the cap of sky it can see (vtkAperturePrecompute: Embree rays for
meshes, horizon sweeps for height fields), then renders the surface with
vtkApertureLightingMapper under suns, sphere lights and a sky.

INPUT (optional; without it, the embedded Mount Fuji tile: 512 x 512 samples 60 m apart,
heights x 1.5):
  meshes           .obj .ply .stl .vtp, and .vtk (VTK legacy: trusted files only, as VTK 9.1's
                   legacy reader can crash on a damaged one)
  height fields    .png: Terrain-RGB (height = -10000 + (R*65536 + G*256 + B) * 0.1 m) when it has
                   colour, else 8- or 16-bit grey heights; .tif/.tiff (GeoTIFF or grey),
                   .asc (ESRI ASCII grid), .img (ERDAS), .vrt (GDAL virtual raster): single-band
                   DEMs through GDAL, spacing from their georeferencing, no-data filled with
                   the lowest height for the picture (and neither occluding nor receiving);
                   .dem (USGS DEM); .hgt (SRTM, 1 or 3 arc-seconds)

Output:
  -o, --output FILE.png  write the picture
  --size WxH             picture size in pixels (default 1280x800; with --mode all, each panel)
  --interactive          open a window: drag to orbit; arrow keys move the sun; m switches the
                         shading mode; a shows the aperture radius as a colour map; [ and ]
                         shrink and grow the lights; s toggles the sky; e and E turn the
                         environment; h lists the keys
  --show apertures       colour the surface by its aperture radius (0: closed, pi/2: a whole
                         hemisphere of sky) instead of shading it (default: --show shading)
  --save-data FILE       write the data with its aperture arrays for ParaView: .vtp (the
                         surface) or, for height fields, .vti (the grid)

Lights and shading:
  --sun AZ,EL[,R]        a sun at compass azimuth AZ (0 north, 90 east) and elevation EL above
                         the horizon, angular radius R (default 0.27, the real sun), in degrees;
                         repeatable; --sun none: no sun (the sky or --env alone). Default
                         (unless --sphere-light or --env is given): one sun, for meshes over
                         the viewer's shoulder (45 deg to the left of the eye's azimuth, 30 deg
                         above the eye, so it follows --azimuth and --elevation); for height
                         fields low in the west-north-west (AZ 285, EL 16), the terrain
                         convention, lighting the default view from its left
  --sphere-light X,Y,Z,R[,I]
                         a sphere light of radius R at (X, Y, Z) in data coordinates, intensity I
                         (default 1: the light an unoccluded surface facing it receives);
                         repeatable
  --sky R,G,B            sky radiance filling the open part of each aperture (default
                         0.24,0.27,0.34; 0,0,0 for none); with --env, a factor on the
                         environment's radiance (default 1,1,1)
  --env FILE.exr         an HDR latitude-longitude environment (OpenEXR) as the sky: each point
                         sees the environment's radiance over its aperture; its top row is the
                         zenith along --up and its centre column looks north. Without --sun or
                         --sphere-light the environment is the only light
  --env-azimuth DEG      turn the environment clockwise about the up axis (default 0)
  --env-exposure STOPS   scale the environment's radiance by 2^STOPS, or auto (default): the
                         scale that shows an open, level surface at 80% white
  --mode MODE            exact (default), smoothstep, simplified, bentnormal, standard (plain VTK
                         lighting), or all: one picture with a panel per mode
  --rays N               rays per point for the apertures (default 256); height fields cast
                         rays only when --rays is given
  --sectors D            height fields: horizon sweeps in D azimuth sectors (default 32)
  --crease DEG           meshes: where faces meet at more than DEG degrees, each side gets its
                         own normal and aperture, as a CAD part's sharp edges need (default 60:
                         tessellated curves and scan noise stay smooth); 180 never splits
  --max-edge L           meshes: split triangles until no edge is longer than L (data units),
                         so that large faces get contact shadows; auto (default) does it when
                         faces are large against the scene (a box on a ground), none never
  --cache FILE           keep the apertures in FILE (.vtp for meshes, .vti for height fields):
                         the next run with the same input and --rays reads them instead of
                         casting rays; a cache made for other data is recomputed and replaced

View:
  --azimuth DEG          compass azimuth of the eye seen from the data (default: 200, from the
                         south-south-west, for height fields; for meshes, along the thinner
                         horizontal axis from the side the surface faces most; the run prints
                         the view it chose)
  --elevation DEG        elevation of the eye (default 28 for height fields, 15 for meshes)
  --zoom F               magnify by F (default 1)
  --up AXIS              the data's up axis: +x -x +y -y +z -z (default +z for height fields;
                         for meshes, the axis opposite a flat base, else +y, the OBJ
                         convention); azimuths and elevations are measured around it
  --background R,G,B     background colour, 0 to 1 (default 0.09,0.1,0.12)

Height fields:
  --spacing METRES       ground distance between samples (default: from a .dem or .hgt file, 60
                         for the embedded tile, else 30)
  --height-scale F       vertical exaggeration (default 1; 1.5 for the embedded tile)
  --max-grid N           larger grids are drawn as a mesh of at most N x N samples (default
                         1024), shaded per texel from the apertures of the whole grid (with
                         --rays: the grid is resampled before the rays)

  -h, --help             this text
  --version              the version

Examples:
  aperture-render -o fuji.png
  aperture-render -o fuji-dawn.png --sun 95,6 --sky 0.25,0.2,0.3 --mode smoothstep
  aperture-render bunny.obj -o bunny.png --sphere-light 0.1,0.2,0.15,0.03,1.5 --sun 0,90
  aperture-render bunny.obj -o bunny-forest.png --env forest.exr --env-azimuth 90
  aperture-render N35E138.hgt --cache n35e138.vti --interactive
  aperture-render scan.ply --mode all --size 480x360 -o modes.png --save-data scan.vtp

Exit status: 0 on success, 1 when the input cannot be used or the picture cannot be made, 2 for
a malformed command line. Errors are one line on stderr.
)";
}
}
