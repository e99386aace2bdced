/*=========================================================================

  Program:   ApertureLighting
  Module:    VolumeFuzzSeeds.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "VolumeFuzzSeeds.h"

#include "vtkImageData.h"
#include "vtkMetaImageWriter.h"
#include "vtkNIFTIImageWriter.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkShortArray.h"
#include "vtkXMLImageDataWriter.h"

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

namespace
{
enum Format : char
{
  VTI = 0,
  MHA = 1,
  NRRD = 2,
  NII = 3,
  NII_GZ = 4
};

// A ball of 1000 in a 10 x 5 x `slices` grid of shorts (one slice: a mound, as heights). Ten
// along x: vtkNrrdReader takes a first axis of 9 or fewer for components.
vtkNew<vtkImageData> Ball(int slices)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(10, 5, slices);
  image->SetSpacing(0.5, 0.5, 1.0);
  image->SetOrigin(-1.0, 2.0, 0.5);
  vtkNew<vtkShortArray> values;
  values->SetName("Density");
  for (int k = 0; k < slices; ++k)
  {
    for (int j = 0; j < 5; ++j)
    {
      for (int i = 0; i < 10; ++i)
      {
        const double r2 = (i - 4.5) * (i - 4.5) + (j - 2.0) * (j - 2.0) + (k - 1.5) * (k - 1.5);
        values->InsertNextValue(static_cast<short>(r2 < 4.0 ? 1000 : -100 + 10 * i));
      }
    }
  }
  image->GetPointData()->SetScalars(values);
  return image;
}

// Named after its format, so that every seed has a file name of its own.
FuzzSeed Seed(const std::string& name, Format format, const std::string& bytes)
{
  static const char* const formats[] = { "vti", "mha", "nrrd", "nii", "nii-gz" };
  const std::string all = static_cast<char>(format) + bytes;
  return FuzzSeed{ std::string(formats[format]) + "-" + name,
    std::vector<char>(all.begin(), all.end()) };
}

// What a writer that writes files only wrote, read back.
template <typename Writer>
std::string Written(Writer* writer, const std::string& extension)
{
  const std::string name =
    "/tmp/aperture-seed-" + std::to_string(static_cast<long>(getpid())) + extension;
  writer->SetFileName(name.c_str());
  writer->Write();
  std::ifstream file(name, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  std::remove(name.c_str());
  return bytes;
}

// Compressed with zlib in small blocks, or not at all; an appended one with 8-byte headers.
std::string Vti(vtkImageData* image, int mode, bool compressed)
{
  vtkNew<vtkXMLImageDataWriter> writer;
  writer->SetInputData(image);
  writer->WriteToOutputStringOn();
  writer->SetDataMode(mode);
  if (compressed)
  {
    writer->SetCompressorTypeToZLib();
    writer->SetBlockSize(256);
    if (mode == vtkXMLWriter::Appended)
    {
      writer->SetHeaderTypeToUInt64();
      writer->EncodeAppendedDataOff();
    }
  }
  else
  {
    writer->SetCompressorTypeToNone();
  }
  writer->Write();
  return writer->GetOutputString();
}

std::string Mha(vtkImageData* image, bool compressed)
{
  vtkNew<vtkMetaImageWriter> writer;
  writer->SetInputData(image);
  writer->SetCompression(compressed);
  return Written(writer.Get(), ".mha");
}

std::string Nii(vtkImageData* image, const std::string& extension)
{
  vtkNew<vtkNIFTIImageWriter> writer;
  writer->SetInputData(image);
  return Written(writer.Get(), extension);
}

// VTK 9.1 has no NRRD writer: the header by hand, then the values as raw little-endian bytes
// or as text.
std::string Nrrd(vtkImageData* image, bool ascii)
{
  int dims[3];
  image->GetDimensions(dims);
  std::string text = "NRRD0004\ntype: short\ndimension: 3\nsizes: " + std::to_string(dims[0]) +
    " " + std::to_string(dims[1]) + " " + std::to_string(dims[2]) +
    "\nspacings: 0.5 0.5 1\nencoding: ";
  text += ascii ? "ascii\n\n" : "raw\nendian: little\n\n";
  auto* values = vtkShortArray::SafeDownCast(image->GetPointData()->GetScalars());
  for (vtkIdType i = 0; i < values->GetNumberOfValues(); ++i)
  {
    const short v = values->GetValue(i);
    if (ascii)
    {
      text += std::to_string(v) + (i % dims[0] == dims[0] - 1 ? "\n" : " ");
    }
    else
    {
      text += static_cast<char>(v & 0xff);
      text += static_cast<char>((v >> 8) & 0xff);
    }
  }
  return text;
}
}

std::vector<FuzzSeed> VolumeFuzzSeeds()
{
  vtkNew<vtkImageData> ball = Ball(4);
  vtkNew<vtkImageData> mound = Ball(1);
  return {
    Seed("ball-ascii", VTI, Vti(ball, vtkXMLWriter::Ascii, false)),
    Seed("ball-base64", VTI, Vti(ball, vtkXMLWriter::Binary, false)),
    Seed("ball-appended", VTI, Vti(ball, vtkXMLWriter::Appended, false)),
    Seed("ball-zlib-base64", VTI, Vti(ball, vtkXMLWriter::Binary, true)),
    Seed("ball-zlib-appended", VTI, Vti(ball, vtkXMLWriter::Appended, true)),
    Seed("mound-heights", VTI, Vti(mound, vtkXMLWriter::Ascii, false)),
    Seed("ball-raw", MHA, Mha(ball, false)),
    Seed("ball-zlib", MHA, Mha(ball, true)),
    Seed("ball-raw", NRRD, Nrrd(ball, false)),
    Seed("ball-ascii", NRRD, Nrrd(ball, true)),
    Seed("ball", NII, Nii(ball, ".nii")),
    Seed("ball", NII_GZ, Nii(ball, ".nii.gz")),
  };
}
