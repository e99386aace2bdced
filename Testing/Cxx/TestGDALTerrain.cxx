/*=========================================================================

  Program:   ApertureLighting
  Module:    TestGDALTerrain.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// DEMs through GDAL: real GeoTIFFs written with GDAL (projected and geographic, Int16, UInt16,
// Float32, no-data, scale and offset) read by vtkGDALDEMReader with their rows, spacing and
// masks right; horizon apertures written by vtkGDALGridWriter tile by tile equal the untiled
// filter and keep the georeferencing; the reader reads only the tiles asked for; damaged, multi-
// band, polar and absurd files are clear errors.

#include "vtkAperturePrecompute.h"
#include "vtkGDALDEMReader.h"
#include "vtkGDALGridWriter.h"

#include "vtkApertureTestHarness.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkShortArray.h"
#include "vtkStringArray.h"
#include "vtkTestErrorObserver.h"
#include "vtkTestUtilities.h"
#include "vtkUnsignedCharArray.h"

#include <cpl_string.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>
#include <vector>

namespace
{
using vtkApertureTest::Check;

std::string Directory;

// Heights of a smooth hill with a ridge, in file order (row 0 north).
double Height(int column, int row)
{
  const double x = column * 0.11, y = row * 0.07;
  return 200.0 + 80.0 * std::sin(x) * std::cos(y) + 3.0 * column - 2.0 * row;
}

struct FileSpec
{
  int Nx = 61, Ny = 47, Bands = 1;
  GDALDataType Type = GDT_Int16;
  double GeoTransform[6] = { 500000.0, 30.0, 0.0, 3900000.0, 0.0, -30.0 };
  int EPSG = 32654; // UTM 54N; 4326 for geographic, 0 for none
  bool HasNoData = true;
  double NoData = -32768.0;
  double Scale = 1.0, Offset = 0.0;
  bool Georeferenced = true;
};

// Writes a DEM with GDAL; texels with (column + 2 row) % 29 == 0 are no-data.
std::string WriteDEM(const std::string& name, const FileSpec& spec)
{
  const std::string path = Directory + "/" + name;
  GDALAllRegister();
  GDALDatasetH ds = GDALCreate(
    GDALGetDriverByName("GTiff"), path.c_str(), spec.Nx, spec.Ny, spec.Bands, spec.Type, nullptr);
  if (spec.Georeferenced)
  {
    GDALSetGeoTransform(ds, const_cast<double*>(spec.GeoTransform));
  }
  if (spec.EPSG && spec.Georeferenced)
  {
    OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
    OSRImportFromEPSG(srs, spec.EPSG);
    char* wkt = nullptr;
    OSRExportToWkt(srs, &wkt);
    GDALSetProjection(ds, wkt);
    CPLFree(wkt);
    OSRDestroySpatialReference(srs);
  }
  std::vector<double> values(spec.Nx * spec.Ny);
  for (int r = 0; r < spec.Ny; ++r)
  {
    for (int c = 0; c < spec.Nx; ++c)
    {
      const bool hole = spec.HasNoData && (c + 2 * r) % 29 == 0;
      values[r * spec.Nx + c] = hole ? spec.NoData : std::round(Height(c, r));
    }
  }
  for (int b = 1; b <= spec.Bands; ++b)
  {
    GDALRasterBandH band = GDALGetRasterBand(ds, b);
    if (spec.HasNoData)
    {
      GDALSetRasterNoDataValue(band, spec.NoData);
    }
    GDALSetRasterScale(band, spec.Scale);
    GDALSetRasterOffset(band, spec.Offset);
    CPLErr err = GDALRasterIO(
      band, GF_Write, 0, 0, spec.Nx, spec.Ny, values.data(), spec.Nx, spec.Ny, GDT_Float64, 0, 0);
    Check(err == CE_None, "writing " + name);
  }
  GDALClose(ds);
  return path;
}

// Runs `reader` expecting failure; true when it failed with an error.
bool FailsClearly(vtkGDALDEMReader* reader)
{
  vtkNew<vtkTest::ErrorObserver> observer, executive;
  reader->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executive);
  reader->Update();
  reader->RemoveAllObservers();
  reader->GetExecutive()->RemoveAllObservers();
  return observer->GetError();
}

void TestProjected()
{
  FileSpec spec;
  const std::string path = WriteDEM("projected.tif", spec);
  vtkNew<vtkGDALDEMReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  Check(dims[0] == spec.Nx && dims[1] == spec.Ny, "projected: dimensions");
  Check(image->GetSpacing()[0] == 30.0 && image->GetSpacing()[1] == 30.0, "projected: spacing");
  // Texel (0, 0) is the south-west texel's centre.
  Check(image->GetOrigin()[0] == 500015.0, "projected: origin x", image->GetOrigin()[0], 500015.0);
  Check(image->GetOrigin()[1] == 3900000.0 - 30.0 * spec.Ny + 15.0, "projected: origin y",
    image->GetOrigin()[1], 3900000.0 - 30.0 * spec.Ny + 15.0);
  vtkDataArray* z = image->GetPointData()->GetScalars();
  vtkDataArray* mask = image->GetPointData()->GetArray("vtkValidPointMask");
  Check(z && mask && std::string(z->GetName()) == "Elevation", "projected: arrays");
  int wrong = 0, holes = 0;
  for (int j = 0; z && mask && j < spec.Ny; ++j)
  {
    for (int i = 0; i < spec.Nx; ++i)
    {
      const int row = spec.Ny - 1 - j; // the file's row 0 is north
      const vtkIdType t = i + j * spec.Nx;
      const bool hole = (i + 2 * row) % 29 == 0;
      holes += hole;
      const double value = z->GetComponent(t, 0);
      const bool ok = hole ? std::isnan(value) && mask->GetComponent(t, 0) == 0.0
                           : value == std::round(Height(i, row)) && mask->GetComponent(t, 0) == 1.0;
      wrong += !ok;
    }
  }
  Check(wrong == 0, "projected: heights and mask per texel, wrong", wrong, 0);
  Check(holes > 50, "projected: the file has no-data texels");
  auto* note =
    vtkStringArray::SafeDownCast(image->GetFieldData()->GetAbstractArray("GroundSpacing"));
  Check(note && note->GetValue(0).find("projected") != std::string::npos, "projected: note");
  Check(!reader->GetGeographic(), "projected: not geographic");
}

// A raster without a geotransform: spacing 1, a warning, and its first row on top, as an image.
void TestNotGeoreferenced()
{
  FileSpec spec;
  spec.Georeferenced = false;
  spec.Type = GDT_Float32;
  vtkNew<vtkGDALDEMReader> reader;
  reader->SetFileName(WriteDEM("plain.tif", spec).c_str());
  vtkNew<vtkTest::ErrorObserver> warnings;
  reader->AddObserver(vtkCommand::WarningEvent, warnings);
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  Check(!reader->GetGeoreferenced() && warnings->GetWarning(), "plain raster: a warning");
  Check(image->GetSpacing()[0] == 1.0 && image->GetSpacing()[1] == 1.0, "plain raster: spacing 1");
  vtkDataArray* z = image->GetPointData()->GetScalars();
  const int i = 7, row = 2; // file row 2 from the top
  const double got = z ? z->GetComponent(i + (spec.Ny - 1 - row) * spec.Nx, 0) : 0.0;
  Check(got == std::round(Height(i, row)), "plain raster: the file's first row is the top", got,
    std::round(Height(i, row)));
}

void TestTypesScaleAndVerticalScale()
{
  for (GDALDataType type : { GDT_UInt16, GDT_Float32, GDT_Int32, GDT_Float64 })
  {
    FileSpec spec;
    spec.Type = type;
    spec.NoData = type == GDT_UInt16 ? 0.0 : -9999.0;
    spec.Scale = 0.5;
    spec.Offset = 10.0;
    const std::string path = WriteDEM("typed.tif", spec);
    vtkNew<vtkGDALDEMReader> reader;
    reader->SetFileName(path.c_str());
    reader->SetVerticalScale(0.3048);
    reader->Update();
    vtkDataArray* z = reader->GetOutput()->GetPointData()->GetScalars();
    const int i = 5, row = 3, j = spec.Ny - 1 - row;
    const double want = (std::round(Height(i, row)) * 0.5 + 10.0) * 0.3048;
    const double got = z ? z->GetComponent(i + j * spec.Nx, 0) : 0.0;
    Check(std::abs(got - want) < 1e-4,
      std::string("type ") + GDALGetDataTypeName(type) + ": scale, offset and vertical scale", got,
      want);
  }
}

// Metres per degree on WGS 84 at 35 degrees north: 91,288 m of longitude, 110,941 m of latitude
// (standard tables).
void TestGeographic()
{
  FileSpec spec;
  spec.EPSG = 4326;
  const double second = 1.0 / 3600.0;
  const double gt[6] = { 138.5, second, 0.0, 35.0 + 0.5 * spec.Ny * second, 0.0, -second };
  std::copy(gt, gt + 6, spec.GeoTransform);
  vtkNew<vtkGDALDEMReader> reader;
  reader->SetFileName(WriteDEM("geographic.tif", spec).c_str());
  reader->Update();
  const double* s = reader->GetOutput()->GetSpacing();
  Check(std::abs(s[0] / (91288.0 * second) - 1.0) < 5e-4, "geographic: east-west metres", s[0],
    91288.0 * second);
  Check(std::abs(s[1] / (110941.0 * second) - 1.0) < 5e-4, "geographic: north-south metres", s[1],
    110941.0 * second);
  Check(reader->GetGeographic(), "geographic: flagged");
  Check(std::string(reader->GetGroundSpacingNote()).find("latitude 35") != std::string::npos,
    "geographic: the note names the latitude");

  // One tile on the NTF datum in degrees (EPSG:4275) and in grads from Paris (EPSG:4807, 400 to
  // the turn): the same ground spacing.
  double degreeSpacing[2];
  for (const int epsg : { 4275, 4807 })
  {
    const double perDegree = epsg == 4807 ? 400.0 / 360.0 : 1.0;
    const double fromParis = epsg == 4807 ? 2.33722917 : 0.0; // Paris, degrees east of Greenwich
    const double tile[6] = { perDegree * (2.5 - fromParis), perDegree * second, 0.0,
      perDegree * 48.8, 0.0, -perDegree * second };
    std::copy(tile, tile + 6, spec.GeoTransform);
    spec.EPSG = epsg;
    reader->SetFileName(WriteDEM("ntf-" + std::to_string(epsg) + ".tif", spec).c_str());
    reader->Update();
    const double* ntf = reader->GetOutput()->GetSpacing();
    if (epsg == 4275)
    {
      std::copy(ntf, ntf + 2, degreeSpacing);
      continue;
    }
    for (int a = 0; a < 2; ++a)
    {
      Check(std::abs(ntf[a] / degreeSpacing[a] - 1.0) < 1e-9,
        "grads: the metres of degrees along axis " + std::to_string(a), ntf[a], degreeSpacing[a]);
    }
    Check(std::string(reader->GetGroundSpacingNote()).find("latitude 48.7") != std::string::npos,
      "grads: the note gives the latitude in degrees");
  }
  spec.EPSG = 4326;

  // A tile that reaches the north pole.
  const double polar[6] = { 0.0, 1.0, 0.0, 90.0, 0.0, -1.0 };
  std::copy(polar, polar + 6, spec.GeoTransform);
  reader->SetFileName(WriteDEM("pole.tif", spec).c_str());
  Check(FailsClearly(reader), "a tile at the pole is an error");
}

// Web Mercator's metres are sec(latitude) ground metres: at 35 degrees north, 30 of them are
// 30 cos 35 = 24.57 m on the ground (the sphere's scale; the ellipsoid's differs by < 0.5%).
void TestWebMercator()
{
  FileSpec spec;
  spec.EPSG = 3857;
  const double y =
    6378137.0 * std::log(std::tan(0.25 * vtkMath::Pi() + 0.5 * 35.0 * vtkMath::Pi() / 180.0));
  const double gt[6] = { 15400000.0, 30.0, 0.0, y + 0.5 * spec.Ny * 30.0, 0.0, -30.0 };
  std::copy(gt, gt + 6, spec.GeoTransform);
  vtkNew<vtkGDALDEMReader> reader;
  reader->SetFileName(WriteDEM("mercator.tif", spec).c_str());
  reader->Update();
  const double want = 30.0 * std::cos(35.0 * vtkMath::Pi() / 180.0);
  for (int a = 0; a < 2; ++a)
  {
    const double got = reader->GetOutput()->GetSpacing()[a];
    Check(std::abs(got / want - 1.0) < 5e-3,
      "Web Mercator: ground metres along axis " + std::to_string(a), got, want);
  }
  Check(std::string(reader->GetGroundSpacingNote()).find("ground metres") != std::string::npos,
    "Web Mercator: the note says the CRS's units are not ground metres");
}

// France's Lambert II extended (EPSG:27572) counts true metres (scale within 0.1% near Paris) on a
// geographic base in grads: its spacing stays the pixel size.
void TestLambertOnGrads()
{
  FileSpec spec;
  spec.EPSG = 27572;
  const double gt[6] = { 600000.0, 30.0, 0.0, 2430000.0, 0.0, -30.0 };
  std::copy(gt, gt + 6, spec.GeoTransform);
  vtkNew<vtkGDALDEMReader> reader;
  reader->SetFileName(WriteDEM("lambert2e.tif", spec).c_str());
  reader->Update();
  for (int a = 0; a < 2; ++a)
  {
    const double got = reader->GetOutput()->GetSpacing()[a];
    Check(std::abs(got / 30.0 - 1.0) < 2e-3,
      "Lambert II extended: metres along axis " + std::to_string(a), got, 30.0);
  }
  Check(std::string(reader->GetGroundSpacingNote()).find("projected CRS's pixel size") !=
      std::string::npos,
    "Lambert II extended: the note says the CRS's metres are used");
}

void TestBadFiles()
{
  vtkNew<vtkGDALDEMReader> reader;
  reader->SetFileName((Directory + "/no-such-file.tif").c_str());
  Check(FailsClearly(reader), "a missing file is an error");

  FileSpec spec;
  spec.Bands = 3;
  reader->SetFileName(WriteDEM("rgb.tif", spec).c_str());
  Check(FailsClearly(reader), "a three-band file is an error");

  spec.Bands = 1;
  const double absurd[6] = { 0.0, 1e-9, 0.0, 0.0, 0.0, -1e-9 };
  std::copy(absurd, absurd + 6, spec.GeoTransform);
  reader->SetFileName(WriteDEM("absurd.tif", spec).c_str());
  Check(FailsClearly(reader), "a spacing of a nanometre is an error");

  // Found by fuzzing: PROJ loops for ever on a Web Mercator pixel of 1e40 m.
  spec.EPSG = 3857;
  const double huge[6] = { 500000.0, 1e40, 0.0, 3900000.0, 0.0, -30.0 };
  std::copy(huge, huge + 6, spec.GeoTransform);
  reader->SetFileName(WriteDEM("huge-pixels.tif", spec).c_str());
  Check(FailsClearly(reader), "a Web Mercator pixel of 1e40 m is an error, at once");
  spec.EPSG = 32654;

  // Truncated and damaged copies of a good file: an error or a read, never a crash.
  spec = FileSpec();
  spec.Nx = spec.Ny = 300;
  std::ifstream in(WriteDEM("whole.tif", spec), std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string cut = Directory + "/truncated.tif";
  std::ofstream(cut, std::ios::binary).write(bytes.data(), bytes.size() / 2);
  reader->SetFileName(cut.c_str());
  Check(FailsClearly(reader), "a truncated GeoTIFF is an error");
  unsigned state = 12345;
  int refused = 0;
  for (int trial = 0; trial < 60; ++trial)
  {
    std::string damaged = bytes;
    for (int k = 0; k < 8; ++k)
    {
      state = state * 1664525u + 1013904223u;
      const size_t at = (state >> 8) % std::min<size_t>(damaged.size(), 4096);
      damaged[at] = static_cast<char>(state >> 24);
    }
    const std::string path = Directory + "/damaged.tif";
    std::ofstream(path, std::ios::binary).write(damaged.data(), damaged.size());
    reader->SetFileName(path.c_str());
    vtkNew<vtkTest::ErrorObserver> observer, executive;
    reader->AddObserver(vtkCommand::ErrorEvent, observer);
    reader->AddObserver(vtkCommand::WarningEvent, observer);
    reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executive);
    reader->Modified();
    reader->Update();
    reader->RemoveAllObservers();
    reader->GetExecutive()->RemoveAllObservers();
    refused += observer->GetError() ? 1 : 0;
  }
  std::cout << "60 damaged GeoTIFF headers: " << refused << " refused with an error, "
            << 60 - refused << " read\n";
}

// Reads a written aperture file's band `b` (1-based) in VTK's row order.
std::vector<float> ReadBand(const std::string& path, int b, int nx, int ny)
{
  std::vector<float> values(nx * ny);
  GDALDatasetH ds = GDALOpen(path.c_str(), GA_ReadOnly);
  if (!ds)
  {
    return {};
  }
  for (int r = 0; r < ny; ++r)
  {
    CPLErr err = GDALRasterIO(GDALGetRasterBand(ds, b), GF_Read, 0, r, nx, 1,
      &values[(ny - 1 - r) * nx], nx, 1, GDT_Float32, 0, 0);
    Check(err == CE_None, "reading back a row");
  }
  GDALClose(ds);
  return values;
}

// Keeps the largest extent the reader was asked for.
struct ExtentSpy
{
  int Largest = 0;
  void operator()(vtkGDALDEMReader* reader)
  {
    const int* e = reader->GetOutput()->GetExtent();
    this->Largest = std::max(this->Largest, (e[1] - e[0] + 1) * (e[3] - e[2] + 1));
  }
};

void TestTiledRoundTrip()
{
  FileSpec spec;
  spec.Nx = 90;
  spec.Ny = 70;
  const std::string dem = WriteDEM("round-trip.tif", spec);
  vtkNew<vtkGDALDEMReader> reader;
  reader->SetFileName(dem.c_str());
  vtkNew<vtkAperturePrecompute> whole;
  whole->SetInputConnection(reader->GetOutputPort());
  whole->LimitDistanceOn();
  whole->SetMaximumDistance(150.0); // 5 texels of 30 m
  whole->ComputeAmbientOcclusionOn();
  whole->Update();
  Check(whole->GetUsedHorizons(), "round trip: a DEM takes the horizon sweeps");
  vtkImageData* reference = whole->GetImageDataOutput();

  vtkNew<vtkAperturePrecompute> tiled;
  tiled->SetInputConnection(reader->GetOutputPort());
  tiled->LimitDistanceOn();
  tiled->SetMaximumDistance(150.0);
  tiled->ComputeAmbientOcclusionOn();
  ExtentSpy spy;
  vtkNew<vtkCallbackCommand> onRead;
  onRead->SetClientData(&spy);
  onRead->SetCallback([](vtkObject* caller, unsigned long, void* data, void*)
    { (*static_cast<ExtentSpy*>(data))(static_cast<vtkGDALDEMReader*>(caller)); });
  reader->AddObserver(vtkCommand::EndEvent, onRead);
  reader->Modified(); // read again, tile by tile
  vtkNew<vtkGDALGridWriter> writer;
  writer->SetInputConnection(tiled->GetOutputPort());
  writer->SetTileRows(16);
  writer->SetTileColumns(23);
  const std::string out = Directory + "/apertures.tif";
  writer->SetFileName(out.c_str());
  Check(writer->Write() == 1, "round trip: written");
  reader->RemoveObserver(onRead);
  // Tiles of 16 rows grow by 5 + 2 texels each way: at most 30 of the 70 rows are read.
  Check(
    spy.Largest <= 90 * 30, "round trip: the reader read tiles, not the DEM", spy.Largest, 90 * 30);

  GDALDatasetH ds = GDALOpen(out.c_str(), GA_ReadOnly);
  Check(ds && GDALGetRasterCount(ds) == 5, "round trip: 5 bands (bent normal xyz, radius, AO)");
  double gtIn[6], gtOut[6];
  GDALDatasetH in = GDALOpen(dem.c_str(), GA_ReadOnly);
  GDALGetGeoTransform(in, gtIn);
  if (ds)
  {
    GDALGetGeoTransform(ds, gtOut);
    for (int k = 0; k < 6; ++k)
    {
      Check(gtIn[k] == gtOut[k], "round trip: geotransform coefficient " + std::to_string(k),
        gtOut[k], gtIn[k]);
    }
    Check(std::string(GDALGetProjectionRef(ds)) == GDALGetProjectionRef(in), "round trip: CRS");
    Check(std::string(GDALGetDescription(GDALGetRasterBand(ds, 4))) == "ApertureRadius",
      "round trip: band 4 is ApertureRadius");
    GDALClose(ds);
  }
  GDALClose(in);

  const char* names[] = { "BentNormal", "BentNormal", "BentNormal", "ApertureRadius",
    "AmbientOcclusion" };
  vtkDataArray* mask = reference->GetPointData()->GetArray("vtkValidPointMask");
  double worst = 0.0;
  int maskWrong = 0;
  for (int b = 0; b < 5; ++b)
  {
    const auto values = ReadBand(out, b + 1, spec.Nx, spec.Ny);
    vtkDataArray* want = reference->GetPointData()->GetArray(names[b]);
    const int c = b < 3 ? b : 0;
    for (vtkIdType t = 0; want && t < static_cast<vtkIdType>(values.size()); ++t)
    {
      const bool valid = !mask || mask->GetComponent(t, 0) != 0.0;
      maskWrong += valid == std::isnan(values[t]);
      if (valid)
      {
        worst = std::max(worst, std::abs(values[t] - want->GetComponent(t, c)));
      }
    }
  }
  Check(mask != nullptr, "round trip: the DEM's no-data is masked in the output");
  Check(maskWrong == 0, "round trip: NaN exactly at no-data texels", maskWrong, 0);
  Check(worst <= 1e-6, "round trip: tiled file == untiled filter", worst, 1e-6);
  std::cout << "Tiled (16 x 23) vs untiled: max difference " << worst << ", largest read "
            << spy.Largest << " of " << spec.Nx * spec.Ny << " texels\n";

  // What the writer refuses.
  vtkNew<vtkGDALGridWriter> bad;
  bad->SetInputConnection(tiled->GetOutputPort());
  bad->SetFileName((Directory + "/no-such-dir/x.tif").c_str());
  vtkNew<vtkTest::ErrorObserver> observer;
  bad->AddObserver(vtkCommand::ErrorEvent, observer);
  Check(bad->Write() == 0 && observer->GetError(), "writer: an uncreatable file is an error");
  bad->SetFileName((Directory + "/missing-array.tif").c_str());
  bad->AddArrayName("NoSuchArray");
  Check(bad->Write() == 0, "writer: a missing array is an error");
  Check(!std::ifstream(Directory + "/missing-array.tif"), "writer: no partial file is left");
}

// Horizons kept by the filter become one band per sector, named by azimuth, equal to the array
// whether the file is written in tiles or not.
void TestHorizonBands()
{
  FileSpec spec;
  spec.Nx = 60;
  spec.Ny = 50;
  const std::string dem = WriteDEM("horizon-bands.tif", spec);
  vtkNew<vtkGDALDEMReader> reader;
  reader->SetFileName(dem.c_str());
  vtkNew<vtkAperturePrecompute> filter;
  filter->SetInputConnection(reader->GetOutputPort());
  filter->LimitDistanceOn();
  filter->SetMaximumDistance(150.0);
  filter->SetNumberOfSectors(8);
  filter->ComputeHorizonAnglesOn();
  filter->Update();
  vtkSmartPointer<vtkImageData> reference = vtkSmartPointer<vtkImageData>::New();
  reference->DeepCopy(filter->GetImageDataOutput());
  vtkNew<vtkGDALGridWriter> writer;
  writer->SetInputConnection(filter->GetOutputPort());
  writer->SetTileRows(16);
  writer->SetTileColumns(25);
  const std::string out = Directory + "/horizon-bands-out.tif";
  writer->SetFileName(out.c_str());
  Check(writer->Write() == 1, "horizon bands: written");
  GDALDatasetH ds = GDALOpen(out.c_str(), GA_ReadOnly);
  Check(ds && GDALGetRasterCount(ds) == 12, "horizon bands: 4 aperture bands and 8 horizons");
  if (ds)
  {
    Check(std::string(GDALGetDescription(GDALGetRasterBand(ds, 5))) == "HorizonAngles_Az22.5" &&
        std::string(GDALGetDescription(GDALGetRasterBand(ds, 12))) == "HorizonAngles_Az337.5",
      "horizon bands: named by the azimuth of their sector's middle");
    GDALClose(ds);
  }
  vtkDataArray* horizons = reference->GetPointData()->GetArray("HorizonAngles");
  vtkDataArray* mask = reference->GetPointData()->GetArray("vtkValidPointMask");
  double worst = 0.0;
  int wrong = 0;
  for (int k = 0; horizons && k < 8; ++k)
  {
    const auto values = ReadBand(out, 5 + k, spec.Nx, spec.Ny);
    for (vtkIdType t = 0; t < static_cast<vtkIdType>(values.size()); ++t)
    {
      const bool valid = !mask || mask->GetComponent(t, 0) != 0.0;
      wrong += valid == std::isnan(values[t]);
      worst = valid ? std::max(worst, std::abs(values[t] - horizons->GetComponent(t, k))) : worst;
    }
  }
  Check(horizons && wrong == 0, "horizon bands: NaN exactly at no-data texels", wrong, 0);
  Check(worst <= 1e-6, "horizon bands: tiled file == untiled filter", worst, 1e-6);
}

// A DEM of one row: an error from the filter; every texel no-data: closed apertures and a warning.
void TestDegenerate()
{
  FileSpec spec;
  spec.Ny = 1;
  vtkNew<vtkGDALDEMReader> reader;
  reader->SetFileName(WriteDEM("one-row.tif", spec).c_str());
  vtkNew<vtkAperturePrecompute> filter;
  filter->SetInputConnection(reader->GetOutputPort());
  vtkNew<vtkTest::ErrorObserver> observer, executive;
  filter->AddObserver(vtkCommand::ErrorEvent, observer);
  filter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executive);
  filter->Update();
  Check(observer->GetError(), "a one-row DEM is an error");

  spec = FileSpec();
  spec.NoData = 7.0;
  spec.Type = GDT_Float32;
  spec.HasNoData = true;
  std::string path = WriteDEM("flat.tif", spec);
  // Rewrite every texel as the no-data value.
  GDALDatasetH ds = GDALOpen(path.c_str(), GA_Update);
  std::vector<float> seven(spec.Nx * spec.Ny, 7.0f);
  CPLErr err = GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, 0, spec.Nx, spec.Ny,
    seven.data(), spec.Nx, spec.Ny, GDT_Float32, 0, 0);
  Check(err == CE_None, "writing an all-no-data DEM");
  GDALClose(ds);
  reader->SetFileName(path.c_str());
  vtkNew<vtkTest::ErrorObserver> warnings;
  filter->AddObserver(vtkCommand::WarningEvent, warnings);
  filter->Update();
  vtkDataArray* r = filter->GetImageDataOutput()->GetPointData()->GetArray("ApertureRadius");
  Check(r && r->GetRange()[1] == 0.0, "all no-data: every aperture closed");
  Check(warnings->GetWarning(), "all no-data: a warning");
}
}

// The writer sends a tile to GDAL a block row (256 rows) at a time: an untiled image of 600
// rows, with arrays of other types than float (short heights, a double vector) and a mask,
// reads back value for value, NaN exactly where the mask is 0, its rows in the right places.
void TestWriterBlockRows()
{
  const int nx = 37, ny = 600;
  vtkNew<vtkImageData> image;
  image->SetDimensions(nx, ny, 1);
  vtkNew<vtkShortArray> heights;
  heights->SetName("Heights");
  vtkNew<vtkDoubleArray> vectors;
  vectors->SetName("Vectors");
  vectors->SetNumberOfComponents(2);
  vtkNew<vtkUnsignedCharArray> mask;
  mask->SetName("vtkValidPointMask");
  for (vtkIdType t = 0; t < nx * ny; ++t)
  {
    heights->InsertNextValue(static_cast<short>(t % 30011 - 15000));
    vectors->InsertNextTuple2(0.25 * t, -1.0 / (t + 1));
    mask->InsertNextValue(t % 7 == 3 ? 0 : 1);
  }
  image->GetPointData()->AddArray(heights);
  image->GetPointData()->AddArray(vectors);
  image->GetPointData()->AddArray(mask);
  vtkNew<vtkGDALGridWriter> writer;
  writer->SetInputData(image);
  writer->AddArrayName("Heights");
  writer->AddArrayName("Vectors");
  const std::string out = Directory + "/block-rows.tif";
  writer->SetFileName(out.c_str());
  Check(writer->Write() == 1, "block rows: written");
  int wrong = 0;
  for (int b = 0; b < 3; ++b)
  {
    const auto values = ReadBand(out, b + 1, nx, ny);
    for (vtkIdType t = 0; t < nx * ny; ++t)
    {
      const double want = b == 0 ? heights->GetValue(t) : vectors->GetComponent(t, b - 1);
      const bool masked = mask->GetValue(t) == 0;
      wrong += values.size() != size_t(nx * ny) ||
        (masked ? !std::isnan(values[t]) : values[t] != static_cast<float>(want));
    }
  }
  Check(wrong == 0, "block rows: 600 rows of short and double arrays read back exactly", wrong, 0);
}

int TestGDALTerrain(int argc, char* argv[])
{
  char* temporary =
    vtkTestUtilities::GetArgOrEnvOrDefault("-T", argc, argv, "VTK_TEMP_DIR", "Testing/Temporary");
  Directory = temporary;
  delete[] temporary;
  TestProjected();
  TestNotGeoreferenced();
  TestTypesScaleAndVerticalScale();
  TestGeographic();
  TestWebMercator();
  TestLambertOnGrads();
  TestBadFiles();
  TestTiledRoundTrip();
  TestHorizonBands();
  TestWriterBlockRows();
  TestDegenerate();
  return vtkApertureTest::Result();
}
