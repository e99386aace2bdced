/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderMetaImage.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "ApertureRenderMetaImage.h"

#include "ApertureRenderText.h"

#include "vtkApertureText.h"

#include <vtksys/FStream.hxx>
#include <vtksys/SystemTools.hxx>

#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace ApertureRender
{
namespace
{
// MetaIO's field names live in char[255].
constexpr size_t LongestName = 254;

// Whether a data file named in a header in `folder` (relative to it, or absolute) exists.
bool DataFileExists(const std::string& folder, const std::string& file)
{
  return vtksys::SystemTools::FileExists(
    vtksys::SystemTools::CollapseFullPath(file, folder.empty() ? "." : folder), true);
}

std::string Trim(const std::string& text)
{
  const size_t first = text.find_first_not_of(" \t\r");
  const size_t last = text.find_last_not_of(" \t\r");
  return first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
}

std::vector<long long> Integers(const std::string& text)
{
  std::istringstream stream(text);
  std::vector<long long> values;
  for (long long value; stream >> value;)
  {
    values.push_back(value);
  }
  return values;
}

// Checks one "name = value" field of the header in `folder`; `dims` carries NDims once it is
// seen. True at ElementDataFile, where the header ends.
bool CheckField(const std::string& folder, const std::string& key, const std::string& value,
  long long& dims, std::string& why)
{
  const std::vector<long long> numbers = Integers(value);
  if (key == "NDims")
  {
    dims = numbers.size() == 1 && numbers[0] >= 1 && numbers[0] <= 3 ? numbers[0] : 0;
    why = dims == 0 ? "its NDims is not 1 to 3" : "";
  }
  else if (key == "DimSize")
  {
    long long values = 1;
    bool sound = dims > 0 && static_cast<long long>(numbers.size()) == dims;
    for (long long n : numbers)
    {
      sound = sound && n >= 1 && n <= INT32_MAX && (values *= n) <= INT32_MAX;
    }
    why = sound ? ""
                : "its DimSize does not follow NDims with as many positive counts of at "
                  "most 2^31 values in all";
  }
  else if (key == "ElementNumberOfChannels" &&
    (numbers.size() != 1 || numbers[0] < 1 || numbers[0] > 4))
  {
    why = "its ElementNumberOfChannels is not 1 to 4";
  }
  else if (key == "ElementDataFile")
  {
    std::istringstream words(value);
    std::string file, more;
    words >> file >> more;
    if (file.empty() || !more.empty() || file == "LIST")
    {
      why = "its data is not LOCAL or in one file";
    }
    else if (file != "LOCAL" && !DataFileExists(folder, file))
    {
      // MetaIO leaks a stream when it cannot open the file.
      why = "its ElementDataFile " + vtkApertureText::QuoteName(file) + " does not exist";
    }
    else if (dims == 0)
    {
      why = "its header gives no NDims";
    }
    return true;
  }
  return false;
}
}

//------------------------------------------------------------------------------
bool CheckMetaImage(const std::string& name, std::string& error)
{
  // The header is read as MetaIO reads it, up to ElementDataFile (whose data follows), within
  // the first 64 KiB.
  vtksys::ifstream file(name.c_str(), std::ios::in | std::ios::binary);
  std::string head(1 << 16, '\0');
  file.read(&head[0], static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(file.gcount()));
  std::istringstream lines(head);
  const std::string folder = vtksys::SystemTools::GetFilenamePath(name);
  std::string why = "its header does not end with ElementDataFile";
  long long dims = 0;
  for (std::string line; std::getline(lines, line);)
  {
    std::string problem =
      IsPrintableText(line) ? "" : "its header holds a byte that is not printable text";
    const size_t equals = line.find('=');
    const std::string key = Trim(line.substr(0, equals));
    if (problem.empty() && Trim(line).empty())
    {
      continue;
    }
    if (problem.empty() && (equals == std::string::npos || key.empty() || key.size() > LongestName))
    {
      problem = "a header line is not a name shorter than 255 characters, = and a value";
    }
    const bool last =
      problem.empty() && CheckField(folder, key, Trim(line.substr(equals + 1)), dims, problem);
    if (!problem.empty() || last)
    {
      why = problem;
      break;
    }
  }
  if (!why.empty())
  {
    error = vtkApertureText::QuoteName(name) + " is not a MetaImage file VTK can read: " + why;
    return false;
  }
  return true;
}
}
