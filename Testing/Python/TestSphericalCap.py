"""vtkSphericalCap from Python: the wrapped signatures, and the values against a brute-force
integral over a Fibonacci lattice of directions."""

import math
import sys

import numpy as np

from aperturelighting import vtkSphericalCap as C


def lattice(n=1_000_000):
    i = np.arange(n)
    z = 1.0 - (2.0 * i + 1.0) / n
    rho = np.sqrt(1.0 - z * z)
    phi = math.pi * (3.0 - math.sqrt(5.0)) * i
    return np.stack([rho * np.cos(phi), rho * np.sin(phi), z], axis=1)


def main():
    w = lattice()
    weight = 4.0 * math.pi / len(w)
    failures = []

    for r1, r2, d in [(0.5, 0.3, 0.4), (1.2, 0.9, 1.5), (0.8, 0.8, 0.05), (1.5, 0.2, 1.45)]:
        a1 = [0.0, 0.0, 1.0]
        a2 = [math.sin(d), 0.0, math.cos(d)]
        inside = (w[:, 2] >= math.cos(r1)) & (w @ np.array(a2) >= math.cos(r2))
        area = inside.sum() * weight
        moment = w[inside].sum(axis=0) * weight

        got = C.IntersectionArea(r1, r2, d)
        if abs(got - area) > 5e-4:
            failures.append(f"IntersectionArea{(r1, r2, d)} = {got}, lattice {area}")
        m = [0.0, 0.0, 0.0]
        C.IntersectionMoment(a1, r1, a2, r2, m)
        if np.abs(np.array(m) - moment).max() > 5e-4:
            failures.append(f"IntersectionMoment{(r1, r2, d)} = {m}, lattice {moment}")
        c = [0.0, 0.0, 0.0]
        if not C.IntersectionCentroid(a1, r1, a2, r2, c):
            failures.append(f"IntersectionCentroid{(r1, r2, d)} found no intersection")
        elif np.abs(np.array(c) - moment / np.linalg.norm(moment)).max() > 1e-3:
            failures.append(f"IntersectionCentroid{(r1, r2, d)} = {c}")
        smooth = C.IntersectionAreaSmoothstep(r1, r2, d)
        if abs(smooth - got) > 0.15 * C.SolidAngleFromCapRadius(min(r1, r2)):
            failures.append(f"IntersectionAreaSmoothstep{(r1, r2, d)} = {smooth}, exact {got}")

    # Sphere light: the lens moment with the hemisphere gives the same irradiance.
    for sigma, theta in [(0.3, 0.2), (0.3, 1.6), (0.785, 1.9), (0.064, 1.0)]:
        m = [0.0, 0.0, 0.0]
        C.IntersectionMoment([math.sin(theta), 0.0, math.cos(theta)], sigma, [0, 0, 1], math.pi / 2, m)
        e = C.SphereLightIrradiance(sigma, theta)
        if abs(e - m[2]) > 1e-9:
            failures.append(f"SphereLightIrradiance{(sigma, theta)} = {e}, lens moment {m[2]}")

    # Round trip, the sun's cap, the simplified factor, and bad input.
    if abs(C.CapRadiusFromSolidAngle(C.SolidAngleFromCapRadius(0.0047)) - 0.0047) > 1e-12:
        failures.append("CapRadiusFromSolidAngle does not invert SolidAngleFromCapRadius")
    if abs(C.SphereLightCapRadius(1.0, 2.0) - math.pi / 6) > 1e-12:
        failures.append("SphereLightCapRadius(1, 2) != pi/6")
    if C.SimplifiedShadowFactor(0.8, 0.01, 0.5) != 1.0 or C.SimplifiedShadowFactor(0.8, 0.01, 0.9) != 0.0:
        failures.append("SimplifiedShadowFactor is not 1 inside and 0 outside the aperture")
    nan = float("nan")
    for value in (C.IntersectionArea(nan, 0.3, 0.2), C.IntersectionArea(-1.0, 0.3, 0.2),
                  C.IntersectionAreaSmoothstep(0.5, nan, 0.2), C.SphereLightIrradiance(nan, 0.1)):
        if value != 0.0:
            failures.append(f"bad input gave {value}, not 0")
    c = [1.0, 1.0, 1.0]
    if C.IntersectionCentroid([0, 0, 0], 0.5, [0, 0, 1], 0.5, c) or c != [0.0, 0.0, 0.0]:
        failures.append("a zero-length axis must give an empty intersection")

    print("IntersectionArea(0.5, 0.3, 0.4) =", C.IntersectionArea(0.5, 0.3, 0.4))
    for f in failures:
        print("FAIL", f, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
