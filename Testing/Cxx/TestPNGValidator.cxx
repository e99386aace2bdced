/*=========================================================================

  Program:   ApertureLighting
  Module:    TestPNGValidator.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkPNGValidator against an encoder written here: PNGs of every colour type, bit depths 1 to 16,
// plain and interlaced, are accepted and vtkPNGReader decodes them to the pixels encoded. Then
// damage: every truncation, random bytes flipped, and flipped bytes with the chunk CRC repaired
// (so that only the compressed data are wrong). Whatever the validator accepts is handed to
// vtkPNGReader, which crashes on any libpng error: the test passing is the guarantee.

#include "vtkApertureTestHarness.h"
#include "vtkPNGValidator.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkPointData.h"
#include "vtk_zlib.h"

#include <cstdint>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using vtkApertureTest::Check;

using Bytes = std::vector<unsigned char>;

void Put32(Bytes& out, uint32_t v)
{
  for (int shift = 24; shift >= 0; shift -= 8)
  {
    out.push_back(static_cast<unsigned char>(v >> shift));
  }
}

void PutChunk(Bytes& out, const char* type, const Bytes& body)
{
  Put32(out, static_cast<uint32_t>(body.size()));
  const size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), body.begin(), body.end());
  Put32(
    out, static_cast<uint32_t>(crc32(0L, out.data() + start, static_cast<uInt>(4 + body.size()))));
}

struct Image
{
  uint32_t Width, Height;
  int Depth, ColorType, Channels;
  bool Interlaced;
  std::vector<uint16_t> Samples; // row-major, Channels per pixel
};

// Packs one row of samples (MSB first below 8 bits, big-endian at 16).
Bytes PackRow(const Image& image, const std::vector<uint16_t>& samples)
{
  Bytes row;
  int bits = 0;
  unsigned acc = 0;
  for (uint16_t s : samples)
  {
    if (image.Depth == 16)
    {
      row.push_back(static_cast<unsigned char>(s >> 8));
      row.push_back(static_cast<unsigned char>(s & 0xff));
      continue;
    }
    acc = (acc << image.Depth) | s;
    bits += image.Depth;
    if (bits == 8)
    {
      row.push_back(static_cast<unsigned char>(acc));
      acc = 0;
      bits = 0;
    }
  }
  if (bits > 0)
  {
    row.push_back(static_cast<unsigned char>(acc << (8 - bits)));
  }
  return row;
}

Bytes Encode(const Image& image)
{
  static const int adam7[7][4] = { { 0, 0, 8, 8 }, { 4, 0, 8, 8 }, { 0, 4, 4, 8 }, { 2, 0, 4, 4 },
    { 0, 2, 2, 4 }, { 1, 0, 2, 2 }, { 0, 1, 1, 2 } };
  const int whole[1][4] = { { 0, 0, 1, 1 } };
  const int(*passes)[4] = image.Interlaced ? adam7 : whole;
  const int passCount = image.Interlaced ? 7 : 1;
  const int bpp = std::max(1, image.Channels * image.Depth / 8);
  Bytes raw;
  int rowIndex = 0;
  for (int p = 0; p < passCount; ++p)
  {
    Bytes previous;
    for (uint32_t y = passes[p][1]; y < image.Height; y += passes[p][3])
    {
      std::vector<uint16_t> samples;
      for (uint32_t x = passes[p][0]; x < image.Width; x += passes[p][2])
      {
        for (int c = 0; c < image.Channels; ++c)
        {
          samples.push_back(image.Samples[(y * image.Width + x) * image.Channels + c]);
        }
      }
      if (samples.empty())
      {
        break;
      }
      const Bytes row = PackRow(image, samples);
      // Filters None, Sub and Up in turn.
      const int filter = rowIndex++ % 3;
      raw.push_back(static_cast<unsigned char>(filter));
      for (size_t i = 0; i < row.size(); ++i)
      {
        const int left = filter == 1 && i >= size_t(bpp) ? row[i - bpp] : 0;
        const int up = filter == 2 && !previous.empty() ? previous[i] : 0;
        raw.push_back(static_cast<unsigned char>(row[i] - left - up));
      }
      previous = row;
    }
  }
  uLongf size = compressBound(static_cast<uLong>(raw.size()));
  Bytes compressed(size);
  compress2(compressed.data(), &size, raw.data(), static_cast<uLong>(raw.size()), 9);
  compressed.resize(size);

  Bytes png = { 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n' };
  Bytes header;
  Put32(header, image.Width);
  Put32(header, image.Height);
  header.push_back(static_cast<unsigned char>(image.Depth));
  header.push_back(static_cast<unsigned char>(image.ColorType));
  header.push_back(0);
  header.push_back(0);
  header.push_back(image.Interlaced ? 1 : 0);
  PutChunk(png, "IHDR", header);
  if (image.ColorType == 3)
  {
    Bytes palette;
    for (int i = 0; i < (1 << image.Depth); ++i)
    {
      palette.insert(palette.end(),
        { static_cast<unsigned char>(i * 7), static_cast<unsigned char>(255 - i), 100 });
    }
    PutChunk(png, "PLTE", palette);
  }
  // Two IDAT chunks, as encoders often split the stream.
  const size_t half = compressed.size() / 2;
  PutChunk(png, "IDAT", Bytes(compressed.begin(), compressed.begin() + half));
  PutChunk(png, "IDAT", Bytes(compressed.begin() + half, compressed.end()));
  PutChunk(png, "tEXt", Bytes{ 'K', 0, 'v' });
  PutChunk(png, "IEND", Bytes());
  return png;
}

// Decodes with vtkPNGReader; the caller must have validated the bytes.
vtkSmartPointer<vtkImageData> Decode(const Bytes& png)
{
  vtkNew<vtkPNGReader> reader;
  reader->SetMemoryBuffer(png.data());
  reader->SetMemoryBufferLength(static_cast<vtkIdType>(png.size()));
  reader->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->ShallowCopy(reader->GetOutput());
  return image;
}

// The value vtkPNGReader gives a sample: bit depths below 8 expand to 8 bits by libpng's rules
// for grey (v * 255 / (2^d - 1)); palette index i becomes the palette's red, 7 i mod 256.
double Expected(const Image& image, uint16_t s)
{
  if (image.ColorType == 3)
  {
    return (s * 7) % 256;
  }
  return image.Depth < 8 ? s * 255 / ((1 << image.Depth) - 1) : s;
}

bool DecodesTo(const Image& image, const Bytes& png)
{
  vtkSmartPointer<vtkImageData> decoded = Decode(png);
  vtkDataArray* scalars = decoded->GetPointData()->GetScalars();
  int dims[3];
  decoded->GetDimensions(dims);
  if (!scalars || dims[0] != int(image.Width) || dims[1] != int(image.Height))
  {
    return false;
  }
  // VTK puts the PNG's first row at the top: row y of the file is VTK row Height - 1 - y.
  for (uint32_t y = 0; y < image.Height; ++y)
  {
    for (uint32_t x = 0; x < image.Width; ++x)
    {
      const vtkIdType id = (image.Height - 1 - y) * image.Width + x;
      const int channels = image.ColorType == 3 ? 1 : image.Channels;
      for (int c = 0; c < channels; ++c)
      {
        const uint16_t s = image.Samples[(y * image.Width + x) * image.Channels + c];
        if (scalars->GetComponent(id, c) != Expected(image, s))
        {
          return false;
        }
      }
    }
  }
  return true;
}
}

int TestPNGValidator(int, char*[])
{
  vtkMath::RandomSeed(11);
  const int formats[][3] = { // colour type, channels, bit depth
    { 0, 1, 1 }, { 0, 1, 2 }, { 0, 1, 4 }, { 0, 1, 8 }, { 0, 1, 16 }, { 2, 3, 8 }, { 2, 3, 16 },
    { 3, 1, 4 }, { 3, 1, 8 }, { 4, 2, 8 }, { 6, 4, 8 }, { 6, 4, 16 }
  };
  std::vector<Bytes> samples;
  int accepted = 0, decoded = 0, cases = 0;
  for (const auto& f : formats)
  {
    for (bool interlaced : { false, true })
    {
      Image image{ 13, 11, f[2], f[0], f[1], interlaced, {} };
      const int maximum = (1 << f[2]) - 1;
      for (uint32_t i = 0; i < image.Width * image.Height * image.Channels; ++i)
      {
        image.Samples.push_back(static_cast<uint16_t>(vtkMath::Round(vtkMath::Random(0, maximum))));
      }
      const Bytes png = Encode(image);
      const std::string problem = vtkPNGValidator::CheckBuffer(png.data(), png.size());
      const std::string name = "colour type " + std::to_string(f[0]) + ", depth " +
        std::to_string(f[2]) + (interlaced ? ", interlaced" : "");
      ++cases;
      Check(problem.empty(), name + " accepted (" + problem + ")");
      if (problem.empty())
      {
        ++accepted;
        const bool same = DecodesTo(image, png);
        decoded += same ? 1 : 0;
        Check(same, name + " decodes to the encoded pixels");
      }
      samples.push_back(png);
    }
  }
  std::cout << accepted << " of " << cases << " well-formed PNGs accepted, " << decoded
            << " decoded to their pixels by vtkPNGReader\n";

  // Every truncation of two of them is refused.
  int truncations = 0, refused = 0;
  for (const Bytes* png : { &samples[4], &samples[11] })
  {
    for (size_t size = 0; size < png->size(); ++size)
    {
      ++truncations;
      refused += vtkPNGValidator::CheckBuffer(png->data(), size).empty() ? 0 : 1;
    }
  }
  std::cout << refused << " of " << truncations << " truncations refused\n";
  Check(refused == truncations, "every truncation is refused");

  // Damage: random bytes flipped, with and without the chunk CRCs repaired. What passes must
  // decode (a libpng error would crash vtkPNGReader here).
  int damaged = 0, passed = 0;
  for (const Bytes& png : samples)
  {
    for (int trial = 0; trial < 150; ++trial)
    {
      Bytes bad = png;
      const size_t at = 8 + static_cast<size_t>(vtkMath::Random(0, bad.size() - 8.001));
      bad[at] ^= static_cast<unsigned char>(1 + vtkMath::Round(vtkMath::Random(0, 254)));
      if (trial % 2)
      {
        // Repair the CRC of every chunk, so that only the content is wrong.
        size_t pos = 8;
        while (pos + 12 <= bad.size())
        {
          const uint32_t length = (uint32_t(bad[pos]) << 24) | (uint32_t(bad[pos + 1]) << 16) |
            (uint32_t(bad[pos + 2]) << 8) | bad[pos + 3];
          if (length > bad.size() - pos - 12)
          {
            break;
          }
          const uLong crc = crc32(0L, bad.data() + pos + 4, length + 4);
          for (int k = 0; k < 4; ++k)
          {
            bad[pos + 8 + length + k] = static_cast<unsigned char>(crc >> (24 - 8 * k));
          }
          pos += 12 + length;
        }
      }
      if (bad == png)
      {
        continue; // the flip hit a CRC that was then repaired
      }
      ++damaged;
      if (vtkPNGValidator::CheckBuffer(bad.data(), bad.size()).empty())
      {
        ++passed;
        Decode(bad);
      }
    }
  }
  std::cout << damaged << " damaged PNGs: " << damaged - passed << " refused, " << passed
            << " passed (still decodable) and decoded without a libpng error\n";

  // Files.
  Check(!vtkPNGValidator::CheckFile("/no/such/file.png").empty(), "a missing file is refused");
  Check(!vtkPNGValidator::CheckFile(nullptr).empty(), "no file name is refused");
  Check(!vtkPNGValidator::CheckBuffer(nullptr, 100).empty(), "a null buffer is refused");
  return vtkApertureTest::Result();
}
