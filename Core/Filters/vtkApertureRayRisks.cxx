/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureRayRisks.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureRayRisks.h"

#include "vtkApertureMemory.h"
#include "vtkApertureRayOffsets.h"
#include "vtkApertureSMP.h"
#include "vtkApertureSurface.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <functional>
#include <numeric>
#include <utility>

namespace
{
// Cells a triangle may span before it is counted as needing the filter unchecked.
constexpr double MaximumCells = 512.0;

void Subtract(const float a[3], const float b[3], double d[3])
{
  for (int k = 0; k < 3; ++k)
  {
    d[k] = double(a[k]) - double(b[k]);
  }
}

double Dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// Squared distance from p to triangle abc (Ericson, Real-Time Collision Detection, 5.1.5).
double Distance2(const float p[3], const float a[3], const float b[3], const float c[3])
{
  double ab[3], ac[3], ap[3], bp[3], cp[3];
  Subtract(b, a, ab);
  Subtract(c, a, ac);
  Subtract(p, a, ap);
  Subtract(p, b, bp);
  Subtract(p, c, cp);
  const double d1 = Dot(ab, ap), d2 = Dot(ac, ap), d3 = Dot(ab, bp), d4 = Dot(ac, bp);
  const double d5 = Dot(ab, cp), d6 = Dot(ac, cp);
  double v = 0.0, w = 0.0; // the closest point is a + v ab + w ac
  const double va = d3 * d6 - d5 * d4, vb = d5 * d2 - d1 * d6, vc = d1 * d4 - d3 * d2;
  if (d1 <= 0.0 && d2 <= 0.0)
  {
  }
  else if (d3 >= 0.0 && d4 <= d3)
  {
    v = 1.0;
  }
  else if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
  {
    v = d1 / (d1 - d3);
  }
  else if (d6 >= 0.0 && d5 <= d6)
  {
    w = 1.0;
  }
  else if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
  {
    w = d2 / (d2 - d6);
  }
  else if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
  {
    w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    v = 1.0 - w;
  }
  else
  {
    const double denominator = 1.0 / (va + vb + vc);
    v = vb * denominator;
    w = vc * denominator;
  }
  double q[3];
  for (int k = 0; k < 3; ++k)
  {
    q[k] = ap[k] - v * ab[k] - w * ac[k];
  }
  return Dot(q, q);
}

//------------------------------------------------------------------------------
// The sum of the lengths of a surface's triangles' edges: fixed blocks on every core, summed in
// order, so that it is the same whatever the number of threads.
double EdgeLengths(const vtkApertureSurface& s)
{
  constexpr vtkIdType block = 65536; // triangles
  std::vector<double> sums((s.GetNumberOfTriangles() + block - 1) / block, 0.0);
  vtkApertureSMP::For(0, static_cast<vtkIdType>(sums.size()), 1,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType b = begin; b < end; ++b)
      {
        for (vtkIdType t = b * block; t < std::min((b + 1) * block, s.GetNumberOfTriangles()); ++t)
        {
          const std::uint32_t* v = &s.Triangles[3 * t];
          for (int k = 0; k < 3; ++k)
          {
            double d[3];
            Subtract(&s.Vertices[3 * size_t(v[k])], &s.Vertices[3 * size_t(v[(k + 1) % 3])], d);
            sums[b] += std::sqrt(Dot(d, d));
          }
        }
      }
    });
  return std::accumulate(sums.begin(), sums.end(), 0.0);
}

//------------------------------------------------------------------------------
// Whether triangle t has a corner with a valid receiving point (`points`, those of vertex v from
// first[v]) whose normal is within acos(PullBack) of perpendicular to the triangle, or against it.
bool AtSteepPoint(const vtkApertureSurface& surface, const std::vector<vtkIdType>& first,
  const std::vector<vtkIdType>& points, vtkIdType t)
{
  const std::uint32_t* v = &surface.Triangles[3 * t];
  double e1[3], e2[3];
  Subtract(&surface.Vertices[3 * size_t(v[1])], &surface.Vertices[3 * size_t(v[0])], e1);
  Subtract(&surface.Vertices[3 * size_t(v[2])], &surface.Vertices[3 * size_t(v[0])], e2);
  const double normal[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
    e1[0] * e2[1] - e1[1] * e2[0] };
  const double length = std::sqrt(Dot(normal, normal));
  for (int c = 0; c < 3; ++c)
  {
    for (vtkIdType k = first[v[c]]; k < first[v[c] + 1]; ++k)
    {
      const float* n = surface.GetNormal(points[k]);
      const double cosine = (n[0] * normal[0] + n[1] * normal[1] + n[2] * normal[2]) / length;
      if (surface.Valid[points[k]] && !(cosine >= vtkApertureRayOffsets::PullBack))
      {
        return true;
      }
    }
  }
  return false;
}
}

//------------------------------------------------------------------------------
vtkApertureRayRisks::vtkApertureRayRisks(const std::vector<const vtkApertureSurface*>& receivers)
{
  // The ray start of every valid receiving point, and two mean edges as the cell size.
  double edges = 0.0;
  vtkIdType count = 0, points = 0;
  for (const vtkApertureSurface* s : receivers)
  {
    points += s->GetNumberOfPoints();
  }
  vtkApertureMemory::Reserve(this->Starts, points);
  for (const vtkApertureSurface* s : receivers)
  {
    this->CollectStarts(*s);
    edges += EdgeLengths(*s);
    count += 3 * s->GetNumberOfTriangles();
  }
  if (this->Starts.empty())
  {
    return;
  }
  std::fill_n(this->Lower, 3, FLT_MAX);
  for (const Start& s : this->Starts)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->Lower[k] = std::min(this->Lower[k], s.Position[k]);
    }
  }
  this->Size =
    static_cast<float>(std::max(count ? 2.0 * edges / count : 0.0, 4.0 * this->LargestRadius));
  this->Size = this->Size > 0.0f ? this->Size : 1.0f;
  this->SortStarts();
}

//------------------------------------------------------------------------------
// Appends the starts of the valid points of `surface`, in their order: blocks of points on every
// core, each writing where the counts of the blocks before it put it.
void vtkApertureRayRisks::CollectStarts(const vtkApertureSurface& surface)
{
  const vtkIdType n = surface.GetNumberOfPoints(), block = 4096;
  const vtkIdType blocks = (n + block - 1) / block;
  std::vector<vtkIdType> first(blocks + 1, 0);
  vtkApertureSMP::For(0, blocks, 1,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType b = begin; b < end; ++b)
      {
        const auto valid = surface.Valid.begin() + b * block;
        first[b + 1] = std::count_if(
          valid, valid + std::min(block, n - b * block), [](unsigned char v) { return v != 0; });
      }
    });
  std::partial_sum(first.begin(), first.end(), first.begin());
  const size_t base = this->Starts.size();
  this->Starts.resize(base + first.back());
  std::vector<float> largest(blocks, 0.0f);
  vtkApertureSMP::For(0, blocks, 1,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType b = begin; b < end; ++b)
      {
        Start* start = &this->Starts[base + first[b]];
        for (vtkIdType i = b * block; i < std::min((b + 1) * block, n); ++i)
        {
          if (surface.Valid[i])
          {
            std::copy_n(&surface.Start[3 * i], 3, start->Position);
            start->Radius = surface.Near[i];
            start->Surface = &surface;
            start->Vertex = surface.PointVertex[i];
            largest[b] = std::max(largest[b], start->Radius);
            ++start;
          }
        }
      }
    });
  for (const float radius : largest)
  {
    this->LargestRadius = std::max(this->LargestRadius, radius);
  }
}

//------------------------------------------------------------------------------
// The starts in the order of their cells' keys (a cell's starts side by side in memory), and
// the table of the cells with their runs of starts, at least twice as many slots as cells.
void vtkApertureRayRisks::SortStarts()
{
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
  vtkApertureMemory::Assign(keyed, this->Starts.size());
  vtkApertureSMP::For(0, static_cast<vtkIdType>(keyed.size()), 4096,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const float* p = this->Starts[i].Position;
        keyed[i] = { Key(this->Index(p[0], 0), this->Index(p[1], 1), this->Index(p[2], 2)),
          static_cast<std::uint32_t>(i) };
      }
    });
  vtkApertureSMP::Sort(keyed.begin(), keyed.end(), std::less<>());
  std::vector<Start> sorted;
  vtkApertureMemory::Assign(sorted, this->Starts.size());
  vtkApertureSMP::For(0, static_cast<vtkIdType>(keyed.size()), 4096,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        sorted[i] = this->Starts[keyed[i].second];
      }
    });
  std::vector<Cell> runs;
  for (std::uint32_t i = 0; i < keyed.size(); ++i)
  {
    if (runs.empty() || runs.back().Key != keyed[i].first)
    {
      runs.push_back({ keyed[i].first, i, i });
    }
    ++runs.back().End;
  }
  this->Starts.swap(sorted);
  this->CellBits = 1;
  while ((size_t(1) << this->CellBits) < 2 * runs.size())
  {
    ++this->CellBits;
  }
  vtkApertureMemory::Assign(this->Cells, size_t(1) << this->CellBits, Cell{ FreeCell, 0, 0 });
  const size_t mask = this->Cells.size() - 1;
  for (const Cell& run : runs)
  {
    size_t slot = this->Slot(run.Key);
    while (this->Cells[slot].Key != FreeCell)
    {
      slot = (slot + 1) & mask;
    }
    this->Cells[slot] = run;
  }
}

//------------------------------------------------------------------------------
// Fibonacci hashing: the top CellBits bits of the key times 2^64 / golden ratio.
size_t vtkApertureRayRisks::Slot(std::uint64_t key) const
{
  return static_cast<size_t>((key * 0x9E3779B97F4A7C15ull) >> (64 - this->CellBits));
}

//------------------------------------------------------------------------------
const vtkApertureRayRisks::Cell* vtkApertureRayRisks::FindCell(std::uint64_t key) const
{
  const size_t mask = this->Cells.size() - 1;
  for (size_t slot = this->Slot(key);; slot = (slot + 1) & mask)
  {
    const Cell& cell = this->Cells[slot];
    if (cell.Key == key || cell.Key == FreeCell)
    {
      return cell.Key == key ? &cell : nullptr;
    }
  }
}

//------------------------------------------------------------------------------
std::int64_t vtkApertureRayRisks::Index(float x, int axis) const
{
  // Clamped to the 21 bits a key has per axis (cells beyond are shared, which is harmless); NaN,
  // from coordinates near FLT_MAX whose differences overflow, goes to cell 0.
  const double c = std::floor((double(x) - this->Lower[axis]) / this->Size);
  return c >= 0.0 ? static_cast<std::int64_t>(std::min(c, 2097151.0)) : 0;
}

//------------------------------------------------------------------------------
std::uint64_t vtkApertureRayRisks::Key(std::int64_t i, std::int64_t j, std::int64_t k)
{
  return static_cast<std::uint64_t>(i) << 42 | static_cast<std::uint64_t>(j) << 21 |
    static_cast<std::uint64_t>(k);
}

//------------------------------------------------------------------------------
std::vector<unsigned char> vtkApertureRayRisks::Find(
  const vtkApertureSurface& surface, bool receiver, const std::vector<unsigned char>& only) const
{
  const vtkIdType triangles = surface.GetNumberOfTriangles();
  std::vector<unsigned char> risky;
  vtkApertureMemory::Assign(risky, triangles);
  if (receiver)
  {
    this->MarkIncident(surface, only, risky);
  }
  vtkApertureSMP::For(0, triangles, 1024,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        risky[t] = risky[t] ||
          ((only.empty() || only[t]) && this->NearStart(surface, static_cast<std::uint32_t>(t)));
      }
    });
  return risky;
}

//------------------------------------------------------------------------------
void vtkApertureRayRisks::MarkIncident(const vtkApertureSurface& surface,
  const std::vector<unsigned char>& only, std::vector<unsigned char>& risky) const
{
  // The receiving points of each vertex.
  const vtkIdType vertices = surface.GetNumberOfVertices();
  std::vector<vtkIdType> first;
  vtkApertureMemory::Assign(first, vertices + 1);
  for (const std::uint32_t v : surface.PointVertex)
  {
    ++first[v + 1];
  }
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<vtkIdType> points, fill;
  vtkApertureMemory::Assign(points, surface.PointVertex.size());
  vtkApertureMemory::Reserve(fill, vertices);
  fill.assign(first.begin(), first.end() - 1);
  for (size_t i = 0; i < points.size(); ++i)
  {
    points[fill[surface.PointVertex[i]]++] = static_cast<vtkIdType>(i);
  }
  vtkApertureSMP::For(0, static_cast<vtkIdType>(risky.size()), 1024,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType t = begin; t < end; ++t)
      {
        risky[t] = (only.empty() || only[t]) && AtSteepPoint(surface, first, points, t);
      }
    });
}

//------------------------------------------------------------------------------
bool vtkApertureRayRisks::NearStart(const vtkApertureSurface& surface, std::uint32_t t) const
{
  if (this->Starts.empty())
  {
    return false;
  }
  const std::uint32_t* v = &surface.Triangles[3 * size_t(t)];
  const float* corner[3] = { &surface.Vertices[3 * size_t(v[0])],
    &surface.Vertices[3 * size_t(v[1])], &surface.Vertices[3 * size_t(v[2])] };
  float box[6];
  std::int64_t lo[3], hi[3];
  double cells = 1.0;
  for (int k = 0; k < 3; ++k)
  {
    box[2 * k] = std::min({ corner[0][k], corner[1][k], corner[2][k] }) - this->LargestRadius;
    box[2 * k + 1] = std::max({ corner[0][k], corner[1][k], corner[2][k] }) + this->LargestRadius;
    lo[k] = this->Index(box[2 * k], k);
    hi[k] = this->Index(box[2 * k + 1], k);
    cells *= static_cast<double>(hi[k] - lo[k] + 1);
  }
  if (!(cells <= MaximumCells))
  {
    return true;
  }
  for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
  {
    for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
    {
      for (std::int64_t k = lo[2]; k <= hi[2]; ++k)
      {
        const Cell* found = this->FindCell(Key(i, j, k));
        for (std::uint32_t c = found ? found->Begin : 0; found && c < found->End; ++c)
        {
          const Start& s = this->Starts[c];
          const float* q = s.Position;
          if (q[0] < box[0] || q[0] > box[1] || q[1] < box[2] || q[1] > box[3] || q[2] < box[4] ||
            q[2] > box[5])
          {
            continue;
          }
          const bool own =
            s.Surface == &surface && (v[0] == s.Vertex || v[1] == s.Vertex || v[2] == s.Vertex);
          if (!own &&
            Distance2(s.Position, corner[0], corner[1], corner[2]) <= double(s.Radius) * s.Radius)
          {
            return true;
          }
        }
      }
    }
  }
  return false;
}
