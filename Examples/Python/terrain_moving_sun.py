"""Mount Fuji through a day: per-texel apertures on a height field, lit by a moving sun.

    python3 terrain_moving_sun.py [fuji-terrain-rgb.png] [picture.png]

Reads a Terrain-RGB tile (vtkTerrainRGBReader), computes one aperture per texel
(vtkAperturePrecompute on the grid), and draws the raised surface with
vtkApertureLightingMapper reading the apertures from the grid as a texture. The apertures are
computed once; the sun moves freely. With a picture name it writes four times of day side by
side; otherwise the sun crosses the sky in a window until you press q.
"""

import math
import os
import sys

from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersCore import vtkImageAppend, vtkPolyDataNormals
from vtkmodules.vtkFiltersGeneral import vtkWarpScalar
from vtkmodules.vtkFiltersGeometry import vtkImageDataGeometryFilter
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkInteractionStyle import vtkInteractorStyleTrackballCamera
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkRenderWindow,
                                         vtkRenderWindowInteractor, vtkRenderer,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL factory)

from aperturelighting import (vtkAperturePrecompute, vtkApertureLightingMapper,
                              vtkTerrainRGBReader)

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_TILE = os.path.join(HERE, "..", "..", "Testing", "Data", "fuji-terrain-rgb.png")


def place_sun(sun, hour):
    """The sun at an hour of the day (6 to 18): rising in the east, highest at noon in the south."""
    t = (hour - 6.0) / 12.0
    azimuth = math.radians(90.0 + 180.0 * t)
    elevation = math.radians(3.0 + 52.0 * math.sin(math.pi * t))
    # Compass: x east, y north, z up.
    sun.SetFocalPoint(0.0, 0.0, 0.0)
    sun.SetPosition(math.cos(elevation) * math.sin(azimuth),
                    math.cos(elevation) * math.cos(azimuth), math.sin(elevation))
    warm = math.sin(math.pi * t)  # low sun, warmer light
    sun.SetColor(1.0, 0.75 + 0.22 * warm, 0.5 + 0.42 * warm)


def main(tile, picture=None):
    reader = vtkTerrainRGBReader()  # heights in metres on a 60 m grid
    reader.SetFileName(tile)
    reader.SetSpacing(60.0, 60.0)

    exaggeration = 1.5
    apertures = vtkAperturePrecompute()  # one aperture per texel of the grid
    apertures.SetInputConnection(reader.GetOutputPort())
    apertures.SetHeightScale(exaggeration)
    apertures.SetNumberOfRays(128)
    apertures.Update()
    grid = apertures.GetOutputDataObject(0)
    if not isinstance(grid, vtkImageData) or grid.GetNumberOfPoints() == 0:
        print(f"Could not compute apertures for {tile}", file=sys.stderr)
        return 1

    # The surface, raised as the precompute raised it; the mapper reads the apertures from the
    # grid (per texel) with texture coordinates generated from x and y.
    surface = vtkImageDataGeometryFilter()
    surface.SetInputData(grid)
    warp = vtkWarpScalar()
    warp.SetInputConnection(surface.GetOutputPort())
    warp.SetScaleFactor(exaggeration)
    warp.UseNormalOn()  # straight up, not along the grid's normals
    warp.SetNormal(0.0, 0.0, 1.0)
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(warp.GetOutputPort())
    normals.SplittingOff()
    mapper = vtkApertureLightingMapper()
    mapper.SetInputConnection(normals.GetOutputPort())
    mapper.SetApertureImage(grid)
    mapper.ScalarVisibilityOff()
    mapper.SetSkyColor(0.55, 0.65, 0.85)
    mapper.SetSkyIntensity(0.35)
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.9, 0.86, 0.78)

    sun = vtkLight()
    sun.SetLightTypeToSceneLight()
    sun.SetPositional(False)
    vtkApertureLightingMapper.SetLightRadius(sun, 0.0047)

    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.AddLight(sun)
    renderer.SetBackground(0.09, 0.1, 0.12)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(15330.0, 15330.0, 0.0)
    camera.SetPosition(9000.0, -14000.0, 20000.0)
    camera.SetViewUp(0.0, 0.0, 1.0)
    renderer.ResetCamera()
    camera.Zoom(2.0)

    window = vtkRenderWindow()
    window.AddRenderer(renderer)
    window.SetWindowName("ApertureLighting: Mount Fuji through a day")

    if picture:
        # Four times of day side by side.
        window.SetOffScreenRendering(1)
        window.SetSize(480, 320)
        day = vtkImageAppend()
        day.SetAppendAxis(0)
        for hour in (7.0, 10.0, 14.0, 17.5):
            place_sun(sun, hour)
            window.Render()
            grab = vtkWindowToImageFilter()
            grab.SetInput(window)
            grab.ReadFrontBufferOff()
            grab.Update()
            frame = vtkImageData()
            frame.DeepCopy(grab.GetOutput())
            day.AddInputData(frame)
        writer = vtkPNGWriter()
        writer.SetInputConnection(day.GetOutputPort())
        writer.SetFileName(picture)
        writer.Write()
        print("wrote", picture)
        return 0

    window.SetSize(1024, 640)
    interactor = vtkRenderWindowInteractor()
    interactor.SetRenderWindow(window)
    interactor.SetInteractorStyle(vtkInteractorStyleTrackballCamera())
    state = {"hour": 6.0}
    place_sun(sun, state["hour"])

    def tick(_caller, _event):
        state["hour"] = 6.0 if state["hour"] >= 18.0 else state["hour"] + 0.1
        place_sun(sun, state["hour"])
        window.Render()

    interactor.AddObserver("TimerEvent", tick)
    window.Render()
    interactor.CreateRepeatingTimer(40)
    print("The sun crosses the sky; drag to orbit, q to quit.")
    interactor.Start()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else DEFAULT_TILE,
                  sys.argv[2] if len(sys.argv) > 2 else None))
