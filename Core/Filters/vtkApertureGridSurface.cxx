/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureGridSurface.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureGridSurface.h"

#include "vtkApertureSurface.h"

#include "vtkArrayDispatch.h"
#include "vtkDataArrayRange.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace
{
// Grid geometry of a height field: point (i, j) is Origin + I * i + J * j + Up * height.
struct Grid
{
  int Extent[6];
  vtkIdType Nx, Ny;
  double Origin[3], I[3], J[3], Up[3];

  explicit Grid(vtkImageData* image)
  {
    image->GetExtent(this->Extent);
    this->Nx = this->Extent[1] - this->Extent[0] + 1;
    this->Ny = this->Extent[3] - this->Extent[2] + 1;
    const double* spacing = image->GetSpacing();
    const double* direction = image->GetDirectionMatrix()->GetData();
    image->TransformIndexToPhysicalPoint(
      this->Extent[0], this->Extent[2], this->Extent[4], this->Origin);
    for (int r = 0; r < 3; ++r)
    {
      this->I[r] = direction[3 * r] * spacing[0];
      this->J[r] = direction[3 * r + 1] * spacing[1];
      this->Up[r] = direction[3 * r + 2];
    }
  }

  void Point(vtkIdType i, vtkIdType j, double height, double p[3]) const
  {
    for (int r = 0; r < 3; ++r)
    {
      p[r] = this->Origin[r] + this->I[r] * i + this->J[r] * j + this->Up[r] * height;
    }
  }
};

// Calls `point(id, p)` with the world position of every grid point, heights read in their own
// type.
template <typename Visit>
struct EachGridPoint
{
  const Grid& G;
  double HeightScale;
  Visit& Point;

  template <typename Array>
  void operator()(Array* heights) const
  {
    const auto values = vtk::DataArrayTupleRange(heights);
    double p[3];
    for (vtkIdType j = 0; j < this->G.Ny; ++j)
    {
      for (vtkIdType i = 0; i < this->G.Nx; ++i)
      {
        const vtkIdType id = i + j * this->G.Nx;
        this->G.Point(i, j, this->HeightScale * static_cast<double>(values[id][0]), p);
        this->Point(id, p);
      }
    }
  }
};

template <typename Visit>
void ForEachGridPoint(const Grid& grid, vtkDataArray* heights, double heightScale, Visit&& visit)
{
  const EachGridPoint<Visit> worker{ grid, heightScale, visit };
  if (!vtkArrayDispatch::Dispatch::Execute(heights, worker))
  {
    worker(heights);
  }
}

// The grid's points in world coordinates (3 each), and whether each is finite.
void GridPoints(const Grid& grid, vtkDataArray* heights, double heightScale,
  std::vector<double>& world, std::vector<unsigned char>& finite)
{
  world.resize(3 * grid.Nx * grid.Ny);
  finite.assign(grid.Nx * grid.Ny, 0);
  ForEachGridPoint(grid, heights, heightScale,
    [&](vtkIdType id, const double p[3])
    {
      std::copy_n(p, 3, &world[3 * id]);
      finite[id] = vtkApertureSurface::IsUsable(p);
    });
}

// Two triangles per grid cell, those with three finite corners, wound so that their normals
// point along the grid's third axis.
std::vector<std::uint32_t> GridTriangles(const Grid& grid, const std::vector<unsigned char>& finite)
{
  const double cross[3] = { grid.I[1] * grid.J[2] - grid.I[2] * grid.J[1],
    grid.I[2] * grid.J[0] - grid.I[0] * grid.J[2], grid.I[0] * grid.J[1] - grid.I[1] * grid.J[0] };
  const bool flip = vtkMath::Dot(cross, grid.Up) < 0.0;
  std::vector<std::uint32_t> triangles;
  triangles.reserve(6 * (grid.Nx - 1) * (grid.Ny - 1));
  auto addTriangle = [&](vtkIdType a, vtkIdType b, vtkIdType c)
  {
    if (finite[a] && finite[b] && finite[c])
    {
      for (const vtkIdType corner : { a, flip ? c : b, flip ? b : c })
      {
        triangles.push_back(static_cast<std::uint32_t>(corner));
      }
    }
  };
  for (vtkIdType j = 0; j + 1 < grid.Ny; ++j)
  {
    for (vtkIdType i = 0; i + 1 < grid.Nx; ++i)
    {
      const vtkIdType p00 = i + j * grid.Nx;
      addTriangle(p00, p00 + 1, p00 + 1 + grid.Nx);
      addTriangle(p00, p00 + 1 + grid.Nx, p00 + grid.Nx);
    }
  }
  return triangles;
}

// The receiving points, one per grid point, with the normal `normalOf(id, n)` gives.
template <typename NormalOf>
void FillGridPoints(vtkApertureSurface& surface, const std::vector<double>& world,
  const std::vector<unsigned char>& finite, NormalOf normalOf)
{
  const vtkIdType n = static_cast<vtkIdType>(finite.size());
  surface.Normals->SetNumberOfTuples(n);
  surface.PointVertex.resize(n);
  surface.Valid.assign(n, 0);
  surface.Key.resize(n);
  float* normals = surface.Normals->GetPointer(0);
  for (vtkIdType id = 0; id < n; ++id)
  {
    surface.PointVertex[id] = static_cast<std::uint32_t>(id);
    surface.Key[id] = vtkApertureSurface::PointKey(&world[3 * id], 0);
    double nrm[3];
    normalOf(id, nrm);
    const double length = vtkMath::Normalize(nrm);
    surface.Valid[id] = finite[id] && length > 0.0 && std::isfinite(length);
    for (int k = 0; k < 3; ++k)
    {
      normals[3 * id + k] = surface.Valid[id] ? static_cast<float>(nrm[k]) : 0.0f;
    }
    surface.InputPoints[id] = id;
    surface.UndefinedNormals += (finite[id] && !surface.Valid[id]) ? 1 : 0;
  }
}

// One receiving point per grid point: the given normal (read in its own type), or the sum of
// its triangles' normals.
void SetGridPoints(vtkApertureSurface& surface, vtkImageData* input,
  const std::vector<double>& world, const std::vector<unsigned char>& finite)
{
  vtkDataArray* given = vtkApertureSurface::GivenNormals(input);
  surface.NormalsComputed = given == nullptr;
  if (!given)
  {
    const std::vector<double> sums = surface.WindingNormals(static_cast<vtkIdType>(finite.size()));
    FillGridPoints(surface, world, finite,
      [&sums](vtkIdType id, double nrm[3]) { std::copy_n(&sums[3 * id], 3, nrm); });
    return;
  }
  auto fill = [&](auto* array)
  {
    const auto tuples = vtk::DataArrayTupleRange<3>(array);
    FillGridPoints(surface, world, finite,
      [&tuples](vtkIdType id, double nrm[3])
      {
        for (int k = 0; k < 3; ++k)
        {
          nrm[k] = static_cast<double>(tuples[id][k]);
        }
      });
  };
  if (!vtkArrayDispatch::Dispatch::Execute(given, fill))
  {
    fill(given);
  }
  surface.CountFlippedNormals();
}
}

//------------------------------------------------------------------------------
bool vtkApertureGridSurface::Set(vtkApertureSurface& surface, vtkImageData* input,
  vtkDataArray* heights, double heightScale, const double origin[3], std::string& error)
{
  const Grid grid(input);
  const vtkIdType n = grid.Nx * grid.Ny;
  if (n >= static_cast<vtkIdType>(vtkApertureSurface::NoVertex))
  {
    error = "more than 2^32 grid points";
    return false;
  }
  surface.Reset(n);
  std::copy_n(origin, 3, surface.Origin);
  std::vector<double> world;
  std::vector<unsigned char> finite;
  GridPoints(grid, heights, heightScale, world, finite);
  surface.Vertices.assign(3 * n + 1, 0.0f);
  for (vtkIdType id = 0; id < n; ++id)
  {
    for (int k = 0; k < 3 && finite[id]; ++k)
    {
      surface.Vertices[3 * id + k] = static_cast<float>(world[3 * id + k] - origin[k]);
    }
    surface.UnusablePoints += finite[id] ? 0 : 1;
  }
  surface.Triangles = GridTriangles(grid, finite);
  if (surface.Triangles.empty())
  {
    error = "the height field has no finite cell";
    return false;
  }
  surface.CornerPoints = surface.Triangles;
  SetGridPoints(surface, input, world, finite);
  return true;
}

//------------------------------------------------------------------------------
void vtkApertureGridSurface::ExpandBounds(
  vtkImageData* input, vtkDataArray* heights, double heightScale, double bounds[6])
{
  ForEachGridPoint(Grid(input), heights, heightScale,
    [&](vtkIdType, const double p[3])
    {
      if (!vtkApertureSurface::IsUsable(p))
      {
        return;
      }
      for (int k = 0; k < 3; ++k)
      {
        bounds[2 * k] = std::min(bounds[2 * k], p[k]);
        bounds[2 * k + 1] = std::max(bounds[2 * k + 1], p[k]);
      }
    });
}
