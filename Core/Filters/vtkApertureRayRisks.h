/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureRayRisks.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureRayRisks
 * @brief   which triangles the hit rules of vtkApertureRayScene can matter for (private)
 *
 * A hit is rejected only on the back of a triangle near a ray's start, or on one of the ray's
 * own triangles. So a triangle needs the hit filter only if
 *
 * - it is at the vertex of a receiving point whose normal is within acos(PullBack) of
 *   perpendicular to its own, or against it (rays from that point can meet it from behind), or
 * - it passes within the Near distance of the ray start of some other receiving point.
 *
 * The second test looks the ray starts up in a hash grid of cells about two edges long. Triangles
 * spanning too many cells to check are counted as needing the filter: that is always correct,
 * only slower.
 */

#ifndef vtkApertureRayRisks_h
#define vtkApertureRayRisks_h

#include "vtkApertureLightingCoreModule.h" // For export macro
#include "vtkType.h"

#include <cstddef>
#include <cstdint>
#include <vector>

class vtkApertureSurface;

class VTKAPERTURELIGHTINGCORE_EXPORT vtkApertureRayRisks
{
public:
  /**
   * Indexes the ray starts of the receivers' valid points (their offsets must be set).
   */
  explicit vtkApertureRayRisks(const std::vector<const vtkApertureSurface*>& receivers);

  /**
   * One flag per triangle of `surface`: 1 where the hit filter is needed. `receiver`: the
   * surface is one of the receivers (its own points' rules apply). Only the triangles flagged in
   * `only` are looked at (the others get 0), all of them when it is empty.
   */
  std::vector<unsigned char> Find(const vtkApertureSurface& surface, bool receiver,
    const std::vector<unsigned char>& only = std::vector<unsigned char>()) const;

private:
  struct Start
  {
    float Position[3];
    float Radius; // the point's Near distance
    const vtkApertureSurface* Surface;
    std::uint32_t Vertex;
  };

  // The cell of a coordinate along an axis, and the key of a cell.
  std::int64_t Index(float x, int axis) const;
  static std::uint64_t Key(std::int64_t i, std::int64_t j, std::int64_t k);
  void MarkIncident(const vtkApertureSurface& surface, const std::vector<unsigned char>& only,
    std::vector<unsigned char>& risky) const;
  bool NearStart(const vtkApertureSurface& surface, std::uint32_t triangle) const;

  std::vector<Start> Starts;
  // The cells that hold starts: an open-addressing hash table (linear probing) of each cell's
  // key and its run of Starts; a free slot has the key FreeCell, which no cell has.
  struct Cell
  {
    std::uint64_t Key;
    std::uint32_t Begin, End;
  };
  static constexpr std::uint64_t FreeCell = ~std::uint64_t(0);
  void CollectStarts(const vtkApertureSurface& surface);
  void SortStarts();
  const Cell* FindCell(std::uint64_t key) const;
  std::size_t Slot(std::uint64_t key) const;
  std::vector<Cell> Cells;
  int CellBits = 0;  // Cells has 2^CellBits slots
  float Size = 1.0f; // of a cell
  float Lower[3] = { 0.0f, 0.0f, 0.0f };
  float LargestRadius = 0.0f;
};

#endif
// VTK-HeaderTest-Exclude: vtkApertureRayRisks.h
