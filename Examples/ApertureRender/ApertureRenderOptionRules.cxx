/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderOptionRules.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "ApertureRenderOptionRules.h"

#include "ApertureRenderOptions.h"

#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
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

// A whole number within [low, high].
bool ToWhole(const std::string& text, double low, double high, int& value)
{
  double number;
  if (!ToNumber(text, number) || number != std::floor(number) || number < low || number > high)
  {
    return false;
  }
  value = static_cast<int>(number);
  return true;
}

// A number within [low, high]; `open` excludes low itself.
bool ToRange(const std::string& text, double low, double high, bool open, double& value)
{
  double number;
  if (!ToNumber(text, number) || number < low || number > high || (open && number == low))
  {
    return false;
  }
  value = number;
  return true;
}

// R,G,B, each within [0, most].
bool ToColour(const std::string& text, double most, double rgb[3])
{
  std::vector<double> numbers;
  if (!ToNumbers(text, 3, 3, numbers) ||
    std::any_of(numbers.begin(), numbers.end(), [most](double c) { return c < 0.0 || c > most; }))
  {
    return false;
  }
  std::copy(numbers.begin(), numbers.end(), rgb);
  return true;
}

const double Huge = std::numeric_limits<double>::max();

std::vector<OptionRule> OutputRules()
{
  return {
    { "Output", { "-o", "--output" }, "FILE.png", "write the picture", "",
      [](const std::string& v, Options& o)
      {
        o.Output = v;
        return true;
      } },
    { "Output", { "--size" }, "WxH",
      "picture size in pixels (default 1280x800; with --mode all, each panel)",
      "is not WIDTHxHEIGHT in pixels (16 to 8192 each)",
      [](const std::string& v, Options& o)
      {
        const size_t x = v.find('x');
        return x != std::string::npos && ToWhole(v.substr(0, x), 16, 8192, o.Width) &&
          ToWhole(v.substr(x + 1), 16, 8192, o.Height);
      } },
    { "Output", { "--interactive" }, "",
      "open a window: drag to orbit; arrow keys move the sun; m switches the shading mode; a "
      "shows the aperture radius as a colour map; [ and ] shrink and grow the lights; s toggles "
      "the sky; e and E turn the environment; h lists the keys",
      "",
      [](const std::string&, Options& o)
      {
        o.Interactive = true;
        return true;
      } },
    { "Output", { "--show" }, "apertures",
      "colour the surface by its aperture radius (0: closed, pi/2: a whole hemisphere of sky) "
      "instead of shading it (default: --show shading)",
      "is not shading or apertures",
      [](const std::string& v, Options& o)
      {
        o.ShowApertures = v == "apertures";
        return v == "shading" || v == "apertures";
      } },
    { "Output", { "--save-data" }, "FILE",
      "write the data with its aperture arrays for ParaView: .vtp (the surface) or, for height "
      "fields, .vti (the grid)",
      "",
      [](const std::string& v, Options& o)
      {
        o.SaveData = v;
        return true;
      } },
  };
}

std::vector<OptionRule> SunRules()
{
  return {
    { "Lights and shading", { "--sun" }, "AZ,EL[,R]",
      "a sun at compass azimuth AZ (0 north, 90 east) and elevation EL above the horizon, "
      "angular radius R (default 0.27, the real sun), in degrees; repeatable; --sun none: no sun "
      "(the sky or --env alone). Default (unless --sphere-light or --env is given): one sun, for "
      "meshes over the viewer's shoulder (45 deg to the left of the eye's azimuth, 30 deg above "
      "the eye, so it follows --azimuth and --elevation); for height fields low in the "
      "west-north-west (AZ 285, EL 16), the terrain convention, lighting the default view from "
      "its left",
      "is not AZIMUTH,ELEVATION[,ANGULAR_RADIUS] in degrees (elevation -90 to 90, radius 0 to 90)",
      [](const std::string& v, Options& o)
      {
        std::vector<double> n;
        if (v == "none")
        {
          o.NoSun = true;
          return true;
        }
        if (!ToNumbers(v, 2, 3, n) || std::abs(n[1]) > 90.0 ||
          (n.size() == 3 && (n[2] < 0.0 || n[2] > 90.0)))
        {
          return false;
        }
        o.Suns.push_back({ n[0], n[1], n.size() == 3 ? n[2] : 0.27 });
        return true;
      } },
    { "Lights and shading", { "--sphere-light" }, "X,Y,Z,R[,I]",
      "a sphere light of radius R at (X, Y, Z) in data coordinates, intensity I (default 1: the "
      "light an unoccluded surface facing it receives); repeatable",
      "is not X,Y,Z,RADIUS[,INTENSITY] (radius > 0, intensity >= 0)",
      [](const std::string& v, Options& o)
      {
        std::vector<double> n;
        if (!ToNumbers(v, 4, 5, n) || n[3] <= 0.0 || (n.size() == 5 && n[4] < 0.0))
        {
          return false;
        }
        o.SphereLights.push_back({ { n[0], n[1], n[2] }, n[3], n.size() == 5 ? n[4] : 1.0 });
        return true;
      } },
  };
}

std::vector<OptionRule> SkyRules()
{
  return {
    { "Lights and shading", { "--sky" }, "R,G,B",
      "sky radiance filling the open part of each aperture (default 0.24,0.27,0.34; 0,0,0 for "
      "none); with --env, a factor on the environment's radiance (default 1,1,1)",
      "is not R,G,B (each >= 0)",
      [](const std::string& v, Options& o) { return o.SkyGiven = ToColour(v, Huge, o.Sky); } },
    { "Lights and shading", { "--env" }, "FILE.exr",
      "an HDR latitude-longitude environment (OpenEXR) as the sky: each point sees the "
      "environment's radiance over its aperture; its top row is the zenith along --up and its "
      "centre column looks north. Without --sun or --sphere-light the environment is the only "
      "light",
      "is not an OpenEXR file (.exr)",
      [](const std::string& v, Options& o)
      {
        o.Environment = v;
        return vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(v)) ==
          ".exr";
      } },
    { "Lights and shading", { "--env-azimuth" }, "DEG",
      "turn the environment clockwise about the up axis (default 0)", "is not a number of degrees",
      [](const std::string& v, Options& o) { return ToNumber(v, o.EnvironmentAzimuth); } },
    { "Lights and shading", { "--env-exposure" }, "STOPS",
      "scale the environment's radiance by 2^STOPS, or auto (default): the scale that shows an "
      "open, level surface at 80% white",
      "is not 'auto' or a number of stops from -64 to 64",
      [](const std::string& v, Options& o)
      {
        o.EnvironmentExposure = std::numeric_limits<double>::quiet_NaN();
        return v == "auto" || ToRange(v, -64.0, 64.0, false, o.EnvironmentExposure);
      } },
    { "Lights and shading", { "--mode" }, "MODE",
      "exact (default), smoothstep, simplified, bentnormal, standard (plain VTK lighting), "
      "horizon (height fields: lights and sky above each texel's horizon in every sector, right "
      "where one cap is wrong under a low sun), mask (meshes: lights and sky through each "
      "point's visibility mask, right where one cap is wrong under a small light), or all: one "
      "picture with a panel per mode",
      "is not one of exact, smoothstep, simplified, bentnormal, standard, horizon, mask, all",
      [](const std::string& v, Options& o)
      {
        const std::vector<std::string>& names = ModeNames();
        o.Mode = v;
        return v == "all" || std::find(names.begin(), names.end(), v) != names.end();
      } },
  };
}

std::vector<OptionRule> ApertureRules()
{
  return {
    { "Apertures", { "--rays" }, "N",
      "rays per point for the apertures (default 256); height fields cast rays only when --rays "
      "is given",
      "is not a whole number from 1 to 65536",
      [](const std::string& v, Options& o) { return o.RaysGiven = ToWhole(v, 1, 65536, o.Rays); } },
    { "Apertures", { "--sectors" }, "D",
      "height fields: horizon sweeps in D azimuth sectors (default 32)",
      "is not a whole number from 4 to 1024",
      [](const std::string& v, Options& o) { return ToWhole(v, 4, 1024, o.Sectors); } },
    { "Apertures", { "--crease" }, "DEG",
      "meshes: where faces meet at more than DEG degrees, each side gets its own normal and "
      "aperture, as a CAD part's sharp edges need (default 60: tessellated curves and scan noise "
      "stay smooth); 180 never splits",
      "is not an angle from 0 to 180 degrees",
      [](const std::string& v, Options& o) { return ToRange(v, 0.0, 180.0, false, o.Crease); } },
    { "Apertures", { "--max-edge" }, "L",
      "meshes: split triangles until no edge is longer than L (data units), so that large faces "
      "get contact shadows; auto (default) does it when faces are large against the scene (a box "
      "on a ground), none never",
      "is not auto, none or a positive length",
      [](const std::string& v, Options& o)
      {
        o.MaximumEdge = v == "none" ? 0.0 : std::numeric_limits<double>::quiet_NaN();
        return v == "auto" || v == "none" || ToRange(v, 0.0, Huge, true, o.MaximumEdge);
      } },
    { "Apertures", { "--cache" }, "FILE",
      "keep the apertures in FILE (.vtp for meshes, .vti for height fields): the next run with the "
      "same input and --rays reads them instead of casting rays; a cache made for other data is "
      "recomputed and replaced",
      "",
      [](const std::string& v, Options& o)
      {
        o.Cache = v;
        return true;
      } },
  };
}

std::vector<OptionRule> ViewRules()
{
  return {
    { "View", { "--azimuth" }, "DEG",
      "compass azimuth of the eye seen from the data (default: 200, from the south-south-west, "
      "for height fields; for meshes, along the thinner horizontal axis from the side the surface "
      "faces most; the run prints the view it chose)",
      "is not a number of degrees",
      [](const std::string& v, Options& o) { return ToNumber(v, o.CameraAzimuth); } },
    { "View", { "--elevation" }, "DEG",
      "elevation of the eye (default 28 for height fields, 15 for meshes)",
      "is not a number of degrees from -89 to 89",
      [](const std::string& v, Options& o)
      { return ToRange(v, -89.0, 89.0, false, o.CameraElevation); } },
    { "View", { "--zoom" }, "F", "magnify by F (default 1)", "is not a positive number",
      [](const std::string& v, Options& o) { return ToRange(v, 0.0, Huge, true, o.Zoom); } },
    { "View", { "--up" }, "AXIS",
      "the data's up axis: +x -x +y -y +z -z (default +z for height fields; for meshes, the axis "
      "opposite a flat base, else +y, the OBJ convention); azimuths and elevations are measured "
      "around it",
      "is not one of +x, -x, +y, -y, +z, -z",
      [](const std::string& v, Options& o)
      {
        o.Up = v.size() == 1 ? "+" + v : v;
        return o.Up.size() == 2 && (o.Up[0] == '+' || o.Up[0] == '-') && o.Up[1] >= 'x' &&
          o.Up[1] <= 'z';
      } },
    { "View", { "--background" }, "R,G,B", "background colour, 0 to 1 (default 0.09,0.1,0.12)",
      "is not R,G,B (each 0 to 1)",
      [](const std::string& v, Options& o) { return ToColour(v, 1.0, o.Background); } },
  };
}

std::vector<OptionRule> FieldRules()
{
  return {
    { "Height fields", { "--spacing" }, "METRES",
      "ground distance between samples (default: from a .dem or .hgt file, 60 for the embedded "
      "tile, else 30)",
      "is not a positive number of metres",
      [](const std::string& v, Options& o) { return ToRange(v, 0.0, Huge, true, o.Spacing); } },
    { "Height fields", { "--height-scale" }, "F",
      "vertical exaggeration (default 1; 1.5 for the embedded tile)", "is not a positive number",
      [](const std::string& v, Options& o) { return ToRange(v, 0.0, Huge, true, o.HeightScale); } },
    { "Height fields", { "--max-grid" }, "N",
      "larger grids are drawn as a mesh of at most N x N samples (default 1024), shaded per texel "
      "from the apertures of the whole grid (with --rays: the grid is resampled before the rays)",
      "is not a whole number from 2 to 16384",
      [](const std::string& v, Options& o) { return ToWhole(v, 2, 16384, o.MaximumGrid); } },
    { "Volumes", { "--volume" }, "PRESET",
      "how a CT or MR volume (.vti, .mha, .mhd, .nrrd, .nhdr, .nii, .nii.gz) is seen: ct-bone, "
      "ct-skin (Hounsfield units), mr (from the scalar range), or an opacity ramp LOW:HIGH (0 at "
      "LOW, opaque at HIGH); default ct-skin for data that holds air at -1000, else mr. Volumes "
      "take --mode exact (default), smoothstep, standard (VTK's own shading) or all",
      "is not ct-bone, ct-skin, mr or LOW:HIGH",
      [](const std::string& v, Options& o)
      {
        double low = 0.0, high = 0.0;
        o.VolumePreset = v;
        return v == "ct-bone" || v == "ct-skin" || v == "mr" ||
          (std::sscanf(v.c_str(), "%lf:%lf", &low, &high) == 2 && high > low);
      } },
    { "Volumes", { "--iso" }, "VALUE",
      "draw the volume's isosurface at VALUE as a mesh instead (apertures by rays, every mesh "
      "mode)",
      "is not a number", [](const std::string& v, Options& o) { return ToNumber(v, o.Iso); } },
    { "", { "-h", "--help" }, "", "this text", "",
      [](const std::string&, Options& o)
      {
        o.Help = true;
        return true;
      } },
    { "", { "--version" }, "", "the version", "",
      [](const std::string&, Options& o)
      {
        o.Version = true;
        return true;
      } },
  };
}
}

const std::vector<OptionRule>& OptionRules()
{
  static const std::vector<OptionRule> rules = []
  {
    std::vector<OptionRule> all;
    for (auto part : { OutputRules, SunRules, SkyRules, ApertureRules, ViewRules, FieldRules })
    {
      const std::vector<OptionRule> some = part();
      all.insert(all.end(), some.begin(), some.end());
    }
    return all;
  }();
  return rules;
}

std::string OptionHelpIntroduction()
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
)";
}

std::string OptionHelpExamples()
{
  return R"(
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
