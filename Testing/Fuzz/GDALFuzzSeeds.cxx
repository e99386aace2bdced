/*=========================================================================

  Program:   ApertureLighting
  Module:    GDALFuzzSeeds.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "GDALFuzzSeeds.h"

#include <cpl_string.h>
#include <cpl_vsi.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <cmath>
#include <string>

namespace
{
struct Spec
{
  const char* Name;
  GDALDataType Type;
  int EPSG;
  const char* Compress;
  bool Tiled;
};

std::string WKT(int epsg)
{
  OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
  OSRImportFromEPSG(srs, epsg);
  char* text = nullptr;
  OSRExportToWkt(srs, &text);
  std::string wkt = text ? text : "";
  CPLFree(text);
  OSRDestroySpatialReference(srs);
  return wkt;
}

// The bytes of a GDAL memory file, which is then removed.
std::vector<char> Take(const char* name)
{
  vsi_l_offset length = 0;
  GByte* bytes = VSIGetMemFileBuffer(name, &length, FALSE);
  std::vector<char> copy(bytes, bytes + length);
  VSIUnlink(name);
  return copy;
}

FuzzSeed GeoTIFF(const Spec& spec)
{
  const int nx = 12, ny = 9;
  const std::string name = std::string("/vsimem/") + spec.Name + ".tif";
  char** options = nullptr;
  options = spec.Compress ? CSLSetNameValue(options, "COMPRESS", spec.Compress) : options;
  if (spec.Tiled)
  {
    options = CSLSetNameValue(options, "TILED", "YES");
    options = CSLSetNameValue(options, "BLOCKXSIZE", "16");
    options = CSLSetNameValue(options, "BLOCKYSIZE", "16");
  }
  GDALDatasetH ds =
    GDALCreate(GDALGetDriverByName("GTiff"), name.c_str(), nx, ny, 1, spec.Type, options);
  CSLDestroy(options);
  double gt[6] = { 500000.0, 30.0, 0.0, 3900000.0, 0.0, -30.0 };
  if (spec.EPSG == 4326)
  {
    const double degrees[6] = { 138.7, 1.0 / 3600, 0.0, 35.4, 0.0, -1.0 / 3600 };
    std::copy(degrees, degrees + 6, gt);
  }
  GDALSetGeoTransform(ds, gt);
  if (spec.EPSG)
  {
    GDALSetProjection(ds, WKT(spec.EPSG).c_str());
  }
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  GDALSetRasterNoDataValue(band, spec.Type == GDT_UInt16 ? 0.0 : -9999.0);
  if (spec.Type == GDT_Float64)
  {
    GDALSetRasterScale(band, 0.5);
    GDALSetRasterOffset(band, 100.0);
  }
  std::vector<double> heights(nx * ny);
  for (int t = 0; t < nx * ny; ++t)
  {
    heights[t] =
      t == 40 ? -9999.0 : 200.0 + 50.0 * std::sin(0.7 * (t % nx)) * std::cos(0.5 * (t / nx));
  }
  CPLErr err =
    GDALRasterIO(band, GF_Write, 0, 0, nx, ny, heights.data(), nx, ny, GDT_Float64, 0, 0);
  GDALClose(ds);
  return FuzzSeed{ spec.Name, err == CE_None ? Take(name.c_str()) : std::vector<char>() };
}
}

std::vector<FuzzSeed> GDALFuzzSeeds()
{
  GDALAllRegister();
  std::vector<FuzzSeed> seeds;
  for (const Spec& spec : { Spec{ "int16-utm", GDT_Int16, 32654, nullptr, false },
         Spec{ "uint16-plain", GDT_UInt16, 0, nullptr, false },
         Spec{ "float32-geographic-deflate", GDT_Float32, 4326, "DEFLATE", true },
         Spec{ "float64-mercator-lzw", GDT_Float64, 3857, "LZW", false } })
  {
    seeds.push_back(GeoTIFF(spec));
  }
  return seeds;
}
