"""A 2-rank pvbatch run gives the serial answer.

    mpirun -np 2 pvbatch --symmetric TestDistributedPvbatch.py <plugin .so> <Testing/Data>

The bunny's OBJ reader reads on rank 0 only: Aperture Precompute on it is the serial run, and
rank 1's empty piece must give an empty output, not an error. The same bunny after Redistribute
Data Set (a spatial split over the ranks) and Extract Surface gives each rank its piece;
Aperture Precompute there gathers the other rank's surface as occluders. Rank 0 fetches both
and compares every point through the ids Generate Ids gave it: mean |difference| of
ApertureRadius <= 0.01 rad and 99th percentile <= 0.03 (issue 17's goals). Then a DEM read in
pieces (the GDAL reader splits its extent over the ranks) must give every rank its part of the
grid, with the analytic aperture on a valley's floor.
"""

import math
import os
import sys
import tempfile

import numpy as np
import paraview.simple as pvs
from paraview import servermanager
from aperture_test_data import write_valley
from vtkmodules.util.numpy_support import vtk_to_numpy


def local_points(proxy):
    """The points of this rank's own piece."""
    return proxy.GetClientSideObject().GetOutputDataObject(0).GetNumberOfPoints()


def by_id(data):
    """ApertureRadius by point id, of the points that cells use (a point split at a crease has
    several values; Extract Surface drops the file's unused points)."""
    ids = vtk_to_numpy(data.GetPointData().GetArray("Ids"))
    radius = vtk_to_numpy(data.GetPointData().GetArray("ApertureRadius"))
    connectivity = vtk_to_numpy(data.GetPolys().GetConnectivityArray())
    values = {}
    for point in np.unique(connectivity):
        values.setdefault(int(ids[point]), []).append(float(radius[point]))
    return values


def height_field(rank, ranks):
    """A DEM in pieces: a cone-shaped valley (slope 0.3) written by rank 0 as an ESRI grid. Each
    rank must get a part of the grid (its extent, from the whole grid's horizons) and the floor
    the analytic aperture pi/2 - atan(0.3)."""
    process = servermanager.vtkProcessModule.GetProcessModule()
    n = 48
    grid = os.path.join(tempfile.gettempdir(), f"aperture-valley-{os.getppid()}.asc")
    if rank == 0:
        write_valley(grid, n, 0.3)
    process.GetGlobalController().Barrier()
    valley = pvs.AperturePrecompute(Input=pvs.GDALDEMReader(FileName=grid))
    valley.UpdatePipeline()
    failures = []
    local = local_points(valley)
    print(f"rank {rank}: {local} of the DEM's {n * n} texels", flush=True)
    if not 0 < local < n * n:
        failures.append(f"rank {rank}: {local} texels of the DEM, not a part of it")
    # The rank whose extent holds the floor checks it.
    image = valley.GetClientSideObject().GetOutputDataObject(0)
    extent = image.GetExtent()
    if extent[0] <= n // 2 <= extent[1] and extent[2] <= n // 2 <= extent[3]:
        radius = image.GetPointData().GetArray("ApertureRadius")
        floor = radius.GetValue(image.ComputePointId([n // 2, n // 2, 0]))
        expected = math.pi / 2 - math.atan(0.3)  # write_valley's floor
        print(f"rank {rank}: the DEM's floor has the aperture {floor:.4f}, analytic "
              f"{expected:.4f}", flush=True)
        if abs(floor - expected) > 0.03:
            failures.append("the DEM's floor differs from the analytic aperture")
    process.GetGlobalController().Barrier()
    if rank == 0:
        os.remove(grid)
    return failures


def main(plugin, data):
    process = servermanager.vtkProcessModule.GetProcessModule()
    rank, ranks = process.GetPartitionId(), process.GetNumberOfLocalPartitions()
    pvs.LoadPlugin(plugin, remote=False)
    bunny = pvs.GenerateIds(Input=pvs.OpenDataFile(data + "/stanford-bunny.obj"),
                            PointIdsArrayName="Ids")
    serial = pvs.AperturePrecompute(Input=bunny, NumberOfRays=256)
    serial.UpdatePipeline()
    split = pvs.ExtractSurface(Input=pvs.RedistributeDataSet(Input=bunny))
    distributed = pvs.AperturePrecompute(Input=split, NumberOfRays=256)
    distributed.UpdatePipeline()
    print(f"rank {rank} of {ranks}: {local_points(serial)} points in the serial run's piece, "
          f"{local_points(distributed)} in the redistributed piece", flush=True)
    failures = []
    if ranks < 2:
        failures.append("not distributed: run it with mpirun -np 2 pvbatch --symmetric")
    if rank > 0 and local_points(serial) != 0:
        failures.append(f"rank {rank}: an empty piece gave {local_points(serial)} points")
    if local_points(distributed) == 0:
        failures.append(f"rank {rank}: no piece after Redistribute Data Set")

    serial_data = servermanager.Fetch(serial)
    distributed_data = servermanager.Fetch(distributed)
    if rank == 0:
        expected = by_id(serial_data)
        got = by_id(distributed_data)
        differences = np.array([min(abs(g - e) for e in expected[i]) for i, values in got.items()
                                for g in values])
        missing = set(expected) - set(got)
        mean = differences.mean()
        p99 = np.percentile(differences, 99)
        print(f"{len(differences)} points compared, {len(missing)} missing: mean |difference| "
              f"{mean:.5f} rad (goal 0.01), 99th percentile {p99:.5f} (goal 0.03), largest "
              f"{differences.max():.4f}", flush=True)
        if missing or mean > 0.01 or p99 > 0.03:
            failures.append("the distributed run differs from the serial one")
    failures += height_field(rank, ranks)
    for failure in failures:
        print(f"FAIL rank {rank}: {failure}", flush=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:3]))
