"""vtkApertureLightingMapper from Python: a precompute -> mapper pipeline renders, each model
differs from standard lighting where apertures are partly closed, light radii travel on lights,
and the composite mapper shares the same settings object."""

import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkFiltersCore import vtkAppendPolyData
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkRenderWindow, vtkRenderer,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL factory)

from aperturelighting import (vtkAperturePrecompute, vtkApertureLightingInterface,
                              vtkApertureLightingMapper, vtkCompositeApertureLightingMapper)


def main():
    failures = []

    # A ball resting on a floor: the floor around the contact point is partly closed.
    ball = vtkSphereSource()
    ball.SetCenter(0, 0, 0.5)
    ball.SetThetaResolution(32)
    ball.SetPhiResolution(16)
    floor = vtkPlaneSource()
    floor.SetOrigin(-2, -2, 0)
    floor.SetPoint1(2, -2, 0)
    floor.SetPoint2(-2, 2, 0)
    floor.SetResolution(40, 40)
    scene = vtkAppendPolyData()
    scene.AddInputConnection(ball.GetOutputPort())
    scene.AddInputConnection(floor.GetOutputPort())
    apertures = vtkAperturePrecompute()
    apertures.SetInputConnection(scene.GetOutputPort())
    apertures.SetNumberOfRays(64)

    mapper = vtkApertureLightingMapper()
    mapper.SetInputConnection(apertures.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    sun = vtkLight()
    sun.SetLightTypeToSceneLight()
    # A low sun: the ball blocks directions near the floor's horizon, which apertures capture (a
    # high sun over a small ball is the paper's limitation: a cap cannot hold the hole).
    sun.SetPosition(1, 0.2, 0.3)
    sun.SetFocalPoint(0, 0, 0)
    renderer.AddLight(sun)
    vtkApertureLightingMapper.SetLightRadius(sun, 0.1)
    if abs(vtkApertureLightingMapper.GetLightRadius(sun) - 0.1) > 1e-12:
        failures.append("the light radius does not travel on the light")
    if vtkApertureLightingMapper.GetLightRadius(vtkLight()) != -1.0:
        failures.append("a light without a radius must report -1")
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(160, 120)
    window.AddRenderer(renderer)
    renderer.GetActiveCamera().SetPosition(0, -4, 3)
    renderer.ResetCamera()

    def image():
        window.Render()
        grab = vtkWindowToImageFilter()
        grab.SetInput(window)
        grab.Update()
        return vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).astype(float)

    mapper.SetShadingModeToStandard()
    standard = image()
    for mode in ("Exact", "Smoothstep", "Simplified", "BentNormal"):
        getattr(mapper, "SetShadingModeTo" + mode)()
        shaded = image()
        difference = np.abs(shaded - standard).mean()
        print(mode, "differs from standard by", difference, "/255 on average")
        if not (shaded.mean() > 10 and difference > 0.5):
            failures.append(f"{mode}: apertures must darken the contact region ({difference})")

    composite = vtkCompositeApertureLightingMapper()
    lighting = composite.GetApertureLighting()
    if not isinstance(lighting, vtkApertureLightingInterface):
        failures.append("the composite mapper must expose its vtkApertureLightingInterface")
    lighting.SetShadingModeToSmoothstep()
    if lighting.GetShadingModeAsString() != "Smoothstep":
        failures.append("settings of the composite mapper do not stick")

    for f in failures:
        print("FAIL", f, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
