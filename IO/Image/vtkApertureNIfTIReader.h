/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureNIfTIReader.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureNIfTIReader
 * @brief   VTK's NIfTI reader behind a check of the file's header
 *
 * vtkNIFTIImageReader trusts the header of a .nii or .nii.gz file and crashes on a damaged one
 * (found by fuzzing VTK 9.1's reader). This reader checks the header first, NIfTI-1 and NIfTI-2
 * in either byte order, and refuses, with one error, a file that is not a single-file volume
 * ("n+1" or "n+2") of 1 to 7 axes, each at least 1 long and at most 2^31 values in all, of a data
 * type VTK reads with matching bits, finite spacings, transforms and scaling, and data after the
 * header (and, uncompressed, within the file). A sound file is read by vtkNIFTIImageReader
 * unchanged: voxel axes with the header's spacing, its orientation matrices beside (GetQFormMatrix,
 * GetSFormMatrix), not applied.
 */

#ifndef vtkApertureNIfTIReader_h
#define vtkApertureNIfTIReader_h

#include "vtkApertureLightingIOImageModule.h" // For export macro
#include "vtkNIFTIImageReader.h"

#include <string> // For HeaderProblem

class VTKAPERTURELIGHTINGIOIMAGE_EXPORT vtkApertureNIfTIReader : public vtkNIFTIImageReader
{
public:
  static vtkApertureNIfTIReader* New();
  vtkTypeMacro(vtkApertureNIfTIReader, vtkNIFTIImageReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * What is wrong with the file's header, as one sentence that names the file; empty when the
   * file can be handed to vtkNIFTIImageReader.
   */
  static std::string HeaderProblem(const char* fileName);

  /**
   * 0 for a file whose header is unsound, else what vtkNIFTIImageReader says.
   */
  int CanReadFile(const char* fileName) override;

protected:
  vtkApertureNIfTIReader();
  ~vtkApertureNIfTIReader() override;

  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

private:
  vtkApertureNIfTIReader(const vtkApertureNIfTIReader&) = delete;
  void operator=(const vtkApertureNIfTIReader&) = delete;
};

#endif
