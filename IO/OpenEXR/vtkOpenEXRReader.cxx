/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkOpenEXRReader.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkOpenEXRReader.h"

#include "vtkApertureText.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtksys/SystemTools.hxx"

#include <OpenEXR/IexBaseExc.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfRgbaFile.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkOpenEXRReader);

namespace
{
// An EXR held in memory, as the OpenEXR library reads files.
class MemoryStream : public Imf::IStream
{
public:
  MemoryStream(const char* data, uint64_t size, const std::string& name)
    : Imf::IStream(name.c_str())
    , Data(data)
    , Size(size)
  {
  }

  bool read(char c[], int n) override
  {
    if (n < 0 || this->Position > this->Size || this->Size - this->Position < uint64_t(n))
    {
      throw Iex::InputExc("the data end before the file does (truncated)");
    }
    std::memcpy(c, this->Data + this->Position, static_cast<size_t>(n));
    this->Position += n;
    return this->Position < this->Size;
  }
  uint64_t tellg() override { return this->Position; }
  void seekg(uint64_t position) override { this->Position = position; }

private:
  const char* Data;
  uint64_t Size;
  uint64_t Position = 0;
};

// The top-level channels an image is read from.
enum class Layout
{
  None,
  Luminance,       // Y
  LuminanceChroma, // Y, RY, BY: converted to RGB by the library
  RGB,
  RGBA
};

Layout LayoutOf(const Imf::ChannelList& channels)
{
  const bool r = channels.findChannel("R"), g = channels.findChannel("G"),
             b = channels.findChannel("B"), a = channels.findChannel("A"),
             y = channels.findChannel("Y");
  if (r || g || b)
  {
    return a ? Layout::RGBA : Layout::RGB;
  }
  if (y)
  {
    return channels.findChannel("RY") || channels.findChannel("BY") ? Layout::LuminanceChroma
                                                                    : Layout::Luminance;
  }
  return Layout::None;
}

int ComponentsOf(Layout layout)
{
  switch (layout)
  {
    case Layout::Luminance:
      return 1;
    case Layout::RGBA:
      return 4;
    case Layout::None:
      return 0;
    default:
      return 3;
  }
}

// The source of the bytes: the memory buffer or the whole file.
struct Source
{
  std::vector<char> FileBytes;
  const char* Data = nullptr;
  uint64_t Size = 0;
};
}

//------------------------------------------------------------------------------
vtkOpenEXRReader::vtkOpenEXRReader()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
void vtkOpenEXRReader::SetMemoryBuffer(const void* buffer)
{
  if (this->MemoryBuffer != buffer)
  {
    this->MemoryBuffer = buffer;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkOpenEXRReader::CanRead()
{
  static const unsigned char magic[4] = { 0x76, 0x2f, 0x31, 0x01 };
  unsigned char head[4] = { 0, 0, 0, 0 };
  if (this->MemoryBuffer)
  {
    if (this->MemoryBufferLength < 4)
    {
      return false;
    }
    std::memcpy(head, this->MemoryBuffer, 4);
  }
  else
  {
    std::ifstream in(this->FileName, std::ios::binary);
    if (!in.read(reinterpret_cast<char*>(head), 4))
    {
      return false;
    }
  }
  return std::memcmp(head, magic, 4) == 0;
}

namespace
{
std::int32_t Int32At(const char* p)
{
  const unsigned char* b = reinterpret_cast<const unsigned char*>(p);
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(b[0]) | (std::uint32_t(b[1]) << 8) |
    (std::uint32_t(b[2]) << 16) | (std::uint32_t(b[3]) << 24));
}

// The value of one header attribute: windows and tiles within maximumSide, chunk counts within
// the file's bytes.
bool CheckAttribute(const std::string& attribute, const std::string& type, const char* value,
  std::int32_t length, uint64_t size, int maximumSide, std::string& error)
{
  if ((attribute == "dataWindow" || attribute == "displayWindow") && type == "box2i" &&
    length == 16)
  {
    const vtkTypeInt64 width = vtkTypeInt64(Int32At(value + 8)) - Int32At(value) + 1;
    const vtkTypeInt64 height = vtkTypeInt64(Int32At(value + 12)) - Int32At(value + 4) + 1;
    if (width < 1 || height < 1 || width > maximumSide || height > maximumSide)
    {
      error = "its " + attribute + " is " + std::to_string(width) + " x " + std::to_string(height) +
        ": sides from 1 to " + std::to_string(maximumSide) + " are allowed";
      return false;
    }
  }
  else if (attribute == "tiles" && type == "tiledesc" && length == 9)
  {
    const vtkTypeInt64 tileWidth = static_cast<std::uint32_t>(Int32At(value));
    const vtkTypeInt64 tileHeight = static_cast<std::uint32_t>(Int32At(value + 4));
    if (tileWidth < 1 || tileHeight < 1 || tileWidth > maximumSide || tileHeight > maximumSide)
    {
      error = "its tiles are " + std::to_string(tileWidth) + " x " + std::to_string(tileHeight) +
        ": sides from 1 to " + std::to_string(maximumSide) + " are allowed";
      return false;
    }
  }
  else if (attribute == "chunkCount" && type == "int" && length == 4 &&
    (Int32At(value) < 0 || static_cast<uint64_t>(Int32At(value)) > size / 8))
  {
    error = "its chunk count, " + std::to_string(Int32At(value)) +
      ", does not fit in the file (truncated or damaged)";
    return false;
  }
  return true;
}

// Walks the headers before the library reads them. The library allocates what an attribute's
// size field says before reading its value, and its chunk tables from the windows and the chunk
// count, so a few damaged bytes could make it ask for gigabytes. Here every attribute must lie
// within the bytes, and pass CheckAttribute().
class HeaderWalk
{
public:
  HeaderWalk(const char* data, uint64_t size, int maximumSide)
    : Data(data)
    , Size(size)
    , MaximumSide(maximumSide)
  {
  }

  bool Check(std::string& error)
  {
    if (this->Size < 8)
    {
      error = "the file ends inside its version field (truncated)";
      return false;
    }
    const std::int32_t version = Int32At(this->Data + 4);
    if ((version & 0xff) != 2)
    {
      error = "OpenEXR format version " + std::to_string(version & 0xff) + " is not supported";
      return false;
    }
    const bool multipart = (version & 0x1000) != 0;
    this->LongestName = (version & 0x400) ? 255 : 31;
    this->At = 8;
    // Multi-part files list headers until an empty one.
    while (this->Header(error))
    {
      if (!multipart || (this->At < this->Size && this->Data[this->At] == 0))
      {
        return true;
      }
      if (this->At >= this->Size)
      {
        error = "the file ends inside its headers (truncated)";
        return false;
      }
    }
    return false;
  }

private:
  // One header: attributes up to a zero byte.
  bool Header(std::string& error)
  {
    while (true)
    {
      if (this->At >= this->Size)
      {
        error = "the file ends inside its header (truncated)";
        return false;
      }
      if (this->Data[this->At] == 0)
      {
        ++this->At;
        return true;
      }
      std::string attribute, type;
      if (!this->Name(attribute) || !this->Name(type) || this->Size - this->At < 4)
      {
        error = "its header is damaged (an attribute without a valid name or type)";
        return false;
      }
      const std::int32_t length = Int32At(this->Data + this->At);
      this->At += 4;
      if (length < 0 || static_cast<uint64_t>(length) > this->Size - this->At)
      {
        error = "its header attribute " + vtkApertureText::Quote(attribute) + " claims " +
          std::to_string(length) + " bytes, more than the file holds (truncated or damaged)";
        return false;
      }
      if (!CheckAttribute(
            attribute, type, this->Data + this->At, length, this->Size, this->MaximumSide, error))
      {
        return false;
      }
      this->At += static_cast<uint64_t>(length);
    }
  }

  // A zero-terminated, non-empty name of at most LongestName characters.
  bool Name(std::string& text)
  {
    const uint64_t end = std::min(this->Size, this->At + this->LongestName + 1);
    const void* zero = std::memchr(this->Data + this->At, 0, static_cast<size_t>(end - this->At));
    if (!zero)
    {
      return false;
    }
    text.assign(this->Data + this->At, static_cast<const char*>(zero));
    this->At += text.size() + 1;
    return !text.empty();
  }

  const char* Data;
  const uint64_t Size;
  const int MaximumSide;
  uint64_t LongestName = 31;
  uint64_t At = 8;
};

// Opens the EXR (after the checks a reader can make without the library), or returns nullptr
// with the reason.
std::unique_ptr<Imf::InputFile> Open(const std::string& fileName, const void* buffer,
  vtkIdType length, int maximumSide, Source& source, std::unique_ptr<MemoryStream>& stream,
  std::string& error)
{
  const std::string what =
    buffer ? std::string("The memory buffer") : vtkApertureText::QuoteName(fileName);
  if (buffer)
  {
    source.Data = static_cast<const char*>(buffer);
    source.Size = static_cast<uint64_t>(length);
  }
  else
  {
    if (fileName.empty() || !vtksys::SystemTools::FileExists(fileName, true))
    {
      error = "OpenEXR file " + vtkApertureText::QuoteName(fileName) + " does not exist";
      return nullptr;
    }
    std::ifstream in(fileName, std::ios::binary);
    source.FileBytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    source.Data = source.FileBytes.data();
    source.Size = source.FileBytes.size();
  }
  static const unsigned char magic[4] = { 0x76, 0x2f, 0x31, 0x01 };
  if (source.Size < 4 || std::memcmp(source.Data, magic, 4) != 0)
  {
    error = what + " is not an OpenEXR file";
    return nullptr;
  }
  if (!HeaderWalk(source.Data, source.Size, maximumSide).Check(error))
  {
    error = what + " cannot be read as OpenEXR: " + error;
    return nullptr;
  }
  try
  {
    stream.reset(new MemoryStream(source.Data, source.Size, buffer ? "memory buffer" : fileName));
    return std::unique_ptr<Imf::InputFile>(new Imf::InputFile(*stream));
  }
  catch (const std::exception& e)
  {
    error = what + " cannot be read as OpenEXR: " + vtkApertureText::Line(e.what(), 200);
  }
  return nullptr;
}
}

//------------------------------------------------------------------------------
int vtkOpenEXRReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  this->Width = this->Height = this->Components = 0;
  Source source;
  std::unique_ptr<MemoryStream> stream;
  std::string error;
  std::unique_ptr<Imf::InputFile> file = Open(this->FileName, this->MemoryBuffer,
    this->MemoryBufferLength, this->MaximumSide, source, stream, error);
  if (!file)
  {
    vtkErrorMacro(<< error << ".");
    return 0;
  }
  const Imf::Header& header = file->header();
  const Imath::Box2i display = header.displayWindow();
  const Imath::Box2i data = header.dataWindow();
  const vtkTypeInt64 width = vtkTypeInt64(display.max.x) - display.min.x + 1;
  const vtkTypeInt64 height = vtkTypeInt64(display.max.y) - display.min.y + 1;
  const vtkTypeInt64 dataWidth = vtkTypeInt64(data.max.x) - data.min.x + 1;
  const vtkTypeInt64 dataHeight = vtkTypeInt64(data.max.y) - data.min.y + 1;
  const Layout layout = LayoutOf(header.channels());
  if (layout == Layout::None)
  {
    std::string names;
    for (auto c = header.channels().begin(); c != header.channels().end(); ++c)
    {
      names += std::string(names.empty() ? "" : ", ") + vtkApertureText::Quote(c.name(), 24);
    }
    vtkErrorMacro("The EXR has no R, G, B or Y channel to read (it has: "
      << (names.empty() ? std::string("none") : vtkApertureText::Line(names, 200)) << ").");
    return 0;
  }
  const int components = ComponentsOf(layout);
  if (width < 1 || height < 1 || dataWidth < 1 || dataHeight < 1 || width > this->MaximumSide ||
    height > this->MaximumSide || dataWidth > this->MaximumSide || dataHeight > this->MaximumSide ||
    4 * components * (width * height + dataWidth * dataHeight) > this->MaximumBytes)
  {
    vtkErrorMacro("The EXR's size, " << width << " x " << height << " (data window " << dataWidth
                                     << " x " << dataHeight << "), is not allowed: sides up to "
                                     << this->MaximumSide << " and " << this->MaximumBytes
                                     << " bytes in all.");
    return 0;
  }
  this->Width = static_cast<int>(width);
  this->Height = static_cast<int>(height);
  this->Components = components;

  vtkInformation* info = outputVector->GetInformationObject(0);
  const int extent[6] = { 0, this->Width - 1, 0, this->Height - 1, 0, 0 };
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  const double spacing[3] = { 1.0, 1.0, 1.0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  info->Set(vtkDataObject::SPACING(), spacing, 3);
  info->Set(vtkDataObject::ORIGIN(), origin, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(info, VTK_FLOAT, components);
  return 1;
}

namespace
{
// The data window's pixels of a luminance-chroma image, which the library converts to RGB.
void ReadLuminanceChroma(const Source& source, const std::string& name, const Imath::Box2i& data,
  int c, std::vector<float>& pixels)
{
  const int width = data.max.x - data.min.x + 1;
  MemoryStream stream(source.Data, source.Size, name);
  Imf::RgbaInputFile rgba(stream);
  std::vector<Imf::Rgba> row(static_cast<size_t>(width));
  for (int y = data.min.y; y <= data.max.y; ++y)
  {
    rgba.setFrameBuffer(
      row.data() - data.min.x - static_cast<ptrdiff_t>(y) * width, 1, static_cast<size_t>(width));
    rgba.readPixels(y);
    for (int x = 0; x < width; ++x)
    {
      float* p = &pixels[(static_cast<size_t>(y - data.min.y) * width + x) * c];
      p[0] = row[x].r;
      p[1] = row[x].g;
      p[2] = row[x].b;
    }
  }
}

// The data window's pixels, channel by channel: missing colour channels read as 0, a missing
// alpha as 1.
void ReadChannels(
  Imf::InputFile& file, Layout layout, const Imath::Box2i& data, int c, std::vector<float>& pixels)
{
  const char* names[4] = { layout == Layout::Luminance ? "Y" : "R", "G", "B", "A" };
  Imf::FrameBuffer frame;
  const size_t xStride = sizeof(float) * c;
  const size_t yStride = xStride * (data.max.x - data.min.x + 1);
  char* base = reinterpret_cast<char*>(pixels.data()) -
    static_cast<ptrdiff_t>(data.min.x) * static_cast<ptrdiff_t>(xStride) -
    static_cast<ptrdiff_t>(data.min.y) * static_cast<ptrdiff_t>(yStride);
  for (int k = 0; k < c; ++k)
  {
    frame.insert(names[k],
      Imf::Slice(Imf::FLOAT, base + k * sizeof(float), xStride, yStride, 1, 1, k == 3 ? 1.0 : 0.0));
  }
  file.setFrameBuffer(frame);
  file.readPixels(data.min.y, data.max.y);
}

// Copies the data window's pixels (top row first) where they overlap the display window into
// `radiance` (bottom row first, as VTK orders images). Lossy compression (DWAA, DWAB) leaves
// values slightly below 0, which become 0 silently; NaN, infinite or clearly negative values
// (below -1% of the mean) are counted: the count is returned.
vtkIdType PlaceDisplayWindow(const std::vector<float>& pixels, const Imath::Box2i& data,
  const Imath::Box2i& display, int c, vtkFloatArray* radiance)
{
  const int dataWidth = data.max.x - data.min.x + 1;
  const int width = display.max.x - display.min.x + 1;
  double sum = 0.0;
  vtkIdType finite = 0;
  for (float v : pixels)
  {
    if (std::isfinite(v))
    {
      sum += v;
      ++finite;
    }
  }
  const float noise = -0.01f * static_cast<float>(finite > 0 ? std::abs(sum) / finite : 0.0);
  vtkIdType repaired = 0;
  for (int y = std::max(data.min.y, display.min.y); y <= std::min(data.max.y, display.max.y); ++y)
  {
    const int row = display.max.y - y;
    for (int x = std::max(data.min.x, display.min.x); x <= std::min(data.max.x, display.max.x); ++x)
    {
      const float* p =
        &pixels[(static_cast<size_t>(y - data.min.y) * dataWidth + (x - data.min.x)) * c];
      float* q =
        radiance->GetPointer((static_cast<vtkIdType>(row) * width + (x - display.min.x)) * c);
      for (int k = 0; k < c; ++k)
      {
        const float v = p[k];
        if (v >= 0.0f && !std::isinf(v))
        {
          q[k] = v;
          continue;
        }
        q[k] = std::isinf(v) && v > 0.0f ? 65504.0f : 0.0f;
        repaired += !(v >= noise) || std::isinf(v) ? 1 : 0;
      }
    }
  }
  return repaired;
}
}

//------------------------------------------------------------------------------
int vtkOpenEXRReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector);
  if (this->Components == 0)
  {
    return 0;
  }
  // 1. The data window's pixels, top row first as in the file (the header was checked in
  // RequestInformation).
  Source source;
  std::unique_ptr<MemoryStream> stream;
  std::string error;
  std::unique_ptr<Imf::InputFile> file = Open(this->FileName, this->MemoryBuffer,
    this->MemoryBufferLength, this->MaximumSide, source, stream, error);
  if (!file)
  {
    vtkErrorMacro(<< error << ".");
    return 0;
  }
  const Imf::Header& header = file->header();
  const Imath::Box2i data = header.dataWindow();
  const int c = this->Components;
  std::vector<float> pixels(
    static_cast<size_t>(data.max.x - data.min.x + 1) * (data.max.y - data.min.y + 1) * c, 0.0f);
  try
  {
    const Layout layout = LayoutOf(header.channels());
    if (layout == Layout::LuminanceChroma)
    {
      ReadLuminanceChroma(source, stream->fileName(), data, c, pixels);
    }
    else
    {
      ReadChannels(*file, layout, data, c, pixels);
    }
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(
      "The EXR's pixels cannot be read: " << vtkApertureText::Line(e.what(), 200) << ".");
    return 0;
  }
  // 2. The display window's radiance, its unusable values repaired and counted.
  output->SetExtent(0, this->Width - 1, 0, this->Height - 1, 0, 0);
  output->SetSpacing(1.0, 1.0, 1.0);
  output->SetOrigin(0.0, 0.0, 0.0);
  vtkNew<vtkFloatArray> radiance;
  radiance->SetName("Radiance");
  radiance->SetNumberOfComponents(c);
  radiance->SetNumberOfTuples(static_cast<vtkIdType>(this->Width) * this->Height);
  radiance->Fill(0.0);
  const vtkIdType repaired = PlaceDisplayWindow(pixels, data, header.displayWindow(), c, radiance);
  output->GetPointData()->SetScalars(radiance);
  if (repaired > 0)
  {
    vtkWarningMacro(<< repaired
                    << " pixel value(s) were NaN, infinite or negative; NaN and negative "
                       "values became 0, infinite ones 65504.");
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkOpenEXRReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "MemoryBuffer: " << this->MemoryBuffer << "\n";
  os << indent << "MemoryBufferLength: " << this->MemoryBufferLength << "\n";
  os << indent << "MaximumSide: " << this->MaximumSide << "\n";
  os << indent << "MaximumBytes: " << this->MaximumBytes << "\n";
}
