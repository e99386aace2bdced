"""How many rays a point needs: the visible fraction's RMS error against a 4096-ray reference.

    python3 ray_budget.py <Testing/Data> [--rays 16,32,...] [--reference 4096] [--quick] [--check]

For the bunny (a scan), the bunny with a tenth of its points jittered (a noisy scan) and a
machined part (a plate, blocks and bosses: CAD), vtkAperturePrecompute's visible fraction
1 - cos(ApertureRadius) at each budget is compared per point with a run of `--reference` rays
and another seed. Schemes: the stratified sampler (the default), random sampling, and two cheap
ways to spend fewer rays, measured before building either: the mean over each point's one-ring
(a filter over the surface), and stopping after PILOT rays where all of them escaped (costed
as if the pilot were the first rays of the budget). Prints the RMS at each budget (and the mean
rays per point) and the rays each scheme needs for the RMS of today's default (256 stratified
rays), interpolated in log-log: the baseline that any sampler that casts fewer rays must beat.
Then the bound on adaptive sampling: how many times fewer rays the best spread of the same
budget over the points would need, if each point's error were known.
--quick: the CAD part alone, 16, 64 and 256 rays against 1024. --check: exit 1 unless the
stratified sampler's RMS falls at each budget and is below random sampling's at each.
"""
import argparse
import math
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersCore import vtkAppendPolyData, vtkCleanPolyData, vtkTriangleFilter
from vtkmodules.vtkFiltersModeling import vtkAdaptiveSubdivisionFilter
from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkCylinderSource
from vtkmodules.vtkIOGeometry import vtkOBJReader

from aperturelighting.vtkApertureLightingCore import vtkAperturePrecompute

DEFAULT_RAYS = 256
PILOT = 32  # the first batch of the early-out scheme


def bunny(data):
    reader = vtkOBJReader()
    reader.SetFileName(os.path.join(data, "stanford-bunny.obj"))
    reader.Update()
    return reader.GetOutput()


def noisy(mesh):
    """A tenth of the points moved by up to 0.2% of the size: a rougher scan."""
    out = mesh.NewInstance()
    out.DeepCopy(mesh)
    points = vtk_to_numpy(out.GetPoints().GetData())
    rng = np.random.default_rng(7)
    chosen = rng.random(len(points)) < 0.1
    points[chosen] += rng.uniform(-1, 1, (chosen.sum(), 3)) * 0.002 * out.GetLength()
    out.GetPoints().Modified()
    return out


def cad_part():
    """A plate with two blocks, a boss and a bore: flat faces, 90-degree edges, contacts."""
    append = vtkAppendPolyData()
    shapes = [(vtkCubeSource(), (0, 0, 0), (6, 0.4, 4)),
              (vtkCubeSource(), (-2, 0.9, 0), (1, 1.4, 3)),
              (vtkCubeSource(), (1.2, 0.5, -1.2), (2.4, 0.6, 0.8))]
    for source, centre, size in shapes:
        source.SetCenter(*centre)
        source.SetXLength(size[0])
        source.SetYLength(size[1])
        source.SetZLength(size[2])
        append.AddInputConnection(source.GetOutputPort())
    for radius, height, centre in ((0.5, 1.2, (1.5, 0.8, 1.0)), (0.35, 0.5, (-0.2, 0.45, 1.2))):
        cylinder = vtkCylinderSource()
        cylinder.SetResolution(48)
        cylinder.SetRadius(radius)
        cylinder.SetHeight(height)
        cylinder.SetCenter(*centre)
        append.AddInputConnection(cylinder.GetOutputPort())
    triangles = vtkTriangleFilter()
    triangles.SetInputConnection(append.GetOutputPort())
    fine = vtkAdaptiveSubdivisionFilter()  # points on the faces, not only at their corners
    fine.SetInputConnection(triangles.GetOutputPort())
    fine.SetMaximumEdgeLength(0.15)
    clean = vtkCleanPolyData()  # shared points, and none that no triangle uses
    clean.SetInputConnection(fine.GetOutputPort())
    clean.Update()
    part = clean.GetOutput()
    part.GetPointData().Initialize()  # the sources' normals, interpolated across merged edges
    return part


def visible_fraction(mesh, rays, seed, sampling="stratified"):
    """Per output point, 1 - cos(ApertureRadius), and the output's edges (pairs of point ids)."""
    precompute = vtkAperturePrecompute()
    precompute.SetInputData(mesh)
    precompute.SetNumberOfRays(rays)
    precompute.SetSeed(seed)
    if sampling == "random":
        precompute.SetSamplingToRandom()
    precompute.Update()
    out = precompute.GetOutput()
    radius = vtk_to_numpy(out.GetPointData().GetArray("ApertureRadius")).astype(np.float64)
    return 1.0 - np.cos(radius), out


def edges(surface):
    """Both directions of every polygon edge of `surface` (crease sides are separate points)."""
    ids = vtk_to_numpy(surface.GetPolys().GetConnectivityArray())
    offsets = vtk_to_numpy(surface.GetPolys().GetOffsetsArray())
    following = np.arange(1, len(ids) + 1)
    last = offsets[1:] - 1
    following[last] = offsets[:-1]  # a polygon's last corner joins its first
    pairs = np.stack([ids, ids[following]], axis=1)
    return np.concatenate([pairs, pairs[:, ::-1]])


def one_ring_mean(values, pairs):
    total = values.copy()
    count = np.ones_like(values)
    np.add.at(total, pairs[:, 0], values[pairs[:, 1]])
    np.add.at(count, pairs[:, 0], 1.0)
    return total / count


def rays_needed(budgets, errors, target):
    """The budget whose RMS is `target`, interpolated in log-log between measured budgets (past
    the last one, extrapolated along the last two)."""
    pairs = list(zip(budgets, errors))
    for (n0, e0), (n1, e1) in zip(pairs, pairs[1:]):
        if (e0 >= target >= e1 or (n1, e1) == pairs[-1]) and e0 > e1:
            exponent = math.log(e0 / target) / math.log(e0 / e1)
            if exponent * math.log(n1 / n0) < math.log(64.0 * budgets[-1] / n0):
                return n0 * (n1 / n0) ** exponent
    return math.inf  # not within 64 times the largest budget


def schemes(mesh, budgets):
    """Per scheme: (mean rays per point, estimate) for each budget."""
    stratified = {n: visible_fraction(mesh, n, 0) for n in budgets}
    random = {n: visible_fraction(mesh, n, 0, "random")[0] for n in budgets}
    pairs = edges(stratified[budgets[0]][1])
    pilot = visible_fraction(mesh, PILOT, 0)[0]
    open_ = pilot >= 1.0 - 1e-6  # every pilot ray escaped: stop there
    return {
        "stratified (today)": [(n, stratified[n][0]) for n in budgets],
        "random": [(n, random[n]) for n in budgets],
        "stratified, mean over the one-ring": [(n, one_ring_mean(stratified[n][0], pairs))
                                               for n in budgets],
        f"{PILOT} rays first, the rest where one was blocked": [
            (float(np.mean(np.where(open_, PILOT, n))), np.where(open_, pilot, stratified[n][0]))
            for n in budgets if n > PILOT],
    }


def adaptive_bound(mesh, reference, rays=64, seeds=(0, 2, 3, 4)):
    """The most any adaptive sampler could save: the ratio of rays at equal RMS between a budget
    spread evenly and the same budget spread as well as possible when each point's error is
    known (its mean square over `seeds` at `rays`, falling as N^-1.5 as the stratified one's)."""
    square = np.mean([(visible_fraction(mesh, rays, s)[0] - reference) ** 2 for s in seeds],
                     axis=0)
    erring = square > 0  # the others are exact whatever their rays: they get none
    if not erring.any():
        return math.inf
    weight = square ** 0.4  # minimises the sum of square * n^-1.5 for a fixed sum of n
    share = weight / weight.mean()
    spread = np.sum(square[erring] * share[erring] ** -1.5)
    return (np.sum(square) / spread) ** (1 / 1.5)


def check(errors):
    """Problems with the sampler's convergence in `errors` (scheme: RMS per budget)."""
    stratified, random = errors["stratified (today)"], errors["random"]
    falls = sorted(stratified, reverse=True) == stratified
    problems = [] if falls else [f"stratified RMS does not fall: {stratified}"]
    return problems + [f"stratified RMS {s:.4f} not below random {r:.4f}"
                       for s, r in zip(stratified, random) if not s < r]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("data")
    parser.add_argument("--rays", default="16,32,64,128,256,512,1024")
    parser.add_argument("--reference", type=int, default=4096)
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args()
    budgets = [int(n) for n in ("16,64,256" if args.quick else args.rays).split(",")]
    reference_rays = 1024 if args.quick else args.reference
    meshes = [("CAD part", cad_part())]
    if not args.quick:
        scan = bunny(args.data)
        meshes = [("bunny (scan)", scan), ("bunny, a tenth jittered", noisy(scan))] + meshes
    print("| mesh | sampling | RMS (mean rays): " + ", ".join(f"{n}" for n in budgets)
          + f" rays | rays for stratified {DEFAULT_RAYS}'s RMS |")
    print("|---|---|---|---|")
    problems = []
    for name, mesh in meshes:
        reference = visible_fraction(mesh, reference_rays, 1)[0]
        target, errors = math.nan, {}
        for scheme, runs in schemes(mesh, budgets).items():
            rays = [n for n, _ in runs]
            errors[scheme] = [float(np.sqrt(np.mean((v - reference) ** 2))) for _, v in runs]
            if scheme == "stratified (today)" and DEFAULT_RAYS in budgets:
                target = errors[scheme][budgets.index(DEFAULT_RAYS)]
            cells = ", ".join(f"{e:.4f} ({n:.0f})" for n, e in zip(rays, errors[scheme]))
            print(f"| {name}, {len(reference)} points | {scheme} | {cells} | "
                  f"{rays_needed(rays, errors[scheme], target):.0f} |")
            sys.stdout.flush()
        if not args.quick:
            gain = adaptive_bound(mesh, reference)
            print(f"| {name}, {len(reference)} points | adaptive, each point's error known "
                  f"(a bound) | {gain:.2f} times fewer rays | {DEFAULT_RAYS / gain:.0f} |")
        problems += [f"{name}: {p}" for p in check(errors)]
    for problem in problems if args.check else []:
        print("FAILED:", problem)
    return 1 if args.check and problems else 0

if __name__ == "__main__":
    sys.exit(main())
