#!/usr/bin/env bash
# Installs the Debian 12 packages the project needs, only those that are missing.
#   install-dependencies.sh        what building and testing need
#   install-dependencies.sh fuzz   and Clang, for `make fuzz` (libFuzzer and the sanitizers)
#   install-dependencies.sh paraview   and ParaView 5.11 with Open MPI, for `make paraview`
# ParaView comes without its Recommends: python3-paraview conflicts with python3-vtk9, and
# removing that would remove libvtk9-dev (`make paraview` unpacks python3-paraview instead).
set -euo pipefail

packages=(
  cmake make g++ pkg-config clang-format
  libvtk9-dev python3-vtk9 python3-numpy
  libembree-dev libopenexr-dev libglm-dev libx11-dev libgdal-dev gdal-bin
  libvtk-dicom-dev python3-vtk-dicom
  saga grass-core
  xvfb xauth openmpi-bin libopenmpi-dev
)
if [ "${1:-}" = "fuzz" ]; then
  packages+=(clang)
fi
if [ "${1:-}" = "paraview" ]; then
  packages+=(paraview paraview-dev)
fi

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)
  [ "$status" = "installed" ] || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "Installing missing packages: ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "error: need root or sudo to install ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
