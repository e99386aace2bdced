"""The plugin in pvpython: LoadPlugin, then every filter and reader through ParaView's proxies.

    pvpython TestPluginFilters.py <plugin .so> <Testing/Data> <work dir>

Checks, on real data: a convex sphere is open everywhere (ApertureRadius = pi/2); on the bunny,
Aperture Precompute's AmbientOcclusion and Aperture Reference's sky irradiance (two independent
ray casts) agree; Occlusion Query Visibility feeds Environment Visibility Lighting under an EXR
opened with File > Open's reader lookup; a DEM (an ESRI grid written here) and the Terrain-RGB
tile read as height fields and get apertures by horizon sweeps; File > Open reads a NIfTI volume
with the plugin's reader.
"""

import math
import os
import sys

import numpy as np
import paraview.simple as pvs
from paraview import servermanager
from aperture_test_data import write_valley
from vtkmodules.util.numpy_support import vtk_to_numpy

FAILURES = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        FAILURES.append(what)


def point_array(proxy, name):
    data = servermanager.Fetch(proxy)
    array = data.GetPointData().GetArray(name)
    return None if array is None else vtk_to_numpy(array)


def main(plugin, data, work):
    pvs.LoadPlugin(plugin, remote=False)
    os.makedirs(work, exist_ok=True)

    # A sphere: nothing of it is in any of its points' hemispheres.
    sphere = pvs.Sphere(ThetaResolution=24, PhiResolution=24)
    open_sphere = pvs.AperturePrecompute(Input=sphere, NumberOfRays=64)
    radius = point_array(open_sphere, "ApertureRadius")
    check(radius is not None and np.allclose(radius, math.pi / 2, atol=1e-6),
          "sphere: ApertureRadius is pi/2 everywhere")

    # Visibility masks: none on the sphere's outside is closed.
    masked = pvs.AperturePrecompute(Input=sphere, NumberOfRays=64, ComputeVisibilityMask=1,
                                    VisibilityMaskBits=144)
    mask = point_array(masked, "VisibilityMask")
    check(mask is not None and mask.shape[1] == 18 and (mask == 255).all(),
          "sphere: VisibilityMask of 144 cells, every one open")

    # The bunny: the apertures' ambient occlusion against the reference's sky (same definition,
    # independent rays: stratified 1024 against Monte-Carlo 1024).
    bunny = pvs.OpenDataFile(os.path.join(data, "stanford-bunny.obj"))
    apertures = pvs.AperturePrecompute(Input=bunny, NumberOfRays=1024, ComputeAmbientOcclusion=1)
    reference = pvs.ApertureReference(Input=bunny, Source="Sky", NumberOfSamples=1024)
    ao = point_array(apertures, "AmbientOcclusion")
    sky = point_array(reference, "ReferenceIrradiance")
    radius = point_array(apertures, "ApertureRadius")
    check(ao is not None and sky is not None and len(sky) <= len(ao),
          "bunny: AmbientOcclusion and ReferenceIrradiance computed")
    if ao is not None and sky is not None:
        # Creases may split points in the apertures' output: compare on the reference's points
        # through their positions.
        out = servermanager.Fetch(apertures)
        ref = servermanager.Fetch(reference)
        index = {tuple(np.round(ref.GetPoint(i), 7)): i for i in range(ref.GetNumberOfPoints())}
        # The reference gives NaN to the file's points that no polygon uses.
        pairs = [(ao[i], sky[index[key]]) for i in range(out.GetNumberOfPoints())
                 if (key := tuple(np.round(out.GetPoint(i), 7))) in index
                 and np.isfinite(sky[index[key]])]
        difference = np.abs(np.array([a - s for a, s in pairs]))
        check(len(pairs) >= 0.95 * np.isfinite(sky).sum() and difference.mean() < 0.02,
              f"bunny: AO and reference sky agree on {len(pairs)} points "
              f"(mean |difference| {difference.mean():.4f} < 0.02)")
        check(0.3 < radius.min() and radius.max() <= math.pi / 2 + 1e-6 and radius.mean() < 1.45,
              f"bunny: ApertureRadius in ({radius.min():.3f}, {radius.max():.3f}), "
              f"mean {radius.mean():.3f}: closed in the creases, open elsewhere")

    # Occlusion Query Visibility (ray cast) under an EXR opened by extension.
    environment = pvs.OpenDataFile(os.path.join(data, "env", "forest.exr"))
    check(environment is not None and environment.GetXMLName() == "OpenEXRReader",
          "File > Open picks the OpenEXR reader for .exr")
    visibility = pvs.OcclusionQueryVisibility(Input=bunny, Backend="Ray cast", Level=1)
    # Light Sphere Visibility, the core's filter: the same matrix as the ray-cast backend.
    core = pvs.LightSphereVisibility(Input=bunny, Level=1)
    by_rays, by_core = point_array(visibility, "Visibility"), point_array(core, "Visibility")
    check(by_rays is not None and by_core is not None and by_core.shape == by_rays.shape
          and np.array_equal(by_core, by_rays) and (by_core > 0).any(),
          "Light Sphere Visibility == Occlusion Query Visibility's ray cast, value for value")
    # Occluders changed in the GUI clear the old ones first (RemoveAllOccluders).
    core.Occluders = [bunny]
    core.Occluders = []
    check(np.array_equal(point_array(core, "Visibility"), by_core),
          "Light Sphere Visibility: occluders added and removed again change nothing")
    lit = pvs.EnvironmentVisibilityLighting(Input=visibility, Environment=environment, UpAxis="Y")
    irradiance = point_array(lit, "EnvironmentLighting")
    check(irradiance is not None and irradiance.shape[1] == 3 and np.isfinite(irradiance).all()
          and irradiance.min() >= 0 and irradiance.max() > 0,
          "environment lighting: finite, non-negative RGB EnvironmentLighting per point")

    # A DEM: a cone-shaped valley (slope 0.3) as an ESRI ASCII grid, through GDAL.
    n = 48
    grid = os.path.join(work, "valley.asc")
    expected = write_valley(grid, n, 0.3)
    dem = pvs.GDALDEMReader(FileName=grid)
    valley = pvs.AperturePrecompute(Input=dem)
    radius = point_array(valley, "ApertureRadius")
    check(radius is not None and len(radius) == n * n, "DEM: one aperture per cell")
    if radius is not None:
        # The floor of a cone of slope 0.3 sees the sky above its walls: a cap of half-angle
        # pi/2 - atan(0.3).
        floor = radius.reshape(n, n)[n // 2, n // 2]
        check(abs(floor - expected) < 0.03,
              f"DEM: the valley floor's aperture {floor:.4f} is pi/2 - atan(slope) = "
              f"{expected:.4f} (+-0.03)")

    # Terrain products on the same valley: the floor of the cone sees the sky above its walls,
    # 1 - sin(atan(0.3)) of it, and its positive openness is 90 degrees less the walls' angle.
    products = pvs.AperturePrecompute(Input=dem, ComputeSkyViewFactor=1,
                                      ComputePositiveOpenness=1, NoDataAs="Fill")
    svf = point_array(products, "SkyViewFactor")
    openness = point_array(products, "PositiveOpenness")
    heights = point_array(products, "Elevation")
    if svf is not None and openness is not None and heights is not None:
        wall = math.atan(0.3)
        apex = int(np.argmin(heights))
        floor = (svf[apex], openness[apex])
        check(abs(floor[0] - (1 - math.sin(wall))) < 0.01 and
              abs(floor[1] - (90 - math.degrees(wall))) < 0.5,
              f"DEM: the floor's sky-view factor {floor[0]:.4f} and openness {floor[1]:.2f}")
    else:
        check(False, "DEM: SkyViewFactor and PositiveOpenness computed")

    # Flat ground on a sphere of 200 m falls away: seen from the middle, each sector's nearest
    # sample, d = 10 m / max(|cos|, |sin|) away, lies d/2R below the horizontal.
    level = os.path.join(work, "level.asc")
    write_valley(level, n, 0.0)
    curved = pvs.AperturePrecompute(Input=pvs.GDALDEMReader(FileName=level),
                                    ComputePositiveOpenness=1, EarthRadius=200.0)
    falling = point_array(curved, "PositiveOpenness")
    if falling is not None:
        steps = [10.0 / max(abs(math.cos(p)), abs(math.sin(p)))
                 for p in ((k + 0.5) * math.pi / 16 for k in range(32))]
        want = 90 + sum(math.degrees(math.atan(d / 400.0)) for d in steps) / 32
        middle = falling.reshape(n, n)[n // 2, n // 2]
        check(abs(middle - want) < 1e-3,
              f"DEM: Earth Radius 200 m, flat ground's openness {middle:.4f} (closed form "
              f"{want:.4f})")
    else:
        check(False, "DEM: PositiveOpenness with an Earth radius")

    # Limit Distance: off by default (every occluder counts); the distance it offers is a
    # quarter of the data's size, not 1e30; on, with a radius shorter than a texel (10 m), the
    # valley floor sees no wall.
    # (As in the GUI, the input has data when the filter is made: the domain reads its bounds.)
    width = n * 10.0
    dem.UpdatePipeline()
    fresh = pvs.AperturePrecompute(Input=dem)
    check(fresh.LimitDistance == 0 and 0.2 * width < fresh.MaximumDistance < 0.3 * width,
          f"DEM: Limit Distance off, Maximum Distance offered {fresh.MaximumDistance} (about a "
          f"quarter of the {width:.0f} m wide valley)")
    local = pvs.AperturePrecompute(Input=dem, LimitDistance=1, MaximumDistance=5.0)
    radius = point_array(local, "ApertureRadius")
    if radius is not None:
        floor = radius.reshape(n, n)[n // 2, n // 2]
        check(floor > expected + 0.1,
              f"DEM: limited to 5 m, the valley floor opens: {floor:.4f} > {expected:.4f}")

    # The Terrain-RGB tile.
    tile = pvs.TerrainRGBReader(FileName=os.path.join(data, "fuji-terrain-rgb.png"), Spacing=[30, 30])
    radius = point_array(pvs.AperturePrecompute(Input=tile), "ApertureRadius")
    check(radius is not None and radius.size > 0 and np.isfinite(radius).all()
          and 0 <= radius.min() and radius.max() <= math.pi / 2 + 1e-6,
          "Terrain-RGB: apertures in [0, pi/2] on every texel")

    # A damaged input is an error, not a crash: a DEM file that is not one.
    broken = os.path.join(work, "broken.asc")
    with open(broken, "w") as f:
        f.write("ncols 4\nnrows garbage\n")
    bad = pvs.GDALDEMReader(FileName=broken)
    bad.UpdatePipeline()
    check(bad.GetDataInformation().GetNumberOfPoints() == 0, "a broken DEM gives no data")

    # NIfTI volumes, which ParaView 5.11 does not open itself: File > Open picks the plugin's
    # reader for .nii.gz; a damaged header gives no data.
    head = pvs.OpenDataFile(os.path.join(data, "volumes", "head-t1-mr.nii.gz"))
    head.UpdatePipeline()
    extent = head.GetDataInformation().GetExtent()
    check(head.GetXMLName() == "ApertureNIfTIReader" and list(extent) == [0, 127, 0, 127, 0, 61],
          f"File > Open reads the head MR (.nii.gz) with the NIfTI reader: extent {list(extent)}")
    damaged = os.path.join(work, "damaged.nii")
    with open(damaged, "wb") as f:
        f.write(b"\x5c\x01\x00\x00" + bytes(340) + b"n+1\x00" + bytes(64))
    bad = pvs.NIfTIReader(FileName=damaged)
    bad.UpdatePipeline()
    check(bad.GetDataInformation().GetNumberOfPoints() == 0, "a damaged NIfTI header gives no data")

    print(f"{len(FAILURES)} failure(s)")
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:4]))
