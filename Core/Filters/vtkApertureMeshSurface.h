/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureMeshSurface.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureMeshSurface
 * @brief   builds a vtkApertureSurface from the polygons and strips of a polydata (private)
 *
 * The steps vtkApertureSurface describes: point ids checked (vtkApertureCellCheck), points at
 * the same position welded, polygons and strips cut into triangles, triangles wound
 * consistently, the triangles around each vertex grouped into sides at creases (or between given
 * normals), and each input point mapped to its receiving points.
 *
 * @sa vtkApertureSurface vtkApertureGridSurface
 */

#ifndef vtkApertureMeshSurface_h
#define vtkApertureMeshSurface_h

#include "vtkApertureLightingCoreModule.h" // For export macro
#include "vtkCellArray.h"                  // For ForEachPolygonOrStrip()
#include "vtkCellArrayIterator.h"          // For ForEachPolygonOrStrip()
#include "vtkPolyData.h"                   // For ForEachPolygonOrStrip()
#include "vtkType.h"

#include <string>
#include <vector>

class vtkApertureSurface;
class vtkPoints;

class VTKAPERTURELIGHTINGCORE_EXPORT vtkApertureMeshSurface
{
public:
  /**
   * Builds the surface from the polygons and strips of a polydata. Normals are the input's when
   * it has a usable normals array, else the normalised sums of the unit normals of each side's
   * triangles. Creases are edges whose faces' normals differ by more than featureAngle degrees
   * (0 to 180; 180 keeps every vertex in one piece). Returns false with one sentence in `error`
   * when the input is unusable: a cell with a point id outside the points (named), or 2^32
   * points or more.
   */
  static bool Set(vtkApertureSurface& surface, vtkPolyData* input, const double origin[3],
    double featureAngle, std::string& error);

  /**
   * Calls `visit(npts, ids, strip)` for each polygon of `input`, then each strip, in cell order.
   */
  template <typename Visit>
  static void ForEachPolygonOrStrip(vtkPolyData* input, Visit&& visit)
  {
    for (vtkCellArray* cells : { input->GetPolys(), input->GetStrips() })
    {
      const bool strip = cells == input->GetStrips();
      vtkIdType npts;
      const vtkIdType* ids;
      auto it = vtk::TakeSmartPointer(cells->NewIterator());
      for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
      {
        it->GetCurrentCell(npts, ids);
        visit(npts, ids, strip);
      }
    }
  }

  /**
   * How a polygon or strip becomes triangles, for every caster and for refinement: appends to
   * `triangles` three local corner indices (0 .. npts - 1) per triangle. Strips alternate their
   * winding; polygons of more than 3 points are ear-cut, or fanned where that fails or a point
   * is not finite (`finite` per point id; nullptr: all are). Without `points`, fans. Safe to
   * call from several threads on the same points.
   */
  static void Triangulate(vtkIdType npts, const vtkIdType* ids, bool strip, vtkPoints* points,
    const unsigned char* finite, std::vector<vtkIdType>& triangles);
};

#endif
// VTK-HeaderTest-Exclude: vtkApertureMeshSurface.h
