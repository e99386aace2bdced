/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureValidMask.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureValidMask
 * @brief   the name of the point array that marks valid texels (private)
 *
 * Height fields mark valid texels 1 and no-data 0 in this array, as VTK's probe filters do: the
 * readers write it, the filters read it.
 */

#ifndef vtkApertureValidMask_h
#define vtkApertureValidMask_h

class vtkApertureValidMask
{
public:
  static const char* Name() { return "vtkValidPointMask"; }
};

#endif
// VTK-HeaderTest-Exclude: vtkApertureValidMask.h
