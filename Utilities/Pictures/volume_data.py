#!/usr/bin/env python3
"""Real head volumes from Debian packages, for the volume pictures and benchmarks (not for the
tests, which use Testing/Data/volumes/). Downloads the packages with `apt-get download` (no root
needed) into FOLDER and writes there:

- head-ct.mha: the head CT of InVesalius' examples (package invesalius-examples, GPL-2; 256 x 256
  x 108 voxels, 0.957 x 0.957 x 1.5 mm, Hounsfield units), converted from its .inv3 project
  (a tar.gz holding main.plist and the raw int16 matrix, rows stored bottom-up);
- head-ct-half.mha: the same at half the resolution across each slice (128 x 128 x 108);
- head-mr.nii.gz: the Colin27 T1 MR of mricron-data (BSD-3-clause; 181 x 217 x 181, 1 mm).

Usage: volume_data.py FOLDER
"""

import glob
import os
import plistlib
import subprocess
import sys
import tarfile

import numpy
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkMetaImageWriter


def download(package, folder):
    """The package's .deb in folder, downloaded unless it is there."""
    found = glob.glob(os.path.join(folder, package + "_*.deb"))
    if not found:
        subprocess.run(["apt-get", "download", package], cwd=folder, check=True)
        found = glob.glob(os.path.join(folder, package + "_*.deb"))
    return found[0]


def extract(deb, member, target):
    """One file of a .deb, by its path in the package, written to target."""
    data = subprocess.run(["dpkg-deb", "--fsys-tarfile", deb], check=True, capture_output=True)
    listing = subprocess.run(["tar", "-x", "-O", "." + member], input=data.stdout, check=True,
                             capture_output=True)
    with open(target, "wb") as out:
        out.write(listing.stdout)


def inv3_volume(path):
    """The CT of an InVesalius project: int16 voxels (z, y, x) and the spacing (x, y, z)."""
    with tarfile.open(path, "r:gz") as project:
        names = project.getnames()
        main = plistlib.loads(project.extractfile(
            next(n for n in names if n.endswith("/main.plist"))).read())
        matrix = main["matrix"]
        raw = project.extractfile(
            next(n for n in names if n.endswith("/" + matrix["filename"]))).read()
    voxels = numpy.frombuffer(raw, dtype=numpy.dtype(matrix["dtype"]).newbyteorder("<"))
    voxels = voxels.reshape(matrix["shape"])[:, ::-1, :]  # rows back to top-down (DICOM's order)
    return numpy.ascontiguousarray(voxels.astype(numpy.int16)), list(main["spacing"])


def write_mha(voxels, spacing, path):
    image = vtkImageData()
    image.SetDimensions(voxels.shape[2], voxels.shape[1], voxels.shape[0])
    image.SetSpacing(spacing)
    scalars = numpy_to_vtk(voxels.ravel(), deep=True)
    scalars.SetName("CT")
    image.GetPointData().SetScalars(scalars)
    writer = vtkMetaImageWriter()
    writer.SetInputData(image)
    writer.SetFileName(path)
    writer.SetCompression(True)
    writer.Write()


def main():
    folder = os.path.abspath(sys.argv[1])
    os.makedirs(folder, exist_ok=True)
    ct = os.path.join(folder, "Cranium.inv3")
    extract(download("invesalius-examples", folder),
            "/usr/share/doc/invesalius-examples/examples/Cranium.inv3", ct)
    voxels, spacing = inv3_volume(ct)
    write_mha(voxels, spacing, os.path.join(folder, "head-ct.mha"))
    write_mha(numpy.ascontiguousarray(voxels[:, ::2, ::2]),
              [2 * spacing[0], 2 * spacing[1], spacing[2]],
              os.path.join(folder, "head-ct-half.mha"))
    extract(download("mricron-data", folder), "/usr/share/mricron/templates/ch2.nii.gz",
            os.path.join(folder, "head-mr.nii.gz"))
    print("volumes in", folder)


if __name__ == "__main__":
    main()
