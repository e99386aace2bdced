"""vtkAperturePrecompute from Python: a pipeline on a sphere next to a wall, the per-texel mode on
the Fuji tile, progress events, and errors reported without exceptions."""

import math
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkSphereSource

from aperturelighting import vtkAperturePrecompute, vtkSphericalCap, vtkTerrainRGBReader

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Data")


def main():
    failures = []

    # A sphere next to a wall: its side facing the wall sees less sky.
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(32)
    sphere.SetPhiResolution(16)
    wall = vtkCubeSource()
    wall.SetBounds(0.6, 0.7, -2, 2, -2, 2)
    precompute = vtkAperturePrecompute()
    precompute.SetInputConnection(sphere.GetOutputPort())
    precompute.AddOccluderConnection(wall.GetOutputPort())
    precompute.ComputeAmbientOcclusionOn()
    progress = []
    precompute.AddObserver(vtkCommand.ProgressEvent, lambda o, e: progress.append(o.GetProgress()))
    precompute.Update()
    out = precompute.GetPolyDataOutput()
    radius = vtk_to_numpy(out.GetPointData().GetArray("ApertureRadius"))
    bent = vtk_to_numpy(out.GetPointData().GetArray("BentNormal"))
    ao = vtk_to_numpy(out.GetPointData().GetArray("AmbientOcclusion"))
    points = vtk_to_numpy(out.GetPoints().GetData())
    facing = points[:, 0] > 0.4
    back = points[:, 0] < -0.49  # normals pointing away from the wall: nothing in their hemisphere
    if not back.any() or not radius[facing].mean() < radius[back].mean() - 0.2:
        failures.append(f"the wall does not close apertures: {radius[facing].mean()} vs {radius[back].mean()}")
    if not np.allclose(radius[back], math.pi / 2, atol=1e-6):
        failures.append("the far side of the sphere must be open")
    if not np.allclose(np.linalg.norm(bent, axis=1), 1.0, atol=1e-5):
        failures.append("bent normals must be unit vectors")
    if not (bent[facing, 0].mean() < -0.1):
        failures.append("bent normals facing the wall must turn away from it")
    if not (0.0 <= ao.min() and ao.max() <= 1.0 and ao[facing].mean() < ao[back].mean()):
        failures.append("ambient occlusion out of range or not darker near the wall")
    if not (progress and progress[-1] == 1.0):
        failures.append(f"progress events: {progress}")

    # Height field: one cap per texel, on the input grid.
    reader = vtkTerrainRGBReader()
    reader.SetFileName(os.path.join(DATA, "fuji-terrain-rgb.png"))
    reader.SetSpacing(60.0, 60.0)
    terrain = vtkAperturePrecompute()
    terrain.SetInputConnection(reader.GetOutputPort())
    terrain.SetNumberOfRays(32)
    terrain.Update()
    image = terrain.GetImageDataOutput()
    r = vtk_to_numpy(image.GetPointData().GetArray("ApertureRadius"))
    if image.GetDimensions() != (512, 512, 1) or r.shape != (512 * 512,):
        failures.append(f"height field output: {image.GetDimensions()}, {r.shape}")
    elevation = vtk_to_numpy(image.GetPointData().GetArray("Elevation"))
    if not (13.0 < elevation.min() < 14.0 and 3750.0 < elevation.max() < 3752.0):
        failures.append(f"Terrain-RGB decoding: {elevation.min()} .. {elevation.max()}")
    if not (0.2 < r.min() and r.max() <= math.pi / 2 + 1e-6):
        failures.append(f"terrain apertures out of range: {r.min()} .. {r.max()}")
    # An array chosen by an empty name (as ParaView sets it before the reader has run): the
    # height field's scalars, the same caps.
    unnamed = vtkAperturePrecompute()
    unnamed.SetInputConnection(reader.GetOutputPort())
    unnamed.SetInputArrayToProcess(0, 0, 0, 0, "")
    unnamed.Update()
    same = unnamed.GetImageDataOutput().GetPointData().GetArray("ApertureRadius")
    if same is None or not np.array_equal(vtk_to_numpy(same), r):
        failures.append("an empty array name must mean the height field's scalars")
    print("Fuji: mean aperture radius", r.mean(), "solid angle", vtkSphericalCap.SolidAngleFromCapRadius(float(r.mean())))

    # Bad input: an error event and an empty output, no exception.
    errors = []
    bad = vtkAperturePrecompute()
    bad.SetInputConnection(sphere.GetOutputPort())
    bad.SetEmbreeConfiguration("threads=banana")
    bad.AddObserver(vtkCommand.ErrorEvent, lambda o, e: errors.append(e))
    bad.GetExecutive().AddObserver(vtkCommand.ErrorEvent, lambda o, e: None)
    bad.Update()
    if not errors or bad.GetPolyDataOutput().GetNumberOfPoints() != 0:
        failures.append("an Embree failure must raise an error event and leave an empty output")

    for f in failures:
        print("FAIL", f, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
