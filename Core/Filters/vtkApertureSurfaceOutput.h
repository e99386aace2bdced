/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureSurfaceOutput.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureSurfaceOutput
 * @brief   a caster's output: the input with the points creases split, and per-point arrays
 *          (private)
 *
 * @sa vtkApertureSurface
 */

#ifndef vtkApertureSurfaceOutput_h
#define vtkApertureSurfaceOutput_h

#include "vtkApertureLightingCoreModule.h" // For export macro

#include "vtkSmartPointer.h" // For vtkSmartPointer
#include "vtkType.h"

#include <string>
#include <vector>

class vtkApertureSurface;
class vtkFloatArray;
class vtkPointData;
class vtkPolyData;
class vtkUnsignedCharArray;

class VTKAPERTURELIGHTINGCORE_EXPORT vtkApertureSurfaceOutput
{
public:
  /**
   * Writes in `output` the input with the points that creases split duplicated (their point
   * data copied) and the cells that use them renumbered; `outputPoints` gets each output point's
   * receiving point (or vtkApertureSurface::NotOnSurface, Invalid). When a crease runs across a
   * triangle strip, the strips become triangles (after the polygons, each with its strip's cell
   * data), as vtkPolyDataNormals does. Without splits the output is a shallow copy.
   */
  static void Make(const vtkApertureSurface& surface, vtkPolyData* input, vtkPolyData* output,
    std::vector<vtkIdType>& outputPoints);

  /**
   * Per-receiving-point values (`components` floats each, from `begin`) as an array over
   * output points (Make()'s `outputPoints`): `open` for points on no polygon or strip,
   * `closed` for invalid ones.
   */
  static vtkSmartPointer<vtkFloatArray> Scatter(const std::string& name, int components,
    const float* begin, const float* end, const std::vector<vtkIdType>& outputPoints,
    const float* open, const float* closed);
  static vtkSmartPointer<vtkUnsignedCharArray> Scatter(const std::string& name, int components,
    const unsigned char* begin, const unsigned char* end,
    const std::vector<vtkIdType>& outputPoints, const unsigned char* open,
    const unsigned char* closed);

  /**
   * When the normals were computed here (the input had none: NormalsComputed), sets them as
   * `pd`'s Normals over Make()'s `outputPoints`, (0, 0, 0) where a point has none.
   */
  static void AddComputedNormals(const vtkApertureSurface& surface, vtkPointData* pd,
    const std::vector<vtkIdType>& outputPoints);
};

#endif
// VTK-HeaderTest-Exclude: vtkApertureSurfaceOutput.h
