"""A pvbatch run on several ranks gives the serial answer.

    mpirun -np 2 pvbatch --symmetric TestDistributedPvbatch.py <plugin .so> <Testing/Data> <work>

(also with -np 4). A surface read on rank 0 only (the bunny's OBJ reader, a CAD part's .vtp):
Aperture Precompute on it is the serial run, and the other ranks' empty pieces must give empty
outputs, not errors. The same surface after Redistribute Data Set (a spatial split over the
ranks) and Extract Surface gives each rank its piece; Aperture Precompute there gathers the
other ranks' surfaces, those around its border as part of its own surface. Rank 0 fetches both
and compares every point through the ids Generate Ids gave it: mean |difference| of
ApertureRadius <= 0.01 rad, 99th percentile <= 0.01 and largest <= 0.05 (issue 25's goals).
Both are drawn by the Aperture Lighting representation (IceT composites the ranks' pieces): the
pictures must agree within noise. Then a DEM read in pieces (the GDAL reader splits its extent
over the ranks) must give every rank its part of the grid, with the analytic aperture on a
valley's floor.
"""

import math
import os
import sys
import tempfile

import numpy as np
import paraview.simple as pvs
from paraview import servermanager
from aperture_test_data import dark_view, read_png, write_cad_part, write_valley
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


def compare(name, serial, distributed, rank):
    """Rank 0: every point of the distributed output against the serial one (collective)."""
    serial_data = servermanager.Fetch(serial)
    distributed_data = servermanager.Fetch(distributed)
    if rank != 0:
        return []
    expected = by_id(serial_data)
    got = by_id(distributed_data)
    differences = np.array([min(abs(g - e) for e in expected[i]) for i, values in got.items()
                            for g in values])
    missing = set(expected) - set(got)
    mean, p99, largest = differences.mean(), np.percentile(differences, 99), differences.max()
    print(f"{name}: {len(differences)} points compared, {len(missing)} missing: mean |difference| "
          f"{mean:.5f} rad (goal 0.01), 99th percentile {p99:.5f} (goal 0.01), largest "
          f"{largest:.4f} (goal 0.05)", flush=True)
    if missing or mean > 0.01 or p99 > 0.01 or largest > 0.05:
        return [f"{name}: the distributed run differs from the serial one"]
    return []


def pictures(name, serial, distributed, work, rank):
    """Both outputs drawn by the Aperture Lighting representation (collective: IceT composites
    every rank's piece); rank 0 compares the pictures."""
    view = dark_view(300)
    shots = []
    for source in (serial, distributed):
        display = pvs.Show(source, view)
        display.ColorArrayName = ["POINTS", ""]
        display.SetRepresentationType("Aperture Lighting")
        display.ApertureShadingMode = "Exact"
        view.ResetCamera()
        path = os.path.join(work, f"{name.replace(' ', '-')}-{len(shots)}.png")
        pvs.SaveScreenshot(path, view, ImageResolution=[300, 300], TransparentBackground=0)
        pvs.Hide(source, view)
        shots.append(path)
    pvs.Delete(view)
    if rank != 0:
        return []
    one, pieces = (read_png(path) for path in shots)
    lit = (one.max(axis=2) > 40).mean()
    mean = np.abs(one - pieces).mean()
    largest = np.abs(one - pieces).max()
    print(f"{name}: pictures of the serial and the distributed output: mean |difference| "
          f"{mean:.3f} levels (goal 0.5), largest {largest:.0f}; {lit:.0%} of the pixels lit",
          flush=True)
    failures = []
    if lit < 0.1:
        failures.append(f"{name}: the picture shows nothing")
    if mean > 0.5:
        failures.append(f"{name}: the pictures differ")
    return failures


def check_surface(name, reader, work, rank):
    """The serial and the distributed precompute of one surface, and their pictures."""
    surface = pvs.GenerateIds(Input=reader, PointIdsArrayName="Ids")
    serial = pvs.AperturePrecompute(Input=surface, NumberOfRays=256)
    serial.UpdatePipeline()
    split = pvs.ExtractSurface(Input=pvs.RedistributeDataSet(Input=surface))
    distributed = pvs.AperturePrecompute(Input=split, NumberOfRays=256)
    distributed.UpdatePipeline()
    print(f"{name}, rank {rank}: {local_points(serial)} points in the serial run's piece, "
          f"{local_points(distributed)} in the redistributed piece", flush=True)
    failures = []
    if rank > 0 and local_points(serial) != 0:
        failures.append(f"{name}, rank {rank}: an empty piece gave {local_points(serial)} points")
    if local_points(distributed) == 0:
        failures.append(f"{name}, rank {rank}: no piece after Redistribute Data Set")
    failures += compare(name, serial, distributed, rank)
    failures += pictures(name, serial, distributed, work, rank)
    return failures


def main(plugin, data, work):
    process = servermanager.vtkProcessModule.GetProcessModule()
    rank, ranks = process.GetPartitionId(), process.GetNumberOfLocalPartitions()
    pvs.LoadPlugin(plugin, remote=False)
    work = os.path.join(work, f"np{ranks}")
    cad = os.path.join(work, "cad-part.vtp")
    if rank == 0:
        os.makedirs(work, exist_ok=True)
        write_cad_part(cad)
    process.GetGlobalController().Barrier()
    failures = []
    if ranks < 2:
        failures.append("not distributed: run it with mpirun -np 2 pvbatch --symmetric")
    failures += check_surface("bunny", pvs.OpenDataFile(data + "/stanford-bunny.obj"), work, rank)
    failures += check_surface("CAD part", pvs.OpenDataFile(cad), work, rank)
    failures += height_field(rank, ranks)
    for failure in failures:
        print(f"FAIL rank {rank}: {failure}", flush=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:4]))
