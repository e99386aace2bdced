/*=========================================================================

  Program:   ApertureLighting
  Module:    MeshFuzzSeeds.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "MeshFuzzSeeds.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkXMLPolyDataWriter.h"

#include <cstdint>
#include <cstring>
#include <string>

namespace
{
enum Format : char
{
  OBJ = 0,
  PLY = 1,
  VTP = 2
};

FuzzSeed Seed(const std::string& name, Format format, const std::string& text)
{
  const std::string bytes = static_cast<char>(format) + text;
  return FuzzSeed{ name, std::vector<char>(bytes.begin(), bytes.end()) };
}

// A pyramid on a square (a quad and four triangles), with a scalar and a cell id.
vtkNew<vtkPolyData> Pyramid()
{
  static const double corners[5][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 },
    { 0.5, 0.5, 1 } };
  vtkNew<vtkPoints> points;
  for (const double* p : corners)
  {
    points->InsertNextPoint(p);
  }
  vtkNew<vtkCellArray> polys;
  const vtkIdType quad[4] = { 0, 3, 2, 1 };
  polys->InsertNextCell(4, quad);
  for (vtkIdType k = 0; k < 4; ++k)
  {
    const vtkIdType side[3] = { k, (k + 1) % 4, 4 };
    polys->InsertNextCell(3, side);
  }
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(points);
  pd->SetPolys(polys);
  vtkNew<vtkFloatArray> height;
  height->SetName("Height");
  vtkNew<vtkIntArray> cellId;
  cellId->SetName("Face");
  for (vtkIdType i = 0; i < 5; ++i)
  {
    height->InsertNextValue(static_cast<float>(points->GetPoint(i)[2]));
    cellId->InsertNextValue(static_cast<int>(i));
  }
  pd->GetPointData()->AddArray(height);
  pd->GetCellData()->AddArray(cellId);
  return pd;
}

// The pyramid with what the mappers' modes beyond one cap read: point normals, 8 sectors of
// horizons and 64-bit visibility masks.
void AddBeyondOneCap(vtkPolyData* pyramid)
{
  vtkNew<vtkFloatArray> normals, horizons;
  vtkNew<vtkUnsignedCharArray> masks;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  horizons->SetName("HorizonAngles");
  horizons->SetNumberOfComponents(8);
  masks->SetName("VisibilityMask");
  masks->SetNumberOfComponents(8);
  for (vtkIdType i = 0; i < 5; ++i)
  {
    normals->InsertNextTuple3(0.0, 0.0, 1.0);
    for (int k = 0; k < 8; ++k)
    {
      horizons->InsertNextValue(0.1f * static_cast<float>(k - 4));
      masks->InsertNextValue(static_cast<unsigned char>(37 * (i + k)));
    }
  }
  pyramid->GetPointData()->SetNormals(normals);
  pyramid->GetPointData()->AddArray(horizons);
  pyramid->GetPointData()->AddArray(masks);
}

std::string Vtp(int mode, bool beyondOneCap = false, bool compressed = false)
{
  vtkNew<vtkXMLPolyDataWriter> writer;
  vtkNew<vtkPolyData> pyramid = Pyramid();
  if (beyondOneCap)
  {
    AddBeyondOneCap(pyramid);
  }
  writer->SetInputData(pyramid);
  writer->WriteToOutputStringOn();
  writer->SetDataMode(mode);
  if (compressed)
  {
    // Small blocks, so that the arrays have several and their headers are worth damaging.
    writer->SetCompressorTypeToZLib();
    writer->SetBlockSize(64);
    writer->EncodeAppendedDataOff();
  }
  else
  {
    writer->SetCompressorTypeToNone();
  }
  writer->Write();
  return writer->GetOutputString();
}

std::string BinaryPLY()
{
  const float xyz[15] = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5f, 0.5f, 1 };
  const std::int32_t strip[8] = { 0, 1, 4, 2, -1, 2, 3, 4 };
  std::string text = "ply\nformat binary_little_endian 1.0\nelement vertex 5\n"
                     "property float x\nproperty float y\nproperty float z\n"
                     "element tristrips 1\nproperty list int int vertex_indices\nend_header\n";
  text.append(reinterpret_cast<const char*>(xyz), sizeof(xyz));
  const std::int32_t count = 8;
  text.append(reinterpret_cast<const char*>(&count), sizeof(count));
  text.append(reinterpret_cast<const char*>(strip), sizeof(strip));
  return text;
}
}

std::vector<FuzzSeed> MeshFuzzSeeds()
{
  return {
    Seed("pyramid-seams", OBJ,
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
      "vn 0 0 -1\nvn 0 -1 0.5\nf 1/1/1 4/4/1 3/3/1 2/2/1\nf 1/1/2 2/2/2 5/3/2\nf 2/1 3/2 5/3\n"
      "f 3/1 4/2 5/3\nf 4/1 1/2 5/3\n"),
    Seed("pyramid-ascii", PLY,
      "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
      "property float z\nelement face 5\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1\n4 0 3 2 1\n3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n"),
    Seed("pyramid-strips", PLY, BinaryPLY()),
    // Finite coordinates whose span overflows a float.
    Seed("pyramid-vast", OBJ,
      "v -3e38 0 0\nv 3e38 0 0\nv 3e38 3e38 0\nv -3e38 3e38 0\nv 0 1 -3e38\n"
      "f 1 4 3 2\nf 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\n"),
    Seed("pyramid-ascii", VTP, Vtp(vtkXMLWriter::Ascii)),
    Seed("pyramid-base64", VTP, Vtp(vtkXMLWriter::Binary)),
    Seed("pyramid-appended", VTP, Vtp(vtkXMLWriter::Appended)),
    Seed("pyramid-zlib-appended", VTP, Vtp(vtkXMLWriter::Appended, false, true)),
    Seed("pyramid-horizons-masks", VTP, Vtp(vtkXMLWriter::Ascii, true)),
  };
}
