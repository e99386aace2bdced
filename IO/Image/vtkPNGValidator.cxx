/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkPNGValidator.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkPNGValidator.h"

#include "vtkApertureText.h"
#include "vtkObjectFactory.h"
#include "vtk_zlib.h"
#include "vtksys/SystemTools.hxx"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkPNGValidator);

namespace
{
// libpng's default limits on the image size.
constexpr uint32_t MaximumSide = 1000000;
// Larger decoded images are refused rather than allocated.
constexpr uint64_t MaximumBytes = uint64_t(1) << 31;

uint32_t BigEndian32(const unsigned char* p)
{
  return (uint32_t(p[0]) << 24) | (uint32_t(p[1]) << 16) | (uint32_t(p[2]) << 8) | uint32_t(p[3]);
}

struct Header
{
  uint32_t Width = 0, Height = 0;
  int BitDepth = 0, ColorType = 0, Interlace = 0;

  int Channels() const
  {
    switch (this->ColorType)
    {
      case 0: // grey
      case 3: // palette
        return 1;
      case 2: // RGB
        return 3;
      case 4: // grey and alpha
        return 2;
      case 6: // RGBA
        return 4;
      default:
        return 0;
    }
  }

  bool ValidDepth() const
  {
    const int d = this->BitDepth;
    switch (this->ColorType)
    {
      case 0:
        return d == 1 || d == 2 || d == 4 || d == 8 || d == 16;
      case 3:
        return d == 1 || d == 2 || d == 4 || d == 8;
      case 2:
      case 4:
      case 6:
        return d == 8 || d == 16;
      default:
        return false;
    }
  }

  uint64_t RowBytes(uint64_t width) const
  {
    return (width * this->Channels() * this->BitDepth + 7) / 8;
  }

  // Width and height of each interlace pass (Adam7), or of the whole image.
  std::vector<std::pair<uint64_t, uint64_t>> Passes() const
  {
    if (this->Interlace == 0)
    {
      return { { this->Width, this->Height } };
    }
    static const int adam7[7][4] = { { 0, 0, 8, 8 }, { 4, 0, 8, 8 }, { 0, 4, 4, 8 }, { 2, 0, 4, 4 },
      { 0, 2, 2, 4 }, { 1, 0, 2, 2 }, { 0, 1, 1, 2 } };
    std::vector<std::pair<uint64_t, uint64_t>> passes;
    for (const auto& p : adam7)
    {
      const uint64_t w = this->Width > uint32_t(p[0]) ? (this->Width - p[0] + p[2] - 1) / p[2] : 0;
      const uint64_t h =
        this->Height > uint32_t(p[1]) ? (this->Height - p[1] + p[3] - 1) / p[3] : 0;
      if (w > 0 && h > 0)
      {
        passes.emplace_back(w, h);
      }
    }
    return passes;
  }
};

std::string ParseHeader(const unsigned char* p, uint32_t length, Header& h)
{
  if (length != 13)
  {
    return "its IHDR chunk has the wrong length";
  }
  h.Width = BigEndian32(p);
  h.Height = BigEndian32(p + 4);
  h.BitDepth = p[8];
  h.ColorType = p[9];
  h.Interlace = p[12];
  std::ostringstream problem;
  if (h.Width == 0 || h.Height == 0 || h.Width > MaximumSide || h.Height > MaximumSide)
  {
    problem << "its size, " << h.Width << " x " << h.Height << ", is invalid";
  }
  else if (h.Channels() == 0 || !h.ValidDepth())
  {
    problem << "colour type " << h.ColorType << " with bit depth " << h.BitDepth
            << " is not a PNG format";
  }
  else if (p[10] != 0 || p[11] != 0 || h.Interlace > 1)
  {
    problem << "its header names an unknown compression, filter or interlace method";
  }
  return problem.str();
}

// Inflates the image data into `out`, which must come to exactly `expected` bytes.
std::string Inflate(
  const std::vector<unsigned char>& compressed, uint64_t expected, std::vector<unsigned char>& out)
{
  out.assign(static_cast<size_t>(expected) + 1, 0);
  z_stream stream;
  std::memset(&stream, 0, sizeof(stream));
  if (inflateInit(&stream) != Z_OK)
  {
    return "zlib could not be initialised";
  }
  stream.next_in = const_cast<Bytef*>(compressed.data());
  stream.avail_in = static_cast<uInt>(compressed.size());
  stream.next_out = out.data();
  stream.avail_out = static_cast<uInt>(out.size());
  const int result = inflate(&stream, Z_FINISH);
  const uint64_t produced = stream.total_out;
  const std::string message = stream.msg ? stream.msg : "";
  inflateEnd(&stream);
  std::ostringstream problem;
  if (result == Z_DATA_ERROR || result == Z_NEED_DICT || result == Z_MEM_ERROR)
  {
    problem << "its compressed image data are damaged" << (message.empty() ? "" : " (") << message
            << (message.empty() ? "" : ")");
  }
  else if (produced > expected)
  {
    problem << "its image data are longer than its header allows";
  }
  else if (result != Z_STREAM_END || produced < expected)
  {
    problem << "its image data are incomplete (" << produced << " of " << expected << " bytes)";
  }
  return problem.str();
}

// What the chunks read so far have said.
struct ChunkState
{
  Header Image;
  bool HaveHeader = false;
  bool HavePalette = false;
  bool InImageData = false;
  bool AfterImageData = false;
  bool Ended = false;
  std::vector<unsigned char> Compressed;
};

// The framing of the chunk at `pos`: a whole chunk, a valid name and, for a critical chunk, its
// CRC. Gives its type, body and length; the problem, or empty.
std::string ReadChunkFrame(const unsigned char* bytes, size_t size, size_t pos, std::string& type,
  const unsigned char*& body, uint32_t& length)
{
  const size_t left = size - pos;
  if (left == 0)
  {
    return "is truncated (it has no IEND chunk)";
  }
  if (left < 12)
  {
    return "is truncated (a chunk header is cut off)";
  }
  length = BigEndian32(bytes + pos);
  type.assign(reinterpret_cast<const char*>(bytes + pos + 4), 4);
  for (char c : type)
  {
    if (!((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z')))
    {
      return "is damaged (a chunk has an invalid name)";
    }
  }
  if (length > 0x7fffffffu || length > left - 12)
  {
    std::ostringstream problem;
    problem << "is truncated (chunk " << type << " needs " << length << " bytes, " << left - 12
            << " are left)";
    return problem.str();
  }
  body = bytes + pos + 8;
  const bool critical = type[0] >= 'A' && type[0] <= 'Z';
  const uLong crc = crc32(0L, bytes + pos + 4, static_cast<uInt>(length + 4));
  if (critical && crc != BigEndian32(body + length))
  {
    return "is damaged (chunk " + type + " fails its CRC check)";
  }
  return std::string();
}

// What a chunk means for the image: IHDR first and once, PLTE valid and before the data, IDAT
// chunks consecutive (their data gathered), IEND last, no unknown critical chunk. The problem, or
// empty.
std::string TakeChunk(
  const std::string& type, const unsigned char* body, uint32_t length, ChunkState& state)
{
  if (!state.HaveHeader && type != "IHDR")
  {
    return "is damaged (it does not start with an IHDR chunk)";
  }
  if (state.InImageData && type != "IDAT")
  {
    state.InImageData = false;
    state.AfterImageData = true;
  }
  if (type == "IHDR")
  {
    const std::string problem = state.HaveHeader ? std::string("it has two IHDR chunks")
                                                 : ParseHeader(body, length, state.Image);
    state.HaveHeader = true;
    return problem.empty() ? problem : "is damaged (" + problem + ")";
  }
  if (type == "PLTE")
  {
    const int color = state.Image.ColorType;
    const bool bad = color == 0 || color == 4 || length == 0 || length % 3 != 0 || length > 768 ||
      state.HavePalette || !state.Compressed.empty();
    state.HavePalette = true;
    return bad ? "is damaged (its PLTE chunk is invalid)" : std::string();
  }
  if (type == "IDAT")
  {
    if (state.AfterImageData)
    {
      return "is damaged (its IDAT chunks are not consecutive)";
    }
    if (state.Image.ColorType == 3 && !state.HavePalette)
    {
      return "is damaged (a palette image without a PLTE chunk)";
    }
    state.InImageData = true;
    state.Compressed.insert(state.Compressed.end(), body, body + length);
    return std::string();
  }
  state.Ended = type == "IEND";
  const bool critical = type[0] >= 'A' && type[0] <= 'Z';
  return critical && !state.Ended ? "uses an unknown critical chunk, " + type : std::string();
}

// The image data inflated to exactly the rows the header describes (all passes of an interlaced
// image), each starting with a filter type from 0 to 4. The problem, or empty.
std::string CheckRows(const Header& header, const std::vector<unsigned char>& compressed)
{
  if (compressed.empty())
  {
    return "is damaged (it has no image data)";
  }
  uint64_t expected = 0;
  const auto passes = header.Passes();
  for (const auto& pass : passes)
  {
    expected += pass.second * (1 + header.RowBytes(pass.first));
  }
  if (expected > MaximumBytes)
  {
    return "is too large to decode here (over 2 GiB of image data)";
  }
  std::vector<unsigned char> rows;
  const std::string inflateProblem = Inflate(compressed, expected, rows);
  if (!inflateProblem.empty())
  {
    return "is damaged (" + inflateProblem + ")";
  }
  uint64_t offset = 0;
  for (const auto& pass : passes)
  {
    const uint64_t stride = 1 + header.RowBytes(pass.first);
    for (uint64_t r = 0; r < pass.second; ++r, offset += stride)
    {
      if (rows[static_cast<size_t>(offset)] > 4)
      {
        return "is damaged (an image row has an invalid filter type)";
      }
    }
  }
  return std::string();
}
}

//------------------------------------------------------------------------------
std::string vtkPNGValidator::CheckFile(const char* fileName)
{
  const std::string name = fileName ? fileName : "";
  if (name.empty() || !vtksys::SystemTools::FileExists(name, true))
  {
    return vtkApertureText::QuoteName(name) + " does not exist";
  }
  std::ifstream in(name, std::ios::binary);
  if (!in)
  {
    return vtkApertureText::QuoteName(name) + " cannot be read";
  }
  const std::vector<char> bytes(
    (std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string problem = vtkPNGValidator::CheckBuffer(bytes.data(), bytes.size());
  return problem.empty() ? problem : vtkApertureText::QuoteName(name) + " " + problem;
}

//------------------------------------------------------------------------------
std::string vtkPNGValidator::CheckBuffer(const void* data, size_t size)
{
  static const unsigned char signature[8] = { 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n' };
  const auto* bytes = static_cast<const unsigned char*>(data);
  if (!bytes || size < 8 || std::memcmp(bytes, signature, 8) != 0)
  {
    return "is not a PNG file";
  }
  // 1. The chunks up to IEND, each framed and in its place; the image data gathered.
  ChunkState state;
  for (size_t pos = 8; !state.Ended;)
  {
    std::string type;
    const unsigned char* body = nullptr;
    uint32_t length = 0;
    std::string problem = ReadChunkFrame(bytes, size, pos, type, body, length);
    problem = problem.empty() ? TakeChunk(type, body, length, state) : problem;
    if (!problem.empty())
    {
      return problem;
    }
    pos += 12 + size_t(length);
  }
  // 2. The image data inflated: every row as long as the header says, with a valid filter.
  return CheckRows(state.Image, state.Compressed);
}

//------------------------------------------------------------------------------
void vtkPNGValidator::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
