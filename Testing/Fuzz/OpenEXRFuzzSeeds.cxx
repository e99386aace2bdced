/*=========================================================================

  Program:   ApertureLighting
  Module:    OpenEXRFuzzSeeds.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "OpenEXRFuzzSeeds.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfRgbaFile.h>
#include <OpenEXR/ImfTiledOutputFile.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace
{
class MemoryOStream : public Imf::OStream
{
public:
  MemoryOStream()
    : Imf::OStream("seed")
  {
  }
  void write(const char c[], int n) override
  {
    if (this->Bytes.size() < this->Position + n)
    {
      this->Bytes.resize(this->Position + n);
    }
    std::memcpy(this->Bytes.data() + this->Position, c, n);
    this->Position += n;
  }
  uint64_t tellp() override { return this->Position; }
  void seekp(uint64_t position) override { this->Position = position; }

  std::vector<char> Bytes;

private:
  uint64_t Position = 0;
};

float Value(int x, int y, int k)
{
  return 0.25f + 0.2f * std::sin(0.7f * x + 1.3f * k) + 0.1f * y;
}

std::vector<char> Write(const Imath::Box2i& display, const Imath::Box2i& data,
  const std::vector<const char*>& channels, Imf::PixelType type, bool tiled,
  Imf::Compression compression)
{
  Imf::Header header(display, data);
  header.compression() = compression;
  for (const char* c : channels)
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
        floats[i] = Value(x, y, static_cast<int>(k));
        halves[i] = floats[i];
      }
    }
  }
  const size_t bytes = type == Imf::FLOAT ? sizeof(float) : sizeof(half);
  char* base = type == Imf::FLOAT ? reinterpret_cast<char*>(floats.data())
                                  : reinterpret_cast<char*>(halves.data());
  // Slices are addressed by absolute pixel coordinates.
  base -= (static_cast<ptrdiff_t>(data.min.y) * w + data.min.x) * n * bytes;
  Imf::FrameBuffer frame;
  for (size_t k = 0; k < n; ++k)
  {
    frame.insert(channels[k], Imf::Slice(type, base + k * bytes, n * bytes, n * bytes * w));
  }
  MemoryOStream stream;
  if (tiled)
  {
    header.setTileDescription(Imf::TileDescription(8, 8, Imf::ONE_LEVEL));
    Imf::TiledOutputFile file(stream, header);
    file.setFrameBuffer(frame);
    file.writeTiles(0, file.numXTiles() - 1, 0, file.numYTiles() - 1);
  }
  else
  {
    Imf::OutputFile file(stream, header);
    file.setFrameBuffer(frame);
    file.writePixels(h);
  }
  return stream.Bytes;
}
}

//------------------------------------------------------------------------------
std::vector<FuzzSeed> OpenEXRFuzzSeeds()
{
  static const struct
  {
    Imf::Compression Value;
    const char* Name;
  } compressions[] = { { Imf::NO_COMPRESSION, "none" }, { Imf::RLE_COMPRESSION, "rle" },
    { Imf::ZIPS_COMPRESSION, "zips" }, { Imf::ZIP_COMPRESSION, "zip" },
    { Imf::PIZ_COMPRESSION, "piz" }, { Imf::PXR24_COMPRESSION, "pxr24" },
    { Imf::B44_COMPRESSION, "b44" }, { Imf::B44A_COMPRESSION, "b44a" },
    { Imf::DWAA_COMPRESSION, "dwaa" }, { Imf::DWAB_COMPRESSION, "dwab" } };
  const Imath::Box2i whole(Imath::V2i(0, 0), Imath::V2i(15, 7));
  const Imath::Box2i inside(Imath::V2i(3, 2), Imath::V2i(12, 6));
  std::vector<FuzzSeed> seeds;
  for (const auto& c : compressions)
  {
    const std::string name = c.Name;
    seeds.push_back(
      { "rgb-half-" + name, Write(whole, whole, { "R", "G", "B" }, Imf::HALF, false, c.Value) });
    seeds.push_back({ "rgba-float-tiled-" + name,
      Write(whole, whole, { "R", "G", "B", "A" }, Imf::FLOAT, true, c.Value) });
  }
  seeds.push_back(
    { "y-float", Write(whole, whole, { "Y" }, Imf::FLOAT, false, Imf::ZIP_COMPRESSION) });
  seeds.push_back({ "window-rgb-float",
    Write(whole, inside, { "R", "G", "B" }, Imf::FLOAT, false, Imf::PIZ_COMPRESSION) });
  {
    MemoryOStream stream;
    {
      Imf::RgbaOutputFile file(stream, Imf::Header(16, 8), Imf::WRITE_YC);
      std::vector<Imf::Rgba> pixels(16 * 8);
      for (int y = 0; y < 8; ++y)
      {
        for (int x = 0; x < 16; ++x)
        {
          pixels[y * 16 + x] = Imf::Rgba(Value(x, y, 0), Value(x, y, 1), Value(x, y, 2), 1.0f);
        }
      }
      file.setFrameBuffer(pixels.data(), 1, 16);
      file.writePixels(8);
    }
    seeds.push_back({ "yc-half", stream.Bytes });
  }
  return seeds;
}
