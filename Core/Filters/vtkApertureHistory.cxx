/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureHistory.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureHistory.h"

#include "vtkApertureSurface.h"
#include "vtkDataObject.h"
#include "vtkFloatArray.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <limits>
#include <unordered_set>

namespace
{
// A moved box spanning more grid cells than this marks every point instead.
constexpr double MaximumCellsPerBox = 32768.0;

// A retraced point whose rays' reach spans more cells of moved boxes than this casts every ray.
constexpr double MaximumCellsPerReach = 512.0;

// The key of grid cell (i, j, k).
std::uint64_t CellKey(std::int64_t i, std::int64_t j, std::int64_t k)
{
  const std::uint64_t m = 0x1FFFFF; // 21 bits each
  return (std::uint64_t(i) & m) | (std::uint64_t(j) & m) << 21 | (std::uint64_t(k) & m) << 42;
}

// The world coordinates of a surface's vertices (3 each).
std::vector<double> WorldVertices(const vtkApertureSurface& surface)
{
  std::vector<double> world(3 * size_t(surface.GetNumberOfVertices()));
  for (size_t i = 0; i < world.size(); ++i)
  {
    world[i] = surface.Vertices[i] + surface.Origin[i % 3];
  }
  return world;
}

// The cells of a grid, marked where boxes grown by `reach` overlap them. The cells are half as
// wide as the reach, so that few points beyond it are marked.
class CellSet
{
public:
  explicit CellSet(double reach)
    : Size(0.5 * reach)
    , Reach(reach)
  {
  }

  // Marks the cells of the box from `lower` to `upper` grown by the reach; false when it spans
  // too many cells (or is not finite) to mark.
  bool AddBox(const double lower[3], const double upper[3])
  {
    std::int64_t lo[3], hi[3];
    double cells = 1.0;
    for (int c = 0; c < 3; ++c)
    {
      const double a = std::floor((lower[c] - this->Reach) / this->Size);
      const double b = std::floor((upper[c] + this->Reach) / this->Size);
      cells *= b - a + 1.0;
      if (!(cells <= MaximumCellsPerBox))
      {
        return false;
      }
      lo[c] = static_cast<std::int64_t>(a);
      hi[c] = static_cast<std::int64_t>(b);
    }
    for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
    {
      for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
      {
        for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
        {
          this->Cells.insert(CellKey(i, j, k));
        }
      }
    }
    return true;
  }

  // AddBox() for boxes of 6 values each (lower x, y, z, upper x, y, z) in the local coordinates
  // of `origin`.
  bool AddBoxes(const std::vector<float>& boxes, const double origin[3])
  {
    for (size_t b = 0; b < boxes.size(); b += 6)
    {
      double lower[3], upper[3];
      for (int k = 0; k < 3; ++k)
      {
        lower[k] = boxes[b + k] + origin[k];
        upper[k] = boxes[b + k + 3] + origin[k];
      }
      if (!this->AddBox(lower, upper))
      {
        return false;
      }
    }
    return true;
  }

  bool Contains(const double p[3]) const
  {
    std::int64_t ijk[3];
    for (int c = 0; c < 3; ++c)
    {
      const double cell = std::floor(p[c] / this->Size);
      if (!(std::abs(cell) < 1e15))
      {
        return true; // not finite or far out: needed
      }
      ijk[c] = static_cast<std::int64_t>(cell);
    }
    return this->Cells.count(CellKey(ijk[0], ijk[1], ijk[2])) > 0;
  }

private:
  double Size;
  double Reach;
  std::unordered_set<std::uint64_t> Cells;
};

// A dense grid of marked cells of `size` over a box (at most 129 cells a side when the size is
// at least 1/128 of the box's largest side).
class Grid
{
public:
  Grid(const float lower[3], const float upper[3], double size)
    : Size(size)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->Lower[k] = lower[k];
      this->Dims[k] = static_cast<int>(std::floor((double(upper[k]) - lower[k]) / size)) + 1;
    }
    this->Marked.assign(size_t(this->Dims[0]) * this->Dims[1] * this->Dims[2], 0);
  }

  // Marks the cell of `x` and its 26 neighbours.
  void MarkAround(const float x[3])
  {
    int c[3];
    for (int k = 0; k < 3; ++k)
    {
      c[k] = this->Cell(x[k], k);
    }
    for (int i = std::max(c[0] - 1, 0); i <= std::min(c[0] + 1, this->Dims[0] - 1); ++i)
    {
      for (int j = std::max(c[1] - 1, 0); j <= std::min(c[1] + 1, this->Dims[1] - 1); ++j)
      {
        for (int k = std::max(c[2] - 1, 0); k <= std::min(c[2] + 1, this->Dims[2] - 1); ++k)
        {
          this->Marked[this->Index(i, j, k)] = 1;
        }
      }
    }
  }

  // Whether the box of a triangle's corners overlaps a marked cell (true when it spans more
  // cells than are worth looking at).
  bool Overlaps(const float* a, const float* b, const float* c) const
  {
    int lo[3], hi[3];
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = this->Cell(std::min({ a[k], b[k], c[k] }), k);
      hi[k] = this->Cell(std::max({ a[k], b[k], c[k] }), k);
    }
    if ((hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1) > 64)
    {
      return true;
    }
    for (int i = lo[0]; i <= hi[0]; ++i)
    {
      for (int j = lo[1]; j <= hi[1]; ++j)
      {
        for (int k = lo[2]; k <= hi[2]; ++k)
        {
          if (this->Marked[this->Index(i, j, k)])
          {
            return true;
          }
        }
      }
    }
    return false;
  }

private:
  int Cell(float x, int k) const
  {
    const double c = std::floor((double(x) - this->Lower[k]) / this->Size);
    return static_cast<int>(std::min(std::max(c, 0.0), double(this->Dims[k] - 1)));
  }
  size_t Index(int i, int j, int k) const
  {
    return (size_t(k) * this->Dims[1] + j) * this->Dims[0] + i;
  }

  double Size;
  double Lower[3];
  int Dims[3];
  std::vector<unsigned char> Marked;
};
}

//------------------------------------------------------------------------------
void vtkApertureHistory::SetKey(const std::string& key)
{
  if (key != this->Key)
  {
    this->Key = key;
    this->Steps.clear();
    this->Forget();
  }
}

//------------------------------------------------------------------------------
vtkDataObject* vtkApertureHistory::Find(double time, vtkMTimeType pipeline) const
{
  for (const Step& step : this->Steps)
  {
    if (step.Time == time && step.Pipeline == pipeline)
    {
      return step.Output;
    }
  }
  return nullptr;
}

//------------------------------------------------------------------------------
void vtkApertureHistory::Store(
  double time, vtkMTimeType pipeline, vtkDataObject* output, int capacity)
{
  if (capacity <= 0 || this->Find(time, pipeline))
  {
    return;
  }
  // Steps of an earlier pipeline cannot be found again.
  this->Steps.erase(std::remove_if(this->Steps.begin(), this->Steps.end(),
                      [pipeline](const Step& step) { return step.Pipeline != pipeline; }),
    this->Steps.end());
  auto copy = vtk::TakeSmartPointer(output->NewInstance());
  copy->ShallowCopy(output);
  this->Steps.push_back(Step{ time, pipeline, copy });
  while (static_cast<int>(this->Steps.size()) > capacity)
  {
    this->Steps.pop_front();
  }
}

//------------------------------------------------------------------------------
bool vtkApertureHistory::SameCells(const vtkApertureSurface& surface) const
{
  return this->Remembered && surface.Triangles == this->Triangles &&
    3 * size_t(surface.GetNumberOfVertices()) == this->VertexWorld.size();
}

//------------------------------------------------------------------------------
std::vector<vtkIdType> vtkApertureHistory::MatchSides(const vtkApertureSurface& surface) const
{
  // Each vertex's first receiving point and number of sides, remembered and new (a vertex's
  // sides are consecutive points).
  const size_t vertices = surface.GetNumberOfVertices();
  std::vector<vtkIdType> oldFirst(vertices, -1), newFirst(vertices, -1);
  std::vector<vtkIdType> oldCount(vertices, 0), newCount(vertices, 0);
  for (size_t p = 0; p < this->PointVertex.size(); ++p)
  {
    const std::uint32_t v = this->PointVertex[p];
    oldFirst[v] = oldFirst[v] < 0 ? static_cast<vtkIdType>(p) : oldFirst[v];
    ++oldCount[v];
  }
  for (size_t p = 0; p < surface.PointVertex.size(); ++p)
  {
    const std::uint32_t v = surface.PointVertex[p];
    newFirst[v] = newFirst[v] < 0 ? static_cast<vtkIdType>(p) : newFirst[v];
    ++newCount[v];
  }
  std::vector<vtkIdType> match(surface.PointVertex.size(), -1);
  for (size_t p = 0; p < match.size(); ++p)
  {
    const std::uint32_t v = surface.PointVertex[p];
    if (oldCount[v] == newCount[v])
    {
      match[p] = oldFirst[v] + (static_cast<vtkIdType>(p) - newFirst[v]);
    }
  }
  return match;
}

//------------------------------------------------------------------------------
// Per vertex, whether one of its input points is somewhere else than last time.
std::vector<unsigned char> vtkApertureHistory::MovedVertices(
  const vtkApertureSurface& surface, const std::vector<double>& world) const
{
  std::vector<unsigned char> moved(surface.GetNumberOfVertices(), 0);
  const size_t stride = world.size() / std::max<size_t>(surface.InputPoints.size(), 1);
  for (size_t i = 0; i < surface.InputPoints.size(); ++i)
  {
    const vtkIdType point = surface.InputPoints[i];
    const double* now = world.data() + stride * i;
    const bool same = std::equal(now, now + stride, this->World.data() + stride * i);
    if (point >= 0 && !same)
    {
      moved[surface.PointVertex[point]] = 1;
    }
  }
  return moved;
}

//------------------------------------------------------------------------------
std::vector<unsigned char> vtkApertureHistory::Needed(
  const vtkApertureSurface& surface, const std::vector<double>& world, double reach)
{
  const vtkIdType n = surface.GetNumberOfPoints();
  std::vector<unsigned char> all(n, CAST);
  this->Sources.assign(n, -1);
  this->Plans.clear();
  this->Reach = reach;
  this->MovedBoxes.clear();
  this->BoxOfCell.clear();
  this->BoxSpan = 0.0f;
  this->Matched =
    !this->Remembered ? NO_SURFACE : (this->SameCells(surface) ? SAME_CELLS : OTHER_CELLS);
  // Another local origin rounds every coordinate differently, as a fresh run would: cast all.
  if (!(reach > 0.0 && reach < 1e300) || world.size() != this->World.size() ||
    world.size() % std::max<size_t>(surface.InputPoints.size(), 1) != 0 ||
    this->Matched != SAME_CELLS || !std::equal(this->Origin, this->Origin + 3, surface.Origin))
  {
    return all;
  }
  const std::vector<unsigned char> moved = this->MovedVertices(surface, world);
  if (2 * std::count(moved.begin(), moved.end(), 1) > static_cast<std::ptrdiff_t>(moved.size()))
  {
    return all; // most of it moved: sorting out the rest would cost more than it saves
  }
  const std::vector<double> now = WorldVertices(surface);
  for (size_t t = 0; t < surface.Triangles.size(); t += 3)
  {
    const std::uint32_t* v = &surface.Triangles[t];
    if (!moved[v[0]] && !moved[v[1]] && !moved[v[2]])
    {
      continue;
    }
    const std::vector<double>& before = this->VertexWorld;
    for (const std::vector<double>* at : { &before, &now })
    {
      const double* corners[3] = { &(*at)[3 * size_t(v[0])], &(*at)[3 * size_t(v[1])],
        &(*at)[3 * size_t(v[2])] };
      this->AddMovedBox(corners, surface.Origin);
    }
  }
  // The points within reach of a moved triangle: those near the merged boxes, which hold them
  // (a few more points than the triangles' own boxes would mark, in far fewer cells).
  CellSet cells(reach);
  if (!(this->BoxSpan < std::numeric_limits<float>::infinity()) ||
    !cells.AddBoxes(this->MovedBoxes, surface.Origin))
  {
    return all; // a moved triangle not finite, or too large to mark
  }
  std::vector<unsigned char> needed(n, REUSE);
  const std::vector<vtkIdType> match = this->MatchSides(surface);
  for (vtkIdType p = 0; p < n; ++p)
  {
    if (match[p] >= 0 && !cells.Contains(&now[3 * size_t(surface.PointVertex[p])]))
    {
      this->Sources[p] = match[p];
    }
    else if (match[p] >= 0 && this->SameRays(surface, p, match[p]))
    {
      needed[p] = RETRACE;
      this->Sources[p] = match[p];
    }
    else
    {
      needed[p] = CAST;
    }
  }
  this->Plans = needed;
  return needed;
}

//------------------------------------------------------------------------------
// A grid over the surface of cells at least as wide as the reach (at most 129 a side), marked
// around each casting point: every place within reach of one lies in a marked cell, so a
// triangle whose box overlaps no marked cell is out of every cast ray's reach.
std::vector<unsigned char> vtkApertureHistory::Reachable(const vtkApertureSurface& surface) const
{
  if (this->Plans.empty() || surface.GetNumberOfVertices() == 0)
  {
    return {};
  }
  const float* vertices = surface.Vertices.data();
  float lower[3] = { FLT_MAX, FLT_MAX, FLT_MAX }, upper[3] = { -FLT_MAX, -FLT_MAX, -FLT_MAX };
  for (vtkIdType v = 0; v < surface.GetNumberOfVertices(); ++v)
  {
    for (int k = 0; k < 3; ++k)
    {
      lower[k] = std::min(lower[k], vertices[3 * v + k]);
      upper[k] = std::max(upper[k], vertices[3 * v + k]);
    }
  }
  double size = this->Reach;
  for (int k = 0; k < 3; ++k)
  {
    size = std::max(size, (double(upper[k]) - lower[k]) / 128.0);
  }
  Grid grid(lower, upper, size);
  for (vtkIdType p = 0; p < static_cast<vtkIdType>(this->Plans.size()); ++p)
  {
    if (this->Plans[p] != REUSE)
    {
      grid.MarkAround(&vertices[3 * size_t(surface.PointVertex[p])]);
    }
  }
  std::vector<unsigned char> reachable(surface.GetNumberOfTriangles());
  for (size_t t = 0; t < reachable.size(); ++t)
  {
    const std::uint32_t* v = &surface.Triangles[3 * t];
    reachable[t] = grid.Overlaps(
      &vertices[3 * size_t(v[0])], &vertices[3 * size_t(v[1])], &vertices[3 * size_t(v[2])]);
  }
  return reachable;
}

//------------------------------------------------------------------------------
bool vtkApertureHistory::SameRays(const vtkApertureSurface& surface, vtkIdType p, vtkIdType q) const
{
  auto same = [p, q](const auto& now, const auto& then, int size)
  { return std::equal(&now[size * p], &now[size * p] + size, &then[size * q]); };
  return !this->Results.Rays.empty() && surface.Valid[p] && this->Valid[q] &&
    same(surface.Start, this->Start, 3) &&
    std::equal(surface.GetNormal(p), surface.GetNormal(p) + 3, &this->Normal[3 * q]) &&
    same(surface.Offset, this->Offset, 1) && same(surface.Near, this->Near, 1) &&
    same(surface.Key, this->RayKey, 1);
}

//------------------------------------------------------------------------------
void vtkApertureHistory::AddMovedBox(const double* const corners[3], const double origin[3])
{
  double box[6] = { 1e300, 1e300, 1e300, -1e300, -1e300, -1e300 };
  for (int c = 0; c < 3; ++c)
  {
    for (int k = 0; k < 3; ++k)
    {
      box[k] = std::min(box[k], corners[c][k] - origin[k]);
      box[k + 3] = std::max(box[k + 3], corners[c][k] - origin[k]);
    }
  }
  // Embree's hits and the rays' box tests round in float: a margin far above both.
  const double size = std::max({ std::abs(box[0]), std::abs(box[1]), std::abs(box[2]),
    std::abs(box[3]), std::abs(box[4]), std::abs(box[5]) });
  const double margin = 1e-4 * this->Reach + 1e-5 * size;
  std::int64_t ijk[3];
  for (int k = 0; k < 3; ++k)
  {
    const double cell = std::floor(box[k] / this->Reach);
    if (!(std::abs(cell) < 1e15))
    {
      this->BoxSpan = std::numeric_limits<float>::infinity(); // no point can look it up
      return;
    }
    ijk[k] = static_cast<std::int64_t>(cell);
  }
  const auto added = this->BoxOfCell.emplace(
    CellKey(ijk[0], ijk[1], ijk[2]), static_cast<std::uint32_t>(this->MovedBoxes.size() / 6));
  if (added.second)
  {
    const float inf = std::numeric_limits<float>::infinity();
    this->MovedBoxes.insert(this->MovedBoxes.end(), { inf, inf, inf, -inf, -inf, -inf });
  }
  float* b = &this->MovedBoxes[6 * size_t(added.first->second)];
  for (int k = 0; k < 3; ++k)
  {
    b[k] = std::min(b[k], static_cast<float>(box[k] - margin));
    b[k + 3] = std::max(b[k + 3], static_cast<float>(box[k + 3] + margin));
    this->BoxSpan = std::max(this->BoxSpan, b[k + 3] - b[k]);
  }
}

//------------------------------------------------------------------------------
int vtkApertureHistory::GetMovedBoxes(const float position[3], float* boxes, int capacity) const
{
  // A box within reach has its lower corner in these cells.
  const double r = this->Reach;
  std::int64_t lo[3], hi[3];
  double cells = 1.0;
  for (int k = 0; k < 3; ++k)
  {
    const double a = std::floor((position[k] - r - this->BoxSpan) / r);
    const double b = std::floor((position[k] + r) / r);
    cells *= b - a + 1.0;
    if (!(cells <= MaximumCellsPerReach && std::abs(a) < 1e15 && std::abs(b) < 1e15))
    {
      return -1;
    }
    lo[k] = static_cast<std::int64_t>(a);
    hi[k] = static_cast<std::int64_t>(b);
  }
  int count = 0;
  for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
  {
    for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
    {
      for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
      {
        const auto found = this->BoxOfCell.find(CellKey(i, j, k));
        if (found == this->BoxOfCell.end())
        {
          continue;
        }
        const float* b = &this->MovedBoxes[6 * size_t(found->second)];
        double distance2 = 0.0;
        for (int c = 0; c < 3; ++c)
        {
          const double d = std::max({ b[c] - position[c], 0.0f, position[c] - b[c + 3] });
          distance2 += d * d;
        }
        if (distance2 > r * r)
        {
          continue;
        }
        if (count == capacity)
        {
          return -1;
        }
        std::copy_n(b, 6, boxes + 6 * count++);
      }
    }
  }
  return count;
}

//------------------------------------------------------------------------------
void vtkApertureHistory::Reuse(Caps& caps) const
{
  const Caps& old = this->Results;
  const size_t n = this->Sources.size();
  const size_t bytes = n ? caps.Mask.size() / n : 0; // mask bytes per point
  for (size_t p = 0; p < n; ++p)
  {
    const vtkIdType q = this->Sources[p];
    if (q < 0 || this->Plans[p] != REUSE)
    {
      continue;
    }
    std::copy_n(&old.BentNormal[3 * q], 3, &caps.BentNormal[3 * p]);
    caps.Radius[p] = old.Radius[q];
    if (!caps.Occlusion.empty())
    {
      caps.Occlusion[p] = old.Occlusion[q];
    }
    std::copy_n(old.Mask.data() + q * bytes, bytes, caps.Mask.data() + p * bytes);
    const int words = old.RayWords;
    if (!caps.Rays.empty() && !old.Rays.empty() && words == caps.RayWords)
    {
      std::copy_n(&old.Rays[q * words], words, &caps.Rays[p * words]);
    }
  }
}

//------------------------------------------------------------------------------
const std::uint64_t* vtkApertureHistory::GetRays(vtkIdType point) const
{
  return &this->Results.Rays[size_t(this->Sources[point]) * this->Results.RayWords];
}

//------------------------------------------------------------------------------
void vtkApertureHistory::Remember(
  const vtkApertureSurface& surface, std::vector<double> world, const Caps& caps)
{
  this->Remembered = true;
  this->World = std::move(world);
  this->VertexWorld = WorldVertices(surface);
  this->Triangles = surface.Triangles;
  this->PointVertex = surface.PointVertex;
  this->Results = caps;
  std::copy_n(surface.Origin, 3, this->Origin);
  this->Start = surface.Start;
  const float* normals = surface.Normals->GetPointer(0);
  this->Normal.assign(normals, normals + 3 * surface.GetNumberOfPoints());
  this->Offset = surface.Offset;
  this->Near = surface.Near;
  this->RayKey = surface.Key;
  this->Valid = surface.Valid;
}

//------------------------------------------------------------------------------
void vtkApertureHistory::Forget()
{
  this->Remembered = false;
  this->World.clear();
  this->VertexWorld.clear();
  this->Triangles.clear();
  this->PointVertex.clear();
  this->Sources.clear();
  this->Plans.clear();
  this->Results = Caps();
  this->Start.clear();
  this->Normal.clear();
  this->Offset.clear();
  this->Near.clear();
  this->RayKey.clear();
  this->Valid.clear();
  this->MovedBoxes.clear();
  this->BoxOfCell.clear();
}
