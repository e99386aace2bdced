/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureDICOMReader.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureDICOMReader.h"

#include "vtkApertureText.h"
#include "vtkDICOMDirectory.h"
#include "vtkDICOMItem.h"
#include "vtkDICOMMetaData.h"
#include "vtkDICOMReader.h"
#include "vtkDICOMValue.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkApertureDICOMReader);

class vtkApertureDICOMReader::vtkInternals
{
public:
  vtkNew<vtkDICOMReader> Reader;
};

namespace
{
// "0: series 4 'T1 AX' (120 files)" for each series of the folder (number and description where
// the files have them).
std::string ListSeries(vtkDICOMDirectory* directory)
{
  std::ostringstream list;
  for (int s = 0; s < directory->GetNumberOfSeries(); ++s)
  {
    const vtkDICOMItem& series = directory->GetSeriesRecord(s);
    const std::string number = series.Get(DC::SeriesNumber).AsString();
    const std::string description = series.Get(DC::SeriesDescription).AsString();
    list << (s ? "; " : "") << s << ":"
         << (number.empty() ? "" : " series " + vtkApertureText::Escape(number, 12))
         << (description.empty() ? "" : " " + vtkApertureText::Quote(description, 32)) << " ("
         << directory->GetFileNamesForSeries(s)->GetNumberOfValues() << " files)";
  }
  return list.str();
}

// Why the files the reader sorted are not one evenly spaced stack ("" when they are): their
// positions along the slice normal, from each file's ImagePositionPatient and the first file's
// ImageOrientationPatient.
std::string CheckSpacing(vtkDICOMReader* reader)
{
  vtkDICOMMetaData* meta = reader->GetMetaData();
  double orientation[6];
  meta->GetAttributeValue(0, DC::ImageOrientationPatient).GetValues(orientation, 6);
  double normal[3] = { orientation[1] * orientation[5] - orientation[2] * orientation[4],
    orientation[2] * orientation[3] - orientation[0] * orientation[5],
    orientation[0] * orientation[4] - orientation[1] * orientation[3] };
  std::vector<double> along;
  for (int f = 0; f < meta->GetNumberOfInstances(); ++f)
  {
    double position[3] = { 0.0, 0.0, 0.0 };
    meta->GetAttributeValue(f, DC::ImagePositionPatient).GetValues(position, 3);
    along.push_back(position[0] * normal[0] + position[1] * normal[1] + position[2] * normal[2]);
  }
  std::sort(along.begin(), along.end());
  std::vector<double> steps;
  for (size_t i = 1; i < along.size(); ++i)
  {
    steps.push_back(along[i] - along[i - 1]);
  }
  if (steps.empty())
  {
    return "";
  }
  const double smallest = *std::min_element(steps.begin(), steps.end());
  const double largest = *std::max_element(steps.begin(), steps.end());
  std::ostringstream why;
  if (!(smallest > 1e-4))
  {
    why << "two slices of the series lie at the same position (" << along.size()
        << " files): two acquisitions mixed in one series?";
  }
  else if (largest > 1.5 * smallest)
  {
    why << "the slices are not evenly spaced (steps from " << smallest << " to " << largest
        << " mm): slices are missing";
  }
  return why.str();
}
}

//------------------------------------------------------------------------------
vtkApertureDICOMReader::vtkApertureDICOMReader()
  : Internals(new vtkInternals)
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkApertureDICOMReader::~vtkApertureDICOMReader()
{
  delete this->Internals;
}

//------------------------------------------------------------------------------
int vtkApertureDICOMReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  const std::string where = vtkApertureText::QuoteName(this->DirectoryName);
  if (!vtksys::SystemTools::FileIsDirectory(this->DirectoryName))
  {
    vtkErrorMacro("Cannot read DICOM: " << where << " is not a folder.");
    return 0;
  }
  vtkNew<vtkDICOMDirectory> directory;
  directory->SetDirectoryName(this->DirectoryName.c_str());
  directory->RequirePixelDataOn();
  directory->Update();
  this->NumberOfSeries = directory->GetNumberOfSeries();
  const int series = this->SeriesIndex < 0 ? 0 : this->SeriesIndex;
  if (this->NumberOfSeries == 0)
  {
    vtkErrorMacro("Cannot read DICOM: " << where << " holds no DICOM image series.");
    return 0;
  }
  if ((this->SeriesIndex < 0 && this->NumberOfSeries > 1) || series >= this->NumberOfSeries)
  {
    vtkErrorMacro("Cannot read DICOM: " << where << " holds " << this->NumberOfSeries << " series ("
                                        << ListSeries(directory)
                                        << "); pick one with SetSeriesIndex().");
    return 0;
  }
  vtkDICOMReader* reader = this->Internals->Reader;
  reader->SetFileNames(directory->GetFileNamesForSeries(series));
  reader->UpdateInformation();
  int extent[6];
  reader->GetOutputInformation(0)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  // A multi-frame file holds its slices in one instance: the reader has placed them.
  const std::string problem = extent[5] <= extent[4]
    ? "the series holds one slice, not a volume"
    : (reader->GetMetaData()->GetNumberOfInstances() > 1 ? CheckSpacing(reader) : "");
  if (!problem.empty())
  {
    vtkErrorMacro("Cannot read DICOM from " << where << ": " << problem << ".");
    return 0;
  }
  vtkInformation* info = outputVector->GetInformationObject(0);
  info->CopyEntry(
    reader->GetOutputInformation(0), vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT());
  info->CopyEntry(reader->GetOutputInformation(0), vtkDataObject::SPACING());
  info->CopyEntry(reader->GetOutputInformation(0), vtkDataObject::ORIGIN());
  info->CopyEntry(reader->GetOutputInformation(0), vtkDataObject::POINT_DATA_VECTOR());
  return 1;
}

//------------------------------------------------------------------------------
int vtkApertureDICOMReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkDICOMReader* reader = this->Internals->Reader;
  reader->Update();
  vtkImageData* read = reader->GetOutput();
  if (!read || !read->GetPointData()->GetScalars() || reader->GetErrorCode() != 0)
  {
    vtkErrorMacro("Cannot read DICOM from " << vtkApertureText::QuoteName(this->DirectoryName)
                                            << ": the pixel data cannot be decoded.");
    return 0;
  }
  vtkImageData* output = vtkImageData::GetData(outputVector);
  output->ShallowCopy(read);
  output->GetPointData()->GetScalars()->SetName("DICOMImage");
  // Patient coordinates: the patient matrix holds the slices' axes and the first voxel's place.
  vtkMatrix4x4* patient = reader->GetPatientMatrix();
  vtkNew<vtkMatrix3x3> rotation;
  double origin[3];
  read->GetOrigin(origin);
  double placed[3];
  for (int r = 0; r < 3; ++r)
  {
    placed[r] = patient->GetElement(r, 3);
    for (int c = 0; c < 3; ++c)
    {
      rotation->SetElement(r, c, patient->GetElement(r, c));
      placed[r] += patient->GetElement(r, c) * origin[c];
    }
  }
  output->SetDirectionMatrix(rotation);
  output->SetOrigin(placed);
  return 1;
}

//------------------------------------------------------------------------------
void vtkApertureDICOMReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DirectoryName: " << this->DirectoryName << "\n";
  os << indent << "SeriesIndex: " << this->SeriesIndex << "\n";
  os << indent << "NumberOfSeries: " << this->NumberOfSeries << "\n";
}
