/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkGDALGridWriter.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkGDALGridWriter
 * @brief   writes point arrays of a 2D image as a georeferenced GeoTIFF, a tile at a time
 *
 * Each component of each chosen point array becomes one Float32 band, named after the array
 * (`ApertureRadius`; `BentNormal_X`, `_Y`, `_Z` for vectors; the array's component names where it
 * has them, as the horizons' `HorizonAngles_Az5.625`, ... do), its unit that of the array
 * (vtkDataArray::UNITS_LABEL(), as vtkAperturePrecompute sets it: `radian`, `degree`, `1`). By
 * default the arrays are those vtkAperturePrecompute writes (BentNormal, ApertureRadius,
 * AmbientOcclusion, HorizonAngles, SkyViewFactor, SkyViewFactorCosine, PositiveOpenness,
 * NegativeOpenness) that the input has, or else its scalars; AddArrayName() chooses others.
 *
 * **Georeferencing.** When the input carries vtkGDALDEMReader's field data (`GeoOrigin`,
 * `GeoSpacing`, `SpatialReference`), the file gets the DEM's CRS and a geotransform that puts every
 * texel where the DEM had it, also for a sub-extent; otherwise the image's origin and spacing
 * make the geotransform, without a CRS. Rows are written north-up (the image's top row first).
 *
 * **No-data.** Texels whose `vtkValidPointMask` is 0 are written as NaN, the bands' no-data value.
 *
 * **Streaming.** Write() asks the upstream pipeline for one tile of TileRows × TileColumns
 * texels at a time (its update extent), writes it and lets it go, so that only one tile (and
 * what the pipeline keeps for it) is in memory, whatever the size of the grid;
 * vtkAperturePrecompute then computes each tile from the tile grown by its MaximumDistance.
 * 0 rows or columns: the whole extent's. Each tile goes to GDAL 256 rows (a row of the file's
 * blocks) at a time, flushed out of GDAL's block cache once written, so that the writer itself
 * holds a few block rows even when the tile is the whole grid; tiles of multiples of 256 rows are
 * written without reading back. Arrays are read in their own type. The file is a tiled,
 * BigTIFF-when-needed GeoTIFF; with Compress on, DEFLATE with the floating-point predictor.
 *
 * An input that is not a 2D image, a missing array, a file that cannot be created, or an upstream
 * failure is an error, and no partial file is left behind.
 */

#ifndef vtkGDALGridWriter_h
#define vtkGDALGridWriter_h

#include "vtkApertureLightingIOGDALModule.h" // For export macro
#include "vtkImageAlgorithm.h"

#include <string> // For std::string
#include <vector> // For std::vector

class vtkImageData;

class VTKAPERTURELIGHTINGIOGDAL_EXPORT vtkGDALGridWriter : public vtkImageAlgorithm
{
public:
  static vtkGDALGridWriter* New();
  vtkTypeMacro(vtkGDALGridWriter, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The GeoTIFF to write.
   */
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  ///@{
  /**
   * The point arrays to write, in this order; none (the default): the aperture arrays the input
   * has, or its scalars.
   */
  void AddArrayName(const char* name);
  void ClearArrayNames();
  int GetNumberOfArrayNames() const { return static_cast<int>(this->ArrayNames.size()); }
  const char* GetArrayName(int i) const;
  ///@}

  ///@{
  /**
   * Rows and columns of the tiles requested from the pipeline; 0: the whole extent's. Default
   * 1024 rows of the whole width.
   */
  vtkSetClampMacro(TileRows, int, 0, VTK_INT_MAX);
  vtkGetMacro(TileRows, int);
  vtkSetClampMacro(TileColumns, int, 0, VTK_INT_MAX);
  vtkGetMacro(TileColumns, int);
  ///@}

  ///@{
  /**
   * DEFLATE compression with the floating-point predictor. Default off (faster to write).
   */
  vtkSetMacro(Compress, bool);
  vtkGetMacro(Compress, bool);
  vtkBooleanMacro(Compress, bool);
  ///@}

  ///@{
  /**
   * Write a cloud-optimised GeoTIFF (GDAL's COG driver: 512² blocks in the order HTTP range
   * reads want, overviews averaged down to one block, DEFLATE with a predictor when Compress is
   * on). The tiles go first to a plain GeoTIFF beside FileName (`FileName.writing.tif`), which
   * is copied and removed, so that the disk needs room for both while it is written. Default off.
   */
  vtkSetMacro(CloudOptimized, bool);
  vtkGetMacro(CloudOptimized, bool);
  vtkBooleanMacro(CloudOptimized, bool);
  ///@}

  /**
   * Writes the file. Returns 1 on success, 0 after an error.
   */
  int Write();

  /**
   * Copies band `band` (from 1) of the written file into a single-band GeoTIFF of its own
   * (tiled, DEFLATE-compressed when Compress is on), with the file's georeferencing and the
   * band's name, unit and no-data value: GRASS's r.sun, for one, reads a horizon per file.
   * Returns 1 on success, 0 after an error (no file left behind).
   */
  int WriteBandCopy(int band, const char* fileName);

protected:
  vtkGDALGridWriter();
  ~vtkGDALGridWriter() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;

  std::string FileName;
  std::vector<std::string> ArrayNames;
  int TileRows = 1024;
  int TileColumns = 0;
  bool Compress = false;
  bool CloudOptimized = false;

private:
  vtkGDALGridWriter(const vtkGDALGridWriter&) = delete;
  void operator=(const vtkGDALGridWriter&) = delete;

  class vtkFile;
  vtkImageData* UpdateTile(const int extent[6]);
  bool ChooseArrays(vtkImageData* image, std::vector<std::string>& names);
  bool CreateFile(
    vtkFile& file, vtkImageData* image, const int whole[6], std::vector<std::string>& arrays);
  bool WriteTile(vtkFile& file, vtkImageData* image, const int tile[6], const int whole[6],
    const std::vector<std::string>& arrays, std::vector<float>& buffer);
};

#endif
