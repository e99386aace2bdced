/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureDICOMReader.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureDICOMReader
 * @brief   a CT or MR volume from a folder of DICOM files, or a clear reason why not
 *
 * Reads one DICOM image series through vtk-dicom (vtkDICOMDirectory finds the series in the folder
 * and its subfolders, vtkDICOMReader sorts the slices along their normal and rescales the values:
 * CT in Hounsfield units) into a vtkImageData in patient coordinates (LPS, millimetres): origin and
 * spacing from the series, the direction matrix from its slice orientation (rows bottom-up in
 * memory, as VTK's image readers have them; the matrix says where they lie), scalars named
 * `DICOMImage`.
 *
 * What a folder of files can hold that is not one volume, each refused with one error and no
 * output: no DICOM image at all; several series (each listed with its number, description and file
 * count: pick one with SetSeriesIndex()); a single slice; slices that are not evenly spaced
 * (missing slices: a gap of more than 1.5 times the smallest step) or that share a position (two
 * acquisitions mixed in one series).
 *
 * @sa vtkVolumeAperturePrecompute
 */

#ifndef vtkApertureDICOMReader_h
#define vtkApertureDICOMReader_h

#include "vtkApertureLightingIODICOMModule.h" // For export macro
#include "vtkImageAlgorithm.h"

#include <string> // For the series' file names

class VTKAPERTURELIGHTINGIODICOM_EXPORT vtkApertureDICOMReader : public vtkImageAlgorithm
{
public:
  static vtkApertureDICOMReader* New();
  vtkTypeMacro(vtkApertureDICOMReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The folder that holds the series.
   */
  vtkSetStdStringFromCharMacro(DirectoryName);
  vtkGetCharFromStdStringMacro(DirectoryName);
  ///@}

  ///@{
  /**
   * Which series of the folder to read, counted from 0 in vtkDICOMDirectory's order (by patient,
   * study, series number). -1 (the default): the folder must hold exactly one.
   */
  vtkSetClampMacro(SeriesIndex, int, -1, VTK_INT_MAX);
  vtkGetMacro(SeriesIndex, int);
  ///@}

  /**
   * The number of series found by the last update (0 before one).
   */
  vtkGetMacro(NumberOfSeries, int);

protected:
  vtkApertureDICOMReader();
  ~vtkApertureDICOMReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::string DirectoryName;
  int SeriesIndex = -1;
  int NumberOfSeries = 0;

private:
  vtkApertureDICOMReader(const vtkApertureDICOMReader&) = delete;
  void operator=(const vtkApertureDICOMReader&) = delete;

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
