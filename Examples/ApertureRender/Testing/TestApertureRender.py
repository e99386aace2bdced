"""aperture-render end to end.

    python3 TestApertureRender.py <aperture-render> <Testing/Data> <work folder>

Every input format it reads (meshes and height fields, made here from the bunny and the Fuji
tile; volumes, from a real head MR and copies of it in each volume format), the embedded default
scene, --mode all, --show apertures, the cache, the data it saves, an
HDR environment as the sky, and bad input: each bad case must end with exit status 1 or 2 and
exactly one line on stderr that says what is wrong, never a crash.
"""

import base64
import os
import re
import shutil
import struct
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPlane, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkClipPolyData, vtkDelaunay3D, vtkStripper
from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkSphereSource
from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLWriter
from vtkmodules.vtkIOImage import (vtkMetaImageWriter, vtkNIFTIImageReader, vtkNIFTIImageWriter,
                                   vtkPNGReader, vtkPNGWriter, vtkTIFFWriter)
from vtkmodules.vtkIOLegacy import vtkPolyDataWriter, vtkUnstructuredGridWriter
from vtkmodules.vtkIOPLY import vtkPLYWriter
from vtkmodules.vtkIOXML import (vtkXMLImageDataReader, vtkXMLImageDataWriter,
                                 vtkXMLPolyDataReader, vtkXMLPolyDataWriter)

from tool_run import run_tool

EXE, DATA, WORK = sys.argv[1:4]
os.makedirs(WORK, exist_ok=True)
FAST = ["--rays", "16", "--size", "200x150", "--max-grid", "96"]
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def path(name):
    return os.path.join(WORK, name)


def run(*args, env=None, before=None):
    # UTF-8 whatever the locale: the messages must be valid UTF-8, ASCII or not.
    return run_tool([EXE, *args], encoding="utf-8", env=env, before=before)


def read_png(name):
    reader = vtkPNGReader()
    reader.SetFileName(name)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())
    return pixels.reshape(h, w, -1)


def looks_rendered(name, width, height):
    """The picture has the size asked for, a surface on it, and light and shade on the surface."""
    if not os.path.exists(name):
        return False
    pixels = read_png(name)[:, :, :3].astype(float)
    background = pixels[0, 0]
    surface = np.abs(pixels - background).sum(axis=2) > 12
    lum = pixels.mean(axis=2)[surface]
    return (pixels.shape[:2] == (height, width) and surface.mean() > 0.1
            and lum.std() > 6 and 20 < lum.mean() < 250)


def expect_picture(what, args, width=200, height=150, picture=None, needles=(), before=None):
    picture = picture or path(what.replace(" ", "-") + ".png")
    result = run(*args, "-o", picture, before=before)
    good = result.returncode == 0 and ("wrote " + os.path.abspath(picture)) in result.stdout
    for needle in needles:
        good = good and needle in result.stdout
    check(good and looks_rendered(picture, width, height) and result.stderr == "",
          f"{what}: exit 0, a rendered {width}x{height} picture, nothing on stderr"
          + ("" if good else f" (exit {result.returncode}: {result.stdout!r} {result.stderr!r})"))
    return result


def expect_failure(what, args, status, words, env=None):
    result = run(*args, env=env)
    # Under `make sanitize` a request for petabytes also draws AddressSanitizer's "==pid==" warning.
    lines = [line for line in result.stderr.splitlines() if not line.startswith("==")]
    one = (len(lines) == 1 and lines[0].startswith("aperture-render: ") and words in lines[0])
    check(result.returncode == status and one,
          f"{what}: exit {status}, one line saying '{words}'"
          + ("" if result.returncode == status and one
             else f" (exit {result.returncode}, stderr {result.stderr!r})"))


def write_bytes(name, data):
    with open(path(name), "wb") as f:
        f.write(data)
    return path(name)


# Inputs, made from the project's data.
bunny = os.path.join(DATA, "stanford-bunny.obj")
fuji_png = os.path.join(DATA, "fuji-terrain-rgb.png")
obj = vtkOBJReader()
obj.SetFileName(bunny)
obj.Update()
mesh = obj.GetOutput()
ascii_ply = vtkPLYWriter()
ascii_ply.SetFileTypeToASCII()
binary_stl = vtkSTLWriter()
binary_stl.SetFileTypeToBinary()
for name, writer in (("bunny.ply", vtkPLYWriter()), ("bunny-ascii.ply", ascii_ply),
                     ("bunny.stl", vtkSTLWriter()), ("bunny-binary.stl", binary_stl),
                     ("bunny.vtp", vtkXMLPolyDataWriter()), ("bunny.vtk", vtkPolyDataWriter())):
    writer.SetInputData(mesh)
    writer.SetFileName(path(name))
    writer.Write()
cube = vtkCubeSource()
tetrahedra = vtkDelaunay3D()
tetrahedra.SetInputConnection(cube.GetOutputPort())
grid_writer = vtkUnstructuredGridWriter()
grid_writer.SetInputConnection(tetrahedra.GetOutputPort())
grid_writer.SetFileName(path("cube-tetrahedra.vtk"))
grid_writer.Write()

# Fuji heights in metres, every fourth sample: 128 x 128.
rgb = read_png(fuji_png).astype(float)
heights = (-10000.0 + (rgb[:, :, 0] * 65536 + rgb[:, :, 1] * 256 + rgb[:, :, 2]) * 0.1)[::4, ::4]


def image_of(values, vtk_array_type):
    image = vtkImageData()
    image.SetDimensions(values.shape[1], values.shape[0], 1)
    image.GetPointData().SetScalars(numpy_to_vtk(values.ravel(), deep=True,
                                                 array_type=vtk_array_type))
    return image


grey = np.clip(heights, 0, 65535).astype(np.uint16)
png_writer = vtkPNGWriter()
png_writer.SetInputData(image_of(grey, 5))  # VTK_UNSIGNED_SHORT
png_writer.SetFileName(path("fuji-grey16.png"))
png_writer.Write()
tiff_writer = vtkTIFFWriter()
tiff_writer.SetInputData(image_of(grey, 5))
tiff_writer.SetFileName(path("fuji.tif"))
tiff_writer.Write()
# SRTM: big-endian 16-bit, north row first (VTK's rows run south to north), with a few voids.
srtm = np.flipud(heights[:121, :121]).astype(">i2")
srtm[60, 60:64] = -32768
write_bytes("N35E138.hgt", srtm.tobytes())


def dem_text(columns, rows, values):
    """A USGS ASCII DEM (type A record, then one B record per column)."""
    spacing = 30.0
    corners = [(0.0, 0.0), (0.0, (rows - 1) * spacing),
               ((columns - 1) * spacing, (rows - 1) * spacing), ((columns - 1) * spacing, 0.0)]
    a = "fuji test DEM".ljust(144)
    a += "%6d%6d%6d%6d" % (1, 1, 1, 54)
    a += "%24.15E" % 0.0 * 15
    a += "%6d%6d%6d" % (2, 2, 4)
    a += "".join("%24.15E%24.15E" % c for c in corners)
    a += "%24.15E%24.15E" % (values.min(), values.max())
    a += "%24.15E" % 0.0 + "%6d" % 0
    a += "%12.6E%12.6E%12.6E" % (spacing, spacing, 1.0)
    a += "%6d%6d" % (1, columns)
    text = a.ljust(1024)
    for c in range(columns):
        text += "%6d%6d%6d%6d" % (1, c + 1, rows, 1)
        text += "%24.15E%24.15E%24.15E%24.15E%24.15E" % (
            c * spacing, 0.0, 0.0, values[:, c].min(), values[:, c].max())
        text += "".join("%6d" % v for v in values[:, c])
    return text


dem_values = np.round(heights[:100, :128]).astype(int)
write_bytes("fuji.dem", dem_text(128, 100, dem_values).encode())

# Good input: every format gives a picture.
expect_picture("default scene", ["--rays", "16", "--size", "320x200"], 320, 200,
               needles=("Mount Fuji",))
for name in ("bunny.ply", "bunny-ascii.ply", "bunny.stl", "bunny-binary.stl", "bunny.vtp",
             "bunny.vtk"):
    expect_picture(name, [path(name), *FAST], needles=("69451 polygons",))
expect_picture("bunny.obj", [bunny, *FAST])
expect_picture("legacy unstructured grid", [path("cube-tetrahedra.vtk"), *FAST, "--up", "+z",
                                            "--elevation", "30", "--azimuth", "150"])
expect_picture("Terrain-RGB tile", [fuji_png, *FAST], needles=("Terrain-RGB", "resampled"))
expect_picture("16-bit grey PNG", [path("fuji-grey16.png"), *FAST], needles=("16-bit grey",))
expect_picture("TIFF", [path("fuji.tif"), *FAST], needles=("TIFF",))
# Horizons (no --rays) on a grid larger than --max-grid: the whole grid's apertures shade a
# decimated mesh per texel; a GeoTIFF with a CRS and no-data through GDAL.
NO_RAYS = ["--size", "200x150", "--max-grid", "96"]
expect_picture("horizons per texel", [path("fuji.tif"), *NO_RAYS],
               needles=("horizon sectors", "16384 points"))
with open(path("fuji.asc"), "w") as f:
    f.write("ncols 64\nnrows 64\nxllcorner 300000\nyllcorner 3900000\ncellsize 50\n"
            "NODATA_value -9999\n")
    for r in range(64):
        f.write(" ".join("-9999" if (r, c) == (10, 10) else f"{500 + 300 * np.sin(r / 9.0) * np.cos(c / 7.0):.1f}"
                         for c in range(64)) + "\n")
subprocess.run(["gdal_translate", "-q", "-a_srs", "EPSG:32654", path("fuji.asc"),
                path("fuji-utm.tif")], check=True)
expect_picture("GeoTIFF", [path("fuji-utm.tif"), *NO_RAYS],
               needles=("GeoTIFF height field, 64 x 64 samples, 50 m apart",
                        "ground spacing: metres", "1 samples without data"))
expect_picture("ESRI ASCII grid", [path("fuji.asc"), *NO_RAYS],
               needles=("GDAL raster (.asc) height field", "50 m apart"))
expect_picture("SRTM tile", [path("N35E138.hgt"), *FAST],
               needles=("SRTM", "4 samples without data"))
expect_picture("USGS DEM", [path("fuji.dem"), *FAST],
               needles=("USGS DEM height field, 128 x 100",))
expect_picture("sphere light and two suns",
               [bunny, *FAST, "--sphere-light", "0,0.2,0.1,0.03,2", "--sun", "200,30",
                "--sun", "120,60,2", "--mode", "smoothstep"])
# A mesh adds the Visibility mask panel; under a small low light it differs from the exact cap's.
expect_picture("every mode", [path("bunny.vtp"), *FAST, "--mode", "all"], 1200, 150)
small_light = [path("bunny.vtp"), *FAST, "--sun", "200,30,2", "--sky", "0,0,0"]
expect_picture("mask", [*small_light, "--mode", "mask"])
expect_picture("mask exact", [*small_light, "--mode", "exact"])
changed = np.abs(read_png(path("mask.png")).astype(float)
                 - read_png(path("mask-exact.png")).astype(float)).max(axis=2) > 8
check(changed.mean() > 0.005, f"a small light: Visibility mask differs from the exact cap on "
      f"{changed.mean():.1%} of the picture")
# A height field adds the Horizon panel; under a low sun it differs from the exact cap's. A mesh
# asked for horizons warns once and shows the exact cap.
expect_picture("every mode of a height field", [path("fuji.asc"), *NO_RAYS, "--mode", "all"],
               1200, 150)
low_sun = [path("fuji.asc"), *NO_RAYS, "--sun", "250,8", "--sky", "0,0,0"]
expect_picture("horizon", [*low_sun, "--mode", "horizon"])
expect_picture("exact", [*low_sun, "--mode", "exact"])
changed = np.abs(read_png(path("horizon.png")).astype(float)
                 - read_png(path("exact.png")).astype(float)).max(axis=2) > 8
check(changed.mean() > 0.01, f"a low sun: Horizon differs from the exact cap on {changed.mean():.1%} "
      "of the picture")
result = run(path("bunny.vtp"), *FAST, "--mode", "horizon", "-o", path("mesh-horizon.png"))
run(path("bunny.vtp"), *FAST, "--mode", "exact", "-o", path("mesh-exact.png"))
said = result.stdout + result.stderr
check(result.returncode == 0 and said.count("Cannot shade with horizons") == 1 and "exact cap" in said and
      os.path.exists(path("mesh-horizon.png")) and
      (read_png(path("mesh-horizon.png")) == read_png(path("mesh-exact.png"))).all(),
      "a mesh in Horizon mode: one warning, the exact cap's picture " + repr(said[-300:]))
result = run(*low_sun, "--mode", "mask", "-o", path("field-mask.png"))
said = result.stdout + result.stderr
check(result.returncode == 0 and said.count("Cannot shade with visibility masks") == 1 and
      (read_png(path("field-mask.png")) == read_png(path("exact.png"))).all(),
      "a height field in mask mode: one warning, the exact cap's picture " + repr(said[-300:]))
expect_picture("aperture colours", [path("fuji.dem"), *FAST, "--show", "apertures"])

# The cache: computed, then read; other settings recompute it. Each run that writes the cache
# gets it back as it expects it before every try (a run is tried again when LeakSanitizer's tracer
# crashed at its exit, after it wrote the cache).
cache = path("bunny-cache.vtp")
written = path("bunny-cache-written.vtp")


def no_cache():
    if os.path.exists(cache):
        os.remove(cache)


expect_picture("cache written", [bunny, *FAST, "--cache", cache], needles=("cached in",),
               before=no_cache)
if os.path.exists(cache):
    shutil.copyfile(cache, written)
expect_picture("cache read", [bunny, *FAST, "--cache", cache], needles=("read from the cache",))
expect_picture("cache for other rays", [bunny, "--size", "200x150", "--rays", "8",
                                        "--cache", cache], needles=("recomputing",),
               before=lambda: os.path.exists(written) and shutil.copyfile(written, cache))
expect_picture("broken cache", [bunny, *FAST, "--cache", path("broken-cache.vtp")],
               needles=("recomputing",),
               before=lambda: write_bytes("broken-cache.vtp", b"<VTKFile type='PolyData'> broken"))

# The data it saves keep the input's points (and cells) and add the aperture arrays; creases
# split the points they run through (--crease 180: none).
saved = path("bunny-saved.vtp")
expect_picture("save data", [bunny, *FAST, "--crease", "180", "--save-data", saved])
reader = vtkXMLPolyDataReader()
reader.SetFileName(saved)
reader.Update()
point_data = reader.GetOutput().GetPointData()
check(reader.GetOutput().GetNumberOfPoints() == 35947
      and reader.GetOutput().GetNumberOfPolys() == 69451
      and all(point_data.GetArray(a) for a in ("BentNormal", "ApertureRadius", "AmbientOcclusion")),
      "saved .vtp: 35947 points with BentNormal, ApertureRadius, AmbientOcclusion")
grid = path("fuji-saved.vti")
expect_picture("save height field", [path("fuji.tif"), *FAST, "--save-data", grid])
image_reader = vtkXMLImageDataReader()
image_reader.SetFileName(grid)
image_reader.Update()
check(image_reader.GetOutput().GetDimensions() == (96, 96, 1)
      and image_reader.GetOutput().GetPointData().GetArray("ApertureRadius") is not None,
      "saved .vti: the 96 x 96 grid with its apertures")

# NaN coordinates: the precompute warns and closes those caps; the picture is still made.
with open(bunny) as f:
    lines = f.read().splitlines()
first_vertex = next(i for i, line in enumerate(lines) if line.startswith("v "))
lines[first_vertex] = "v nan nan nan"
write_bytes("bunny-nan.obj", "\n".join(lines).encode())
expect_picture("NaN point", [path("bunny-nan.obj"), *FAST])

# An HDR environment as the sky: turning it changes the picture, -1 stop halves the light.
forest = os.path.join(DATA, "env", "forest.exr")
expect_picture("environment sky on a mesh", [bunny, *FAST, "--env", forest])
expect_picture("environment sky on a height field",
               [fuji_png, *FAST, "--env", os.path.join(DATA, "env", "sunrise.exr")])
env_pictures = {}
for name, extra in (("env-0", []), ("env-180", ["--env-azimuth", "180"]),
                    ("env-dark", ["--env-exposure", "-1"]), ("env-bright", ["--env-exposure", "0"])):
    env_pictures[name] = path(name + ".png")
    run(bunny, *FAST, "--env", forest, *extra, "-o", env_pictures[name])
lit = {name: read_png(p)[:, :, :3].astype(float) for name, p in env_pictures.items()}
mask = np.abs(lit["env-0"] - lit["env-0"][0, 0]).sum(axis=2) > 12
turned = np.abs(lit["env-180"] - lit["env-0"])[mask].mean()
ratio = lit["env-dark"][mask].mean() / lit["env-bright"][mask].mean()
check(turned > 4, f"--env-azimuth 180 changes the shading (mean {turned:.1f} levels)")
check(0.35 < ratio < 0.65, f"--env-exposure -1 against 0: {ratio:.2f} of the light (linear 0.5)")

# Real files. A PLY scan stored as triangle strips (vtkPLYReader reads none): drawn, and the same
# apertures as the triangles.
stripper = vtkStripper()
stripper.SetInputData(mesh)
stripper.Update()
strips = stripper.GetOutput()
strip_ids = vtk_to_numpy(strips.GetStrips().GetConnectivityArray())
strip_offsets = vtk_to_numpy(strips.GetStrips().GetOffsetsArray())
restarted = []
for a, b in zip(strip_offsets[:-1], strip_offsets[1:]):
    restarted.extend(strip_ids[a:b].tolist() + [-1])
xyz = vtk_to_numpy(strips.GetPoints().GetData()).astype("<f4")


def strip_ply(name, binary):
    header = ("ply\nformat %s 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
              "property float z\nelement tristrips 1\nproperty list int int vertex_indices\n"
              "end_header\n") % ("binary_little_endian" if binary else "ascii", len(xyz))
    if binary:
        body = xyz.tobytes() + struct.pack("<i", len(restarted)) + \
            np.array(restarted, dtype="<i4").tobytes()
    else:
        body = ("\n".join(" ".join(repr(float(c)) for c in p) for p in xyz) + "\n" +
                " ".join(str(v) for v in [len(restarted)] + restarted) + "\n").encode()
    return write_bytes(name, header.encode() + body)


triangles_saved = path("bunny-triangles.vtp")
run(bunny, *FAST, "--save-data", triangles_saved, "-o", path("x.png"))
for name, binary in (("bunny-strips.ply", True), ("bunny-strips-ascii.ply", False)):
    saved_strips = path(name + ".vtp")
    expect_picture(name, [strip_ply(name, binary), *FAST, "--save-data", saved_strips],
                   needles=("triangle strips",))
    # Points split at creases come in another order: matched by position and normal.
    apertures = []
    for saved_file in (triangles_saved, saved_strips):
        r = vtkXMLPolyDataReader()
        r.SetFileName(saved_file)
        r.Update()
        pd = r.GetOutput()
        keys = np.hstack([vtk_to_numpy(pd.GetPoints().GetData()),
                          np.round(vtk_to_numpy(pd.GetPointData().GetNormals()), 5)])
        radius = vtk_to_numpy(pd.GetPointData().GetArray("ApertureRadius"))
        apertures.append({tuple(k): v for k, v in zip(keys.tolist(), radius)})
    same = (apertures[0].keys() == apertures[1].keys()
            and max(abs(apertures[0][k] - apertures[1][k]) for k in apertures[0]) < 1e-6)
    check(same, f"{name}: the apertures of the same triangles, point for point")

# Points that are not finite: said in one line; the rest is drawn.
polydata_reader = vtkXMLPolyDataReader()
polydata_reader.SetFileName(path("bunny.vtp"))
polydata_reader.Update()
for value, name in ((float("inf"), "bunny-inf.vtp"), (float("nan"), "bunny-nan.vtp")):
    broken_mesh = vtkPolyData()
    broken_mesh.DeepCopy(polydata_reader.GetOutput())
    broken_mesh.GetPoints().SetPoint(0, value, 0.0, 0.0)
    vtp_writer = vtkXMLPolyDataWriter()
    vtp_writer.SetInputData(broken_mesh)
    vtp_writer.SetFileName(path(name))
    vtp_writer.Write()
    expect_picture(name, [path(name), *FAST], needles=("1 point(s) are not finite",))

# Bad point ids: a clear line, exit 1, whatever reader took the file.
expect_failure("OBJ face past the points",
               [write_bytes("bad-face.obj", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n"),
                "-o", path("x.png")], 1, "'f' names v '99', but there are 3")
bad_ply = ("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
           "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
           "0 0 0\n1 0 0\n0 1 0\n3 0 1 500000\n")
expect_failure("PLY face past the points", [write_bytes("bad-face.ply", bad_ply.encode()),
                                            "-o", path("x.png")], 1, "uses vertex 500000")
bad_binary = (b"ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
              b"property float y\nproperty float z\nelement face 1\n"
              b"property list uchar int vertex_indices\nend_header\n" +
              np.zeros(9, dtype="<f4").tobytes() + struct.pack("<Biii", 3, 0, -5, 1))
expect_failure("binary PLY with a negative index",
               [write_bytes("bad-binary.ply", bad_binary), "-o", path("x.png")], 1,
               "uses vertex -5")
legacy = (b"# vtk DataFile Version 3.0\nbad\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n"
          b"0 0 0 1 0 0 0 1 0\nPOLYGONS 1 4\n3 0 1 500000\n")
expect_failure("legacy polygon past the points", [write_bytes("bad-polygon.vtk", legacy),
                                                  "-o", path("x.png")], 1, "uses point id 500000")
grid_text = (b"# vtk DataFile Version 3.0\nbad\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 float\n"
             b"0 0 0 1 0 0 0 1 0 0 0 1\nCELLS 1 5\n4 0 1 2 400000\nCELL_TYPES 1\n10\n")
expect_failure("legacy grid cell past the points", [write_bytes("bad-cell.vtk", grid_text),
                                                    "-o", path("x.png")], 1, "uses point id 400000")
bad_vtp = vtkPolyData()
bad_vtp.DeepCopy(polydata_reader.GetOutput())
bad_vtp.GetCellData().Initialize()
bad_vtp.GetPolys().InsertNextCell(3, [0, 1, 4000000000])
vtp_writer = vtkXMLPolyDataWriter()
vtp_writer.SetInputData(bad_vtp)
vtp_writer.SetFileName(path("bad-ids.vtp"))
vtp_writer.Write()
expect_failure("VTP polygon past the points", [path("bad-ids.vtp"), "-o", path("x.png")], 1,
               "uses point id 4000000000")

# A box standing on a ground of two triangles: refined automatically for its contact shadows.
box_obj = ["v -2 -2 0", "v 2 -2 0", "v 2 2 0", "v -2 2 0", "f 1 2 3", "f 1 3 4"]
corners = [(x, y, z) for z in (0, 1) for y in (-0.5, 0.5) for x in (-0.5, 0.5)]
box_obj += ["v %g %g %g" % c for c in corners]
for face in ((1, 3, 4, 2), (5, 6, 8, 7), (1, 2, 6, 5), (3, 7, 8, 4), (1, 5, 7, 3), (2, 4, 8, 6)):
    box_obj.append("f " + " ".join(str(4 + i) for i in face))
box_file = write_bytes("box-on-ground.obj", ("\n".join(box_obj) + "\n").encode())
box_saved = path("box-on-ground.vtp")
expect_picture("box on a ground", [box_file, *FAST, "--up", "+z", "--save-data", box_saved],
               needles=("refined to edges of at most",))
r = vtkXMLPolyDataReader()
r.SetFileName(box_saved)
r.Update()
box_points = vtk_to_numpy(r.GetOutput().GetPoints().GetData())
box_ao = vtk_to_numpy(r.GetOutput().GetPointData().GetArray("AmbientOcclusion"))
ground = np.abs(box_points[:, 2]) < 1e-9
out = np.max(np.abs(box_points[:, :2]), axis=1)
by_wall = ground & (out > 0.5) & (out < 0.6)
far_away = ground & (out > 1.5)
check(by_wall.sum() > 20 and box_ao[by_wall].mean() < box_ao[far_away].mean() - 0.1,
      f"the ground by the walls is darker ({box_ao[by_wall].mean():.2f}) than away "
      f"({box_ao[far_away].mean():.2f})")
result = run(box_file, *FAST, "--up", "+z", "--max-edge", "none", "-o", path("x.png"))
check(result.returncode == 0 and "refined" not in result.stdout, "--max-edge none: no refinement")

# Auto exposure keeps highlights under a low sun (sunrise.exr): few pixels at full white.
sunrise = os.path.join(DATA, "env", "sunrise.exr")
exposed = path("bunny-sunrise.png")
expect_picture("low sun", [bunny, *FAST, "--env", sunrise], picture=exposed)
pixels = read_png(exposed)[:, :, :3].astype(float)
on_object = np.abs(pixels - pixels[0, 0]).sum(axis=2) > 12
saturated = (pixels.max(axis=2) >= 254)[on_object].mean()
check(saturated <= 0.05, f"auto exposure under a low sun: {100 * saturated:.1f}% of the "
      "object saturated (at most 5%)")

# The default view shows a mesh's broad side, whichever axis it stands on: a slab 2 wide, 0.6
# deep and 2 high on a base, stored z up and y up.
def slab(up_axis):
    source = vtkCubeSource()
    source.SetBounds(-1, 1, -0.3, 0.3, 0, 2)
    source.Update()
    pd = vtkPolyData()
    pd.DeepCopy(source.GetOutput())
    xyz = vtk_to_numpy(pd.GetPoints().GetData())
    if up_axis == "y":
        xyz[:, [1, 2]] = xyz[:, [2, 1]] * [1, -1]
    pd.GetPoints().Modified()
    pd.GetPointData().Initialize()
    vtp = vtkXMLPolyDataWriter()
    vtp.SetInputData(pd)
    vtp.SetFileName(path("slab-%s.vtp" % up_axis))
    vtp.Write()
    return path("slab-%s.vtp" % up_axis)


def silhouette(args):
    picture = path("view.png")
    run(*args, "--rays", "16", "--size", "200x150", "-o", picture)
    pixels = read_png(picture)[:, :, :3].astype(float)
    return (np.abs(pixels - pixels[0, 0]).sum(axis=2) > 12).mean()


for up_axis in ("z", "y"):
    name = slab(up_axis)
    default = silhouette([name])
    top = silhouette([name, "--up", "+" + up_axis, "--elevation", "89"])
    narrow = silhouette([name, "--up", "+" + up_axis, "--azimuth", "90"])
    check(default > 1.3 * max(top, narrow),
          f"a slab stored {up_axis} up is seen from its broad side by default "
          f"({default:.3f} of the picture, top {top:.3f}, narrow side {narrow:.3f})")

# Bad input: one line, non-zero exit.
expect_failure("missing file", [path("no-such.obj"), "-o", path("x.png")], 1, "does not exist")
os.makedirs(path("empty-folder"), exist_ok=True)
expect_failure("a folder without DICOM", [path("empty-folder"), "-o", path("x.png")], 1,
               "no DICOM image series")
expect_failure("empty file", [write_bytes("empty.obj", b""), "-o", path("x.png")], 1, "is empty")
expect_failure("unknown format", [write_bytes("model.xyz", b"1 2 3"), "-o", path("x.png")], 1,
               "unknown format")
expect_failure("text that is not a mesh", [write_bytes("noise.obj", b"hello world\n"),
                                           "-o", path("x.png")], 1, "no polygons")
expect_failure("points and lines only", [write_bytes("lines.obj", b"v 0 0 0\nv 1 0 0\nl 1 2\n"),
                                         "-o", path("x.png")], 1, "no polygons")
expect_failure("broken PLY", [write_bytes("broken.ply", b"ply\nformat nonsense\n"),
                              "-o", path("x.png")], 1, "PLY")

def truncated(name, fraction=2):
    """A copy of the file `name` cut to 1/fraction of its length."""
    data = open(path(name), "rb").read()
    return write_bytes("truncated-" + name, data[:len(data) // fraction])


for name in ("bunny.ply", "bunny-ascii.ply", "bunny-binary.stl", "bunny.vtp", "bunny.vtk"):
    for fraction in (2, 7):
        expect_failure(f"{name} cut to 1/{fraction}",
                       [truncated(name, fraction), "-o", path("x.png")], 1, "truncated-" + name)
expect_failure("broken STL", [write_bytes("broken.stl", b"solid x\n facet nonsense\n"),
                              "-o", path("x.png")], 1, "broken.stl")
# vtkPLY gives up on a format line that is not "format <type> <version>" and leaks the elements
# it read before it: refused first.
late_format = (b"ply\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
               b"format ascii 1.0 extra\nelement face 1\nproperty list uchar int vertex_indices\n"
               b"end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
expect_failure("PLY with a bad format line", [write_bytes("late-format.ply", late_format),
                                              "-o", path("x.png")], 1, "PLY format line")
expect_failure("broken VTP", [write_bytes("broken.vtp", b"not xml at all"),
                              "-o", path("x.png")], 1, "not a VTK XML polydata file")
# Counts no file of that size can hold (the reader would allocate them before reading).
bunny_vtp = open(path("bunny.vtp"), "rb").read()
huge = (("points", b'NumberOfPoints="35947"', b'NumberOfPoints="1152921504606846976"'),
        ("components", b'Name="GroupIds"', b'Name="GroupIds" NumberOfComponents="4000000000"'),
        ("polygons", b'NumberOfPolys="69451"', b'NumberOfPolys="9e18"'))
for what, old, new in huge:
    check(old in bunny_vtp, f"bunny.vtp says {old!r}")
    expect_failure(f"VTP announcing too many {what}",
                   [write_bytes("huge.vtp", bunny_vtp.replace(old, new, 1)), "-o", path("x.png")],
                   1, "its counts announce")
# An offsets array (data, not a count) that asks the reader for petabytes.
huge_offsets = (b'<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1">\n<PolyData>\n'
                b'<Piece NumberOfPoints="3" NumberOfPolys="1">\n<Points>\n'
                b'<DataArray type="Float32" NumberOfComponents="3" format="ascii">'
                b"0 0 0 1 0 0 0 1 0</DataArray>\n</Points>\n<Polys>\n"
                b'<DataArray type="Int64" Name="connectivity" format="ascii">0 1 2</DataArray>\n'
                b'<DataArray type="Int64" Name="offsets" format="ascii">1000000000000000'
                b"</DataArray>\n</Polys>\n</Piece>\n</PolyData>\n</VTKFile>\n")
expect_failure("VTP whose offsets ask for petabytes",
               [write_bytes("huge-offsets.vtp", huge_offsets), "-o", path("x.png")], 1,
               "more memory than there is")
# Two cell arrays of one name: the reader would read through the one it dropped.
same_names = huge_offsets.replace(b"1000000000000000", b"3").replace(
    b"<Polys>", b'<CellData>\n<DataArray type="Int32" Name="Face" format="ascii">0</DataArray>\n'
    b'<DataArray type="Int32" Name="Face" format="ascii">0</DataArray>\n</CellData>\n<Polys>')
expect_failure("VTP with two cell arrays of one name",
               [write_bytes("same-names.vtp", same_names), "-o", path("x.png")], 1,
               "two arrays of one group")
expect_failure("broken legacy VTK", [write_bytes("broken.vtk", b"garbage\n"),
                                     "-o", path("x.png")], 1, "not a VTK legacy file")
fuji_bytes = open(fuji_png, "rb").read()
expect_failure("truncated PNG", [write_bytes("truncated.png", fuji_bytes[:len(fuji_bytes) // 2]),
                                 "-o", path("x.png")], 1, "truncated")
expect_failure("PNG that is not one", [write_bytes("fake.png", b"GIF89a" + bytes(100)),
                                       "-o", path("x.png")], 1, "not a PNG file")
expect_failure("TIFF that is not one", [write_bytes("fake.tif", b"II*\0garbage"),
                                        "-o", path("x.png")], 1, "fake.tif")
tiff_bytes = open(path("fuji.tif"), "rb").read()
expect_failure("truncated TIFF", [write_bytes("truncated.tif", tiff_bytes[:len(tiff_bytes) // 3]),
                                  "-o", path("x.png")], 1, "truncated.tif")
expect_failure("SRTM of the wrong size", [write_bytes("N10E010.hgt", bytes(1000)),
                                          "-o", path("x.png")], 1, "not an SRTM tile")
expect_failure("DEM that is not one", [write_bytes("fake.dem", b"x" * 2000),
                                       "-o", path("x.png")], 1, "not a USGS DEM")
expect_failure("narrow DEM", [write_bytes("narrow.dem", dem_text(20, 10, dem_values[:10, :20])
                                          .encode()), "-o", path("x.png")], 1, "100")
dem_full = open(path("fuji.dem"), "rb").read()
expect_failure("truncated DEM", [write_bytes("truncated.dem", dem_full[:len(dem_full) // 2]),
                                 "-o", path("x.png")], 1, "truncated")
expect_failure("missing environment", [bunny, *FAST, "--env", path("none.exr"),
                                      "-o", path("x.png")], 1, "does not exist")
forest_bytes = open(os.path.join(DATA, "env", "forest.exr"), "rb").read()
for fraction in (2, 50):
    expect_failure(f"environment cut to 1/{fraction}",
                   [bunny, *FAST, "-o", path("x.png"), "--env",
                    write_bytes(f"cut-{fraction}.exr", forest_bytes[:len(forest_bytes) // fraction])],
                   1, "cannot be used")
expect_failure("environment that is not an EXR",
               [bunny, *FAST, "-o", path("x.png"), "--env", write_bytes("fake.exr", b"P6\n1 1\n")],
               1, "not an OpenEXR file")
expect_failure("no X display", [bunny, *FAST, "-o", path("x.png")], 1, "X display",
               env={k: v for k, v in os.environ.items() if k != "DISPLAY"})

# The default sun follows the view. Half of a bumpy ellipsoid, open on the y-z plane, has no base
# (so +y is up) and is thinnest along x: its outside faces east or west, and the camera looks
# from there. Under the default sun the side it sees must be lit: at least half as bright as
# under a headlight (a sun at the eye) and brighter than under the sky alone (--sun none).
def open_shell(facing, name):
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(72)
    sphere.SetPhiResolution(48)
    sphere.Update()
    shell = sphere.GetOutput()
    p = vtk_to_numpy(shell.GetPoints().GetData()).astype(float)
    bump = 1.0 + 0.1 * np.sin(7 * np.arctan2(p[:, 1], p[:, 2])) * np.sin(9 * p[:, 1])
    shell.GetPoints().SetData(numpy_to_vtk(p * bump[:, None] * [0.8, 2.0, 2.4], deep=True))
    plane = vtkPlane()
    plane.SetNormal(facing, 0.0, 0.0)
    clip = vtkClipPolyData()
    clip.SetInputData(shell)
    clip.SetClipFunction(plane)
    writer = vtkXMLPolyDataWriter()
    writer.SetInputConnection(clip.GetOutputPort())
    writer.SetFileName(path(name))
    writer.Write()
    return path(name)


def surface_brightness(pictures):
    """Mean luminance, in each picture, over the pixels where the first shows the surface."""
    images = [read_png(p)[:, :, :3].astype(float) for p in pictures]
    surface = np.abs(images[0] - images[0][0, 0]).sum(axis=2) > 12
    return surface.mean(), [image.mean(axis=2)[surface].mean() for image in images]


for facing, compass in ((1.0, "E"), (-1.0, "W")):
    shell = open_shell(facing, f"shell-{compass}.vtp")
    result = run(shell, *FAST, "-o", path(f"sun-default-{compass}.png"))
    view = re.search(r"view: eye from the (\w+) \(azimuth ([-\d.e]+), ([-\d.e]+) deg up\)",
                     result.stdout)
    check(result.returncode == 0 and view is not None and view.group(1) == compass,
          f"shell facing {compass}: the default view looks from the {compass} "
          f"({view.group(0) if view else result.stdout + result.stderr})")
    if not view:
        continue
    eye = f"{view.group(2)},{view.group(3)}"
    for light, extra in (("headlight", ["--sun", eye]), ("sky", ["--sun", "none"])):
        run(shell, *FAST, *extra, "-o", path(f"sun-{light}-{compass}.png"))
    shown, (headlight, default, sky) = surface_brightness(
        [path(f"sun-{light}-{compass}.png") for light in ("headlight", "default", "sky")])
    check(shown > 0.1 and default >= 0.5 * headlight and default > 1.1 * sky,
          f"shell facing {compass}: the side seen is lit by the default sun (mean {default:.1f} "
          f">= half the headlight's {headlight:.1f}, > the sky's {sky:.1f}; surface "
          f"{100 * shown:.0f}% of the picture)")

# Hostile bytes: a message that quotes a file (or its name) must be safe to print as it is.
def expect_safe_failure(what, args, status, escaped, env=None):
    """Refused with one line on stderr that is valid UTF-8, holds no byte below 0x20 but its
    final newline, is at most 400 characters long and shows `escaped` (the quoted bytes, escaped)."""
    result = run_tool([EXE, *args], env=env)
    err = result.stderr.replace(b"\r\n", b"\n")
    lines = [line for line in err.split(b"\n")[:-1] if not line.startswith(b"==")]
    try:
        text = lines[0].decode("utf-8") if len(lines) == 1 else ""
    except UnicodeDecodeError:
        text = ""
    safe = (len(lines) == 1 and err.endswith(b"\n") and text.startswith("aperture-render: ")
            and all(b >= 0x20 for b in lines[0]) and len(text) <= 400 and escaped in text)
    check(result.returncode == status and safe,
          f"{what}: exit {status}, one safe line showing {escaped!r}"
          + ("" if result.returncode == status and safe
             else f" (exit {result.returncode}, stderr {result.stderr[:600]!r})"))


bunny_obj = open(bunny, "rb").read()
faces = bunny_obj.index(b"\nf ") + 1
for what, line, escaped in (
        ("an ESC sequence", b"f 1 2 \x1b]0;owned\x07\x1b[2J\n", r"\x1b]0;owned\x07"),
        ("invalid UTF-8", b"f 1 \xff\xfe\xc0\xaf 3\n", r"\xff\xfe\xc0\xaf"),
        ("a NUL", b"f 1 \x00\x1b[2J 3\n", "hostile.obj"),
        ("a right-to-left override", b"f 1 2 3\xe2\x80\xae/cod.exe\n", r"\u202e"),
        ("a 1 MB line", b"f 1 2 3 " + b"\x1b[31m" * 200000 + b"\n", r"\x1b[31m")):
    expect_safe_failure(f"OBJ with {what}",
                        [write_bytes("hostile.obj", bunny_obj[:faces] + line + bunny_obj[faces:]),
                         "-o", path("x.png")], 1, escaped)
expect_safe_failure("PLY with an ESC in its format word",
                    [write_bytes("hostile.ply", late_format.replace(
                        b"format ascii 1.0 extra\n", b"").replace(
                        b"ply\n", b"ply\nformat \x1b[8mascii 1.0\n")), "-o", path("x.png")],
                    1, "hostile.ply")
hostile_name = "evil\x1b[2J\nname\x07"
hostile_escaped = r"evil\x1b[2J\x0aname\x07"
expect_safe_failure("a file name holding ESC, a newline and BEL",
                    [write_bytes(hostile_name + ".tif", b"II*\0garbage"), "-o", path("x.png")],
                    1, hostile_escaped)
expect_safe_failure("a missing environment of such a name",
                    [bunny, *FAST, "--env", path(hostile_name + ".exr"), "-o", path("x.png")],
                    1, hostile_escaped)
expect_safe_failure("a DISPLAY holding ESC and BEL", [bunny, *FAST, "-o", path("x.png")], 1,
                    r"\x1b]0;owned\x07:99",
                    env={**os.environ, "DISPLAY": "\x1b]0;owned\x07:99"})
expect_safe_failure("an unknown option holding ESC", ["--\x1b[2Jfrobnicate", "-o", path("x.png")],
                    2, r"--\x1b[2Jfrobnicate")

# Malformed command lines: exit 2.
for args, words in (
        (["--sun", "30,abc"], "--sun '30,abc'"),
        (["--sun", "30"], "AZIMUTH,ELEVATION"),
        (["--sun", "30,100"], "elevation -90 to 90"),
        (["--sun", "nan,30"], "--sun 'nan,30'"),
        (["--sphere-light", "1,2,3"], "X,Y,Z,RADIUS"),
        (["--sphere-light", "1,2,3,-1"], "radius > 0"),
        (["--size", "100xfoo"], "WIDTHxHEIGHT"),
        (["--size", "10x10"], "16 to 8192"),
        (["--rays", "-5"], "1 to 65536"),
        (["--rays", "2.5"], "whole number"),
        (["--zoom", "0"], "positive"),
        (["--sky", "1,2"], "R,G,B"),
        (["--mode", "fancy"], "not one of"),
        (["--show", "everything"], "shading or apertures"),
        (["--up", "w"], "+x"),
        (["--frobnicate"], "unknown option"),
        ([bunny, fuji_png], "one input at a time"),
        (["-o", path("x.jpg")], "must end in .png"),
        (["-o", path("no/such/folder/x.png")], "does not exist"),
        (["--cache", path("x.txt")], "must end in"),
        (["--cache", path("fuji.vtp")], "must end in .vti"),
        (["--save-data", path("bunny.vti"), bunny], ".vtp"),
        (["--env", path("sky.hdr")], "not an OpenEXR file"),
        (["--env-azimuth", "90"], "give one with --env"),
        (["--env", path("sky.exr"), "--env-azimuth", "east"], "number of degrees"),
        (["--env", path("sky.exr"), "--env-exposure", "bright"], "'auto' or a number"),
        (["--crease", "200"], "0 to 180"),
        (["--max-edge", "-1"], "auto, none or a positive length"),
        (["--sun"], "needs a value")):
    if args[-1] != "--sun" and "-o" not in args:
        args = [*args, "-o", path("x.png")]
    name = " ".join(os.path.basename(a) if os.sep in a else a for a in args)
    expect_failure("command line " + name, args, 2, words)
expect_failure("neither -o nor --interactive", [bunny], 2, "--interactive")

# Volumes: a real head MR (NIfTI) and the same voxels as .vti, .mha and .nrrd (a detached header
# and raw data, as NRRD files often are); every volume mode; --iso through the mesh pipeline.
mr = os.path.join(DATA, "volumes", "head-t1-mr.nii.gz")
nifti = vtkNIFTIImageReader()
nifti.SetFileName(mr)
nifti.Update()
volume = nifti.GetOutput()
dims = volume.GetDimensions()
described = f"a volume of {dims[0]} x {dims[1]} x {dims[2]} voxels"
expect_picture("volume from NIfTI", [mr, "--size", "200x150"], needles=(described,))
for name, writer in (("head.vti", vtkXMLImageDataWriter()), ("head.mha", vtkMetaImageWriter())):
    writer.SetInputData(volume)
    writer.SetFileName(path(name))
    writer.Write()
    expect_picture("volume from " + name, [path(name), "--size", "200x150"], needles=(described,))
raw = vtk_to_numpy(volume.GetPointData().GetScalars())
write_bytes("head.raw", raw.astype("<i2").tobytes())
spacing = volume.GetSpacing()
write_bytes("head.nhdr", (
    "NRRD0004\ntype: short\ndimension: 3\n"
    f"sizes: {dims[0]} {dims[1]} {dims[2]}\nspacings: {spacing[0]} {spacing[1]} {spacing[2]}\n"
    "encoding: raw\nendian: little\ndata file: head.raw\n\n").encode())
expect_picture("volume from NRRD", [path("head.nhdr"), "--size", "200x150"], needles=(described,))
modes = expect_picture("volume, every mode", [mr, "--size", "200x150", "--mode", "all",
                                              "--volume", "mr"], width=600)
if os.path.exists(path("volume,-every-mode.png")):
    panels = read_png(path("volume,-every-mode.png"))[:, :, :3].astype(float)
    standard, exact = panels[:, :200], panels[:, 200:400]
    check(np.abs(standard - exact).mean() > 2.0, "volume: aperture shading is not VTK's")
# An HDR sky on a volume: the environment alone (no default sun) draws another picture than the
# uniform sky alone, and turning it changes the picture. (Sky-lit volumes are dim and even, so
# these are not held to looks_rendered.)
sunrise = os.path.join(DATA, "env", "sunrise.exr")
skies = {}
for name, extra in (("uniform", ["--sun", "none"]), ("hdr", ["--env", sunrise]),
                    ("turned", ["--env", sunrise, "--env-azimuth", "120"])):
    picture = path(f"volume-sky-{name}.png")
    result = run(mr, "--size", "200x150", *extra, "-o", picture)
    drawn = result.returncode == 0 and result.stderr == "" and os.path.exists(picture)
    check(drawn, f"volume, {name} sky: exit 0, a picture, nothing on stderr"
          + ("" if drawn else f" (exit {result.returncode}: {result.stderr!r})"))
    if drawn:
        skies[name] = read_png(picture)[:, :, :3].astype(float)
if len(skies) == 3:
    check(np.abs(skies["hdr"] - skies["uniform"]).mean() > 1.0 and
          np.abs(skies["turned"] - skies["hdr"]).mean() > 0.2,
          f"volume: the HDR sky differs from the uniform one "
          f"({np.abs(skies['hdr'] - skies['uniform']).mean():.2f} levels) and turns "
          f"({np.abs(skies['turned'] - skies['hdr']).mean():.2f})")
# DICOM: the MR written as a CT series of one file a slice by vtk-dicom, read from its folder.
from vtkdicom import vtkDICOMCTGenerator, vtkDICOMWriter  # noqa: E402 (python3-vtk-dicom)
series = path("dicom-series")
if os.path.isdir(series):
    for old in os.listdir(series):
        os.remove(os.path.join(series, old))
os.makedirs(series, exist_ok=True)
dicom = vtkDICOMWriter()
generator = vtkDICOMCTGenerator()
dicom.SetGenerator(generator)
dicom.SetInputData(volume)
dicom.SetFilePrefix(series)
dicom.SetFilePattern("%s/IM-%04d.dcm")
dicom.SetFileDimensionality(2)
dicom.Write()
expect_picture("volume from a DICOM folder", [series, "--size", "200x150"], needles=(described,))
os.remove(os.path.join(series, "IM-0010.dcm"))
expect_failure("DICOM with a missing slice", [series, "-o", path("x.png")], 1,
               "slices are missing")
expect_picture("volume isosurface", [mr, "--iso", "60", *FAST], needles=("--iso",))
flat = vtkImageData()
flat.SetDimensions(40, 30, 1)
flat.GetPointData().SetScalars(numpy_to_vtk(np.random.default_rng(1).random(1200) * 100, 1))
for name, image in (("flat.vti", flat),):
    writer = vtkXMLImageDataWriter()
    writer.SetInputData(image)
    writer.SetFileName(path(name))
    writer.Write()
expect_picture("a 2D .vti is a height field", [path("flat.vti"), *FAST],
               needles=("a height field of 40 x 30",))
pair = vtkImageData()
pair.SetDimensions(8, 8, 8)
pair.GetPointData().SetScalars(numpy_to_vtk(np.zeros((512, 2)), 1))
writer = vtkXMLImageDataWriter()
writer.SetInputData(pair)
writer.SetFileName(path("pair.vti"))
writer.Write()
expect_failure("volume of two components", [path("pair.vti"), "-o", path("x.png")], 1,
               "2-component scalars")
# Headers that VTK 9.1's readers trust: before aperture-render checked them, the first hung it,
# the second handed a file name to printf as its format, the long name overflowed MetaIO's buffer
# and FuzzVolumeReaders crashed the NIfTI reader with damaged headers and the NRRD reader with a
# spacing of 0.
nrrd = b"NRRD0004\ntype: short\ndimension: 3\nsizes: 10 5 4"
long_name = (b"ObjectType = Image\nNDims = 3\n" + b"N" * 300 + b" = 1\nDimSize = 2 2 2\n"
             b"ElementType = MET_UCHAR\nElementDataFile = LOCAL\n" + bytes(8))
nifti_writer = vtkNIFTIImageWriter()
nifti_writer.SetInputData(volume)
nifti_writer.SetFileName(path("head.nii"))
nifti_writer.Write()
with open(path("head.nii"), "rb") as f:
    header = bytearray(f.read(348))
axes, offset = bytearray(header), bytearray(header)
axes[40:42] = struct.pack("<h", 9)
offset[108:112] = struct.pack("<f", float("nan"))
for name, data, words in (
        ("cut.nrrd", nrrd, "its header's last line does not end"),
        ("pattern.nrrd", nrrd + b"\ndata file: %n%s 1 5 0\n\n", "lies in several files"),
        ("no-sizes.nrrd", b"NRRD0004\ntype: short\ndimension: 3\n\n", "gives no sizes"),
        ("spacing.nrrd", nrrd + b"\nspacings: 0 1 1\n\n", "spacings are not one finite"),
        ("long-name.mha", long_name, "a name shorter than 255 characters"),
        ("missing.mha", long_name.replace(b"N" * 300 + b" = 1\n", b"").replace(
            b"LOCAL", b"nowhere.raw"), "'nowhere.raw' does not exist"),
        ("axes.nii", bytes(axes) + bytes(4), "it has 9 axes"),
        ("offset.nii", bytes(offset) + bytes(4), "data offset is not a finite number")):
    expect_failure("volume header " + name, [write_bytes(name, data), "-o", path("x.png")], 1,
                   words)
expect_failure("volume in a surface mode", [mr, "--mode", "horizon", "-o", path("x.png")], 2,
               "volumes take exact, smoothstep, standard or all")


# Compressed VTI in each layout VTK writes (inline base64, appended raw or base64; 4- or 8-byte
# headers) reads; a damaged block header is one error. VTK 9.1 allocated and filled the blocks
# a damaged count announced (gigabytes), and with no blocks but a partial last one read a block
# it had no size for (FuzzMeshReaders, on a VTP).
def compressed_vti(name, layout, header_bytes):
    writer = vtkXMLImageDataWriter()
    writer.SetInputData(volume)
    writer.SetFileName(path(name))
    writer.SetBlockSize(3000)  # a partial last block
    writer.SetHeaderTypeToUInt64() if header_bytes == 8 else writer.SetHeaderTypeToUInt32()
    if layout == "inline":
        writer.SetDataModeToBinary()
    else:
        writer.SetDataModeToAppended()
        writer.SetEncodeAppendedData(layout == "base64")
    writer.Write()
    return path(name)


def damage_vti(source, name, word, value):
    """A copy of `source` with word `word` of its first array's compression header set."""
    with open(source, "rb") as f:
        data = f.read()
    size = 8 if b'header_type="UInt64"' in data else 4
    if b"<AppendedData" in data:
        tag = data.index(b"<AppendedData")
        start = data.index(b"_", tag) + 1
        encoded = b'encoding="base64"' in data[tag:start]
    else:
        start = data.index(b">", data.index(b"<DataArray")) + 1
        while data[start:start + 1].isspace():
            start += 1
        encoded = True
    stored = 4 * size if encoded else 3 * size  # three header words, base64 in whole groups
    head = bytearray(base64.b64decode(data[start:start + stored]) if encoded
                     else data[start:start + stored])
    head[word * size:(word + 1) * size] = value.to_bytes(size, "little")
    head = base64.b64encode(bytes(head)) if encoded else bytes(head)
    return write_bytes(name, data[:start] + head + data[start + stored:])


for layout, header_bytes in (("inline", 4), ("raw", 8), ("base64", 4)):
    name = compressed_vti(f"zlib-{layout}.vti", layout, header_bytes)
    expect_picture(f"compressed VTI, {layout}", [name, "--size", "200x150"],
                   needles=(described,))
    expect_failure(f"compressed VTI, {layout}, damaged block count",
                   [damage_vti(name, f"count-{layout}.vti", 0, 2**32 - 16), "-o", path("x.png")],
                   1, "compressed blocks, more than the file holds")
    expect_failure(f"compressed VTI, {layout}, block size 0",
                   [damage_vti(name, f"zero-{layout}.vti", 1, 0), "-o", path("x.png")],
                   1, "its block sizes are inconsistent")
    expect_failure(f"compressed VTI, {layout}, no blocks but a last one",
                   [damage_vti(name, f"none-{layout}.vti", 0, 0), "-o", path("x.png")],
                   1, "its block sizes are inconsistent")
    expect_failure(f"compressed VTI, {layout}, vast blocks",
                   [damage_vti(name, f"vast-{layout}.vti", 1, 2**31), "-o", path("x.png")],
                   1, "its compressed blocks do not fit the file")
expect_failure("volume preset", [mr, "--volume", "fancy", "-o", path("x.png")], 2,
               "is not ct-bone, ct-skin, mr or LOW:HIGH")
expect_failure("volume empty isosurface", [mr, "--iso", "1e9", "-o", path("x.png")], 1,
               "gives no surface")
expect_failure("volume cache", [mr, "--cache", path("c.vti"), "-o", path("x.png")], 2,
               "not volumes")

help_text = run("--help")
options = ["-o", "--size", "--interactive", "--save-data", "--show", "--sun", "--sphere-light",
           "--sky", "--env", "--env-azimuth", "--env-exposure", "--mode", "--rays", "--crease",
           "--max-edge", "--cache", "--azimuth", "--elevation", "--zoom", "--up",
           "--background", "--spacing", "--height-scale", "--max-grid", "--volume", "--iso",
           "--help", "--version",
           "Examples:"]
check(help_text.returncode == 0 and all(o in help_text.stdout for o in options),
      "--help explains every option, with examples")
version = run("--version")
check(version.returncode == 0 and version.stdout.startswith("aperture-render "), "--version")

print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
