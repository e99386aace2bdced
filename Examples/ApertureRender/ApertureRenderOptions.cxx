/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderOptions.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "ApertureRenderOptions.h"

#include "ApertureRenderOptionRules.h"

#include "vtkApertureText.h"

#include <limits>
#include <set>
#include <sstream>

namespace ApertureRender
{
namespace
{
const OptionRule* FindRule(const std::string& name)
{
  for (const OptionRule& rule : OptionRules())
  {
    for (const std::string& known : rule.Names)
    {
      if (known == name)
      {
        return &rule;
      }
    }
  }
  return nullptr;
}

// The checks that concern several options, and the defaults that depend on others.
int Finish(const std::vector<std::string>& positional, const std::set<std::string>& given,
  Options& options, std::string& error)
{
  if (positional.size() > 1)
  {
    error = "one input at a time, got " + vtkApertureText::QuoteName(positional[0]) + " and " +
      vtkApertureText::QuoteName(positional[1]);
    return 2;
  }
  options.Input = positional.empty() ? "" : positional[0];
  if (options.Output.empty() && !options.Interactive)
  {
    error = "say where the picture goes (-o picture.png) or ask for a window (--interactive)";
    return 2;
  }
  if (options.Environment.empty() &&
    (given.count("--env-azimuth") || given.count("--env-exposure")))
  {
    error = std::string(given.count("--env-azimuth") ? "--env-azimuth" : "--env-exposure") +
      " applies to an environment: give one with --env";
    return 2;
  }
  if (options.Mode == "all" && !given.count("--size"))
  {
    // A row of five panels.
    options.Width = 640;
    options.Height = 400;
  }
  if (options.HeightScale == 0.0)
  {
    options.HeightScale = options.Input.empty() ? 1.5 : 1.0;
  }
  return 0;
}

// "  -o, --output FILE.png" in a column of 23 characters, then the help wrapped at 97.
std::string HelpLines(const OptionRule& rule)
{
  std::string head = "  ";
  for (const std::string& name : rule.Names)
  {
    head += (head.size() > 2 ? ", " : "") + name;
  }
  head += rule.Value.empty() ? "" : " " + rule.Value;
  const std::string indent(25, ' ');
  // The help starts on the head's line when that leaves two spaces between them.
  std::string text = head.size() <= 23 ? "" : head + "\n";
  std::string line = head.size() <= 23 ? head + std::string(25 - head.size(), ' ') : indent;
  std::istringstream words(rule.Help);
  std::string word;
  while (words >> word)
  {
    if (line.size() > indent.size() && line.size() + 1 + word.size() > 97)
    {
      text += line + "\n";
      line = indent;
    }
    line += (line.size() > indent.size() ? " " : "") + word;
  }
  return text + line + "\n";
}
}

Options::Options()
  : MaximumEdge(std::numeric_limits<double>::quiet_NaN())
  , CameraAzimuth(std::numeric_limits<double>::quiet_NaN())
  , CameraElevation(std::numeric_limits<double>::quiet_NaN())
  , EnvironmentExposure(std::numeric_limits<double>::quiet_NaN())
  , Iso(std::numeric_limits<double>::quiet_NaN())
{
}

const std::vector<std::string>& ModeNames()
{
  static const std::vector<std::string> names = { "exact", "smoothstep", "simplified", "bentnormal",
    "standard", "horizon", "mask" };
  return names;
}

bool WantsHorizons(const Options& options)
{
  return options.Mode == "horizon" || options.Mode == "all" || options.Interactive;
}

bool WantsMasks(const Options& options)
{
  return options.Mode == "mask" || options.Mode == "all" || options.Interactive;
}

int ParseOptions(int argc, char* argv[], Options& options, std::string& error)
{
  // The first error is kept and the rest read, so that --help anywhere still answers.
  std::string first;
  std::set<std::string> given;
  std::vector<std::string> positional;
  for (int i = 1; i < argc; ++i)
  {
    const std::string word = argv[i];
    const OptionRule* rule = FindRule(word);
    if (!rule && word.size() > 1 && word[0] == '-' && first.empty())
    {
      first = "unknown option " + vtkApertureText::Quote(word) + " (see --help)";
    }
    if (!rule)
    {
      positional.push_back(word);
      continue;
    }
    const bool needsValue = !rule->Value.empty();
    if (needsValue && i + 1 >= argc)
    {
      first = first.empty() ? "option " + word + " needs a value (see --help)" : first;
      break;
    }
    const std::string value = needsValue ? argv[++i] : "";
    if (!rule->Apply(value, options) && first.empty())
    {
      const bool file = rule->Value.find("FILE") != std::string::npos;
      first = word + " " +
        (file ? vtkApertureText::QuoteName(value) : vtkApertureText::Quote(value)) + " " +
        rule->Expected;
    }
    given.insert(rule->Names.back());
  }
  if (options.Help || options.Version)
  {
    return 0;
  }
  error = first;
  return first.empty() ? Finish(positional, given, options, error) : 2;
}

std::string HelpText()
{
  std::string text = OptionHelpIntroduction();
  std::string section;
  for (const OptionRule& rule : OptionRules())
  {
    if (rule.Section != section)
    {
      section = rule.Section;
      text += "\n" + (section.empty() ? std::string() : section + ":\n");
    }
    text += HelpLines(rule);
  }
  return text + OptionHelpExamples();
}
}
