"""aperture-render end to end.

    python3 TestApertureRender.py <aperture-render> <Testing/Data> <work folder>

Every input format it reads (meshes and height fields, made here from the bunny and the Fuji
tile), the embedded default scene, --mode all, --show apertures, the cache, the data it saves, an
HDR environment as the sky, and bad input: each bad case must end with exit status 1 or 2 and
exactly one line on stderr that says what is wrong, never a crash.
"""

import os
import struct
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersCore import vtkDelaunay3D
from vtkmodules.vtkFiltersSources import vtkCubeSource
from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLWriter
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter, vtkTIFFWriter
from vtkmodules.vtkIOLegacy import vtkPolyDataWriter, vtkUnstructuredGridWriter
from vtkmodules.vtkIOPLY import vtkPLYWriter
from vtkmodules.vtkIOXML import (vtkXMLImageDataReader, vtkXMLPolyDataReader,
                                 vtkXMLPolyDataWriter)

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


def run(*args, env=None):
    return subprocess.run([EXE, *args], capture_output=True, text=True, timeout=600, env=env)


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


def expect_picture(what, args, width=200, height=150, picture=None, needles=()):
    picture = picture or path(what.replace(" ", "-") + ".png")
    result = run(*args, "-o", picture)
    good = result.returncode == 0 and ("wrote " + os.path.abspath(picture)) in result.stdout
    for needle in needles:
        good = good and needle in result.stdout
    check(good and looks_rendered(picture, width, height) and result.stderr == "",
          f"{what}: exit 0, a rendered {width}x{height} picture, nothing on stderr"
          + ("" if good else f" (exit {result.returncode}: {result.stdout!r} {result.stderr!r})"))
    return result


def expect_failure(what, args, status, words, env=None):
    result = run(*args, env=env)
    lines = result.stderr.splitlines()
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
expect_picture("SRTM tile", [path("N35E138.hgt"), *FAST],
               needles=("SRTM", "4 samples without data"))
expect_picture("USGS DEM", [path("fuji.dem"), *FAST],
               needles=("USGS DEM height field, 128 x 100",))
expect_picture("sphere light and two suns",
               [bunny, *FAST, "--sphere-light", "0,0.2,0.1,0.03,2", "--sun", "200,30",
                "--sun", "120,60,2", "--mode", "smoothstep"])
expect_picture("every mode", [path("bunny.vtp"), *FAST, "--mode", "all"], 1000, 150)
expect_picture("aperture colours", [path("fuji.dem"), *FAST, "--show", "apertures"])

# The cache: computed, then read; other settings recompute it.
cache = path("bunny-cache.vtp")
if os.path.exists(cache):
    os.remove(cache)
expect_picture("cache written", [bunny, *FAST, "--cache", cache], needles=("cached in",))
expect_picture("cache read", [bunny, *FAST, "--cache", cache], needles=("read from the cache",))
expect_picture("cache for other rays", [bunny, "--size", "200x150", "--rays", "8",
                                        "--cache", cache], needles=("recomputing",))
write_bytes("broken-cache.vtp", b"<VTKFile type='PolyData'> broken")
expect_picture("broken cache", [bunny, *FAST, "--cache", path("broken-cache.vtp")],
               needles=("recomputing",))

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

# Bad input: one line, non-zero exit.
expect_failure("missing file", [path("no-such.obj"), "-o", path("x.png")], 1, "does not exist")
expect_failure("directory", [WORK, "-o", path("x.png")], 1, "is a directory")
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
expect_failure("broken VTP", [write_bytes("broken.vtp", b"not xml at all"),
                              "-o", path("x.png")], 1, "not a VTK XML polydata file")
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
        (["--sun"], "needs a value")):
    if args[-1] != "--sun" and "-o" not in args:
        args = [*args, "-o", path("x.png")]
    name = " ".join(os.path.basename(a) if os.sep in a else a for a in args)
    expect_failure("command line " + name, args, 2, words)
expect_failure("neither -o nor --interactive", [bunny], 2, "--interactive")

help_text = run("--help")
options = ["-o", "--size", "--interactive", "--save-data", "--show", "--sun", "--sphere-light",
           "--sky", "--env", "--env-azimuth", "--env-exposure", "--mode", "--rays", "--cache", "--azimuth", "--elevation", "--zoom", "--up",
           "--background", "--spacing", "--height-scale", "--max-grid", "--help", "--version",
           "Examples:"]
check(help_text.returncode == 0 and all(o in help_text.stdout for o in options),
      "--help explains every option, with examples")
version = run("--version")
check(version.returncode == 0 and version.stdout.startswith("aperture-render "), "--version")

print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
