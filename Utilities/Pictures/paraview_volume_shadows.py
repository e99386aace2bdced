"""Soft shadows on a volume in ParaView 5.11, in one pvpython run: ParaView's shaded Volume (VTK
9.2's gradient shading), the same with VTK 9.2's volumetric shadows (Global Illumination Reach
0.2, Volumetric Scattering Blending 1), and the plugin's Aperture Volume, each in a view of its
own on the same data, camera, lights and transfer functions, each sampled at ParaView's still-frame
distance (locked to the input's spacing). Frames are alternated between the views (the camera
turns 2 degrees a frame); the median frame of each and its ratio to the shaded Volume are printed
as a table, and each view's picture is written to OUT/paraview-<name>.png.

Usage: source build-paraview/env.sh && xvfb-run -a pvpython paraview_volume_shadows.py \\
           PLUGIN.so VOLUME OUT [--size 800x600] [--frames 7] [--check]

VOLUME is any volume ParaView or the plugin opens (.vti, .mha, .nrrd, .nii.gz). The transfer
function is aperture-render's preset: ct-skin where the data holds air (Hounsfield units below
-500), else mr. The first frame of each view (shaders, textures and, for Aperture Volume, the
apertures) is timed apart.
--check fails unless every frame is finite and each representation draws its own picture.
"""

import argparse
import os
import sys
import time

import numpy as np
import paraview.simple as pvs
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

KINDS = ("shaded", "shadows", "aperture")


def transfer_functions(array, low, high):
    """aperture-render's ct-skin or mr preset on the array's colour map and opacity."""
    lut = pvs.GetColorTransferFunction(array)
    opacity = pvs.GetOpacityTransferFunction(array)
    if low < -500.0:
        lut.RGBPoints = [-600.0, 0.85, 0.6, 0.5, 300.0, 0.95, 0.78, 0.68]
        opacity.Points = [-600.0, 0.0, 0.5, 0.0, -300.0, 0.8, 0.5, 0.0, 300.0, 0.8, 0.5, 0.0]
    else:
        span = high - low
        lut.RGBPoints = [low, 0.7, 0.66, 0.62, high, 1.0, 0.97, 0.94]
        opacity.Points = [low + 0.12 * span, 0.0, 0.5, 0.0, low + 0.3 * span, 0.5, 0.5, 0.0,
                          high, 0.8, 0.5, 0.0]


def make_view(source, array, kind, size):
    view = pvs.CreateRenderView(ViewSize=size, OrientationAxesVisibility=0,
                                Background=[0.1, 0.1, 0.12])
    view.UseColorPaletteForBackground = 0
    display = pvs.Show(source, view)
    pvs.ColorBy(display, ("POINTS", array))
    display.SetRepresentationType("Aperture Volume" if kind == "aperture" else "Volume")
    display.Shade = 1
    display.Ambient = 0.2
    display.Diffuse = 0.9
    if kind == "shadows":
        display.GlobalIlluminationReach = 0.2
        display.VolumetricScatteringBlending = 1.0
    if kind == "aperture":
        display.ApertureVolumeLightSize = 10.0
    return view


def face_the_camera(view, bounds, name):
    """The face toward the camera, as aperture-render shows a volume: from +y for NIfTI (RAS),
    from -y for the others (LPS), z up."""
    centre = [0.5 * (bounds[2 * a] + bounds[2 * a + 1]) for a in range(3)]
    reach = 2.2 * max(bounds[2 * a + 1] - bounds[2 * a] for a in range(3))
    side = -1.0 if name.lower().endswith((".nii", ".nii.gz")) else 1.0
    view.CameraFocalPoint = centre
    view.CameraPosition = [centre[0], centre[1] + side * reach, centre[2]]
    view.CameraViewUp = [0.0, 0.0, 1.0]


def frame(view):
    view.GetActiveCamera().Azimuth(2.0)
    start = time.perf_counter()
    pvs.Render(view)
    return time.perf_counter() - start


def read_png(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    return vtk_to_numpy(image.GetPointData().GetScalars()).astype(float)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("plugin")
    parser.add_argument("volume")
    parser.add_argument("out")
    parser.add_argument("--size", default="800x600")
    parser.add_argument("--frames", type=int, default=7)
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args()
    size = [int(v) for v in args.size.split("x")]
    os.makedirs(args.out, exist_ok=True)
    pvs.LoadPlugin(args.plugin, remote=False)
    source = pvs.OpenDataFile(args.volume)
    source.UpdatePipeline()
    info = source.GetDataInformation()
    array = source.PointData.keys()[0]
    low, high = source.PointData[array].GetRange()
    transfer_functions(array, low, high)
    views = {kind: make_view(source, array, kind, size) for kind in KINDS}
    first = {}
    for kind, view in views.items():
        start = time.perf_counter()
        pvs.Render(view)  # shaders, textures, the apertures; it also resets the camera
        first[kind] = time.perf_counter() - start
        face_the_camera(view, info.GetBounds(), args.volume)
    times = {kind: [] for kind in KINDS}
    for _ in range(args.frames):
        for kind, view in views.items():
            times[kind].append(frame(view))
    median = {kind: float(np.median(t)) for kind, t in times.items()}
    extent = info.GetExtent()
    print(f"ParaView {pvs.GetParaViewVersion().major}.{pvs.GetParaViewVersion().minor}, "
          f"{os.path.basename(args.volume)} "
          f"({extent[1] - extent[0] + 1} x {extent[3] - extent[2] + 1} x "
          f"{extent[5] - extent[4] + 1}), {size[0]} x {size[1]}, median of {args.frames} "
          "alternated frames")
    print("| representation | seconds a frame | ratio to Volume, shaded |")
    print("|---|---|---|")
    names = {"shaded": "Volume, shaded (VTK 9.2)",
             "shadows": "Volume, volumetric shadows (VTK 9.2, reach 0.2)",
             "aperture": "Aperture Volume (exact, 10 degree lights)"}
    for kind in KINDS:
        print(f"| {names[kind]} | {median[kind]:.3f} | {median[kind] / median['shaded']:.2f} |")
    print("first frames (shaders, textures; Aperture Volume's apertures): " +
          ", ".join(f"{kind} {first[kind]:.2f} s" for kind in KINDS))
    pictures = {}
    for kind, view in views.items():
        path = os.path.join(args.out, f"paraview-{kind}.png")
        pvs.SaveScreenshot(path, view, ImageResolution=size, TransparentBackground=0)
        pictures[kind] = read_png(path)
    if args.check:
        finite = all(np.isfinite(t).all() and min(t) > 0 for t in times.values())
        differ = min(np.abs(pictures[a] - pictures[b]).mean()
                     for a, b in (("shaded", "shadows"), ("shaded", "aperture"),
                                  ("shadows", "aperture")))
        print(f"check: frames finite {finite}; the pictures differ pairwise by at least "
              f"{differ:.2f} levels on average (> 0.2)")
        return 0 if finite and differ > 0.2 else 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
