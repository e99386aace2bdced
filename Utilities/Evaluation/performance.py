"""The performance report: every benchmark of the project in one run, as Markdown and plots.

    /usr/bin/python3 Utilities/Evaluation/performance.py --bin build/bin [--data Testing/Data]
                     [--out docs] [--max-level 3]

Runs BenchmarkAperturePrecompute (filter against bare Embree), BenchmarkOcclusionQueryVisibility
(the paper's Table 1 per backend, up to --max-level: level 4 with the OcclusionQuery backend takes
minutes on llvmpipe), BenchmarkApertureLightingMapper (frame-time ratios) and
BenchmarkEnvironmentLighting (relighting), BenchmarkDynamicVisibility (Table 1's dynamic rows
and the filtered orbit) and BenchmarkTerrain (horizons against rays, a 10,000² GeoTIFF, memory
over DEM sizes), each printing its own side-by-side ratios, then four sweeps measured here:
precompute time (rays) against vertices (Fuji grids), horizon time against texels x sectors,
visibility time against k (bunny, RayCast and DepthCompare) and aperture error against rays
(bunny, stratified and random against 4096 rays). Writes performance.md and images/performance-*.png under --out. Needs an X
display (run it under xvfb-run, as `make report` does).
"""

import argparse
import datetime
import math
import os
import platform
import subprocess
import sys
import tempfile
import time

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkChartsCore import vtkAxis, vtkChart, vtkChartXY
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkCommonDataModel import vtkTable
from vtkmodules.vtkIOGeometry import vtkOBJReader
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkImagingCore import vtkImageResize
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
from vtkmodules.vtkViewsContext2D import vtkContextView
import vtkmodules.vtkRenderingContextOpenGL2  # noqa: F401  (charts)
import vtkmodules.vtkRenderingFreeType  # noqa: F401  (text)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL factory)

from aperturelighting import (vtkAperturePrecompute, vtkOcclusionQueryVisibility,
                              vtkTerrainRGBReader)

COLOURS = ((31, 119, 180), (214, 39, 40), (44, 160, 44), (148, 103, 189))


def machine():
    cpu = platform.processor()
    try:
        with open("/proc/cpuinfo") as f:
            cpu = next(line.split(":", 1)[1].strip() for line in f if line.startswith("model name"))
    except (OSError, StopIteration):
        pass
    memory = ""
    try:
        with open("/proc/meminfo") as f:
            kib = int(next(line.split()[1] for line in f if line.startswith("MemTotal")))
        memory = f", {kib / 2 ** 20:.0f} GiB"
    except (OSError, StopIteration, ValueError):
        pass
    return f"{cpu}, {os.cpu_count()} cores{memory}, {platform.system()} {platform.release()}"


def run_benchmark(binary, *args):
    start = time.time()
    result = subprocess.run([binary, *args], capture_output=True, text=True)
    text = result.stdout.strip()
    if result.returncode != 0:
        text += f"\n\n(exit {result.returncode}: {result.stderr.strip()[-500:]})"
    return text, time.time() - start


def plot(path, title, xlabel, ylabel, series, logx=True, logy=True):
    """A line chart of named (x, y) series, written as a PNG."""
    view = vtkContextView()
    view.GetRenderWindow().SetOffScreenRendering(1)
    view.GetRenderWindow().SetSize(640, 420)
    view.GetRenderer().SetBackground(1, 1, 1)
    chart = vtkChartXY()
    chart.SetTitle(title)
    chart.SetShowLegend(True)
    view.GetScene().AddItem(chart)
    for index, (name, xs, ys) in enumerate(series):
        table = vtkTable()
        for column, values in (("x", xs), (name, ys)):
            array = vtkFloatArray()
            array.SetName(column)
            for v in values:
                array.InsertNextValue(v)
            table.AddColumn(array)
        line = chart.AddPlot(vtkChart.LINE)
        line.SetInputData(table, 0, 1)
        line.SetColor(*COLOURS[index % len(COLOURS)], 255)
        line.SetWidth(2.0)
        line.SetMarkerStyle(4)
    bottom, left = chart.GetAxis(vtkAxis.BOTTOM), chart.GetAxis(vtkAxis.LEFT)
    bottom.SetTitle(xlabel)
    left.SetTitle(ylabel)
    bottom.SetLogScale(logx)
    left.SetLogScale(logy)
    view.GetRenderWindow().Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(view.GetRenderWindow())
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())
    writer.SetFileName(path)
    writer.Write()


def fuji_grid(data, side, spacing):
    """The Fuji tile (texels `spacing` apart) resampled to side x side, computed."""
    reader = vtkTerrainRGBReader()
    reader.SetFileName(os.path.join(data, "fuji-terrain-rgb.png"))
    reader.SetSpacing(spacing, spacing)
    resize = vtkImageResize()
    resize.SetInputConnection(reader.GetOutputPort())
    resize.SetOutputDimensions(side, side, 1)
    resize.Update()
    return resize


def precompute_sweep(data):
    """Precompute seconds (256 rays) on Fuji grids of growing size."""
    points, seconds = [], []
    for side in (64, 128, 256, 512, 1024):
        precompute = vtkAperturePrecompute()
        precompute.SetInputConnection(fuji_grid(data, side, 60.0).GetOutputPort())
        precompute.SetMethodToRays()
        precompute.SetNumberOfRays(256)
        start = time.perf_counter()
        precompute.Update()
        points.append(side * side)
        seconds.append(time.perf_counter() - start)
    return points, seconds


def horizon_sweep(data):
    """Horizon-sweep seconds on Fuji grids of growing size, per sector count."""
    result = {}
    for sectors in (8, 16, 32, 64):
        work, seconds = [], []
        for side in (256, 512, 1024, 2048, 4096):
            precompute = vtkAperturePrecompute()
            precompute.SetInputConnection(fuji_grid(data, side, 30.0).GetOutputPort())
            precompute.SetNumberOfSectors(sectors)
            start = time.perf_counter()
            precompute.Update()
            work.append(side * side * sectors)
            seconds.append(time.perf_counter() - start)
        result[f"{sectors} sectors"] = (work, seconds)
    return result


def visibility_sweep(bunny):
    """Visibility seconds against k on the bunny, per backend."""
    result = {}
    for backend in ("RayCast", "DepthCompare"):
        ks, seconds = [], []
        for level in range(5):
            f = vtkOcclusionQueryVisibility()
            f.SetInputData(bunny)
            getattr(f, "SetBackendTo" + backend)()
            f.SetLevel(level)
            start = time.perf_counter()
            f.Update()
            elapsed = time.perf_counter() - start
            if f.GetOutput().GetNumberOfPoints() == 0:
                break
            ks.append(4 * 4 ** level + 2)
            seconds.append(elapsed)
        result[backend] = (ks, seconds)
    return result


def error_sweep(bunny):
    """Mean |aperture radius - radius at 4096 rays| against rays, stratified and random."""
    def radius(rays, random):
        f = vtkAperturePrecompute()
        f.SetInputData(bunny)
        f.SetNumberOfRays(rays)
        if random:
            f.SetSamplingToRandom()
        f.Update()
        return vtk_to_numpy(f.GetOutput().GetPointData().GetArray("ApertureRadius")).astype(float)
    truth = radius(4096, False)
    counts = [16, 32, 64, 128, 256, 512, 1024]
    return counts, {name: [np.abs(radius(n, random) - truth).mean() for n in counts]
                    for name, random in (("stratified", False), ("random", True))}


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", default=os.path.join(here, "..", "..", "build", "bin"))
    parser.add_argument("--data", default=os.path.join(here, "..", "..", "Testing", "Data"))
    parser.add_argument("--out", default=os.path.join(here, "..", "..", "docs"))
    parser.add_argument("--max-level", default="3")
    args = parser.parse_args()
    os.makedirs(os.path.join(args.out, "images"), exist_ok=True)
    started = time.time()
    sections = []
    for name, extra in (("BenchmarkAperturePrecompute", []),
                        ("BenchmarkOcclusionQueryVisibility", ["--max-level", args.max_level]),
                        ("BenchmarkApertureLightingMapper", []),
                        ("BenchmarkEnvironmentLighting", []),
                        ("BenchmarkDynamicVisibility", ["--max-level", args.max_level]),
                        ("BenchmarkTerrain", [tempfile.gettempdir()])):
        print("running", name, *extra, flush=True)
        text, seconds = run_benchmark(os.path.join(args.bin, name), args.data, *extra)
        anchor = '<a id="terrain"></a>\n\n' if name == "BenchmarkTerrain" else ""
        sections.append(f"{anchor}## {name}\n\n`{name} Testing/Data {' '.join(extra)}` "
                        f"({seconds:.0f} s)\n\n{text}\n")

    print("sweeps", flush=True)
    reader = vtkOBJReader()
    reader.SetFileName(os.path.join(args.data, "stanford-bunny.obj"))
    reader.Update()
    bunny = reader.GetOutput()
    points, seconds = precompute_sweep(args.data)
    plot(os.path.join(args.out, "images", "performance-precompute.png"),
         "vtkAperturePrecompute, 256 rays, Fuji grids", "points", "seconds",
         [("precompute", points, seconds)])
    visibility = visibility_sweep(bunny)
    plot(os.path.join(args.out, "images", "performance-visibility.png"),
         "vtkOcclusionQueryVisibility, bunny", "k (directions)", "seconds",
         [(name, ks, s) for name, (ks, s) in visibility.items()])
    horizons = horizon_sweep(args.data)
    plot(os.path.join(args.out, "images", "performance-horizons.png"),
         "vtkAperturePrecompute horizon sweeps, Fuji grids 256² to 4096²",
         "texels x sectors", "seconds", [(name, w, s) for name, (w, s) in horizons.items()])
    counts, error = error_sweep(bunny)
    plot(os.path.join(args.out, "images", "performance-rays.png"),
         "Aperture radius error against 4096 rays, bunny", "rays per point",
         "mean |r - r4096| (rad)", [(name, counts, e) for name, e in error.items()])
    slope = {name: np.polyfit(np.log(counts), np.log(e), 1)[0] for name, e in error.items()}

    lines = ["# Performance report", "",
             f"Made by `make report` (`Utilities/Evaluation/performance.py`) on "
             f"{datetime.date.today()}, in {time.time() - started:.0f} s, on: {machine()}; "
             "OpenGL: Mesa llvmpipe through Xvfb. The benchmarks measure side by side in one run "
             "(this machine is shared and noisy): read the ratios, not the absolute times.", "",
             "## Sweeps", "",
             "![precompute time against points](images/performance-precompute.png)",
             "![visibility time against k](images/performance-visibility.png)",
             "![aperture error against rays](images/performance-rays.png)",
             "![horizon time against texels x sectors](images/performance-horizons.png)", "",
             "| Fuji grid points | " + " | ".join(str(p) for p in points) + " |",
             "|---|" + "---|" * len(points),
             "| precompute, 256 rays (s) | " + " | ".join(f"{s:.2f}" for s in seconds) + " |", ""]
    for name, (ks, s) in visibility.items():
        lines += [f"| bunny visibility, {name}: k | " + " | ".join(str(k) for k in ks) + " |",
                  "|---|" + "---|" * len(ks),
                  "| seconds | " + " | ".join(f"{x:.2f}" for x in s) + " |", ""]
    for name, (w, s) in horizons.items():
        lines += [f"| horizons, {name}: texels x sectors (M) | "
                  + " | ".join(f"{x / 1e6:.0f}" for x in w) + " |", "|---|" + "---|" * len(w),
                  "| seconds | " + " | ".join(f"{x:.2f}" for x in s) + " |",
                  "| ns per texel-sector | " + " | ".join(f"{1e9 * t / x:.1f}" for t, x in zip(s, w))
                  + " |", ""]
    lines += ["| rays | " + " | ".join(str(c) for c in counts) + " | slope |",
              "|---|" + "---|" * (len(counts) + 1)]
    for name, e in error.items():
        lines.append(f"| {name}: mean error (mrad) | " + " | ".join(f"{1000 * x:.2f}" for x in e)
                     + f" | N^{slope[name]:.2f} |")
    lines += [""] + sections
    with open(os.path.join(args.out, "performance.md"), "w") as f:
        f.write("\n".join(lines))
    print("wrote", os.path.join(args.out, "performance.md"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
