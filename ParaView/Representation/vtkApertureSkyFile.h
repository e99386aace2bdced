/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureSkyFile.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureSkyFile
 * @brief   The sky environment file of a representation: its name, its map, whether it loaded
 *
 * Both representations take an HDR sky as a file name (a latitude-longitude OpenEXR file, as
 * ParaView's properties give it). A name that cannot be read is reported against the
 * representation and leaves the uniform sky. Not a VTK object: a member of each representation.
 */

#ifndef vtkApertureSkyFile_h
#define vtkApertureSkyFile_h

#include "vtkEnvironmentMap.h" // For the map
#include "vtkNew.h"            // For vtkNew

#include <string> // For the name

class vtkObject;

class vtkApertureSkyFile
{
public:
  vtkApertureSkyFile();

  /**
   * Reads `fileName` (nullptr or empty: none) unless it is the one read already; true when the
   * environment to use changed. A file that cannot be read is an error of `reporter`.
   */
  bool SetFileName(const char* fileName, vtkObject* reporter);

  /**
   * The environment, or nullptr for the uniform sky.
   */
  vtkEnvironmentMap* GetEnvironment() { return this->Loaded ? this->Map.Get() : nullptr; }

  /**
   * The map itself, loaded or not: its up axis and azimuth are kept either way.
   */
  vtkEnvironmentMap* GetMap() { return this->Map; }

  void PrintSelf(ostream& os, vtkIndent indent);

private:
  std::string FileName;
  vtkNew<vtkEnvironmentMap> Map;
  bool Loaded = false;
};

#endif
