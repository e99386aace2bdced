/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderPLY.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "ApertureRenderPLY.h"

#include "ApertureRenderText.h"

#include "vtkApertureText.h"
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

// The point ids of a face or strip: the vertex_indices list of a face or tristrips element (a
// vertex_index list is renamed so as it is read). Read with `visit(element, values)`.
bool IsIndexList(const Element& element, const Property& property)
{
  return property.CountSize > 0 && !property.Real &&
    (element.Name == "face" || element.Name == "tristrips") && property.Name == "vertex_indices";
}

// Whether vtkPLYReader reads an element's property as a list (it frees what it takes for one);
// -1 for properties it does not read.
int ReadsAsList(const std::string& element, const std::string& property)
{
  static const std::map<std::string, int> known = { { "face vertex_indices", 1 },
    { "face texcoord", 1 }, { "face intensity", 0 }, { "face red", 0 }, { "face green", 0 },
    { "face blue", 0 }, { "face alpha", 0 }, { "vertex x", 0 }, { "vertex y", 0 },
    { "vertex z", 0 }, { "vertex u", 0 }, { "vertex v", 0 }, { "vertex texture_u", 0 },
    { "vertex texture_v", 0 }, { "vertex nx", 0 }, { "vertex ny", 0 }, { "vertex nz", 0 },
    { "vertex red", 0 }, { "vertex green", 0 }, { "vertex blue", 0 }, { "vertex alpha", 0 },
    { "vertex diffuse_red", 0 }, { "vertex diffuse_green", 0 }, { "vertex diffuse_blue", 0 } };
  const auto found = known.find(element + " " + property);
  return found == known.end() ? -1 : found->second;
}

// vtkPLYReader reads, without checking, one vertex element with x, y and z, then at most one face
// element with vertex_indices, each known property a list or a scalar as it expects (see
// ReadsAsList). Says what breaks that, or empty.
std::string CheckLayout(const std::vector<Element>& elements)
{
  std::map<std::string, int> seen;
  for (const Element& element : elements)
  {
    const std::string& name = element.Name;
    if (++seen[name] > 1 && (name == "vertex" || name == "face"))
    {
      return "has more than one " + name + " element";
    }
    if (name == "face" && !seen.count("vertex"))
    {
      return "has its faces before its vertices";
    }
    // The reader skips nothing: it would read an element it ignores as the vertices or faces.
    const bool read = name == "vertex" || name == "face";
    if (read && seen.size() > (seen.count("vertex") + seen.count("face")))
    {
      return "has a " + name + " element after one it does not read";
    }
    std::map<std::string, bool> isList; // vtkPLY finds the first property of a name
    for (const Property& p : element.Properties)
    {
      isList.emplace(p.Name, p.CountSize > 0);
    }
    for (const auto& property : isList)
    {
      const int expected = ReadsAsList(name, property.first);
      if (expected >= 0 && expected != static_cast<int>(property.second))
      {
        return "has a " + name + " property " + property.first + " that is " +
          (property.second ? "a list" : "not a list");
      }
    }
    if ((name == "vertex" && !(isList.count("x") && isList.count("y") && isList.count("z"))) ||
      (name == "face" && !isList.count("vertex_indices")))
    {
      return "has " + name + " elements without " +
        (name == "face" ? "vertex_indices" : "x, y and z");
    }
  }
  return seen.count("vertex") ? std::string() : "has no vertex element";
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

// Printable text in lines vtkPLY's 4096-byte buffer holds (with room for its own edits). vtkPLY
// ends a line's words at a NUL byte and then reads past the words it found.
bool IsLineText(const std::string& text)
{
  size_t line = 0;
  for (const char c : text)
  {
    line = c == '\n' ? 0 : line + 1;
    if (line > 4000)
    {
      return false;
    }
  }
  return IsPrintableText(text);
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
          problem = "is truncated (in its " + vtkApertureText::Quote(element.Name) + " elements)";
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
          problem = "is truncated or damaged (a list in its " +
            vtkApertureText::Quote(element.Name) + " elements runs past the end)";
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
      // vtkPLY reads no line at the end of the file without its newline.
      if (!std::getline(body, line) || body.eof())
      {
        problem = "is truncated (it has fewer " + vtkApertureText::Quote(element.Name) +
          " lines than its header says)";
        return false;
      }
      if ((element.Name == "vertex" || element.Name == "face") && !IsLineText(line))
      {
        problem = "is damaged (a " + vtkApertureText::Quote(element.Name) +
          " line is not text, or too long)";
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
          problem =
            "is damaged (a " + vtkApertureText::Quote(element.Name) + " line has too few values)";
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

// Adds an "element" or "property" line's words to `elements`; false with a sentence.
bool AddElementOrProperty(const std::string& keyword, std::istringstream& words,
  std::vector<Element>& elements, std::string& problem)
{
  if (keyword == "element")
  {
    Element element;
    double count = -1.0;
    words >> element.Name >> count;
    if (!elements.empty() && elements.back().Properties.empty())
    {
      problem = "is damaged (element " + vtkApertureText::Quote(elements.back().Name) +
        " has no properties)";
      return false;
    }
    if (!(count >= 0.0 && count < 4e9))
    {
      problem =
        "is damaged (element " + vtkApertureText::Quote(element.Name) + " has an invalid count)";
      return false;
    }
    element.Count = static_cast<uint64_t>(count);
    elements.push_back(element);
    return true;
  }
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
  if (elements.empty() || !known || property.Name.empty())
  {
    problem = "is damaged (a property has an unknown type or no element)";
    return false;
  }
  elements.back().Properties.push_back(property);
  return true;
}

// A "format" line's type. vtkPLY gives up (leaking the elements read so far) on a line that is
// not "format" and two words, the first a known type; false with a sentence for such a line.
bool ReadFormat(std::istringstream& words, std::string& format, std::string& problem)
{
  std::string version, extra;
  words >> format >> version;
  const bool known =
    format == "ascii" || format == "binary_little_endian" || format == "binary_big_endian";
  if (!known || version.empty() || (words >> extra))
  {
    problem = "is damaged (its PLY format line is not 'format ascii|binary_little_endian|"
              "binary_big_endian <version>')";
    return false;
  }
  return true;
}

// The header's elements and format, read line by line as vtkPLY reads it (its header ends at
// the first line without words); false with a sentence when it is not a good PLY header.
bool ReadHeader(const std::string& bytes, std::vector<Element>& elements, std::string& format,
  size_t& bodyStart, std::string& problem)
{
  size_t at = 0;
  std::string keyword;
  while (keyword != "end_header")
  {
    const size_t end = bytes.find('\n', at);
    std::string line = bytes.substr(at, end == std::string::npos ? end : end - at);
    // vtkPLY writes "vertex_indices" over a line from its first "vertex_index" on.
    const size_t renamed = line.find("vertex_index");
    line = renamed == std::string::npos ? line : line.substr(0, renamed) + "vertex_indices";
    std::istringstream words(line);
    keyword.clear();
    words >> keyword;
    problem = (at == 0 && keyword != "ply") ? "is not a PLY file (it does not start with 'ply')"
      : !IsLineText(line)
      ? "is damaged (its header has bytes that are not text, or too long a line)"
      : end == std::string::npos ? "is truncated or not a PLY file (no end_header line)"
      : keyword.empty()          ? "is damaged (a blank line in its header, before end_header)"
                                 : "";
    if (!problem.empty() ||
      ((keyword == "element" || keyword == "property") &&
        !AddElementOrProperty(keyword, words, elements, problem)))
    {
      return false;
    }
    if (keyword == "format" && !ReadFormat(words, format, problem))
    {
      return false;
    }
    at = end + 1;
  }
  const std::string layout = elements.empty() || elements.back().Properties.empty()
    ? "has an element without properties"
    : CheckLayout(elements);
  if (!layout.empty())
  {
    problem = "is damaged (it " + layout + ", which VTK's PLY reader cannot read)";
    return false;
  }
  bodyStart = at;
  return true;
}
}

bool CheckPLY(const std::string& name, vtkCellArray* strips, std::string& error)
{
  std::ifstream in(name, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string prefix = vtkApertureText::QuoteName(name) + " ";
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
    if (!isStrip && ids.size() > 255)
    {
      problem = "has face " + std::to_string(face) + " with " + std::to_string(ids.size()) +
        " vertices, more than VTK's PLY reader reads (255)";
      return false;
    }
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
    problem = "has an unknown format, " + vtkApertureText::Quote(format);
  }
  if (!good)
  {
    error = prefix + problem;
  }
  return good;
}
}
