"""An "Aperture Volume" drawn in pieces gives the serial picture: occluders on other ranks shade.

    mpirun -np 1 pvbatch --symmetric TestDistributedVolume.py <plugin .so> <work>
    mpirun -np 2 pvbatch --symmetric TestDistributedVolume.py <plugin .so> <work>

A deep round well in a block (DEEP_WELL), seen from straight above under one scene light 45
degrees from the zenith: the well's floor sees the sky within 15 degrees of the zenith, so it
lies in the walls' shadow. The XML reader splits the volume along z, its longest axis: on two
ranks the floor and the walls' lowest 6 voxels are one rank's piece, the rest of the walls the
other's. Alone, that floor would see the sky within 50 degrees of the zenith and the light.
The serial run (one rank) writes the reference picture, after checking the shadow: the floor at
most half as bright as the block's top. The distributed run checks that the floor's rank read
its piece with the apertures' halo as ghost levels (up to the walls' top), the shadow, and that
its picture (IceT composites the pieces) is the serial one within noise.
"""

import os
import sys

import numpy as np
import paraview.simple as pvs
from paraview import servermanager
from aperture_test_data import DEEP_WELL, read_png, shot, volume_from_above, write_well_volume
from vtkmodules.vtkRenderingCore import vtkCoordinate

SIZE = 300
REACH = 12.0  # the Occluder Reach (MaximumDistance) in voxels: 1.5 times it is the halo
OPACITY = [0.0, 0.0, 0.5, 0.0, 40.0, 0.0, 0.5, 0.0, 60.0, 1.0, 0.5, 0.0, 100.0, 1.0, 0.5, 0.0]


def scene(work):
    path = os.path.join(work, "deep-well.vti")
    process = servermanager.vtkProcessModule.GetProcessModule()
    if process.GetPartitionId() == 0:
        write_well_volume(path, DEEP_WELL)
    process.GetGlobalController().Barrier()
    source = pvs.OpenDataFile(path)
    view, light, display, _ = volume_from_above(
        source, SIZE, OPACITY, DEEP_WELL["centre"], 0.5 * DEEP_WELL["dimensions"][1])
    light.Position = [1.0, 0.0, 1.0]  # 45 degrees from the zenith
    display.SetRepresentationType("Aperture Volume")
    display.ApertureVolumeMaximumDistance = REACH
    return source, view


def brightness(picture, view, x, y, z, half=3):
    """The mean brightness of the picture about the world point's pixel."""
    coordinate = vtkCoordinate()
    coordinate.SetCoordinateSystemToWorld()
    coordinate.SetValue(x, y, z)
    column, row = (int(round(v)) for v in coordinate.GetComputedDoubleDisplayValue(
        view.GetRenderer()))
    return picture[row - half:row + half + 1, column - half:column + half + 1].mean()


def floor_over_top(picture, view):
    """The well's floor over the block's top (1: as bright)."""
    floor = brightness(picture, view, *DEEP_WELL["centre"], DEEP_WELL["floor"])
    top = brightness(picture, view, 6.0, 6.0, DEEP_WELL["top"])
    return floor / top


def main(plugin, work):
    process = servermanager.vtkProcessModule.GetProcessModule()
    rank, ranks = process.GetPartitionId(), process.GetNumberOfLocalPartitions()
    pvs.LoadPlugin(plugin, remote=False)
    if rank == 0:
        os.makedirs(work, exist_ok=True)
    process.GetGlobalController().Barrier()
    source, view = scene(work)
    picture = shot(view, work, f"deep-well-np{ranks}", SIZE)
    # The reader's output is the last piece the representation asked for, ghosts included.
    extent = source.GetClientSideObject().GetOutputDataObject(0).GetExtent()
    print(f"rank {rank} of {ranks}: the reader's z extent {extent[4]}..{extent[5]}", flush=True)
    failures = []
    holds_floor = extent[4] <= DEEP_WELL["floor"] <= extent[5]
    if holds_floor and extent[5] < DEEP_WELL["top"]:
        failures.append(f"the floor's piece ends at z = {extent[5]}, below the walls' top")
    if rank != 0:
        return report(rank, failures)
    ratio = floor_over_top(picture, view)
    print(f"{ranks} rank(s): the well's floor over the block's top {ratio:.3f} (goal 0.5 at most)",
          flush=True)
    if ratio > 0.5:
        failures.append(f"the walls' shadow on the floor is missing ({ratio:.3f})")
    reference = os.path.join(work, "deep-well-np1.png")
    if ranks > 1 and not os.path.exists(reference):
        failures.append("no serial picture: run this with one rank first")
    elif ranks > 1:
        difference = np.abs(picture - read_png(reference))
        print(f"{ranks} ranks against one: mean |difference| {difference.mean():.3f} levels "
              f"(goal 0.5), 99th percentile {np.percentile(difference, 99):.0f}, largest "
              f"{difference.max():.0f}", flush=True)
        if difference.mean() > 0.5:
            failures.append("the distributed picture differs from the serial one")
    return report(rank, failures)


def report(rank, failures):
    for failure in failures:
        print(f"FAIL rank {rank}: {failure}", flush=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:3]))
