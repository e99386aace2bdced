"""The core's Python module alone, without a display: it computes apertures and the visibility
matrix by rays, and no OpenGL or X11 library is loaded into the process afterwards."""

import os
import sys

assert "DISPLAY" not in os.environ, "run with DISPLAY unset"

from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

from aperturelighting import vtkApertureLightingCore as core
from aperturelighting import vtkLightSphereVisibility  # the umbrella's lazy lookup

assert vtkLightSphereVisibility is core.vtkLightSphereVisibility

# A ground of 11 x 11 points and a roof above its middle, facing down.
points, polys = vtkPoints(), vtkCellArray()
side = 11
for j in range(side):
    for i in range(side):
        points.InsertNextPoint(-1 + 0.2 * i, -1 + 0.2 * j, 0)
        if i and j:
            c = j * side + i
            polys.InsertNextCell(4, (c - side - 1, c - side, c, c - 1))
roof = points.GetNumberOfPoints()
for x, y in ((-0.4, -0.4), (-0.4, 0.4), (0.4, 0.4), (0.4, -0.4)):
    points.InsertNextPoint(x, y, 0.3)
polys.InsertNextCell(4, (roof, roof + 1, roof + 2, roof + 3))
scene = vtkPolyData()
scene.SetPoints(points)
scene.SetPolys(polys)

middle, corner = (side // 2) * side + side // 2, 0
apertures = core.vtkAperturePrecompute()
apertures.SetNumberOfRays(128)
apertures.SetInputData(scene)
apertures.Update()
radius = apertures.GetPolyDataOutput().GetPointData().GetArray("ApertureRadius")
assert radius.GetValue(middle) < radius.GetValue(corner), "the roof shades nothing"

visibility = vtkLightSphereVisibility()
visibility.SetLevel(1)
visibility.SetInputData(scene)
visibility.Update()
matrix = visibility.GetOutput().GetPointData().GetArray("Visibility")
seen = [sum(matrix.GetComponent(p, j) > 0 for j in range(18)) for p in (middle, corner)]
assert seen[0] < seen[1], seen

with open("/proc/self/maps") as maps:
    loaded = {line.split()[-1] for line in maps if "/" in line}
names = sorted(os.path.basename(path) for path in loaded)
forbidden = [n for n in names if n.startswith(("libGL", "libEGL", "libOpenGL", "libX11",
                                               "libvtkRendering", "libvtkApertureLightingRendering"))]
assert not forbidden, forbidden
print("core without a display: aperture radius %.3f < %.3f, directions seen %d < %d; "
      "%d libraries loaded, none of GL or X11" % (radius.GetValue(middle),
                                                  radius.GetValue(corner), *seen, len(names)))
sys.exit(0)
