"""A volume under one light: VTK's shading, the aperture mapper and the Monte-Carlo reference.

    xvfb-run -a python3 Utilities/Pictures/volume_reference.py VOLUME PICTURE [options]

Five panels of one view: VTK 9.1's gradient Phong shading; vtkApertureVolumeMapper (exact); the
light each voxel's own cap gives (the mapper's formula per voxel) drawn as the colour of an
unshaded volume, with the voxels' light interpolated between them; the reference drawn the same
way, the light vtkVolumeApertureReference gives (rays marched through the transmittance over the
light's cap, on one voxel in --step along each axis, trilinear between them); and |mapper −
reference| four times brighter. All under one directional light from over the viewer's left
shoulder (angular radius --light-radius), white, Diffuse 1 and no ambient or specular term, with
one opacity ramp (--ramp LOW:HIGH, opaque at HIGH over one voxel; by default 20% to 50% of the
scalar range) and one sample distance. Prints the mean |picture − reference| over the pixels that
either draws, in levels and over the reference's mean there, for the mapper (as set by default),
the mapper blending its voxels' light rather than their caps (InterpolateLight on), the mapper
reading its apertures in place (SurfaceOffset 0) with light and with caps blended, the voxels' caps
and no shadow.

The build's Python package must be on the path (PYTHONPATH=build/lib/python3.11/dist-packages).
"""

import argparse
import math
import sys

import numpy as np
from aperturelighting import (vtkApertureVolumeMapper, vtkSphericalCap,
                              vtkVolumeAperturePrecompute, vtkVolumeApertureReference)
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction
from vtkmodules.vtkImagingCore import vtkImageReslice
from vtkmodules.vtkIOImage import vtkImageReader2Factory, vtkNIFTIImageReader, vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLImageDataReader
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkLight, vtkRenderer,
                                         vtkRenderWindow, vtkVolume, vtkVolumeProperty,
                                         vtkWindowToImageFilter)
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkOpenGLGPUVolumeRayCastMapper
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factories)


def read_volume(path):
    if path.endswith((".nii", ".nii.gz")):
        reader = vtkNIFTIImageReader()
    elif path.endswith(".vti"):
        reader = vtkXMLImageDataReader()
    else:
        reader = vtkImageReader2Factory.CreateImageReader2(path)
    if reader is None:
        sys.exit(f"{path}: not a volume VTK reads")
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def opacity_property(low, high, unit):
    """A white volume property with the ramp, lit by Diffuse alone."""
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(low, 0.0)
    opacity.AddPoint(high, 1.0)
    color = vtkColorTransferFunction()
    color.AddRGBPoint(low, 1.0, 1.0, 1.0)
    color.AddRGBPoint(high, 1.0, 1.0, 1.0)
    prop = vtkVolumeProperty()
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(unit)
    prop.SetColor(color)
    prop.SetInterpolationTypeToLinear()
    prop.ShadeOn()
    prop.SetAmbient(0.0)
    prop.SetDiffuse(1.0)
    prop.SetSpecular(0.0)
    return prop


def reference_light(volume, prop, light, radius, step, samples):
    """The light each voxel gets according to vtkVolumeApertureReference, on every step-th voxel
    and trilinear between them, on the volume's grid."""
    reference = vtkVolumeApertureReference()
    reference.SetInputData(volume)
    reference.SetVolumeProperty(prop)
    reference.SetLightDirection(*light)
    reference.SetLightRadius(radius)
    reference.SetSampleStep(step)
    reference.SetNumberOfSamples(samples)
    reference.Update()
    sampled = reference.GetOutput()
    sampled.GetPointData().SetActiveScalars("ReferenceIrradiance")  # what reslicing interpolates
    reslice = vtkImageReslice()
    reslice.SetInputData(sampled)
    reslice.SetInformationInput(volume)
    reslice.SetInterpolationModeToLinear()
    reslice.Update()
    return vtk_to_numpy(reslice.GetOutput().GetPointData().GetScalars()).astype(np.float32)


def cap_light(volume, prop, light, radius):
    """The light each voxel gets according to its own aperture (the mapper's exact formula at
    the voxel, without the interpolation between voxels that the mapper's samples do)."""
    precompute = vtkVolumeAperturePrecompute()
    precompute.SetInputData(volume)
    precompute.SetVolumeProperty(prop)
    precompute.Update()
    data = precompute.GetOutput().GetPointData()
    bent = vtk_to_numpy(data.GetArray("BentNormal"))
    apertures = vtk_to_numpy(data.GetArray("ApertureRadius"))
    angles = np.arccos(np.clip(bent @ np.asarray(light), -1.0, 1.0))
    area = vtkSphericalCap.SolidAngleFromCapRadius(radius)
    return np.array([vtkSphericalCap.IntersectionArea(float(r), radius, float(d)) / area
                     for r, d in zip(apertures, angles)], dtype=np.float32)


def emission_volume(volume, prop, light_values):
    """Two components on the volume's grid, the light and the volume's scalars, and the property
    that draws the light as the colour (grey, 1 white) through the volume's opacity, unshaded."""
    scalars = vtk_to_numpy(volume.GetPointData().GetScalars()).astype(np.float32)
    pair = vtkImageData()
    pair.CopyStructure(volume)
    pair.GetPointData().SetScalars(numpy_to_vtk(np.stack([light_values, scalars], axis=1),
                                                deep=1))
    drawn = vtkVolumeProperty()
    drawn.IndependentComponentsOff()  # the first component is the colour, the second opacity
    drawn.SetScalarOpacity(prop.GetScalarOpacity())
    drawn.SetScalarOpacityUnitDistance(prop.GetScalarOpacityUnitDistance())
    grey = vtkColorTransferFunction()
    grey.AddRGBPoint(0.0, 0.0, 0.0, 0.0)
    grey.AddRGBPoint(1.0, 1.0, 1.0, 1.0)
    drawn.SetColor(grey)
    drawn.SetInterpolationTypeToLinear()
    drawn.ShadeOff()
    return pair, drawn


def render(data, mapper, prop, camera, light, size, distance):
    """One picture (height x width x 3 floats) of the data through the mapper."""
    mapper.SetInputData(data)
    mapper.AutoAdjustSampleDistancesOff()
    mapper.SetSampleDistance(distance)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    renderer = vtkRenderer()
    renderer.SetBackground(0.0, 0.0, 0.0)
    renderer.AddVolume(volume)
    renderer.SetActiveCamera(camera)
    renderer.AddLight(light)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(*size)
    window.AddRenderer(renderer)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    pixels = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())
    return pixels.reshape(size[1], size[0], -1)[:, :, :3].astype(float)


def write_png(path, picture):
    image = vtkImageData()
    image.SetDimensions(picture.shape[1], picture.shape[0], 1)
    image.GetPointData().SetScalars(numpy_to_vtk(
        np.clip(picture, 0, 255).astype(np.uint8).reshape(-1, 3).copy(), deep=1))
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("volume")
    parser.add_argument("picture")
    parser.add_argument("--size", default="400x400")
    parser.add_argument("--ramp", help="LOW:HIGH, opaque at HIGH")
    parser.add_argument("--light-radius", type=float, default=0.1, help="radians")
    parser.add_argument("--step", type=int, default=2, help="reference on every step-th voxel")
    parser.add_argument("--samples", type=int, default=64, help="reference rays a voxel")
    parser.add_argument("--azimuth", type=float, default=0.0, help="camera turn (degrees)")
    parser.add_argument("--elevation", type=float, default=0.0, help="camera tilt (degrees)")
    parser.add_argument("--check", action="store_true",
                        help="fail unless the voxels' caps are much nearer the reference than "
                        "no shadow, the mapper blending light and reading in place is about as "
                        "near as they are, and blending light is nearer than blending caps")
    args = parser.parse_args()
    size = [int(v) for v in args.size.split("x")]
    volume = read_volume(args.volume)
    low, high = volume.GetScalarRange()
    if args.ramp:
        low, high = (float(v) for v in args.ramp.split(":"))
    else:
        low, high = low + 0.2 * (high - low), low + 0.5 * (high - low)
    unit = min(volume.GetSpacing())
    prop = opacity_property(low, high, unit)

    renderer = vtkRenderer()  # only to frame the camera on the volume
    probe = vtkVolume()
    probe.SetMapper(vtkOpenGLGPUVolumeRayCastMapper())
    probe.GetMapper().SetInputData(volume)
    renderer.AddVolume(probe)
    renderer.ResetCamera()
    camera = renderer.GetActiveCamera()
    camera.Azimuth(args.azimuth)
    camera.Elevation(args.elevation)
    camera.OrthogonalizeViewUp()
    renderer.ResetCamera()
    camera.Zoom(1.3)
    # Toward the light: over the viewer's left shoulder.
    forward = np.subtract(camera.GetFocalPoint(), camera.GetPosition())
    forward /= np.linalg.norm(forward)
    up = np.array(camera.GetViewUp())
    right = np.cross(forward, up)
    toward = -0.5 * forward + 0.7 * up - 0.5 * right
    toward /= np.linalg.norm(toward)
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(0)
    light.SetFocalPoint(0.0, 0.0, 0.0)
    light.SetPosition(*toward)
    light.SetIntensity(1.0)

    distance = 0.5 * unit
    phong = render(volume, vtkOpenGLGPUVolumeRayCastMapper(), prop, camera, light, size,
                   distance)
    mapper = vtkApertureVolumeMapper()
    mapper.SetLightRadius(args.light_radius)
    mapper.SetSkyColor(0.0, 0.0, 0.0)
    aperture = render(volume, mapper, prop, camera, light, size, distance)
    mapper.InterpolateLightOn()
    blended_light = render(volume, mapper, prop, camera, light, size, distance)
    mapper.SetSurfaceOffset(0.0)
    in_place = render(volume, mapper, prop, camera, light, size, distance)
    mapper.InterpolateLightOff()
    caps_in_place = render(volume, mapper, prop, camera, light, size, distance)
    emitted = {}
    for name, values in (
            ("reference", reference_light(volume, prop, toward, args.light_radius, args.step,
                                          args.samples)),
            ("voxels' caps", cap_light(volume, prop, toward, args.light_radius)),
            ("no shadow", np.ones(volume.GetNumberOfPoints(), dtype=np.float32))):
        pair, drawn = emission_volume(volume, prop, values)
        emitted[name] = render(pair, vtkOpenGLGPUVolumeRayCastMapper(), drawn, camera, light,
                               size, distance)
    reference = emitted["reference"]
    print(f"{args.volume}: light radius {args.light_radius} rad, reference {args.samples} rays "
          f"on one voxel in {args.step} along each axis")
    errors = {}
    for name, picture in (
            ("the mapper", aperture),
            ("the mapper, light interpolated (InterpolateLight on)", blended_light),
            ("the mapper, light interpolated, read in place (SurfaceOffset 0)", in_place),
            ("the mapper, caps interpolated, read in place", caps_in_place),
            ("the voxels' caps drawn as the reference", emitted["voxels' caps"]),
            ("no shadow (light 1 everywhere) drawn so", emitted["no shadow"])):
        drawn_pixels = (picture.max(axis=2) > 2) | (reference.max(axis=2) > 2)
        mean = np.abs(picture - reference)[drawn_pixels].mean()
        errors[name] = mean / reference[drawn_pixels].mean()
        print(f"{name} against the reference over {drawn_pixels.mean():.0%} of the picture: mean "
              f"|difference| {mean:.1f} levels, {errors[name]:.1%} of the reference's mean")
    caps = errors["the voxels' caps drawn as the reference"]
    both = errors["the mapper, light interpolated, read in place (SurfaceOffset 0)"]
    checks = (
        (caps < 0.25 * errors["no shadow (light 1 everywhere) drawn so"],
         "the caps' light is not nearer the reference than no shadow at all"),
        # Read in place, the mapper blends the voxels' light as the emission volume does.
        (both < 1.1 * caps, "the mapper read in place is further from the reference than the "
         "voxels' caps"),
        (errors["the mapper, light interpolated (InterpolateLight on)"] < errors["the mapper"],
         "blending the voxels' light is not nearer the reference than blending their caps"))
    failed = False
    for passed, why in checks if args.check else ():
        if not passed:
            print(f"FAIL: {why}")
            failed = True
    write_png(args.picture, np.concatenate(
        [phong, aperture, emitted["voxels' caps"], reference,
         4.0 * np.abs(aperture - reference)], axis=1))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
