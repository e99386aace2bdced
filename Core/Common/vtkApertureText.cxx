/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureText.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureText.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <vector>

namespace
{
// ASCII, so that a reader decoding messages as ASCII (a C locale) is not stopped by our marks.
const char* const Ellipsis = "...";
const std::size_t EllipsisWidth = 3;

// How many bytes a UTF-8 sequence that starts with `lead` has; 0 for a byte that starts none
// (continuation bytes, the overlong leads 0xc0 and 0xc1, leads beyond U+10FFFF).
std::size_t SequenceLength(unsigned char lead)
{
  if (lead < 0x80)
  {
    return 1;
  }
  if (lead >= 0xc2 && lead < 0xe0)
  {
    return 2;
  }
  if (lead >= 0xe0 && lead < 0xf0)
  {
    return 3;
  }
  return lead >= 0xf0 && lead < 0xf5 ? 4 : 0;
}

// The code point of the valid UTF-8 sequence at text[at], and its length in bytes; a length of 0
// when the bytes there are not one (a bad lead or continuation byte, an overlong form, a
// surrogate, beyond U+10FFFF, cut off by the end).
std::uint32_t Decode(const std::string& text, std::size_t at, std::size_t& length)
{
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[at + k]); };
  const unsigned char lead = byte(0);
  length = SequenceLength(lead);
  if (length == 0 || at + length > text.size())
  {
    length = 0;
    return 0;
  }
  static const unsigned char leadMask[5] = { 0, 0x7f, 0x1f, 0x0f, 0x07 };
  std::uint32_t code = lead & leadMask[length];
  for (std::size_t k = 1; k < length; ++k)
  {
    if ((byte(k) & 0xc0) != 0x80)
    {
      length = 0;
      return 0;
    }
    code = (code << 6) | (byte(k) & 0x3f);
  }
  static const std::uint32_t least[5] = { 0, 0, 0x80, 0x800, 0x10000 };
  if (code < least[length] || code > 0x10ffff || (code >= 0xd800 && code <= 0xdfff))
  {
    length = 0;
    return 0;
  }
  return code;
}

// Characters a terminal acts on or that change how the text around them reads: C0 and C1
// controls, DEL, bidirectional marks, embeddings, overrides and isolates, line separators.
bool IsControl(std::uint32_t code)
{
  return code < 0x20 || (code >= 0x7f && code <= 0x9f) || code == 0x200e || code == 0x200f ||
    (code >= 0x2028 && code <= 0x202e) || (code >= 0x2066 && code <= 0x2069);
}

std::string Hex(const char* format, unsigned value)
{
  char buffer[8];
  std::snprintf(buffer, sizeof(buffer), format, value);
  return buffer;
}

// The text as the pieces it is shown as: one per character kept, one per escape; at most
// `most` of them (a piece is at least a character wide, so a head of `maximumLength` characters
// needs no more than maximumLength + 1 to know it is cut, however long the text).
std::vector<std::string> Pieces(
  const std::string& text, bool doubleBackslash, std::size_t most = std::string::npos)
{
  std::vector<std::string> pieces;
  pieces.reserve(std::min(text.size(), most));
  for (std::size_t at = 0; at < text.size() && pieces.size() < most;)
  {
    std::size_t length = 0;
    const std::uint32_t code = Decode(text, at, length);
    if (length == 0 || (length == 1 && IsControl(code)))
    {
      pieces.push_back(Hex("\\x%02x", static_cast<unsigned char>(text[at])));
      ++at;
      continue;
    }
    if (IsControl(code))
    {
      pieces.push_back(Hex("\\u%04x", code));
    }
    else if (code == '\\' && doubleBackslash)
    {
      pieces.push_back("\\\\");
    }
    else
    {
      pieces.push_back(text.substr(at, length));
    }
    at += length;
  }
  return pieces;
}

// How many pieces Head() needs for `maximumLength` characters.
std::size_t HeadPieces(std::size_t maximumLength)
{
  return maximumLength == std::string::npos ? maximumLength : maximumLength + 1;
}

// A piece's width on the screen, in characters.
std::size_t Width(const std::string& piece)
{
  const auto lead = static_cast<unsigned char>(piece[0]);
  return lead >= 0x80 ? 1 : piece.size();
}

// The width of all the pieces, in characters.
std::size_t TotalWidth(const std::vector<std::string>& pieces)
{
  std::size_t width = 0;
  for (const std::string& piece : pieces)
  {
    width += Width(piece);
  }
  return width;
}

// The pieces within `maximumLength` characters: all of them, or the first ones and `...`.
std::string Head(const std::vector<std::string>& pieces, std::size_t maximumLength)
{
  const bool cut = TotalWidth(pieces) > maximumLength;
  const std::size_t room = cut ? maximumLength - std::min(maximumLength, EllipsisWidth) : 0;
  std::string result;
  std::size_t width = 0;
  for (std::size_t k = 0; k < pieces.size(); ++k)
  {
    width += Width(pieces[k]);
    if (cut && width > room)
    {
      return result + Ellipsis;
    }
    result += pieces[k];
  }
  return result;
}

// The pieces within `maximumLength` characters: all of them, or `...` and the last ones.
std::string Tail(const std::vector<std::string>& pieces, std::size_t maximumLength)
{
  const bool cut = TotalWidth(pieces) > maximumLength;
  const std::size_t room = cut ? maximumLength - std::min(maximumLength, EllipsisWidth) : 0;
  std::size_t width = 0;
  std::size_t first = pieces.size();
  while (first > 0 && (!cut || width + Width(pieces[first - 1]) <= room))
  {
    width += Width(pieces[--first]);
  }
  std::string result = cut ? Ellipsis : "";
  for (std::size_t k = first; k < pieces.size(); ++k)
  {
    result += pieces[k];
  }
  return result;
}
}

std::string vtkApertureText::Escape(const std::string& text, std::size_t maximumLength)
{
  return Head(Pieces(text, true, HeadPieces(maximumLength)), maximumLength);
}

std::string vtkApertureText::Quote(const std::string& text, std::size_t maximumLength)
{
  return "'" + Escape(text, maximumLength) + "'";
}

std::string vtkApertureText::QuoteName(const std::string& name, std::size_t maximumLength)
{
  return "'" + Tail(Pieces(name, true), maximumLength) + "'";
}

std::string vtkApertureText::Line(const std::string& message, std::size_t maximumLength)
{
  return Head(Pieces(message, false, HeadPieces(maximumLength)), maximumLength);
}

bool vtkApertureText::IsSafe(const std::string& text)
{
  for (std::size_t at = 0; at < text.size();)
  {
    std::size_t length = 0;
    const std::uint32_t code = Decode(text, at, length);
    if (length == 0 || IsControl(code))
    {
      return false;
    }
    at += length;
  }
  return true;
}
