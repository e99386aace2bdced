#!/usr/bin/env bash
# Runs the OpenGL tests and the GPU benchmarks of a bundle (bundle.sh) through the EGL window,
# without an X display: on a machine with an NVIDIA GPU (its EGL vendor file is used when
# present) or here on Mesa. Prints one line per test (result, seconds, image error) and each
# benchmark's own report (QUICK=1: their quick sizes; BENCH_TIMEOUT: seconds each, 300); test
# logs and images go to OUT_DIR. Run from the repository's root.
# Usage: run-gpu.sh BUNDLE.tar.xz OUT_DIR [regex of the tests and benchmarks to run]
set -uo pipefail
bundle=$(realpath "$1")
out=$(realpath -m "$2")
only=${3:-.}
root=$(mktemp -d)
trap 'rm -rf "$root"' EXIT
tar -C "$root" -xJf "$bundle" 2>/dev/null ||
  python3 -c 'import sys, tarfile; tarfile.open(sys.argv[1]).extractall(sys.argv[2])' "$bundle" "$root"
mkdir -p "$out/images"
nvidia=/usr/local/nvidia
if [ -f $nvidia/share/glvnd/egl_vendor.d/10_nvidia.json ]; then
  export __EGL_VENDOR_LIBRARY_FILENAMES=$nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
  export LD_LIBRARY_PATH=$root/lib:$nvidia/lib64:$nvidia/lib:${LD_LIBRARY_PATH:-}
  nvidia-smi -L || true
else
  export LD_LIBRARY_PATH=$root/lib:${LD_LIBRARY_PATH:-}
fi
export LD_PRELOAD=$root/lib/libApertureEGLWindow.so
unset DISPLAY
data=$PWD/Testing
tests=$("$root/bin/vtkApertureLightingGLTests" 2>&1 | sed -n 's/^ *[0-9]*\. *\(Test[A-Za-z0-9]*\).*/\1/p')
failed=0
for t in $tests; do
  [[ $t =~ $only ]] || continue
  args=(-D "$data" -T "$out/images")
  [ -f "$data/Data/Baseline/$t.png" ] && args+=(-V "$data/Data/Baseline/$t.png")
  start=$EPOCHREALTIME
  timeout 300 "$root/bin/vtkApertureLightingGLTests" "$t" "${args[@]}" > "$out/$t.log" 2>&1
  rc=$?
  seconds=$(awk "BEGIN { print $EPOCHREALTIME - $start }")
  error=$(grep -o 'name="ImageError" type="numeric/double">[^<]*' "$out/$t.log" | tail -1 | sed 's/.*>//')
  [ $rc -eq 0 ] && result=passed || { result="FAILED ($rc)"; failed=$((failed + 1)); }
  printf '%-45s %-12s %7.2f s  image error %s\n' "$t" "$result" "$seconds" "${error:--}"
done
grep -h -m1 "OpenGL renderer string" "$out"/*.log | head -1
for b in BenchmarkApertureLightingMapper BenchmarkOcclusionQueryVisibility \
  BenchmarkDynamicVisibility BenchmarkEnvironmentLighting; do
  [[ $b =~ $only ]] || continue
  echo "== $b"
  timeout "${BENCH_TIMEOUT:-300}" "$root/bin/$b" "$data/Data" ${QUICK:+--quick} 2>&1 | grep -v "^\s*$" | tail -40
done
if [[ BenchmarkVolumeAperture =~ $only ]]; then
  echo "== BenchmarkVolumeAperture"
  timeout "${BENCH_TIMEOUT:-300}" "$root/bin/BenchmarkVolumeAperture" ${QUICK:+--quick} 2>&1 | tail -40
fi
echo "$failed test(s) failed"
