/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureRefinement.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureRefinement
 * @brief   splits a surface's triangles until no edge is longer than a length (private)
 *
 * Per-vertex apertures are interpolated across faces: on a box's wall with four vertices, the
 * contact shadow at its foot becomes a gradient over the whole wall. Refinement gives such faces
 * enough points. Polygons and strips become triangles (as vtkApertureSurface::Triangulate()
 * cuts them); every pass splits each edge longer than the maximum at its midpoint (a case table
 * of 1 to 4 triangles, the best diagonal for quadrilaterals), until none is left. Vertices and
 * lines pass as they are.
 *
 * Midpoints are shared by the two triangles of an edge through the edge's point ids, not
 * through their positions, as vtkAdaptiveSubdivisionFilter's point locator does: the two sides
 * of a texture seam keep their own points and texture coordinates. Point data is interpolated
 * (each new point from the original triangle's corners), cell data copied to the triangles a cell
 * becomes.
 */

#ifndef vtkApertureRefinement_h
#define vtkApertureRefinement_h

#include "vtkApertureLightingCoreModule.h" // For export macro
#include "vtkType.h"

#include <string>

class vtkPolyData;

class VTKAPERTURELIGHTINGCORE_EXPORT vtkApertureRefinement
{
public:
  /// More triangles than this are refused.
  static constexpr vtkIdType MaximumNumberOfTriangles = 20000000;

  /**
   * Refines `input` (whose point ids must be valid) into `output`. Returns false with one
   * sentence in `error` when the result would have more than MaximumNumberOfTriangles
   * triangles, or `maximumEdgeLength` is not positive.
   */
  static bool Refine(
    vtkPolyData* input, double maximumEdgeLength, vtkPolyData* output, std::string& error);

  /**
   * The longest edge of the input's polygons and strips (0 without any), for callers that
   * choose a maximum from the scene.
   */
  static double LongestEdge(vtkPolyData* input);
};

#endif
// VTK-HeaderTest-Exclude: vtkApertureRefinement.h
