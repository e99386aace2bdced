/*=========================================================================

  Program:   ApertureLighting
  Module:    TestApertureDICOMReader.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkApertureDICOMReader on series written here by vtk-dicom's writer (a CT of one file a
// slice): the voxels, spacing and placement come back; a second series in the folder, a missing
// slice, an empty folder, a folder of non-DICOM files and no folder at all each give one error.

#include "vtkApertureDICOMReader.h"
#include "vtkDICOMCTGenerator.h"
#include "vtkDICOMWriter.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkShortArray.h"
#include "vtkTestErrorObserver.h"
#include "vtkTestUtilities.h"

#include <vtksys/SystemTools.hxx>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

namespace
{
bool Check(bool ok, const std::string& what)
{
  std::printf("%s %s\n", ok ? "ok  " : "FAIL", what.c_str());
  return ok;
}

// A CT of 24 x 20 x 12 voxels, 0.8 x 0.8 x 2.5 mm, values from -1000 to +1000 HU.
vtkSmartPointer<vtkImageData> MakeCT(int seed)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(24, 20, 12);
  image->SetSpacing(0.8, 0.8, 2.5);
  image->AllocateScalars(VTK_SHORT, 1);
  auto* values = vtkShortArray::SafeDownCast(image->GetPointData()->GetScalars());
  for (vtkIdType i = 0; i < values->GetNumberOfValues(); ++i)
  {
    values->SetValue(i, static_cast<short>((i * 37 + seed * 11) % 2001 - 1000));
  }
  return image;
}

void WriteSeries(
  vtkImageData* image, const std::string& folder, const char* pattern = "%s/IM-%04d.dcm")
{
  vtksys::SystemTools::MakeDirectory(folder);
  vtkNew<vtkDICOMCTGenerator> generator;
  vtkNew<vtkDICOMWriter> writer;
  writer->SetGenerator(generator);
  writer->SetInputData(image);
  writer->SetFilePrefix(folder.c_str());
  writer->SetFilePattern(pattern);
  writer->SetFileDimensionality(2);
  writer->Write();
}

// Reads `folder`; the error message ("" when none) in `error`.
vtkSmartPointer<vtkImageData> Read(const std::string& folder, int series, std::string& error)
{
  vtkNew<vtkTest::ErrorObserver> errors, executive;
  vtkNew<vtkApertureDICOMReader> reader;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executive);
  reader->SetDirectoryName(folder.c_str());
  reader->SetSeriesIndex(series);
  reader->Update();
  error = errors->GetError() ? errors->GetErrorMessage() : "";
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->ShallowCopy(reader->GetOutput());
  return image;
}

bool SameVoxels(vtkImageData* a, vtkImageData* b)
{
  vtkDataArray* x = a->GetPointData()->GetScalars();
  vtkDataArray* y = b->GetPointData()->GetScalars();
  if (!x || !y || x->GetNumberOfTuples() != y->GetNumberOfTuples())
  {
    return false;
  }
  for (vtkIdType i = 0; i < x->GetNumberOfTuples(); ++i)
  {
    if (x->GetTuple1(i) != y->GetTuple1(i))
    {
      return false;
    }
  }
  return true;
}

bool ExpectError(const std::string& folder, const std::string& words, const std::string& what)
{
  std::string error;
  vtkSmartPointer<vtkImageData> image = Read(folder, -1, error);
  const size_t start = error.find("): ");
  std::printf(
    "     %s\n", start == std::string::npos ? "(no error)" : error.substr(start + 3).c_str());
  return Check(error.find(words) != std::string::npos && image->GetNumberOfPoints() == 0,
    what + ": one error saying '" + words + "'");
}
}

int TestApertureDICOMReader(int argc, char* argv[])
{
  char* temporary =
    vtkTestUtilities::GetArgOrEnvOrDefault("-T", argc, argv, "VTK_TEMP_DIR", "Testing/Temporary");
  const std::string root = std::string(temporary) + "/TestApertureDICOMReader";
  delete[] temporary;
  vtksys::SystemTools::RemoveADirectory(root);
  bool ok = true;

  auto ct = MakeCT(1);
  WriteSeries(ct, root + "/one");
  std::string error;
  auto read = Read(root + "/one", -1, error);
  int dims[3];
  read->GetDimensions(dims);
  ok &= Check(error.empty() && dims[0] == 24 && dims[1] == 20 && dims[2] == 12,
    "one series: read, 24 x 20 x 12");
  ok &= Check(SameVoxels(ct, read), "one series: every voxel as written (Hounsfield units)");
  const double* spacing = read->GetSpacing();
  ok &= Check(std::abs(spacing[0] - 0.8) < 1e-6 && std::abs(spacing[2] - 2.5) < 1e-6,
    "one series: spacing 0.8 x 0.8 x 2.5 mm");

  WriteSeries(MakeCT(2), root + "/one", "%s/JM-%04d.dcm");
  ok &= ExpectError(root + "/one", "holds 2 series", "two series");
  auto second = Read(root + "/one", 1, error);
  ok &= Check(error.empty() && second->GetNumberOfPoints() == ct->GetNumberOfPoints(),
    "two series: SetSeriesIndex(1) reads one of them");

  WriteSeries(ct, root + "/gap");
  vtksys::SystemTools::RemoveFile(root + "/gap/IM-0005.dcm");
  ok &= ExpectError(root + "/gap", "slices are missing", "a missing slice");

  vtksys::SystemTools::MakeDirectory(root + "/empty");
  ok &= ExpectError(root + "/empty", "no DICOM image series", "an empty folder");
  vtksys::SystemTools::MakeDirectory(root + "/junk");
  std::ofstream(root + "/junk/IM-0001.dcm") << "DICM? not really\n";
  ok &= ExpectError(root + "/junk", "no DICOM image series", "a folder of non-DICOM files");
  ok &= ExpectError(root + "/nowhere", "is not a folder", "no folder");
  return ok ? 0 : 1;
}
