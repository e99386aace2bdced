/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderOptionRules.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// aperture-render's options as one table: each option's names, help and meaning in one place,
// from which ParseOptions reads the command line and HelpText writes --help. A new option is one
// more rule.

#ifndef ApertureRenderOptionRules_h
#define ApertureRenderOptionRules_h

#include <functional>
#include <string>
#include <vector>

namespace ApertureRender
{
struct Options;

struct OptionRule
{
  std::string Section;            // the heading it is listed under in --help
  std::vector<std::string> Names; // "-o", "--output"
  std::string Value;              // its value's name in --help; empty: a switch
  std::string Help;               // one paragraph, wrapped by HelpText
  // What a valid value is, for "<name> '<value>' <Expected>".
  std::string Expected;
  // Stores the value (empty for a switch) in the options; false when it is not valid.
  std::function<bool(const std::string& value, Options& options)> Apply;
};

// Every option, in the order --help lists them.
const std::vector<OptionRule>& OptionRules();

// --help before the options (usage, inputs) and after them (examples, exit status).
std::string OptionHelpIntroduction();
std::string OptionHelpExamples();
}

#endif
