/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkAperturePrecompute.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkAperturePrecompute
 * @brief   per-vertex or per-texel visibility caps for ambient aperture lighting
 *
 * vtkAperturePrecompute is the preprocessing stage of ambient aperture lighting (Oat & Sander
 * 2007). For every point of a surface it casts NumberOfRays rays over the hemisphere around the
 * point's normal with Embree and summarises what it sees as a spherical cap, the aperture:
 *
 * - `BentNormal` (float, 3 components, unit, world space): the normalised mean unoccluded
 *   direction V = normalize(∫ V(p, ω) ω dω), uniform over solid angle as in the paper;
 * - `ApertureRadius` (float, radians in [0, π/2]): r = acos(1 − A/2π), A the visible solid angle;
 * - optionally `AmbientOcclusion` (float in [0, 1]): the cosine-weighted visible fraction
 *   (1/π) ∫ V(p, ω) max(n·ω, 0) dω, the usual ambient occlusion, which is 1 for an open plane.
 *
 * Input port 0 takes
 * - a vtkPolyData: polygons and triangle strips cast and receive rays; vertices and lines are
 *   kept in the output but neither cast nor receive (points used only by them get an open
 *   aperture, r = π/2, around their normal, or +z without one);
 * - a vtkImageData height field (the per-texel mode): a 2D grid whose point scalars (the input
 *   array to process) are heights. Grid point (i, j) sits at the image's physical position of
 *   (i, j, 0) raised by HeightScale × height along the grid's third axis; the surface is
 *   triangulated as (i,j)(i+1,j)(i+1,j+1) and (i,j)(i+1,j+1)(i,j+1). The output is the same grid
 *   with one cap per grid point, ready to be used as a texture. By default its visibility comes
 *   from horizon sweeps, not rays (see SetMethod()), and the filter streams: an update extent
 *   smaller than the grid is computed from that extent grown by MaximumDistance, so that a
 *   large DEM goes through in tiles whose results equal the whole grid's;
 * - a composite dataset of vtkPolyData: every leaf occludes every other and each leaf gets its
 *   arrays.
 *
 * Input port 1 (optional, repeatable, AddOccluderConnection()) takes extra vtkPolyData
 * occluders that cast shadows but get no output.
 *
 * Real meshes (see vtkApertureSurface for how): points at the same position are one surface
 * point, with one aperture, whatever the file's texture seams split; triangles are wound
 * consistently; a crease (an edge whose faces' normals differ by more than FeatureAngle, or
 * given normals further apart) gives each side its own normal and aperture. When the input
 * shares a point across a crease the output splits it, as vtkPolyDataNormals does, copying its
 * point data; otherwise the output has the input's points and cells. MaximumEdgeLength > 0
 * refines the surface first: the output is then the refined surface, its point data
 * interpolated. A point lying on another surface sees the open half of its hemisphere (contact),
 * and folded or sliver triangles of its own do not close it (self-hits): see vtkApertureRayScene.
 *
 * The output has the input's type and keeps every input array; the input is never modified. When
 * the input has no usable point normals, the normals that were used are added as `Normals`
 * (the normalised sums of the unit normals of each side's triangles; the +z side of the grid for
 * height fields).
 *
 * Sampling is deterministic: the Hammersley set of NumberOfRays points, uniform over the
 * hemisphere's solid angle, shifted per point by a Cranley-Patterson rotation derived from Seed
 * and the point's position (SetSamplingToRandom() draws independent uniform samples instead, for
 * comparison). Rays start RayOffset × (mean length of the point's edges) above the point along its
 * normal, at least far enough to clear single-precision rounding, and stop at MaximumDistance
 * when LimitDistance is on.
 * Geometry is translated to a local origin before it reaches Embree, so UTM-sized coordinates
 * (1e5 to 1e7) keep their precision.
 *
 * Rays are traced in packets of 16 (rtcOccluded16) over blocks of points with vtkSMPTools, in
 * batches of about a million rays; progress is reported and AbortExecute checked between
 * batches. An aborted run produces an empty output.
 *
 * Points that are not finite (or larger than 1e16, beyond what Embree traces), or whose normal
 * is undefined, get a closed aperture (r = 0) with
 * BentNormal (0, 0, 1) and one warning. Empty input, input without polygons or strips, a cell
 * with a point id outside the points, image data that is not a 2D grid with one-component
 * scalars, and Embree failures are errors.
 *
 * @sa vtkSphericalCap vtkApertureLightingMapper
 */

#ifndef vtkAperturePrecompute_h
#define vtkAperturePrecompute_h

#include "vtkApertureLightingCoreModule.h" // For export macro
#include "vtkPassInputTypeAlgorithm.h"

#include <limits> // For std::numeric_limits
#include <memory> // For std::unique_ptr
#include <string> // For std::string

class vtkApertureHistory;
class vtkMultiProcessController;

class VTKAPERTURELIGHTINGCORE_EXPORT vtkAperturePrecompute : public vtkPassInputTypeAlgorithm
{
public:
  static vtkAperturePrecompute* New();
  vtkTypeMacro(vtkAperturePrecompute, vtkPassInputTypeAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Extra occluders (vtkPolyData) on input port 1: they cast shadows but get no output.
   */
  void AddOccluderConnection(vtkAlgorithmOutput* output);
  void AddOccluderData(vtkDataObject* data);
  void RemoveAllOccluders();
  ///@}

  ///@{
  /**
   * Rays per point, in [1, 65536]. Default 256.
   */
  vtkSetClampMacro(NumberOfRays, int, 1, 65536);
  vtkGetMacro(NumberOfRays, int);
  ///@}

  ///@{
  /**
   * Whether visibility is searched only up to MaximumDistance: rays stop there and horizons
   * ignore the ground beyond, for local occlusion (and so that a height field streams in tiles
   * of bounded overlap). Default off: occluders count however far they are.
   */
  vtkSetMacro(LimitDistance, bool);
  vtkGetMacro(LimitDistance, bool);
  vtkBooleanMacro(LimitDistance, bool);
  ///@}

  ///@{
  /**
   * The distance (world units) visibility is searched to when LimitDistance is on; ignored when
   * it is off. Default VTK_DOUBLE_MAX.
   */
  vtkSetClampMacro(MaximumDistance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumDistance, double);
  ///@}

  ///@{
  /**
   * Ray start offset along the normal, relative to the mean length of the point's edges (the
   * grid spacing for height fields), in [0, 1]. Default 0.001.
   */
  vtkSetClampMacro(RayOffset, double, 0.0, 1.0);
  vtkGetMacro(RayOffset, double);
  ///@}

  ///@{
  /**
   * Seed of the per-point sample rotations (or of the random samples). Default 0.
   */
  vtkSetMacro(Seed, int);
  vtkGetMacro(Seed, int);
  ///@}

  enum Sampling
  {
    STRATIFIED = 0,
    RANDOM = 1
  };

  ///@{
  /**
   * STRATIFIED (default): a rotated Hammersley set; RANDOM: independent uniform samples.
   */
  vtkSetClampMacro(Sampling, int, STRATIFIED, RANDOM);
  vtkGetMacro(Sampling, int);
  void SetSamplingToStratified() { this->SetSampling(STRATIFIED); }
  void SetSamplingToRandom() { this->SetSampling(RANDOM); }
  ///@}

  ///@{
  /**
   * Height field mode: heights are multiplied by this factor. Default 1.
   */
  vtkSetMacro(HeightScale, double);
  vtkGetMacro(HeightScale, double);
  ///@}

  ///@{
  /**
   * Also write the cosine-weighted visible fraction. Default off.
   */
  vtkSetMacro(ComputeAmbientOcclusion, bool);
  vtkGetMacro(ComputeAmbientOcclusion, bool);
  vtkBooleanMacro(ComputeAmbientOcclusion, bool);
  ///@}

  ///@{
  /**
   * Add the normals the apertures were computed against as `Normals` when the input has none.
   * Default on. Off saves 12 bytes a point where only the apertures are wanted (aperture-precompute
   * writes no normals): the horizon sweeps then keep each texel's normal in 4 bytes (octahedral,
   * within 7.5e-5 rad) in the AmbientOcclusion array until they write it (in 4 bytes of their own
   * without AO), and the outputs move by less than 1e-4; rays give the same bits.
   */
  vtkSetMacro(ComputeNormals, bool);
  vtkGetMacro(ComputeNormals, bool);
  vtkBooleanMacro(ComputeNormals, bool);
  ///@}

  ///@{
  /**
   * Also keep the horizon of every sector (height fields swept for horizons only; with rays the
   * filter warns and writes none). Default off. `HorizonAngles` (float, NumberOfSectors
   * components) holds per texel h_k, radians above the horizontal plane in [−π/2, π/2]: the
   * elevation of the highest sample within MaximumDistance along the middle of sector k, which
   * covers the azimuths [2πk/S, 2π(k+1)/S) counted from the grid's i axis toward its j axis
   * (counter-clockwise from east on a north-up DEM), in the grid's own frame; −π/2 where nothing
   * is in range, π/2 (closed) at no-data texels. vtkHorizonLighting shades from them (the
   * mappers' Horizon mode); they cost 4 bytes per sector and texel.
   */
  vtkSetMacro(ComputeHorizonAngles, bool);
  vtkGetMacro(ComputeHorizonAngles, bool);
  vtkBooleanMacro(ComputeHorizonAngles, bool);
  ///@}

  ///@{
  /**
   * Terrain products of the same horizons (height fields swept for horizons only; with rays the
   * filter warns and writes none), each a float point array, NaN at no-data texels, its unit in
   * vtkDataArray::UNITS_LABEL(). Default off.
   * - `SkyViewFactor`: Ω/2π, the visible fraction of the sky above the horizontal plane
   *   (Zakšek et al. 2011; RVT's SVF): 1 − (1/D) Σ sin(max(h_k, 0)).
   * - `SkyViewFactorCosine`: the cosine-weighted sky-view factor (Häntzschel et al. 2005;
   *   SAGA's `SVF`): (1/π) ∫ n·ω dω over the sky above max(h_k, 0), not clipped at the tangent
   *   plane. It equals `AmbientOcclusion` where every horizon is at or above both the horizontal
   *   and the tangent plane (valleys, pits); elsewhere AmbientOcclusion counts the tangent
   *   hemisphere below the horizontal as open and this does not ((1 + cos slope)/2 on a plane).
   * - `PositiveOpenness`, `NegativeOpenness` (degrees): Yokoyama et al. (2002) within
   *   MaximumDistance, the mean of 90° − h_k and of 90° + (the lowest elevation angle in sector
   *   k), over the sectors with a sample in range (edges of the grid see fewer; NaN with none).
   *   The negative one sweeps the negated heights too: about 1.6 times the time.
   */
  vtkSetMacro(ComputeSkyViewFactor, bool);
  vtkGetMacro(ComputeSkyViewFactor, bool);
  vtkBooleanMacro(ComputeSkyViewFactor, bool);
  vtkSetMacro(ComputeSkyViewFactorCosine, bool);
  vtkGetMacro(ComputeSkyViewFactorCosine, bool);
  vtkBooleanMacro(ComputeSkyViewFactorCosine, bool);
  vtkSetMacro(ComputePositiveOpenness, bool);
  vtkGetMacro(ComputePositiveOpenness, bool);
  vtkBooleanMacro(ComputePositiveOpenness, bool);
  vtkSetMacro(ComputeNegativeOpenness, bool);
  vtkGetMacro(ComputeNegativeOpenness, bool);
  vtkBooleanMacro(ComputeNegativeOpenness, bool);
  ///@}

  ///@{
  /**
   * Degrees counter-clockwise from the grid's i axis where sector 0 of the horizon sweeps
   * starts. Default 0: sector k covers [360k/D, 360(k+1)/D). GRASS's r.horizon directions
   * start, start + step, … are the sectors' middles with SectorRotation = start − 180/D. The
   * mappers' Horizon mode expects 0 (it warns otherwise).
   */
  vtkSetMacro(SectorRotation, double);
  vtkGetMacro(SectorRotation, double);
  ///@}

  ///@{
  /**
   * Radius of the sphere a height field's ground lies on, in its horizontal world units:
   * 6371000 for the Earth in metres (GRASS's r.horizon and r.sun take that), R / (1 − k) to
   * count refraction of coefficient k. A sample at distance d then lies d²/2R lower as seen
   * from a texel: 7.8 m at 10 km, 785 m at 100 km. Default 0: flat ground. Horizon sweeps
   * only (the filter warns with rays); every output sees the curved ground.
   */
  vtkSetMacro(EarthRadius, double);
  vtkGetMacro(EarthRadius, double);
  ///@}

  enum NoDataTreatments
  {
    NO_DATA_OPEN = 0,
    NO_DATA_WALL = 1,
    NO_DATA_FILL = 2
  };

  ///@{
  /**
   * What the horizon sweeps make of a height field's no-data texels (not finite, or 0 in
   * `vtkValidPointMask`). NO_DATA_OPEN (default): they neither occlude nor receive (closed
   * apertures, NaN products). NO_DATA_WALL: they block like a cliff as high as
   * NoDataWallHeight (NaN, the default: the highest valid height of the texels swept, which a
   * tile knows only of itself and its halo: set it, e.g. from vtkGDALDEMReader's
   * ComputeHeightRange(), when streaming) and still get no output. NO_DATA_FILL: their heights
   * are interpolated linearly between the nearest valid texels within NoDataFillDistance
   * texels on both sides along the row, the column and the two diagonals through them, the
   * lines weighted by 1/span² (planes are filled exactly, where GDAL's FillNodata, inverse
   * distance weighting, leaves bumps on slopes; one-sided texels by 1/d² where no line has
   * both), and they get outputs like the others; texels no valid one reaches stay no-data. Tiles
   * grow their halo by NoDataFillDistance so that they still equal the whole grid. With rays the
   * filter warns and keeps no-data open.
   */
  vtkSetClampMacro(NoDataAs, int, NO_DATA_OPEN, NO_DATA_FILL);
  vtkGetMacro(NoDataAs, int);
  void SetNoDataAsToOpen() { this->SetNoDataAs(NO_DATA_OPEN); }
  void SetNoDataAsToWall() { this->SetNoDataAs(NO_DATA_WALL); }
  void SetNoDataAsToFill() { this->SetNoDataAs(NO_DATA_FILL); }
  vtkSetMacro(NoDataWallHeight, double);
  vtkGetMacro(NoDataWallHeight, double);
  vtkSetClampMacro(NoDataFillDistance, int, 1, 100000);
  vtkGetMacro(NoDataFillDistance, int);
  ///@}

  ///@{
  /**
   * Also keep which cells of each point's hemisphere are open, for points that cast rays
   * (horizon sweeps warn and keep none). Default off. `VisibilityMask` (unsigned char,
   * VisibilityMaskBits / 8 components) holds one bit per cell of vtkVisibilityMask's equal-area
   * grid in the point's tangent frame (cell k at bit k % 8 of component k / 8), 1 for open: a
   * cell is open when at least half of its VisibilityMaskRaysPerCell rays, on a stratified
   * sub-grid of the cell, escape, under the same contact and self-hit rules as the aperture's
   * rays. They cost VisibilityMaskBits × VisibilityMaskRaysPerCell rays a point more: 256 at the
   * defaults, 2.0 times the time of the apertures alone on the bunny. The cells' size, not their
   * rays, limits the accuracy (bunny, light at 60°, r = 0.064, 95th-percentile error: 26% with
   * 1, 4 or 9 rays a cell, which cost 2.0, 4.5 and 7.6 times; 60% with 64 cells, 11% with 1024).
   * Points that cast no rays get a closed mask (no-data) or an open one (points on no polygon),
   * as their apertures are.
   */
  vtkSetMacro(ComputeVisibilityMask, bool);
  vtkGetMacro(ComputeVisibilityMask, bool);
  vtkBooleanMacro(ComputeVisibilityMask, bool);
  ///@}

  ///@{
  /**
   * Cells of the mask: 64, 144, 256 (default, 32 bytes a point), 400, 576, 784 or 1024; rays per
   * cell: 1 (default), 4, 9 or 16. Other values are an error when the mask is asked for.
   */
  vtkSetMacro(VisibilityMaskBits, int);
  vtkGetMacro(VisibilityMaskBits, int);
  vtkSetMacro(VisibilityMaskRaysPerCell, int);
  vtkGetMacro(VisibilityMaskRaysPerCell, int);
  ///@}

  ///@{
  /**
   * Names of the output arrays. Defaults: "BentNormal", "ApertureRadius", "AmbientOcclusion",
   * "HorizonAngles", "VisibilityMask".
   */
  vtkSetStdStringFromCharMacro(BentNormalArrayName);
  vtkGetCharFromStdStringMacro(BentNormalArrayName);
  vtkSetStdStringFromCharMacro(ApertureRadiusArrayName);
  vtkGetCharFromStdStringMacro(ApertureRadiusArrayName);
  vtkSetStdStringFromCharMacro(AmbientOcclusionArrayName);
  vtkGetCharFromStdStringMacro(AmbientOcclusionArrayName);
  vtkSetStdStringFromCharMacro(HorizonAnglesArrayName);
  vtkGetCharFromStdStringMacro(HorizonAnglesArrayName);
  vtkSetStdStringFromCharMacro(VisibilityMaskArrayName);
  vtkGetCharFromStdStringMacro(VisibilityMaskArrayName);
  ///@}

  ///@{
  /**
   * Creases: where the normals of two faces sharing an edge differ by more than this angle
   * (degrees, 0 to 180), each side gets its own normal and aperture; with given normals, points
   * welded together whose normals differ by more. Default 60: the 90 degree edges of CAD parts
   * split, tessellated curves of 8 or more segments and the noise of scans do not. 180 never
   * splits.
   */
  vtkSetClampMacro(FeatureAngle, double, 0.0, 180.0);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /**
   * Polydata only: when positive, triangles are split until no edge is longer (world units), so
   * that large faces get points enough for contact shadows; the output is then the refined
   * surface. Default 0: no refinement.
   */
  vtkSetClampMacro(MaximumEdgeLength, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumEdgeLength, double);
  ///@}

  enum AccelerationStructures
  {
    AUTOMATIC = 0,
    COMPACT = 1,
    FAST = 2
  };

  ///@{
  /**
   * Embree's acceleration structure. AUTOMATIC (default) builds the fast one while it takes under
   * an eighth of the machine's physical memory or container limit (up to 8 million triangles on 8
   * GiB, 25 million on 24 GiB) and the compact one above (about 70% of the memory, 75% of the
   * speed).
   */
  vtkSetClampMacro(AccelerationStructure, int, AUTOMATIC, FAST);
  vtkGetMacro(AccelerationStructure, int);
  void SetAccelerationStructureToAutomatic() { this->SetAccelerationStructure(AUTOMATIC); }
  void SetAccelerationStructureToCompact() { this->SetAccelerationStructure(COMPACT); }
  void SetAccelerationStructureToFast() { this->SetAccelerationStructure(FAST); }
  ///@}

  ///@{
  /**
   * Configuration string handed to rtcNewDevice() (for example "threads=2,verbose=1"); empty
   * by default. An invalid string makes the filter fail with Embree's message.
   */
  vtkSetStdStringFromCharMacro(EmbreeConfiguration);
  vtkGetCharFromStdStringMacro(EmbreeConfiguration);
  ///@}

  enum Methods
  {
    HORIZONS_FOR_HEIGHT_FIELDS = 0,
    RAYS = 1,
    HORIZONS = 2
  };

  ///@{
  /**
   * How visibility is found. HORIZONS_FOR_HEIGHT_FIELDS (default): horizon sweeps for a height
   * field without occluders, rays otherwise. RAYS: NumberOfRays Embree rays per point. HORIZONS:
   * horizon sweeps, for height fields only (anything else, or occluders, is an error): the
   * horizon of every texel in NumberOfSectors azimuth sectors, found along lines across the
   * grid in time linear in texels × sectors, then per sector the exact visible solid angle
   * above it (see vtkHorizonApertures). Texels that are not finite, or 0 in a
   * `vtkValidPointMask` point array, are no-data: they neither occlude nor receive, and get a
   * closed aperture and a 0 in the output's `vtkValidPointMask`.
   */
  vtkSetClampMacro(Method, int, HORIZONS_FOR_HEIGHT_FIELDS, HORIZONS);
  vtkGetMacro(Method, int);
  void SetMethodToHorizonsForHeightFields() { this->SetMethod(HORIZONS_FOR_HEIGHT_FIELDS); }
  void SetMethodToRays() { this->SetMethod(RAYS); }
  void SetMethodToHorizons() { this->SetMethod(HORIZONS); }
  ///@}

  ///@{
  /**
   * Azimuth sectors of the horizon sweeps, in [4, 1024]. Default 32.
   */
  vtkSetClampMacro(NumberOfSectors, int, 4, 1024);
  vtkGetMacro(NumberOfSectors, int);
  ///@}

  /**
   * Whether the last update swept horizons (or cast rays).
   */
  vtkGetMacro(UsedHorizons, bool);

  /**
   * The surface points that cast rays in the last update, NumberOfRays each: one per position
   * and side of a crease (points welded together cast once), or per texel; 0 after horizon
   * sweeps, after a time step found in the cache, and for the points whose caps were reused.
   */
  vtkGetMacro(NumberOfSurfacePoints, vtkIdType);

  ///@{
  /**
   * Time series. A temporal input passes its time steps through. The outputs of the last
   * TimeStepCacheSize steps (default 16; 0 keeps none) are kept, by the input's time
   * (vtkDataObject::DATA_TIME_STEP): a second visit to a step is a lookup, as long as neither
   * the filter's settings nor anything upstream but the time changed. Each kept step holds its
   * output's new arrays.
   */
  vtkSetClampMacro(TimeStepCacheSize, int, 0, 1024);
  vtkGetMacro(TimeStepCacheSize, int);
  ///@}

  ///@{
  /**
   * A surface that moves (its points, not its cells): when an update's polydata has the same
   * cells and points as the last one's, only the receiving points within reach of a triangle
   * that moved (MaximumDistance plus the rays' offsets, where the triangle was or where it is)
   * cast rays again; the others keep their caps. Needs LimitDistance (unbounded rays can see
   * any motion). Serial runs of one polydata without refinement only. Of the points that cast
   * again, those whose rays did not change cast only the rays that pass near a moved triangle
   * (NumberOfRaysTraced). Default off: the filter then keeps the last surface's triangles,
   * coordinates, rays and caps (about 100 bytes and a bit a ray per point).
   */
  vtkSetMacro(ReuseUnmovedPoints, bool);
  vtkGetMacro(ReuseUnmovedPoints, bool);
  vtkBooleanMacro(ReuseUnmovedPoints, bool);
  ///@}

  ///@{
  /**
   * Whether a point's rays follow its id instead of its position (default off): the global id
   * (vtkPointData::GetGlobalIds()) of the first input point at its position, or that point's
   * index, and its side at a crease. A point that moves keeps its rays, so that an animation
   * does not flicker with sampling noise. Keyed by position, welded and unwelded copies of a
   * mesh get the same rays; keyed by index they do not, and pieces of a distributed run need
   * global ids to match a serial run.
   */
  vtkSetMacro(KeyRaysByPointId, bool);
  vtkGetMacro(KeyRaysByPointId, bool);
  vtkBooleanMacro(KeyRaysByPointId, bool);
  ///@}

  /**
   * What the last update did: computed every point (COMPUTED), took the step from the time-step
   * cache (CACHED_TIME_STEP), cast rays for the points near moved triangles only
   * (MOVED_POINTS), or computed every point because the cells changed since the last update
   * (NEW_TOPOLOGY: a rebuild, where a moving surface of fixed cells would reuse).
   */
  enum UpdateKinds
  {
    COMPUTED = 0,
    CACHED_TIME_STEP = 1,
    MOVED_POINTS = 2,
    NEW_TOPOLOGY = 3
  };
  vtkGetMacro(LastUpdate, int);

  /// Receiving points whose caps the last update reused (MOVED_POINTS).
  vtkGetMacro(NumberOfReusedPoints, vtkIdType);

  /**
   * The rays the last update traced (visibility-mask rays included). Below
   * NumberOfSurfacePoints x NumberOfRays after a MOVED_POINTS update: a point near moved
   * triangles whose own rays did not change (it did not move, nor did its normal) casts again
   * only its rays that pass through a box around the moved triangles, and keeps the last answer
   * of the others.
   */
  vtkGetMacro(NumberOfRaysTraced, vtkIdType);

  ///@{
  /**
   * The controller of a distributed run (default: the global one). When the update asks for one
   * of several pieces and the controller has several processes, the filter gathers every other
   * rank's polygons and strips as occluders (only those within MaximumDistance of this rank's
   * bounds when LimitDistance is on), so that each piece gets the serial answer; every rank must
   * then update the filter, and an empty piece gives an empty output. Height-field pieces need no
   * gathering: the filter makes a piece's extent (a block of the grid) and asks its input for it
   * grown by MaximumDistance (all of the grid when LimitDistance is off).
   */
  virtual void SetController(vtkMultiProcessController* controller);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

protected:
  vtkAperturePrecompute();
  ~vtkAperturePrecompute() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  // A height field's tile needs MaximumDistance of grid around it.
  int RequestUpdateExtent(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  int NumberOfRays = 256;
  bool LimitDistance = false;
  double MaximumDistance = VTK_DOUBLE_MAX;
  double RayOffset = 0.001;
  int Seed = 0;
  int Sampling = STRATIFIED;
  double HeightScale = 1.0;
  bool ComputeAmbientOcclusion = false;
  bool ComputeNormals = true;
  bool ComputeHorizonAngles = false;
  bool ComputeSkyViewFactor = false;
  bool ComputeSkyViewFactorCosine = false;
  bool ComputePositiveOpenness = false;
  bool ComputeNegativeOpenness = false;
  double SectorRotation = 0.0;
  double EarthRadius = 0.0;
  int NoDataAs = NO_DATA_OPEN;
  double NoDataWallHeight = std::numeric_limits<double>::quiet_NaN();
  int NoDataFillDistance = 64;
  bool ComputeVisibilityMask = false;
  int VisibilityMaskBits = 256;
  int VisibilityMaskRaysPerCell = 1;
  double FeatureAngle = 60.0;
  double MaximumEdgeLength = 0.0;
  int AccelerationStructure = AUTOMATIC;
  int Method = HORIZONS_FOR_HEIGHT_FIELDS;
  int NumberOfSectors = 32;
  bool UsedHorizons = false;
  vtkIdType NumberOfSurfacePoints = 0;
  int TimeStepCacheSize = 16;
  bool ReuseUnmovedPoints = false;
  bool KeyRaysByPointId = false;
  int LastUpdate = COMPUTED;
  vtkIdType NumberOfReusedPoints = 0;
  vtkIdType NumberOfRaysTraced = 0;
  vtkMultiProcessController* Controller = nullptr;
  std::string BentNormalArrayName = "BentNormal";
  std::string ApertureRadiusArrayName = "ApertureRadius";
  std::string AmbientOcclusionArrayName = "AmbientOcclusion";
  std::string HorizonAnglesArrayName = "HorizonAngles";
  std::string VisibilityMaskArrayName = "VisibilityMask";
  std::string EmbreeConfiguration;

private:
  vtkAperturePrecompute(const vtkAperturePrecompute&) = delete;
  // MaximumDistance when LimitDistance is on, else VTK_DOUBLE_MAX.
  double SearchDistance() const;
  // RequestData() of this rank's piece.
  int Compute(vtkInformationVector** inputVector, vtkInformationVector* outputVector);
  // The settings' part of PrintSelf(): also the key of what earlier updates computed.
  void PrintSettings(ostream& os, vtkIndent indent);
  void operator=(const vtkAperturePrecompute&) = delete;

  class vtkRun; // the steps of one RequestData
  // What earlier updates computed: time steps, a moving surface's caps.
  std::unique_ptr<vtkApertureHistory> History;
};

#endif
