/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureSurfaceOutput.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureSurfaceOutput.h"

#include "vtkApertureSurface.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace
{
// Make()'s new points: one per input point and receiving point other than its own, in the
// order asked for, numbered after the input's; each copies its input point with all its data.
class PointSplitter
{
public:
  PointSplitter(vtkIdType inputPoints, const std::vector<vtkIdType>& pointOfInput,
    std::vector<vtkIdType>& outputPoints)
    : N(inputPoints)
    , PointOfInput(pointOfInput)
    , OutputPoints(outputPoints)
  {
  }

  // The output point of input point `id` for receiving point `point`.
  vtkIdType Point(vtkIdType id, vtkIdType point)
  {
    if (point == this->PointOfInput[id] || point < 0)
    {
      return id;
    }
    const std::uint64_t key = static_cast<std::uint64_t>(id) << 32 | std::uint64_t(point);
    auto inserted = this->Added.emplace(key, this->N + static_cast<vtkIdType>(this->Added.size()));
    if (inserted.second)
    {
      this->From->InsertNextId(id);
      this->To->InsertNextId(inserted.first->second);
      this->OutputPoints.push_back(point);
    }
    return inserted.first->second;
  }

  // A copy of `cells` whose split corners (in connectivity order) use their receiving points'.
  vtkSmartPointer<vtkCellArray> Renumber(
    vtkCellArray* cells, const std::vector<vtkApertureSurface::SplitCorner>& splits)
  {
    auto result = vtkSmartPointer<vtkCellArray>::New();
    result->DeepCopy(cells);
    vtkDataArray* connectivity = result->GetConnectivityArray();
    for (const vtkApertureSurface::SplitCorner& corner : splits)
    {
      connectivity->SetTuple1(corner.Corner, this->Point(corner.InputPoint, corner.Point));
    }
    return result;
  }

  // The output's points and point data: the input's, then the new points'.
  void CopyPoints(vtkPolyData* input, vtkPolyData* output) const
  {
    const vtkIdType total = this->N + this->From->GetNumberOfIds();
    vtkNew<vtkPoints> points;
    points->SetDataType(input->GetPoints()->GetDataType());
    points->SetNumberOfPoints(total);
    for (vtkIdType i = 0; i < this->N; ++i)
    {
      points->SetPoint(i, input->GetPoint(i));
    }
    for (vtkIdType k = 0; k < this->From->GetNumberOfIds(); ++k)
    {
      points->SetPoint(this->To->GetId(k), input->GetPoint(this->From->GetId(k)));
    }
    output->SetPoints(points);
    vtkNew<vtkPointData> pd;
    pd->CopyAllOn(vtkDataSetAttributes::COPYTUPLE);
    pd->CopyAllocate(input->GetPointData(), total);
    pd->CopyData(input->GetPointData(), 0, this->N, 0);
    pd->CopyData(input->GetPointData(), this->From, this->To);
    output->GetPointData()->ShallowCopy(pd);
  }

private:
  const vtkIdType N;
  const std::vector<vtkIdType>& PointOfInput;
  std::vector<vtkIdType>& OutputPoints;
  std::unordered_map<std::uint64_t, vtkIdType> Added;
  vtkNew<vtkIdList> From, To;
};

// Cell data when strips became triangles: vertices, lines and polygons as they were, then each
// strip's data on each of its triangles.
void BrokenStripData(const vtkApertureSurface& surface, vtkPolyData* input, vtkPolyData* output)
{
  const vtkIdType before =
    input->GetNumberOfVerts() + input->GetNumberOfLines() + input->GetNumberOfPolys();
  const vtkIdType triangles = static_cast<vtkIdType>(surface.StripTriangles.size() / 7);
  vtkNew<vtkCellData> cd;
  cd->CopyAllOn(vtkDataSetAttributes::COPYTUPLE);
  cd->CopyAllocate(input->GetCellData(), before + triangles);
  cd->CopyData(input->GetCellData(), 0, before, 0);
  for (vtkIdType t = 0; t < triangles; ++t)
  {
    cd->CopyData(input->GetCellData(), before + surface.StripTriangles[7 * t], before + t);
  }
  output->GetCellData()->ShallowCopy(cd);
}
}

//------------------------------------------------------------------------------
void vtkApertureSurfaceOutput::Make(const vtkApertureSurface& surface, vtkPolyData* input,
  vtkPolyData* output, std::vector<vtkIdType>& outputPoints)
{
  output->ShallowCopy(input);
  outputPoints = surface.InputPoints;
  if (surface.SplitPoints == 0 && !surface.BreakStrips)
  {
    return;
  }
  PointSplitter splitter(input->GetNumberOfPoints(), surface.InputPoints, outputPoints);
  vtkSmartPointer<vtkCellArray> polys = splitter.Renumber(input->GetPolys(), surface.PolySplits);
  if (surface.BreakStrips)
  {
    // Strips crossing a crease become their triangles, after the polygons.
    for (size_t t = 0; t < surface.StripTriangles.size(); t += 7)
    {
      const vtkIdType* triangle = &surface.StripTriangles[t + 1];
      const vtkIdType ids[3] = { splitter.Point(triangle[0], triangle[1]),
        splitter.Point(triangle[2], triangle[3]), splitter.Point(triangle[4], triangle[5]) };
      polys->InsertNextCell(3, ids);
    }
    output->SetStrips(vtkSmartPointer<vtkCellArray>::New());
    BrokenStripData(surface, input, output);
  }
  else
  {
    output->SetStrips(splitter.Renumber(input->GetStrips(), surface.StripSplits));
  }
  output->SetPolys(polys);
  splitter.CopyPoints(input, output);
}

//------------------------------------------------------------------------------
namespace
{
template <typename ArrayType, typename T>
vtkSmartPointer<ArrayType> ScatterValues(const std::string& name, int components, const T* begin,
  const T* end, const std::vector<vtkIdType>& outputPoints, const T* open, const T* closed)
{
  const vtkIdType n = static_cast<vtkIdType>(outputPoints.size());
  auto array = vtkSmartPointer<ArrayType>::New();
  array->SetName(name.c_str());
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(n);
  T* out = array->GetPointer(0);
  const vtkIdType points = (end - begin) / components;
  for (vtkIdType o = 0; o < n; ++o)
  {
    const vtkIdType p = outputPoints[o];
    const T* from = p >= 0 && p < points ? begin + components * p
                                         : (p == vtkApertureSurface::Invalid ? closed : open);
    std::copy_n(from, components, out + components * o);
  }
  return array;
}
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkFloatArray> vtkApertureSurfaceOutput::Scatter(const std::string& name,
  int components, const float* begin, const float* end, const std::vector<vtkIdType>& outputPoints,
  const float* open, const float* closed)
{
  return ScatterValues<vtkFloatArray>(name, components, begin, end, outputPoints, open, closed);
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkUnsignedCharArray> vtkApertureSurfaceOutput::Scatter(const std::string& name,
  int components, const unsigned char* begin, const unsigned char* end,
  const std::vector<vtkIdType>& outputPoints, const unsigned char* open,
  const unsigned char* closed)
{
  return ScatterValues<vtkUnsignedCharArray>(
    name, components, begin, end, outputPoints, open, closed);
}

//------------------------------------------------------------------------------
void vtkApertureSurfaceOutput::AddComputedNormals(
  const vtkApertureSurface& surface, vtkPointData* pd, const std::vector<vtkIdType>& outputPoints)
{
  if (surface.NormalsComputed)
  {
    const float none[3] = { 0.0f, 0.0f, 0.0f };
    const float* normals = surface.GetNormal(0);
    pd->SetNormals(Scatter(
      "Normals", 3, normals, normals + 3 * surface.GetNumberOfPoints(), outputPoints, none, none));
  }
}
