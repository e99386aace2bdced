"""Irradiance error of every shading method against a Monte-Carlo ground truth (the 2007 paper's
Figure 7, measured).

    /usr/bin/python3 Utilities/Evaluation/evaluate.py [--quick] [--data Testing/Data]
                                                      [--out docs] [--check]
                                                      [--mesh FILE [--up AXIS]] [--dem FILE]
                                                      [--json ROWS.json]

For each scene (the paper's cylinder on a plane, the Mount Fuji tile, the Stanford bunny), light
radius (0.001, 0.064, 0.314, 0.785 rad) and light direction (elevations 60, 30 and 8 degrees:
the last grazes), every vertex's irradiance from a distant light of that size, normalised so
that an unoccluded light at normal incidence gives 1, is computed by:

- reference: vtkApertureReference, Monte-Carlo over the light's cap with Embree;
- AAL exact (centroid Lambert), AAL exact (lens moment), smoothstep, simplified, bent normal:
  vtkSphericalCap.LightTransfer on the apertures of vtkAperturePrecompute (the mapper's shaders
  match it within 0.5/255, TestApertureLightingMapperPixels); on height fields (the Mount Fuji
  tile, --dem) the apertures and normals of the height-field path, the horizon sweeps;
- horizon (height fields): vtkHorizonLighting.LightTransfer on the sweep's 32 horizons as the
  GPU gets them (8 bits a sector; the mapper matches it within 0.5/255,
  TestApertureLightingMapperHorizons);
- visibility mask (meshes): vtkVisibilityMask.LightTransfer on the precompute's 256-cell mask
  (one ray a cell), on the CPU: the mappers do not shade with it yet;
- SH PRT, order 6 (bands 0-5): visibility x cosine projected per vertex from the k = 1026
  visibility matrix, the light's cap projected analytically (Funk-Hecke);
- visibility matrix, k = 258: (1/pi) sum_j M_ij L_j w_j with the cap's radiance split over the
  lightsphere's cells.

Errors, over the vertices that face the light (n . l > 0): mean |E - E_ref| and its 95th
percentile, both relative to the mean reference irradiance of those vertices. Writes
evaluation.md (tables), evaluation.json and images/evaluation-montage.png under --out; --quick
runs the cylinder scene with fewer rays (the ctest); --check exits 1 when AAL exact fails to
beat bent normal (with the lens moment: for every r >= 0.064; with the centroid: for 0.064 <=
r <= 0.314), the visibility matrix is off by more than 5% for r >= 0.314 above 30 degrees, or
horizon is worse than AAL exact by more than the reference noise plus one point in any cell.

Any data: --mesh FILE (OBJ, PLY, STL, VTP; --up x|y|z, default z, for the light's elevations)
and --dem FILE (any raster GDAL reads, through vtkGDALDEMReader, resampled to at most 256
samples a side) replace the built-in scenes; --json OUT writes one row per cell and method,
{"scene", "elevation", "radius", "method", "mean", "p95"}, errors in percent.
"""

import argparse
import json
import math
import os
import platform
import sys
import time

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkLookupTable
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPolyData
from vtkmodules.vtkFiltersCore import (vtkAppendPolyData, vtkImageAppend, vtkPolyDataNormals,
                                       vtkTriangleFilter)
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter, vtkWarpScalar
from vtkmodules.vtkFiltersGeometry import vtkImageDataGeometryFilter
from vtkmodules.vtkFiltersSources import vtkCylinderSource, vtkPlaneSource
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkIOGeometry import vtkOBJReader, vtkSTLReader
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkImagingCore import vtkImageResize
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderWindow,
                                         vtkRenderer, vtkTextActor, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingFreeType  # noqa: F401  (text)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL factory)

from aperturelighting import (vtkAperturePrecompute, vtkApertureReference, vtkGDALDEMReader,
                              vtkHorizonLighting, vtkLightSphere, vtkOcclusionQueryVisibility,
                              vtkSphericalCap, vtkTerrainRGBReader, vtkVisibilityMask)

RADII = (0.001, 0.064, 0.314, 0.785)
ELEVATIONS = (60.0, 30.0, 8.0)
AZIMUTH = 225.0
METHODS = ("AAL exact", "AAL exact (moment)", "horizon", "visibility mask", "smoothstep",
           "simplified", "bent normal", "SH PRT order 6", "visibility k=258")
SHADING = {"AAL exact": (vtkSphericalCap.EXACT, vtkSphericalCap.CENTROID),
           "AAL exact (moment)": (vtkSphericalCap.EXACT, vtkSphericalCap.MOMENT),
           "smoothstep": (vtkSphericalCap.SMOOTHSTEP, vtkSphericalCap.CENTROID),
           "simplified": (vtkSphericalCap.SIMPLIFIED, vtkSphericalCap.CENTROID),
           "bent normal": (vtkSphericalCap.BENT_NORMAL, vtkSphericalCap.CENTROID)}


def triangulated(algorithm):
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(algorithm.GetOutputPort())
    normals.SplittingOff()
    normals.ConsistencyOn()
    normals.AutoOrientNormalsOff()
    triangles = vtkTriangleFilter()
    triangles.SetInputConnection(normals.GetOutputPort())
    triangles.Update()
    out = vtkPolyData()
    out.DeepCopy(triangles.GetOutput())
    return out


def cylinder_scene(resolution):
    """The paper's didactic scene: a cylinder standing on a plane (z up)."""
    plane = vtkPlaneSource()
    plane.SetOrigin(-2, -2, 0)
    plane.SetPoint1(2, -2, 0)
    plane.SetPoint2(-2, 2, 0)
    plane.SetResolution(resolution, resolution)
    cylinder = vtkCylinderSource()
    cylinder.SetRadius(0.3)
    cylinder.SetHeight(1.2)
    cylinder.SetResolution(64)
    cylinder.CappingOn()
    stand = vtkTransform()
    stand.Translate(0, 0, 0.6)
    stand.RotateX(90)  # the source's axis is y
    moved = vtkTransformPolyDataFilter()
    moved.SetInputConnection(cylinder.GetOutputPort())
    moved.SetTransform(stand)
    both = vtkAppendPolyData()
    both.AddInputConnection(plane.GetOutputPort())
    both.AddInputConnection(moved.GetOutputPort())
    return triangulated(both), (0.0, 0.0, 1.0), None


def height_field_scene(reader, side, scale):
    """A DEM resampled to side x side samples at most, as a triangulated surface (z up, heights
    x scale) whose points are the grid's, i fastest, and as the grid itself."""
    reader.Update()
    dims = reader.GetOutput().GetDimensions()
    resize = vtkImageResize()
    resize.SetInputConnection(reader.GetOutputPort())
    resize.SetOutputDimensions(min(side, dims[0]), min(side, dims[1]), 1)
    resize.Update()
    image = vtkImageData()
    image.DeepCopy(resize.GetOutput())
    grid = vtkImageDataGeometryFilter()
    grid.SetInputData(image)
    warp = vtkWarpScalar()
    warp.SetInputConnection(grid.GetOutputPort())
    warp.SetScaleFactor(scale)
    warp.UseNormalOn()
    warp.SetNormal(0, 0, 1)
    surface = triangulated(warp)
    surface.GetPointData().SetScalars(None)
    return surface, (0.0, 0.0, 1.0), (image, scale)


def fuji_scene(data, side):
    """The Mount Fuji tile (60 m samples, heights x 1.5)."""
    reader = vtkTerrainRGBReader()
    reader.SetFileName(os.path.join(data, "fuji-terrain-rgb.png"))
    reader.SetSpacing(60.0, 60.0)
    return height_field_scene(reader, side, 1.5)


def dem_scene(name):
    reader = vtkGDALDEMReader()
    reader.SetFileName(name)
    return height_field_scene(reader, 256, 1.0)


def mesh_scene(name, up):
    readers = {".obj": vtkOBJReader, ".ply": vtkPLYReader, ".stl": vtkSTLReader,
               ".vtp": vtkXMLPolyDataReader}
    reader = readers[os.path.splitext(name)[1].lower()]()
    reader.SetFileName(name)
    axis = {"x": (1.0, 0.0, 0.0), "y": (0.0, 1.0, 0.0), "z": (0.0, 0.0, 1.0)}[up[-1]]
    return triangulated(reader), tuple(-a if up.startswith("-") else a for a in axis), None


def bunny_scene(data):
    reader = vtkOBJReader()
    reader.SetFileName(os.path.join(data, "stanford-bunny.obj"))
    reader.Update()
    bunny = vtkPolyData()
    bunny.DeepCopy(reader.GetOutput())
    return bunny, (0.0, 1.0, 0.0), None


def light_direction(up, elevation, azimuth=AZIMUTH):
    up = np.asarray(up, dtype=float)
    east = np.array([1.0, 0.0, 0.0]) if abs(up[0]) < 0.5 else np.array([0.0, 1.0, 0.0])
    north = np.cross(up, east)
    e, a = math.radians(elevation), math.radians(azimuth)
    return math.cos(e) * (math.sin(a) * east + math.cos(a) * north) + math.sin(e) * up


def legendre(lmax, x):
    p = [np.ones_like(x), x]
    for l in range(1, lmax):
        p.append(((2 * l + 1) * x * p[l] - l * p[l - 1]) / (l + 1))
    return p[:lmax + 1]


def cap_samples(direction, radius, count=4096):
    """Stratified directions uniform over a cap."""
    i = np.arange(count) + 0.5
    cos_t = 1 - (i / count) * (1 - math.cos(radius))
    phi = i * math.pi * (3 - math.sqrt(5))
    sin_t = np.sqrt(np.maximum(0, 1 - cos_t ** 2))
    d = np.asarray(direction)
    t = np.cross(d, [1, 0, 0] if abs(d[0]) < 0.6 else [0, 1, 0])
    t /= np.linalg.norm(t)
    b = np.cross(d, t)
    return (cos_t[:, None] * d + sin_t[:, None] * (np.cos(phi)[:, None] * t
                                                   + np.sin(phi)[:, None] * b))


class Scene:
    def __init__(self, name, surface, up, rays, samples, grid=None):
        self.name, self.surface, self.up, self.samples = name, surface, up, samples
        start = time.time()
        self.horizons, self.mask = None, None
        if grid:
            self.precompute_grid(*grid)
        else:
            precompute = vtkAperturePrecompute()
            precompute.SetInputData(surface)
            precompute.SetNumberOfRays(rays)
            precompute.ComputeVisibilityMaskOn()
            precompute.Update()
            self.keep_caps(precompute.GetOutput().GetPointData())
            self.mask = precompute.GetOutput().GetPointData().GetArray("VisibilityMask")
        visibility = vtkOcclusionQueryVisibility()
        visibility.SetInputData(surface)
        visibility.SetBackendToRayCast()
        visibility.SetLevel(4)
        visibility.Update()
        vout = visibility.GetOutput()
        self.matrix = vtk_to_numpy(vout.GetPointData().GetArray("Visibility"))
        self.directions = vtk_to_numpy(vout.GetFieldData().GetArray("LightDirections"))
        self.weights = vtk_to_numpy(vout.GetFieldData().GetArray("LightWeights"))
        level3 = vtkLightSphere()
        level3.SetLevel(3)
        self.weights258 = np.array([level3.GetWeight(j) for j in range(258)])
        self.setup_seconds = time.time() - start

    def keep_caps(self, pd):
        self.normals = vtk_to_numpy(pd.GetNormals()).astype(float)
        self.bent = vtk_to_numpy(pd.GetArray("BentNormal")).astype(float)
        self.radius = vtk_to_numpy(pd.GetArray("ApertureRadius")).astype(float)

    def precompute_grid(self, image, scale):
        """The height-field path: caps and horizons from the sweeps on the grid, whose points
        are the surface's; the surface takes the sweep's normals, so that every method and the
        reference shade the same hemisphere."""
        precompute = vtkAperturePrecompute()
        precompute.SetInputData(image)
        precompute.SetHeightScale(scale)
        precompute.ComputeHorizonAnglesOn()
        precompute.Update()
        pd = precompute.GetOutput().GetPointData()
        self.keep_caps(pd)
        self.horizons = pd.GetArray("HorizonAngles")
        surface = vtkPolyData()
        surface.ShallowCopy(self.surface)
        surface.GetPointData().SetNormals(pd.GetNormals())
        self.surface = surface

    def reference(self, direction, radius):
        ref = vtkApertureReference()
        ref.SetInputData(self.surface)
        ref.SetLightDirection(*direction)
        ref.SetLightRadius(radius)
        ref.SetNumberOfSamples(self.samples)
        ref.Update()
        pd = ref.GetOutput().GetPointData()
        return (vtk_to_numpy(pd.GetArray("ReferenceIrradiance")).astype(float),
                vtk_to_numpy(pd.GetArray("ReferenceNoise")).astype(float))

    def method(self, name, direction, radius):
        if name == "visibility mask":
            if self.mask is None:
                return None
            transfer = vtkVisibilityMask.LightTransfer
            d = list(direction)
            return np.array([transfer(self.mask, i, n, d, radius)
                             for i, n in enumerate(self.normals.tolist())])
        if name == "horizon":
            if self.horizons is None:
                return None
            transfer = vtkHorizonLighting.LightTransfer
            d = list(direction)
            return np.array([transfer(self.horizons, i, n, d, radius, True)
                             for i, n in enumerate(self.normals.tolist())])
        if name in SHADING:
            shading, lambert = SHADING[name]
            transfer = vtkSphericalCap.LightTransfer
            d = list(direction)
            return np.array([transfer(shading, lambert, n, b, r, d, radius)
                             for n, b, r in zip(self.normals.tolist(), self.bent.tolist(),
                                                self.radius.tolist())])
        scale = vtkSphericalCap.LightRadiance(radius)
        if name == "SH PRT order 6":
            # Funk-Hecke: the cap's projection on band l is 2 pi int_{cos r}^1 P_l, so the
            # order-6 product of light and transfer is sum_j M_ij w_j K(d . l_j).
            c = math.cos(radius)
            p_c = legendre(6, np.array(c))
            bands = [1 - c] + [(p_c[l - 1] - p_c[l + 1]) / (2 * l + 1) for l in range(1, 6)]
            t = self.directions @ np.asarray(direction)
            p_t = legendre(5, t)
            kernel = sum(scale * 2 * math.pi * bands[l] * (2 * l + 1) / (4 * math.pi) * p_t[l]
                         for l in range(6))
            return self.matrix @ (self.weights * kernel)
        # The visibility matrix at k = 258: the cap's radiance per lightsphere cell.
        samples = cap_samples(direction, radius)
        nearest = np.argmax(samples @ self.directions[:258].T, axis=1)
        share = np.bincount(nearest, minlength=258) / len(samples)
        cap = vtkSphericalCap.SolidAngleFromCapRadius(radius)
        return self.matrix[:, :258] @ (scale * cap * share)


def focus_of(camera):
    return np.array(camera.GetFocalPoint())


def one_vertex_a_triangle(surface, values):
    """Per-vertex values as a per-fragment mask shading would show them: bits do not
    interpolate, so each triangle takes its first vertex's (its normal's variation aside)."""
    cells = vtk_to_numpy(surface.GetPolys().GetConnectivityArray())
    offsets = vtk_to_numpy(surface.GetPolys().GetOffsetsArray())
    return values[cells[offsets[:-1]]]


def mask_panels(scene, reference, estimates):
    """The mask where one cap fails: the reference, the cap, the mask per vertex interpolated
    (the mappers' choice) and per fragment, and both errors; then the same 5 times closer
    where the per-fragment picture departs most from the interpolated one."""
    mask = estimates["visibility mask"]
    per_fragment = one_vertex_a_triangle(scene.surface, mask)
    values = [reference, estimates["AAL exact"], mask, per_fragment,
              np.abs(estimates["AAL exact"] - reference), np.abs(mask - reference)]
    titles = ["reference", "AAL exact", "mask per vertex", "mask per fragment",
              "|AAL exact - ref|", "|mask - ref|"]
    # The vertex whose triangles' one-vertex values depart most from its own, smoothed by its
    # neighbourhood: where facets would show.
    cells = vtk_to_numpy(scene.surface.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    departure = np.zeros(len(mask))
    np.maximum.at(departure, cells.ravel(), np.repeat(np.abs(per_fragment - mask[cells].mean(
        axis=1)), 3))
    points = vtk_to_numpy(scene.surface.GetPoints().GetData())
    focus = points[np.argmax(departure)]
    return [render_panels(scene, values, titles, 240),
            render_panels(scene, values, [t + ", 5x" for t in titles], 240, focus, 5.0)]


def errors(estimate, reference, facing):
    keep = facing & np.isfinite(reference)
    mean_ref = reference[keep].mean()
    diff = np.abs(estimate[keep] - reference[keep])
    return diff.mean() / mean_ref, np.percentile(diff, 95) / mean_ref


def render_panels(scene, values, titles, size, focus=None, zoom=1.0):
    """One picture per array of per-vertex (or, as many as the cells, per-cell) values: grey
    0..1, or errors in colour; the whole scene, or `zoom` times closer around `focus`."""
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(size, size)
    renderer = vtkRenderer()
    renderer.SetBackground(0.1, 0.11, 0.13)
    window.AddRenderer(renderer)
    surface = vtkPolyData()
    surface.ShallowCopy(scene.surface)
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(surface)
    mapper.SetScalarModeToUsePointData()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().LightingOff()
    renderer.AddActor(actor)
    label = vtkTextActor()
    label.GetTextProperty().SetFontSize(max(11, size // 14))
    label.SetPosition(6, size - size // 9)
    renderer.AddActor2D(label)
    camera = renderer.GetActiveCamera()
    up = np.asarray(scene.up)
    focus = np.array(scene.surface.GetCenter())
    eye = focus + 2.2 * np.linalg.norm(np.array(scene.surface.GetBounds()[1::2])
                                       - np.array(scene.surface.GetBounds()[0::2])) * (
        0.45 * up + light_direction(up, 0.0, 200.0) * 0.9)
    camera.SetFocalPoint(*focus)
    camera.SetPosition(*eye)
    camera.SetViewUp(*up)
    renderer.ResetCamera()
    camera.Zoom(1.25)
    if focus is not None:
        shift = np.asarray(focus) - focus_of(camera)
        camera.SetFocalPoint(*(focus_of(camera) + shift))
        camera.SetPosition(*(np.array(camera.GetPosition()) + shift))
        camera.Zoom(zoom)
        renderer.ResetCameraClippingRange()
    grey, heat = vtkLookupTable(), vtkLookupTable()
    grey.SetRange(0.0, 1.0)
    grey.SetSaturationRange(0, 0)
    grey.SetValueRange(0, 1)
    grey.SetHueRange(0, 0)
    grey.Build()
    heat.SetRange(0.0, 0.3)
    heat.SetHueRange(0.66, 0.0)
    heat.Build()
    pictures = []
    for array, title in zip(values, titles):
        data = numpy_to_vtk(np.nan_to_num(array).astype(np.float32), deep=1)
        data.SetName("E")
        per_cell = len(array) == surface.GetNumberOfCells() != surface.GetNumberOfPoints()
        surface.GetPointData().SetScalars(None if per_cell else data)
        surface.GetCellData().SetScalars(data if per_cell else None)
        surface.Modified()
        if per_cell:
            mapper.SetScalarModeToUseCellData()
        else:
            mapper.SetScalarModeToUsePointData()
        is_error = title.startswith("|")
        mapper.SetLookupTable(heat if is_error else grey)
        mapper.SetScalarRange(*(heat.GetRange() if is_error else grey.GetRange()))
        label.SetInput(title)
        window.Render()
        grab = vtkWindowToImageFilter()
        grab.SetInput(window)
        grab.ReadFrontBufferOff()
        grab.Update()
        picture = vtkImageData()
        picture.DeepCopy(grab.GetOutput())
        pictures.append(picture)
    return pictures


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    here = os.path.dirname(os.path.abspath(__file__))
    parser.add_argument("--data", default=os.path.join(here, "..", "..", "Testing", "Data"))
    parser.add_argument("--out", default=os.path.join(here, "..", "..", "docs"))
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--mesh", help="a mesh of your own (OBJ, PLY, STL, VTP)")
    parser.add_argument("--up", default="z", choices=("x", "y", "z", "-x", "-y", "-z"))
    parser.add_argument("--dem", help="a DEM of your own (any raster GDAL reads)")
    parser.add_argument("--json", help="rows of scene, elevation, radius, method, mean, p95")
    args = parser.parse_args()
    os.makedirs(os.path.join(args.out, "images"), exist_ok=True)

    rays, samples = (128, 256) if args.quick else (512, 1024)
    builders = [("cylinder on a plane", lambda: cylinder_scene(40 if args.quick else 100))]
    if not args.quick:
        builders += [("Mount Fuji", lambda: fuji_scene(args.data, 128)),
                     ("Stanford bunny", lambda: bunny_scene(args.data))]
    if args.mesh or args.dem:
        builders = ([(os.path.basename(args.mesh), lambda: mesh_scene(args.mesh, args.up))]
                    if args.mesh else []) + (
            [(os.path.basename(args.dem), lambda: dem_scene(args.dem))] if args.dem else [])
    results, montage_rows, horizon_rows, mask_rows, failures = [], [], [], [], []
    for name, build in builders:
        surface, up, grid = build()
        scene = Scene(name, surface, up, rays, samples, grid)
        print(f"{name}: {surface.GetNumberOfPoints()} points, apertures ({rays} rays) and "
              f"visibility (k = 1026) in {scene.setup_seconds:.1f} s", flush=True)
        worst_cap = None  # where the cap's p95 is worst at r = 0.064, for the mask's pictures
        for elevation in ELEVATIONS:
            direction = light_direction(up, elevation)
            facing = scene.normals @ direction > 0
            for radius in RADII:
                reference, noise = scene.reference(direction, radius)
                keep = facing & np.isfinite(reference)
                cell = {"scene": name, "elevation": elevation, "radius": radius,
                        "points": int(keep.sum()),
                        "noise": float(noise[keep].mean() / reference[keep].mean()),
                        "methods": {}}
                estimates = {}
                for method in METHODS:
                    estimates[method] = scene.method(method, direction, radius)
                    if estimates[method] is None:
                        continue
                    mean, p95 = errors(estimates[method], reference, facing)
                    cell["methods"][method] = {"mean": float(mean), "p95": float(p95)}
                results.append(cell)
                print(f"  elevation {elevation:4.0f}, r = {radius:5.3f}: " + ", ".join(
                    f"{m} {100 * e['mean']:.1f}%" for m, e in cell["methods"].items()), flush=True)
                if elevation == 30.0 and radius == 0.064:
                    shown = [m for m in METHODS if estimates[m] is not None]
                    values = [reference] + [estimates[m] for m in shown] + [
                        np.abs(estimates["AAL exact"] - reference)]
                    titles = ["reference"] + shown + ["|AAL exact - ref|"]
                    montage_rows.append(render_panels(scene, values, titles, 200))
                if elevation == 8.0 and radius == 0.064 and scene.horizons is not None:
                    horizon_rows.append(render_panels(
                        scene, [reference, estimates["AAL exact"], estimates["horizon"],
                                np.abs(estimates["AAL exact"] - reference),
                                np.abs(estimates["horizon"] - reference)],
                        ["reference, sun at 8 deg", "AAL exact", "horizon", "|AAL exact - ref|",
                         "|horizon - ref|"], 240))
                if radius == 0.064 and estimates.get("visibility mask") is not None and (
                        worst_cap is None or
                        cell["methods"]["AAL exact"]["p95"] > worst_cap[0]):
                    worst_cap = (cell["methods"]["AAL exact"]["p95"], reference, estimates)
        if worst_cap:
            mask_rows += mask_panels(scene, worst_cap[1], worst_cap[2])
    # Checks: the paper's claims, as measured. With the lens moment, AAL exact beats bent normal
    # wherever the light has a size; with the centroid Lambert it does up to r = 0.314 (beyond,
    # the centroid overestimates by up to 2/(1 + cos r), see docs/evaluation.md).
    for cell in results:
        m, where = cell["methods"], (f"{cell['scene']}, elevation {cell['elevation']:.0f}, "
                                     f"r = {cell['radius']}")
        if cell["radius"] >= 0.064 and not m["AAL exact (moment)"]["mean"] < m["bent normal"]["mean"]:
            failures.append(where + ": AAL exact (moment) does not beat bent normal")
        if 0.064 <= cell["radius"] <= 0.314 and not m["AAL exact"]["mean"] < m["bent normal"]["mean"]:
            failures.append(where + ": AAL exact does not beat bent normal")
        if cell["radius"] >= 0.314 and cell["elevation"] >= 30.0 and \
                m["visibility k=258"]["mean"] > 0.05:
            failures.append(where + ": the visibility matrix is off by "
                            f"{100 * m['visibility k=258']['mean']:.1f}%")
        # A mode beyond one cap is never worse than the cap beyond the reference's noise.
        for new in ("horizon", "visibility mask"):
            for stat in ("mean", "p95"):
                if new in m and m[new][stat] > m["AAL exact"][stat] + cell["noise"] + 0.01:
                    failures.append(f"{where}: {new} {stat} {100 * m[new][stat]:.1f}% is worse "
                                    f"than AAL exact's {100 * m['AAL exact'][stat]:.1f}%")
    write_outputs(args, results, {"evaluation-montage": montage_rows,
                                  "evaluation-horizon": horizon_rows,
                                  "evaluation-mask": mask_rows}, rays, samples)
    for failure in failures:
        print("FAIL", failure)
    return 1 if args.check and failures else 0


def write_montage(rows, name):
    """Rows of pictures, the first on top, as one PNG."""
    column = vtkImageAppend()
    column.SetAppendAxis(1)
    for row in reversed(rows):
        strip = vtkImageAppend()
        strip.SetAppendAxis(0)
        for picture in row:
            strip.AddInputData(picture)
        strip.Update()
        image = vtkImageData()
        image.DeepCopy(strip.GetOutput())
        column.AddInputData(image)
    writer = vtkPNGWriter()
    writer.SetInputConnection(column.GetOutputPort())
    writer.SetFileName(name)
    writer.Write()


def write_outputs(args, results, montages, rays, samples):
    suffix = "-quick" if args.quick else ""
    with open(os.path.join(args.out, f"evaluation{suffix}.json"), "w") as f:
        json.dump(results, f, indent=1)
    if args.json:
        rows = [{"scene": c["scene"], "elevation": c["elevation"], "radius": c["radius"],
                 "method": m, "mean": 100 * e["mean"], "p95": 100 * e["p95"]}
                for c in results for m, e in c["methods"].items()]
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=1)
    for name, rows in montages.items():
        if rows:
            write_montage(rows, os.path.join(args.out, "images", f"{name}{suffix}.png"))
    lines = [f"Measured with `{' '.join(['/usr/bin/python3'] + sys.argv)}` on "
             f"{platform.node() and platform.machine()} ({os.cpu_count()} cores), {rays} aperture "
             f"rays, {samples} reference samples per vertex.", ""]
    for scene in dict.fromkeys(c["scene"] for c in results):
        lines += [f"### {scene}", "",
                  "Mean / 95th-percentile irradiance error, relative to the mean reference "
                  "irradiance of the vertices facing the light.", "",
                  "| elevation | r (rad) | " + " | ".join(METHODS) + " | reference noise |",
                  "|---|---|" + "---|" * len(METHODS) + "---|"]
        for c in (c for c in results if c["scene"] == scene):
            best = min(e["mean"] for e in c["methods"].values())
            cells = []
            for m in METHODS:
                e = c["methods"].get(m)
                text = f"{100 * e['mean']:.1f} / {100 * e['p95']:.0f}" if e else "n/a"
                cells.append(f"**{text}**" if e and e["mean"] == best else text)
            lines.append(f"| {c['elevation']:.0f}° | {c['radius']} | " + " | ".join(cells)
                         + f" | {100 * c['noise']:.2f} |")
        lines.append("")
    with open(os.path.join(args.out, f"evaluation-tables{suffix}.md"), "w") as f:
        f.write("\n".join(lines))


if __name__ == "__main__":
    sys.exit(main())
