/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureCellCheck.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureCellCheck
 * @brief   finds cells whose point ids lie outside their dataset's points (private)
 *
 * VTK's filters and mappers read through cell point ids without checking them: a damaged file
 * (an OBJ face `f 1 2 99`, a polygon with index 500000) makes them read or write out of bounds.
 * The module's filters and mappers check every id here first, and refuse such input with a
 * sentence naming the first bad cell. Offsets that do not describe the connectivity array are
 * reported too.
 */

#ifndef vtkApertureCellCheck_h
#define vtkApertureCellCheck_h

#include "vtkApertureLightingCoreModule.h" // For export macro
#include "vtkType.h"

#include <string>

class vtkCellArray;
class vtkPolyData;
class vtkUnstructuredGrid;

class VTKAPERTURELIGHTINGCORE_EXPORT vtkApertureCellCheck
{
public:
  /**
   * The first bad cell of the vertices, lines, polygons and strips of a polydata, as a sentence
   * ("polygon 3 (cell 7) uses point id 99, but there are 3 points"), or empty when all are good.
   */
  static std::string FindBadCell(vtkPolyData* input);

  /**
   * The same for the cells of an unstructured grid.
   */
  static std::string FindBadCell(vtkUnstructuredGrid* input);

  /**
   * The same for one cell array of cells named `kind`, whose first cell has id `firstCellId`,
   * in a dataset of numberOfPoints points.
   */
  static std::string FindBadCell(
    vtkCellArray* cells, vtkIdType numberOfPoints, const char* kind, vtkIdType firstCellId);
};

#endif
// VTK-HeaderTest-Exclude: vtkApertureCellCheck.h
