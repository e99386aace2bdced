"""VTK 9.2's volumetric shadows against its own gradient shading, in ParaView 5.11's pvpython
(VTK 9.2), on one volume, view and sample distance, frames alternated: the frame-time ratio that
docs/volumes.md sets beside vtkApertureVolumeMapper's (which is built on VTK 9.1, so the two cannot
run in one process). Writes vtk92-shaded.png and vtk92-shadows.png.

Usage: source build-paraview/env.sh && xvfb-run -a pvpython vtk92_volumetric_shadows.py VOLUME.mha
"""

import sys
import time

import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL classes behind the factories)
from vtkmodules.vtkCommonCore import vtkVersion
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkIOImage import vtkMetaImageReader, vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderWindow, vtkRenderer,
                                         vtkVolume, vtkVolumeProperty, vtkWindowToImageFilter)
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkOpenGLGPUVolumeRayCastMapper

FRAMES = 7


def volume_property(image):
    """Opaque above 30% of the range, as BenchmarkVolumeAperture --frames sees a file."""
    low, high = image.GetScalarRange()
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(low + 0.3 * (high - low), 0.0)
    opacity.AddPoint(high, 1.0)
    color = vtkColorTransferFunction()
    color.AddRGBPoint(low, 0.9, 0.8, 0.7)
    color.AddRGBPoint(high, 1.0, 1.0, 1.0)
    prop = vtkVolumeProperty()
    prop.SetScalarOpacity(opacity)
    prop.SetColor(color)
    prop.SetScalarOpacityUnitDistance(image.GetSpacing()[0])
    prop.SetInterpolationTypeToLinear()
    prop.ShadeOn()
    return prop


def volume(image, prop, shadows):
    mapper = vtkOpenGLGPUVolumeRayCastMapper()
    mapper.SetInputData(image)
    mapper.AutoAdjustSampleDistancesOff()
    mapper.SetSampleDistance(0.5 * image.GetSpacing()[0])
    if shadows:
        mapper.SetGlobalIlluminationReach(0.2)
        mapper.SetVolumetricScatteringBlending(1.0)
    actor = vtkVolume()
    actor.SetMapper(mapper)
    actor.SetProperty(prop)
    return actor


def median_frame(window, renderer, actor):
    renderer.AddVolume(actor)
    window.Render()  # shaders and textures
    times = []
    for _ in range(FRAMES):
        actor.RotateZ(2.0)
        start = time.time()
        window.Render()
        times.append(time.time() - start)
    renderer.RemoveVolume(actor)
    return sorted(times)[FRAMES // 2]


def main():
    reader = vtkMetaImageReader()
    reader.SetFileName(sys.argv[1])
    reader.Update()
    image = reader.GetOutput()
    prop = volume_property(image)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(800, 600)
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    actors = {"shaded": volume(image, prop, False), "shadows": volume(image, prop, True)}
    renderer.AddVolume(actors["shaded"])
    renderer.ResetCamera()
    renderer.RemoveVolume(actors["shaded"])
    times = {name: 0.0 for name in actors}
    for _ in range(2):
        for name, actor in actors.items():
            times[name] += median_frame(window, renderer, actor) / 2
    print(f"VTK {vtkVersion.GetVTKVersion()}, 800 x 600: shaded {times['shaded']:.3f} s, "
          f"volumetric shadows {times['shadows']:.3f} s, "
          f"ratio {times['shadows'] / times['shaded']:.2f}")
    for name, actor in actors.items():
        renderer.AddVolume(actor)
        window.Render()
        grab = vtkWindowToImageFilter()
        grab.SetInput(window)
        writer = vtkPNGWriter()
        writer.SetInputConnection(grab.GetOutputPort())
        writer.SetFileName(f"vtk92-{name}.png")
        writer.Write()
        renderer.RemoveVolume(actor)


if __name__ == "__main__":
    main()
