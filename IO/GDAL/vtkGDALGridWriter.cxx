/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkGDALGridWriter.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkGDALGridWriter.h"

#include "vtkApertureText.h"
#include "vtkApertureValidMask.h"
#include "vtkGDALSession.h"

#include "vtkAlgorithmOutput.h"
#include "vtkArrayDispatch.h"
#include "vtkDataArray.h"
#include "vtkDataArrayRange.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <cpl_error.h>
#include <cpl_string.h>
#include <cpl_vsi.h>
#include <gdal.h>
#include <gdal_utils.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>

vtkStandardNewMacro(vtkGDALGridWriter);

namespace
{
// The georeferencing of texel index (0, 0): its centre and the pixel size in CRS units, and the
// CRS; from vtkGDALDEMReader's field data, or else the image's own origin and spacing.
struct GeoReference
{
  double Origin[2];
  double Spacing[2];
  std::string WKT;

  explicit GeoReference(vtkImageData* image)
  {
    vtkFieldData* field = image->GetFieldData();
    auto* origin = vtkArrayDownCast<vtkDataArray>(field->GetAbstractArray("GeoOrigin"));
    auto* spacing = vtkArrayDownCast<vtkDataArray>(field->GetAbstractArray("GeoSpacing"));
    auto* wkt = vtkArrayDownCast<vtkStringArray>(field->GetAbstractArray("SpatialReference"));
    const bool stored =
      origin && spacing && origin->GetNumberOfValues() == 2 && spacing->GetNumberOfValues() == 2;
    for (int a = 0; a < 2; ++a)
    {
      this->Origin[a] = stored ? origin->GetComponent(0, a) : image->GetOrigin()[a];
      this->Spacing[a] = stored ? spacing->GetComponent(0, a) : std::abs(image->GetSpacing()[a]);
    }
    this->WKT = stored && wkt && wkt->GetNumberOfValues() > 0 ? wkt->GetValue(0) : "";
  }

  // GDAL's geotransform of a north-up file holding the whole extent.
  void GeoTransform(const int whole[6], double gt[6]) const
  {
    gt[0] = this->Origin[0] + (whole[0] - 0.5) * this->Spacing[0];
    gt[1] = this->Spacing[0];
    gt[2] = 0.0;
    gt[3] = this->Origin[1] + (whole[3] + 0.5) * this->Spacing[1];
    gt[4] = 0.0;
    gt[5] = -this->Spacing[1];
  }
};

// A band of the file: its name, and its unit (vtkDataArray::UNITS_LABEL()), or "".
struct Band
{
  std::string Name;
  std::string Unit;
};

// Copies the finished GeoTIFF `from` into a cloud-optimised GeoTIFF `to` with overviews, through
// GDAL's COG driver, and removes `from`; false with `error`, and neither file left, on failure.
bool CopyCloudOptimized(
  const std::string& from, const std::string& to, bool compress, std::string& error)
{
  vtkGDALSession session;
  CPLErrorReset();
  GDALDriverH cog = GDALGetDriverByName("COG");
  GDALDatasetH source = cog ? GDALOpen(from.c_str(), GA_ReadOnly) : nullptr;
  char** options = CSLSetNameValue(nullptr, "BIGTIFF", "IF_SAFER");
  options = CSLSetNameValue(options, "COMPRESS", compress ? "DEFLATE" : "NONE");
  options = CSLSetNameValue(options, "PREDICTOR", compress ? "YES" : "NO");
  options = CSLSetNameValue(options, "RESAMPLING", "AVERAGE");
  GDALDatasetH copy =
    source ? GDALCreateCopy(cog, to.c_str(), source, FALSE, options, nullptr, nullptr) : nullptr;
  CSLDestroy(options);
  if (copy)
  {
    GDALClose(copy);
  }
  if (source)
  {
    GDALClose(source);
  }
  VSIUnlink(from.c_str());
  if (!copy || CPLGetLastErrorType() >= CE_Failure)
  {
    error = "cannot write the cloud-optimised " + vtkApertureText::QuoteName(to) + ": " +
      (cog ? session.LastError() : "this GDAL has no COG driver");
    VSIUnlink(to.c_str());
    return false;
  }
  return true;
}
}

//------------------------------------------------------------------------------
// The file being written; removed unless Keep() was called.
class vtkGDALGridWriter::vtkFile
{
public:
  explicit vtkFile(const std::string& name)
    : Name(name)
  {
  }
  ~vtkFile()
  {
    const bool remove = this->Dataset != nullptr; // not closed by Flush(): a failed write
    if (this->Dataset)
    {
      GDALClose(this->Dataset);
    }
    if (remove)
    {
      VSIUnlink(this->Name.c_str());
    }
  }
  vtkFile(const vtkFile&) = delete;
  vtkFile& operator=(const vtkFile&) = delete;

  bool Create(const int whole[6], const std::vector<Band>& bands, bool compress,
    const GeoReference& geo, std::string& error);
  bool WriteBand(int band, int fileColumn, int fileRow, int nx, int rows, const float* values,
    std::string& error);
  // Writes what GDAL still caches; with `close`, closes the file and keeps it. GDAL reports
  // failures of these writes (a full disk) only as errors, not as return values.
  bool Flush(bool close, std::string& error);

  vtkGDALSession Session;
  std::string Name;
  GDALDatasetH Dataset = nullptr;
};

//------------------------------------------------------------------------------
bool vtkGDALGridWriter::vtkFile::Create(const int whole[6], const std::vector<Band>& bands,
  bool compress, const GeoReference& geo, std::string& error)
{
  GDALDriverH driver = GDALGetDriverByName("GTiff");
  char** options = nullptr;
  options = CSLSetNameValue(options, "TILED", "YES");
  options = CSLSetNameValue(options, "BLOCKXSIZE", "256");
  options = CSLSetNameValue(options, "BLOCKYSIZE", "256");
  options = CSLSetNameValue(options, "BIGTIFF", "IF_SAFER");
  if (compress)
  {
    options = CSLSetNameValue(options, "COMPRESS", "DEFLATE");
    options = CSLSetNameValue(options, "PREDICTOR", "3");
  }
  this->Dataset = driver
    ? GDALCreate(driver, this->Name.c_str(), whole[1] - whole[0] + 1, whole[3] - whole[2] + 1,
        static_cast<int>(bands.size()), GDT_Float32, options)
    : nullptr;
  CSLDestroy(options);
  if (!this->Dataset)
  {
    error =
      "cannot create " + vtkApertureText::QuoteName(this->Name) + ": " + this->Session.LastError();
    return false;
  }
  double gt[6];
  geo.GeoTransform(whole, gt);
  if (GDALSetGeoTransform(this->Dataset, gt) != CE_None ||
    (!geo.WKT.empty() && GDALSetProjection(this->Dataset, geo.WKT.c_str()) != CE_None))
  {
    error = "cannot georeference " + vtkApertureText::QuoteName(this->Name) + ": " +
      this->Session.LastError();
    return false;
  }
  for (size_t b = 0; b < bands.size(); ++b)
  {
    GDALRasterBandH band = GDALGetRasterBand(this->Dataset, static_cast<int>(b) + 1);
    GDALSetDescription(band, bands[b].Name.c_str());
    GDALSetRasterUnitType(band, bands[b].Unit.c_str());
    GDALSetRasterNoDataValue(band, std::numeric_limits<double>::quiet_NaN());
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkGDALGridWriter::vtkFile::Flush(bool close, std::string& error)
{
  CPLErrorReset();
  if (close)
  {
    GDALClose(this->Dataset);
    this->Dataset = nullptr;
  }
  else
  {
    GDALFlushCache(this->Dataset);
  }
  if (CPLGetLastErrorType() >= CE_Failure)
  {
    error =
      "cannot write " + vtkApertureText::QuoteName(this->Name) + ": " + this->Session.LastError();
    if (close)
    {
      VSIUnlink(this->Name.c_str());
    }
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkGDALGridWriter::vtkFile::WriteBand(
  int band, int fileColumn, int fileRow, int nx, int rows, const float* values, std::string& error)
{
  GDALRasterBandH h = GDALGetRasterBand(this->Dataset, band + 1);
  if (GDALRasterIO(h, GF_Write, fileColumn, fileRow, nx, rows, const_cast<float*>(values), nx, rows,
        GDT_Float32, 0, 0) != CE_None)
  {
    error =
      "cannot write " + vtkApertureText::QuoteName(this->Name) + ": " + this->Session.LastError();
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
vtkGDALGridWriter::vtkGDALGridWriter()
{
  this->SetNumberOfOutputPorts(0);
}

//------------------------------------------------------------------------------
int vtkGDALGridWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}

//------------------------------------------------------------------------------
void vtkGDALGridWriter::AddArrayName(const char* name)
{
  if (name)
  {
    this->ArrayNames.emplace_back(name);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkGDALGridWriter::ClearArrayNames()
{
  this->ArrayNames.clear();
  this->Modified();
}

//------------------------------------------------------------------------------
const char* vtkGDALGridWriter::GetArrayName(int i) const
{
  return i >= 0 && i < this->GetNumberOfArrayNames() ? this->ArrayNames[i].c_str() : nullptr;
}

//------------------------------------------------------------------------------
// The upstream pipeline's image for `extent`, or nullptr after an error.
vtkImageData* vtkGDALGridWriter::UpdateTile(const int extent[6])
{
  vtkAlgorithmOutput* connection = this->GetInputConnection(0, 0);
  vtkAlgorithm* upstream = connection->GetProducer();
  const int port = connection->GetIndex();
  vtkNew<vtkInformationVector> requests;
  requests->SetNumberOfInformationObjects(upstream->GetNumberOfOutputPorts());
  requests->GetInformationObject(port)->Set(
    vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent, 6);
  auto* image = upstream->Update(port, requests)
    ? vtkImageData::SafeDownCast(upstream->GetOutputDataObject(port))
    : nullptr;
  const int* got = image ? image->GetExtent() : nullptr;
  if (!got || got[0] > extent[0] || got[1] < extent[1] || got[2] > extent[2] || got[3] < extent[3])
  {
    vtkErrorMacro("The pipeline gave no image for rows " << extent[2] << " to " << extent[3]
                                                         << "; nothing written.");
    return nullptr;
  }
  return image;
}

//------------------------------------------------------------------------------
bool vtkGDALGridWriter::ChooseArrays(vtkImageData* image, std::vector<std::string>& names)
{
  vtkPointData* pd = image->GetPointData();
  names = this->ArrayNames;
  if (names.empty())
  {
    for (const char* name : { "BentNormal", "ApertureRadius", "AmbientOcclusion", "HorizonAngles",
           "SkyViewFactor", "SkyViewFactorCosine", "PositiveOpenness", "NegativeOpenness" })
    {
      if (pd->GetArray(name))
      {
        names.emplace_back(name);
      }
    }
  }
  if (names.empty() && pd->GetScalars() && pd->GetScalars()->GetName())
  {
    names.emplace_back(pd->GetScalars()->GetName());
  }
  for (const auto& name : names)
  {
    if (!pd->GetArray(name.c_str()))
    {
      vtkErrorMacro("The input has no numeric point array " << vtkApertureText::Quote(name)
                                                            << "; nothing written.");
      return false;
    }
  }
  if (names.empty())
  {
    vtkErrorMacro("The input has no point arrays to write.");
  }
  return !names.empty();
}

//------------------------------------------------------------------------------
int vtkGDALGridWriter::Write()
{
  if (this->GetNumberOfInputConnections(0) < 1 || this->FileName.empty())
  {
    vtkErrorMacro(<< (this->FileName.empty() ? "No file name." : "No input."));
    return 0;
  }
  vtkAlgorithmOutput* connection = this->GetInputConnection(0, 0);
  vtkAlgorithm* upstream = connection->GetProducer();
  vtkInformation* info = upstream->GetOutputInformation(connection->GetIndex());
  int whole[6] = { 0, -1, 0, -1, 0, -1 };
  if (!upstream->GetExecutive()->UpdateInformation() ||
    !info->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    vtkErrorMacro("The input has no extent (its reader failed?); nothing written.");
    return 0;
  }
  info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
  if (whole[4] != whole[5] || whole[1] < whole[0] || whole[3] < whole[2])
  {
    vtkErrorMacro("The input is not a 2D image; nothing written.");
    return 0;
  }
  const int nx = whole[1] - whole[0] + 1, ny = whole[3] - whole[2] + 1;
  const int rows = this->TileRows > 0 ? std::min(this->TileRows, ny) : ny;
  const int columns = this->TileColumns > 0 ? std::min(this->TileColumns, nx) : nx;
  const double tiles = std::ceil(double(ny) / rows) * std::ceil(double(nx) / columns);
  // A cloud-optimised file is copied from a plain one written beside it.
  const std::string plain = this->CloudOptimized ? this->FileName + ".writing.tif" : this->FileName;
  vtkFile file(plain);
  std::vector<std::string> arrays;
  std::vector<float> buffer;
  int done = 0;
  this->UpdateProgress(0.0);
  // Tiles from the north (top) row down and west to east, the order of the file's blocks.
  for (int top = whole[3]; top >= whole[2]; top -= rows)
  {
    for (int left = whole[0]; left <= whole[1]; left += columns)
    {
      const int tile[6] = { left, std::min(whole[1], left + columns - 1),
        std::max(whole[2], top - rows + 1), top, whole[4], whole[5] };
      vtkImageData* image = this->UpdateTile(tile);
      if (!image || (!file.Dataset && !this->CreateFile(file, image, whole, arrays)) ||
        !this->WriteTile(file, image, tile, whole, arrays, buffer))
      {
        return 0;
      }
      this->UpdateProgress(++done / tiles);
    }
  }
  std::string error;
  if (!file.Flush(true, error) ||
    (this->CloudOptimized && !CopyCloudOptimized(plain, this->FileName, this->Compress, error)))
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  return 1;
}

//------------------------------------------------------------------------------
// The file, its bands named after the first tile's arrays.
bool vtkGDALGridWriter::CreateFile(
  vtkFile& file, vtkImageData* image, const int whole[6], std::vector<std::string>& arrays)
{
  if (!this->ChooseArrays(image, arrays))
  {
    return false;
  }
  std::vector<Band> bands;
  static const char* const axes[] = { "_X", "_Y", "_Z" };
  for (const auto& name : arrays)
  {
    vtkDataArray* array = image->GetPointData()->GetArray(name.c_str());
    vtkInformation* info = array->GetInformation();
    const char* unit =
      info->Has(vtkDataArray::UNITS_LABEL()) ? info->Get(vtkDataArray::UNITS_LABEL()) : "";
    const int components = array->GetNumberOfComponents();
    for (int c = 0; c < components; ++c)
    {
      const char* given = array->GetComponentName(c);
      bands.push_back({ components == 1 ? name
                                        : name +
            (given      ? "_" + std::string(given)
                : c < 3 ? axes[c]
                        : "_" + std::to_string(c)),
        unit });
    }
  }
  std::string error;
  if (!file.Create(whole, bands, this->Compress, GeoReference(image), error))
  {
    vtkErrorMacro(<< error);
    return false;
  }
  return true;
}

namespace
{
// The file's blocks are this many rows high: a tile goes to GDAL this many rows at a time.
constexpr int BlockRows = 256;

// Copies component `c` of the rows of `rows` (x0, x1, y0, y1, top row first) into `buffer`, in
// the array's own type.
struct CopyRows
{
  vtkImageData* Image;
  const int* Rows;
  int Component;
  float* Buffer;

  template <typename Array>
  void operator()(Array* array) const
  {
    const auto values = vtk::DataArrayTupleRange(array);
    const int nx = this->Rows[1] - this->Rows[0] + 1;
    const int z = this->Image->GetExtent()[4];
    vtkSMPTools::For(0, this->Rows[3] - this->Rows[2] + 1,
      [&](vtkIdType first, vtkIdType last)
      {
        for (vtkIdType r = first; r < last; ++r)
        {
          int ijk[3] = { this->Rows[0], this->Rows[3] - static_cast<int>(r), z };
          const vtkIdType start = this->Image->ComputePointId(ijk);
          for (vtkIdType i = 0; i < nx; ++i)
          {
            this->Buffer[r * nx + i] = static_cast<float>(values[start + i][this->Component]);
          }
        }
      });
  }
};

// Component `c` of `array` over `rows` into `buffer`, NaN where `mask` (optional) is 0.
void Copy(vtkImageData* image, vtkDataArray* array, int c, vtkDataArray* mask, const int rows[6],
  float* buffer)
{
  const CopyRows copy{ image, rows, c, buffer };
  if (!vtkArrayDispatch::Dispatch::Execute(array, copy))
  {
    copy(array);
  }
  if (!mask)
  {
    return;
  }
  const vtkIdType count = static_cast<vtkIdType>(rows[1] - rows[0] + 1) * (rows[3] - rows[2] + 1);
  std::vector<float> valid(count);
  const CopyRows copyMask{ image, rows, 0, valid.data() };
  if (!vtkArrayDispatch::Dispatch::Execute(mask, copyMask))
  {
    copyMask(mask);
  }
  for (vtkIdType k = 0; k < count; ++k)
  {
    buffer[k] = valid[k] != 0.0f ? buffer[k] : std::numeric_limits<float>::quiet_NaN();
  }
}
}

//------------------------------------------------------------------------------
// One tile, a block row at a time: its rows of every band, top row first, NaN where the mask
// says no-data, then out of GDAL's block cache. Whatever the tile, the writer holds a few block
// rows (a tile that is the whole grid would otherwise hold it a second time, in GDAL's cache).
bool vtkGDALGridWriter::WriteTile(vtkFile& file, vtkImageData* image, const int tile[6],
  const int whole[6], const std::vector<std::string>& arrays, std::vector<float>& buffer)
{
  std::vector<vtkDataArray*> found;
  for (const auto& name : arrays)
  {
    found.push_back(image->GetPointData()->GetArray(name.c_str()));
    if (!found.back())
    {
      vtkErrorMacro(
        "A tile has no point array " << vtkApertureText::Quote(name) << "; nothing written.");
      return false;
    }
  }
  vtkDataArray* mask = image->GetPointData()->GetArray(vtkApertureValidMask::Name());
  const int nx = tile[1] - tile[0] + 1;
  buffer.resize(static_cast<size_t>(nx) * BlockRows);
  std::string error;
  for (int top = tile[3]; top >= tile[2]; top -= BlockRows)
  {
    const int rows[6] = { tile[0], tile[1], std::max(tile[2], top - BlockRows + 1), top, tile[4],
      tile[5] };
    int band = 0;
    for (vtkDataArray* array : found)
    {
      for (int c = 0; c < array->GetNumberOfComponents(); ++c, ++band)
      {
        Copy(image, array, c, mask, rows, buffer.data());
        if (!file.WriteBand(band, tile[0] - whole[0], whole[3] - top, nx, top - rows[2] + 1,
              buffer.data(), error))
        {
          vtkErrorMacro(<< error);
          return false;
        }
      }
    }
    if (!file.Flush(false, error))
    {
      vtkErrorMacro(<< error);
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkGDALGridWriter::WriteBandCopy(int band, const char* fileName)
{
  vtkGDALSession session;
  const std::string to = fileName ? fileName : "";
  GDALDatasetH source = GDALOpen(this->FileName.c_str(), GA_ReadOnly);
  if (!source || band < 1 || band > GDALGetRasterCount(source) || to.empty())
  {
    vtkErrorMacro("cannot copy band " << band << " of "
                                      << vtkApertureText::QuoteName(this->FileName)
                                      << (source ? ": no such band or no file name." : ": ")
                                      << (source ? "" : session.LastError()));
    if (source)
    {
      GDALClose(source);
    }
    return 0;
  }
  const std::string arguments[] = { "-of", "GTiff", "-b", std::to_string(band), "-co", "TILED=YES",
    "-co", this->Compress ? "COMPRESS=DEFLATE" : "COMPRESS=NONE" };
  std::vector<char*> argv;
  for (const auto& argument : arguments)
  {
    argv.push_back(const_cast<char*>(argument.c_str()));
  }
  argv.push_back(nullptr);
  GDALTranslateOptions* options = GDALTranslateOptionsNew(argv.data(), nullptr);
  CPLErrorReset();
  GDALDatasetH copy = GDALTranslate(to.c_str(), source, options, nullptr);
  GDALTranslateOptionsFree(options);
  if (copy)
  {
    GDALRasterBandH from = GDALGetRasterBand(source, band), into = GDALGetRasterBand(copy, 1);
    GDALSetDescription(into, GDALGetDescription(from));
    GDALSetRasterUnitType(into, GDALGetRasterUnitType(from));
    GDALClose(copy);
  }
  GDALClose(source);
  if (!copy || CPLGetLastErrorType() >= CE_Failure)
  {
    vtkErrorMacro("cannot write " << vtkApertureText::QuoteName(to) << ": " << session.LastError());
    VSIUnlink(to.c_str());
    return 0;
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkGDALGridWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "ArrayNames:";
  for (const auto& name : this->ArrayNames)
  {
    os << " " << name;
  }
  os << (this->ArrayNames.empty() ? " (the aperture arrays, or the scalars)\n" : "\n");
  os << indent << "TileRows: " << this->TileRows << "\n";
  os << indent << "TileColumns: " << this->TileColumns << "\n";
  os << indent << "Compress: " << this->Compress << "\n";
  os << indent << "CloudOptimized: " << this->CloudOptimized << "\n";
}
