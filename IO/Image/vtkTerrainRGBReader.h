/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkTerrainRGBReader.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkTerrainRGBReader
 * @brief   reads a Terrain-RGB elevation tile (PNG) as a height field
 *
 * Terrain-RGB tiles (Mapbox and compatible servers) store elevation in the red, green and blue
 * bytes of a PNG: height = -10000 + (R × 65536 + G × 256 + B) × 0.1 metres. This reader decodes
 * them into a 2D vtkImageData whose point scalars, a float array named `Elevation`, are metres,
 * ready for vtkAperturePrecompute's height-field mode or vtkWarpScalar. Image row 0 is the bottom
 * (southern) row, as VTK orders images; the tile's ground size is not in the file, so the grid
 * spacing (metres per pixel) and origin are properties. The PNG can also be read from memory
 * (SetMemoryBuffer()), for tiles compiled into a program or received over a network.
 *
 * A missing or unreadable file, a buffer that is not a PNG, or a PNG without at least three 8-bit
 * channels is an error.
 */

#ifndef vtkTerrainRGBReader_h
#define vtkTerrainRGBReader_h

#include "vtkApertureLightingIOImageModule.h" // For export macro
#include "vtkImageAlgorithm.h"

#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <string> // For std::string

class vtkPNGReader;

class VTKAPERTURELIGHTINGIOIMAGE_EXPORT vtkTerrainRGBReader : public vtkImageAlgorithm
{
public:
  static vtkTerrainRGBReader* New();
  vtkTypeMacro(vtkTerrainRGBReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The PNG file.
   */
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  ///@{
  /**
   * Read the PNG from this buffer of MemoryBufferLength bytes instead of FileName. The buffer is
   * not copied: it must outlive the reads. Set nullptr to read FileName again.
   */
  void SetMemoryBuffer(const void* buffer);
  const void* GetMemoryBuffer() const { return this->MemoryBuffer; }
  vtkSetClampMacro(MemoryBufferLength, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(MemoryBufferLength, vtkIdType);
  ///@}

  ///@{
  /**
   * Ground distance between pixel centres along x and y. Default (1, 1).
   */
  vtkSetVector2Macro(Spacing, double);
  vtkGetVector2Macro(Spacing, double);
  ///@}

  ///@{
  /**
   * Position of the first pixel. Default (0, 0, 0).
   */
  vtkSetVector3Macro(Origin, double);
  vtkGetVector3Macro(Origin, double);
  ///@}

  /**
   * Decodes one Terrain-RGB pixel to metres: -10000 + (R 65536 + G 256 + B) 0.1, computed in
   * decimetres first so that every height is the nearest double to its decimal value (sea level
   * exactly 0, whatever the compiler contracts).
   */
  static double DecodeHeight(unsigned char r, unsigned char g, unsigned char b)
  {
    return (r * 65536 + g * 256 + b - 100000) / 10.0;
  }

protected:
  vtkTerrainRGBReader();
  ~vtkTerrainRGBReader() override = default;

  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  // A PNG reader set up for the file or the memory buffer; nullptr, after an error, when there is
  // nothing readable.
  vtkSmartPointer<vtkPNGReader> MakePNGReader();

  std::string FileName;
  const void* MemoryBuffer = nullptr;
  vtkIdType MemoryBufferLength = 0;
  double Spacing[2] = { 1.0, 1.0 };
  double Origin[3] = { 0.0, 0.0, 0.0 };

private:
  vtkTerrainRGBReader(const vtkTerrainRGBReader&) = delete;
  void operator=(const vtkTerrainRGBReader&) = delete;
};

#endif
