/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkOpenEXRReader.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkOpenEXRReader
 * @brief   reads OpenEXR images (HDR environments) as float vtkImageData
 *
 * Reads an OpenEXR file, or an EXR held in memory (SetMemoryBuffer()), with the OpenEXR 3
 * library: scanline or tiled, any compression (DWAB included), half or float channels, RGB, RGBA,
 * luminance (Y) or luminance-chroma (Y, RY, BY, converted to RGB). The output is a 2D float image
 * whose point scalars, named `Radiance`, have 3 components (RGB, and for luminance-chroma), 4
 * (RGBA) or 1 (Y). It covers the file's display window: pixels of the data window go where its
 * offset puts them, others are 0. As VTK orders images, row 0 is the bottom of the picture
 * (the file's last row).
 *
 * Bad input is an error and an empty output, never a crash: a missing file, a file that is not
 * OpenEXR, a truncated or damaged one (the library's exception becomes the message), no R, G, B
 * or Y channel, and sizes past MaximumSide or MaximumBytes, checked before anything is
 * allocated. The headers are checked before the library reads them, since it allocates what a
 * damaged size field says: every attribute must lie within the file, and the windows and tiles
 * within MaximumSide. NaN and negative pixel values become 0 and infinite ones 65504 (the largest
 * half), with one warning unless they are only the slightly negative values lossy compression
 * (DWAA, DWAB) leaves, above -1% of the mean.
 *
 * @sa vtkEnvironmentMap
 */

#ifndef vtkOpenEXRReader_h
#define vtkOpenEXRReader_h

#include "vtkApertureLightingIOOpenEXRModule.h" // For export macro
#include "vtkImageAlgorithm.h"

#include <string> // For std::string

class VTKAPERTURELIGHTINGIOOPENEXR_EXPORT vtkOpenEXRReader : public vtkImageAlgorithm
{
public:
  static vtkOpenEXRReader* New();
  vtkTypeMacro(vtkOpenEXRReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The EXR file.
   */
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  ///@{
  /**
   * Read the EXR from this buffer of MemoryBufferLength bytes instead of FileName. The buffer
   * is not copied: it must outlive the reads. Set nullptr to read FileName again.
   */
  void SetMemoryBuffer(const void* buffer);
  const void* GetMemoryBuffer() const { return this->MemoryBuffer; }
  vtkSetClampMacro(MemoryBufferLength, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(MemoryBufferLength, vtkIdType);
  ///@}

  ///@{
  /**
   * Largest width or height accepted (default 32768), and largest output in bytes (default
   * 1 GiB). Larger images are refused before any memory is allocated for them.
   */
  vtkSetClampMacro(MaximumSide, int, 1, 1 << 20);
  vtkGetMacro(MaximumSide, int);
  vtkSetClampMacro(MaximumBytes, vtkTypeInt64, 1, VTK_TYPE_INT64_MAX);
  vtkGetMacro(MaximumBytes, vtkTypeInt64);
  ///@}

  /**
   * Whether the file (or the memory buffer) starts like an OpenEXR file.
   */
  bool CanRead();

protected:
  vtkOpenEXRReader();
  ~vtkOpenEXRReader() override = default;

  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  std::string FileName;
  const void* MemoryBuffer = nullptr;
  vtkIdType MemoryBufferLength = 0;
  int MaximumSide = 32768;
  vtkTypeInt64 MaximumBytes = vtkTypeInt64(1) << 30;

private:
  vtkOpenEXRReader(const vtkOpenEXRReader&) = delete;
  void operator=(const vtkOpenEXRReader&) = delete;

  // What RequestInformation learnt from the header.
  int Width = 0;
  int Height = 0;
  int Components = 0;
};

#endif
