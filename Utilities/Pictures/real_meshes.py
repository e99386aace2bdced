"""The pictures of docs/precompute.md's real meshes: what real files bring, as aperture-render
draws them.

    python3 real_meshes.py <aperture-render> <Testing/Data> <work folder> <docs/images>

- real-seams.png: the bunny as an OBJ whose every face corner has its own vt (208,353 points for
  35,947 positions), its aperture radius and its shading: one smooth surface;
- real-cad.png: a machined part from an STL file (points shared across its sharp edges): as it
  was drawn before (--crease 180 --max-edge none: edges smeared into bevels) and by default;
- real-boxes.png: boxes on a ground of two triangles: no contact shadows with --max-edge none,
  refined automatically by default;
- real-scan.png: the bunny with 50 folded, sliver and crumpled spots, as aperture colours: no
  black specks.
"""

import math
import os
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersCore import (vtkAppendPolyData, vtkCleanPolyData, vtkPolyDataNormals,
                                       vtkTriangleFilter)
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkFiltersModeling import vtkLinearExtrusionFilter
from vtkmodules.vtkFiltersSources import vtkCylinderSource
from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLWriter
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.vtkIOPLY import vtkPLYWriter
from vtkmodules.vtkFiltersCore import vtkImageAppend

EXE, DATA, WORK, IMAGES = sys.argv[1:5]
os.makedirs(WORK, exist_ok=True)
SIZE = "480x360"


def render(name, args):
    out = os.path.join(WORK, name)
    subprocess.run([EXE, *args, "--size", SIZE, "-o", out], check=True, stdout=subprocess.DEVNULL)
    return out


def row(pictures, name):
    append = vtkImageAppend()
    append.SetAppendAxis(0)
    for picture in pictures:
        reader = vtkPNGReader()
        reader.SetFileName(picture)
        reader.Update()
        append.AddInputData(reader.GetOutput())
    writer = vtkPNGWriter()
    writer.SetInputConnection(append.GetOutputPort())
    writer.SetFileName(os.path.join(IMAGES, name))
    writer.Write()
    print(os.path.join(IMAGES, name))


bunny_file = os.path.join(DATA, "stanford-bunny.obj")
reader = vtkOBJReader()
reader.SetFileName(bunny_file)
reader.Update()
bunny = reader.GetOutput()
xyz = vtk_to_numpy(bunny.GetPoints().GetData())
triangles = vtk_to_numpy(bunny.GetPolys().GetConnectivityArray()).reshape(-1, 3)

# Texture seams everywhere.
seams = os.path.join(WORK, "bunny-seams.obj")
with open(seams, "w") as f:
    f.writelines("v %r %r %r\n" % tuple(p) for p in xyz.tolist())
    for t, (a, b, c) in enumerate(triangles.tolist()):
        f.write("vt 0.1 0.2\nvt 0.3 0.4\nvt 0.5 0.6\n")
        f.write("f %d/%d %d/%d %d/%d\n" % (a + 1, 3 * t + 1, b + 1, 3 * t + 2, c + 1, 3 * t + 3))
row([render("seams-apertures.png", [seams, "--show", "apertures"]),
     render("seams-shaded.png", [seams, "--sun", "225,40"])], "real-seams.png")

# A machined part: an extruded L with a chamfer, and a boss, merged as an STL reader merges.
profile = vtkPolyData()
points = vtkPoints()
for x, y in ((0, 0), (4, 0), (4, 1), (1.5, 1), (1, 1.5), (1, 3), (0, 3)):
    points.InsertNextPoint(x, y, 0)
profile.SetPoints(points)
outline = vtkCellArray()
outline.InsertNextCell(7, list(range(7)))
profile.SetPolys(outline)
extrude = vtkLinearExtrusionFilter()
extrude.SetInputData(profile)
extrude.SetExtrusionTypeToVectorExtrusion()
extrude.SetVector(0, 0, 2)
extrude.CappingOn()
boss = vtkCylinderSource()
boss.SetResolution(48)
boss.SetRadius(0.45)
boss.SetHeight(0.8)
boss.SetCenter(2.8, 0.5, 2.4)  # its axis along y: turned to stand on the top face
boss.CappingOn()
stand = vtkTransform()
stand.Translate(2.8, 0.5, 2.0)
stand.RotateX(90)
stand.Translate(-2.8, -0.5, -2.4)
upright = vtkTransformPolyDataFilter()
upright.SetInputConnection(boss.GetOutputPort())
upright.SetTransform(stand)
part = vtkAppendPolyData()
for source in (extrude, upright):
    tri = vtkTriangleFilter()
    tri.SetInputConnection(source.GetOutputPort())
    part.AddInputConnection(tri.GetOutputPort())
merged = vtkCleanPolyData()
merged.SetInputConnection(part.GetOutputPort())
stl = os.path.join(WORK, "part.stl")
writer = vtkSTLWriter()
writer.SetInputConnection(merged.GetOutputPort())
writer.SetFileName(stl)
writer.Write()
view = ["--up", "+z", "--azimuth", "210", "--elevation", "30", "--sun", "250,50"]
row([render("cad-180.png", [stl, *view, "--crease", "180", "--max-edge", "none"]),
     render("cad-60.png", [stl, *view])], "real-cad.png")

# Boxes on a ground of two triangles, as OBJ.
lines = ["v -3 -3 0", "v 3 -3 0", "v 3 3 0", "v -3 3 0", "f 1 2 3", "f 1 3 4"]
first = 5
for (cx, cy, w, d, h) in ((-1.2, 0.5, 1.2, 1.0, 1.4), (0.9, -0.6, 1.4, 0.9, 0.7),
                         (1.1, 1.4, 0.6, 0.6, 2.0)):
    corners = [(cx + sx * w / 2, cy + sy * d / 2, z) for z in (0, h) for sy in (-1, 1)
               for sx in (-1, 1)]
    lines += ["v %g %g %g" % c for c in corners]
    for face in ((0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2),
                 (1, 3, 7, 5)):
        lines.append("f " + " ".join(str(first + i) for i in face))
    first += 8
boxes = os.path.join(WORK, "boxes.obj")
with open(boxes, "w") as f:
    f.write("\n".join(lines) + "\n")
# Sky light only (the sun below the horizon): contact shadows show as they are.
view = ["--up", "+z", "--azimuth", "200", "--elevation", "35", "--sun", "0,-90",
        "--sky", "0.85,0.88,0.95"]
row([render("boxes-coarse.png", [boxes, *view, "--max-edge", "none"]),
     render("boxes-refined.png", [boxes, *view])], "real-boxes.png")

# A damaged scan: folds (a vertex pushed 30% across its triangle's opposite edge), slivers and
# crumples at 50 vertices, as in TestRealWorldMeshes.
normals = vtkPolyDataNormals()
normals.SetInputData(bunny)
normals.SplittingOff()
normals.Update()
n = vtk_to_numpy(normals.GetOutput().GetPointData().GetNormals())
edge = np.linalg.norm(xyz[triangles[:1000, 0]] - xyz[triangles[:1000, 1]], axis=1).mean()
pts = xyz.astype(float).tolist()
tris = triangles.tolist()
incident = {}
for i, t in enumerate(tris):
    for v in t:
        incident.setdefault(v, []).append(i)
defect = 0
for v in range(100, 35000, 700):
    if v not in incident:
        continue
    t = tris[incident[v][0]]
    k = t.index(v)
    a, b = t[(k + 1) % 3], t[(k + 2) % 3]
    kind = defect % 5
    defect += 1
    if kind < 3:
        mid = (xyz[a] + xyz[b]) / 2
        pts[v] = (mid + 0.3 * (mid - xyz[v]) + 0.02 * (kind - 1) * edge * n[v]).tolist()
    elif kind == 3:
        pts.append((xyz[v] + 1e-4 * (xyz[a] - xyz[v])).tolist())
        m = len(pts) - 1
        for ti in list(incident[v]):
            if a in tris[ti]:
                one, two = list(tris[ti]), list(tris[ti])
                one[one.index(a)] = m
                two[two.index(v)] = m
                tris[ti] = one
                tris.append(two)
    else:
        pts.append((xyz[v] + 2e-4 * (xyz[a] - xyz[v]) + 1e-4 * (xyz[b] - xyz[v])
                    + 3e-5 * edge * n[v]).tolist())
        q = len(pts) - 1
        ti = incident[v][0]
        tris[ti] = [v, a, q]
        tris += [[a, b, q], [b, v, q]]
scan = vtkPolyData()
scan_points = vtkPoints()
for p in pts:
    scan_points.InsertNextPoint(p)
scan.SetPoints(scan_points)
cells = vtkCellArray()
for t in tris:
    cells.InsertNextCell(3, t)
scan.SetPolys(cells)
damaged = os.path.join(WORK, "bunny-damaged.ply")
ply = vtkPLYWriter()
ply.SetInputData(scan)
ply.SetFileName(damaged)
ply.Write()
row([render("scan-clean.png", [bunny_file, "--show", "apertures"]),
     render("scan-damaged.png", [damaged, "--show", "apertures"])], "real-scan.png")
