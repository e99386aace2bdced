"""The Stanford bunny relit by HDR environments from its visibility matrix (Sattler et al. 2004).

    python3 bunny_environment.py [bunny.obj] [picture.png] [environment.exr ...]

Computes once which of 258 lightsphere directions each vertex sees (vtkOcclusionQueryVisibility,
on the GPU), then relights it under each environment (vtkEnvironmentVisibilityLighting) as the
environment turns around it: turning or switching the environment never recomputes the
visibility. The environments default to the forest and sunrise maps. With a picture name (`-`
for none) it renders every environment at four turns, one row per environment, and exits;
otherwise it opens a window where the environment turns: e switches environments, +/- change
the exposure, q quits.
"""

import math
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOGeometry import vtkOBJReader
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkFiltersCore import vtkImageAppend
from vtkmodules.vtkInteractionStyle import vtkInteractorStyleTrackballCamera
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderWindow,
                                         vtkRenderWindowInteractor, vtkRenderer,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL factory)

from aperturelighting import (vtkEnvironmentVisibilityLighting, vtkOcclusionQueryVisibility,
                              vtkOpenEXRReader)

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Testing", "Data")
TURNS = (0.0, 90.0, 180.0, 270.0)


def auto_exposure(relight):
    """Stops that bring the 95th percentile of the relit luminance over a full turn to 0.8."""
    luminance = []
    for azimuth in TURNS:
        relight.SetAzimuth(azimuth)
        relight.Update()
        rgb = vtk_to_numpy(relight.GetOutput().GetPointData().GetArray("EnvironmentLighting"))
        luminance.append(rgb @ np.array([0.2126, 0.7152, 0.0722]))
    relight.SetAzimuth(0.0)
    bright = np.percentile(np.concatenate(luminance), 95)
    return math.log2(0.8 / bright) if bright > 0 else 0.0


def main(bunny, picture, files):
    window = vtkRenderWindow()
    window.SetSize(360, 360)
    window.SetWindowName("ApertureLighting: bunny under HDR environments")
    if picture:
        window.SetOffScreenRendering(1)

    # The visibility matrix: 258 directions (lightsphere level 3), rendered in this window's
    # OpenGL context. Computed once, whatever the environments do afterwards.
    reader = vtkOBJReader()
    reader.SetFileName(bunny)
    visibility = vtkOcclusionQueryVisibility()
    visibility.SetInputConnection(reader.GetOutputPort())
    visibility.SetLevel(3)
    visibility.SetRenderWindow(window)
    visibility.Update()
    if visibility.GetOutput().GetNumberOfPoints() == 0:
        print(f"Could not compute the visibility of {bunny}", file=sys.stderr)
        return 1

    # The environments, Y up as the bunny is, each with its own exposure.
    relight = vtkEnvironmentVisibilityLighting()
    relight.SetInputConnection(visibility.GetOutputPort())
    relight.SetUpAxisToY()
    environments, exposures = [], []
    for name in files:
        environment = vtkOpenEXRReader()
        environment.SetFileName(name)
        environment.Update()
        if environment.GetOutput().GetNumberOfPoints() == 0:
            print(f"Could not read the environment {name}", file=sys.stderr)
            return 1
        relight.SetEnvironmentConnection(environment.GetOutputPort())
        environments.append(environment)
        exposures.append(auto_exposure(relight))
    current = [0]

    def show(which):
        current[0] = which
        relight.SetEnvironmentConnection(environments[which].GetOutputPort())
        relight.SetExposure(exposures[which])

    show(0)

    # The relit colours drawn as they are: unlit, straight from EnvironmentColors.
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(relight.GetOutputPort())
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("EnvironmentColors")
    mapper.SetColorModeToDirectScalars()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().LightingOff()

    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(0.12, 0.13, 0.16)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(-0.02, 0.12, 0.5)
    camera.SetFocalPoint(-0.02, 0.1, 0.0)
    renderer.ResetCamera()
    camera.Zoom(1.4)
    window.AddRenderer(renderer)

    if picture:
        # One row per environment (the first at the top), turned by 0, 90, 180, 270 degrees.
        rows = vtkImageAppend()
        rows.SetAppendAxis(1)
        for which in reversed(range(len(environments))):
            show(which)
            row = vtkImageAppend()
            row.SetAppendAxis(0)
            for azimuth in TURNS:
                relight.SetAzimuth(azimuth)
                window.Render()
                grab = vtkWindowToImageFilter()
                grab.SetInput(window)
                grab.ReadFrontBufferOff()
                grab.Update()
                frame = vtkImageData()
                frame.DeepCopy(grab.GetOutput())
                row.AddInputData(frame)
            row.Update()
            strip = vtkImageData()
            strip.DeepCopy(row.GetOutput())
            rows.AddInputData(strip)
        writer = vtkPNGWriter()
        writer.SetInputConnection(rows.GetOutputPort())
        writer.SetFileName(picture)
        writer.Write()
        print("wrote", picture)
        return 0

    window.SetSize(720, 720)
    interactor = vtkRenderWindowInteractor()
    interactor.SetRenderWindow(window)
    interactor.SetInteractorStyle(vtkInteractorStyleTrackballCamera())

    def on_timer(_caller, _event):
        relight.SetAzimuth((relight.GetAzimuth() + 2.0) % 360.0)
        window.Render()

    def on_key(caller, _event):
        key = caller.GetKeySym()
        if key == "e":
            show((current[0] + 1) % len(environments))
            print("environment:", environments[current[0]].GetFileName())
        elif key in ("plus", "minus", "KP_Add", "KP_Subtract"):
            exposures[current[0]] += 0.5 if key in ("plus", "KP_Add") else -0.5
            relight.SetExposure(exposures[current[0]])
            print("exposure:", exposures[current[0]], "stops")

    interactor.AddObserver("TimerEvent", on_timer)
    interactor.AddObserver("KeyPressEvent", on_key)
    window.Render()
    interactor.CreateRepeatingTimer(40)
    print("The environment turns; e: next environment, +/-: exposure, drag to orbit, q: quit")
    interactor.Start()
    return 0


if __name__ == "__main__":
    arguments = sys.argv[1:]
    sys.exit(main(arguments[0] if arguments else os.path.join(DATA, "stanford-bunny.obj"),
                  arguments[1] if len(arguments) > 1 and arguments[1] != "-" else None,
                  arguments[2:] or [os.path.join(DATA, "env", "forest.exr"),
                                    os.path.join(DATA, "env", "sunrise.exr")]))
