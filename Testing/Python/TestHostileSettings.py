"""Every floating-point setting of every filter, set to NaN, an infinity or a vast value.

VTK's clamping setters let NaN through, and Python users set what they like. Whatever the value,
each filter must either fail with an error or give an output whose floating-point point arrays
are finite; a crash (Embree asserts on NaN rays) fails the whole test. The settings are found by
introspection, so new ones are covered without a change here.
"""

import math
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource

import aperturelighting as al

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Data")
VALUES = (math.nan, math.inf, -math.inf, 1e300, -1e300)
IGNORED = {"Progress"}  # vtkAlgorithm's own, not a setting


class Errors:
    """Counts the ErrorEvents of an algorithm, so that expected errors stay quiet."""

    CallDataType = "string0"

    def __init__(self, algorithm):
        self.count = 0
        algorithm.AddObserver("ErrorEvent", self)

    def __call__(self, _caller, _event, message=None):
        self.count += 1


def sphere():
    source = vtkSphereSource()
    source.SetThetaResolution(16)
    source.SetPhiResolution(8)
    return source


def terrain():
    reader = al.vtkTerrainRGBReader()
    reader.SetFileName(os.path.join(DATA, "fuji-terrain-rgb.png"))
    reader.SetSpacing(60.0, 60.0)
    return reader


def volume():
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(0, 11, 0, 11, 0, 11)
    return source


def visibility():
    rays = al.vtkOcclusionQueryVisibility()
    source = sphere()
    rays.SetInputConnection(source.GetOutputPort())
    rays.SetBackendToRayCast()
    rays.SetLevel(1)
    return rays


def environment():
    image = vtkImageData()
    image.SetDimensions(16, 8, 1)
    image.GetPointData().SetScalars(numpy_to_vtk(np.ones((128, 3), dtype=np.float32), deep=1))
    return image


def relight(filter):
    rays = visibility()
    filter.SetInputConnection(rays.GetOutputPort())
    filter.SetEnvironmentData(environment())


CASES = [
    ("vtkAperturePrecompute on a mesh", al.vtkAperturePrecompute, sphere),
    ("vtkAperturePrecompute on a height field", al.vtkAperturePrecompute, terrain),
    ("vtkApertureReference", al.vtkApertureReference, sphere),
    ("vtkLightSphereVisibility", al.vtkLightSphereVisibility, sphere),
    ("vtkOcclusionQueryVisibility (rays)", al.vtkOcclusionQueryVisibility, sphere),
    ("vtkEnvironmentVisibilityLighting", al.vtkEnvironmentVisibilityLighting, relight),
    ("vtkVolumeAperturePrecompute", al.vtkVolumeAperturePrecompute, volume),
    ("vtkVolumeApertureReference", al.vtkVolumeApertureReference, volume),
]


def settings(filter):
    """The names of the filter's floating-point Set/Get pairs."""
    names = []
    for method in dir(filter):
        name = method[3:]
        if method.startswith("Set") and name not in IGNORED and hasattr(filter, "Get" + name):
            try:
                value = getattr(filter, "Get" + name)()
            except TypeError:
                continue
            if isinstance(value, float):
                names.append(name)
    return names


def configure(cls, input):
    filter = cls()
    if input is relight:
        relight(filter)
    else:
        # A name for the source: a temporary would be freed before its port is used.
        source = input()
        filter.SetInputConnection(source.GetOutputPort())
    if cls is al.vtkOcclusionQueryVisibility:
        filter.SetBackendToRayCast()
        filter.SetLevel(1)
    if cls is al.vtkAperturePrecompute:
        filter.SetNumberOfRays(32)
    return filter


def nonfinite_arrays(output):
    data = output.GetPointData()
    names = []
    for i in range(data.GetNumberOfArrays()):
        array = data.GetArray(i)
        if array is not None:
            values = vtk_to_numpy(array)
            if values.dtype.kind == "f" and not np.isfinite(values).all():
                names.append(array.GetName())
    return names


def main():
    failures = []
    tried = 0
    for what, cls, input in CASES:
        for name in settings(cls()):
            for value in VALUES:
                filter = configure(cls, input)
                errors = Errors(filter)
                getattr(filter, "Set" + name)(value)
                filter.Update()
                tried += 1
                bad = [] if errors.count else nonfinite_arrays(filter.GetOutputDataObject(0))
                if bad:
                    failures.append(f"{what}: {name} = {value}: no error, and {bad} not finite")
    print(f"{tried} runs of {len(CASES)} filters")
    for failure in failures:
        print("FAIL " + failure)
    return 1 if failures or tried < 60 else 0


if __name__ == "__main__":
    sys.exit(main())
