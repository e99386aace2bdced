/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkHorizonHeightField.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkHorizonHeightField
 * @brief   vtkHorizonApertures on a vtkImageData height field (private)
 *
 * Takes the heights of an image (any scalar type, times a height scale) and its no-data texels
 * (heights that are not finite, and texels whose `vtkValidPointMask` point array is 0) to the
 * horizon sweeps, in the grid's own frame: x along i, y along j at the image's spacing, z along
 * its third axis. The results go back as point arrays of the output extent, their directions in
 * world coordinates (the image's direction matrix), as vtkAperturePrecompute writes them.
 *
 * @sa vtkHorizonApertures vtkAperturePrecompute
 */

#ifndef vtkHorizonHeightField_h
#define vtkHorizonHeightField_h

#include "vtkApertureLightingCoreModule.h" // For export macro
#include "vtkType.h"

#include <functional>
#include <limits>
#include <string>

class vtkDataArray;
class vtkImageData;
class vtkPointData;

class VTKAPERTURELIGHTINGCORE_EXPORT vtkHorizonHeightField
{
public:
  /// What to compute, and the names of the arrays to write.
  struct Settings
  {
    double HeightScale = 1.0;
    int Sectors = 32;
    double MaximumDistance = VTK_DOUBLE_MAX;
    bool AmbientOcclusion = false;
    bool Normals = true; ///< "Normals", unless the output has normals
    bool Horizons = false;
    bool SkyViewFactor = false;       ///< "SkyViewFactor"
    bool SkyViewFactorCosine = false; ///< "SkyViewFactorCosine"
    bool PositiveOpenness = false;    ///< "PositiveOpenness"
    bool NegativeOpenness = false;    ///< "NegativeOpenness"
    /// Degrees counter-clockwise from the grid's i axis where sector 0 starts.
    double SectorRotation = 0.0;
    /// Radius of the sphere the ground lies on, world units; 0: flat (vtkHorizonApertures).
    double EarthRadius = 0.0;
    /// No-data texels: Open (neither occlude nor receive), Wall, of WallHeight (NaN: the
    /// highest valid height of the window swept), occluding but getting no output, or Fill,
    /// from the valid texels within FillDistance texels (vtkAperturePrecompute::SetNoDataAs()),
    /// then computed as the others. The values are vtkAperturePrecompute's NO_DATA_*.
    enum NoDataTreatment
    {
      Open = 0,
      Wall = 1,
      Fill = 2
    };
    int NoDataAs = Open;
    double WallHeight = std::numeric_limits<double>::quiet_NaN();
    int FillDistance = 64;
    const char* BentNormalName = "BentNormal";
    const char* RadiusName = "ApertureRadius";
    const char* OcclusionName = "AmbientOcclusion";
    const char* HorizonName = "HorizonAngles";
  };

  /**
   * Computes the apertures of `extent` (within the image's extent, whose texels occlude) and adds
   * them to `output` (the point data of a grid of that extent): the bent normals, radii, ambient
   * occlusion, horizons (in the grid's frame, Sectors components named by their middle azimuths)
   * and terrain products if asked, each with its unit (vtkDataArray::UNITS_LABEL()), "Normals"
   * (those of the triangulated surface, which the sweeps use) if asked and `output` has none, and,
   * where there is no-data, the valid mask. `progress` as for vtkHorizonApertures::Compute().
   * Returns the number of no-data texels in the extent, or -1 with one sentence in `error`.
   */
  static vtkIdType Compute(vtkImageData* image, vtkDataArray* heights, const int extent[6],
    const Settings& settings, vtkPointData* output, std::string& error,
    const std::function<bool(double fraction)>& progress = nullptr);

  /**
   * Texels of halo that a tile needs around it so that its apertures equal the whole grid's:
   * the search radius in texels of the finer spacing, 2 for the interpolation, and `fill` more
   * when no-data is filled from that far; -1 without a radius (the whole grid).
   */
  static int Halo(double maximumDistance, const double spacing[3], int fill = 0);
};

#endif
// VTK-HeaderTest-Exclude: vtkHorizonHeightField.h
