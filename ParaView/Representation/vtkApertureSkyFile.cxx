/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureSkyFile.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureSkyFile.h"

#include "vtkApertureText.h"
#include "vtkImageData.h"
#include "vtkOpenEXRReader.h"

//------------------------------------------------------------------------------
vtkApertureSkyFile::vtkApertureSkyFile()
{
  this->Map->SetUpAxisToY(); // ParaView's view up
}

//------------------------------------------------------------------------------
bool vtkApertureSkyFile::SetFileName(const char* fileName, vtkObject* reporter)
{
  const std::string name = fileName ? fileName : "";
  if (name == this->FileName)
  {
    return false;
  }
  this->FileName = name;
  this->Loaded = false;
  if (!name.empty())
  {
    vtkNew<vtkOpenEXRReader> reader;
    reader->SetFileName(name.c_str());
    reader->Update();
    vtkImageData* image = reader->GetOutput();
    this->Loaded = reader->GetErrorCode() == 0 && image->GetNumberOfPoints() > 0;
    if (this->Loaded)
    {
      this->Map->SetImage(image);
    }
    else
    {
      vtkErrorWithObjectMacro(reporter,
        "Cannot read the sky environment " << vtkApertureText::QuoteName(name)
                                           << "; the sky stays uniform.");
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkApertureSkyFile::PrintSelf(ostream& os, vtkIndent indent)
{
  os << indent << "SkyEnvironmentFile: \"" << this->FileName << "\""
     << (this->Loaded ? "" : " (not in use)") << "\n";
  os << indent << "SkyEnvironment:\n";
  this->Map->PrintSelf(os, indent.GetNextIndent());
}
