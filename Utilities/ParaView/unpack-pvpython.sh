#!/usr/bin/env bash
# Unpacks python3-paraview (pvpython and ParaView's Python modules) into <dir>/python3-paraview,
# at the installed paraview's version. The package itself cannot be installed beside our VTK 9.1
# build: it conflicts with python3-vtk9, on which libvtk9-dev depends.
set -euo pipefail
dir="$1"
target="$dir/python3-paraview"
version=$(dpkg-query -W -f='${Version}' paraview)
stamp="$target/.version"
[ -f "$stamp" ] && [ "$(cat "$stamp")" = "$version" ] && exit 0

mkdir -p "$dir/debs"
if ! (cd "$dir/debs" && apt-get download -qq "python3-paraview=$version" 2>/dev/null); then
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  (cd "$dir/debs" && apt-get download -qq "python3-paraview=$version") || {
    echo "error: cannot download python3-paraview $version (pvpython, pvbatch's modules)" >&2
    exit 1
  }
fi
rm -rf "$target"
dpkg-deb -x "$dir"/debs/python3-paraview_*.deb "$target"
echo "$version" > "$stamp"
