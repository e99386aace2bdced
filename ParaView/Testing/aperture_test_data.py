"""Test data the plugin's tests write themselves."""

import math


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
