/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkGDALDEMReader.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkGDALDEMReader
 * @brief   reads a single-band DEM (GeoTIFF and the other rasters GDAL reads) as a height field
 *
 * The output is a 2D vtkImageData whose point scalars, a float array named `Elevation`, are the
 * band's values times the band's own scale plus offset, times VerticalScale (0.3048 for a DEM in
 * feet). Image row 0 is the southern row, as VTK orders images (GDAL's row 0 is the northern one).
 * Any integer or real band type reads (Byte, Int16, UInt16, Int32, UInt32, Float32, Float64);
 * complex bands and files of more than one band are errors.
 *
 * **Spacing.** The ground spacing comes from the geotransform, so that slopes, and with them
 * apertures, are right:
 * - projected CRS (UTM, national grids): the pixel size in the CRS's linear unit times its
 *   factor to metres; the origin is the first texel's centre in CRS coordinates. Where those
 *   are not ground metres (Web Mercator: sec φ of them, 1.22 at 35°), by more than 1% at the
 *   tile's centre, the ground distance of a pixel there;
 * - geographic CRS (degrees): metres per degree of the WGS 84 ellipsoid at the latitude of the
 *   tile's centre, so that the spacing is exact at the centre and off by the change of cos φ
 *   across the tile (a warning when that is more than 1%); the origin is then (0, 0). A tile
 *   that reaches a pole is an error;
 * - no georeferencing (no geotransform): spacing 1 (a warning), the file's first row the
 *   northern one, as images are seen.
 * Rotated or sheared geotransforms are an error. How the spacing was found is said in the
 * output's field data (`GroundSpacing`, one sentence) and by GetGroundSpacingNote().
 *
 * **No-data.** Texels equal to the band's no-data value, and values that are not finite, are
 * NaN in `Elevation` and 0 in the `vtkValidPointMask` point array (1 elsewhere; the array is only
 * there when some texel is no-data). vtkAperturePrecompute's horizon sweeps take them as neither
 * occluding nor receiving.
 *
 * **Georeferencing** goes with the data, as field data that vtkGDALGridWriter writes back:
 * `GeoOrigin` (CRS coordinates of texel (0, 0)'s centre), `GeoSpacing` (pixel size in CRS
 * units, both positive) and `SpatialReference` (the CRS as WKT, empty without one).
 *
 * **Streaming.** Only the update extent is read from the file: a DEM larger than memory goes
 * through a pipeline in tiles (see vtkAperturePrecompute and vtkGDALGridWriter).
 *
 * A missing, truncated or corrupt file, absurd spacings (not finite, under 1 mm or over 1000 km)
 * and a piece too large to allocate are errors with GDAL's own message where it has one.
 */

#ifndef vtkGDALDEMReader_h
#define vtkGDALDEMReader_h

#include "vtkApertureLightingIOGDALModule.h" // For export macro
#include "vtkImageAlgorithm.h"

#include <string> // For std::string

class vtkImageData;

class VTKAPERTURELIGHTINGIOGDAL_EXPORT vtkGDALDEMReader : public vtkImageAlgorithm
{
public:
  static vtkGDALDEMReader* New();
  vtkTypeMacro(vtkGDALDEMReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The raster file (or any name GDAL opens, such as /vsizip/ paths).
   */
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  ///@{
  /**
   * Factor from the band's unit to metres (or to whatever unit the spacing is in). Default 1.
   */
  vtkSetMacro(VerticalScale, double);
  vtkGetMacro(VerticalScale, double);
  ///@}

  /**
   * Whether GDAL can open the file as a raster.
   */
  static bool CanReadFile(const char* fileName);

  /**
   * After UpdateInformation(): how the ground spacing was found, in one sentence (also the
   * output's `GroundSpacing` field data).
   */
  const char* GetGroundSpacingNote() const { return this->GroundSpacingNote.c_str(); }

  /**
   * After UpdateInformation(): whether the file's CRS is geographic (degrees), and whether the
   * file has a geotransform at all (without one: spacing 1, its first row the northern one).
   */
  vtkGetMacro(Geographic, bool);
  vtkGetMacro(Georeferenced, bool);

  /**
   * After UpdateInformation(): degrees counter-clockwise from the grid's north (its +y axis) to
   * true north at the tile's centre, the meridian convergence of a projected CRS (-1.31 for a
   * UTM 54N tile at 138.7° E, 35.4° N, west of the zone's central meridian). The grid's
   * directions are azimuths on the grid; tools that take true directions, as GRASS's r.horizon
   * and r.sun do, need them turned by this much. 0 for a geographic CRS or none.
   */
  vtkGetMacro(GridConvergence, double);

  /**
   * The lowest and highest height of the whole file in metres (scale, offset and VerticalScale
   * applied; no-data left out), read through once: what a tile cannot know of the others, as
   * the height of vtkAperturePrecompute's no-data walls. False, after an error, when the file
   * cannot be read or holds no valid height.
   */
  bool ComputeHeightRange(double range[2]);

protected:
  vtkGDALDEMReader();
  ~vtkGDALDEMReader() override = default;

  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  std::string FileName;
  double VerticalScale = 1.0;

private:
  vtkGDALDEMReader(const vtkGDALDEMReader&) = delete;
  void operator=(const vtkGDALDEMReader&) = delete;

  class vtkRaster;
  bool FindGroundSpacing(const double geoTransform[6], std::string& error);
  bool ReadRows(vtkRaster& raster, const int extent[6], float* heights);
  bool MaskNoData(vtkRaster& raster, vtkImageData* output);

  // What RequestInformation found: the grid and its georeferencing.
  int Size[2] = { 0, 0 };
  double Spacing[2] = { 1.0, 1.0 };
  double Origin[2] = { 0.0, 0.0 };
  double GeoOrigin[2] = { 0.0, 0.0 };
  double GeoSpacing[2] = { 1.0, 1.0 };
  std::string SpatialReference;
  std::string GroundSpacingNote;
  bool Geographic = false;
  bool Georeferenced = false;
  bool NorthUp = true;
  double GridConvergence = 0.0;
};

#endif
