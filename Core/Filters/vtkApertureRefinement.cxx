/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureRefinement.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureRefinement.h"

#include "vtkApertureMeshSurface.h"
#include "vtkApertureSurface.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <array>
#include <cmath>
#include <sstream>
#include <unordered_map>
#include <vector>

namespace
{
// A point of the refined surface as a combination of at most three input points (those of the
// input triangle it lies in).
struct Combination
{
  std::array<vtkIdType, 3> Ids = { { -1, -1, -1 } };
  std::array<double, 3> Weights = { { 0.0, 0.0, 0.0 } };
};

class Refiner
{
public:
  Refiner(vtkPolyData* input, double maximumEdgeLength)
    : Input(input)
    , Maximum2(maximumEdgeLength * maximumEdgeLength)
  {
    const vtkIdType n = input->GetNumberOfPoints();
    vtkApertureSurface::WorldPoints(input->GetPoints(), this->Points);
    this->Combinations.resize(n);
    this->Finite.resize(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      const double* x = &this->Points[3 * i];
      this->Finite[i] = std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
      this->Combinations[i].Ids[0] = i;
      this->Combinations[i].Weights[0] = 1.0;
    }
  }

  // The input's polygons and strips as triangles, each with its cell.
  void Triangulate()
  {
    std::vector<vtkIdType> local;
    vtkIdType cell = this->Input->GetNumberOfVerts() + this->Input->GetNumberOfLines();
    vtkApertureMeshSurface::ForEachPolygonOrStrip(this->Input,
      [&](vtkIdType npts, const vtkIdType* ids, bool strip)
      {
        local.clear();
        vtkApertureMeshSurface::Triangulate(
          npts, ids, strip, this->Input->GetPoints(), this->Finite.data(), local);
        for (const vtkIdType k : local)
        {
          this->Triangles.push_back(ids[k]);
        }
        this->Cells.insert(this->Cells.end(), local.size() / 3, cell++);
      });
  }

  // One pass: every edge longer than the maximum split at its midpoint. False when nothing was.
  bool Pass()
  {
    std::vector<vtkIdType> triangles, cells;
    bool split = false;
    for (size_t t = 0; t < this->Cells.size(); ++t)
    {
      vtkIdType p[6] = { this->Triangles[3 * t], this->Triangles[3 * t + 1],
        this->Triangles[3 * t + 2], -1, -1, -1 };
      int mask = 0;
      for (int e = 0; e < 3; ++e)
      {
        if (vtkMath::Distance2BetweenPoints(this->Point(p[e]), this->Point(p[(e + 1) % 3])) >
          this->Maximum2)
        {
          mask |= 1 << e;
          p[3 + e] = this->Midpoint(p[e], p[(e + 1) % 3]);
        }
      }
      split = split || mask != 0;
      const size_t before = triangles.size();
      this->Split(p, mask, triangles);
      cells.insert(cells.end(), (triangles.size() - before) / 3, this->Cells[t]);
    }
    this->Triangles.swap(triangles);
    this->Cells.swap(cells);
    return split;
  }

  vtkIdType GetNumberOfTriangles() const { return static_cast<vtkIdType>(this->Cells.size()); }

  void Write(vtkPolyData* output) const;

private:
  const double* Point(vtkIdType id) const { return &this->Points[3 * id]; }

  vtkIdType Midpoint(vtkIdType a, vtkIdType b)
  {
    const std::uint64_t key =
      static_cast<std::uint64_t>(std::min(a, b)) << 32 | static_cast<std::uint64_t>(std::max(a, b));
    const vtkIdType next = static_cast<vtkIdType>(this->Combinations.size());
    auto inserted = this->Midpoints.emplace(key, next);
    if (!inserted.second)
    {
      return inserted.first->second;
    }
    for (int k = 0; k < 3; ++k)
    {
      this->Points.push_back(0.5 * (this->Points[3 * a + k] + this->Points[3 * b + k]));
    }
    Combination mid;
    int used = 0;
    for (const Combination* end : { &this->Combinations[a], &this->Combinations[b] })
    {
      for (int k = 0; k < 3 && end->Ids[k] >= 0; ++k)
      {
        int slot = 0;
        while (slot < used && mid.Ids[slot] != end->Ids[k])
        {
          ++slot;
        }
        if (slot == used && used < 3) // both ends lie in one input triangle: at most 3 ids
        {
          mid.Ids[used++] = end->Ids[k];
        }
        if (slot < 3)
        {
          mid.Weights[slot] += 0.5 * end->Weights[k];
        }
      }
    }
    this->Combinations.push_back(mid);
    return next;
  }

  // Appends the triangles a triangle with corners p[0..2] and midpoints p[3..5] becomes.
  void Split(const vtkIdType p[6], int mask, std::vector<vtkIdType>& out) const
  {
    auto triangle = [&](int a, int b, int c) { out.insert(out.end(), { p[a], p[b], p[c] }); };
    // A quadrilateral a b c d (in the triangle's winding) by its shorter diagonal.
    auto quad = [&](int a, int b, int c, int d)
    {
      if (vtkMath::Distance2BetweenPoints(this->Point(p[a]), this->Point(p[c])) <=
        vtkMath::Distance2BetweenPoints(this->Point(p[b]), this->Point(p[d])))
      {
        triangle(a, b, c);
        triangle(a, c, d);
      }
      else
      {
        triangle(a, b, d);
        triangle(b, c, d);
      }
    };
    switch (mask)
    {
      case 0:
        triangle(0, 1, 2);
        break;
      case 1:
        triangle(0, 3, 2);
        triangle(3, 1, 2);
        break;
      case 2:
        triangle(0, 1, 4);
        triangle(0, 4, 2);
        break;
      case 4:
        triangle(0, 1, 5);
        triangle(5, 1, 2);
        break;
      case 3:
        triangle(3, 1, 4);
        quad(0, 3, 4, 2);
        break;
      case 6:
        triangle(5, 4, 2);
        quad(0, 1, 4, 5);
        break;
      case 5:
        triangle(0, 3, 5);
        quad(3, 1, 2, 5);
        break;
      default:
        triangle(0, 3, 5);
        triangle(3, 1, 4);
        triangle(5, 4, 2);
        triangle(3, 4, 5);
    }
  }

  vtkPolyData* Input;
  double Maximum2;
  std::vector<double> Points;
  std::vector<unsigned char> Finite;
  std::vector<Combination> Combinations;
  std::unordered_map<std::uint64_t, vtkIdType> Midpoints;
  std::vector<vtkIdType> Triangles, Cells;
};

void Refiner::Write(vtkPolyData* output) const
{
  vtkPolyData* input = this->Input;
  const vtkIdType n = input->GetNumberOfPoints();
  const vtkIdType total = static_cast<vtkIdType>(this->Combinations.size());
  vtkNew<vtkPoints> points;
  points->SetDataType(input->GetPoints()->GetDataType());
  points->SetNumberOfPoints(total);
  for (vtkIdType i = 0; i < total; ++i)
  {
    points->SetPoint(i, this->Point(i));
  }
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(this->GetNumberOfTriangles(), 3 * this->GetNumberOfTriangles());
  for (size_t t = 0; t < this->Cells.size(); ++t)
  {
    polys->InsertNextCell(3, &this->Triangles[3 * t]);
  }
  output->Initialize();
  output->SetPoints(points);
  output->SetVerts(input->GetVerts());
  output->SetLines(input->GetLines());
  output->SetPolys(polys);
  output->GetFieldData()->ShallowCopy(input->GetFieldData());

  // Point data: the input's points as they are, new points interpolated from theirs.
  vtkPointData* pd = output->GetPointData();
  pd->InterpolateAllocate(input->GetPointData(), total);
  pd->CopyData(input->GetPointData(), 0, n, 0);
  vtkNew<vtkIdList> ids;
  for (vtkIdType i = n; i < total; ++i)
  {
    const Combination& c = this->Combinations[i];
    ids->SetNumberOfIds(0);
    double weights[3];
    for (int k = 0; k < 3 && c.Ids[k] >= 0; ++k)
    {
      ids->InsertNextId(c.Ids[k]);
      weights[k] = c.Weights[k];
    }
    pd->InterpolatePoint(input->GetPointData(), i, ids, weights);
  }

  // Cell data: vertices and lines as they are, each triangle its cell's.
  vtkCellData* cd = output->GetCellData();
  const vtkIdType kept = input->GetNumberOfVerts() + input->GetNumberOfLines();
  cd->CopyAllocate(input->GetCellData(), kept + this->GetNumberOfTriangles());
  for (vtkIdType c = 0; c < kept; ++c)
  {
    cd->CopyData(input->GetCellData(), c, c);
  }
  for (size_t t = 0; t < this->Cells.size(); ++t)
  {
    cd->CopyData(input->GetCellData(), this->Cells[t], kept + static_cast<vtkIdType>(t));
  }
}
}

//------------------------------------------------------------------------------
bool vtkApertureRefinement::Refine(
  vtkPolyData* input, double maximumEdgeLength, vtkPolyData* output, std::string& error)
{
  if (!(maximumEdgeLength > 0.0))
  {
    error = "the maximum edge length must be positive";
    return false;
  }
  Refiner refiner(input, maximumEdgeLength);
  refiner.Triangulate();
  while (refiner.Pass())
  {
    if (refiner.GetNumberOfTriangles() > MaximumNumberOfTriangles)
    {
      std::ostringstream what;
      what << "refining to edges of at most " << maximumEdgeLength << " would make more than "
           << MaximumNumberOfTriangles << " triangles";
      error = what.str();
      return false;
    }
  }
  refiner.Write(output);
  return true;
}

//------------------------------------------------------------------------------
double vtkApertureRefinement::LongestEdge(vtkPolyData* input)
{
  double longest2 = 0.0;
  std::vector<vtkIdType> local;
  vtkApertureMeshSurface::ForEachPolygonOrStrip(input,
    [&](vtkIdType npts, const vtkIdType* ids, bool strip)
    {
      local.clear();
      // Fans are enough to measure edges, and need no finite points.
      vtkApertureMeshSurface::Triangulate(npts, ids, strip, nullptr, nullptr, local);
      for (size_t k = 0; k < local.size(); ++k)
      {
        double a[3], b[3];
        input->GetPoint(ids[local[k]], a);
        input->GetPoint(ids[local[k % 3 == 2 ? k - 2 : k + 1]], b);
        const double d2 = vtkMath::Distance2BetweenPoints(a, b);
        longest2 = std::isfinite(d2) ? std::max(longest2, d2) : longest2;
      }
    });
  return std::sqrt(longest2);
}
