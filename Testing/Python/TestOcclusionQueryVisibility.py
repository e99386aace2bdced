"""vtkLightSphere and vtkOcclusionQueryVisibility from Python.

The lightsphere's weights sum to 4 pi; a plane's visibility matrix, summed with those weights,
gives the irradiance of a uniform white sky, pi; a plate on port 1 takes its share away; the
RayCast and DepthCompare backends agree on the bunny; VisibilityBits match Visibility.
"""

import math
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkIOGeometry import vtkOBJReader
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL factory)

from aperturelighting import vtkLightSphere, vtkOcclusionQueryVisibility

failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


sphere = vtkLightSphere()
sphere.SetLevel(3)
weights = [sphere.GetWeight(j) for j in range(sphere.GetNumberOfDirections())]
direction = [0.0, 0.0, 0.0]
sphere.GetDirection(257, direction)
check(sphere.GetNumberOfDirections() == 258 and abs(sum(weights) - 4 * math.pi) < 1e-12
      and abs(np.linalg.norm(direction) - 1) < 1e-15,
      "lightsphere level 3: 258 unit directions, weights summing to 4 pi")


def visibility(source, backend, level, occluder=None, bits=False):
    f = vtkOcclusionQueryVisibility()
    f.SetInputConnection(source.GetOutputPort())
    if occluder is not None:
        f.AddOccluderConnection(occluder.GetOutputPort())
    getattr(f, "SetBackendTo" + backend)()
    f.SetLevel(level)
    f.SetComputeVisibilityBits(bits)
    f.Update()
    return f.GetOutput()


# A tilted plane under a uniform white sky receives pi (sum over j of M_ij w_j).
plane = vtkPlaneSource()
plane.SetNormal(0.3, 0.2, 0.93)
plane.SetResolution(6, 6)
plate = vtkPlaneSource()
plate.SetCenter(0.0, 0.0, 0.3)
plate.SetNormal(0.3, 0.2, 0.93)
for backend in ("DepthCompare", "RayCast"):
    out = visibility(plane, backend, 4)
    m = vtk_to_numpy(out.GetPointData().GetArray("Visibility"))
    w = vtk_to_numpy(out.GetFieldData().GetArray("LightWeights"))
    irradiance = m @ w
    check(np.abs(irradiance - math.pi).max() < 0.01 * math.pi,
          f"{backend}: an open plane under a white sky receives pi "
          f"(worst {np.abs(irradiance - math.pi).max():.4f} off)")
    shaded = vtk_to_numpy(visibility(plane, backend, 4, plate).GetPointData()
                          .GetArray("Visibility")) @ w
    middle = int(np.argmin(np.linalg.norm(vtk_to_numpy(out.GetPoints().GetData()), axis=1)))
    check(shaded[middle] < 0.5 * irradiance[middle],
          f"{backend}: a plate on port 1 shades the plane's middle ({shaded[middle]:.3f} of "
          f"{irradiance[middle]:.3f})")

# The bunny: RayCast and DepthCompare agree where n.l > 0.1; bits match values.
data = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "..", "Data")
bunny = vtkOBJReader()
bunny.SetFileName(os.path.join(data, "stanford-bunny.obj"))
rays = visibility(bunny, "RayCast", 2, bits=True)
depth = visibility(bunny, "DepthCompare", 2)
a = vtk_to_numpy(rays.GetPointData().GetArray("Visibility"))
b = vtk_to_numpy(depth.GetPointData().GetArray("Visibility"))
n = vtk_to_numpy(rays.GetPointData().GetNormals())
directions = vtk_to_numpy(rays.GetFieldData().GetArray("LightDirections"))
lit = n @ directions.T > 0.1
agreement = ((a > 0) == (b > 0))[lit].mean()
check(agreement >= 0.97, f"bunny: RayCast and DepthCompare agree on {100 * agreement:.2f}%")
bits = rays.GetPointData().GetAbstractArray("VisibilityBits")
k = bits.GetNumberOfComponents()
sample = range(0, rays.GetNumberOfPoints(), 997)
check(all(bool(bits.GetValue(i * k + j)) == (a[i, j] > 0) for i in sample for j in range(k)),
      "VisibilityBits match Visibility")

sys.exit(1 if failures else 0)
