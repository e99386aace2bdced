"""Visibility kept current while things move (Sattler et al. 2004, sections 4 and 6).

    python3 dynamic_scenes.py deform [environment.exr] [picture.png]
    python3 dynamic_scenes.py orbit [bunny.obj] [environment.exr] [picture.png]

The Python twin of DynamicScenes.cxx, driven by vtkDynamicVisibilityDriver.
deform: a rippling ball, its visibility recomputed every frame at a coarse lightsphere level
chosen to keep each update under 50 ms, relit by an HDR environment; when the animation stops
(space), idle frames refine the lightsphere up to k = 258.
orbit: the camera circles the Stanford bunny with vertex filtering on: each frame computes
visibility (k = 66 while moving) only for the points of triangles coming into view.
With a picture name the example runs a fixed animation, prints what each frame computed, writes a
strip of frames and exits; otherwise it opens a window (space: pause or resume, q: quit).
"""

import math
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_INT
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkCommonDataModel import vtkDataObject, vtkImageData
from vtkmodules.vtkFiltersCore import vtkArrayCalculator, vtkImageAppend
from vtkmodules.vtkFiltersGeneral import vtkWarpScalar
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOGeometry import vtkOBJReader
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkInteractionStyle import vtkInteractorStyleTrackballCamera
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderWindow,
                                         vtkRenderWindowInteractor, vtkRenderer,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL factory)

from aperturelighting import (vtkDynamicVisibilityDriver, vtkEnvironmentVisibilityLighting,
                              vtkOcclusionQueryVisibility, vtkOpenEXRReader)

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Testing", "Data")
USAGE = ("usage: dynamic_scenes.py deform [environment.exr] [picture.png]\n"
         "       dynamic_scenes.py orbit [bunny.obj] [environment.exr] [picture.png]")


def set_phase(ripple, phase):
    """The ripple's phase: rings running from pole to pole."""
    ripple.SetFunction(f"0.18*sin(14*coordsZ-{phase:.6f})")


def auto_exposure(relight):
    """Stops that put the 95th percentile of the relit luminance at 0.8."""
    relight.Update()
    rgb = vtk_to_numpy(relight.GetOutput().GetPointData().GetArray("EnvironmentLighting"))
    bright = np.percentile(rgb @ np.array([0.2126, 0.7152, 0.0722]), 95)
    return math.log2(0.8 / bright) if bright > 0 else 0.0


def main(argv):
    mode = argv[1] if len(argv) > 1 else "deform"
    if mode not in ("deform", "orbit"):
        print(USAGE, file=sys.stderr)
        return 2
    orbit = mode == "orbit"
    args = argv[2:]
    bunny = args.pop(0) if orbit and args else os.path.join(DATA, "stanford-bunny.obj")
    environment_file = args.pop(0) if args else os.path.join(DATA, "env", "forest.exr")
    picture = args[0] if args and args[0] != "-" else None

    window = vtkRenderWindow()
    window.SetSize(360, 360)
    window.SetWindowName("ApertureLighting: dynamic scenes")
    if picture:
        window.SetOffScreenRendering(1)
    renderer = vtkRenderer()
    renderer.SetBackground(0.12, 0.13, 0.16)
    window.AddRenderer(renderer)

    # The geometry: a ball whose surface ripples, or the bunny.
    ball = vtkSphereSource()
    ball.SetThetaResolution(160)
    ball.SetPhiResolution(80)
    ripple = vtkArrayCalculator()
    ripple.SetInputConnection(ball.GetOutputPort())
    ripple.AddCoordinateScalarVariable("coordsZ", 2)
    ripple.SetResultArrayName("Ripple")
    set_phase(ripple, 0.0)
    warp = vtkWarpScalar()
    warp.SetInputConnection(ripple.GetOutputPort())
    warp.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_POINTS, "Ripple")
    reader = vtkOBJReader()
    reader.SetFileName(bunny)
    source = reader if orbit else warp

    visibility = vtkOcclusionQueryVisibility()
    visibility.SetInputConnection(source.GetOutputPort())
    visibility.SetRenderWindow(window)
    visibility.SetVertexFiltering(orbit)
    if orbit:
        # Rays cost in proportion to the points computed, which filtering keeps few; the GPU
        # backends render every direction's depth however few points need it.
        visibility.SetBackendToRayCast()
    visibility.SetViewRenderer(renderer)

    environment = vtkOpenEXRReader()
    environment.SetFileName(environment_file)
    environment.Update()
    if environment.GetOutput().GetNumberOfPoints() == 0:
        print(f"Could not read the environment {environment_file}", file=sys.stderr)
        return 1
    relight = vtkEnvironmentVisibilityLighting()
    relight.SetInputConnection(visibility.GetOutputPort())
    relight.SetEnvironmentConnection(environment.GetOutputPort())
    if orbit:
        relight.SetUpAxisToY()

    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(relight.GetOutputPort())
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("EnvironmentColors")
    mapper.SetColorModeToDirectScalars()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().LightingOff()
    renderer.AddActor(actor)
    camera = renderer.GetActiveCamera()
    if orbit:
        camera.SetPosition(-0.02, 0.12, 0.5)
        camera.SetFocalPoint(-0.02, 0.1, 0.0)
    else:
        camera.SetPosition(3.0, 0.0, 1.2)
        camera.SetViewUp(0.0, 0.0, 1.0)
    source.Update()
    if source.GetOutput().GetNumberOfPolys() == 0:
        print(f"Could not read a surface from {bunny}", file=sys.stderr)
        return 1
    renderer.ResetCamera(source.GetOutput().GetBounds())
    camera.Zoom(1.4 if orbit else 1.2)

    # The driver: coarse while moving (within 50 ms an update), up to k = 258 when idle. A static
    # mesh computes each point once, so the orbit can afford k = 66 while it moves.
    driver = vtkDynamicVisibilityDriver()
    driver.SetVisibility(visibility)
    driver.SetLighting(relight)
    driver.SetProp(actor)
    driver.SetMaximumLevel(3)
    driver.SetTargetUpdateTime(0.05)
    driver.SetMinimumLevel(2 if orbit else 0)

    visibility.SetLevel(2)
    relight.SetExposure(auto_exposure(relight))

    state = {"frame": 0, "running": True, "timer": -1}

    def step():
        state["frame"] += 1
        if orbit:
            camera.Azimuth(10.0)
        else:
            set_phase(ripple, 0.35 * state["frame"])

    def report():
        print(f"frame {state['frame']}: {'moving' if driver.GetMoving() else 'idle'}, "
              f"k level {driver.GetLevel()}, {visibility.GetNumberOfComputedPoints()} points "
              f"computed, {visibility.GetNumberOfUnseenTriangles()} triangles unseen, update "
              f"{int(1000 * driver.GetLastUpdateTime())} ms")

    if picture:
        driver.Attach(renderer)
        strip = vtkImageAppend()
        strip.SetAppendAxis(0)

        def grab():
            frame = vtkWindowToImageFilter()
            frame.SetInput(window)
            frame.ReadFrontBufferOff()
            # The frame as the driver left it: a re-render would count as an idle frame.
            frame.ShouldRerenderOff()
            frame.Update()
            copy = vtkImageData()
            copy.DeepCopy(frame.GetOutput())
            strip.AddInputData(copy)

        frames = 36 if orbit else 12
        computed = 0
        for f in range(frames):
            window.Render()
            report()
            computed += visibility.GetNumberOfComputedPoints()
            if f % (frames // 3) == 0:
                grab()
            step()
        # Idle: the driver refines one level a frame.
        while driver.NeedsRefinement():
            window.Render()
            report()
            computed += visibility.GetNumberOfComputedPoints()
        window.Render()
        grab()
        print(f"{computed} point updates in {state['frame']} frames "
              f"({visibility.GetOutput().GetNumberOfPoints()} points)")
        writer = vtkPNGWriter()
        writer.SetInputConnection(strip.GetOutputPort())
        writer.SetFileName(picture)
        writer.Write()
        print(f"wrote {picture}")
        return 0

    window.SetSize(720, 720)
    interactor = vtkRenderWindowInteractor()
    interactor.SetRenderWindow(window)
    interactor.SetInteractorStyle(vtkInteractorStyleTrackballCamera())
    driver.Attach(renderer, interactor)

    @calldata_type(VTK_INT)
    def on_timer(caller, event, timer):
        # The driver's refining frames come by timer too; only ours step the animation.
        if timer == state["timer"] and state["running"]:
            step()
            window.Render()

    def on_key(caller, event):
        if caller.GetKeySym() == "space":
            state["running"] = not state["running"]
            print("running" if state["running"] else "paused: refining")
            # A paused animation is an idle scene: the driver refines it frame by frame.
            window.Render()

    interactor.AddObserver(vtkCommand.TimerEvent, on_timer)
    interactor.AddObserver(vtkCommand.KeyPressEvent, on_key)
    window.Render()
    state["timer"] = interactor.CreateRepeatingTimer(40)
    print("space: pause (the lightsphere refines) or resume, drag to orbit, q: quit")
    interactor.Start()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
