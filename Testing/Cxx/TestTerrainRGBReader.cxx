/*=========================================================================

  Program:   ApertureLighting
  Module:    TestTerrainRGBReader.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkTerrainRGBReader: the decoding formula, the Fuji tile's summit height, reading from memory
// against reading the file, and damaged input (missing, not a PNG, truncated, grey) failing with
// one error instead of a crash.

#include "vtkApertureTestHarness.h"
#include "vtkTerrainRGBReader.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkTestErrorObserver.h"
#include "vtkTestUtilities.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

namespace
{
using vtkApertureTest::Check;

std::vector<char> ReadBytes(const std::string& name)
{
  std::ifstream in(name, std::ios::binary);
  return std::vector<char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void WriteBytes(const std::string& name, const char* data, size_t size)
{
  std::ofstream out(name, std::ios::binary);
  out.write(data, static_cast<std::streamsize>(size));
}

// Updates the reader and expects it to fail with one error that says `words`, and no output.
void ExpectFailure(vtkTerrainRGBReader* reader, const std::string& words, const std::string& what)
{
  vtkNew<vtkTest::ErrorObserver> errors, executiveErrors;
  const unsigned long tag = reader->AddObserver(vtkCommand::ErrorEvent, errors);
  const unsigned long executiveTag =
    reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executiveErrors);
  const bool updated = reader->GetExecutive()->Update() != 0;
  reader->RemoveObserver(tag);
  reader->GetExecutive()->RemoveObserver(executiveTag);
  const std::string message = errors->GetError() ? errors->GetErrorMessage() : "(no error)";
  size_t count = 0;
  for (size_t at = message.find("ERROR: In"); at != std::string::npos;
       at = message.find("ERROR: In", at + 1))
  {
    ++count;
  }
  std::cout << what << ": " << message.substr(message.find("): ") + 3);
  Check(!updated && count == 1 && message.find(words) != std::string::npos &&
      reader->GetOutput()->GetNumberOfPoints() == 0,
    what + " fails with one error that says '" + words + "'");
}
}

int TestTerrainRGBReader(int argc, char* argv[])
{
  // height = -10000 + (R 65536 + G 256 + B) 0.1: sea level is (1, 134, 160).
  Check(vtkTerrainRGBReader::DecodeHeight(1, 134, 160) == 0.0, "sea level");
  Check(vtkTerrainRGBReader::DecodeHeight(0, 0, 0) == -10000.0, "lowest code");
  Check(std::abs(vtkTerrainRGBReader::DecodeHeight(2, 26, 32) - 3776.0) < 1e-9, "3776 m");

  char* fileName = vtkTestUtilities::ExpandDataFileName(argc, argv, "Data/fuji-terrain-rgb.png");
  const std::string fuji = fileName;
  delete[] fileName;
  char* tempDir =
    vtkTestUtilities::GetArgOrEnvOrDefault("-T", argc, argv, "VTK_TEMP_DIR", "Testing/Temporary");
  const std::string temp = tempDir;
  delete[] tempDir;

  vtkNew<vtkTerrainRGBReader> fromFile;
  fromFile->SetFileName(fuji.c_str());
  fromFile->SetSpacing(60.0, 60.0);
  fromFile->Update();
  vtkImageData* heights = fromFile->GetOutput();
  double range[2];
  heights->GetPointData()->GetScalars()->GetRange(range);
  int dims[3];
  heights->GetDimensions(dims);
  std::cout << "Fuji tile: " << dims[0] << " x " << dims[1] << ", heights " << range[0] << " to "
            << range[1] << " m\n";
  Check(dims[0] == 512 && dims[1] == 512 && dims[2] == 1, "512 x 512 grid");
  // Mount Fuji's summit is 3776 m; the tile's samples reach just below it.
  Check(range[1] > 3600.0 && range[1] <= 3776.5, "summit height");
  Check(heights->GetSpacing()[0] == 60.0, "spacing");

  // The same tile from memory.
  std::vector<char> bytes = ReadBytes(fuji);
  vtkNew<vtkTerrainRGBReader> fromMemory;
  fromMemory->SetMemoryBuffer(bytes.data());
  fromMemory->SetMemoryBufferLength(static_cast<vtkIdType>(bytes.size()));
  fromMemory->SetSpacing(60.0, 60.0);
  fromMemory->Update();
  vtkDataArray* a = heights->GetPointData()->GetScalars();
  vtkDataArray* b = fromMemory->GetOutput()->GetPointData()->GetScalars();
  bool same = b && b->GetNumberOfTuples() == a->GetNumberOfTuples();
  for (vtkIdType i = 0; same && i < a->GetNumberOfTuples(); ++i)
  {
    same = a->GetTuple1(i) == b->GetTuple1(i);
  }
  std::cout << "memory buffer vs file: " << (same ? "identical" : "different") << "\n";
  Check(same, "memory buffer reads the same heights as the file");

  // Damaged input.
  vtkNew<vtkTerrainRGBReader> bad;
  bad->SetFileName((temp + "/no-such-tile.png").c_str());
  ExpectFailure(bad, "does not exist", "missing file");

  const std::string notPNG = temp + "/TestTerrainRGBReader-not-a-png.png";
  WriteBytes(notPNG, "v 0 0 0\nv 1 0 0\n", 16);
  bad->SetFileName(notPNG.c_str());
  ExpectFailure(bad, "is not a PNG file", "not a PNG");

  const std::string truncated = temp + "/TestTerrainRGBReader-truncated.png";
  WriteBytes(truncated, bytes.data(), bytes.size() / 3);
  bad->SetFileName(truncated.c_str());
  ExpectFailure(bad, "is truncated", "truncated PNG file");

  vtkNew<vtkImageData> grey;
  grey->SetDimensions(4, 4, 1);
  grey->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  static_cast<vtkUnsignedCharArray*>(grey->GetPointData()->GetScalars())->Fill(7);
  const std::string greyName = temp + "/TestTerrainRGBReader-grey.png";
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(grey);
  writer->SetFileName(greyName.c_str());
  writer->Write();
  bad->SetFileName(greyName.c_str());
  ExpectFailure(bad, "three 8-bit channels", "grey PNG");

  bad->SetMemoryBuffer(bytes.data());
  bad->SetMemoryBufferLength(static_cast<vtkIdType>(bytes.size() / 3));
  ExpectFailure(bad, "is truncated", "truncated memory buffer");
  bad->SetMemoryBufferLength(4);
  ExpectFailure(bad, "is not a PNG file", "4-byte memory buffer");
  const std::string garbage(4096, 'x');
  bad->SetMemoryBuffer(garbage.data());
  bad->SetMemoryBufferLength(static_cast<vtkIdType>(garbage.size()));
  ExpectFailure(bad, "is not a PNG file", "memory buffer that is not a PNG");

  // Back to a good source after the failures.
  bad->SetMemoryBuffer(nullptr);
  bad->SetFileName(fuji.c_str());
  bad->Update();
  Check(bad->GetOutput()->GetNumberOfPoints() == 512 * 512, "a failed reader recovers");
  return vtkApertureTest::Result();
}
