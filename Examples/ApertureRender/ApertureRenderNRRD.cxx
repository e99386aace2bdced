/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderNRRD.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "ApertureRenderNRRD.h"

#include "ApertureRenderText.h"

#include "vtkApertureText.h"

#include <vtksys/FStream.hxx>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace ApertureRender
{
namespace
{
// What vtkNrrdReader takes as its header: the first 4 MiB up to a NUL, cut after the first
// blank line (the whole of it for a detached header).
std::string HeaderOf(const std::string& name)
{
  vtksys::ifstream file(name.c_str(), std::ios::in | std::ios::binary);
  std::string bytes(0x400000 - 1, '\0');
  file.read(&bytes[0], static_cast<std::streamsize>(bytes.size()));
  bytes.resize(static_cast<size_t>(file.gcount()));
  bytes.resize(bytes.find('\0') == std::string::npos ? bytes.size() : bytes.find('\0'));
  for (const char* blank : { "\n\n", "\n\r\n" })
  {
    const size_t end = bytes.find(blank);
    if (end != std::string::npos)
    {
      bytes.resize(end + std::string(blank).size());
    }
  }
  return bytes;
}

std::vector<std::string> Words(const std::string& text)
{
  std::istringstream stream(text);
  std::vector<std::string> words;
  for (std::string word; stream >> word;)
  {
    words.push_back(word);
  }
  return words;
}

// An integer in [low, high] written alone, as atoi would read it.
bool IntegerIn(const std::string& word, long long low, long long high, long long& value)
{
  char* end = nullptr;
  value = std::strtoll(word.c_str(), &end, 10);
  return end != word.c_str() && *end == '\0' && value >= low && value <= high;
}

// True when `words` are one finite, non-zero number for each of `dimension` axes (NaN, as NRRD
// writes it, for the components axis of a 4-D file).
bool SpacingsFit(const std::vector<std::string>& words, long long dimension)
{
  if (static_cast<long long>(words.size()) != dimension)
  {
    return false;
  }
  for (size_t i = 0; i < words.size(); ++i)
  {
    char* end = nullptr;
    const double value = std::strtod(words[i].c_str(), &end);
    const bool components = dimension == 4 && i == 0 && std::isnan(value);
    if (end == words[i].c_str() || *end != '\0' ||
      (!components && (!std::isfinite(value) || value == 0.0)))
    {
      return false;
    }
  }
  return true;
}

// Checks one "field: description" line; `dimension` and `sizes` carry what earlier lines set.
bool CheckField(const std::string& field, const std::string& description, long long& dimension,
  bool& sizes, std::string& why)
{
  const std::vector<std::string> words = Words(description);
  long long value = 0;
  if (field == "dimension" || field == "space dimension")
  {
    if (words.size() != 1 || !IntegerIn(words[0], 1, field == "dimension" ? 4 : 3, value))
    {
      why = "its " + field + " is not " + (field == "dimension" ? "1 to 4" : "1 to 3");
      return false;
    }
    dimension = value;
  }
  else if (field == "space")
  {
    dimension = 3;
  }
  else if (field == "sizes")
  {
    long long values = 1;
    if (dimension < 1 || static_cast<long long>(words.size()) != dimension)
    {
      why = "its sizes do not follow a dimension and count as many axes";
      return false;
    }
    for (const std::string& word : words)
    {
      if (!IntegerIn(word, 1, INT32_MAX, value) || (values *= value) > INT32_MAX)
      {
        why = "its sizes are not positive counts of at most 2^31 values in all";
        return false;
      }
    }
    sizes = true;
  }
  else if (field == "spacings" && !SpacingsFit(words, dimension))
  {
    // vtkNrrdReader crashes on a spacing of 0 or one it cannot parse.
    why = "its spacings are not one finite, non-zero number per axis";
    return false;
  }
  else if ((field == "space origin" || field == "data file" || field == "datafile") &&
    words.empty())
  {
    why = "its " + field + " is empty";
    return false;
  }
  else if ((field == "data file" || field == "datafile") &&
    (words.size() != 1 || words[0] == "LIST"))
  {
    why = "its data lies in several files, which is not supported";
    return false;
  }
  return true;
}
}

//------------------------------------------------------------------------------
bool CheckNRRD(const std::string& name, std::string& error)
{
  const std::string header = HeaderOf(name);
  std::string why;
  if (header.compare(0, 4, "NRRD") != 0)
  {
    why = "it does not start with NRRD";
  }
  else if (header.back() != '\n')
  {
    why = "its header's last line does not end";
  }
  std::istringstream lines(header);
  std::string line;
  std::getline(lines, line);
  long long dimension = 0;
  bool sizes = false;
  while (why.empty() && std::getline(lines, line) && !line.empty() && line != "\r")
  {
    if (line[0] == '#')
    {
      continue; // a comment, which the reader skips
    }
    if (!IsPrintableText(line))
    {
      why = "its header holds a byte that is not printable text";
    }
    const size_t colon = line.find(": ");
    if (why.empty() && colon != std::string::npos)
    {
      CheckField(line.substr(0, colon), line.substr(colon + 2), dimension, sizes, why);
    }
  }
  if (why.empty() && !sizes)
  {
    why = "its header gives no sizes";
  }
  if (!why.empty())
  {
    error = vtkApertureText::QuoteName(name) + " is not a NRRD file VTK can read: " + why;
    return false;
  }
  return true;
}
}
