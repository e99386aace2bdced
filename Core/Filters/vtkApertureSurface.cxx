/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureSurface.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureSurface.h"

#include "vtkApertureMemory.h"
#include "vtkApertureRaySampler.h"

#include "vtkApertureSMP.h"
#include "vtkArrayDispatch.h"
#include "vtkCellArray.h"
#include "vtkDataArrayRange.h"
#include "vtkDataSet.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <cstring>

// Defined here too: C++14 (Clang's default) needs a definition for the references that
// std::vector's assign() and friends bind to it.
constexpr std::uint32_t vtkApertureSurface::NoVertex;

//------------------------------------------------------------------------------
bool vtkApertureSurface::IsUsable(const double p[3])
{
  // Written so that NaN fails too.
  return std::abs(p[0]) <= LargestCoordinate && std::abs(p[1]) <= LargestCoordinate &&
    std::abs(p[2]) <= LargestCoordinate;
}

//------------------------------------------------------------------------------
vtkDataArray* vtkApertureSurface::GivenNormals(vtkDataSet* input)
{
  vtkDataArray* normals = input->GetPointData()->GetNormals();
  if (normals && normals->GetNumberOfComponents() == 3 &&
    normals->GetNumberOfTuples() == input->GetNumberOfPoints())
  {
    return normals;
  }
  return nullptr;
}

//------------------------------------------------------------------------------
std::uint64_t vtkApertureSurface::PointKey(const double p[3], unsigned int side)
{
  std::uint64_t h = vtkApertureRaySampler::Mix(side);
  for (int k = 0; k < 3; ++k)
  {
    const double x = p[k] + 0.0;
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof(bits));
    h = vtkApertureRaySampler::Mix(h ^ bits);
  }
  return h;
}

//------------------------------------------------------------------------------
std::uint64_t vtkApertureSurface::IdKey(vtkIdType id, unsigned int side)
{
  // Apart from every position's key: a different first mix.
  return vtkApertureRaySampler::Mix(
    vtkApertureRaySampler::Mix(~std::uint64_t(side)) ^ static_cast<std::uint64_t>(id));
}

//------------------------------------------------------------------------------
void vtkApertureSurface::KeyByPointIds(vtkDataArray* globalIds)
{
  std::vector<vtkIdType> first(this->GetNumberOfVertices(), -1);
  for (size_t i = 0; i < this->InputPoints.size(); ++i)
  {
    const vtkIdType point = this->InputPoints[i];
    if (point >= 0 && first[this->PointVertex[point]] < 0)
    {
      first[this->PointVertex[point]] = globalIds
        ? static_cast<vtkIdType>(globalIds->GetTuple1(static_cast<vtkIdType>(i)))
        : static_cast<vtkIdType>(i);
    }
  }
  // A vertex's sides are consecutive receiving points.
  unsigned int side = 0;
  for (size_t p = 0; p < this->PointVertex.size(); ++p)
  {
    side = p > 0 && this->PointVertex[p] == this->PointVertex[p - 1] ? side + 1 : 0;
    this->Key[p] = IdKey(first[this->PointVertex[p]], side);
  }
}

//------------------------------------------------------------------------------
void vtkApertureSurface::InitializeBounds(double bounds[6])
{
  for (int k = 0; k < 3; ++k)
  {
    bounds[2 * k] = VTK_DOUBLE_MAX;
    bounds[2 * k + 1] = -VTK_DOUBLE_MAX;
  }
}

//------------------------------------------------------------------------------
void vtkApertureSurface::OriginOf(const double bounds[6], double origin[3])
{
  const double side =
    std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  const double step =
    side > 0.0 && side < VTK_DOUBLE_MAX ? std::ldexp(1.0, std::ilogb(side) - 4) : 0.0;
  for (int k = 0; k < 3; ++k)
  {
    const double middle = bounds[0] <= bounds[1] ? 0.5 * (bounds[2 * k] + bounds[2 * k + 1]) : 0.0;
    origin[k] = step > 0.0 ? step * std::round(middle / step) : middle;
  }
}

//------------------------------------------------------------------------------
void vtkApertureSurface::ExpandBounds(vtkPolyData* input, double bounds[6])
{
  vtkDataArray* data = input->GetPoints() ? input->GetPoints()->GetData() : nullptr;
  auto expand = [bounds](auto* array)
  {
    for (const auto tuple : vtk::DataArrayTupleRange<3>(array))
    {
      const double p[3] = { static_cast<double>(tuple[0]), static_cast<double>(tuple[1]),
        static_cast<double>(tuple[2]) };
      if (!IsUsable(p))
      {
        continue;
      }
      for (int k = 0; k < 3; ++k)
      {
        bounds[2 * k] = std::min(bounds[2 * k], p[k]);
        bounds[2 * k + 1] = std::max(bounds[2 * k + 1], p[k]);
      }
    }
  };
  if (data && !vtkArrayDispatch::Dispatch::Execute(data, expand))
  {
    expand(data);
  }
}

//------------------------------------------------------------------------------
void vtkApertureSurface::WorldPoints(vtkPoints* points, std::vector<double>& world)
{
  vtkDataArray* data = points ? points->GetData() : nullptr;
  vtkApertureMemory::Assign(world, data ? 3 * data->GetNumberOfTuples() : 0);
  auto copy = [&world](auto* array)
  {
    const auto tuples = vtk::DataArrayTupleRange<3>(array);
    vtkApertureSMP::For(0, tuples.size(),
      [&](vtkIdType first, vtkIdType last)
      {
        for (vtkIdType i = first; i < last; ++i)
        {
          for (int k = 0; k < 3; ++k)
          {
            world[3 * i + k] = static_cast<double>(tuples[i][k]);
          }
        }
      });
  };
  if (data && !vtkArrayDispatch::Dispatch::Execute(data, copy))
  {
    copy(data);
  }
}

//------------------------------------------------------------------------------
const float* vtkApertureSurface::GetNormal(vtkIdType point) const
{
  return this->Normals->GetPointer(3 * point);
}

//------------------------------------------------------------------------------
void vtkApertureSurface::Reserve(vtkIdType points)
{
  vtkApertureMemory::Reserve(this->PointVertex, points);
  vtkApertureMemory::Reserve(this->Valid, points);
  vtkApertureMemory::Reserve(this->Key, points);
  this->Normals->Allocate(3 * points);
  vtkApertureMemory::AdviseHugePages(this->Normals->GetVoidPointer(0), 3 * points * sizeof(float));
}

//------------------------------------------------------------------------------
void vtkApertureSurface::Reset(vtkIdType inputPoints)
{
  this->Vertices.clear();
  this->Triangles.clear();
  this->PointVertex.clear();
  this->Normals = vtkSmartPointer<vtkFloatArray>::New();
  this->Normals->SetName("Normals");
  this->Normals->SetNumberOfComponents(3);
  this->Valid.clear();
  this->Offset.clear();
  this->Key.clear();
  this->CornerPoints.clear();
  vtkApertureMemory::Assign(this->InputPoints, inputPoints, NotOnSurface);
  this->PolySplits.clear();
  this->StripSplits.clear();
  this->StripTriangles.clear();
  this->NormalsComputed = false;
  this->UnusablePoints = 0;
  this->UndefinedNormals = 0;
  this->FlippedNormals = 0;
  this->SplitPoints = 0;
  this->BreakStrips = false;
}

//------------------------------------------------------------------------------
std::vector<double> vtkApertureSurface::WindingNormals(vtkIdType points) const
{
  std::vector<double> sums(3 * points, 0.0);
  for (size_t t = 0; t < this->Triangles.size(); t += 3)
  {
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      const float* v = &this->Vertices[3 * size_t(this->Triangles[t + k])];
      std::copy(v, v + 3, p[k]);
    }
    const double e1[3] = { p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2] };
    const double e2[3] = { p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2] };
    double n[3];
    vtkMath::Cross(e1, e2, n);
    if (vtkMath::Normalize(n) > 0.0)
    {
      for (int k = 0; k < 3; ++k)
      {
        for (int c = 0; c < 3; ++c)
        {
          sums[3 * size_t(this->CornerPoints[t + k]) + c] += n[c];
        }
      }
    }
  }
  return sums;
}

//------------------------------------------------------------------------------
void vtkApertureSurface::CountFlippedNormals()
{
  const std::vector<double> winding = this->WindingNormals(this->GetNumberOfPoints());
  this->FlippedNormals = 0;
  for (vtkIdType i = 0; i < this->GetNumberOfPoints(); ++i)
  {
    const float* n = this->GetNormal(i);
    const double dot =
      n[0] * winding[3 * i] + n[1] * winding[3 * i + 1] + n[2] * winding[3 * i + 2];
    this->FlippedNormals += (this->Valid[i] && dot < 0.0) ? 1 : 0;
  }
}

//------------------------------------------------------------------------------
void vtkApertureSurface::CountSplitPoints()
{
  std::vector<unsigned char> split(this->InputPoints.size(), 0);
  for (const auto* splits : { &this->PolySplits, &this->StripSplits })
  {
    for (const SplitCorner& corner : *splits)
    {
      split[corner.InputPoint] = 1;
    }
  }
  this->SplitPoints = std::count(split.begin(), split.end(), 1);
}

//------------------------------------------------------------------------------
void vtkApertureSurface::KeepInputs(vtkPolyData* input)
{
  const vtkIdType n = input->GetNumberOfPoints();
  this->InputPoints.resize(n);
  // The input's cells come first: its corners are the first of each connectivity.
  auto keep = [](std::vector<SplitCorner>& splits, vtkCellArray* cells)
  {
    const vtkIdType corners = cells->GetNumberOfConnectivityIds();
    splits.erase(std::find_if(splits.begin(), splits.end(),
                   [corners](const SplitCorner& s) { return s.Corner >= corners; }),
      splits.end());
  };
  keep(this->PolySplits, input->GetPolys());
  keep(this->StripSplits, input->GetStrips());
  const vtkIdType strips = input->GetNumberOfStrips();
  std::vector<vtkIdType> stripTriangles;
  for (size_t t = 0; t < this->StripTriangles.size(); t += 7)
  {
    if (this->StripTriangles[t] < strips)
    {
      stripTriangles.insert(stripTriangles.end(), this->StripTriangles.begin() + t,
        this->StripTriangles.begin() + t + 7);
    }
  }
  this->StripTriangles.swap(stripTriangles);
  this->BreakStrips = this->BreakStrips && strips > 0;

  // The counts, over the input's points only.
  this->CountSplitPoints();
  this->UnusablePoints = 0;
  this->UndefinedNormals = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    const vtkIdType point = this->InputPoints[i];
    const bool finite = IsUsable(p);
    this->UnusablePoints += point == Invalid && !finite ? 1 : 0;
    this->UndefinedNormals += finite && (point == Invalid || (point >= 0 && !this->Valid[point]));
  }
}
