/*=========================================================================

  Program:   ApertureLighting
  Module:    TestApertureText.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkApertureText: what it escapes (known cases: ESC sequences, NUL, DEL, C1 and bidirectional
// controls, every kind of invalid UTF-8), and, on random bytes, that its results are always safe
// to print (checked by a validator written here, not by IsSafe alone), bounded in length,
// undone exactly by an independent unescaper, and that Line is idempotent.

#include "vtkApertureTestHarness.h"
#include "vtkApertureText.h"

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>

namespace
{
using vtkApertureTest::Check;

// Valid UTF-8 with no byte below 0x20 and no DEL, by the table of RFC 3629 (written apart from
// vtkApertureText's decoder). Counts the characters in `length`.
bool PrintableUTF8(const std::string& s, std::size_t& length)
{
  length = 0;
  for (std::size_t i = 0; i < s.size(); ++length)
  {
    const auto b = [&](std::size_t k) { return i + k < s.size() ? (unsigned char)s[i + k] : 0; };
    const auto in = [](unsigned v, unsigned lo, unsigned hi) { return v >= lo && v <= hi; };
    if (b(0) >= 0x20 && b(0) < 0x7f)
    {
      i += 1;
    }
    else if (in(b(0), 0xc2, 0xdf) && in(b(1), 0x80, 0xbf))
    {
      i += 2;
    }
    else if ((b(0) == 0xe0 && in(b(1), 0xa0, 0xbf)) ||
      ((in(b(0), 0xe1, 0xec) || in(b(0), 0xee, 0xef)) && in(b(1), 0x80, 0xbf)) ||
      (b(0) == 0xed && in(b(1), 0x80, 0x9f)))
    {
      if (!in(b(2), 0x80, 0xbf))
      {
        return false;
      }
      i += 3;
    }
    else if ((b(0) == 0xf0 && in(b(1), 0x90, 0xbf)) ||
      (in(b(0), 0xf1, 0xf3) && in(b(1), 0x80, 0xbf)) || (b(0) == 0xf4 && in(b(1), 0x80, 0x8f)))
    {
      if (!in(b(2), 0x80, 0xbf) || !in(b(3), 0x80, 0xbf))
      {
        return false;
      }
      i += 4;
    }
    else
    {
      return false;
    }
  }
  return true;
}

// The bytes an escaped text stands for: \xNN, \uNNNN (as UTF-8) and \\ undone.
std::string Unescape(const std::string& s)
{
  std::string bytes;
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    if (s[i] != '\\' || i + 1 >= s.size())
    {
      bytes += s[i];
    }
    else if (s[i + 1] == '\\')
    {
      bytes += '\\';
      i += 1;
    }
    else if (s[i + 1] == 'x')
    {
      bytes += static_cast<char>(std::stoi(s.substr(i + 2, 2), nullptr, 16));
      i += 3;
    }
    else if (s[i + 1] == 'u')
    {
      const int code = std::stoi(s.substr(i + 2, 4), nullptr, 16);
      if (code < 0x800)
      {
        bytes += static_cast<char>(0xc0 | (code >> 6));
      }
      else
      {
        bytes += static_cast<char>(0xe0 | (code >> 12));
        bytes += static_cast<char>(0x80 | ((code >> 6) & 0x3f));
      }
      bytes += static_cast<char>(0x80 | (code & 0x3f));
      i += 5;
    }
  }
  return bytes;
}

void CheckKnownCases()
{
  const struct
  {
    std::string In, Out;
  } cases[] = {
    { "plain.obj", "plain.obj" },
    { "\x1b]0;pwned\x07", "\\x1b]0;pwned\\x07" },
    { std::string("a\0b", 3), "a\\x00b" },
    { "tab\tnew\nline\r\x7f", "tab\\x09new\\x0aline\\x0d\\x7f" },
    { "caf\xc3\xa9 \xe6\x97\xa5\xe6\x9c\xac \xf0\x9f\x8c\x8b",
      "caf\xc3\xa9 \xe6\x97\xa5\xe6\x9c\xac \xf0\x9f\x8c\x8b" },
    { "\x92\xda\xff\x15", "\\x92\\xda\\xff\\x15" },
    { "\xc0\xaf", "\\xc0\\xaf" },                   // overlong '/'
    { "\xed\xa0\x80", "\\xed\\xa0\\x80" },          // a surrogate
    { "\xf4\x90\x80\x80", "\\xf4\\x90\\x80\\x80" }, // past U+10FFFF
    { "\xe2\x82", "\\xe2\\x82" },                   // cut off by the end
    { "\xc2\x9b"
      "31m",
      "\\u009b31m" }, // C1 CSI
    { "abc\xe2\x80\xae"
      "cod.exe",
      "abc\\u202ecod.exe" }, // right-to-left override
    { "back\\slash", "back\\\\slash" },
  };
  for (const auto& c : cases)
  {
    const std::string got = vtkApertureText::Escape(c.In, 1000);
    Check(got == c.Out, "Escape of a known case gives " + got + ", want " + c.Out);
    Check(Unescape(got) == c.In, "the known case " + c.Out + " unescapes to its bytes");
  }
  Check(vtkApertureText::Quote("x") == "'x'", "Quote puts the text in single quotes");
  Check(vtkApertureText::Line("a\\x1b") == "a\\x1b", "Line keeps a backslash");

  const std::string longText(1 << 20, 'W');
  const std::string cut = vtkApertureText::Escape(longText, 40);
  Check(cut == std::string(37, 'W') + "...", "a 1 MiB text is cut to 40 characters with '...'");
  const std::string name = "/" + std::string(300, 'd') + "/model.obj";
  const std::string quoted = vtkApertureText::QuoteName(name, 60);
  Check(quoted.size() > 12 && quoted.compare(quoted.size() - 11, 11, "/model.obj'") == 0 &&
      quoted.compare(0, 4, "'...") == 0 && quoted.size() == 62,
    "a long file name keeps its end: " + quoted);
}

// Random bytes, biased toward the troublesome ones, through every function.
void CheckRandomTexts()
{
  std::mt19937 random(12345);
  const unsigned char troublesome[] = { 0x00, 0x1b, 0x07, 0x0a, 0x7f, 0x5c, 0x80, 0x9b, 0xbf, 0xc0,
    0xc2, 0xe0, 0xe2, 0xed, 0xef, 0xf0, 0xf4, 0xf5, 0xff };
  for (int trial = 0; trial < 20000; ++trial)
  {
    std::string text(random() % 80, ' ');
    for (char& c : text)
    {
      const unsigned r = random();
      c = static_cast<char>(r % 3 == 0 ? troublesome[(r >> 8) % sizeof(troublesome)]
                                       : (r % 3 == 1 ? 0x20 + (r >> 8) % 95 : (r >> 8) % 256));
    }
    const std::size_t limit = 1 + random() % 100;
    const std::string results[] = { vtkApertureText::Escape(text, limit),
      vtkApertureText::QuoteName(text, limit), vtkApertureText::Line(text, limit) };
    for (const std::string& result : results)
    {
      std::size_t length = 0;
      Check(PrintableUTF8(result, length), "a result is valid UTF-8 with no control byte");
      Check(length <= std::max<std::size_t>(limit, 3) + 2,
        "a result is at most its limit long (and its quotes; '...' needs 3)");
      Check(vtkApertureText::IsSafe(result), "IsSafe agrees that a result is safe");
      Check(std::any_of(text.begin(), text.end(), [](char c) { return c & 0x80; }) ||
          std::none_of(result.begin(), result.end(), [](char c) { return c & 0x80; }),
        "an ASCII text gives an ASCII result");
    }
    Check(vtkApertureText::Line(results[2], 1000) == results[2], "Line is idempotent");
    const std::string whole = vtkApertureText::Escape(text, 1000);
    Check(Unescape(whole) == text, "Escape is undone exactly by unescaping");
    std::size_t length = 0;
    Check(vtkApertureText::IsSafe(text) == PrintableUTF8(text, length) ||
        text.find("\xe2\x80") != std::string::npos || text.find("\xc2") != std::string::npos,
      "IsSafe agrees with the validator on input (C1 and bidirectional controls aside)");
  }
}
}

int TestApertureText(int, char*[])
{
  CheckKnownCases();
  CheckRandomTexts();
  return vtkApertureTest::Result();
}
