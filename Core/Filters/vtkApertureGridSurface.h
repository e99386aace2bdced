/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureGridSurface.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureGridSurface
 * @brief   builds a vtkApertureSurface from a height field (private)
 *
 * Grid point (i, j) of a 2D vtkImageData, raised by its height along the grid's third axis (its
 * direction matrix and spacing respected), is one vertex and one receiving point; each grid cell
 * with four finite corners gives two triangles. Heights are read in their own type (float,
 * double or integer arrays, through vtkArrayDispatch).
 *
 * @sa vtkApertureSurface vtkApertureMeshSurface
 */

#ifndef vtkApertureGridSurface_h
#define vtkApertureGridSurface_h

#include "vtkApertureLightingCoreModule.h" // For export macro

#include <string>

class vtkApertureSurface;
class vtkDataArray;
class vtkImageData;

class VTKAPERTURELIGHTINGCORE_EXPORT vtkApertureGridSurface
{
public:
  /**
   * Builds the surface of a 2D height field: grid point (i, j) raised by heightScale × height
   * along the grid's third axis, normals to that side. One receiving point per grid point (a
   * texel cannot be split).
   */
  static bool Set(vtkApertureSurface& surface, vtkImageData* input, vtkDataArray* heights,
    double heightScale, const double origin[3], std::string& error);

  /**
   * Grows bounds as vtkApertureSurface::ExpandBounds() does, by the height field's finite points.
   */
  static void ExpandBounds(
    vtkImageData* input, vtkDataArray* heights, double heightScale, double bounds[6]);
};

#endif
// VTK-HeaderTest-Exclude: vtkApertureGridSurface.h
