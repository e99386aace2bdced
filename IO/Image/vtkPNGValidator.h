/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkPNGValidator.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkPNGValidator
 * @brief   tells whether a PNG file or buffer decodes cleanly, before vtkPNGReader reads it
 *          (private: a workaround for VTK 9.1)
 *
 * VTK 9.1's vtkPNGReader cannot recover from an error inside libpng: a truncated or damaged PNG
 * crashes the program. This class checks a PNG completely without libpng: the signature, every
 * chunk's length and CRC, the header's values, the chunk order, and the compressed image data,
 * which must inflate to exactly the size the header implies, with a valid filter byte on every
 * row (interlaced images included). A PNG that passes decodes without a libpng error.
 * vtkTerrainRGBReader and aperture-render call it first.
 *
 * Each check returns an empty string for a good PNG, otherwise one sentence that says what is
 * wrong, e.g. "the file is truncated (chunk IDAT needs 8192 bytes, 1200 are left)".
 */

#ifndef vtkPNGValidator_h
#define vtkPNGValidator_h

#include "vtkApertureLightingIOImageModule.h" // For export macro
#include "vtkObject.h"

#include <string> // For std::string

class VTKAPERTURELIGHTINGIOIMAGE_EXPORT vtkPNGValidator : public vtkObject
{
public:
  static vtkPNGValidator* New();
  vtkTypeMacro(vtkPNGValidator, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Checks the PNG file; an empty string when it is good, else what is wrong with it (a missing
   * or unreadable file included).
   */
  static std::string CheckFile(const char* fileName);

  /**
   * Checks a PNG held in memory (size bytes); an empty string when it is good.
   */
  static std::string CheckBuffer(const void* data, size_t size);

protected:
  vtkPNGValidator() = default;
  ~vtkPNGValidator() override = default;

private:
  vtkPNGValidator(const vtkPNGValidator&) = delete;
  void operator=(const vtkPNGValidator&) = delete;
};

#endif
// VTK-HeaderTest-Exclude: vtkPNGValidator.h
