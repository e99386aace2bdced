/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkGDALDEMReader.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkGDALDEMReader.h"

#include "vtkApertureText.h"
#include "vtkApertureValidMask.h"
#include "vtkGDALSession.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#include <gdal.h>
#include <ogr_srs_api.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

vtkStandardNewMacro(vtkGDALDEMReader);

namespace
{
constexpr double Pi = 3.14159265358979323846;
constexpr double DegreesToRadians = Pi / 180.0;

// Metres per degree of longitude and of latitude at latitude phi (degrees) on an ellipsoid.
void MetresPerDegree(double semiMajor, double inverseFlattening, double phi, double metres[2])
{
  const double f = inverseFlattening > 0.0 ? 1.0 / inverseFlattening : 0.0;
  const double e2 = f * (2.0 - f);
  const double s = std::sin(phi * DegreesToRadians);
  const double w = 1.0 - e2 * s * s;
  metres[0] = DegreesToRadians * semiMajor / std::sqrt(w) * std::cos(phi * DegreesToRadians);
  metres[1] = DegreesToRadians * semiMajor * (1.0 - e2) / (w * std::sqrt(w));
}

// Degrees in one unit of a geographic CRS's angles: 1, or 0.9 for grads (NTF Paris, the base of
// France's Lambert zones).
double DegreesPerAngularUnit(OGRSpatialReferenceH geographic)
{
  const double radians = OSRGetAngularUnits(geographic, nullptr);
  return radians > 0.0 ? radians / DegreesToRadians : 1.0;
}

// The ground distance, in metres, of one pixel along each axis at the tile's centre, for a
// projected CRS with a geographic base; false where it cannot be found.
bool GroundSpacing(
  OGRSpatialReferenceH srs, const double gt[6], const int size[2], double ground[2])
{
  const double cx = gt[0] + 0.5 * size[0] * gt[1], cy = gt[3] + 0.5 * size[1] * gt[5];
  double x[3] = { cx, cx + gt[1], cx }, y[3] = { cy, cy, cy + gt[5] };
  for (int k = 0; k < 3; ++k)
  {
    // No projection reaches past 1e8 m; PROJ can loop for ever on coordinates like 1e40.
    if (!(std::abs(x[k]) < 1e8 && std::abs(y[k]) < 1e8))
    {
      return false;
    }
  }
  OGRSpatialReferenceH geographic = OSRCloneGeogCS(srs);
  if (!geographic)
  {
    return false;
  }
  OSRSetAxisMappingStrategy(geographic, OAMS_TRADITIONAL_GIS_ORDER);
  OSRSetAxisMappingStrategy(srs, OAMS_TRADITIONAL_GIS_ORDER);
  OGRCoordinateTransformationH toGeographic = OCTNewCoordinateTransformation(srs, geographic);
  const bool ok = toGeographic && OCTTransform(toGeographic, 3, x, y, nullptr);
  if (ok)
  {
    OGRErr err = OGRERR_NONE;
    const double degrees = DegreesPerAngularUnit(geographic);
    double metres[2];
    MetresPerDegree(OSRGetSemiMajor(geographic, &err), OSRGetInvFlattening(geographic, &err),
      degrees * y[0], metres);
    for (int a = 0; a < 2; ++a)
    {
      const double east = degrees * (x[a + 1] - x[0]) * metres[0];
      const double north = degrees * (y[a + 1] - y[0]) * metres[1];
      ground[a] = std::sqrt(east * east + north * north);
    }
  }
  if (toGeographic)
  {
    OCTDestroyCoordinateTransformation(toGeographic);
  }
  OSRDestroySpatialReference(geographic);
  return ok && ground[0] > 0.0 && ground[1] > 0.0;
}

// Degrees counter-clockwise from the grid's north (+y) to true north at the tile's centre (the
// meridian convergence, with the sign of a rotation of the grid onto the meridians): a point a
// little north of the centre, through the CRS's geographic base and back. 0 where it cannot be
// found.
double Convergence(OGRSpatialReferenceH srs, const double gt[6], const int size[2])
{
  const double cx = gt[0] + 0.5 * size[0] * gt[1], cy = gt[3] + 0.5 * size[1] * gt[5];
  if (!(std::abs(cx) < 1e8 && std::abs(cy) < 1e8))
  {
    return 0.0;
  }
  OGRSpatialReferenceH geographic = OSRCloneGeogCS(srs);
  if (!geographic)
  {
    return 0.0;
  }
  OSRSetAxisMappingStrategy(geographic, OAMS_TRADITIONAL_GIS_ORDER);
  OSRSetAxisMappingStrategy(srs, OAMS_TRADITIONAL_GIS_ORDER);
  OGRCoordinateTransformationH to = OCTNewCoordinateTransformation(srs, geographic);
  OGRCoordinateTransformationH back = OCTNewCoordinateTransformation(geographic, srs);
  double x[2] = { cx, cx }, y[2] = { cy, cy };
  bool ok = to && back && OCTTransform(to, 1, x, y, nullptr);
  if (ok)
  {
    y[1] = y[0] + 1e-3 / DegreesPerAngularUnit(geographic); // a thousandth of a degree north
    x[1] = x[0];
    x[0] = cx;
    y[0] = cy;
    ok = OCTTransform(back, 1, x + 1, y + 1, nullptr);
  }
  for (auto* transform : { to, back })
  {
    if (transform)
    {
      OCTDestroyCoordinateTransformation(transform);
    }
  }
  OSRDestroySpatialReference(geographic);
  const double east = x[1] - cx, north = y[1] - cy;
  return ok && (east != 0.0 || north != 0.0) ? std::atan2(-east, north) / DegreesToRadians : 0.0;
}

vtkNew<vtkDoubleArray> Pair(const char* name, const double values[2])
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->SetNumberOfComponents(2);
  array->InsertNextTuple(values);
  return array;
}

vtkNew<vtkStringArray> Text(const char* name, const std::string& value)
{
  vtkNew<vtkStringArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  return array;
}

// The grid's spacing and origin in ground metres, how they were found, and what to say about it
// (sentences that follow the file's name).
struct Ground
{
  double Spacing[2] = { 1.0, 1.0 };
  double Origin[2] = { 0.0, 0.0 };
  double Convergence = 0.0;
  std::string Note, Warning, Error;
};

// A geographic CRS: metres at the tile's central latitude on the CRS's ellipsoid, from the
// geotransform in the CRS's angular units.
Ground GeographicGround(
  OGRSpatialReferenceH srs, const double gt[6], const int size[2], const double geoSpacing[2])
{
  Ground ground;
  const double degrees = DegreesPerAngularUnit(srs);
  const double north = degrees * std::max(gt[3], gt[3] + size[1] * gt[5]);
  const double south = degrees * std::min(gt[3], gt[3] + size[1] * gt[5]);
  const double centre = 0.5 * (north + south);
  OGRErr err = OGRERR_NONE;
  const double a = OSRGetSemiMajor(srs, &err), inverseFlattening = OSRGetInvFlattening(srs, &err);
  double metres[2], edge[2];
  MetresPerDegree(a, inverseFlattening, centre, metres);
  MetresPerDegree(a, inverseFlattening, std::abs(north) > std::abs(south) ? north : south, edge);
  for (int k = 0; k < 2; ++k)
  {
    ground.Spacing[k] = geoSpacing[k] * degrees * metres[k];
  }
  std::ostringstream text;
  text << "metres at the tile's central latitude " << centre << " degrees (geographic CRS)";
  ground.Note = text.str();
  if (!(std::max(std::abs(north), std::abs(south)) < 90.0 - 1e-9))
  {
    ground.Error =
      "reaches a pole, where degrees of longitude have no length; reproject it (gdalwarp)";
  }
  else if (edge[0] < 0.99 * metres[0])
  {
    text.str("");
    text << "spans latitudes " << south << " to " << north
         << " degrees: its east-west spacing varies by " << 100.0 * (1.0 - edge[0] / metres[0])
         << "% across it; reproject it for exact slopes.";
    ground.Warning = text.str();
  }
  return ground;
}

// A projected CRS (or none): its linear unit in metres, unless the ground distance at the tile's
// centre differs by more than 1% (Web Mercator's "metres" are sec(latitude) ground metres, and
// slopes need the ground's).
Ground ProjectedGround(OGRSpatialReferenceH srs, const double gt[6], const int size[2],
  const double geoSpacing[2], const double geoOrigin[2])
{
  Ground ground;
  const double unit = srs ? OSRGetLinearUnits(srs, nullptr) : 1.0;
  for (int k = 0; k < 2; ++k)
  {
    ground.Spacing[k] = geoSpacing[k] * unit;
    ground.Origin[k] = geoOrigin[k] * unit;
  }
  ground.Note = srs ? "metres from the projected CRS's pixel size"
                    : "pixel size of the file's geotransform (no CRS: taken as metres)";
  ground.Convergence = srs ? Convergence(srs, gt, size) : 0.0;
  double metres[2];
  if (srs && GroundSpacing(srs, gt, size, metres) &&
    (std::abs(metres[0] / ground.Spacing[0] - 1.0) > 0.01 ||
      std::abs(metres[1] / ground.Spacing[1] - 1.0) > 0.01))
  {
    std::ostringstream text;
    text << "ground metres at the tile's centre; the projected CRS's units are "
         << ground.Spacing[0] / metres[0] << " of them there";
    ground.Note = text.str();
    std::copy(metres, metres + 2, ground.Spacing);
  }
  return ground;
}
}

//------------------------------------------------------------------------------
// The open file and its band, closed on destruction.
class vtkGDALDEMReader::vtkRaster
{
public:
  vtkRaster(const std::string& name, std::string& error)
  {
    this->Dataset =
      GDALOpenEx(name.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr);
    if (!this->Dataset)
    {
      error = "cannot open " + vtkApertureText::QuoteName(name) +
        " as a raster: " + this->Session.LastError();
      return;
    }
    const int bands = GDALGetRasterCount(this->Dataset);
    if (bands != 1)
    {
      error = vtkApertureText::QuoteName(name) + " has " + std::to_string(bands) +
        " bands; a DEM has one";
      return;
    }
    this->Band = GDALGetRasterBand(this->Dataset, 1);
    if (GDALDataTypeIsComplex(GDALGetRasterDataType(this->Band)))
    {
      error = vtkApertureText::QuoteName(name) + " holds complex numbers, not heights";
      this->Band = nullptr;
    }
  }
  ~vtkRaster()
  {
    if (this->Dataset)
    {
      GDALClose(this->Dataset);
    }
  }
  vtkRaster(const vtkRaster&) = delete;
  vtkRaster& operator=(const vtkRaster&) = delete;

  vtkGDALSession Session;
  GDALDatasetH Dataset = nullptr;
  GDALRasterBandH Band = nullptr;
};

//------------------------------------------------------------------------------
vtkGDALDEMReader::vtkGDALDEMReader()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
bool vtkGDALDEMReader::CanReadFile(const char* fileName)
{
  vtkGDALSession session;
  GDALDatasetH dataset = fileName
    ? GDALOpenEx(fileName, GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr)
    : nullptr;
  if (dataset)
  {
    GDALClose(dataset);
  }
  return dataset != nullptr;
}

//------------------------------------------------------------------------------
int vtkGDALDEMReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  std::string error;
  vtkRaster raster(this->FileName, error);
  if (!raster.Band)
  {
    vtkErrorMacro(<< (error.empty() ? "Cannot read the DEM." : error));
    return 0;
  }
  this->Size[0] = GDALGetRasterXSize(raster.Dataset);
  this->Size[1] = GDALGetRasterYSize(raster.Dataset);
  if (this->Size[0] < 1 || this->Size[1] < 1)
  {
    vtkErrorMacro(<< vtkApertureText::QuoteName(this->FileName) << " has no texels.");
    return 0;
  }

  // Geotransform: x = gt0 + column gt1 + row gt2, y = gt3 + column gt4 + row gt5.
  // Without one GDAL gives (0, 1, 0, 0, 0, 1), south-up; an image's first row is its top.
  double gt[6];
  this->Georeferenced = GDALGetGeoTransform(raster.Dataset, gt) == CE_None;
  if (!this->Georeferenced)
  {
    const double image[6] = { 0.0, 1.0, 0.0, 0.0, 0.0, -1.0 };
    std::copy(image, image + 6, gt);
  }
  this->NorthUp = gt[5] < 0.0;
  if (gt[2] != 0.0 || gt[4] != 0.0 || !(gt[1] > 0.0) || gt[5] == 0.0)
  {
    vtkErrorMacro(<< vtkApertureText::QuoteName(this->FileName)
                  << " has a rotated, sheared or mirrored geotransform; warp it north-up "
                     "first (gdalwarp).");
    return 0;
  }
  const double nx = this->Size[0], ny = this->Size[1];
  this->GeoSpacing[0] = gt[1];
  this->GeoSpacing[1] = std::abs(gt[5]);
  this->GeoOrigin[0] = gt[0] + 0.5 * gt[1];
  this->GeoOrigin[1] = gt[5] < 0.0 ? gt[3] + (ny - 0.5) * gt[5] : gt[3] + 0.5 * gt[5];
  const char* wkt = GDALGetProjectionRef(raster.Dataset);
  this->SpatialReference = wkt ? wkt : "";
  if (!this->FindGroundSpacing(gt, error))
  {
    vtkErrorMacro(<< error);
    return 0;
  }

  vtkInformation* info = outputVector->GetInformationObject(0);
  const int extent[6] = { 0, this->Size[0] - 1, 0, this->Size[1] - 1, 0, 0 };
  const double spacing[3] = { this->Spacing[0], this->Spacing[1], 1.0 };
  const double origin[3] = { this->Origin[0], this->Origin[1], 0.0 };
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  info->Set(vtkDataObject::SPACING(), spacing, 3);
  info->Set(vtkDataObject::ORIGIN(), origin, 3);
  info->Set(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT(), 1);
  vtkDataObject::SetPointDataActiveScalarInfo(info, VTK_FLOAT, 1);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkGDALDEMReader::FindGroundSpacing(const double gt[6], std::string& error)
{
  OGRSpatialReferenceH srs = this->SpatialReference.empty() || !this->Georeferenced
    ? nullptr
    : OSRNewSpatialReference(this->SpatialReference.c_str());
  this->Geographic = srs && OSRIsGeographic(srs);
  Ground ground;
  if (!this->Georeferenced)
  {
    ground.Note = "no georeferencing: spacing 1";
    vtkWarningMacro(<< vtkApertureText::QuoteName(this->FileName)
                    << " is not georeferenced: spacing 1.");
  }
  else if (this->Geographic)
  {
    ground = GeographicGround(srs, gt, this->Size, this->GeoSpacing);
  }
  else
  {
    ground = ProjectedGround(srs, gt, this->Size, this->GeoSpacing, this->GeoOrigin);
  }
  if (srs)
  {
    OSRDestroySpatialReference(srs);
  }
  std::copy(ground.Spacing, ground.Spacing + 2, this->Spacing);
  std::copy(ground.Origin, ground.Origin + 2, this->Origin);
  this->GroundSpacingNote = ground.Note;
  this->GridConvergence = ground.Convergence;
  if (!ground.Warning.empty())
  {
    vtkWarningMacro(<< vtkApertureText::QuoteName(this->FileName) << " " << ground.Warning);
  }
  error = ground.Error.empty() ? std::string()
                               : vtkApertureText::QuoteName(this->FileName) + " " + ground.Error;
  for (const double spacing : this->Spacing)
  {
    if (error.empty() && !(spacing >= 1e-3 && spacing <= 1e6))
    {
      error = vtkApertureText::QuoteName(this->FileName) + " has a ground spacing of " +
        std::to_string(spacing) + " m, outside [1 mm, 1000 km]";
    }
  }
  return error.empty();
}

//------------------------------------------------------------------------------
int vtkGDALDEMReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* info = outputVector->GetInformationObject(0);
  vtkImageData* output = vtkImageData::GetData(info);
  int extent[6];
  info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
  output->SetExtent(extent);
  output->SetSpacing(this->Spacing[0], this->Spacing[1], 1.0);
  output->SetOrigin(this->Origin[0], this->Origin[1], 0.0);
  const vtkIdType nx = extent[1] - extent[0] + 1, ny = extent[3] - extent[2] + 1;
  if (nx < 1 || ny < 1)
  {
    return 1; // an empty piece
  }
  std::string error;
  vtkRaster raster(this->FileName, error);
  vtkNew<vtkFloatArray> heights;
  heights->SetName("Elevation");
  if (!raster.Band || !heights->Allocate(nx * ny))
  {
    vtkErrorMacro(<< (error.empty() ? "Cannot allocate " + std::to_string(nx * ny) + " texels."
                                    : error));
    output->Initialize();
    return 0;
  }
  heights->SetNumberOfTuples(nx * ny);
  if (!this->ReadRows(raster, extent, heights->GetPointer(0)))
  {
    output->Initialize();
    return 0;
  }
  output->GetPointData()->SetScalars(heights);
  if (!this->MaskNoData(raster, output))
  {
    vtkErrorMacro("Cannot allocate the no-data mask of " << nx * ny << " texels.");
    output->Initialize();
    return 0;
  }
  vtkFieldData* field = output->GetFieldData();
  field->AddArray(Pair("GeoOrigin", this->GeoOrigin));
  field->AddArray(Pair("GeoSpacing", this->GeoSpacing));
  field->AddArray(Text("SpatialReference", this->SpatialReference));
  field->AddArray(Text("GroundSpacing", this->GroundSpacingNote));
  return 1;
}

//------------------------------------------------------------------------------
// The extent's rows, southern first, in blocks with progress between them.
bool vtkGDALDEMReader::ReadRows(vtkRaster& raster, const int extent[6], float* heights)
{
  const bool northUp = this->NorthUp;
  const int nx = extent[1] - extent[0] + 1, ny = extent[3] - extent[2] + 1;
  const int rowsPerBlock = std::max(1, (1 << 22) / nx);
  this->UpdateProgress(0.0);
  for (int first = 0; first < ny; first += rowsPerBlock)
  {
    const int rows = std::min(rowsPerBlock, ny - first);
    // VTK rows first … first + rows - 1 of the extent; in the file, north-up files count down.
    const int j = extent[2] + first;
    const int fileRow = northUp ? this->Size[1] - 1 - (j + rows - 1) : j;
    float* block = heights + static_cast<vtkIdType>(first) * nx;
    // The blocks read leave GDAL's cache: the heights are in `block` now.
    if (GDALRasterIO(raster.Band, GF_Read, extent[0], fileRow, nx, rows, block, nx, rows,
          GDT_Float32, 0, 0) != CE_None ||
      GDALFlushRasterCache(raster.Band) != CE_None)
    {
      vtkErrorMacro("Cannot read " << vtkApertureText::QuoteName(this->FileName) << ": "
                                   << raster.Session.LastError());
      return false;
    }
    if (northUp)
    {
      for (int r = 0; r < rows / 2; ++r)
      {
        std::swap_ranges(block + static_cast<vtkIdType>(r) * nx,
          block + static_cast<vtkIdType>(r + 1) * nx,
          block + static_cast<vtkIdType>(rows - 1 - r) * nx);
      }
    }
    this->UpdateProgress(static_cast<double>(first + rows) / ny);
  }
  return true;
}

//------------------------------------------------------------------------------
// Scale and offset applied; no-data and non-finite texels NaN and masked. False when the mask
// cannot be allocated.
bool vtkGDALDEMReader::MaskNoData(vtkRaster& raster, vtkImageData* output)
{
  int hasNoData = 0, hasScale = 0, hasOffset = 0;
  const double noData = GDALGetRasterNoDataValue(raster.Band, &hasNoData);
  const double scale = GDALGetRasterScale(raster.Band, &hasScale) * this->VerticalScale;
  const double offset = GDALGetRasterOffset(raster.Band, &hasOffset) * this->VerticalScale;
  const float marker = static_cast<float>(noData);
  auto* heights = vtkFloatArray::SafeDownCast(output->GetPointData()->GetScalars());
  float* z = heights->GetPointer(0);
  const vtkIdType n = heights->GetNumberOfTuples();
  vtkNew<vtkUnsignedCharArray> mask;
  mask->SetName(vtkApertureValidMask::Name());
  if (!mask->Allocate(n))
  {
    return false;
  }
  mask->SetNumberOfTuples(n);
  unsigned char* valid = mask->GetPointer(0);
  vtkSMPTools::For(0, n,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType t = first; t < last; ++t)
      {
        const double value = z[t] * scale + offset;
        valid[t] = std::isfinite(value) && !(hasNoData && z[t] == marker);
        z[t] = valid[t] ? static_cast<float>(value) : std::numeric_limits<float>::quiet_NaN();
      }
    });
  if (std::find(valid, valid + n, 0) != valid + n)
  {
    output->GetPointData()->AddArray(mask);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkGDALDEMReader::ComputeHeightRange(double range[2])
{
  std::string error;
  vtkRaster raster(this->FileName, error);
  double minmax[2] = { 0.0, 0.0 };
  if (error.empty() && GDALComputeRasterMinMax(raster.Band, FALSE, minmax) == CE_None)
  {
    int hasScale = 0, hasOffset = 0;
    const double scale = GDALGetRasterScale(raster.Band, &hasScale) * this->VerticalScale;
    const double offset = GDALGetRasterOffset(raster.Band, &hasOffset) * this->VerticalScale;
    for (int k = 0; k < 2; ++k)
    {
      range[k] = minmax[k] * scale + offset;
    }
    if (range[0] > range[1])
    {
      std::swap(range[0], range[1]);
    }
    return std::isfinite(range[0]) && std::isfinite(range[1]);
  }
  vtkErrorMacro(<< (error.empty() ? "no valid height in " +
                      vtkApertureText::QuoteName(this->FileName) + ": " + raster.Session.LastError()
                                  : error));
  return false;
}

//------------------------------------------------------------------------------
void vtkGDALDEMReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "VerticalScale: " << this->VerticalScale << "\n";
  os << indent << "Size: " << this->Size[0] << " x " << this->Size[1] << "\n";
  os << indent << "Spacing: " << this->Spacing[0] << ", " << this->Spacing[1] << "\n";
  os << indent << "Origin: " << this->Origin[0] << ", " << this->Origin[1] << "\n";
  os << indent << "GeoOrigin: " << this->GeoOrigin[0] << ", " << this->GeoOrigin[1] << "\n";
  os << indent << "GeoSpacing: " << this->GeoSpacing[0] << ", " << this->GeoSpacing[1] << "\n";
  os << indent << "Georeferenced: " << this->Georeferenced << "\n";
  os << indent << "NorthUp: " << this->NorthUp << "\n";
  os << indent << "Geographic: " << this->Geographic << "\n";
  os << indent << "GroundSpacingNote: " << this->GroundSpacingNote << "\n";
  os << indent << "GridConvergence: " << this->GridConvergence << "\n";
  os << indent << "SpatialReference: " << (this->SpatialReference.empty() ? "(none)" : "WKT")
     << "\n";
}
