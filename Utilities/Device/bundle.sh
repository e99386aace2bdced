#!/usr/bin/env bash
# Packs what the GPU check (run-gpu.sh, docs/testing.md) needs on a machine that has neither
# Debian's VTK nor an X server: the test driver and the benchmarks, this project's libraries, the
# EGL window library and every shared library they load, except glibc's and the C++ runtime,
# which the other machine has in a newer version. Usage: bundle.sh BUILD_DIR OUTPUT.tar.xz
set -euo pipefail
build=$(realpath "$1")
out=$(realpath -m "$2")
mkdir -p "$(dirname "$out")"
programs="vtkApertureLightingGLTests BenchmarkApertureLightingMapper
  BenchmarkOcclusionQueryVisibility BenchmarkDynamicVisibility BenchmarkEnvironmentLighting
  BenchmarkVolumeAperture"
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/bin" "$stage/lib"
for p in $programs; do cp "$build/bin/$p" "$stage/bin/"; done
cp "$build/lib/libApertureEGLWindow.so" "$stage/lib/"
system='/(libc|libm|libpthread|libdl|librt|libresolv|libutil|ld-linux-x86-64|libstdc\+\+|libgcc_s)\.so'
for f in "$stage"/bin/* "$stage/lib/libApertureEGLWindow.so"; do
  ldd "$f" | awk '/=> \//{print $3}'
done | sort -u | grep -v -E "$system" | while read -r lib; do
  cp -L "$lib" "$stage/lib/"
done
tar -C "$stage" -cf - bin lib | xz -T0 -6 > "$out"
du -h "$out"
