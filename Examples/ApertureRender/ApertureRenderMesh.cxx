/*=========================================================================

  Program:   ApertureLighting
  Module:    ApertureRenderMesh.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "ApertureRenderMesh.h"

#include "ApertureRenderInput.h"
#include "ApertureRenderMessages.h"
#include "ApertureRenderOBJ.h"
#include "ApertureRenderPLY.h"
#include "ApertureRenderXMLBlocks.h"

#include "vtkApertureCellCheck.h"
#include "vtkApertureText.h"
#include "vtkCellArray.h"
#include "vtkDataSetReader.h"
#include "vtkDataSetSurfaceFilter.h"
#include "vtkOBJReader.h"
#include "vtkPLYReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSTLReader.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLDataElement.h"
#include "vtkXMLDataParser.h"
#include "vtkXMLPolyDataReader.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <set>
#include <sstream>
#include <vector>

namespace ApertureRender
{
namespace
{
// The first cell whose point ids lie outside the points (a damaged file), or empty.
std::string BadCell(vtkDataObject* data)
{
  if (auto* grid = vtkUnstructuredGrid::SafeDownCast(data))
  {
    return vtkApertureCellCheck::FindBadCell(grid);
  }
  auto* poly = vtkPolyData::SafeDownCast(data);
  return poly ? vtkApertureCellCheck::FindBadCell(poly) : std::string();
}

// Points that are not finite: said once; the filter closes them and the view leaves out the
// cells that use them.
void NoteNonFinitePoints(Input& input)
{
  vtkPoints* points = input.Mesh->GetPoints();
  for (vtkIdType i = 0; points && i < points->GetNumberOfPoints(); ++i)
  {
    const double* p = points->GetPoint(i);
    input.NonFinitePoints +=
      (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])) ? 0 : 1;
  }
  if (input.NonFinitePoints > 0)
  {
    input.Notes.push_back(std::to_string(input.NonFinitePoints) +
      " point(s) are not finite (NaN or infinite): the cells that use them are left out");
  }
}

// vtkSTLReader reads what a truncated binary file holds without a word; its header says how
// many triangles there should be (50 bytes each after 84 bytes of header).
bool CheckSTL(const std::string& name, std::string& error)
{
  if (vtksys::SystemTools::DetectFileType(name.c_str()) == vtksys::SystemTools::FileTypeText)
  {
    return true;
  }
  const unsigned long size = vtksys::SystemTools::FileLength(name);
  unsigned char count[4] = { 0, 0, 0, 0 };
  FILE* file = vtksys::SystemTools::Fopen(name, "rb");
  const bool header =
    file && std::fseek(file, 80, SEEK_SET) == 0 && std::fread(count, 1, 4, file) == 4;
  if (file)
  {
    std::fclose(file);
  }
  const uint64_t triangles =
    count[0] | (uint64_t(count[1]) << 8) | (uint64_t(count[2]) << 16) | (uint64_t(count[3]) << 24);
  if (!header || size < 84 + 50 * triangles)
  {
    std::ostringstream what;
    what << vtkApertureText::QuoteName(name) << " is truncated (its header announces " << triangles
         << " triangles, " << (size > 84 ? (size - 84) / 50 : 0) << " are there)";
    error = what.str();
    return false;
  }
  return true;
}

// A count attribute of a VTP element (0 when absent); -1 when it is not a count.
double VTPCount(vtkXMLDataElement* element, const char* name)
{
  const char* text = element->GetAttribute(name);
  char* end = nullptr;
  const double count = text ? std::strtod(text, &end) : 0.0;
  return (text && (end == text || !(count >= 0.0))) ? -1.0 : count;
}

// The values a VTP group's arrays take: `tuples` each (a FieldData array says its own) times its
// components; -1 when an attribute is not a count.
double VTPArrayValues(vtkXMLDataElement* group, double tuples)
{
  const bool field = std::string(group->GetName() ? group->GetName() : "") == "FieldData";
  double values = 0.0;
  for (int j = 0; j < group->GetNumberOfNestedElements(); ++j)
  {
    vtkXMLDataElement* array = group->GetNestedElement(j);
    const double count = field ? VTPCount(array, "NumberOfTuples") : tuples;
    const double components = VTPCount(array, "NumberOfComponents");
    if (count < 0.0 || components < 0.0)
    {
      return -1.0;
    }
    values += count * std::max(components, 1.0);
  }
  return values;
}

// The values a VTP piece's counts ask the reader to allocate: its points, cell offsets and every
// array; -1 when an attribute is not a count.
double VTPPieceValues(vtkXMLDataElement* piece)
{
  const double points = VTPCount(piece, "NumberOfPoints");
  double cells = 0.0;
  for (const char* kind : { "NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys" })
  {
    const double count = VTPCount(piece, kind);
    cells = (count < 0.0 || cells < 0.0) ? -1.0 : cells + count;
  }
  double values = (points < 0.0 || cells < 0.0) ? -1.0 : 3.0 * points + cells + 4.0;
  for (int i = 0; values >= 0.0 && i < piece->GetNumberOfNestedElements(); ++i)
  {
    vtkXMLDataElement* group = piece->GetNestedElement(i);
    const std::string name = group->GetName() ? group->GetName() : "";
    const double arrays =
      VTPArrayValues(group, name == "PointData" ? points : (name == "CellData" ? cells : 0.0));
    values = arrays < 0.0 ? -1.0 : values + arrays;
  }
  return values;
}

// A name two arrays of one group (a piece's PointData or CellData, or the FieldData) share, or
// empty: vtkXMLPolyDataReader replaces the first by the second and then reads through the one it
// dropped.
std::string SharedArrayName(vtkXMLDataElement* polyData)
{
  std::vector<vtkXMLDataElement*> groups;
  for (int i = 0; i < polyData->GetNumberOfNestedElements(); ++i)
  {
    vtkXMLDataElement* element = polyData->GetNestedElement(i);
    groups.push_back(element);
    for (int j = 0; j < element->GetNumberOfNestedElements(); ++j)
    {
      groups.push_back(element->GetNestedElement(j));
    }
  }
  for (vtkXMLDataElement* group : groups)
  {
    const std::string kind = group->GetName() ? group->GetName() : "";
    std::set<std::string> names;
    for (int k = 0; (kind == "PointData" || kind == "CellData" || kind == "FieldData") &&
         k < group->GetNumberOfNestedElements();
         ++k)
    {
      const char* name = group->GetNestedElement(k)->GetAttribute("Name");
      if (name && !names.insert(name).second)
      {
        return name;
      }
    }
  }
  return std::string();
}

// vtkXMLPolyDataReader allocates what a piece's counts say before it reads the data: a damaged
// count can ask for exabytes. Stored plainly (ASCII, base64, raw) every value takes a byte or more;
// VTK's compressors on its 32 KiB blocks pack at most about 630 (zlib) or 250 (LZMA) bytes into
// one, so a compressed file may announce 4096 values a byte.
bool CheckVTPSizes(
  vtkXMLDataElement* root, vtkXMLDataElement* polyData, const std::string& name, std::string& error)
{
  const double fileSize = static_cast<double>(vtksys::SystemTools::FileLength(name));
  const double capacity = root->GetAttribute("compressor") ? 4096.0 * fileSize : fileSize;
  double values = 0.0;
  for (int i = 0; i < polyData->GetNumberOfNestedElements(); ++i)
  {
    vtkXMLDataElement* element = polyData->GetNestedElement(i);
    const bool isPiece = std::string(element->GetName() ? element->GetName() : "") == "Piece";
    const double piece = isPiece ? VTPPieceValues(element) : VTPArrayValues(element, 0.0);
    if (piece < 0.0)
    {
      error =
        vtkApertureText::QuoteName(name) + " is damaged (a count that is not a number of items)";
      return false;
    }
    values += piece;
  }
  if (values > capacity)
  {
    std::ostringstream what;
    what << vtkApertureText::QuoteName(name) << " is damaged: its counts announce " << values
         << " values, more than " << static_cast<unsigned long>(fileSize) << " bytes can hold";
    error = what.str();
    return false;
  }
  return true;
}

// vtkXMLPolyDataReader leaks the arrays of a piece whose points do not have 3 components: its
// header is read first, and every piece's Points array checked.
bool CheckVTP(vtkXMLPolyDataReader* reader, MessageCapture& messages, const std::string& name,
  std::string& error)
{
  messages.Clear();
  reader->UpdateInformation();
  vtkXMLDataElement* root =
    reader->GetXMLParser() ? reader->GetXMLParser()->GetRootElement() : nullptr;
  vtkXMLDataElement* data = root ? root->FindNestedElementWithName("PolyData") : nullptr;
  if (!messages.FirstError().empty() || !data)
  {
    error = "cannot read " + vtkApertureText::QuoteName(name) + ": " +
      messages.FirstErrorOr("no PolyData element");
    return false;
  }
  for (int i = 0; i < data->GetNumberOfNestedElements(); ++i)
  {
    vtkXMLDataElement* points = data->GetNestedElement(i)->FindNestedElementWithName("Points");
    vtkXMLDataElement* array = points ? points->FindNestedElementWithName("DataArray") : nullptr;
    int components = 1;
    if (array && (!array->GetScalarAttribute("NumberOfComponents", components) || components != 3))
    {
      error =
        vtkApertureText::QuoteName(name) + " is damaged (its points do not have 3 components)";
      return false;
    }
  }
  const std::string shared = SharedArrayName(data);
  if (!shared.empty())
  {
    error = vtkApertureText::QuoteName(name) + " is damaged (two arrays of one group are named " +
      vtkApertureText::Quote(shared) + ")";
    return false;
  }
  return CheckVTPSizes(root, data, name, error) && CheckCompressedBlocks(reader, name, error);
}

// Updates a reader; false with a sentence when it reports an error or runs out of memory (a
// damaged count in a file can ask VTK's readers for any amount).
bool Run(
  vtkAlgorithm* reader, MessageCapture& messages, const std::string& name, std::string& error)
{
  messages.Clear();
  try
  {
    reader->Update();
  }
  catch (const std::bad_alloc&)
  {
    error = "cannot read " + vtkApertureText::QuoteName(name) +
      ": it asks for more memory than there is (damaged?)";
    return false;
  }
  if (!messages.FirstError().empty() || !reader->GetOutputDataObject(0))
  {
    error = "cannot read " + vtkApertureText::QuoteName(name) + ": " +
      messages.FirstErrorOr("unknown error");
    return false;
  }
  const std::string bad = BadCell(reader->GetOutputDataObject(0));
  if (!bad.empty())
  {
    error = vtkApertureText::QuoteName(name) + " is damaged: " + bad;
    return false;
  }
  return true;
}

// Legacy files may hold any dataset: its outer surface is shaded. vtkDataSetSurfaceFilter reads
// through the cells' point ids, so the dataset is read and checked first.
vtkSmartPointer<vtkAlgorithm> NewLegacySurface(
  const std::string& name, MessageCapture& messages, std::string& error)
{
  auto legacy = vtkSmartPointer<vtkDataSetReader>::New();
  legacy->SetFileName(name.c_str());
  legacy->ReadAllScalarsOn();
  legacy->ReadAllVectorsOn();
  legacy->ReadAllNormalsOn();
  legacy->ReadAllTCoordsOn();
  legacy->ReadAllFieldsOn();
  legacy->ReadAllColorScalarsOn();
  const bool header = legacy->OpenVTKFile() && legacy->ReadHeader();
  legacy->CloseVTKFile();
  if (!header)
  {
    error = vtkApertureText::QuoteName(name) + " is not a VTK legacy file";
    return nullptr;
  }
  if (!Run(legacy, messages, name, error))
  {
    return nullptr;
  }
  auto surface = vtkSmartPointer<vtkDataSetSurfaceFilter>::New();
  surface->SetInputConnection(legacy->GetOutputPort());
  return surface;
}

// The reader for a file, after the checks its format needs; null with a sentence when the file
// cannot be read. A PLY file's triangle strips go into `strips` (vtkPLYReader reads none).
vtkSmartPointer<vtkAlgorithm> NewReader(const std::string& name, const std::string& extension,
  MessageCapture& messages, vtkCellArray* strips, std::string& error)
{
  if (extension == ".obj" && CheckOBJ(name, error))
  {
    auto obj = vtkSmartPointer<vtkOBJReader>::New();
    obj->SetFileName(name.c_str());
    return obj;
  }
  if (extension == ".ply" && CheckPLY(name, strips, error))
  {
    auto ply = vtkSmartPointer<vtkPLYReader>::New();
    ply->SetFileName(name.c_str());
    return ply;
  }
  if (extension == ".stl" && CheckSTL(name, error))
  {
    auto stl = vtkSmartPointer<vtkSTLReader>::New();
    stl->SetFileName(name.c_str());
    return stl;
  }
  if (extension == ".vtp")
  {
    auto vtp = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    if (!vtp->CanReadFile(name.c_str()))
    {
      error = vtkApertureText::QuoteName(name) + " is not a VTK XML polydata file";
      return nullptr;
    }
    vtp->SetFileName(name.c_str());
    return CheckVTP(vtp, messages, name, error) ? vtp : nullptr;
  }
  if (extension == ".vtk")
  {
    return NewLegacySurface(name, messages, error);
  }
  error =
    error.empty() ? vtkApertureText::QuoteName(name) + " is not a mesh file this reads" : error;
  return nullptr;
}
}

bool LoadMesh(const std::string& name, const std::string& extension, MessageCapture& messages,
  Input& input, std::string& error)
{
  vtkNew<vtkCellArray> strips;
  vtkSmartPointer<vtkAlgorithm> reader = NewReader(name, extension, messages, strips, error);
  if (!reader || !Run(reader, messages, name, error))
  {
    return false;
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->ShallowCopy(reader->GetOutputDataObject(0));
  if (strips->GetNumberOfCells() > 0)
  {
    mesh->SetStrips(strips);
  }
  if (mesh->GetNumberOfPolys() + mesh->GetNumberOfStrips() == 0)
  {
    std::ostringstream what;
    what << vtkApertureText::QuoteName(name) << " has no polygons to shade ("
         << mesh->GetNumberOfPoints() << " points, " << mesh->GetNumberOfLines() << " lines)";
    error = what.str();
    return false;
  }
  input.Mesh = mesh;
  std::ostringstream description;
  description << vtksys::SystemTools::GetFilenameName(name) << ": " << mesh->GetNumberOfPoints()
              << " points, " << mesh->GetNumberOfPolys() << " polygons";
  if (mesh->GetNumberOfStrips() > 0)
  {
    description << ", " << mesh->GetNumberOfStrips() << " triangle strips";
  }
  input.Description = description.str();
  NoteNonFinitePoints(input);
  return true;
}
}
