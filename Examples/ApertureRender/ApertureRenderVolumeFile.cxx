/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderVolumeFile.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "ApertureRenderVolumeFile.h"

#include "ApertureRenderInput.h"
#include "ApertureRenderMessages.h"
#include "ApertureRenderMetaImage.h"
#include "ApertureRenderNRRD.h"
#include "ApertureRenderXMLBlocks.h"

#include "vtkApertureDICOMReader.h"
#include "vtkApertureNIfTIReader.h"
#include "vtkApertureText.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkImageReader2.h"
#include "vtkMetaImageReader.h"
#include "vtkNew.h"
#include "vtkNrrdReader.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkXMLImageDataReader.h"

#include <vtksys/SystemTools.hxx>

#include <sstream>

namespace ApertureRender
{
namespace
{
bool EndsWith(const std::string& text, const std::string& end)
{
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

std::string Lower(const std::string& name)
{
  return vtksys::SystemTools::LowerCase(name);
}

// The reader for a volume file, by extension.
vtkSmartPointer<vtkAlgorithm> VolumeReader(const std::string& name)
{
  const std::string lower = Lower(name);
  if (EndsWith(lower, ".vti"))
  {
    auto reader = vtkSmartPointer<vtkXMLImageDataReader>::New();
    reader->SetFileName(name.c_str());
    return reader;
  }
  vtkSmartPointer<vtkImageReader2> reader;
  if (EndsWith(lower, ".nii") || EndsWith(lower, ".nii.gz"))
  {
    reader = vtkSmartPointer<vtkApertureNIfTIReader>::New();
  }
  else if (EndsWith(lower, ".nrrd") || EndsWith(lower, ".nhdr"))
  {
    reader = vtkSmartPointer<vtkNrrdReader>::New();
  }
  else
  {
    reader = vtkSmartPointer<vtkMetaImageReader>::New();
  }
  reader->SetFileName(name.c_str());
  return reader;
}

// VTK 9.1's NRRD, NIfTI and MetaImage readers trust their headers: each is checked first.
bool CheckHeader(const std::string& name, std::string& error)
{
  const std::string lower = Lower(name);
  if (EndsWith(lower, ".nrrd") || EndsWith(lower, ".nhdr"))
  {
    return CheckNRRD(name, error);
  }
  if (EndsWith(lower, ".nii") || EndsWith(lower, ".nii.gz"))
  {
    error = vtkApertureNIfTIReader::HeaderProblem(name.c_str());
    return error.empty();
  }
  return EndsWith(lower, ".vti") || CheckMetaImage(name, error);
}

// The volume read from `name` into `input` (a one-slice image becomes a height field where
// `flatIsField`), or false with the reason.
bool TakeImage(
  const std::string& name, bool flatIsField, vtkImageData* image, Input& input, std::string& error)
{
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  int dims[3];
  image->GetDimensions(dims);
  if (scalars->GetNumberOfComponents() != 1)
  {
    error = vtkApertureText::QuoteName(name) + " holds " +
      std::to_string(scalars->GetNumberOfComponents()) +
      "-component scalars; a volume needs one (a grey-level CT or MR)";
    return false;
  }
  if (dims[2] == 1 && flatIsField && dims[0] > 1 && dims[1] > 1)
  {
    // Heights are a float array named Elevation, whatever the file held.
    vtkNew<vtkFloatArray> heights;
    heights->DeepCopy(scalars);
    heights->SetName("Elevation");
    input.Heights = vtkSmartPointer<vtkImageData>::New();
    input.Heights->CopyStructure(image);
    input.Heights->GetPointData()->SetScalars(heights);
    input.Description = vtkApertureText::QuoteName(name) + ", a height field of " +
      std::to_string(dims[0]) + " x " + std::to_string(dims[1]) + " samples";
    return true;
  }
  if (dims[0] < 2 || dims[1] < 2 || dims[2] < 2)
  {
    error = vtkApertureText::QuoteName(name) + " is " + std::to_string(dims[0]) + " x " +
      std::to_string(dims[1]) + " x " + std::to_string(dims[2]) +
      " voxels; a volume needs at least 2 along each axis";
    return false;
  }
  input.Volume = image;
  const double* spacing = image->GetSpacing();
  std::ostringstream description;
  description << vtkApertureText::QuoteName(name) << ", a volume of " << dims[0] << " x " << dims[1]
              << " x " << dims[2] << " voxels, " << spacing[0] << " x " << spacing[1] << " x "
              << spacing[2] << " apart";
  input.Description = description.str();
  return true;
}

}

//------------------------------------------------------------------------------
bool IsVolumeFile(const std::string& name)
{
  const std::string lower = Lower(name);
  for (const char* end : { ".vti", ".mha", ".mhd", ".nrrd", ".nhdr", ".nii", ".nii.gz" })
  {
    if (EndsWith(lower, end))
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
bool LoadVolume(const std::string& name, MessageCapture& messages, Input& input, std::string& error)
{
  if (!CheckHeader(name, error))
  {
    return false;
  }
  vtkSmartPointer<vtkAlgorithm> reader = VolumeReader(name);
  messages.Clear();
  auto* xml = vtkXMLReader::SafeDownCast(reader);
  if (xml && !CheckCompressedBlocks(xml, name, error))
  {
    return false;
  }
  reader->Update();
  auto* image = vtkImageData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!messages.FirstError().empty() || !image || !image->GetPointData()->GetScalars())
  {
    error = vtkApertureText::QuoteName(name) + " cannot be read as a volume: " +
      (messages.FirstError().empty() ? std::string("it holds no point scalars")
                                     : messages.FirstError());
    return false;
  }
  // NIfTI's axes are RAS, the face toward +y; DICOM's, and so most MetaImage and NRRD files', LPS.
  input.FrontAzimuth =
    EndsWith(Lower(name), ".nii") || EndsWith(Lower(name), ".nii.gz") ? 0.0 : 180.0;
  return TakeImage(name, EndsWith(Lower(name), ".vti"), image, input, error);
}

//------------------------------------------------------------------------------
bool LoadDICOM(
  const std::string& folder, MessageCapture& messages, Input& input, std::string& error)
{
  vtkNew<vtkApertureDICOMReader> reader;
  reader->SetDirectoryName(folder.c_str());
  messages.Clear();
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  if (!messages.FirstError().empty() || !image->GetPointData()->GetScalars())
  {
    error = messages.FirstError().empty()
      ? vtkApertureText::QuoteName(folder) + " cannot be read as a DICOM series"
      : messages.FirstError();
    return false;
  }
  input.FrontAzimuth = 180.0; // patient coordinates, LPS: the face toward -y
  return TakeImage(folder + " (DICOM)", false, image, input, error);
}

}
