"""The time of Aperture Precompute on a surface in pieces, for docs/paraview.md's scaling table.

    source build-paraview/env.sh
    VTK_SMP_MAX_THREADS=2 pvbatch Utilities/ParaView/distributed_scaling.py <plugin .so> <obj>
    VTK_SMP_MAX_THREADS=1 mpirun -np 2 pvbatch --symmetric Utilities/ParaView/distributed_scaling.py \
        <plugin .so> <obj>

The surface goes through Redistribute Data Set and Extract Surface as in
TestDistributedPvbatch.py; rank 0 prints the wall time of the precompute alone (gathering
included), between two barriers, with `rays` rays a point (default 1024), and each rank its
piece's triangles. Run it under the configurations to compare in one session, one after the
other.
"""

import sys
import time

import paraview.simple as pvs
from paraview import servermanager


def main(plugin, obj, rays="1024"):
    process = servermanager.vtkProcessModule.GetProcessModule()
    controller = process.GetGlobalController()
    rank, ranks = process.GetPartitionId(), process.GetNumberOfLocalPartitions()
    pvs.LoadPlugin(plugin, remote=False)
    split = pvs.ExtractSurface(Input=pvs.RedistributeDataSet(Input=pvs.OpenDataFile(obj)))
    split.UpdatePipeline()
    precompute = pvs.AperturePrecompute(Input=split, NumberOfRays=int(rays))
    controller.Barrier()
    start = time.perf_counter()
    precompute.UpdatePipeline()
    controller.Barrier()
    elapsed = time.perf_counter() - start
    cells = split.GetClientSideObject().GetOutputDataObject(0).GetNumberOfCells()
    print(f"rank {rank}: a piece of {cells} triangles", flush=True)
    controller.Barrier()
    if rank == 0:
        print(f"{ranks} rank(s): precompute {elapsed:.2f} s, {rays} rays", flush=True)


if __name__ == "__main__":
    main(*sys.argv[1:])
