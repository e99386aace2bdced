"""docs/images/terrain-10k.png: a 10,000 x 10,000 DEM rendered by aperture-render from a mesh of
at most 1,000 x 1,000 points, shaded per texel from the whole grid's horizon apertures.

    python3 big_terrain.py <aperture-render> <Testing/Data> <work folder> <docs/images>

The DEM is the Fuji tile resampled (cubic) to 10,000 x 10,000 over its 15.3 km, written as a
Float32 GeoTIFF tile by tile with vtkGDALGridWriter.
"""

import os
import subprocess
import sys

from aperturelighting import vtkGDALGridWriter, vtkTerrainRGBReader
from vtkmodules.vtkImagingCore import vtkImageChangeInformation, vtkImageResize

RENDER, DATA, WORK, IMAGES = sys.argv[1:5]
SIDE = 10000
os.makedirs(WORK, exist_ok=True)

tile = vtkTerrainRGBReader()
tile.SetFileName(os.path.join(DATA, "fuji-terrain-rgb.png"))
resize = vtkImageResize()
resize.SetInputConnection(tile.GetOutputPort())
resize.SetOutputDimensions(SIDE, SIDE, 1)
resize.InterpolateOn()
ground = vtkImageChangeInformation()
ground.SetInputConnection(resize.GetOutputPort())
spacing = 30.0 * 511 / (SIDE - 1)
ground.SetOutputSpacing(spacing, spacing, 1.0)
dem = os.path.join(WORK, "fuji-10k.tif")
writer = vtkGDALGridWriter()
writer.SetInputConnection(ground.GetOutputPort())
writer.SetFileName(dem)
writer.SetTileRows(1000)
if not writer.Write():
    sys.exit("cannot write " + dem)

subprocess.run([RENDER, dem, "-o", os.path.join(IMAGES, "terrain-10k.png"), "--size", "1280x800",
                "--height-scale", "1.5", "--sun", "285,16"], check=True)
os.remove(dem)
