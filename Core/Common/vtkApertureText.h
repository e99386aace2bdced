/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureText.h

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
/**
 * @class   vtkApertureText
 * @brief   text from a file or a user, made safe to print in a message (private)
 *
 * A file made to hurt can put terminal control sequences (ESC, C1 codes, bidirectional
 * overrides) or invalid UTF-8 into a message that quotes it: retitle a terminal, hide text, fake a
 * success line, break a log reader. Every message of the module and its tools that quotes input
 * (file content, file and array names, a reader's or GDAL's own words) passes it through here.
 *
 * What is kept: printable ASCII and valid UTF-8 of printable characters. What is escaped: bytes
 * below 0x20 and DEL as `\xNN`, bytes that are not valid UTF-8 one by one as `\xNN`, C1 controls,
 * bidirectional controls and line separators as `\uNNNN`. Lengths count the characters shown (an
 * escape counts as the characters it writes); what is cut is marked with `...`, within the
 * length. The result is valid UTF-8 with no byte below 0x20, and ASCII unless the input holds
 * printable non-ASCII characters (a name in another script), so that a reader decoding as ASCII
 * (a C locale) is only ever stopped by the input's own letters.
 */

#ifndef vtkApertureText_h
#define vtkApertureText_h

#include "vtkApertureLightingCoreModule.h" // For export macro

#include <cstddef>
#include <string>

class VTKAPERTURELIGHTINGCORE_EXPORT vtkApertureText
{
public:
  /**
   * Input text as a message quotes it: escaped as above, a backslash doubled (so that an escape
   * in the result always means a byte of the input), cut after `maximumLength` characters.
   */
  static std::string Escape(const std::string& text, std::size_t maximumLength = 48);

  /**
   * Escape() in single quotes: `'text'`.
   */
  static std::string Quote(const std::string& text, std::size_t maximumLength = 48);

  /**
   * A file name in single quotes: escaped as Escape(), and when long, cut at its start rather
   * than its end, which keeps the name of the file itself.
   */
  static std::string QuoteName(const std::string& name, std::size_t maximumLength = 120);

  /**
   * A whole message made safe for a terminal or a log, as one line: escaped as Escape() except
   * that backslashes are kept (parts already escaped stay as they are, so Line(Line(m)) ==
   * Line(m)), cut after `maximumLength` characters.
   */
  static std::string Line(const std::string& message, std::size_t maximumLength = 300);

  /**
   * Whether `text` could be printed as it is: valid UTF-8, no byte below 0x20, no DEL, no
   * character Escape() escapes. Tests and fuzzers check messages with it.
   */
  static bool IsSafe(const std::string& text);
};

#endif
// VTK-HeaderTest-Exclude: vtkApertureText.h
