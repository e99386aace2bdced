#!/usr/bin/env python3
"""Fails when a function of the library or its tools is longer than the limit (80 lines, header
to closing brace).

Usage: CheckFunctionLength.py SOURCE_DIR [--limit N] [--list N]

Reads the .cxx and .h files of the library folders (Core, IO, Rendering, Volume), the tools
(Examples/ApertureRender), the fuzz targets and the ParaView plugin, with
comments and literals blanked, and measures every function body that is not inside another
function: free functions, methods defined out of line and those defined in class bodies.
Lambdas count as part of the function that holds them. A function may be longer when a comment
within the three lines above it says why, starting "Longer than 80 lines:". --list N prints the
N longest.
"""

import argparse
import pathlib
import re
import sys

FOLDERS = ("Core", "IO", "Rendering", "Volume", "Examples/ApertureRender", "Testing/Fuzz",
           "ParaView")
REASON = "Longer than 80 lines:"
CONTROL = re.compile(r"\b(if|for|while|switch|catch|do|else|try)\s*(\(|$)")
FUNCTION_END = re.compile(r"\)\s*(const)?\s*(noexcept)?\s*(override|final)?\s*(->[^{]*)?$")
INITIALIZERS = re.compile(r"\)\s*:\s*[A-Za-z_][\w:<>]*\s*[({]")


def blank(text):
    """The text with comments, string and character literals replaced by spaces (newlines kept)."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
        elif c in "\"'":
            if c == '"' and i > 0 and text[i - 1] == "R":  # raw string R"(...)"
                close = ")" + text[i + 1:text.find("(", i)] + '"'
                j = text.find(close, i) + len(close)
            else:
                j = i + 1
                while j < n and text[j] != c:
                    j += 2 if text[j] == "\\" else 1
                j += 1
        else:
            out.append(c)
            i += 1
            continue
        out.append(re.sub(r"[^\n]", " ", text[i:j]))
        i = j
    return "".join(out)


def kind(header):
    """What a brace opens, from the text before it: namespace, class, function or other."""
    header = " ".join(header.split())
    if re.search(r"\bnamespace\b", header) or header.startswith('extern "C"'):
        return "namespace"
    if re.search(r"\b(class|struct|union|enum)\b[^()]*$", header):
        return "class"
    if "(" in header and not CONTROL.search(header) and "=" not in header.split("(")[0]:
        if FUNCTION_END.search(header) or INITIALIZERS.search(header):
            return "function"
    return "other"


def functions(path):
    """(first line, last line, header) of each outermost function body in the file."""
    original = path.read_text(errors="replace")
    text = blank(original)
    lines = original.split("\n")
    found, stack, start = [], [], 0
    for i, c in enumerate(text):
        if c in ";{}":
            if c == "{":
                header = text[start:i]
                inside = any(k in ("function", "other") for k, _ in stack)
                k = "other" if inside else kind(re.sub(r"^\s*#.*$", "", header, flags=re.M))
                first = text.count("\n", 0, start + len(header) - len(header.lstrip()))
                stack.append((k, first))
            elif c == "}" and stack:
                k, first = stack.pop()
                if k == "function":
                    last = text.count("\n", 0, i)
                    found.append((first + 1, last + 1, lines[first].strip()))
            start = i + 1
    return found, lines


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("source")
    parser.add_argument("--limit", type=int, default=80)
    parser.add_argument("--list", type=int, default=0)
    args = parser.parse_args()
    root = pathlib.Path(args.source)
    measured, too_long = [], []
    for folder in FOLDERS:
        for path in sorted((root / folder).rglob("*")):
            if path.suffix not in (".cxx", ".h"):
                continue
            found, lines = functions(path)
            for first, last, header in found:
                length = last - first + 1
                where = f"{path.relative_to(root)}:{first}"
                measured.append((length, where, header))
                above = "\n".join(lines[max(0, first - 4):first - 1])
                if length > args.limit and REASON not in above:
                    too_long.append((length, where, header))
    for length, where, header in sorted(measured, reverse=True)[:args.list]:
        print(f"{length:4d} {where} {header}")
    print(f"{len(measured)} functions measured; the longest: "
          f"{max(measured)[0] if measured else 0} lines")
    for length, where, header in sorted(too_long, reverse=True):
        print(f"FAIL {where}: {length} lines (limit {args.limit}) without a reason beside it: "
              f"{header}")
    return 1 if too_long else 0


if __name__ == "__main__":
    sys.exit(main())
