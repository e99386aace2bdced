"""ApertureLighting for VTK: soft shadows from dynamic area lights.

Every class of the VTK::ApertureLighting module is available here, for example::

    from aperturelighting import vtkSphericalCap
"""

from .vtkApertureLighting import *  # noqa: F401,F403
