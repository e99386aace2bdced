"""Test data the plugin's tests write themselves, their views, and the pictures they read back."""

import math
import os


def dark_view(size):
    """A render view of size x size pixels on a dark grey background, without axes."""
    import paraview.simple as pvs

    view = pvs.CreateRenderView(ViewSize=[size, size], OrientationAxesVisibility=0,
                                Background=[0.1, 0.1, 0.12])
    view.UseColorPaletteForBackground = 0
    return view


def volume_from_above(source, size, opacity_points, centre, scale):
    """The volume `source` (scalars "density") drawn white through the opacity points and lit by
    Diffuse alone, in a view of one directional scene light (the light kit off, intensity 0.6;
    the caller places it), seen straight down the z axis onto centre (x, y) in parallel
    projection of the given scale. Returns the view, the light, the display and the opacity."""
    import paraview.simple as pvs

    view = dark_view(size)
    view.UseLight = 0
    light = pvs.AddLight(view=view)
    light.Coords = "Scene"
    light.Type = "Directional"
    light.FocalPoint = [0.0, 0.0, 0.0]
    light.Intensity = 0.6
    display = pvs.Show(source, view)
    pvs.ColorBy(display, ("POINTS", "density"))
    top = opacity_points[-4]
    pvs.GetColorTransferFunction("density").RGBPoints = [0.0, 1, 1, 1, top, 1, 1, 1]
    opacity = pvs.GetOpacityTransferFunction("density")
    opacity.Points = opacity_points
    display.ScalarOpacityUnitDistance = 1.0
    display.Ambient = 0.0
    display.Diffuse = 1.0
    display.Specular = 0.0
    pvs.Render(view)  # the first render resets the camera: set it after
    view.CameraPosition = [centre[0], centre[1], 200.0]
    view.CameraFocalPoint = [centre[0], centre[1], 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = scale
    return view, light, display, opacity


def shot(view, work, name, size=400):
    """Renders the view and returns its size x size picture, written to work/name.png."""
    import paraview.simple as pvs

    path = os.path.join(work, name + ".png")
    pvs.Render(view)
    pvs.SaveScreenshot(path, view, ImageResolution=[size, size], TransparentBackground=0)
    return read_png(path)


def baseline_error(view, picture, baseline, size=400):
    """The picture's mean |difference| from the baseline PNG (infinite if their sizes differ);
    None after writing the baseline from the view where there was none (look at it)."""
    import numpy as np
    import paraview.simple as pvs

    if not os.path.exists(baseline):
        os.makedirs(os.path.dirname(baseline), exist_ok=True)
        pvs.SaveScreenshot(baseline, view, ImageResolution=[size, size], TransparentBackground=0)
        print(f"wrote the baseline {baseline}: look at it")
        return None
    expected = read_png(baseline)
    return np.abs(picture - expected).mean() if expected.shape == picture.shape else np.inf


def read_png(path):
    """A PNG's RGB pixels as floats (height x width x 3)."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader

    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())
    return pixels.reshape(height, width, -1)[:, :, :3].astype(float)


def write_valley(path, n=48, slope=0.3, cell=10.0):
    """An n x n ESRI ASCII grid of a cone-shaped valley rising at `slope` from its centre
    (n/2, n/2): its floor sees the sky above a cap of half-angle pi/2 - atan(slope)."""
    with open(path, "w") as f:
        f.write(f"ncols {n}\nnrows {n}\nxllcorner 0\nyllcorner 0\ncellsize {cell}\n"
                "NODATA_value -9999\n")
        for row in range(n):
            f.write(" ".join(f"{slope * cell * math.hypot(col - n / 2, row - n / 2):.2f}"
                             for col in range(n)) + "\n")
    return math.pi / 2 - math.atan(slope)


def write_cad_part(path):
    """A CAD part as a .vtp file: an L-shaped bracket (an extruded profile) with a cylindrical
    boss standing on its foot, each faceted as an STL file is (faces meeting at a crease share
    their points) and subdivided; 90-degree creases, concave corners and a contact."""
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    from vtkmodules.vtkFiltersCore import vtkAppendPolyData, vtkCleanPolyData, vtkTriangleFilter
    from vtkmodules.vtkFiltersModeling import (vtkLinearExtrusionFilter,
                                               vtkLinearSubdivisionFilter)
    from vtkmodules.vtkFiltersSources import vtkCylinderSource
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

    def faceted(source, levels):
        triangles = vtkTriangleFilter()
        triangles.SetInputConnection(source.GetOutputPort())
        merged = vtkCleanPolyData()
        merged.SetInputConnection(triangles.GetOutputPort())
        subdivided = vtkLinearSubdivisionFilter()
        subdivided.SetInputConnection(merged.GetOutputPort())
        subdivided.SetNumberOfSubdivisions(levels)
        subdivided.Update()
        return subdivided.GetOutput()

    profile = vtkPolyData()
    corners = vtkPoints()
    for x, y in ((0, 0), (4, 0), (4, 1), (1, 1), (1, 3), (0, 3)):
        corners.InsertNextPoint(x, y, 0.0)
    polygon = vtkCellArray()
    polygon.InsertNextCell(6, range(6))
    profile.SetPoints(corners)
    profile.SetPolys(polygon)
    bracket = vtkLinearExtrusionFilter()
    bracket.SetInputData(profile)
    bracket.SetExtrusionTypeToVectorExtrusion()
    bracket.SetVector(0.0, 0.0, 2.0)
    bracket.CappingOn()
    boss = vtkCylinderSource()  # along y, standing on the foot's top (y = 1)
    boss.SetRadius(0.5)
    boss.SetHeight(1.0)
    boss.SetCenter(2.5, 1.5, 1.0)
    boss.SetResolution(24)
    part = vtkAppendPolyData()
    part.AddInputData(faceted(bracket, 3))
    part.AddInputData(faceted(boss, 2))
    part.Update()
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(part.GetOutput())
    writer.Write()



# The well volume of write_well_volume: its grid, the well's centre, floor, top and radii.
WELL = {"dimensions": (64, 48, 24), "centre": (40.0, 24.0), "floor": 4.0, "top": 16.0,
        "radius": 4.0, "ring": 14.0, "block": 100.0, "ring_value": 200.0}


# A deeper well in a taller volume, for pieces split along z: its floor below the middle, its
# walls above (no ring).
DEEP_WELL = {"dimensions": (48, 48, 80), "centre": (24.0, 24.0), "floor": 34.0, "top": 57.0,
             "radius": 6.0, "ring": 6.0, "block": 100.0, "ring_value": 100.0}


def write_well_volume(path, s=WELL):
    """A .vti volume of unit voxels of the well s: a block (value 100) under z = top with a round
    well down to z = floor, its wall a ring (value 200) out to the ring radius, empty (0)
    elsewhere. The well's floor sees the sky within atan(radius / depth) of the zenith; with the
    ring transparent, within atan(ring / depth)."""
    import numpy as np

    nx, ny, nz = s["dimensions"]
    z, y, x = np.mgrid[0:nz, 0:ny, 0:nx].astype(float)
    rho = np.hypot(x - s["centre"][0], y - s["centre"][1])
    values = np.where(z < s["top"], s["block"], 0.0)
    shaft = (z >= s["floor"]) & (z < s["top"])
    values[shaft & (rho < s["ring"])] = s["ring_value"]
    values[shaft & (rho < s["radius"])] = 0.0
    write_volume(path, values)


def write_volume(path, values):
    """A .vti volume of unit voxels from a (z, y, x) array, its scalars named density."""
    from vtkmodules.vtkCommonDataModel import vtkImageData
    from vtkmodules.vtkIOXML import vtkXMLImageDataWriter
    from vtkmodules.util.numpy_support import numpy_to_vtk
    import numpy as np

    image = vtkImageData()
    image.SetDimensions(*reversed(values.shape))
    array = numpy_to_vtk(values.ravel().astype(np.float32), deep=1)
    array.SetName("density")
    image.GetPointData().SetScalars(array)
    writer = vtkXMLImageDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()
