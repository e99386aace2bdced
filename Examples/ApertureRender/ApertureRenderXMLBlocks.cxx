/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderXMLBlocks.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "ApertureRenderXMLBlocks.h"

#include "vtkApertureText.h"
#include "vtkBase64Utilities.h"
#include "vtkXMLDataElement.h"
#include "vtkXMLDataParser.h"
#include "vtkXMLReader.h"
#include "vtksys/SystemTools.hxx"

#include <cctype>
#include <cstdint>
#include <fstream>
#include <vector>

namespace ApertureRender
{
namespace
{
// VTK's compressors pack at most about 1032 bytes into one (zlib); a block announcing more than
// this many bytes per compressed byte is damaged.
const double MaximumRatio = 4096.0;

// Where one array's data begin in the file, and how they are stored there.
struct Stored
{
  std::int64_t Position = 0;
  bool Base64 = false;
};

// How the file stores its compressed arrays: header words of 4 or 8 bytes, in either byte order.
struct Layout
{
  std::string Name;
  std::int64_t FileSize = 0;
  int WordSize = 4;
  bool BigEndian = false;
};

// `count` bytes of `name` from `position`, decoded from base64 if they are stored so (where the
// header is a base64 block of its own), or empty where the file ends first.
std::vector<unsigned char> ReadBytes(
  const Layout& layout, const Stored& stored, std::uint64_t count)
{
  const std::uint64_t stored64 = stored.Base64 ? (count + 2) / 3 * 4 : count;
  if (stored.Position < 0 ||
    stored64 > static_cast<std::uint64_t>(layout.FileSize - stored.Position))
  {
    return {};
  }
  std::ifstream file(layout.Name, std::ios::binary);
  file.seekg(stored.Position);
  std::vector<unsigned char> raw(static_cast<size_t>(stored64));
  if (!file.read(reinterpret_cast<char*>(raw.data()), static_cast<std::streamsize>(raw.size())))
  {
    return {};
  }
  if (!stored.Base64)
  {
    return raw;
  }
  std::vector<unsigned char> decoded(static_cast<size_t>(count) + 3);
  const size_t n =
    vtkBase64Utilities::DecodeSafely(raw.data(), raw.size(), decoded.data(), decoded.size());
  decoded.resize(n < count ? 0 : static_cast<size_t>(count));
  return decoded;
}

std::uint64_t Word(const Layout& layout, const std::vector<unsigned char>& bytes, size_t i)
{
  std::uint64_t value = 0;
  for (int b = 0; b < layout.WordSize; ++b)
  {
    const int k = layout.BigEndian ? b : layout.WordSize - 1 - b;
    value = (value << 8) | bytes[i * layout.WordSize + k];
  }
  return value;
}

// Why the compression header at `stored` does not fit the file, or empty when it does.
std::string HeaderProblem(const Layout& layout, const Stored& stored)
{
  const std::vector<unsigned char> head = ReadBytes(layout, stored, 3 * layout.WordSize);
  if (head.empty())
  {
    return "its compression header lies past the end of the file";
  }
  const std::uint64_t blocks = Word(layout, head, 0);
  const std::uint64_t blockSize = Word(layout, head, 1);
  const std::uint64_t lastSize = Word(layout, head, 2);
  // Every block has a size word in the header, and at least a byte of data after it.
  const double left =
    static_cast<double>(layout.FileSize - stored.Position) * (stored.Base64 ? 0.75 : 1.0);
  if (static_cast<double>(blocks) * (layout.WordSize + 1) > left)
  {
    return "it announces " + std::to_string(blocks) +
      " compressed blocks, more than the file holds";
  }
  // No blocks but a last one makes vtkXMLDataParser's total wrap around below 0 and read a
  // block it has no size for.
  if ((blocks > 0 && (blockSize == 0 || lastSize > blockSize)) || (blocks == 0 && lastSize > 0))
  {
    return "its block sizes are inconsistent";
  }
  const std::vector<unsigned char> sizes =
    ReadBytes(layout, stored, (3 + blocks) * layout.WordSize);
  double compressed = 0.0;
  for (size_t i = 0; i < blocks && !sizes.empty(); ++i)
  {
    compressed += static_cast<double>(Word(layout, sizes, 3 + i));
  }
  const double total = static_cast<double>(blocks) * static_cast<double>(blockSize) -
    (lastSize > 0 ? static_cast<double>(blockSize - lastSize) : 0.0);
  if (sizes.empty() || compressed > left || total > MaximumRatio * (compressed + 1.0))
  {
    return "its compressed blocks do not fit the file";
  }
  return std::string();
}

// Where the data of a binary or appended DataArray begin; false for ASCII ones. As VTK decides:
// an offset makes an array appended, whatever its format says.
bool FindStored(vtkXMLDataElement* array, vtkXMLDataElement* appended, vtkXMLDataParser* parser,
  const Layout& layout, Stored& stored)
{
  const std::string format = array->GetAttribute("format") ? array->GetAttribute("format") : "";
  if (array->GetAttribute("offset"))
  {
    const char* encoding = appended ? appended->GetAttribute("encoding") : nullptr;
    vtkTypeInt64 offset = -1;
    stored.Base64 = !encoding || std::string(encoding) != "raw";
    stored.Position = array->GetScalarAttribute("offset", offset) && offset >= 0 && appended
      ? parser->GetAppendedDataPosition() + offset
      : -1;
    return true;
  }
  if (format != "binary")
  {
    return false;
  }
  // As vtkXMLDataParser finds it: past the start tag's '>' and the blanks after it.
  std::ifstream file(layout.Name, std::ios::binary);
  file.seekg(array->GetXMLByteIndex());
  char c = 0;
  while (file.get(c) && c != '>')
  {
  }
  while (file.get(c) && std::isspace(static_cast<unsigned char>(c)))
  {
  }
  stored.Base64 = true;
  stored.Position = file ? static_cast<std::int64_t>(file.tellg()) - 1 : -1;
  return true;
}

// The first problem among the DataArray elements at or below `element`, or empty.
std::string FindProblem(vtkXMLDataElement* element, vtkXMLDataElement* appended,
  vtkXMLDataParser* parser, const Layout& layout)
{
  Stored stored;
  const std::string kind = element->GetName() ? element->GetName() : "";
  if (kind == "DataArray" && FindStored(element, appended, parser, layout, stored))
  {
    const std::string problem = HeaderProblem(layout, stored);
    if (!problem.empty())
    {
      const char* name = element->GetAttribute("Name");
      return "array " + vtkApertureText::Quote(name ? name : "") + ": " + problem;
    }
  }
  for (int i = 0; i < element->GetNumberOfNestedElements(); ++i)
  {
    const std::string problem = FindProblem(element->GetNestedElement(i), appended, parser, layout);
    if (!problem.empty())
    {
      return problem;
    }
  }
  return std::string();
}
}

//------------------------------------------------------------------------------
bool CheckCompressedBlocks(vtkXMLReader* reader, const std::string& name, std::string& error)
{
  reader->UpdateInformation();
  vtkXMLDataParser* parser = reader->GetXMLParser();
  vtkXMLDataElement* root = parser ? parser->GetRootElement() : nullptr;
  if (!root || !root->GetAttribute("compressor"))
  {
    return true;
  }
  Layout layout;
  layout.Name = name;
  layout.FileSize = static_cast<std::int64_t>(vtksys::SystemTools::FileLength(name));
  const char* header = root->GetAttribute("header_type");
  const char* order = root->GetAttribute("byte_order");
  layout.WordSize = header && std::string(header) == "UInt64" ? 8 : 4;
  layout.BigEndian = order && std::string(order) == "BigEndian";
  const std::string problem =
    FindProblem(root, root->FindNestedElementWithName("AppendedData"), parser, layout);
  if (!problem.empty())
  {
    error = vtkApertureText::QuoteName(name) + " is damaged (" + problem + ")";
    return false;
  }
  return true;
}
}
