/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureHistory.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureHistory
 * @brief   what earlier updates of vtkAperturePrecompute computed, for time series (private)
 *
 * Two kinds of reuse, both keyed by the filter's settings and its occluders (a new key empties
 * them), so that only the data's time or points change between what they reuse:
 *
 * - **Time steps**: the outputs of the last time steps, by the time value they were computed
 *   for; a second visit to a step is a lookup (Find(), Store()).
 * - **A moving surface of fixed cells**: the last update's surface and caps. When the new
 *   surface has the same triangles on the same vertices, only the points within `reach` (the
 *   rays' length plus their offsets) of a triangle that moved, where it was or where it is, can
 *   see something else; Needed() marks them, and the points of a vertex whose sides at creases
 *   changed in number; Reuse() copies the others' caps (a vertex's sides in order), Remember()
 *   keeps this update for the next.
 * - **Rays that pass nowhere near what moved**: a marked point whose rays start where they did,
 *   the same way (same local coordinates, normal, offsets and key), keeps the answer of every
 *   ray that passes through none of the boxes around the moved triangles (GetMovedBoxes()), so
 *   that it casts only the others again (GetRays() holds the last answers).
 * - **Triangles out of reach**: Reachable() says which triangles the rays of the points that cast
 *   again can hit, so that the update's scene holds only those.
 */

#ifndef vtkApertureHistory_h
#define vtkApertureHistory_h

#include "vtkApertureLightingCoreModule.h" // For export macro
#include "vtkSmartPointer.h"               // For vtkSmartPointer
#include "vtkType.h"

#include <cstdint>
#include <deque>
#include <string>
#include <unordered_map>
#include <vector>

class vtkApertureSurface;
class vtkDataObject;

class VTKAPERTURELIGHTINGCORE_EXPORT vtkApertureHistory
{
public:
  /// The caps of a surface's receiving points, their visibility masks, and for a moving surface
  /// the answer of each of their rays (a bit each, set where it escaped; RayWords words a point).
  struct Caps
  {
    std::vector<float> BentNormal, Radius, Occlusion;
    std::vector<unsigned char> Mask;
    std::vector<std::uint64_t> Rays;
    int RayWords = 0;
  };

  /// What Needed() says of a receiving point: keep its caps, cast every ray, or cast only the
  /// rays that pass through a moved triangle's box.
  enum Plan : unsigned char
  {
    REUSE = 0,
    CAST = 1,
    RETRACE = 2
  };

  /// Empties both kinds of reuse when `key` differs from the last one given.
  void SetKey(const std::string& key);

  ///@{
  /**
   * The output of the step at `time` computed when the input's pipeline had the modification
   * time `pipeline`, or nullptr; Store() keeps a shallow copy of one, and at most `capacity`
   * steps (the oldest goes first; 0 keeps none).
   */
  vtkDataObject* Find(double time, vtkMTimeType pipeline) const;
  void Store(double time, vtkMTimeType pipeline, vtkDataObject* output, int capacity);
  ///@}

  /**
   * Per receiving point of `surface`, a Plan: CAST for every point unless the remembered surface
   * has the same cells and local origin; then REUSE except for the points within `reach` of a
   * triangle with a vertex that moved, and those of a vertex with another number of sides; of
   * these, RETRACE for the points whose rays are the remembered ones. `world` holds the same number
   * of values for each input point: its coordinates, and its given normal if there is one (a point
   * whose values changed moved).
   */
  std::vector<unsigned char> Needed(
    const vtkApertureSurface& surface, const std::vector<double>& world, double reach);

  /**
   * Per triangle of `surface`, whether a ray of a point that Needed() did not plan to REUSE can
   * hit it (the triangle comes near such a point: within the reach, and a little more); empty
   * when Needed() planned every point to CAST.
   */
  std::vector<unsigned char> Reachable(const vtkApertureSurface& surface) const;

  /// Copies the remembered caps (and rays) of the points that Needed() planned to REUSE.
  void Reuse(Caps& caps) const;

  /// The remembered answers of the rays of a point that Needed() planned to RETRACE.
  const std::uint64_t* GetRays(vtkIdType point) const;

  /**
   * The boxes (6 values each: lower x, y, z, upper x, y, z, in the surface's local coordinates,
   * grown by a margin for rounding) around the moved triangles, where they were and where they
   * are, that lie within the rays' reach of `position`: at most `capacity` into `boxes`. Their
   * number, or -1 if there are more.
   */
  int GetMovedBoxes(const float position[3], float* boxes, int capacity) const;

  /// Keeps this update's surface, input coordinates and caps for the next one.
  void Remember(const vtkApertureSurface& surface, std::vector<double> world, const Caps& caps);

  /// Forgets the remembered surface (a run that cannot be reused: composite, distributed...).
  void Forget();

  /// What the last Needed() found remembered: no surface, one of other cells, or the same.
  enum Match
  {
    NO_SURFACE,
    OTHER_CELLS,
    SAME_CELLS
  };
  Match GetMatch() const { return this->Matched; }

private:
  // Whether `surface` has the remembered surface's triangles and vertices.
  bool SameCells(const vtkApertureSurface& surface) const;
  // The remembered receiving point of each of `surface`'s points of the same vertex and side
  // (-1 where the vertex has another number of sides).
  std::vector<vtkIdType> MatchSides(const vtkApertureSurface& surface) const;
  std::vector<unsigned char> MovedVertices(
    const vtkApertureSurface& surface, const std::vector<double>& world) const;
  // Whether point `p` of `surface` casts the rays that remembered point `q` cast.
  bool SameRays(const vtkApertureSurface& surface, vtkIdType p, vtkIdType q) const;
  // Grows the box of the reach-sized cell that holds the lower corner of the triangle with
  // `corners` (world coordinates) to hold it, in the local coordinates of `origin`.
  void AddMovedBox(const double* const corners[3], const double origin[3]);

  std::string Key;
  struct Step
  {
    double Time;
    vtkMTimeType Pipeline;
    vtkSmartPointer<vtkDataObject> Output;
  };
  std::deque<Step> Steps;
  bool Remembered = false;
  Match Matched = NO_SURFACE;
  std::vector<double> World;       // the input's coordinates (and normals), per point
  std::vector<double> VertexWorld; // the surface's vertices, world coordinates (3 each)
  std::vector<std::uint32_t> Triangles, PointVertex;
  std::vector<vtkIdType> Sources; // Needed()'s match of each point, -1 where cast
  std::vector<unsigned char> Plans;
  Caps Results;
  // Where the remembered points' rays started, and which way (vtkApertureSurface's arrays).
  double Origin[3] = { 0.0, 0.0, 0.0 };
  std::vector<float> Start, Normal, Offset, Near;
  std::vector<std::uint64_t> RayKey;
  std::vector<unsigned char> Valid;
  // The moved triangles' boxes, merged by the cell of the reach's size that holds their lower
  // corner: 6 values each, the box of each cell, the largest side of a box, the reach.
  std::vector<float> MovedBoxes;
  std::unordered_map<std::uint64_t, std::uint32_t> BoxOfCell;
  float BoxSpan = 0.0f;
  double Reach = 0.0;
};

#endif
// VTK-HeaderTest-Exclude: vtkApertureHistory.h
