/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkHorizonApertures.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkHorizonApertures
 * @brief   per-texel apertures of a height field from horizon angles, without rays (private)
 *
 * Casting rays from every texel of a 10,000 × 10,000 DEM costs hours; horizons give the same
 * visibility of a height field in time linear in texels × azimuth sectors. For each of D
 * sectors (sector k covers azimuths [2πk/D, 2π(k+1)/D) from +x toward +y; its middle direction
 * φ stands for it), the horizon h(φ) of a texel is the largest elevation angle
 * atan((z(q) − z(p)) / |q − p|) over the samples q along its ray within MaximumDistance (−π/2
 * without any). With the tangent-plane elevation e(φ) = atan(−(n_x cos φ + n_y sin φ) / n_z)
 * and a = max(h, e), the sector's visible elevations are a … π/2, which gives per sector the
 * solid angle Δφ (1 − sin a) and ∫ω dω; summed: the visible solid angle A, the aperture radius
 * r = acos(1 − A / 2π), the bent normal (∫ω dω normalised) and the ambient occlusion
 * (1/π) n · ∫ω dω. The sums are kept as what each sector takes away from the open hemisphere
 * (a = 0 everywhere: A = 2π, ∫ω dω = (0, 0, π)), so that an open plane loses nothing to
 * single-precision rounding.
 *
 * Samples (Timonen and Westerholm 2010, "Scalable Height Field Self-Shadowing"). The major axis
 * of a direction is i where |cos φ| / Dx ≥ |sin φ| / Dy, else j. Lines of the direction cross
 * the grid one per integer offset along the minor axis, anchored on the whole DEM's indices
 * (Origin), and have one sample per integer major index, its height interpolated between the
 * two nearest texels along the minor axis (one within 1e-9 texel of a texel is on it: along
 * the axes and diagonals, where rounding would otherwise make it need a neighbour off the
 * grid's edge); samples Δ = Dx / |cos φ| (or Dy / |sin φ|) apart.
 * Each texel is the nearest texel of exactly one line sample, at minor offset fr in
 * [−1/2, 1/2): that sample is where the texel looks from, at the sample's height (the texel's
 * tangent plane at the sample where the interpolation needs a no-data texel or one off the
 * grid), so that a plane stays exactly open. A sample that needs such a texel does not occlude.
 *
 * Sweep. Each line is swept against the direction, so that the samples a receiver's ray meets
 * come before it. Without a radius, a stack holds the upper convex hull of the samples seen:
 * a new sample pops the hull points that the one below them overtops as seen from it; the top
 * is then its horizon, and it is pushed (amortised O(1)). With MaximumDistance, W = the number
 * of samples within it (the largest w with w Δ ≤ MaximumDistance; without a radius, more than
 * a line has): the line is cut into blocks of W samples; a receiver in block b takes the better
 * of a hull restarted at the start of block b, and the upper hull of the suffix of block b − 1
 * within W samples of it. Those
 * suffix hulls are all built by one backward sweep over block b − 1 with a stack that records
 * what each push overwrote; undoing the pushes one by one gives the hulls of ever shorter
 * suffixes as the receivers advance, and a binary search on the unimodal elevations along a
 * hull finds the tangent (O(log W)), unless the suffix's highest sample at its nearest
 * distance cannot beat the current block's horizon. The result is the exact maximum over the
 * samples in range, so that a tile with a halo of MaximumDistance + 2 texels, given its Origin,
 * gets what the whole DEM gets.
 *
 * Lines are swept in parallel, in groups of adjacent lines that read and write neighbouring
 * texels together; opposite sectors (φ and φ + π) share their lines, so that one pass gathers
 * the samples and adds to the texels for both, sweeping each line both ways. What a pass's
 * sectors take from each receiver of a line is computed right after its sweeps, in a loop over
 * the line's samples without branches that the compiler vectorises (GCC and Clang build the
 * file without errno from sqrt and without FP traps for that); the scatter then adds four
 * floats per texel, besides the horizons and the terrain products (per texel, with a branchy
 * arctangent, this was half the sweeps' time). Each texel is
 * written by one line per pass and passes are summed in order, so that results do not depend
 * on threads. Per-texel sums live in the output arrays until the last pass (33 bytes per
 * output texel in all, besides the input and the threads' buffers of a group of lines). Kept
 * horizons (Buffers::Horizons, 4 bytes a sector) are written into their own array, sector-major
 * in blocks of 1024 texels, which one pass turns into per-texel records at the end.
 *
 * Terrain products, from the same horizons (h⁺ the horizon, h⁻ that of the negated heights,
 * i.e. minus the lowest elevation angle, which the same lines give by a second sweep of their
 * negated samples): the sky-view factor Ω/2π of the sky above the horizontal plane (Zakšek et
 * al. 2011), 1 − Σ Δφ sin(max(h⁺, 0)) / 2π; its cosine-weighted form (Häntzschel et al. 2005,
 * SAGA's SVF), (1/π) ∫ n·ω over the sky above max(h⁺, 0), integrated per sector as the
 * apertures are, without clipping at the tangent plane; and the openness of Yokoyama et al.
 * (2002), the mean over sectors of 90° − h⁺ (positive) and 90° − h⁻ (negative), in degrees,
 * over the sectors that have a sample in range (NaN where none has).
 *
 * Normals are those of the triangulated surface vtkAperturePrecompute's rays see (cells split
 * as (i,j)(i+1,j)(i+1,j+1) and (i,j)(i+1,j+1)(i,j+1)): the normalised sum of the unit normals of
 * a texel's up to six triangles with valid corners, so that both methods measure the same
 * hemisphere (central differences differ from them by 1.7° on the Fuji tile; with them the
 * visible fraction was 0.0103 RMS from 4096 rays per texel, with these 0.0088). No-data texels
 * (Valid 0, or a height that is not finite) neither occlude nor receive.
 *
 * Earth curvature (Grid::EarthRadius): a sample d away counts d²/2R lower. On a line with
 * positions a Δ, that is the same hull search over heights lowered by Δ² a²/2R, whose slopes
 * then differ from the curved ground's by a term linear in the receiver's a (derived beside
 * Uncurve()); the search stays exact, and tiles still equal the whole DEM.
 */

#ifndef vtkHorizonApertures_h
#define vtkHorizonApertures_h

#include "vtkApertureLightingCoreModule.h" // For export macro
#include "vtkType.h"

#include <functional>
#include <string>
#include <vector>

class VTKAPERTURELIGHTINGCORE_EXPORT vtkHorizonApertures
{
public:
  /// A height field and what to compute on it.
  struct Grid
  {
    /// Nx × Ny heights, i fastest (i + j Nx), vertical scale applied.
    const float* Heights = nullptr;
    /// Per texel, 0 for no-data; nullptr: all valid.
    const unsigned char* Valid = nullptr;
    /// Per texel, 0 for a valid texel that occludes but gets no output (no-data taken as a
    /// wall): closed, as no-data texels are; nullptr: every valid texel receives.
    const unsigned char* Receives = nullptr;
    vtkIdType Nx = 0;
    vtkIdType Ny = 0;
    ///@{
    /// Ground spacing along i (+x, east) and j (+y, north).
    double Dx = 1.0;
    double Dy = 1.0;
    ///@}
    /// Azimuth sectors (D).
    int Sectors = 16;
    /// Search radius in world units; VTK_DOUBLE_MAX or infinity: unlimited.
    double MaximumDistance = VTK_DOUBLE_MAX;
    /// Texels to compute outputs for: i in [OutputExtent[0], OutputExtent[1]], j in
    /// [OutputExtent[2], OutputExtent[3]]; an empty extent (the default) is the whole grid.
    vtkIdType OutputExtent[4] = { 0, -1, 0, -1 };
    /// Index of texel (0, 0) in the whole DEM, on which the lines are anchored: a tile passes
    /// its offset so that it samples as the whole DEM does.
    vtkIdType Origin[2] = { 0, 0 };
    /// Where sector 0 starts, radians counter-clockwise from +x: sector k covers
    /// [SectorRotation + 2πk/D, SectorRotation + 2π(k+1)/D). GRASS's r.horizon directions are
    /// sector middles with SectorRotation = start − π/D.
    double SectorRotation = 0.0;
    /// Radius of the sphere the ground lies on, in world units (6,371,000 for the Earth in
    /// metres); 0 (default): flat ground. A sample d away lies d²/2R lower, as GRASS's
    /// r.horizon and r.sun take it.
    double EarthRadius = 0.0;
  };

  /// The caller's arrays for the output extent (i fastest): 3, 1, 1, 3, 1 and Sectors values
  /// per texel.
  struct Buffers
  {
    float* BentNormals;      ///< unit; the normal where not valid
    float* ApertureRadius;   ///< radians; 0 where not valid
    float* AmbientOcclusion; ///< 1 on an open plane; 0 where not valid; may be null
    /// (0, 0, 1) where not valid; may be null: the sweeps then keep each normal in 4 bytes
    /// (octahedral, within 7.5e-5 rad) in AmbientOcclusion's array until they write it, or in
    /// an array of their own without AO; the outputs move by less than 1e-4.
    float* Normals;
    unsigned char* Valid; ///< 0 for no-data texels
    /// The horizon h of each sector (sector k at k + Sectors × texel), radians; π/2 (closed)
    /// where not valid; may be null.
    float* Horizons = nullptr;
    ///@{
    /// Terrain products (see the class description): the sky-view factors in [0, 1], the
    /// openness in degrees; NaN where not valid; each may be null.
    float* SkyViewFactor = nullptr;
    float* SkyViewFactorCosine = nullptr;
    float* PositiveOpenness = nullptr;
    float* NegativeOpenness = nullptr;
    ///@}
  };

  /// Per texel of the output extent, i fastest, in arrays of its own.
  struct Apertures
  {
    vtkIdType Nx = 0;
    vtkIdType Ny = 0;
    std::vector<float> BentNormals;      ///< 3 each, unit; (0, 0, 1) where not valid
    std::vector<float> ApertureRadius;   ///< radians; 0 where not valid
    std::vector<float> AmbientOcclusion; ///< 1 on an open plane; 0 where not valid
    std::vector<float> Normals;          ///< 3 each; (0, 0, 1) where not valid
    std::vector<unsigned char> Valid;    ///< 0 for no-data texels
  };

  /**
   * Computes the apertures of the grid's output extent into the caller's buffers (sized by
   * GetOutputSize()), or into arrays of the output's own. `progress` is called after each pass
   * (a sector, or with an even number of sectors a sector and its opposite) with the fraction
   * done; when it returns false, Compute() stops and fails (owned arrays are cleared). Returns
   * false with one sentence in `error` for unusable input or an abort.
   */
  static bool Compute(const Grid& grid, const Buffers& output, std::string& error,
    const std::function<bool(double fraction)>& progress = nullptr);
  static bool Compute(const Grid& grid, Apertures& output, std::string& error,
    const std::function<bool(double fraction)>& progress = nullptr);

  /**
   * The size of the grid's output extent (what Buffers must hold); false with one sentence in
   * `error` for unusable input.
   */
  static bool GetOutputSize(const Grid& grid, vtkIdType& nx, vtkIdType& ny, std::string& error);

  /**
   * The horizon h of one sector (0 … Sectors − 1) per texel of the output extent, as Compute()
   * uses it: −π/2 without any sample in range, NaN for no-data texels. For checks, and for
   * callers that need the horizons themselves.
   */
  static bool ComputeHorizons(
    const Grid& grid, int sector, std::vector<float>& horizons, std::string& error);

  /**
   * Adds to `deficit` what azimuths [phi0, phi1) with visible elevations a … π/2 take away
   * from the open hemisphere, ∫∫ over elevations 0 … a (negative below 0): the solid angle,
   * then ∫ω dω (3 components). The open hemisphere less the deficits of all sectors is what a
   * texel sees.
   */
  static void AddSectorDeficit(double phi0, double phi1, double a, double deficit[4]);
};

#endif
// VTK-HeaderTest-Exclude: vtkHorizonApertures.h
