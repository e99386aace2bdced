"""vtkApertureNIfTIReader: VTK's NIfTI reader behind a check of the header.

A sound file (the head MR, gzipped NIfTI-1; the same voxels written as NIfTI-2 and as NIfTI-1
byte-swapped) reads as vtkNIFTIImageReader reads it, voxel for voxel. Each damaged header (the
fields VTK 9.1's reader trusts and crashed on: axes, sizes, data type, bits, spacings, data
offset, a cut file, another magic) gives one error naming the file, no output and CanReadFile 0,
without reaching vtkNIFTIImageReader.
"""

import math
import os
import struct
import sys
import tempfile

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkNIFTIImageReader, vtkNIFTIImageWriter

import aperturelighting as al

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Data")
FAILURES = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        FAILURES.append(what)


class Errors:
    """The messages of an algorithm's ErrorEvents, so that expected errors stay quiet."""

    CallDataType = "string0"

    def __init__(self, algorithm):
        self.messages = []
        algorithm.AddObserver("ErrorEvent", self)

    def __call__(self, _caller, _event, message=None):
        self.messages.append(message)


def read(reader_type, name):
    reader = reader_type()
    errors = Errors(reader)
    reader.SetFileName(name)
    reader.Update()
    return reader.GetOutput(), errors.messages


def voxels(image):
    scalars = image.GetPointData().GetScalars()
    return None if scalars is None else vtk_to_numpy(scalars)


def check_sound(name, what):
    ours, errors = read(al.vtkApertureNIfTIReader, name)
    theirs, _ = read(vtkNIFTIImageReader, name)
    same = (voxels(ours) is not None and ours.GetDimensions() == theirs.GetDimensions() and
            ours.GetSpacing() == theirs.GetSpacing() and
            np.array_equal(voxels(ours), voxels(theirs)))
    check(not errors and same and al.vtkApertureNIfTIReader.HeaderProblem(name) == "",
          f"{what}: read as vtkNIFTIImageReader reads it ({ours.GetDimensions()})")
    return ours


def check_damaged(folder, name, data, words):
    path = os.path.join(folder, name)
    with open(path, "wb") as f:
        f.write(data)
    image, errors = read(al.vtkApertureNIfTIReader, path)
    problem = al.vtkApertureNIfTIReader.HeaderProblem(path)
    check(len(errors) == 1 and name in errors[0] and words in errors[0] and problem in errors[0]
          and image.GetNumberOfPoints() == 0 and al.vtkApertureNIfTIReader().CanReadFile(path) == 0,
          f"{name}: one error with '{words}' ({errors[0] if errors else 'none'})")


def write(image, path, version=1):
    writer = vtkNIFTIImageWriter()
    writer.SetInputData(image)
    writer.SetFileName(path)
    writer.SetNIFTIVersion(version)
    writer.Write()
    with open(path, "rb") as f:
        return bytearray(f.read())


def swapped_nifti1(data):
    """A NIfTI-1 file in the other byte order: every header field swapped, the voxels too."""
    out = bytearray(data)
    layout = "i10s18sihcc8h3f4h8f3fhcc2f2f2i80s24s2h6f12f16s4s"  # 348 bytes
    fields = struct.unpack("<" + layout, bytes(data[:348]))
    out[:348] = struct.pack(">" + layout, *fields)
    offset = int(struct.unpack("<f", bytes(data[108:112]))[0])
    datatype = struct.unpack("<h", bytes(data[70:72]))[0]
    dtype = {2: "u1", 4: "<i2", 8: "<i4", 16: "<f4", 512: "<u2"}[datatype]
    values = np.frombuffer(bytes(data[offset:]), dtype=dtype)
    out[offset:] = values.astype(values.dtype.newbyteorder(">")).tobytes()
    return bytes(out)


def main():
    head = os.path.join(DATA, "volumes", "head-t1-mr.nii.gz")
    image = check_sound(head, "the head MR (.nii.gz)")
    with tempfile.TemporaryDirectory() as folder:
        sound = write(image, os.path.join(folder, "head.nii"))
        write(image, os.path.join(folder, "head2.nii"), version=2)
        check_sound(os.path.join(folder, "head2.nii"), "NIfTI-2")
        with open(os.path.join(folder, "swapped.nii"), "wb") as f:
            f.write(swapped_nifti1(sound))
        check_sound(os.path.join(folder, "swapped.nii"), "NIfTI-1, big-endian")

        def edited(offset, fmt, *values):
            data = bytearray(sound)
            data[offset:offset + struct.calcsize(fmt)] = struct.pack(fmt, *values)
            return bytes(data)

        for name, data, words in (
                ("empty.nii", b"", "does not start with a NIfTI-1 or NIfTI-2 header"),
                ("cut.nii", bytes(sound[:200]), "does not start with a NIfTI"),
                ("magic.nii", edited(344, "4s", b"ni1\0"), "not that of a single-file volume"),
                ("axes.nii", edited(40, "<h", 9), "it has 9 axes"),
                ("size.nii", edited(44, "<h", 0), "an axis has no samples"),
                ("vast.nii", edited(42, "<3h", 32767, 32767, 32767), "more than 2^31 values"),
                ("type.nii", edited(70, "<h", 3), "data type is not one VTK reads"),
                ("bits.nii", edited(72, "<h", 7), "does not match its bits"),
                ("spacing.nii", edited(80, "<f", math.nan), "not a finite number"),
                ("offset.nii", edited(108, "<f", math.inf), "not a finite number"),
                ("inside.nii", edited(108, "<f", 100.0), "does not lie after its header"),
                ("short.nii", bytes(sound[:len(sound) // 2]), "within the file")):
            check_damaged(folder, name, data, words)
    print(f"{len(FAILURES)} failure(s)")
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
