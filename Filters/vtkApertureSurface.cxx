/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureSurface.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureSurface.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkPolygon.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
bool IsFinite(const double p[3])
{
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

void Expand(const double p[3], double bounds[6])
{
  for (int k = 0; k < 3; ++k)
  {
    bounds[2 * k] = std::min(bounds[2 * k], p[k]);
    bounds[2 * k + 1] = std::max(bounds[2 * k + 1], p[k]);
  }
}

// Point normals the input provides: 3 components, one tuple per point.
vtkDataArray* UsableNormals(vtkDataSet* input)
{
  vtkDataArray* normals = input->GetPointData()->GetNormals();
  if (normals && normals->GetNumberOfComponents() == 3 &&
    normals->GetNumberOfTuples() == input->GetNumberOfPoints())
  {
    return normals;
  }
  return nullptr;
}

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
  for (int k = 0; k < 3; ++k)
  {
    origin[k] = bounds[0] <= bounds[1] ? 0.5 * (bounds[2 * k] + bounds[2 * k + 1]) : 0.0;
  }
}

//------------------------------------------------------------------------------
void vtkApertureSurface::ExpandBounds(vtkPolyData* input, double bounds[6])
{
  vtkPoints* points = input->GetPoints();
  const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  double p[3];
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->GetPoint(i, p);
    if (IsFinite(p))
    {
      Expand(p, bounds);
    }
  }
}

//------------------------------------------------------------------------------
void vtkApertureSurface::ExpandBounds(
  vtkImageData* input, vtkDataArray* heights, double heightScale, double bounds[6])
{
  const Grid grid(input);
  double p[3];
  for (vtkIdType j = 0; j < grid.Ny; ++j)
  {
    for (vtkIdType i = 0; i < grid.Nx; ++i)
    {
      grid.Point(i, j, heightScale * heights->GetComponent(i + j * grid.Nx, 0), p);
      if (IsFinite(p))
      {
        Expand(p, bounds);
      }
    }
  }
}

//------------------------------------------------------------------------------
const float* vtkApertureSurface::GetNormal(vtkIdType id) const
{
  return this->Normals->GetPointer(3 * id);
}

//------------------------------------------------------------------------------
void vtkApertureSurface::Allocate(vtkIdType n)
{
  this->Points.assign(3 * n + 1, 0.0f);
  this->Triangles.clear();
  this->Normals = vtkSmartPointer<vtkFloatArray>::New();
  this->Normals->SetName("Normals");
  this->Normals->SetNumberOfComponents(3);
  this->Normals->SetNumberOfTuples(n);
  this->Normals->Fill(0.0);
  this->NormalsComputed = false;
  this->Receives.assign(n, 0);
  this->Valid.assign(n, 0);
  this->EdgeLength.assign(n, 0.0f);
  this->NonFinitePoints = 0;
  this->UndefinedNormals = 0;
  this->FlippedNormals = 0;
}

//------------------------------------------------------------------------------
bool vtkApertureSurface::SetPolyData(vtkPolyData* input, const double origin[3], std::string& error)
{
  const vtkIdType n = input->GetNumberOfPoints();
  if (n >= static_cast<vtkIdType>(std::numeric_limits<std::uint32_t>::max()))
  {
    error = "more than 2^32 points";
    return false;
  }
  this->Allocate(n);
  std::copy_n(origin, 3, this->Origin);

  std::vector<unsigned char> finite(n, 0);
  vtkPoints* points = input->GetPoints();
  double p[3];
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->GetPoint(i, p);
    finite[i] = IsFinite(p);
    for (int k = 0; k < 3 && finite[i]; ++k)
    {
      this->Points[3 * i + k] = static_cast<float>(p[k] - origin[k]);
    }
  }

  auto addTriangle = [&](vtkIdType a, vtkIdType b, vtkIdType c)
  {
    if (finite[a] && finite[b] && finite[c])
    {
      this->Triangles.push_back(static_cast<std::uint32_t>(a));
      this->Triangles.push_back(static_cast<std::uint32_t>(b));
      this->Triangles.push_back(static_cast<std::uint32_t>(c));
    }
  };

  // Polygons: triangles as they are, larger polygons by ear cutting (a fan where that fails).
  vtkNew<vtkPolygon> polygon;
  vtkNew<vtkIdList> local;
  vtkIdType npts;
  const vtkIdType* ids;
  auto polys = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    polys->GetCurrentCell(npts, ids);
    bool allFinite = true;
    for (vtkIdType k = 0; k < npts; ++k)
    {
      this->Receives[ids[k]] = 1;
      allFinite = allFinite && finite[ids[k]];
    }
    if (npts == 3)
    {
      addTriangle(ids[0], ids[1], ids[2]);
    }
    else if (npts > 3 && allFinite)
    {
      polygon->Initialize(static_cast<int>(npts), ids, points);
      if (polygon->Triangulate(local) && local->GetNumberOfIds() == 3 * (npts - 2))
      {
        for (vtkIdType t = 0; t < local->GetNumberOfIds(); t += 3)
        {
          addTriangle(ids[local->GetId(t)], ids[local->GetId(t + 1)], ids[local->GetId(t + 2)]);
        }
      }
      else
      {
        for (vtkIdType k = 1; k + 1 < npts; ++k)
        {
          addTriangle(ids[0], ids[k], ids[k + 1]);
        }
      }
    }
  }

  // Strips alternate their winding.
  auto strips = vtk::TakeSmartPointer(input->GetStrips()->NewIterator());
  for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell())
  {
    strips->GetCurrentCell(npts, ids);
    for (vtkIdType k = 0; k < npts; ++k)
    {
      this->Receives[ids[k]] = 1;
    }
    for (vtkIdType k = 0; k + 2 < npts; ++k)
    {
      if (k % 2 == 0)
      {
        addTriangle(ids[k], ids[k + 1], ids[k + 2]);
      }
      else
      {
        addTriangle(ids[k + 1], ids[k], ids[k + 2]);
      }
    }
  }

  for (vtkIdType i = 0; i < n; ++i)
  {
    this->NonFinitePoints += (this->Receives[i] && !finite[i]) ? 1 : 0;
  }

  std::vector<float> winding;
  this->AccumulateTriangleData(winding);

  vtkDataArray* given = UsableNormals(input);
  vtkSmartPointer<vtkDataArray> oriented;
  if (!given && !this->ConsistentlyWound())
  {
    // vtkPolyDataNormals makes the orientation consistent first (without splitting, so that
    // points stay 1:1); only meshes with inconsistent winding pay for it.
    vtkNew<vtkCellArray> cells;
    cells->AllocateExact(this->GetNumberOfTriangles(), 3 * this->GetNumberOfTriangles());
    for (size_t t = 0; t < this->Triangles.size(); t += 3)
    {
      const vtkIdType tri[3] = { this->Triangles[t], this->Triangles[t + 1],
        this->Triangles[t + 2] };
      cells->InsertNextCell(3, tri);
    }
    vtkNew<vtkPolyData> triangles;
    triangles->SetPoints(points);
    triangles->SetPolys(cells);
    vtkNew<vtkPolyDataNormals> normalsFilter;
    normalsFilter->SetInputData(triangles);
    normalsFilter->SplittingOff();
    normalsFilter->ConsistencyOn();
    normalsFilter->NonManifoldTraversalOn();
    normalsFilter->ComputePointNormalsOn();
    normalsFilter->ComputeCellNormalsOff();
    normalsFilter->Update();
    oriented = normalsFilter->GetOutput()->GetPointData()->GetNormals();
    if (!oriented || oriented->GetNumberOfTuples() != n)
    {
      error = "could not compute point normals";
      return false;
    }
  }
  this->SetNormals(given ? given : oriented.Get(), given != nullptr, finite, winding);
  return true;
}

//------------------------------------------------------------------------------
bool vtkApertureSurface::ConsistentlyWound() const
{
  std::vector<std::uint64_t> edges;
  edges.reserve(this->Triangles.size());
  for (size_t t = 0; t < this->Triangles.size(); t += 3)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::uint64_t a = this->Triangles[t + k];
      const std::uint64_t b = this->Triangles[t + (k + 1) % 3];
      if (a != b)
      {
        edges.push_back((a << 32) | b);
      }
    }
  }
  std::sort(edges.begin(), edges.end());
  return std::adjacent_find(edges.begin(), edges.end()) == edges.end();
}

//------------------------------------------------------------------------------
void vtkApertureSurface::SetNormals(vtkDataArray* normals, bool given,
  const std::vector<unsigned char>& finite, const std::vector<float>& winding)
{
  this->NormalsComputed = !given;
  float* out = this->Normals->GetPointer(0);
  for (vtkIdType i = 0; i < this->GetNumberOfPoints(); ++i)
  {
    if (!finite[i])
    {
      continue;
    }
    double nrm[3] = { winding[3 * i], winding[3 * i + 1], winding[3 * i + 2] };
    if (normals)
    {
      normals->GetTuple(i, nrm);
    }
    const double length = std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
    if (!(length > 0.0) || !std::isfinite(length))
    {
      this->UndefinedNormals += this->Receives[i] ? 1 : 0;
      continue;
    }
    for (int k = 0; k < 3; ++k)
    {
      out[3 * i + k] = static_cast<float>(nrm[k] / length);
    }
    this->Valid[i] = 1;
    const double dot =
      nrm[0] * winding[3 * i] + nrm[1] * winding[3 * i + 1] + nrm[2] * winding[3 * i + 2];
    this->FlippedNormals += (given && this->Receives[i] && dot < 0.0) ? 1 : 0;
  }
}

//------------------------------------------------------------------------------
bool vtkApertureSurface::SetHeightField(vtkImageData* input, vtkDataArray* heights,
  double heightScale, const double origin[3], std::string& error)
{
  const Grid grid(input);
  const vtkIdType n = grid.Nx * grid.Ny;
  if (n >= static_cast<vtkIdType>(std::numeric_limits<std::uint32_t>::max()))
  {
    error = "more than 2^32 grid points";
    return false;
  }
  std::copy_n(origin, 3, this->Origin);
  this->Allocate(n);

  std::vector<unsigned char> finite(n, 0);
  double p[3];
  for (vtkIdType j = 0; j < grid.Ny; ++j)
  {
    for (vtkIdType i = 0; i < grid.Nx; ++i)
    {
      const vtkIdType id = i + j * grid.Nx;
      grid.Point(i, j, heightScale * heights->GetComponent(id, 0), p);
      finite[id] = IsFinite(p);
      this->Receives[id] = 1;
      for (int k = 0; k < 3 && finite[id]; ++k)
      {
        this->Points[3 * id + k] = static_cast<float>(p[k] - origin[k]);
      }
      this->NonFinitePoints += finite[id] ? 0 : 1;
    }
  }

  // Wind the triangles so that their normals point along the grid's third axis.
  double cross[3] = { grid.I[1] * grid.J[2] - grid.I[2] * grid.J[1],
    grid.I[2] * grid.J[0] - grid.I[0] * grid.J[2], grid.I[0] * grid.J[1] - grid.I[1] * grid.J[0] };
  const bool flip = cross[0] * grid.Up[0] + cross[1] * grid.Up[1] + cross[2] * grid.Up[2] < 0.0;
  this->Triangles.reserve(6 * (grid.Nx - 1) * (grid.Ny - 1));
  auto addTriangle = [&](vtkIdType a, vtkIdType b, vtkIdType c)
  {
    if (finite[a] && finite[b] && finite[c])
    {
      this->Triangles.push_back(static_cast<std::uint32_t>(a));
      this->Triangles.push_back(static_cast<std::uint32_t>(flip ? c : b));
      this->Triangles.push_back(static_cast<std::uint32_t>(flip ? b : c));
    }
  };
  for (vtkIdType j = 0; j + 1 < grid.Ny; ++j)
  {
    for (vtkIdType i = 0; i + 1 < grid.Nx; ++i)
    {
      const vtkIdType p00 = i + j * grid.Nx;
      const vtkIdType p10 = p00 + 1;
      const vtkIdType p01 = p00 + grid.Nx;
      const vtkIdType p11 = p01 + 1;
      addTriangle(p00, p10, p11);
      addTriangle(p00, p11, p01);
    }
  }

  std::vector<float> winding;
  this->AccumulateTriangleData(winding);

  vtkDataArray* given = UsableNormals(input);
  this->SetNormals(given, given != nullptr, finite, winding);
  if (this->Triangles.empty())
  {
    error = "the height field has no finite cell";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkApertureSurface::AccumulateTriangleData(std::vector<float>& winding)
{
  const vtkIdType n = this->GetNumberOfPoints();
  winding.assign(3 * n, 0.0f);
  std::vector<float> edgeSum(n, 0.0f);
  std::vector<std::uint32_t> edgeCount(n, 0);
  const float* pts = this->Points.data();
  for (size_t t = 0; t < this->Triangles.size(); t += 3)
  {
    const std::uint32_t v[3] = { this->Triangles[t], this->Triangles[t + 1],
      this->Triangles[t + 2] };
    float e[3][3];
    for (int k = 0; k < 3; ++k)
    {
      const float* a = pts + 3 * v[k];
      const float* b = pts + 3 * v[(k + 1) % 3];
      for (int c = 0; c < 3; ++c)
      {
        e[k][c] = b[c] - a[c];
      }
      const float length = std::sqrt(e[k][0] * e[k][0] + e[k][1] * e[k][1] + e[k][2] * e[k][2]);
      for (const std::uint32_t end : { v[k], v[(k + 1) % 3] })
      {
        edgeSum[end] += length;
        ++edgeCount[end];
      }
    }
    // Unit triangle normal, summed at each corner (degenerate triangles add nothing).
    const float nrm[3] = { e[0][1] * e[1][2] - e[0][2] * e[1][1],
      e[0][2] * e[1][0] - e[0][0] * e[1][2], e[0][0] * e[1][1] - e[0][1] * e[1][0] };
    const float length = std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
    if (length > 0.0f)
    {
      for (const std::uint32_t corner : v)
      {
        for (int c = 0; c < 3; ++c)
        {
          winding[3 * corner + c] += nrm[c] / length;
        }
      }
    }
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    this->EdgeLength[i] = edgeCount[i] ? edgeSum[i] / edgeCount[i] : 0.0f;
  }
}

//------------------------------------------------------------------------------
bool vtkApertureSurface::SetScene(vtkPolyData* input, const std::vector<vtkPolyData*>& occluders,
  vtkApertureSurface& receivers, std::vector<vtkApertureSurface>& occluderSurfaces,
  std::string& error)
{
  // One local origin for everything keeps single precision where the geometry is.
  double bounds[6];
  InitializeBounds(bounds);
  ExpandBounds(input, bounds);
  for (vtkPolyData* occluder : occluders)
  {
    ExpandBounds(occluder, bounds);
  }
  double origin[3];
  OriginOf(bounds, origin);
  std::string problem;
  if (!receivers.SetPolyData(input, origin, problem))
  {
    error = "Cannot use the input: " + problem + ".";
    return false;
  }
  occluderSurfaces = std::vector<vtkApertureSurface>(occluders.size());
  vtkIdType triangles = receivers.GetNumberOfTriangles();
  for (size_t i = 0; i < occluders.size(); ++i)
  {
    if (!occluderSurfaces[i].SetPolyData(occluders[i], origin, problem))
    {
      error = "Cannot use occluder " + std::to_string(i) + ": " + problem + ".";
      return false;
    }
    triangles += occluderSurfaces[i].GetNumberOfTriangles();
  }
  if (triangles == 0)
  {
    error = "Neither the input nor the occluders have polygons or triangle strips: nothing casts "
            "shadows and points have no normals.";
    return false;
  }
  return true;
}
