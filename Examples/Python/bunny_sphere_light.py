"""The Stanford bunny lit by a sphere light through ambient aperture lighting.

    python3 bunny_sphere_light.py [bunny.obj] [picture.png]

Computes the apertures once (vtkAperturePrecompute), then draws them with
vtkApertureLightingMapper. With a picture name it renders off screen and exits; otherwise it
opens a window: m switches shading models, l/L shrink or grow the light, q quits.
"""

import os
import sys

from vtkmodules.vtkIOGeometry import vtkOBJReader
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkInteractionStyle import vtkInteractorStyleTrackballCamera
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkRenderWindow,
                                         vtkRenderWindowInteractor, vtkRenderer,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL factory)

from aperturelighting import (vtkAperturePrecompute, vtkApertureLightingInterface,
                              vtkApertureLightingMapper)

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_BUNNY = os.path.join(HERE, "..", "..", "Testing", "Data", "stanford-bunny.obj")


def main(bunny, picture=None):
    reader = vtkOBJReader()
    reader.SetFileName(bunny)

    # The apertures: one visibility cap per vertex, 256 rays each.
    apertures = vtkAperturePrecompute()
    apertures.SetInputConnection(reader.GetOutputPort())
    apertures.SetNumberOfRays(256)
    apertures.AddObserver("ProgressEvent", lambda o, e: print(
        f"\rapertures: {100 * o.GetProgress():3.0f}%", end="", flush=True))
    apertures.Update()
    print()
    if apertures.GetPolyDataOutput().GetNumberOfPoints() == 0:
        print(f"Could not compute apertures for {bunny}", file=sys.stderr)
        return 1

    mapper = vtkApertureLightingMapper()
    mapper.SetInputConnection(apertures.GetOutputPort())
    mapper.SetShadingModeToExact()
    mapper.SetSkyColor(0.55, 0.65, 1.0)
    mapper.SetSkyIntensity(0.25)
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.95, 0.85, 0.75)

    # A sphere light of radius 0.04 to the upper right; its size travels on the light.
    lamp = vtkLight()
    lamp.SetLightTypeToSceneLight()
    lamp.SetPositional(True)
    lamp.SetConeAngle(180.0)
    lamp.SetPosition(0.2, 0.25, 0.1)
    lamp.SetColor(1.0, 0.9, 0.75)
    vtkApertureLightingMapper.SetLightRadius(lamp, 0.04)

    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.AddLight(lamp)
    renderer.SetBackground(0.12, 0.13, 0.16)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(-0.02, 0.12, 0.5)
    camera.SetFocalPoint(-0.02, 0.1, 0.0)
    renderer.ResetCamera()
    camera.Zoom(1.4)

    window = vtkRenderWindow()
    window.SetSize(800, 700)
    window.AddRenderer(renderer)
    window.SetWindowName("ApertureLighting: bunny and sphere light")

    if picture:
        window.SetOffScreenRendering(1)
        window.Render()
        grab = vtkWindowToImageFilter()
        grab.SetInput(window)
        writer = vtkPNGWriter()
        writer.SetInputConnection(grab.GetOutputPort())
        writer.SetFileName(picture)
        writer.Write()
        print("wrote", picture)
        return 0

    interactor = vtkRenderWindowInteractor()
    interactor.SetRenderWindow(window)
    interactor.SetInteractorStyle(vtkInteractorStyleTrackballCamera())

    def on_key(caller, _event):
        key = caller.GetKeySym()
        if key == "m":
            modes = vtkApertureLightingInterface.STANDARD + 1
            mapper.SetShadingMode((mapper.GetShadingMode() + 1) % modes)
            print("shading:", mapper.GetApertureLighting().GetShadingModeAsString())
        elif key in ("l", "L"):
            radius = vtkApertureLightingMapper.GetLightRadius(lamp)
            vtkApertureLightingMapper.SetLightRadius(lamp, radius / 1.5 if key == "l" else radius * 1.5)
            print("light radius:", vtkApertureLightingMapper.GetLightRadius(lamp))
        window.Render()

    interactor.AddObserver("KeyPressEvent", on_key)
    print("m: shading model, l/L: smaller/larger light, q: quit")
    window.Render()
    interactor.Start()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else DEFAULT_BUNNY,
                  sys.argv[2] if len(sys.argv) > 2 else None))
