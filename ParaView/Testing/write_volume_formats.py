"""The head MR of Testing/Data in every volume format the CLI reads, for TestVolumeFormats.py.

    python3 write_volume_formats.py <Testing/Data> <folder>

Run by Debian's Python (VTK 9.1 and vtk-dicom, which ParaView's VTK 9.2 cannot load): head.vti,
head.mha, head.nhdr with its raw data (a detached NRRD header), and a DICOM series of one file a
slice in the folder dicom/, written by vtk-dicom as an MR series.
"""

import os
import sys

from vtkdicom import vtkDICOMMRGenerator, vtkDICOMWriter  # python3-vtk-dicom
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkMetaImageWriter, vtkNIFTIImageReader
from vtkmodules.vtkIOXML import vtkXMLImageDataWriter


def main(data, folder):
    reader = vtkNIFTIImageReader()
    reader.SetFileName(os.path.join(data, "volumes", "head-t1-mr.nii.gz"))
    reader.Update()
    volume = reader.GetOutput()
    os.makedirs(os.path.join(folder, "dicom"), exist_ok=True)
    for name, writer in (("head.vti", vtkXMLImageDataWriter()),
                         ("head.mha", vtkMetaImageWriter())):
        writer.SetInputData(volume)
        writer.SetFileName(os.path.join(folder, name))
        writer.Write()
    dims, spacing = volume.GetDimensions(), volume.GetSpacing()
    with open(os.path.join(folder, "head.raw"), "wb") as raw:
        raw.write(vtk_to_numpy(volume.GetPointData().GetScalars()).astype("<i2").tobytes())
    with open(os.path.join(folder, "head.nhdr"), "w") as header:
        header.write(f"NRRD0004\ntype: short\ndimension: 3\nsizes: {dims[0]} {dims[1]} {dims[2]}\n"
                     f"spacings: {spacing[0]} {spacing[1]} {spacing[2]}\nencoding: raw\n"
                     "endian: little\ndata file: head.raw\n\n")
    dicom = vtkDICOMWriter()
    dicom.SetGenerator(vtkDICOMMRGenerator())
    dicom.SetInputData(volume)
    dicom.SetFilePrefix(os.path.join(folder, "dicom"))
    dicom.SetFilePattern("%s/IM-%04d.dcm")
    dicom.SetFileDimensionality(2)
    dicom.Write()
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:3]))
