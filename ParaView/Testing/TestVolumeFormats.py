"""Every volume format the CLI reads opens in ParaView and draws as "Aperture Volume".

    pvpython TestVolumeFormats.py <plugin .so> <Testing/Data> <folder of write_volume_formats.py>

The head MR of Testing/Data is read by the plugin's NIfTI reader (ParaView 5.11 opens no NIfTI
file itself); the same voxels as .vti, .mha and a detached NRRD header (ParaView's own readers,
through File > Open) and as a DICOM series (ParaView's DICOM directory reader, as the plugin's
vtk-dicom reader needs VTK 9.1) must give the same grid and every voxel the same value. Each is
offered the Aperture Volume representation, and the DICOM series drawn with it lights the head.
"""

import os
import sys

import numpy as np
import paraview.simple as pvs
from paraview import servermanager
from aperture_test_data import dark_view, shot
from vtkmodules.util.numpy_support import vtk_to_numpy

FAILURES = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what, flush=True)
    if not ok:
        FAILURES.append(what)


def voxels(source):
    """The grid's dimensions and spacing, and its scalars as a (z, y, x) array."""
    image = servermanager.Fetch(source)
    dims = image.GetDimensions()
    values = vtk_to_numpy(image.GetPointData().GetScalars()).astype(float)
    return dims, image.GetSpacing(), values.reshape(dims[2], dims[1], dims[0])


def picture(source, view, name, folder):
    """The source drawn as Aperture Volume (the mr preset's opacity ramp, one light 45 degrees
    from the view), the camera reset to it."""
    display = pvs.Show(source, view)
    scalars = source.PointData.keys()[0]
    pvs.ColorBy(display, ("POINTS", scalars))
    display.SetRepresentationType("Aperture Volume")
    pvs.GetOpacityTransferFunction(scalars).Points = [0.0, 0.0, 0.5, 0.0, 60.0, 0.0, 0.5, 0.0,
                                                      250.0, 1.0, 0.5, 0.0]
    view.ResetCamera()
    image = shot(view, folder, name, 300)
    pvs.Hide(source, view)
    return image


def main(plugin, data, folder):
    pvs.LoadPlugin(plugin, remote=False)
    nifti = pvs.OpenDataFile(os.path.join(data, "volumes", "head-t1-mr.nii.gz"))
    dims, spacing, expected = voxels(nifti)
    print(f"NIfTI ({nifti.GetXMLName()}): {dims}, spacing {spacing}")
    readers = {name: pvs.OpenDataFile(os.path.join(folder, name))
               for name in ("head.vti", "head.mha", "head.nhdr")}
    readers["DICOM series"] = pvs.DICOMReaderdirectory(FileName=os.path.join(folder, "dicom"))
    for name, reader in readers.items():
        got_dims, got_spacing, got = voxels(reader)
        same = got_dims == dims and np.array_equal(got, expected)
        check(same and np.allclose(got_spacing, spacing, rtol=1e-5),
              f"{name} ({reader.GetXMLName()}): {got_dims}, spacing {got_spacing}, the NIfTI's "
              f"voxels {'alike' if same else 'differ'}")
    view = dark_view(300)
    for name, reader in readers.items():
        display = pvs.Show(reader, view)
        types = display.GetProperty("Representation").Available
        check("Aperture Volume" in types, f"{name} offers Aperture Volume")
        pvs.Hide(reader, view)
    reference = picture(nifti, view, "nifti", folder)
    lit = (reference.max(axis=2) > 40).mean()
    check(lit > 0.1, f"Aperture Volume lights the NIfTI head ({lit:.0%} of the pixels)")
    dicom = picture(readers["DICOM series"], view, "dicom", folder)
    difference = np.abs(dicom - reference).mean()
    check(difference < 0.5, f"the DICOM series draws as the NIfTI ({difference:.3f} levels)")
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:4]))
