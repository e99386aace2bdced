/*=========================================================================

  Program:   ApertureLighting
  Module:    TestOpenEXRReader.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkOpenEXRReader against files written here with the OpenEXR library: RGB half scanlines,
// RGBA float tiles, luminance, luminance-chroma, a data window inside the display window, the
// row order, NaN/Inf/negative values; then the CC0 environments (DWAB), the same file from
// memory, and bad input: missing, not EXR, truncated, absurd sizes, an attribute claiming 2 GiB,
// absurd tiles, no colour channel, and a few hundred randomly damaged files, none of which may
// crash the reader.

#include "vtkApertureTestHarness.h"
#include "vtkOpenEXRReader.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkTestErrorObserver.h"
#include "vtkTestUtilities.h"
#include "vtksys/SystemTools.hxx"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfRgbaFile.h>
#include <OpenEXR/ImfTiledOutputFile.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

namespace
{
using vtkApertureTest::Check;

// A smooth, asymmetric test value of channel k at file pixel (x, y) (row 0 at the top).
float Value(int x, int y, int k)
{
  return 0.25f * (k + 1) + 0.01f * x + 0.1f * y;
}

// Writes a w x h image of the given channels (FLOAT or HALF) over a data window.
void Write(const std::string& name, const Imath::Box2i& display, const Imath::Box2i& data,
  const std::vector<std::string>& channels, Imf::PixelType type, bool tiled,
  Imf::Compression compression = Imf::ZIP_COMPRESSION)
{
  Imf::Header header(display, data);
  header.compression() = compression;
  for (const std::string& c : channels)
  {
    header.channels().insert(c, Imf::Channel(type));
  }
  const int w = data.max.x - data.min.x + 1, h = data.max.y - data.min.y + 1;
  const size_t n = channels.size();
  std::vector<float> floats(static_cast<size_t>(w) * h * n);
  std::vector<half> halves(floats.size());
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      for (size_t k = 0; k < n; ++k)
      {
        const size_t i = (static_cast<size_t>(y) * w + x) * n + k;
        floats[i] = Value(x + data.min.x, y + data.min.y, static_cast<int>(k));
        halves[i] = floats[i];
      }
    }
  }
  const size_t bytes = type == Imf::FLOAT ? sizeof(float) : sizeof(half);
  char* base = (type == Imf::FLOAT ? reinterpret_cast<char*>(floats.data())
                                   : reinterpret_cast<char*>(halves.data())) -
    (static_cast<ptrdiff_t>(data.min.x) + static_cast<ptrdiff_t>(data.min.y) * w) * n * bytes;
  Imf::FrameBuffer frame;
  for (size_t k = 0; k < n; ++k)
  {
    frame.insert(channels[k], Imf::Slice(type, base + k * bytes, n * bytes, n * bytes * w));
  }
  if (tiled)
  {
    header.setTileDescription(Imf::TileDescription(16, 16, Imf::ONE_LEVEL));
    Imf::TiledOutputFile file(name.c_str(), header);
    file.setFrameBuffer(frame);
    file.writeTiles(0, file.numXTiles() - 1, 0, file.numYTiles() - 1);
  }
  else
  {
    Imf::OutputFile file(name.c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(h);
  }
}

// Reads a file; returns its radiance (empty after an error) and the errors and warnings.
struct Result
{
  vtkSmartPointer<vtkImageData> Image;
  int Errors = 0;
  int Warnings = 0;
  std::string Message;
};

Result Read(
  const std::string& name, const std::vector<char>* memory = nullptr, vtkTypeInt64 maximumBytes = 0)
{
  vtkNew<vtkOpenEXRReader> reader;
  if (memory)
  {
    reader->SetMemoryBuffer(memory->data());
    reader->SetMemoryBufferLength(static_cast<vtkIdType>(memory->size()));
  }
  else
  {
    reader->SetFileName(name.c_str());
  }
  if (maximumBytes > 0)
  {
    reader->SetMaximumBytes(maximumBytes);
  }
  vtkNew<vtkTest::ErrorObserver> observer, executive;
  reader->AddObserver(vtkCommand::ErrorEvent, observer);
  reader->AddObserver(vtkCommand::WarningEvent, observer);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executive);
  const bool ok = reader->GetExecutive()->Update() != 0;
  Result r;
  r.Errors = observer->GetError() ? 1 : 0;
  r.Warnings = observer->GetWarning() ? 1 : 0;
  r.Message = observer->GetError() ? observer->GetErrorMessage() : observer->GetWarningMessage();
  if (!r.Message.empty())
  {
    r.Message = r.Message.substr(r.Message.find("): ") + 3);
  }
  if (ok && reader->GetOutput()->GetPointData()->GetScalars())
  {
    r.Image = reader->GetOutput();
  }
  return r;
}

std::vector<char> Bytes(const std::string& name)
{
  std::ifstream in(name, std::ios::binary);
  return std::vector<char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void Save(const std::string& name, const std::vector<char>& bytes)
{
  std::ofstream out(name, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// Largest |read - written| over the image, for channel values written by Value().
double WorstError(vtkImageData* image, const Imath::Box2i& display, int components)
{
  vtkDataArray* a = image->GetPointData()->GetScalars();
  const int h = display.max.y - display.min.y + 1, w = display.max.x - display.min.x + 1;
  double worst = 0.0;
  for (int row = 0; row < h; ++row)
  {
    const int y = display.max.y - row; // VTK row 0 is the file's last row
    for (int x = 0; x < w; ++x)
    {
      for (int k = 0; k < components; ++k)
      {
        const double got = a->GetComponent(static_cast<vtkIdType>(row) * w + x, k);
        worst = std::max(worst, std::abs(got - Value(x + display.min.x, y, k)));
      }
    }
  }
  return worst;
}
}

int TestOpenEXRReader(int argc, char* argv[])
{
  char* temporary =
    vtkTestUtilities::GetArgOrEnvOrDefault("-T", argc, argv, "VTK_TEMP_DIR", "Testing/Temporary");
  const std::string temp = std::string(temporary) + "/TestOpenEXRReader-";
  delete[] temporary;
  if (!vtksys::SystemTools::FileIsDirectory(vtksys::SystemTools::GetFilenamePath(temp)))
  {
    std::cout << "FAIL no folder for the test's files: " << temp << " (give -T)\n";
    return EXIT_FAILURE;
  }
  const Imath::Box2i whole(Imath::V2i(0, 0), Imath::V2i(63, 31));

  // RGB half scanlines, RGBA float tiles, luminance: values and row order.
  Write(temp + "rgb-half.exr", whole, whole, { "R", "G", "B" }, Imf::HALF, false);
  Write(temp + "rgba-float-tiled.exr", whole, whole, { "R", "G", "B", "A" }, Imf::FLOAT, true);
  Write(temp + "y.exr", whole, whole, { "Y" }, Imf::FLOAT, false);
  struct Case
  {
    const char* Name;
    int Components;
    double Tolerance;
  };
  for (const Case& c : { Case{ "rgb-half.exr", 3, 4e-3 }, Case{ "rgba-float-tiled.exr", 4, 1e-6 },
         Case{ "y.exr", 1, 1e-6 } })
  {
    Result r = Read(temp + c.Name);
    const bool shaped = r.Image && r.Image->GetDimensions()[0] == 64 &&
      r.Image->GetDimensions()[1] == 32 &&
      r.Image->GetPointData()->GetScalars()->GetNumberOfComponents() == c.Components;
    const double worst = shaped ? WorstError(r.Image, whole, c.Components) : 1e9;
    std::cout << c.Name << ": " << (shaped ? "64 x 32" : "wrong shape") << ", worst error " << worst
              << "\n";
    Check(shaped && worst <= c.Tolerance && r.Errors == 0 && r.Warnings == 0,
      std::string("reads ") + c.Name);
  }

  // Luminance-chroma, converted to RGB by the library (chroma is subsampled: a grey ramp).
  {
    const int w = 64, h = 32;
    Imf::RgbaOutputFile file((temp + "yc.exr").c_str(), w, h, Imf::WRITE_YC);
    std::vector<Imf::Rgba> pixels(static_cast<size_t>(w) * h);
    for (int y = 0; y < h; ++y)
    {
      for (int x = 0; x < w; ++x)
      {
        const float v = 0.5f + 0.01f * x;
        pixels[static_cast<size_t>(y) * w + x] = Imf::Rgba(v, v, v, 1.0f);
      }
    }
    file.setFrameBuffer(pixels.data(), 1, w);
    file.writePixels(h);
  }
  Result yc = Read(temp + "yc.exr");
  double worstGrey = 1e9;
  if (yc.Image && yc.Image->GetPointData()->GetScalars()->GetNumberOfComponents() == 3)
  {
    worstGrey = 0.0;
    vtkDataArray* a = yc.Image->GetPointData()->GetScalars();
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        worstGrey = std::max(worstGrey, std::abs(a->GetComponent(i, k) - (0.5 + 0.01 * (i % 64))));
      }
    }
  }
  std::cout << "luminance-chroma: worst grey error " << worstGrey << "\n";
  Check(worstGrey < 0.01, "reads luminance-chroma as RGB");

  // A data window inside the display window: its pixels where they belong, zeros elsewhere.
  const Imath::Box2i inside(Imath::V2i(10, 5), Imath::V2i(29, 14));
  Write(temp + "window.exr", whole, inside, { "R", "G", "B" }, Imf::FLOAT, false);
  Result window = Read(temp + "window.exr");
  bool placed = window.Image != nullptr;
  for (int row = 0; placed && row < 32; ++row)
  {
    const int y = 31 - row;
    for (int x = 0; x < 64; ++x)
    {
      const bool in = x >= 10 && x <= 29 && y >= 5 && y <= 14;
      const double got = window.Image->GetPointData()->GetScalars()->GetComponent(row * 64 + x, 1);
      placed = placed && std::abs(got - (in ? Value(x, y, 1) : 0.0)) < 1e-6;
    }
  }
  Check(placed, "a data window is placed at its offset in the display window");

  // NaN, infinite and negative values are repaired, with one warning.
  {
    Imf::Header header(4, 2);
    header.channels().insert("R", Imf::Channel(Imf::FLOAT));
    const float nan = std::numeric_limits<float>::quiet_NaN(),
                inf = std::numeric_limits<float>::infinity();
    float values[8] = { 1.0f, nan, inf, -5.0f, 2.0f, -inf, 3.0f, 0.5f };
    Imf::FrameBuffer frame;
    frame.insert("R", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(values), 4, 16));
    Imf::OutputFile file((temp + "bad-values.exr").c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(2);
  }
  Result repaired = Read(temp + "bad-values.exr");
  bool clean = repaired.Image != nullptr;
  const double expected[8] = { 2.0, 0.0, 3.0, 0.5, 1.0, 0.0, 65504.0, 0.0 }; // rows flipped
  for (int i = 0; clean && i < 8; ++i)
  {
    clean = repaired.Image->GetPointData()->GetScalars()->GetComponent(i, 0) == expected[i];
  }
  std::cout << "bad values: " << repaired.Message;
  Check(clean && repaired.Warnings == 1, "NaN, infinite and negative values repaired, one warning");

  // The CC0 environments (DWAB), from the file and from memory.
  char* envName = vtkTestUtilities::ExpandDataFileName(argc, argv, "Data/env/forest.exr");
  const std::string forest = envName;
  delete[] envName;
  Result fromFile = Read(forest);
  const std::vector<char> forestBytes = Bytes(forest);
  Result fromMemory = Read("", &forestBytes);
  bool same = fromFile.Image && fromMemory.Image;
  double mean = 0.0;
  if (same)
  {
    vtkDataArray* a = fromFile.Image->GetPointData()->GetScalars();
    vtkDataArray* b = fromMemory.Image->GetPointData()->GetScalars();
    for (vtkIdType i = 0; same && i < a->GetNumberOfValues(); ++i)
    {
      same = a->GetVariantValue(i) == b->GetVariantValue(i);
      mean += a->GetVariantValue(i).ToDouble();
    }
    mean /= a->GetNumberOfValues();
  }
  std::cout << "forest.exr: " << (fromFile.Image ? fromFile.Image->GetDimensions()[0] : 0) << " x "
            << (fromFile.Image ? fromFile.Image->GetDimensions()[1] : 0) << ", mean radiance "
            << mean << ", memory " << (same ? "=" : "!=") << " file\n";
  Check(same && fromFile.Image->GetDimensions()[0] == 1024 &&
      fromFile.Image->GetDimensions()[1] == 512 && mean > 0.3 && mean < 1.0 &&
      fromFile.Warnings == 0,
    "reads the DWAB environment, the same from memory");

  // Bad input: one error each, no output, no crash.
  auto expectError = [&](const Result& r, const std::string& words, const std::string& what)
  {
    std::cout << what << ": " << r.Message;
    Check(!r.Image && r.Errors == 1 && r.Message.find(words) != std::string::npos, what);
  };
  expectError(Read(temp + "missing.exr"), "does not exist", "missing file");
  std::vector<char> notEXR(200, 'x');
  Save(temp + "not.exr", notEXR);
  expectError(Read(temp + "not.exr"), "is not an OpenEXR file", "not an EXR");
  std::vector<char> truncated(forestBytes.begin(), forestBytes.begin() + forestBytes.size() / 2);
  Save(temp + "truncated.exr", truncated);
  expectError(Read(temp + "truncated.exr"), "cannot be read", "truncated EXR");
  expectError(Read(temp + "rgb-half.exr", nullptr, 1000), "is not allowed", "over MaximumBytes");
  // A header that claims 100000 x 100000 pixels.
  const Imath::Box2i huge(Imath::V2i(0, 0), Imath::V2i(99999, 99999));
  {
    Imf::Header header(huge, Imath::Box2i(Imath::V2i(0, 0), Imath::V2i(0, 0)));
    header.channels().insert("R", Imf::Channel(Imf::HALF));
    half one = 1.0f;
    Imf::FrameBuffer frame;
    frame.insert("R", Imf::Slice(Imf::HALF, reinterpret_cast<char*>(&one), 2, 2));
    Imf::OutputFile file((temp + "huge.exr").c_str(), header);
    file.setFrameBuffer(frame);
    file.writePixels(1);
  }
  expectError(Read(temp + "huge.exr"), "are allowed", "absurd size");
  // An attribute whose size field claims 2 GiB: the library would allocate that before reading.
  std::vector<char> greedy = Bytes(temp + "rgb-half.exr");
  const size_t sizeField = 8 + std::strlen("channels") + 1 + std::strlen("chlist") + 1;
  Check(std::string(greedy.data() + 8) == "channels", "the first attribute is the channel list");
  const unsigned char claim[4] = { 0xff, 0xff, 0xff, 0x7f };
  std::memcpy(&greedy[sizeField], claim, 4);
  expectError(Read("", &greedy), "more than the file holds", "attribute size past the end");
  // Tiles of 2^31 x 1 pixels.
  std::vector<char> tiles = Bytes(temp + "rgba-float-tiled.exr");
  const std::string tileAttribute("tiles\0tiledesc\0", 15);
  const auto tileAt =
    std::search(tiles.begin(), tiles.end(), tileAttribute.begin(), tileAttribute.end());
  Check(tileAt != tiles.end(), "the tiled file has a tile description");
  if (tileAt != tiles.end())
  {
    const unsigned char wide[4] = { 0x00, 0x00, 0x00, 0x80 };
    std::memcpy(&*(tileAt + 15 + 4), wide, 4);
    expectError(Read("", &tiles), "are allowed", "absurd tile size");
  }
  Write(temp + "depth-only.exr", whole, whole, { "Z" }, Imf::FLOAT, false);
  expectError(Read(temp + "depth-only.exr"), "no R, G, B or Y channel", "no colour channel");

  // Damaged files: random bytes flipped in a small DWAB-free EXR and in the forest map.
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(5);
  const std::vector<char> small = Bytes(temp + "rgb-half.exr");
  int readable = 0, refused = 0;
  for (int trial = 0; trial < 300; ++trial)
  {
    std::vector<char> damaged = trial % 3 ? small : forestBytes;
    const int flips = 1 + trial % 4;
    for (int f = 0; f < flips; ++f)
    {
      const size_t at = static_cast<size_t>(random->GetNextValue() * (damaged.size() - 1));
      damaged[at] = static_cast<char>(static_cast<int>(random->GetNextValue() * 256) - 128);
    }
    Result r = Read("", &damaged);
    (r.Image ? readable : refused) += 1;
  }
  std::cout << "300 damaged files: " << refused << " refused with an error, " << readable
            << " read\n";
  return vtkApertureTest::Result();
}
