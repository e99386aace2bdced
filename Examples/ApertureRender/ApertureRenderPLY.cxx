/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderPLY.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "ApertureRenderPLY.h"

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <vector>

namespace ApertureRender
{
namespace
{
struct Property
{
  int Size = 0;      // bytes of a scalar, or of each list item
  int CountSize = 0; // bytes of a list's count; 0 for scalars
};

struct Element
{
  std::string Name;
  uint64_t Count = 0;
  std::vector<Property> Properties;
};

int TypeSize(const std::string& type)
{
  static const std::map<std::string, int> sizes = { { "char", 1 }, { "int8", 1 }, { "uchar", 1 },
    { "uint8", 1 }, { "short", 2 }, { "int16", 2 }, { "ushort", 2 }, { "uint16", 2 }, { "int", 4 },
    { "int32", 4 }, { "uint", 4 }, { "uint32", 4 }, { "float", 4 }, { "float32", 4 },
    { "double", 8 }, { "float64", 8 } };
  const auto found = sizes.find(type);
  return found == sizes.end() ? 0 : found->second;
}

// An unsigned count of `size` bytes at `p`, in the file's byte order.
uint64_t ReadCount(const unsigned char* p, int size, bool bigEndian)
{
  uint64_t value = 0;
  for (int i = 0; i < size; ++i)
  {
    value |= uint64_t(p[bigEndian ? i : size - 1 - i]) << (8 * (size - 1 - i));
  }
  return value;
}

bool CheckBinary(const std::string& bytes, size_t offset, const std::vector<Element>& elements,
  bool bigEndian, std::string& problem)
{
  for (const Element& element : elements)
  {
    bool lists = false;
    uint64_t fixed = 0;
    for (const Property& p : element.Properties)
    {
      lists = lists || p.CountSize > 0;
      fixed += p.Size;
    }
    if (!lists)
    {
      if (element.Count > (bytes.size() - offset) / std::max<uint64_t>(fixed, 1) && fixed > 0)
      {
        problem = "is truncated (its " + element.Name + " elements do not fit in the file)";
        return false;
      }
      offset += static_cast<size_t>(element.Count * fixed);
      continue;
    }
    for (uint64_t i = 0; i < element.Count; ++i)
    {
      for (const Property& p : element.Properties)
      {
        const size_t need = p.CountSize > 0 ? p.CountSize : p.Size;
        if (bytes.size() - offset < need)
        {
          problem = "is truncated (in its " + element.Name + " elements)";
          return false;
        }
        if (p.CountSize > 0)
        {
          const uint64_t count = ReadCount(
            reinterpret_cast<const unsigned char*>(bytes.data()) + offset, p.CountSize, bigEndian);
          offset += p.CountSize;
          if (count > (bytes.size() - offset) / p.Size)
          {
            problem = "is truncated or damaged (a list in its " + element.Name +
              " elements runs past the end)";
            return false;
          }
          offset += static_cast<size_t>(count * p.Size);
        }
        else
        {
          offset += p.Size;
        }
      }
    }
  }
  return true;
}

bool CheckASCII(const std::string& bytes, size_t offset, const std::vector<Element>& elements,
  std::string& problem)
{
  // vtkPLYReader reads one element per line.
  std::istringstream body(bytes.substr(offset));
  std::string line;
  for (const Element& element : elements)
  {
    for (uint64_t i = 0; i < element.Count; ++i)
    {
      if (!std::getline(body, line))
      {
        problem = "is truncated (it has fewer " + element.Name + " lines than its header says)";
        return false;
      }
      std::istringstream words(line);
      std::vector<std::string> values(
        (std::istream_iterator<std::string>(words)), std::istream_iterator<std::string>());
      size_t at = 0;
      for (const Property& p : element.Properties)
      {
        size_t need = 1;
        if (p.CountSize > 0 && at < values.size())
        {
          char* end = nullptr;
          const double count = std::strtod(values[at].c_str(), &end);
          need = (*end == '\0' && count >= 0.0 && count < 1e7) ? 1 + static_cast<size_t>(count)
                                                               : values.size() + 1;
        }
        if (values.size() - at < need || at > values.size())
        {
          problem = "is damaged (a " + element.Name + " line has too few values)";
          return false;
        }
        at += need;
      }
    }
  }
  return true;
}
}

bool CheckPLY(const std::string& name, std::string& error)
{
  std::ifstream in(name, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string prefix = "'" + name + "' ";
  const size_t end = bytes.find("end_header");
  if (bytes.compare(0, 3, "ply") != 0 || end == std::string::npos)
  {
    error = prefix + "is not a PLY file (no ply ... end_header header)";
    return false;
  }
  const size_t bodyStart = bytes.find('\n', end);
  std::istringstream header(bytes.substr(0, end));
  std::string line, format;
  std::vector<Element> elements;
  while (std::getline(header, line))
  {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "format")
    {
      words >> format;
    }
    else if (keyword == "element")
    {
      Element element;
      double count = -1.0;
      words >> element.Name >> count;
      if (!(count >= 0.0 && count < 4e9))
      {
        error = prefix + "is damaged (element " + element.Name + " has an invalid count)";
        return false;
      }
      element.Count = static_cast<uint64_t>(count);
      elements.push_back(element);
    }
    else if (keyword == "property")
    {
      std::string type;
      words >> type;
      Property property;
      if (type == "list")
      {
        std::string countType, itemType;
        words >> countType >> itemType;
        property.CountSize = TypeSize(countType);
        property.Size = TypeSize(itemType);
        if (property.CountSize == 0)
        {
          property.Size = 0;
        }
      }
      else
      {
        property.Size = TypeSize(type);
      }
      if (elements.empty() || property.Size == 0)
      {
        error = prefix + "is damaged (a property has an unknown type or no element)";
        return false;
      }
      elements.back().Properties.push_back(property);
    }
  }
  if (bodyStart == std::string::npos)
  {
    error = prefix + "is truncated (nothing after its header)";
    return false;
  }
  std::string problem;
  bool good = false;
  if (format == "ascii")
  {
    good = CheckASCII(bytes, bodyStart + 1, elements, problem);
  }
  else if (format == "binary_little_endian" || format == "binary_big_endian")
  {
    good = CheckBinary(bytes, bodyStart + 1, elements, format == "binary_big_endian", problem);
  }
  else
  {
    problem = "has an unknown format, '" + format + "'";
  }
  if (!good)
  {
    error = prefix + problem;
  }
  return good;
}
}
