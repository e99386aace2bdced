/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderPLY.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "ApertureRenderPLY.h"

#include "vtkCellArray.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>
#include <vector>

namespace ApertureRender
{
namespace
{
struct Property
{
  std::string Name;
  int Size = 0;      // bytes of a scalar, or of each list item
  int CountSize = 0; // bytes of a list's count; 0 for scalars
  bool Signed = false;
  bool Real = false;
};

struct Element
{
  std::string Name;
  uint64_t Count = 0;
  std::vector<Property> Properties;
};

// The point ids of a face or strip: the vertex_indices (or vertex_index) list of a face or
// tristrips element. Reads it with `visit(element, values)`.
bool IsIndexList(const Element& element, const Property& property)
{
  return property.CountSize > 0 && !property.Real &&
    (element.Name == "face" || element.Name == "tristrips") &&
    (property.Name == "vertex_indices" || property.Name == "vertex_index");
}

using Visitor = std::function<bool(const Element&, const std::vector<int64_t>&)>;

bool SetType(const std::string& type, Property& property)
{
  static const std::map<std::string, std::pair<int, char>> types = { { "char", { 1, 's' } },
    { "int8", { 1, 's' } }, { "uchar", { 1, 'u' } }, { "uint8", { 1, 'u' } },
    { "short", { 2, 's' } }, { "int16", { 2, 's' } }, { "ushort", { 2, 'u' } },
    { "uint16", { 2, 'u' } }, { "int", { 4, 's' } }, { "int32", { 4, 's' } },
    { "uint", { 4, 'u' } }, { "uint32", { 4, 'u' } }, { "float", { 4, 'f' } },
    { "float32", { 4, 'f' } }, { "double", { 8, 'f' } }, { "float64", { 8, 'f' } } };
  const auto found = types.find(type);
  if (found == types.end())
  {
    return false;
  }
  property.Size = found->second.first;
  property.Signed = found->second.second == 's';
  property.Real = found->second.second == 'f';
  return true;
}

// An integer of `size` bytes at `p`, in the file's byte order.
int64_t ReadInteger(const unsigned char* p, int size, bool isSigned, bool bigEndian)
{
  uint64_t value = 0;
  for (int i = 0; i < size; ++i)
  {
    value |= uint64_t(p[bigEndian ? i : size - 1 - i]) << (8 * (size - 1 - i));
  }
  if (isSigned && size < 8 && (value >> (8 * size - 1)) & 1u)
  {
    value |= ~uint64_t(0) << (8 * size); // sign extension
  }
  return static_cast<int64_t>(value);
}

bool WalkBinary(const std::string& bytes, size_t offset, const std::vector<Element>& elements,
  bool bigEndian, const Visitor& visit, std::string& problem)
{
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  std::vector<int64_t> values;
  for (const Element& element : elements)
  {
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
        if (p.CountSize == 0)
        {
          offset += p.Size;
          continue;
        }
        const uint64_t count =
          static_cast<uint64_t>(ReadInteger(data + offset, p.CountSize, false, bigEndian));
        offset += p.CountSize;
        if (count > (bytes.size() - offset) / p.Size)
        {
          problem = "is truncated or damaged (a list in its " + element.Name +
            " elements runs past the end)";
          return false;
        }
        if (IsIndexList(element, p))
        {
          values.resize(count);
          for (uint64_t k = 0; k < count; ++k)
          {
            values[k] = ReadInteger(data + offset + k * p.Size, p.Size, p.Signed, bigEndian);
          }
          if (!visit(element, values))
          {
            return false;
          }
        }
        offset += static_cast<size_t>(count * p.Size);
      }
    }
  }
  return true;
}

bool WalkASCII(const std::string& bytes, size_t offset, const std::vector<Element>& elements,
  const Visitor& visit, std::string& problem)
{
  // vtkPLYReader reads one element per line.
  std::istringstream body(bytes.substr(offset));
  std::string line;
  std::vector<int64_t> ids;
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
      const std::vector<std::string> values(
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
        if (at > values.size() || values.size() - at < need)
        {
          problem = "is damaged (a " + element.Name + " line has too few values)";
          return false;
        }
        if (IsIndexList(element, p))
        {
          ids.clear();
          for (size_t k = at + 1; k < at + need; ++k)
          {
            char* end = nullptr;
            const double id = std::strtod(values[k].c_str(), &end);
            ids.push_back(*end == '\0' && std::abs(id) < 9e18
                ? static_cast<int64_t>(id)
                : std::numeric_limits<int64_t>::min());
          }
          if (!visit(element, ids))
          {
            return false;
          }
        }
        at += need;
      }
    }
  }
  return true;
}

// The header's elements and format; false with a sentence when it is not a PLY header.
bool ReadHeader(const std::string& bytes, std::vector<Element>& elements, std::string& format,
  size_t& bodyStart, std::string& problem)
{
  const size_t end = bytes.find("end_header");
  if (bytes.compare(0, 3, "ply") != 0 || end == std::string::npos)
  {
    problem = "is not a PLY file (no ply ... end_header header)";
    return false;
  }
  bodyStart = bytes.find('\n', end);
  std::istringstream header(bytes.substr(0, end));
  std::string line;
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
        problem = "is damaged (element " + element.Name + " has an invalid count)";
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
      bool known = false;
      if (type == "list")
      {
        std::string countType, itemType;
        words >> countType >> itemType;
        Property count;
        known = SetType(countType, count) && !count.Real && SetType(itemType, property);
        property.CountSize = count.Size;
      }
      else
      {
        known = SetType(type, property);
      }
      words >> property.Name;
      if (elements.empty() || !known)
      {
        problem = "is damaged (a property has an unknown type or no element)";
        return false;
      }
      elements.back().Properties.push_back(property);
    }
  }
  if (bodyStart == std::string::npos)
  {
    problem = "is truncated (nothing after its header)";
    return false;
  }
  ++bodyStart;
  return true;
}
}

bool CheckPLY(const std::string& name, vtkCellArray* strips, std::string& error)
{
  std::ifstream in(name, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string prefix = "'" + name + "' ";
  std::vector<Element> elements;
  std::string format, problem;
  size_t bodyStart = 0;
  if (!ReadHeader(bytes, elements, format, bodyStart, problem))
  {
    error = prefix + problem;
    return false;
  }
  int64_t vertices = 0;
  for (const Element& element : elements)
  {
    vertices += element.Name == "vertex" ? static_cast<int64_t>(element.Count) : 0;
  }
  // Every face and strip index must name a vertex (-1 restarts a strip).
  std::vector<vtkIdType> strip;
  uint64_t face = 0;
  const Visitor visit = [&](const Element& element, const std::vector<int64_t>& ids)
  {
    const bool isStrip = element.Name == "tristrips";
    for (size_t k = 0; k < ids.size(); ++k)
    {
      const int64_t id = ids[k];
      if ((id < 0 || id >= vertices) && !(isStrip && id == -1))
      {
        std::ostringstream what;
        what << "is damaged (" << (isStrip ? "a triangle strip" : "face " + std::to_string(face))
             << " uses vertex " << id << ", but there are " << vertices << " vertices)";
        problem = what.str();
        return false;
      }
      if (isStrip && strips)
      {
        // A strip ends at -1 and at the end of its list.
        if (id >= 0)
        {
          strip.push_back(static_cast<vtkIdType>(id));
        }
        if (id < 0 || k + 1 == ids.size())
        {
          if (strip.size() >= 3)
          {
            strips->InsertNextCell(static_cast<vtkIdType>(strip.size()), strip.data());
          }
          strip.clear();
        }
      }
    }
    face += isStrip ? 0 : 1;
    return true;
  };
  bool good = false;
  if (format == "ascii")
  {
    good = WalkASCII(bytes, bodyStart, elements, visit, problem);
  }
  else if (format == "binary_little_endian" || format == "binary_big_endian")
  {
    good = WalkBinary(bytes, bodyStart, elements, format == "binary_big_endian", visit, problem);
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
