/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderOBJ.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "ApertureRenderOBJ.h"

#include "ApertureRenderMessages.h"

#include "vtkApertureText.h"
#include "vtksys/SystemTools.hxx"

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace ApertureRender
{
namespace
{
// What OBJ elements index: vertices, texture coordinates and normals.
const char* const Kinds[3] = { "v", "vt", "vn" };

// What the file holds, in all and up to the line being checked.
struct Counts
{
  long Total[3] = { 0, 0, 0 };
  long Seen[3] = { 0, 0, 0 };
  bool Materials = false; // any usemtl in the file
  bool Material = false;  // a usemtl before this line
};

// The file's lines as vtkOBJReader reads them: fgets into a 256 KiB buffer, up to a NUL byte.
bool ReadLines(const std::string& name, std::vector<std::string>& lines)
{
  FILE* file = vtksys::SystemTools::Fopen(name, "rb");
  if (!file)
  {
    return false;
  }
  std::vector<char> line(1 << 18);
  while (std::fgets(line.data(), static_cast<int>(line.size()), file))
  {
    lines.emplace_back(line.data());
  }
  std::fclose(file);
  return true;
}

// The v, v/t, v//n or v/t/n words of a face, line or point element. False with what is wrong.
bool CheckElement(std::istringstream& words, const Counts& counts, std::string& what)
{
  std::string word;
  while (words >> word)
  {
    if (word.back() == '/')
    {
      what = "a word ending in '/', " + vtkApertureText::Quote(word);
      return false;
    }
    std::istringstream parts(word);
    std::string part;
    for (int k = 0; k < 3 && std::getline(parts, part, '/'); ++k)
    {
      if (part.empty() && k > 0)
      {
        continue;
      }
      char* end = nullptr;
      const long index = std::strtol(part.c_str(), &end, 10);
      const bool valid = *end == '\0' && !part.empty() &&
        ((index > 0 && index <= counts.Total[k]) || (index < 0 && -index <= counts.Seen[k]));
      if (!valid)
      {
        what = std::string(Kinds[k]) + " " + vtkApertureText::Quote(part) + ", but there are " +
          std::to_string(counts.Total[k]);
        return false;
      }
      if (k == 1 && counts.Materials && !counts.Material)
      {
        what = "texture coordinates before the first usemtl";
        return false;
      }
    }
  }
  return true;
}

// A v, vt or vn line (kind 0, 1, 2): false when it holds too few numbers.
bool CheckCoordinates(std::istringstream& words, int kind, std::string& what)
{
  static const int least[3] = { 3, 2, 3 };
  int numbers = 0;
  std::string word;
  while (words >> word)
  {
    char* end = nullptr;
    std::strtod(word.c_str(), &end);
    numbers += *end == '\0' ? 1 : 0;
  }
  what = "a '" + std::string(Kinds[kind]) + "' with " + std::to_string(numbers) + " numbers";
  return numbers >= least[kind];
}

// One line; `counts` advances past it. False with what is wrong.
bool CheckLine(const std::string& line, Counts& counts, std::string& what)
{
  std::istringstream words(line);
  std::string command;
  words >> command;
  for (int k = 0; k < 3; ++k)
  {
    if (command == Kinds[k])
    {
      ++counts.Seen[k];
      return CheckCoordinates(words, k, what);
    }
  }
  if (command == "usemtl")
  {
    std::string material;
    words >> material;
    counts.Material = true;
    what = "a material name longer than 99 characters";
    return material.size() < 100;
  }
  const bool element = command == "f" || command == "l" || command == "p";
  if (element && !CheckElement(words, counts, what))
  {
    what = "'" + command + "' names " + what;
    return false;
  }
  return true;
}
}

bool CheckOBJ(const std::string& name, std::string& error)
{
  std::vector<std::string> lines;
  if (!ReadLines(name, lines))
  {
    error = vtkApertureText::QuoteName(name) + " cannot be read";
    return false;
  }
  Counts counts;
  for (const std::string& text : lines)
  {
    std::istringstream words(text);
    std::string command;
    words >> command;
    for (int k = 0; k < 3; ++k)
    {
      counts.Total[k] += command == Kinds[k] ? 1 : 0;
    }
    counts.Materials = counts.Materials || command == "usemtl";
  }
  for (size_t number = 0; number < lines.size(); ++number)
  {
    std::string what;
    if (!CheckLine(lines[number], counts, what))
    {
      error = vtkApertureText::QuoteName(name) + " is damaged (line " + std::to_string(number + 1) +
        ": " + what + ")";
      return false;
    }
  }
  return true;
}
}
