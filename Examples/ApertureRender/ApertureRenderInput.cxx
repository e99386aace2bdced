/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderInput.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "ApertureRenderInput.h"
#include "ApertureRenderVolume.h"
#include "ApertureRenderVolumeFile.h"

#include "ApertureRenderFuji.h"
#include "ApertureRenderMesh.h"
#include "ApertureRenderMessages.h"
#include "ApertureRenderOptions.h"

#include "vtkApertureRefinement.h"
#include "vtkApertureSurface.h"
#include "vtkApertureText.h"
#include "vtkCellArray.h"
#include "vtkDEMReader.h"
#include "vtkFloatArray.h"
#include "vtkGDALDEMReader.h"
#include "vtkImageReader2.h"
#include "vtkImageResize.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOpenEXRReader.h"
#include "vtkPNGReader.h"
#include "vtkPNGValidator.h"
#include "vtkPointData.h"
#include "vtkTerrainRGBReader.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <regex>
#include <sstream>

namespace ApertureRender
{
namespace
{
// Metres per arc-second of latitude.
constexpr double MetresPerArcSecond = 30.87;

// The edge length a mesh is refined to: --max-edge, or automatically 1/64 of the scene's
// diagonal when its longest edge is more than 1/16 of it, coarser if that would make more than
// a million triangles.
void ChooseMaximumEdge(const Options& options, Input& input)
{
  if (!std::isnan(options.MaximumEdge))
  {
    input.MaximumEdge = options.MaximumEdge;
    return;
  }
  double bounds[6];
  vtkApertureSurface::InitializeBounds(bounds);
  vtkApertureSurface::ExpandBounds(input.Mesh, bounds);
  const double diagonal = std::sqrt(std::pow(bounds[1] - bounds[0], 2) +
    std::pow(bounds[3] - bounds[2], 2) + std::pow(bounds[5] - bounds[4], 2));
  if (!(vtkApertureRefinement::LongestEdge(input.Mesh) > diagonal / 16.0))
  {
    return;
  }
  // Each triangle becomes about (its longest edge / L)^2 triangles.
  double squares = 0.0;
  std::vector<vtkIdType> local;
  for (vtkCellArray* cells : { input.Mesh->GetPolys(), input.Mesh->GetStrips() })
  {
    vtkIdType npts;
    const vtkIdType* ids;
    for (cells->InitTraversal(); cells->GetNextCell(npts, ids);)
    {
      double longest = 0.0;
      for (vtkIdType k = 0; k < npts; ++k)
      {
        double a[3], b[3];
        input.Mesh->GetPoint(ids[k], a);
        input.Mesh->GetPoint(ids[(k + 1) % npts], b);
        const double d = std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
        longest = std::isfinite(d) ? std::max(longest, d) : longest;
      }
      squares += longest * longest * std::max<vtkIdType>(1, npts - 2);
    }
  }
  input.MaximumEdge = std::max(diagonal / 64.0, std::sqrt(squares / 1e6));
  std::ostringstream note;
  note << "faces are large against the scene: refined to edges of at most " << input.MaximumEdge
       << " for contact shadows (--max-edge)";
  input.Notes.push_back(note.str());
}

// A USGS DEM's type A record as vtkDEMReader reads it: the grid's columns and rows (as
// vtkDEMReader::ComputeExtentOriginAndSpacing finds them from the corners SW, NW, NE, SE and the
// resolution) and the number of profiles; false when the record is incomplete or invalid.
bool ReadDEMHeader(FILE* file, double& columns, double& rows, int& profiles)
{
  char record[1025] = { 0 };
  const bool header = std::fread(record, 1, 1024, file) == 1024;
  for (char& c : record)
  {
    c = c == 'D' ? 'E' : c; // Fortran exponents
  }
  int planeUnit = 0, elevationUnit = 0, counts[2] = { 0, 0 };
  float corners[8] = { 0 }, resolution[3] = { 0 };
  const bool fields = header &&
    std::sscanf(record + 528, "%6d%6d", &planeUnit, &elevationUnit) == 2 &&
    std::sscanf(record + 546, "%24g%24g%24g%24g%24g%24g%24g%24g", corners, corners + 1, corners + 2,
      corners + 3, corners + 4, corners + 5, corners + 6, corners + 7) == 8;
  char buffer[13] = { 0 };
  for (int k = 0; fields && k < 3; ++k)
  {
    std::copy(record + 816 + 12 * k, record + 828 + 12 * k, buffer);
    std::sscanf(buffer, "%12g", resolution + k);
  }
  if (!fields || std::sscanf(record + 852, "%6d%6d", counts, counts + 1) != 2 ||
    !(resolution[0] > 0.0f) || !(resolution[1] > 0.0f) || !std::isfinite(resolution[0]) ||
    !std::isfinite(resolution[1]))
  {
    return false;
  }
  const float east = std::max(corners[4], corners[6]), west = std::min(corners[2], corners[0]);
  const float north = std::max(corners[5], corners[3]), south = std::min(corners[1], corners[7]);
  columns = std::floor((east - west) / resolution[0] + 1.0);
  rows = std::floor((north - south) / resolution[1] + 1.0);
  profiles = counts[1];
  return true;
}

// The profiles after the header: each inside the grid and complete; "" or what is wrong.
std::string CheckDEMProfiles(FILE* file, double columns, double rows, int profiles)
{
  std::fseek(file, 1024, SEEK_SET);
  for (int column = 0; column < profiles; ++column)
  {
    int id[2], size[2];
    char header[121];
    if (std::fscanf(file, "%6d%6d%6d%6d", id, id + 1, size, size + 1) == EOF)
    {
      break;
    }
    if (std::fscanf(file, "%120c", header) != 1)
    {
      return " is truncated (a profile header is cut off)";
    }
    const double row = id[0] - 1.0, col = id[1] - 1.0, last = row + size[0] - 1.0;
    if (col < 0 || col >= columns || row < 0 || last >= rows)
    {
      return " is damaged (a profile lies outside the grid its header declares)";
    }
    int value;
    for (int k = 0; k < size[0]; ++k)
    {
      if (std::fscanf(file, "%6d", &value) != 1)
      {
        return " is truncated (a profile ends early)";
      }
    }
  }
  return "";
}

// Checks a USGS DEM the way vtkDEMReader reads it, which would divide by zero on a grid
// narrower than 100 columns and write outside its image for profiles that do not fit.
bool CheckDEM(const std::string& name, std::string& error)
{
  FILE* file = vtksys::SystemTools::Fopen(name, "rb");
  if (!file)
  {
    error = vtkApertureText::QuoteName(name) + " cannot be read";
    return false;
  }
  double columns = 0.0, rows = 0.0;
  int profiles = 0;
  std::string problem;
  if (!ReadDEMHeader(file, columns, rows, profiles))
  {
    problem = " is not a USGS DEM (its type A record is incomplete or invalid)";
  }
  else if (!(columns >= 100 && rows >= 2 && columns * rows <= double(1 << 28)))
  {
    std::ostringstream what;
    what << " is a DEM of " << columns << " x " << rows
         << " samples; VTK's DEM reader needs 100 to 16384 columns and 2 or more rows";
    problem = what.str();
  }
  else
  {
    problem = CheckDEMProfiles(file, columns, rows, profiles);
  }
  std::fclose(file);
  error = problem.empty() ? "" : vtkApertureText::QuoteName(name) + problem;
  return problem.empty();
}

// Extensions read as single-band DEMs through GDAL.
bool IsGDALRaster(const std::string& extension)
{
  return extension == ".tif" || extension == ".tiff" || extension == ".asc" ||
    extension == ".img" || extension == ".vrt";
}

// The heights of an image's first scalar component as a float Elevation array, on a copy of
// its grid.
vtkSmartPointer<vtkImageData> AsHeights(vtkImageData* image)
{
  auto heights = vtkSmartPointer<vtkImageData>::New();
  heights->CopyStructure(image);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  vtkNew<vtkFloatArray> elevation;
  elevation->SetName("Elevation");
  elevation->SetNumberOfTuples(scalars->GetNumberOfTuples());
  for (vtkIdType i = 0; i < scalars->GetNumberOfTuples(); ++i)
  {
    elevation->SetValue(i, static_cast<float>(scalars->GetComponent(i, 0)));
  }
  heights->GetPointData()->SetScalars(elevation);
  return heights;
}

// A PNG's heights: Terrain-RGB when it has colour, else grey heights `spacing` apart.
vtkSmartPointer<vtkImageData> ReadPNGHeights(
  const std::string& name, double spacing, std::string& kind, std::string& error)
{
  error = vtkPNGValidator::CheckFile(name.c_str());
  if (!error.empty())
  {
    return nullptr;
  }
  vtkNew<vtkPNGReader> png;
  png->SetFileName(name.c_str());
  png->UpdateInformation();
  if (png->GetNumberOfScalarComponents() >= 3 && png->GetDataScalarType() == VTK_UNSIGNED_CHAR)
  {
    vtkNew<vtkTerrainRGBReader> terrain;
    terrain->SetFileName(name.c_str());
    terrain->SetSpacing(spacing, spacing);
    terrain->Update();
    kind = "Terrain-RGB";
    return terrain->GetOutput();
  }
  png->Update();
  kind = png->GetDataScalarType() == VTK_UNSIGNED_SHORT ? "16-bit grey" : "8-bit grey";
  vtkSmartPointer<vtkImageData> image = AsHeights(png->GetOutput());
  image->SetSpacing(spacing, spacing, 1.0);
  return image;
}

// A single-band raster through GDAL, spaced by its georeferencing unless --spacing is given.
vtkSmartPointer<vtkImageData> ReadGDALHeights(const std::string& name, const std::string& extension,
  const Options& options, MessageCapture& messages, Input& input, std::string& kind,
  std::string& error)
{
  vtkNew<vtkGDALDEMReader> raster;
  raster->SetFileName(name.c_str());
  raster->Update();
  if (!messages.FirstError().empty())
  {
    error = "cannot read " + vtkApertureText::QuoteName(name) + ": " + messages.FirstError();
    return nullptr;
  }
  vtkSmartPointer<vtkImageData> image = raster->GetOutput();
  const bool georeferenced = raster->GetGeoreferenced();
  if (options.Spacing > 0.0 || !georeferenced)
  {
    const double spacing = options.Spacing > 0.0 ? options.Spacing : 30.0;
    image->SetSpacing(spacing, spacing, 1.0);
  }
  else
  {
    input.Notes.push_back(std::string("ground spacing: ") + raster->GetGroundSpacingNote());
  }
  const bool tiff = extension == ".tif" || extension == ".tiff";
  kind = tiff ? (georeferenced ? "GeoTIFF" : "TIFF") : "GDAL raster (" + extension + ")";
  return image;
}

// A USGS DEM, checked before VTK's reader reads it.
vtkSmartPointer<vtkImageData> ReadUSGSHeights(
  const std::string& name, const Options& options, std::string& kind, std::string& error)
{
  if (!CheckDEM(name, error))
  {
    return nullptr;
  }
  vtkNew<vtkDEMReader> dem;
  dem->SetFileName(name.c_str());
  dem->SetElevationReferenceToSeaLevel();
  dem->Update();
  vtkSmartPointer<vtkImageData> image = AsHeights(dem->GetOutput());
  if (options.Spacing > 0.0)
  {
    image->SetSpacing(options.Spacing, options.Spacing, 1.0);
  }
  kind = "USGS DEM";
  return image;
}

// An SRTM tile's spacing: samples 3600/(N-1) arc-seconds apart, east-west shrinking with the
// latitude its name gives (N35E138.hgt: 35 to 36 degrees north); --spacing overrides both.
void SetSRTMSpacing(
  vtkImageData* image, const std::string& name, int side, const Options& options, Input& input)
{
  const double arcSeconds = 3600.0 / (side - 1);
  double latitude = 0.0;
  std::smatch match;
  const std::string base = vtksys::SystemTools::GetFilenameName(name);
  if (std::regex_search(base, match, std::regex("^([NSns])([0-9]{1,2})[EWew][0-9]{1,3}")))
  {
    latitude = std::stod(match[2]) + 0.5;
    latitude = (match[1] == "S" || match[1] == "s") ? -latitude : latitude;
  }
  else
  {
    input.Notes.push_back("the tile's name gives no latitude: east-west spacing as at the equator");
  }
  const double dy = options.Spacing > 0.0 ? options.Spacing : arcSeconds * MetresPerArcSecond;
  const double dx =
    options.Spacing > 0.0 ? options.Spacing : dy * std::cos(latitude * 3.141592653589793 / 180.0);
  image->SetSpacing(dx, dy, 1.0);
}

// SRTM: N x N big-endian 16-bit heights, north row first, -32768 where there is no data.
vtkSmartPointer<vtkImageData> ReadSRTMHeights(const std::string& name, const Options& options,
  MessageCapture& messages, Input& input, std::string& kind, std::string& error)
{
  const unsigned long bytes = vtksys::SystemTools::FileLength(name);
  const auto side = static_cast<int>(std::lround(std::sqrt(bytes / 2.0)));
  if (side < 2 || 2ul * side * side != bytes)
  {
    error = vtkApertureText::QuoteName(name) + " is not an SRTM tile: its " +
      std::to_string(bytes) + " bytes are not N x N 16-bit samples";
    return nullptr;
  }
  vtkNew<vtkImageReader2> raw;
  raw->SetFileName(name.c_str());
  raw->SetFileDimensionality(2);
  raw->SetDataScalarTypeToShort();
  raw->SetDataByteOrderToBigEndian();
  raw->SetNumberOfScalarComponents(1);
  raw->SetDataExtent(0, side - 1, 0, side - 1, 0, 0);
  raw->FileLowerLeftOff();
  raw->Update();
  if (!messages.FirstError().empty())
  {
    error = "cannot read " + vtkApertureText::QuoteName(name) + ": " + messages.FirstError();
    return nullptr;
  }
  vtkSmartPointer<vtkImageData> image = AsHeights(raw->GetOutput());
  SetSRTMSpacing(image, name, side, options, input);
  kind = "SRTM";
  return image;
}

bool LoadHeightField(const std::string& name, const std::string& extension, const Options& options,
  MessageCapture& messages, Input& input, std::string& error)
{
  std::string kind;
  error.clear();
  messages.Clear();
  vtkSmartPointer<vtkImageData> image;
  if (extension == ".png")
  {
    image = ReadPNGHeights(name, options.Spacing > 0.0 ? options.Spacing : 30.0, kind, error);
  }
  else if (IsGDALRaster(extension))
  {
    image = ReadGDALHeights(name, extension, options, messages, input, kind, error);
  }
  else if (extension == ".dem")
  {
    image = ReadUSGSHeights(name, options, kind, error);
  }
  else // .hgt
  {
    image = ReadSRTMHeights(name, options, messages, input, kind, error);
  }
  if (!error.empty())
  {
    return false;
  }
  if (!messages.FirstError().empty() || !image || image->GetNumberOfPoints() == 0)
  {
    error = "cannot read " + vtkApertureText::QuoteName(name) + ": " +
      messages.FirstErrorOr("no heights in it");
    return false;
  }
  input.Heights = image;
  std::ostringstream description;
  int dims[3];
  image->GetDimensions(dims);
  description << (name.empty() ? std::string("Mount Fuji")
                               : vtksys::SystemTools::GetFilenameName(name))
              << ": " << kind << " height field, " << dims[0] << " x " << dims[1] << " samples, "
              << image->GetSpacing()[0] << " m apart";
  input.Description = description.str();
  return true;
}

// SRTM voids (-32768) and non-finite heights become the lowest valid height.
void FillVoids(Input& input)
{
  auto* heights = vtkFloatArray::SafeDownCast(input.Heights->GetPointData()->GetScalars());
  float lowest = std::numeric_limits<float>::max();
  vtkIdType voids = 0;
  for (vtkIdType i = 0; i < heights->GetNumberOfTuples(); ++i)
  {
    const float h = heights->GetValue(i);
    if (std::isfinite(h) && h > -32767.0f)
    {
      lowest = std::min(lowest, h);
    }
  }
  for (vtkIdType i = 0; i < heights->GetNumberOfTuples(); ++i)
  {
    const float h = heights->GetValue(i);
    if (!std::isfinite(h) || h <= -32767.0f)
    {
      heights->SetValue(i, lowest == std::numeric_limits<float>::max() ? 0.0f : lowest);
      ++voids;
    }
  }
  if (voids > 0)
  {
    input.Notes.push_back(std::to_string(voids) + " samples without data set to the lowest height");
  }
}
}

//------------------------------------------------------------------------------
void Resample(Input& input, int maximum)
{
  int dims[3];
  input.Heights->GetDimensions(dims);
  if (std::max(dims[0], dims[1]) <= maximum)
  {
    return;
  }
  const double shrink = static_cast<double>(maximum) / std::max(dims[0], dims[1]);
  const int nx = std::max(2, static_cast<int>(std::lround(dims[0] * shrink)));
  const int ny = std::max(2, static_cast<int>(std::lround(dims[1] * shrink)));
  vtkNew<vtkImageResize> resize;
  resize->SetInputData(input.Heights);
  resize->SetOutputDimensions(nx, ny, 1);
  resize->Update();
  input.Heights = resize->GetOutput();
  input.Heights->GetPointData()->GetScalars()->SetName("Elevation");
  input.Notes.push_back("resampled from " + std::to_string(dims[0]) + " x " +
    std::to_string(dims[1]) + " to " + std::to_string(nx) + " x " + std::to_string(ny) +
    " samples (--max-grid)");
}

// A volume, its isosurface with --iso, or a height field for a 2D .vti.
bool LoadVolumeOrSurface(const std::string& name, const Options& options, MessageCapture& messages,
  Input& input, std::string& error)
{
  if (!LoadVolume(name, messages, input, error))
  {
    return false;
  }
  if (input.Heights)
  {
    FillVoids(input);
    return true;
  }
  if (std::isnan(options.Iso))
  {
    return true;
  }
  if (!ContourVolume(options, input, error))
  {
    return false;
  }
  ChooseMaximumEdge(options, input);
  return true;
}

bool LoadInput(const Options& options, MessageCapture& messages, Input& input, std::string& error)
{
  const std::string& name = options.Input;
  if (name.empty())
  {
    vtkNew<vtkTerrainRGBReader> fuji;
    fuji->SetMemoryBuffer(FujiTerrainRGB);
    fuji->SetMemoryBufferLength(static_cast<vtkIdType>(FujiTerrainRGBSize));
    const double spacing = options.Spacing > 0.0 ? options.Spacing : 60.0;
    fuji->SetSpacing(spacing, spacing);
    messages.Clear();
    fuji->Update();
    if (!messages.FirstError().empty())
    {
      error = "the embedded Mount Fuji tile cannot be read: " + messages.FirstError();
      return false;
    }
    input.Heights = fuji->GetOutput();
    std::ostringstream description;
    description << "Mount Fuji (embedded Terrain-RGB tile), 512 x 512 samples, " << spacing
                << " m apart";
    input.Description = description.str();
  }
  else
  {
    if (!vtksys::SystemTools::FileExists(name))
    {
      error = vtkApertureText::QuoteName(name) + " does not exist";
      return false;
    }
    if (vtksys::SystemTools::FileIsDirectory(name))
    {
      return LoadDICOM(name, messages, input, error);
    }
    if (vtksys::SystemTools::FileLength(name) == 0)
    {
      error = vtkApertureText::QuoteName(name) + " is empty";
      return false;
    }
    if (IsVolumeFile(name))
    {
      return LoadVolumeOrSurface(name, options, messages, input, error);
    }
    const std::string extension =
      vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(name));
    static const std::vector<std::string> meshes = { ".obj", ".ply", ".stl", ".vtp", ".vtk" };
    static const std::vector<std::string> fields = { ".png", ".tif", ".tiff", ".asc", ".img",
      ".vrt", ".dem", ".hgt" };
    if (std::find(meshes.begin(), meshes.end(), extension) != meshes.end())
    {
      if (!LoadMesh(name, extension, messages, input, error))
      {
        return false;
      }
      ChooseMaximumEdge(options, input);
      return true;
    }
    if (std::find(fields.begin(), fields.end(), extension) == fields.end())
    {
      error = vtkApertureText::QuoteName(name) + " has an unknown format" +
        (extension.empty() ? std::string() : " (" + extension + ")") +
        "; known: .obj .ply .stl .vtp .vtk .png .tif .tiff .asc .img .vrt .dem .hgt, volumes "
        ".vti .mha .mhd .nrrd .nhdr .nii .nii.gz";
      return false;
    }
    if (!LoadHeightField(name, extension, options, messages, input, error))
    {
      return false;
    }
  }
  FillVoids(input);
  return true;
}

bool LoadEnvironment(
  const Options& options, MessageCapture& messages, Input& input, std::string& error)
{
  const std::string& name = options.Environment;
  if (name.empty())
  {
    return true;
  }
  if (!vtksys::SystemTools::FileExists(name) || vtksys::SystemTools::FileIsDirectory(name))
  {
    error = "--env " + vtkApertureText::QuoteName(name) + " does not exist or is not a file";
    return false;
  }
  vtkNew<vtkOpenEXRReader> reader;
  reader->SetFileName(name.c_str());
  messages.Clear();
  reader->Update();
  if (!messages.FirstError().empty() || reader->GetOutput()->GetNumberOfPoints() == 0)
  {
    error = "--env " + vtkApertureText::QuoteName(name) + " cannot be used: " +
      (messages.FirstError().empty() ? std::string("it holds no pixels") : messages.FirstError());
    return false;
  }
  for (const std::string& warning : messages.Warnings())
  {
    input.Notes.push_back("--env " + vtkApertureText::QuoteName(name) + ": " + warning);
  }
  input.Environment = reader->GetOutput();
  int dims[3];
  input.Environment->GetDimensions(dims);
  if (dims[0] != 2 * dims[1])
  {
    std::ostringstream note;
    note << "--env " << vtkApertureText::QuoteName(name) << " is " << dims[0] << " x " << dims[1]
         << ", not 2:1; it is stretched over the sphere as a latitude-longitude map";
    input.Notes.push_back(note.str());
  }
  return true;
}
}
