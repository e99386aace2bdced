"""aperture-precompute end to end.

    python3 TestAperturePrecompute.py <aperture-precompute> <Testing/Data> <work folder>

A DEM as an ESRI ASCII grid (a format GDAL reads, written here from the Fuji tile, with a hole of
no-data) becomes a GeoTIFF of apertures with the DEM's georeferencing, NaN at the no-data
texels; tiles of any height give the same file contents as one piece; bad input ends with exit
status 1 or 2 and one line on stderr. `gdalinfo` (Debian's gdal-bin) reads the results.
"""

import json
import math
import os
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

from tool_run import run_tool

EXE, DATA, WORK = sys.argv[1:4]
os.makedirs(WORK, exist_ok=True)
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def path(name):
    return os.path.join(WORK, name)


def run(*args):
    return run_tool([EXE, *args], text=True)


def gdalinfo(name, *flags):
    out = subprocess.run(["gdalinfo", "-json", *flags, name], capture_output=True, text=True)
    return json.loads(out.stdout) if out.returncode == 0 else None


def fuji_heights(step):
    reader = vtkPNGReader()
    reader.SetFileName(os.path.join(DATA, "fuji-terrain-rgb.png"))
    reader.Update()
    w, h, _ = reader.GetOutput().GetDimensions()
    rgb = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars()).reshape(h, w, -1)
    rgb = rgb[::-1, :, :3].astype(np.int64)  # the file's first row north
    heights = (rgb[..., 0] * 65536 + rgb[..., 1] * 256 + rgb[..., 2] - 100000) / 10.0
    return heights[::step, ::step]


def write_ascii_grid(name, heights, cell, hole):
    rows, cols = heights.shape
    with open(name, "w") as f:
        f.write(f"ncols {cols}\nnrows {rows}\nxllcorner 300000\nyllcorner 3900000\n"
                f"cellsize {cell}\nNODATA_value -9999\n")
        for r in range(rows):
            values = ["-9999" if hole(r, c) else f"{heights[r, c]:.1f}" for c in range(cols)]
            f.write(" ".join(values) + "\n")


def hole(r, c):
    return 40 <= r < 44 and 50 <= c < 56


dem = path("fuji.asc")
write_ascii_grid(dem, fuji_heights(4), 120.0, hole)

# One piece: the whole DEM.
out = path("apertures.tif")
result = run(dem, "-o", out, "--sectors", "16", "--quiet")
check(result.returncode == 0 and result.stderr == "", "whole DEM: exit 0, nothing on stderr")
info = gdalinfo(out, "-stats")
check(info is not None, "the output is a raster GDAL reads")
if info:
    names = [b.get("description") for b in info["bands"]]
    check(names == ["BentNormal_X", "BentNormal_Y", "BentNormal_Z", "ApertureRadius",
                    "AmbientOcclusion"], "bands named after the arrays: " + str(names))
    check(info["geoTransform"] == [300000.0, 120.0, 0.0, 3900000.0 + 128 * 120.0, 0.0, -120.0],
          "the DEM's geotransform: " + str(info["geoTransform"]))
    radius = info["bands"][3]
    check(0.0 <= radius["minimum"] and radius["maximum"] <= math.pi / 2 + 1e-6,
          f"radii within [0, pi/2]: {radius['minimum']} .. {radius['maximum']}")
    valid = float(radius["metadata"][""]["STATISTICS_VALID_PERCENT"])
    check(abs(valid - 100 * (1 - 24 / 128 ** 2)) < 0.006,  # gdalinfo prints 2 decimals
          f"exactly the 24 no-data texels are NaN (no-data): {valid}% valid")

# Tiles of 5 x 5 and of 37 x 37 with a search radius: the same contents as one piece with it.
sums = []
for rows in ("5", "37", "100000"):
    name = path(f"tiled-{rows}.tif")
    result = run(dem, "-o", name, "--sectors", "16", "--max-distance", "1500", "--tile-size",
                 rows, "--quiet")
    check(result.returncode == 0, f"--max-distance 1500 --tile-size {rows}: exit 0")
    tiled = gdalinfo(name, "-checksum")
    sums.append([b.get("checksum") for b in tiled["bands"]] if tiled else None)
check(sums[0] is not None and sums[0] == sums[1] == sums[2],
      "tiles of 5 x 5, 37 x 37 and one piece: identical bands " + str(sums))
whole_sums = [b.get("checksum") for b in gdalinfo(out, "-checksum")["bands"]]
check(sums[0] != whole_sums, "a search radius of 1500 m changes the bands")
result = run(dem, "-o", path("unlimited.tif"), "--sectors", "16", "--max-distance", "none",
             "--quiet")
unlimited = gdalinfo(path("unlimited.tif"), "-checksum")
check(result.returncode == 0 and unlimited and
      [b.get("checksum") for b in unlimited["bands"]] == whole_sums,
      "--max-distance none: the bands of the run without a limit")

# --horizons: one band per sector after the apertures, named by azimuth, in [-pi/2, pi/2]; the
# other bands unchanged.
result = run(dem, "-o", path("horizons.tif"), "--sectors", "16", "--horizons", "--quiet")
horizons = gdalinfo(path("horizons.tif"), "-stats", "-checksum")
check(result.returncode == 0 and horizons is not None, "--horizons: exit 0")
if horizons:
    names = [b.get("description") for b in horizons["bands"]]
    check(names[5:] == [f"HorizonAngles_Az{22.5 * (k + 0.5):g}" for k in range(16)],
          "--horizons: bands HorizonAngles_Az11.25 ... Az348.75: " + str(names[5:]))
    check([b.get("checksum") for b in horizons["bands"][:5]] == whole_sums,
          "--horizons leaves the aperture bands as they were")
    check(all(-math.pi / 2 - 1e-3 <= b["minimum"] and b["maximum"] <= math.pi / 2 + 1e-3
              for b in horizons["bands"][5:]),  # gdalinfo prints 3 decimals
          "--horizons: angles within [-pi/2, pi/2]")

# --earth-curvature: every sector's horizon lower (15 km of ground: up to 18 m of fall), the
# summary says so; --earth-radius of the same value gives the same file.
result = run(dem, "-o", path("curved.tif"), "--sectors", "16", "--horizons",
             "--earth-curvature")
curved = gdalinfo(path("curved.tif"), "-stats", "-checksum")
check(result.returncode == 0 and curved is not None and "Earth radius 6371 km" in result.stdout,
      "--earth-curvature: exit 0, in the summary: " + result.stdout.strip())
if curved and horizons:
    def mean(band):  # the metadata's, in full (the JSON's "mean" has 3 decimals)
        return float(band["metadata"][""]["STATISTICS_MEAN"])
    lower = [mean(c) < mean(f) for c, f in zip(curved["bands"][5:], horizons["bands"][5:])]
    check(all(lower), f"--earth-curvature: every horizon band's mean lower {lower}")
result = run(dem, "-o", path("radius.tif"), "--sectors", "16", "--horizons", "--quiet",
             "--earth-radius", "6371000")
radius = gdalinfo(path("radius.tif"), "-checksum")
check(radius is not None and curved is not None and
      [b.get("checksum") for b in radius["bands"]] == [b.get("checksum") for b in curved["bands"]],
      "--earth-radius 6371000 == --earth-curvature")

# --outputs: the terrain products, in a fixed order, each with its unit; the apertures only when
# named; NaN at no-data; values in their ranges.
result = run(dem, "-o", path("products.tif"), "--sectors", "16", "--quiet",
             "--outputs", "openness,svf-cosine,svf")
products = gdalinfo(path("products.tif"), "-stats")
check(result.returncode == 0 and products is not None, "--outputs: exit 0")
if products:
    bands = [(b.get("description"), b.get("unit")) for b in products["bands"]]
    check(bands == [("SkyViewFactor", "1"), ("SkyViewFactorCosine", "1"),
                    ("PositiveOpenness", "degree"), ("NegativeOpenness", "degree")],
          "--outputs: bands and units " + str(bands))
    low = [b["minimum"] for b in products["bands"]]
    high = [b["maximum"] for b in products["bands"]]
    check(0.0 <= min(low[:2]) and max(high[:2]) <= 1.0, f"sky-view factors in [0, 1]: {low} {high}")
    check(0.0 < min(low[2:]) and max(high[2:]) < 180.0, f"openness in (0, 180): {low} {high}")
    valid = float(products["bands"][0]["metadata"][""]["STATISTICS_VALID_PERCENT"])
    check(abs(valid - 100 * (1 - 24 / 128 ** 2)) < 0.006, f"products NaN at no-data: {valid}%")

# --nodata-as: walls keep the hole NaN and take sky from around it; a fill leaves no hole.
open_mean = products["bands"][0]["mean"] if products else None
for mode, holes in (("wall", 24), ("fill", 0)):
    name = path(f"nodata-{mode}.tif")
    result = run(dem, "-o", name, "--sectors", "16", "--quiet", "--nodata-as", mode,
                 "--outputs", "svf")
    info = gdalinfo(name, "-stats")
    check(result.returncode == 0 and info is not None, f"--nodata-as {mode}: exit 0")
    if info and open_mean is not None:
        band = info["bands"][0]
        valid = float(band["metadata"][""]["STATISTICS_VALID_PERCENT"])
        check(abs(valid - 100 * (1 - holes / 128 ** 2)) < 0.006,
              f"--nodata-as {mode}: {holes} no-data texels left: {valid}% valid")
        if mode == "wall":
            check(band["mean"] < open_mean, f"walls take sky: SVF mean {band['mean']} < "
                  f"{open_mean}")

# Tiles give the products of one piece too, with no-data filled (the halo grows by the fill's
# reach) and as walls (of the DEM's highest height, read once).
for mode in ("fill", "wall"):
    sums = []
    for rows in ("37", "100000"):
        name = path(f"tiled-products-{mode}-{rows}.tif")
        result = run(dem, "-o", name, "--sectors", "16", "--max-distance", "1500",
                     "--tile-size", rows, "--quiet", "--nodata-as", mode,
                     "--outputs", "svf,svf-cosine,openness")
        tiled = gdalinfo(name, "-checksum")
        sums.append([b.get("checksum") for b in tiled["bands"]] if tiled else None)
    check(sums[0] is not None and sums[0] == sums[1],
          f"--nodata-as {mode}: tiles of 37 x 37 give the products of one piece " + str(sums))

# --cog: a cloud-optimised GeoTIFF with overviews, the same values, no temporary file left.
result = run(dem, "-o", path("cog.tif"), "--sectors", "16", "--quiet", "--cog", "--compress")
cog = gdalinfo(path("cog.tif"), "-checksum")
check(result.returncode == 0 and cog is not None and
      cog.get("metadata", {}).get("IMAGE_STRUCTURE", {}).get("LAYOUT") == "COG",
      "--cog: layout COG")
check(cog is not None and [b.get("checksum") for b in cog["bands"]] == whole_sums,
      "--cog: the bands of the plain file")
check(not any(n.endswith(".writing.tif") for n in os.listdir(WORK)), "--cog: no file left over")

# --grass-horizons: one raster per direction, named as r.horizon names them (step 22.5: one
# decimal), each direction's horizon in radians.
result = run(dem, "-o", path("grass.tif"), "--sectors", "16", "--quiet",
             "--grass-horizons", path("hz"))
names = sorted(n for n in os.listdir(WORK) if n.startswith("hz_"))
want = sorted(f"hz_{int(22.5 * k):03d}_{int(225 * k) % 10}.tif" for k in range(16))
check(result.returncode == 0 and names == want, "--grass-horizons: r.horizon's names " +
      str(names[:3]))
east = gdalinfo(path("hz_000_0.tif"), "-stats")
check(east is not None and len(east["bands"]) == 1 and east["bands"][0].get("unit") == "radian"
      and -math.pi / 2 - 1e-3 <= east["bands"][0]["minimum"], "--grass-horizons: one band, radians")

# Progress and summary on a normal run.
result = run(dem, "-o", path("summary.tif"), "--sectors", "8")
check(result.returncode == 0 and "128 x 128 texels" in result.stdout and "spacing 120" in
      result.stdout, "summary: " + result.stdout.strip())

# Bad input: exit 1 (data) or 2 (command line), one line on stderr.
truncated = path("truncated.tif")
with open(out, "rb") as f, open(truncated, "wb") as g:
    g.write(f.read()[:3000])
empty = path("all-no-data.asc")
write_ascii_grid(empty, fuji_heights(16), 480.0, lambda r, c: True)
cases = [
    ([path("missing.tif"), "-o", path("x.tif")], 1),
    ([empty, "-o", path("x.tif"), "--nodata-as", "wall"], 1),  # no height to build walls of
    ([truncated, "-o", path("x.tif")], 1),
    ([out, "-o", path("x.tif")], 1),  # five bands: not a DEM
    ([dem, "-o", path("no-such-folder/x.tif")], 1),
    ([dem], 2),
    ([dem, "-o", path("x.tif"), "--sectors", "2"], 2),
    ([dem, "-o", path("x.tif"), "--max-distance", "-5"], 2),
    ([dem, "-o", path("x.tif"), "--sectors"], 2),
    ([dem, "-o", path("x.tif"), "--frobnicate"], 2),
    ([dem, dem, "-o", path("x.tif")], 2),
    ([dem, "-o", path("x.tif"), "--outputs", "svf,shade"], 2),
    ([dem, "-o", path("x.tif"), "--outputs", ""], 2),
    ([dem, "-o", path("x.tif"), "--nodata-as", "lake"], 2),
    ([dem, "-o", path("x.tif"), "--nodata-as"], 2),
    ([dem, "-o", path("x.tif"), "--earth-radius", "-6371000"], 2),
    ([dem, "-o", path("x.tif"), "--earth-radius", "nan"], 2),
    ([dem, "-o", path("x.tif"), "--earth-radius"], 2),
    ([dem, "-o", path("x.tif"), "--grass-horizons", path("g"), "--sectors", "7"], 2),
    ([dem, "-o", path("x.tif"), "--grass-horizons", path("g"), "--sector-rotation", "3"], 2),
    ([dem, "-o", path("x.tif"), "--grass-horizons", path("no-such-folder/g")], 1),
]
for args, status in cases:
    result = run(*args)
    lines = result.stderr.strip().splitlines()
    check(result.returncode == status and len(lines) == 1,
          f"{' '.join(os.path.basename(a) for a in args)}: exit {result.returncode} "
          f"(want {status}), stderr {lines}")
check(not os.path.exists(path("x.tif")), "no output left behind by a failed run")

result = run("--help")
check(result.returncode == 0 and "usage: aperture-precompute" in result.stdout, "--help")

print(f"{len(failures)} failed" if failures else "all passed")
sys.exit(1 if failures else 0)
