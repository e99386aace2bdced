"""vtkOpenEXRReader, vtkEnvironmentMap and vtkEnvironmentVisibilityLighting from Python.

The forest map reads as a 2:1 float RGB image; a damaged copy fails with an error and an empty
output; the environment's conventions hold (the top row looks up, the centre column north);
the relit colours equal (1/pi) sum_j M_ij L_j w_j computed here with numpy from the filter's
own inputs; a uniform environment lights an open sphere to 1; turning the environment or
changing the exposure re-executes the relighting but never the visibility filter.
"""

import math
import os
import shutil
import sys
import tempfile

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkDoubleArray
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOGeometry import vtkOBJReader
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL factory)

from aperturelighting import (vtkEnvironmentMap, vtkEnvironmentVisibilityLighting,
                              vtkOcclusionQueryVisibility, vtkOpenEXRReader)

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Data")
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


class Errors:
    """Counts the ErrorEvents of an algorithm, so that expected errors stay quiet."""

    CallDataType = "string0"

    def __init__(self, algorithm):
        self.count = 0
        self.last = ""
        algorithm.AddObserver("ErrorEvent", self)

    def __call__(self, _caller, _event, message=None):
        self.count += 1
        self.last = message or ""


# Reading: the forest map is a 2:1 linear RGB float image with finite, non-negative pixels.
forest = vtkOpenEXRReader()
forest.SetFileName(os.path.join(DATA, "env", "forest.exr"))
forest.Update()
image = forest.GetOutput()
width, height, _ = image.GetDimensions()
pixels = vtk_to_numpy(image.GetPointData().GetScalars())
check(width == 2 * height and pixels.shape == (width * height, 3) and pixels.dtype == np.float32
      and np.all(np.isfinite(pixels)) and pixels.min() >= 0 and pixels.max() > 1,
      f"forest.exr: {width} x {height} float RGB, HDR range up to {pixels.max():.1f}")

# A truncated copy: one error, an empty image, no crash.
scratch = tempfile.mkdtemp()
try:
    with open(os.path.join(DATA, "env", "forest.exr"), "rb") as whole:
        data = whole.read()
    truncated = os.path.join(scratch, "truncated.exr")
    with open(truncated, "wb") as part:
        part.write(data[: len(data) // 3])
    broken = vtkOpenEXRReader()
    broken.SetFileName(truncated)
    errors = Errors(broken)
    broken.Update()
    check(errors.count >= 1 and broken.GetOutput().GetNumberOfPoints() == 0,
          f"truncated EXR: error '{errors.last.strip().splitlines()[-1][:60]}' and an empty output")
finally:
    shutil.rmtree(scratch)

# Conventions: with Z up, image point (u, v) = (0.5, 1) looks up and (0.5, 0.5) looks north (+y).
environment = vtkEnvironmentMap()
environment.SetImage(image)
environment.SetUpAxisToZ()
up = [0.0, 0.0, 0.0]
north = [0.0, 0.0, 0.0]
east = [0.0, 0.0, 0.0]
environment.DirectionOf(0.5, 1.0, up)
environment.DirectionOf(0.5, 0.5, north)
environment.DirectionOf(0.75, 0.5, east)
check(np.allclose(up, [0, 0, 1]) and np.allclose(north, [0, 1, 0])
      and np.allclose(east, [1, 0, 0]), "Z up: top row looks up, centre north, right quarter east")
environment.SetAzimuth(90.0)
environment.DirectionOf(0.5, 0.5, north)
check(np.allclose(north, [1, 0, 0]), "azimuth 90: what was north now looks east")

# Visibility of the bunny, once, RayCast (no OpenGL needed), k = 66.
bunny = vtkOBJReader()
bunny.SetFileName(os.path.join(DATA, "stanford-bunny.obj"))
visibility = vtkOcclusionQueryVisibility()
visibility.SetInputConnection(bunny.GetOutputPort())
visibility.SetBackendToRayCast()
visibility.SetLevel(2)
visibility_runs = []
visibility.AddObserver("StartEvent", lambda o, e: visibility_runs.append(1))

relight = vtkEnvironmentVisibilityLighting()
relight.SetInputConnection(visibility.GetOutputPort())
relight.SetEnvironmentConnection(forest.GetOutputPort())
relight.SetUpAxisToY()
relight_runs = []
relight.AddObserver("StartEvent", lambda o, e: relight_runs.append(1))
relight.Update()
out = relight.GetOutput()
lighting = vtk_to_numpy(out.GetPointData().GetArray("EnvironmentLighting"))
colours = vtk_to_numpy(out.GetPointData().GetArray("EnvironmentColors"))
check(lighting.shape == (out.GetNumberOfPoints(), 3) and colours.dtype == np.uint8
      and out.GetPointData().GetArray("Visibility") is not None,
      "EnvironmentLighting (float RGB) and EnvironmentColors (uint8 RGB) added, input arrays kept")

# An independent evaluation of c_i = (1/pi) sum_j M_ij L_j w_j from the same inputs.
matrix = vtk_to_numpy(out.GetPointData().GetArray("Visibility")).astype(np.float64)
directions = out.GetFieldData().GetArray("LightDirections")
weights = vtk_to_numpy(out.GetFieldData().GetArray("LightWeights")).astype(np.float64)
reference_map = relight.GetEnvironmentMap()
radiance = vtkDoubleArray()
reference_map.CellRadiance(directions, radiance)
expected = matrix @ (vtk_to_numpy(radiance) * weights[:, None]) / math.pi
error = np.abs(lighting - expected).max() / expected.max()
check(error < 1e-5, f"EnvironmentLighting = (1/pi) M (L w) computed in numpy (max rel {error:.1e})")
gamma_check = np.clip(255 * np.clip(expected, 0, None) ** (1 / 2.2), 0, 255)
colour_error = np.abs(colours.astype(np.float64) - gamma_check).max()
check(colour_error <= 1.0, f"EnvironmentColors = 255 c^(1/2.2), within {colour_error:.2f} of 255")

# Exposure +1 stop: colours brighter by 2^(1/2.2), linear values unchanged, visibility untouched.
relight.SetExposure(1.0)
relight.Update()
brighter = vtk_to_numpy(relight.GetOutput().GetPointData().GetArray("EnvironmentColors"))
unchanged = vtk_to_numpy(relight.GetOutput().GetPointData().GetArray("EnvironmentLighting"))
dim = (colours > 20) & (colours < 100)
ratio = np.median(brighter[dim].astype(np.float64) / colours[dim])
check(abs(ratio - 2 ** (1 / 2.2)) < 0.02 and np.array_equal(unchanged, lighting),
      f"exposure +1: colours x{ratio:.3f} (2^(1/2.2) = {2 ** (1 / 2.2):.3f}), lighting unchanged")

# Turning the environment half way round changes the lighting; a full turn gives it back.
relight.SetExposure(0.0)
relight.SetAzimuth(180.0)
relight.Update()
turned = vtk_to_numpy(relight.GetOutput().GetPointData().GetArray("EnvironmentLighting")).copy()
relight.SetAzimuth(360.0)
relight.Update()
full_turn = vtk_to_numpy(relight.GetOutput().GetPointData().GetArray("EnvironmentLighting"))
change = np.abs(turned - lighting).mean() / lighting.mean()
back = np.abs(full_turn - lighting).max() / lighting.max()
check(change > 0.05 and back < 1e-4,
      f"azimuth 180 changes the lighting by {100 * change:.0f}%, 360 restores it ({back:.1e})")
check(len(visibility_runs) == 1 and len(relight_runs) == 4,
      f"visibility computed {len(visibility_runs)} time(s), relighting {len(relight_runs)} times")

# A sphere, open everywhere, under a uniform environment of radiance 1 comes out at 1.
uniform = vtkImageData()
uniform.SetDimensions(64, 32, 1)
uniform.GetPointData().SetScalars(numpy_to_vtk(np.ones((64 * 32, 3), dtype=np.float32), deep=1))
sphere = vtkSphereSource()
sphere.SetThetaResolution(24)
sphere.SetPhiResolution(12)
sphere_visibility = vtkOcclusionQueryVisibility()
sphere_visibility.SetInputConnection(sphere.GetOutputPort())
sphere_visibility.SetBackendToRayCast()
sphere_visibility.SetLevel(3)
sphere_light = vtkEnvironmentVisibilityLighting()
sphere_light.SetInputConnection(sphere_visibility.GetOutputPort())
sphere_light.SetEnvironmentData(uniform)
sphere_light.Update()
ones = vtk_to_numpy(sphere_light.GetOutput().GetPointData().GetArray("EnvironmentLighting"))
deviation = np.abs(ones - 1)
check(deviation.mean() < 0.02 and deviation.max() < 0.05,
      f"uniform environment on a sphere, k = 258: mean |c - 1| {deviation.mean():.4f}, "
      f"max {deviation.max():.4f}")

# Without an environment the relighting fails with an error and an empty output.
lonely = vtkEnvironmentVisibilityLighting()
lonely.SetInputConnection(sphere_visibility.GetOutputPort())
errors = Errors(lonely)
lonely.Update()
check(errors.count >= 1 and lonely.GetOutput().GetNumberOfPoints() == 0,
      "no environment: error and an empty output")

if failures:
    print(f"{len(failures)} check(s) failed")
    sys.exit(1)
