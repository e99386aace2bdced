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
 */

#ifndef vtkApertureHistory_h
#define vtkApertureHistory_h

#include "vtkApertureLightingCoreModule.h" // For export macro
#include "vtkSmartPointer.h"               // For vtkSmartPointer
#include "vtkType.h"

#include <cstdint>
#include <deque>
#include <string>
#include <vector>

class vtkApertureSurface;
class vtkDataObject;

class VTKAPERTURELIGHTINGCORE_EXPORT vtkApertureHistory
{
public:
  /// The caps of a surface's receiving points, and their visibility masks.
  struct Caps
  {
    std::vector<float> BentNormal, Radius, Occlusion;
    std::vector<unsigned char> Mask;
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
   * Per receiving point of `surface`, 1 where its caps must be cast: every point unless the
   * remembered surface has the same cells; then the points within `reach` of a triangle with a
   * vertex that moved, and those of a vertex with another number of sides. `world` holds the same
   * number of values for each input point: its coordinates, and its given normal if there is one (a
   * point whose values changed moved).
   */
  std::vector<unsigned char> Needed(
    const vtkApertureSurface& surface, const std::vector<double>& world, double reach);

  /// Copies the remembered caps of the points that Needed() did not mark into `caps`.
  void Reuse(Caps& caps) const;

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
  Caps Results;
};

#endif
// VTK-HeaderTest-Exclude: vtkApertureHistory.h
