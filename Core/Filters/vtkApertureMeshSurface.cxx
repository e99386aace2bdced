/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureMeshSurface.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureMeshSurface.h"

#include "vtkApertureCellCheck.h"
#include "vtkApertureMemory.h"
#include "vtkApertureSMP.h"
#include "vtkApertureSurface.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArrayRange.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolygon.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <numeric>

namespace
{
// Union-find over small index sets (the triangles around one vertex), and the keys that group
// them (kept between vertices, so that they are allocated once).
struct Classes
{
  std::vector<int> Parent;
  std::vector<std::pair<vtkIdType, int>> Keyed;
  void Reset(size_t n)
  {
    this->Parent.resize(n);
    std::iota(this->Parent.begin(), this->Parent.end(), 0);
  }
  int Find(int i)
  {
    while (this->Parent[i] != i)
    {
      i = this->Parent[i] = this->Parent[this->Parent[i]];
    }
    return i;
  }
  void Unite(int a, int b) { this->Parent[this->Find(a)] = this->Find(b); }
};

// The sides of one vertex (groups of its triangles): each triangle's side, each side's sum of
// unit face normals and area, the vertex's area-weighted normal and total area.
struct Sides
{
  // The unit (or zero) normal and the area of each triangle around the vertex: kept for every
  // triangle, they would be the largest array of a large surface's intake.
  std::vector<std::array<float, 4>> Faces;
  std::vector<int> Of;
  std::vector<std::array<double, 3>> Sums;
  std::vector<double> Areas;
  double VertexNormal[3] = { 0.0, 0.0, 0.0 };
  double Total = 0.0;
  // Scratch kept between vertices: the side of each class, the sides in order.
  std::vector<int> OfRoot;
  std::vector<size_t> Order;
};

// The receiving points made for a run of vertices on one thread, numbered from 0 in the run
// until StorePoints() appends them to the surface, in the order of their vertices.
struct PointBlock
{
  std::vector<std::uint32_t> Vertex;
  std::vector<std::uint64_t> Key;
  std::vector<unsigned char> Valid;
  std::vector<float> Normals; // 3 each
  void Clear()                // keeping the room for the next wave
  {
    this->Vertex.clear();
    this->Key.clear();
    this->Valid.clear();
    this->Normals.clear();
  }
};

// Vertices a block of the loops over vertices, and blocks a wave of SidesFromCreases(): only one
// wave's points are held twice (the bunny has 36 blocks in 3 waves).
constexpr vtkIdType BlockVertices = 1024;
constexpr vtkIdType WaveBlocks = 16;
}

//------------------------------------------------------------------------------
// The steps of Set(), with what they share.
namespace
{
// Sets on[i] for every point id i of a vtkCellArray's connectivity (vtkCellArray::Visit()).
struct MarkPoints
{
  template <typename State>
  void operator()(State& state, std::vector<unsigned char>& on) const
  {
    for (const auto id : vtk::DataArrayValueRange<1>(state.GetConnectivity()))
    {
      on[static_cast<size_t>(id)] = 1;
    }
  }
};

struct Build
{
  vtkApertureSurface& S;
  vtkPolyData* Input;
  vtkIdType N;
  std::vector<unsigned char> Finite;    // per input point
  std::vector<std::uint32_t> VertexOf;  // per input point (NoVertex when not finite)
  std::vector<vtkIdType> VertexInput;   // an input point of each vertex
  std::vector<unsigned char> OnSurface; // input point used by a polygon or strip
  // 32-bit where the size limits of Set() allow: the triangles dominate the memory.
  std::vector<std::uint32_t> TriInput;     // every triangle's input points, 3 each
  std::vector<std::uint32_t> TriCell;      // its polygon or strip
  std::vector<std::uint32_t> TriCorner;    // the connectivity index of each corner
  std::vector<std::uint32_t> TriPoint;     // the receiving point of each corner (NoVertex: none)
  std::vector<std::uint32_t> Geometry;     // triangles with three distinct vertices
  std::vector<vtkIdType> IncidentStart;    // per vertex, into Incident
  std::vector<std::uint32_t> Incident;     // 3 * geometry triangle + corner
  std::vector<vtkIdType> VertexFirstPoint; // each vertex's first receiving point (-1: none)
  vtkIdType Corners = 0;                   // polygon corners, then strip corners
  vtkIdType Polygons = 0;                  // cells before the first strip

  Build(vtkApertureSurface& surface, vtkPolyData* input)
    : S(surface)
    , Input(input)
    , N(input->GetNumberOfPoints())
  {
  }

  vtkIdType Vertex(vtkIdType triangle, int corner) const
  {
    return this->VertexOf[this->TriInput[3 * triangle + corner]];
  }
  // The receiving point of corner c, -1 when it has none.
  vtkIdType PointOf(size_t c) const
  {
    const std::uint32_t point = this->TriPoint[c];
    return point == vtkApertureSurface::NoVertex ? -1 : static_cast<vtkIdType>(point);
  }

  void Weld();
  void Triangulate();
  void MarkOnSurface(vtkCellArray* const arrays[2]);
  void CutCells(vtkCellArray* const arrays[2], const std::vector<vtkIdType>& first, vtkIdType begin,
    vtkIdType end, std::atomic<bool>& dropped);
  void DropNotFinite();
  void SelectGeometry();
  vtkIdType Neighbour(vtkIdType corner, int step) const;
  void Orient();
  bool Consistent() const;
  std::vector<std::vector<std::pair<vtkIdType, bool>>> ManifoldNeighbours() const;
  void FlipPieces(const std::vector<std::vector<std::pair<vtkIdType, bool>>>& next);
  void FacesAround(const std::uint32_t* corners, int m, Sides& sides) const;
  void FindIncident();
  void SidesFromCreases(double cosAngle);
  void CreaseSides(vtkIdType begin, vtkIdType end, double cosAngle, PointBlock& block);
  void GroupCreaseFaces(
    const std::uint32_t* corners, int m, double cosAngle, Classes& classes, Sides& sides) const;
  void SumSides(int m, Classes& classes, Sides& sides) const;
  void MakeSidePoints(
    vtkIdType v, Sides& sides, std::vector<vtkIdType>& pointOfSide, PointBlock& block);
  void SidesFromNormals(vtkDataArray* normals, double cosAngle);
  vtkIdType AddPoint(
    PointBlock& block, vtkIdType vertex, unsigned int side, const double normal[3]);
  std::vector<vtkIdType> StorePoints(std::vector<PointBlock>& blocks, vtkIdType count);
  void MapInputPoints();
  void PointOfEachInput();
  void CornerPoints();
  void TrianglePoints(
    vtkIdType cell, vtkIdType first, vtkIdType npts, size_t& t, std::vector<vtkIdType>& local);
  void StripTriangles();
};
}

//------------------------------------------------------------------------------
// Points at the same position become one vertex, numbered in the order of their first point.
void Build::Weld()
{
  std::vector<double> world; // input points, 3 each
  vtkApertureSurface::WorldPoints(this->Input->GetPoints(), world);
  vtkApertureMemory::Assign(this->Finite, this->N);
  std::vector<vtkIdType> order;
  vtkApertureMemory::Reserve(order, this->N);
  for (vtkIdType i = 0; i < this->N; ++i)
  {
    this->Finite[i] = vtkApertureSurface::IsUsable(&world[3 * i]);
    if (this->Finite[i])
    {
      order.push_back(i);
    }
  }
  const double* w = world.data();
  vtkApertureSMP::Sort(order.begin(), order.end(),
    [w](vtkIdType a, vtkIdType b)
    {
      const double* p = w + 3 * a;
      const double* q = w + 3 * b;
      return std::make_tuple(p[0], p[1], p[2], a) < std::make_tuple(q[0], q[1], q[2], b);
    });
  std::vector<vtkIdType> first;
  vtkApertureMemory::Assign(first, this->N, vtkIdType(-1));
  for (size_t k = 0; k < order.size(); ++k)
  {
    const bool same = k > 0 && w[3 * order[k]] == w[3 * order[k - 1]] &&
      w[3 * order[k] + 1] == w[3 * order[k - 1] + 1] &&
      w[3 * order[k] + 2] == w[3 * order[k - 1] + 2];
    first[order[k]] = same ? first[order[k - 1]] : order[k];
  }
  vtkApertureMemory::Assign(this->VertexOf, this->N, vtkApertureSurface::NoVertex);
  for (vtkIdType i = 0; i < this->N; ++i)
  {
    if (this->Finite[i] && first[i] == i)
    {
      this->VertexOf[i] = static_cast<std::uint32_t>(this->VertexInput.size());
      this->VertexInput.push_back(i);
    }
  }
  for (vtkIdType i = 0; i < this->N; ++i)
  {
    if (this->Finite[i])
    {
      this->VertexOf[i] = this->VertexOf[first[i]];
    }
  }
  const vtkIdType vertices = static_cast<vtkIdType>(this->VertexInput.size());
  vtkApertureMemory::Assign(this->S.Vertices, 3 * vertices + 1);
  for (vtkIdType v = 0; v < vertices; ++v)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->S.Vertices[3 * v + k] =
        static_cast<float>(w[3 * this->VertexInput[v] + k] - this->S.Origin[k]);
    }
  }
}

//------------------------------------------------------------------------------
// Every polygon and strip as triangles of input points, remembering their cell and corners. A
// cell of n corners makes n - 2 triangles (none below 3): counted first, the cells are then cut
// on every core, each into its own slots, and the triangles with a corner that is not finite
// are dropped afterwards.
void Build::Triangulate()
{
  vtkCellArray* const arrays[2] = { this->Input->GetPolys(), this->Input->GetStrips() };
  this->Polygons = arrays[0]->GetNumberOfCells();
  const vtkIdType cells = this->Polygons + arrays[1]->GetNumberOfCells();
  this->MarkOnSurface(arrays);
  std::vector<vtkIdType> first; // each cell's first triangle
  vtkApertureMemory::Assign(first, cells + 1);
  vtkApertureSMP::For(0, cells, 4096,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType g = begin; g < end; ++g)
      {
        const vtkIdType npts = g < this->Polygons ? arrays[0]->GetCellSize(g)
                                                  : arrays[1]->GetCellSize(g - this->Polygons);
        first[g + 1] = std::max<vtkIdType>(0, npts - 2);
      }
    });
  std::partial_sum(first.begin(), first.end(), first.begin());
  this->Corners = arrays[0]->GetNumberOfConnectivityIds() + arrays[1]->GetNumberOfConnectivityIds();
  vtkApertureMemory::Assign(this->TriInput, 3 * first.back());
  vtkApertureMemory::Assign(this->TriCorner, 3 * first.back());
  vtkApertureMemory::Assign(this->TriCell, first.back());
  std::atomic<bool> dropped(false);
  vtkApertureSMP::For(0, cells, 1024,
    [&](vtkIdType begin, vtkIdType end) { this->CutCells(arrays, first, begin, end, dropped); });
  if (dropped)
  {
    this->DropNotFinite();
  }
}

//------------------------------------------------------------------------------
// The input points that a polygon or strip names.
void Build::MarkOnSurface(vtkCellArray* const arrays[2])
{
  vtkApertureMemory::Assign(this->OnSurface, this->N);
  arrays[0]->Visit(MarkPoints{}, this->OnSurface);
  arrays[1]->Visit(MarkPoints{}, this->OnSurface);
}

//------------------------------------------------------------------------------
// Cells [begin, end) of the polygons, then strips, as triangles in their slots from first[g]
// on (vtkApertureMeshSurface::Triangulate() makes exactly as many as counted); a triangle with
// a corner that is not finite gets the cell NoVertex, to be dropped.
void Build::CutCells(vtkCellArray* const arrays[2], const std::vector<vtkIdType>& first,
  vtkIdType begin, vtkIdType end, std::atomic<bool>& dropped)
{
  const vtkIdType polygonCorners = arrays[0]->GetNumberOfConnectivityIds();
  const vtkSmartPointer<vtkCellArrayIterator> cells[2] = {
    vtk::TakeSmartPointer(arrays[0]->NewIterator()), vtk::TakeSmartPointer(arrays[1]->NewIterator())
  };
  std::vector<vtkIdType> local;
  bool allFinite = true;
  for (vtkIdType g = begin; g < end; ++g)
  {
    const int strip = g < this->Polygons ? 0 : 1;
    const vtkIdType c = g - strip * this->Polygons;
    vtkIdType npts;
    const vtkIdType* ids;
    cells[strip]->GetCellAtId(c, npts, ids);
    const vtkIdType corner = strip * polygonCorners +
      static_cast<vtkIdType>(arrays[strip]->GetOffsetsArray()->GetComponent(c, 0));
    local.clear();
    vtkApertureMeshSurface::Triangulate(
      npts, ids, strip == 1, this->Input->GetPoints(), this->Finite.data(), local);
    for (vtkIdType t = 0, slot = first[g]; t < first[g + 1] - first[g]; ++t, ++slot)
    {
      bool finite = true;
      for (int k = 0; k < 3; ++k)
      {
        const vtkIdType at = local[3 * t + k];
        this->TriInput[3 * slot + k] = static_cast<std::uint32_t>(ids[at]);
        this->TriCorner[3 * slot + k] = static_cast<std::uint32_t>(corner + at);
        finite = finite && this->Finite[ids[at]];
      }
      this->TriCell[slot] = finite ? static_cast<std::uint32_t>(g) : vtkApertureSurface::NoVertex;
      allFinite = allFinite && finite;
    }
  }
  if (!allFinite)
  {
    dropped = true;
  }
}

//------------------------------------------------------------------------------
// The triangles CutCells() marked dropped removed, the others kept in order.
void Build::DropNotFinite()
{
  size_t kept = 0;
  for (size_t t = 0; t < this->TriCell.size(); ++t)
  {
    if (this->TriCell[t] == vtkApertureSurface::NoVertex)
    {
      continue;
    }
    if (kept != t)
    {
      std::copy_n(&this->TriInput[3 * t], 3, &this->TriInput[3 * kept]);
      std::copy_n(&this->TriCorner[3 * t], 3, &this->TriCorner[3 * kept]);
      this->TriCell[kept] = this->TriCell[t];
    }
    ++kept;
  }
  this->TriInput.resize(3 * kept);
  this->TriCorner.resize(3 * kept);
  this->TriCell.resize(kept);
}

//------------------------------------------------------------------------------
void vtkApertureMeshSurface::Triangulate(vtkIdType npts, const vtkIdType* ids, bool strip,
  vtkPoints* points, const unsigned char* finite, std::vector<vtkIdType>& triangles)
{
  auto add = [&triangles](vtkIdType a, vtkIdType b, vtkIdType c)
  {
    triangles.push_back(a);
    triangles.push_back(b);
    triangles.push_back(c);
  };
  if (strip)
  {
    for (vtkIdType k = 0; k + 2 < npts; ++k)
    {
      k % 2 == 0 ? add(k, k + 1, k + 2) : add(k + 1, k, k + 2);
    }
    return;
  }
  bool allFinite = true;
  for (vtkIdType k = 0; k < npts && finite; ++k)
  {
    allFinite = allFinite && finite[ids[k]];
  }
  if (npts > 3 && allFinite && points)
  {
    // Not vtkCell::Initialize(): it reads through vtkPoints::GetPoint(id), which returns the
    // array's one tuple buffer, shared by every thread.
    vtkNew<vtkPolygon> polygon;
    polygon->GetPointIds()->SetNumberOfIds(npts);
    polygon->GetPoints()->SetNumberOfPoints(npts);
    for (vtkIdType k = 0; k < npts; ++k)
    {
      double x[3];
      points->GetPoint(ids[k], x);
      polygon->GetPoints()->SetPoint(k, x);
      polygon->GetPointIds()->SetId(k, ids[k]);
    }
    vtkNew<vtkIdList> local;
    if (polygon->Triangulate(local) && local->GetNumberOfIds() == 3 * (npts - 2))
    {
      for (vtkIdType t = 0; t < local->GetNumberOfIds(); t += 3)
      {
        add(local->GetId(t), local->GetId(t + 1), local->GetId(t + 2));
      }
      return;
    }
  }
  for (vtkIdType k = 1; k + 1 < npts; ++k)
  {
    add(0, k, k + 1);
  }
}

//------------------------------------------------------------------------------
// The triangles with three distinct vertices: the geometry.
void Build::SelectGeometry()
{
  const vtkIdType triangles = static_cast<vtkIdType>(this->TriCell.size());
  vtkApertureMemory::Reserve(this->Geometry, triangles);
  for (vtkIdType t = 0; t < triangles; ++t)
  {
    const vtkIdType a = this->Vertex(t, 0), b = this->Vertex(t, 1), c = this->Vertex(t, 2);
    if (a != b && b != c && c != a)
    {
      this->Geometry.push_back(t);
    }
  }
}

//------------------------------------------------------------------------------
// The other end of corner `corner` (3 * g + k)'s outgoing (next) or incoming edge.
vtkIdType Build::Neighbour(vtkIdType corner, int step) const
{
  return this->Vertex(this->Geometry[corner / 3], static_cast<int>((corner % 3 + step) % 3));
}

//------------------------------------------------------------------------------
// Winds the triangles consistently across manifold edges, so that every triangle has a front.
// Each connected piece keeps the winding most of its triangles had.
void Build::Orient()
{
  if (!this->Consistent())
  {
    this->FlipPieces(this->ManifoldNeighbours());
    this->FindIncident(); // the corners of flipped triangles moved
  }
}

//------------------------------------------------------------------------------
// Consistent when no two triangles leave a vertex along the same edge.
bool Build::Consistent() const
{
  const vtkIdType vertices = static_cast<vtkIdType>(this->IncidentStart.size()) - 1;
  std::atomic<bool> consistent(true);
  vtkApertureSMP::For(0, vertices, BlockVertices,
    [&](vtkIdType begin, vtkIdType end)
    {
      std::vector<vtkIdType> ends;
      for (vtkIdType v = begin; v < end && consistent.load(std::memory_order_relaxed); ++v)
      {
        ends.clear();
        for (vtkIdType c = this->IncidentStart[v]; c < this->IncidentStart[v + 1]; ++c)
        {
          ends.push_back(this->Neighbour(this->Incident[c], 1));
        }
        std::sort(ends.begin(), ends.end());
        if (std::adjacent_find(ends.begin(), ends.end()) != ends.end())
        {
          consistent = false;
        }
      }
    });
  return consistent;
}

//------------------------------------------------------------------------------
// Each geometry triangle's neighbours across manifold edges (v, x), v < x, and whether the two
// run the edge in opposite directions (agree on their winding).
std::vector<std::vector<std::pair<vtkIdType, bool>>> Build::ManifoldNeighbours() const
{
  const vtkIdType vertices = static_cast<vtkIdType>(this->IncidentStart.size()) - 1;
  std::vector<std::vector<std::pair<vtkIdType, bool>>> next(this->Geometry.size());
  std::vector<std::pair<vtkIdType, vtkIdType>> edges; // (x, corner)
  for (vtkIdType v = 0; v < vertices; ++v)
  {
    edges.clear();
    for (vtkIdType c = this->IncidentStart[v]; c < this->IncidentStart[v + 1]; ++c)
    {
      for (int step : { 1, 2 })
      {
        const vtkIdType x = this->Neighbour(this->Incident[c], step);
        if (x > v)
        {
          const vtkIdType corner = this->Incident[c];
          edges.emplace_back(x, step == 1 ? corner : -1 - corner);
        }
      }
    }
    std::sort(edges.begin(), edges.end());
    for (size_t e = 0; e + 1 < edges.size(); ++e)
    {
      const bool pair = edges[e].first == edges[e + 1].first &&
        (e + 2 == edges.size() || edges[e + 2].first != edges[e].first) &&
        (e == 0 || edges[e - 1].first != edges[e].first);
      if (pair)
      {
        // Corners >= 0 run the edge v -> x, the others x -> v.
        const vtkIdType a = edges[e].second, b = edges[e + 1].second;
        const vtkIdType ga = (a >= 0 ? a : -1 - a) / 3, gb = (b >= 0 ? b : -1 - b) / 3;
        const bool agree = (a >= 0) != (b >= 0);
        next[ga].emplace_back(gb, agree);
        next[gb].emplace_back(ga, agree);
      }
    }
  }
  return next;
}

//------------------------------------------------------------------------------
// Walks each connected piece from a seed, marking the triangles whose winding differs from the
// seed's, then flips the minority.
void Build::FlipPieces(const std::vector<std::vector<std::pair<vtkIdType, bool>>>& next)
{
  std::vector<signed char> flip(this->Geometry.size(), -1);
  for (size_t seed = 0; seed < this->Geometry.size(); ++seed)
  {
    if (flip[seed] >= 0)
    {
      continue;
    }
    std::vector<vtkIdType> piece = { static_cast<vtkIdType>(seed) };
    flip[seed] = 0;
    size_t flipped = 0;
    for (size_t k = 0; k < piece.size(); ++k)
    {
      for (const auto& neighbour : next[piece[k]])
      {
        if (flip[neighbour.first] < 0)
        {
          flip[neighbour.first] = static_cast<signed char>(flip[piece[k]] ^ !neighbour.second);
          flipped += flip[neighbour.first];
          piece.push_back(neighbour.first);
        }
      }
    }
    const bool invert = 2 * flipped > piece.size();
    for (const vtkIdType g : piece)
    {
      if (flip[g] != invert)
      {
        const vtkIdType t = this->Geometry[g];
        std::swap(this->TriInput[3 * t + 1], this->TriInput[3 * t + 2]);
        std::swap(this->TriCorner[3 * t + 1], this->TriCorner[3 * t + 2]);
      }
    }
  }
}

//------------------------------------------------------------------------------
void Build::FacesAround(const std::uint32_t* corners, int m, Sides& sides) const
{
  std::vector<std::array<float, 4>>& faces = sides.Faces;
  faces.resize(m);
  for (int i = 0; i < m; ++i)
  {
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      const float* v = &this->S.Vertices[3 * this->Vertex(this->Geometry[corners[i] / 3], k)];
      std::copy(v, v + 3, p[k]);
    }
    const double e1[3] = { p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2] };
    const double e2[3] = { p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2] };
    double n[3];
    vtkMath::Cross(e1, e2, n);
    const double length = vtkMath::Normalize(n);
    const bool area = length > 0.0; // zero area: no direction
    for (int k = 0; k < 3; ++k)
    {
      faces[i][k] = area ? static_cast<float>(n[k]) : 0.0f;
    }
    faces[i][3] = area ? static_cast<float>(0.5 * length) : 0.0f;
  }
}

//------------------------------------------------------------------------------
// The geometry triangle corners around each vertex (3 * g + corner).
void Build::FindIncident()
{
  const vtkIdType vertices = static_cast<vtkIdType>(this->VertexInput.size());
  vtkApertureMemory::Assign(this->IncidentStart, vertices + 1);
  for (size_t g = 0; g < this->Geometry.size(); ++g)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++this->IncidentStart[this->Vertex(this->Geometry[g], k) + 1];
    }
  }
  std::partial_sum(
    this->IncidentStart.begin(), this->IncidentStart.end(), this->IncidentStart.begin());
  vtkApertureMemory::Assign(this->Incident, 3 * this->Geometry.size());
  std::vector<vtkIdType> fill(this->IncidentStart.begin(), this->IncidentStart.end() - 1);
  for (size_t g = 0; g < this->Geometry.size(); ++g)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->Incident[fill[this->Vertex(this->Geometry[g], k)]++] =
        3 * static_cast<vtkIdType>(g) + k;
    }
  }
}

//------------------------------------------------------------------------------
// A receiving point of `block` (its id there) on a side of a vertex.
vtkIdType Build::AddPoint(
  PointBlock& block, vtkIdType vertex, unsigned int side, const double normal[3])
{
  const vtkIdType id = static_cast<vtkIdType>(block.Vertex.size());
  block.Vertex.push_back(static_cast<std::uint32_t>(vertex));
  double p[3];
  this->Input->GetPoint(this->VertexInput[vertex], p);
  block.Key.push_back(vtkApertureSurface::PointKey(p, side));
  double n[3] = { normal[0], normal[1], normal[2] };
  const double length = vtkMath::Normalize(n);
  const bool valid = length > 0.0 && std::isfinite(length);
  block.Valid.push_back(valid ? 1 : 0);
  for (int k = 0; k < 3; ++k)
  {
    block.Normals.push_back(valid ? static_cast<float>(n[k]) : 0.0f);
  }
  if (this->VertexFirstPoint[vertex] < 0)
  {
    this->VertexFirstPoint[vertex] = id;
  }
  return id;
}

//------------------------------------------------------------------------------
// Computed normals: around each vertex, triangles of one cell, or across an edge whose faces
// are within the feature angle, are one side; each side's normal sums its unit face normals.
// Waves of blocks of vertices on every core, their points then numbered in vertex order as one
// core would: the same surface whatever the number of threads.
void Build::SidesFromCreases(double cosAngle)
{
  const vtkIdType vertices = static_cast<vtkIdType>(this->IncidentStart.size()) - 1;
  std::vector<PointBlock> blocks(WaveBlocks);
  for (vtkIdType wave = 0; wave < vertices; wave += WaveBlocks * BlockVertices)
  {
    const vtkIdType end = std::min(vertices, wave + WaveBlocks * BlockVertices);
    auto block = [&](vtkIdType b) { return std::min(end, wave + b * BlockVertices); };
    const vtkIdType count = (end - wave + BlockVertices - 1) / BlockVertices;
    vtkApertureSMP::For(0, count, 1,
      [&](vtkIdType begin, vtkIdType last)
      {
        for (vtkIdType b = begin; b < last; ++b)
        {
          this->CreaseSides(block(b), block(b + 1), cosAngle, blocks[b]);
        }
      });
    const std::vector<vtkIdType> first = this->StorePoints(blocks, count);
    vtkApertureSMP::For(0, count, 1,
      [&](vtkIdType begin, vtkIdType last)
      {
        // The corners' and vertices' points, numbered in their block, get their surface ids.
        for (vtkIdType v = block(begin); v < block(last); ++v)
        {
          const vtkIdType shift = first[(v - wave) / BlockVertices];
          for (vtkIdType c = this->IncidentStart[v]; c < this->IncidentStart[v + 1]; ++c)
          {
            const std::uint32_t corner = this->Incident[c];
            this->TriPoint[3 * this->Geometry[corner / 3] + corner % 3] += shift;
          }
          this->VertexFirstPoint[v] += this->VertexFirstPoint[v] >= 0 ? shift : 0;
        }
      });
  }
}

//------------------------------------------------------------------------------
// The sides of vertices begin .. end - 1, their points in `block`.
void Build::CreaseSides(vtkIdType begin, vtkIdType end, double cosAngle, PointBlock& block)
{
  Classes classes;
  Sides sides;
  std::vector<vtkIdType> pointOfSide;
  for (vtkIdType v = begin; v < end; ++v)
  {
    const std::uint32_t* corners = this->Incident.data() + this->IncidentStart[v];
    const int m = static_cast<int>(this->IncidentStart[v + 1] - this->IncidentStart[v]);
    if (m == 0)
    {
      continue; // in no triangle: its points are on no surface, or only in degenerate cells
    }
    this->FacesAround(corners, m, sides);
    this->GroupCreaseFaces(corners, m, cosAngle, classes, sides);
    this->SumSides(m, classes, sides);
    this->MakeSidePoints(v, sides, pointOfSide, block);
    for (int i = 0; i < m; ++i)
    {
      this->TriPoint[3 * this->Geometry[corners[i] / 3] + corners[i] % 3] =
        static_cast<std::uint32_t>(pointOfSide[sides.Of[i]]);
    }
  }
}

//------------------------------------------------------------------------------
// The points of the first `count` blocks appended to the surface's, one block after the other
// (each block emptied). The surface id of each block's first point.
std::vector<vtkIdType> Build::StorePoints(std::vector<PointBlock>& blocks, vtkIdType count)
{
  vtkApertureSurface& s = this->S;
  std::vector<vtkIdType> first(count);
  for (vtkIdType b = 0; b < count; ++b)
  {
    PointBlock& block = blocks[b];
    first[b] = s.GetNumberOfPoints();
    s.PointVertex.insert(s.PointVertex.end(), block.Vertex.begin(), block.Vertex.end());
    s.Key.insert(s.Key.end(), block.Key.begin(), block.Key.end());
    s.Valid.insert(s.Valid.end(), block.Valid.begin(), block.Valid.end());
    // WritePointer() grows the array geometrically and never shrinks it (SetNumberOfValues()
    // would reallocate it to the exact size at every block).
    const vtkIdType values = s.Normals->GetNumberOfValues();
    float* normals = s.Normals->WritePointer(values, static_cast<vtkIdType>(block.Normals.size()));
    std::copy(block.Normals.begin(), block.Normals.end(), normals);
    block.Clear();
  }
  return first;
}

//------------------------------------------------------------------------------
// The m triangles around a vertex (`corners`, 3 * geometry triangle + corner) in classes: those
// of one polygon, and those across an edge whose faces are within the feature angle.
void Build::GroupCreaseFaces(
  const std::uint32_t* corners, int m, double cosAngle, Classes& classes, Sides& sides) const
{
  classes.Reset(m);
  auto triangle = [&](int i) { return this->Geometry[corners[i] / 3]; };
  std::vector<std::pair<vtkIdType, int>>& keyed = classes.Keyed;
  keyed.clear();
  for (int i = 0; i < m; ++i)
  {
    // Polygons are one face each; a strip's triangles are faces of their own.
    const vtkIdType cell = this->TriCell[triangle(i)];
    keyed.emplace_back(cell < this->Polygons ? cell : -1 - i, i);
  }
  std::sort(keyed.begin(), keyed.end());
  for (int i = 1; i < m; ++i)
  {
    if (keyed[i].first == keyed[i - 1].first)
    {
      classes.Unite(keyed[i].second, keyed[i - 1].second);
    }
  }
  // Triangles sharing an edge (v, x), by the other end x.
  keyed.clear();
  for (int i = 0; i < m; ++i)
  {
    const int corner = static_cast<int>(corners[i] % 3);
    keyed.emplace_back(this->Vertex(triangle(i), (corner + 1) % 3), i);
    keyed.emplace_back(this->Vertex(triangle(i), (corner + 2) % 3), i);
  }
  std::sort(keyed.begin(), keyed.end());
  for (size_t a = 0; a < keyed.size(); ++a)
  {
    for (size_t b = a + 1; b < keyed.size() && keyed[b].first == keyed[a].first; ++b)
    {
      const float* na = sides.Faces[keyed[a].second].data();
      const float* nb = sides.Faces[keyed[b].second].data();
      if (vtkMath::Dot(na, na) > 0.0f && vtkMath::Dot(na, nb) >= cosAngle)
      {
        classes.Unite(keyed[a].second, keyed[b].second);
      }
    }
  }
}

//------------------------------------------------------------------------------
// The classes of the m triangles around a vertex (Faces) as its sides, numbered in the order
// met.
void Build::SumSides(int m, Classes& classes, Sides& sides) const
{
  sides.Of.resize(m);
  sides.Sums.clear();
  sides.Areas.clear();
  std::fill(sides.VertexNormal, sides.VertexNormal + 3, 0.0);
  sides.Total = 0.0;
  std::vector<int>& sideOfRoot = sides.OfRoot;
  sideOfRoot.assign(m, -1);
  for (int i = 0; i < m; ++i)
  {
    const int root = classes.Find(i);
    if (sideOfRoot[root] < 0)
    {
      sideOfRoot[root] = static_cast<int>(sides.Sums.size());
      sides.Sums.push_back({ 0.0, 0.0, 0.0 });
      sides.Areas.push_back(0.0);
    }
    const int side = sides.Of[i] = sideOfRoot[root];
    const float* n = sides.Faces[i].data();
    const double area = sides.Faces[i][3];
    for (int k = 0; k < 3; ++k)
    {
      sides.Sums[side][k] += n[k];
      sides.VertexNormal[k] += area * n[k];
    }
    sides.Areas[side] += area;
    sides.Total += area;
  }
}

//------------------------------------------------------------------------------
// One receiving point per side of a vertex, but a side without a direction, or a fold (a small
// side facing against a clearly oriented vertex: a scan's folded triangle, not a crease), joins
// the vertex's largest side.
void Build::MakeSidePoints(
  vtkIdType v, Sides& sides, std::vector<vtkIdType>& pointOfSide, PointBlock& block)
{
  const std::vector<std::array<double, 3>>& sums = sides.Sums;
  const std::vector<double>& areas = sides.Areas;
  const double* vertexNormal = sides.VertexNormal;
  const double total = sides.Total;
  const size_t largest = std::max_element(areas.begin(), areas.end()) - areas.begin();
  const bool oriented = vtkMath::Norm(vertexNormal) > 0.5 * total;
  auto joins = [&](size_t s)
  {
    const bool fold = oriented && s != largest && areas[s] < 0.25 * total &&
      vtkMath::Dot(sums[s].data(), vertexNormal) < 0.0;
    return fold || !(vtkMath::Dot(sums[s].data(), sums[s].data()) > 0.0);
  };
  // The sides in the order of their directions, whatever the order of the triangles, so that
  // the same surface in another cell order (strips, triangles) casts the same rays.
  std::vector<size_t>& order = sides.Order;
  order.resize(sums.size());
  std::iota(order.begin(), order.end(), 0);
  auto direction = [&sums](size_t s)
  {
    const double length = vtkMath::Norm(sums[s].data());
    std::array<double, 3> d;
    for (int k = 0; k < 3; ++k)
    {
      d[k] = length > 0.0 ? std::round(1e6 * sums[s][k] / length) : 0.0;
    }
    return d;
  };
  std::sort(order.begin(), order.end(),
    [&direction](size_t a, size_t b) { return direction(a) < direction(b); });
  pointOfSide.assign(sums.size(), -1);
  unsigned int ordinal = 0;
  for (const size_t s : order)
  {
    if (!joins(s))
    {
      pointOfSide[s] = this->AddPoint(block, v, ordinal++, sums[s].data());
    }
  }
  const double none[3] = { 0.0, 0.0, 0.0 };
  const vtkIdType fallback = pointOfSide[largest] >= 0
    ? pointOfSide[largest]
    : (this->VertexFirstPoint[v] >= 0 ? this->VertexFirstPoint[v]
                                      : this->AddPoint(block, v, ordinal, none));
  for (vtkIdType& point : pointOfSide)
  {
    point = point >= 0 ? point : fallback;
  }
}

//------------------------------------------------------------------------------
// Given normals: the points welded into a vertex whose normals are within the feature angle are
// one side (a point's normal is never split); its normal is the sum of theirs.
void Build::SidesFromNormals(vtkDataArray* normals, double cosAngle)
{
  std::vector<PointBlock> points(1); // one block, the only one: its ids are the surface's
  PointBlock& block = points.front();
  std::vector<vtkIdType> cluster;
  vtkApertureMemory::Assign(cluster, this->N, vtkIdType(-1));
  for (vtkIdType v = 0; v + 1 < static_cast<vtkIdType>(this->IncidentStart.size()); ++v)
  {
    // The distinct input points at v, each with its unit normal (zero if it has none).
    std::vector<vtkIdType> members;
    for (vtkIdType c = this->IncidentStart[v]; c < this->IncidentStart[v + 1]; ++c)
    {
      const vtkIdType corner = this->Incident[c];
      members.push_back(this->TriInput[3 * this->Geometry[corner / 3] + corner % 3]);
    }
    if (members.empty())
    {
      continue;
    }
    std::sort(members.begin(), members.end());
    members.erase(std::unique(members.begin(), members.end()), members.end());
    std::vector<std::array<double, 3>> unit(members.size()), sums;
    std::vector<int> sideOf(members.size(), -1);
    std::vector<size_t> firstOf; // each side's first member
    for (size_t i = 0; i < members.size(); ++i)
    {
      normals->GetTuple(members[i], unit[i].data());
      const double length = vtkMath::Normalize(unit[i].data());
      if (!(length > 0.0) || !std::isfinite(length))
      {
        continue;
      }
      for (size_t s = 0; s < sums.size() && sideOf[i] < 0; ++s)
      {
        // Against the side's first normal: a greedy clustering, deterministic in point order.
        if (vtkMath::Dot(unit[i].data(), unit[firstOf[s]].data()) >= cosAngle)
        {
          sideOf[i] = static_cast<int>(s);
        }
      }
      if (sideOf[i] < 0)
      {
        sideOf[i] = static_cast<int>(sums.size());
        sums.push_back({ 0.0, 0.0, 0.0 });
        firstOf.push_back(i);
      }
      for (int k = 0; k < 3; ++k)
      {
        sums[sideOf[i]][k] += unit[i][k];
      }
    }
    std::vector<vtkIdType> pointOfSide(sums.size());
    for (size_t s = 0; s < sums.size(); ++s)
    {
      pointOfSide[s] = this->AddPoint(block, v, static_cast<unsigned int>(s), sums[s].data());
    }
    const double none[3] = { 0.0, 0.0, 0.0 };
    const vtkIdType fallback =
      sums.empty() ? this->AddPoint(block, v, 0, none) : pointOfSide.front();
    for (size_t i = 0; i < members.size(); ++i)
    {
      cluster[members[i]] = sideOf[i] >= 0 ? pointOfSide[sideOf[i]] : fallback;
    }
  }
  for (const vtkIdType t : this->Geometry)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->TriPoint[3 * t + k] = static_cast<std::uint32_t>(cluster[this->TriInput[3 * t + k]]);
    }
  }
  this->StorePoints(points, 1);
}

//------------------------------------------------------------------------------
// Each input point's receiving point (the first of its corners'), the corners' for
// vtkApertureSurfaceOutput, and the geometry for Embree.
void Build::MapInputPoints()
{
  // What the sides needed makes room for what the mapping makes.
  std::vector<std::uint32_t>().swap(this->Incident);
  std::vector<vtkIdType>().swap(this->IncidentStart);
  this->PointOfEachInput();
  this->CornerPoints();
  if (this->S.BreakStrips)
  {
    this->StripTriangles();
  }
  vtkApertureMemory::Reserve(this->S.Triangles, 3 * this->Geometry.size());
  vtkApertureMemory::Reserve(this->S.CornerPoints, 3 * this->Geometry.size());
  for (const vtkIdType t : this->Geometry)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->S.Triangles.push_back(static_cast<std::uint32_t>(this->Vertex(t, k)));
      this->S.CornerPoints.push_back(this->TriPoint[3 * t + k]);
    }
  }
}

//------------------------------------------------------------------------------
// Each input point's receiving point: the first of its corners' sides, in their order;
// vtkApertureSurface::Invalid where not finite or without a normal,
// vtkApertureSurface::NotOnSurface where in no cell.
void Build::PointOfEachInput()
{
  std::vector<vtkIdType>& map = this->S.InputPoints;
  vtkApertureMemory::Assign(map, this->N, vtkApertureSurface::NotOnSurface);
  for (size_t c = 0; c < this->TriPoint.size(); ++c)
  {
    // The first of its sides, in their order.
    const vtkIdType i = this->TriInput[c];
    const vtkIdType point = this->PointOf(c);
    if (point >= 0 && (map[i] == vtkApertureSurface::NotOnSurface || point < map[i]))
    {
      map[i] = point;
    }
  }
  for (vtkIdType i = 0; i < this->N; ++i)
  {
    if (!this->OnSurface[i])
    {
      map[i] = vtkApertureSurface::NotOnSurface;
      continue;
    }
    if (!this->Finite[i])
    {
      map[i] = vtkApertureSurface::Invalid;
      ++this->S.UnusablePoints;
      continue;
    }
    if (map[i] == vtkApertureSurface::NotOnSurface)
    {
      // Only in degenerate or dropped triangles: the vertex's side, if it has one.
      map[i] = this->VertexFirstPoint[this->VertexOf[i]];
    }
    if (map[i] < 0 || !this->S.Valid[map[i]])
    {
      map[i] = map[i] < 0 ? vtkApertureSurface::Invalid : map[i];
      ++this->S.UndefinedNormals;
    }
  }
}

//------------------------------------------------------------------------------
// The cells' split corners (those whose receiving point is not their input point's), and
// whether a corner, in a strip, has triangles on different sides (the strip is then broken into
// triangles). Cell by cell, so that no receiving point is held for every corner.
void Build::CornerPoints()
{
  const std::vector<vtkIdType>& map = this->S.InputPoints;
  std::vector<vtkIdType> local;
  size_t t = 0;        // the first triangle of the cell
  vtkIdType cell = 0;  // polygons, then strips
  vtkIdType first = 0; // the cell's first corner, over polygons then strips
  for (vtkCellArray* cells : { this->Input->GetPolys(), this->Input->GetStrips() })
  {
    auto& splits = cells == this->Input->GetPolys() ? this->S.PolySplits : this->S.StripSplits;
    vtkIdType c = 0; // in this cell array's connectivity
    vtkIdType npts;
    const vtkIdType* ids;
    auto it = vtk::TakeSmartPointer(cells->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cell)
    {
      it->GetCurrentCell(npts, ids);
      this->TrianglePoints(cell, first, npts, t, local);
      for (vtkIdType k = 0; k < npts; ++k, ++c)
      {
        if (local[k] >= 0 && local[k] != map[ids[k]])
        {
          splits.push_back({ c, ids[k], local[k] });
        }
      }
      first += npts;
    }
  }
  this->S.CountSplitPoints();
}

//------------------------------------------------------------------------------
// The receiving points of the `npts` corners of cell `cell` (the first at `first`) from its
// triangles, which begin at triangle t (moved past them): each corner's first triangle
// corner's, -1 where none has one.
void Build::TrianglePoints(
  vtkIdType cell, vtkIdType first, vtkIdType npts, size_t& t, std::vector<vtkIdType>& local)
{
  local.assign(npts, -1);
  for (; t < this->TriCell.size() && this->TriCell[t] == cell; ++t)
  {
    for (int j = 0; j < 3; ++j)
    {
      vtkIdType& at = local[this->TriCorner[3 * t + j] - first];
      const vtkIdType point = this->PointOf(3 * t + j);
      this->S.BreakStrips = this->S.BreakStrips || (at >= 0 && point >= 0 && at != point);
      at = at >= 0 ? at : point;
    }
  }
}

//------------------------------------------------------------------------------
// Each strip triangle with three distinct points, with its strip and its corners' points.
void Build::StripTriangles()
{
  const std::vector<vtkIdType>& map = this->S.InputPoints;
  for (size_t t = 0; t < this->TriCell.size(); ++t)
  {
    const std::uint32_t* in = &this->TriInput[3 * t];
    if (this->TriCell[t] < this->Polygons || in[0] == in[1] || in[1] == in[2] || in[0] == in[2])
    {
      continue;
    }
    this->S.StripTriangles.push_back(this->TriCell[t] - this->Polygons);
    for (int k = 0; k < 3; ++k)
    {
      this->S.StripTriangles.push_back(in[k]);
      const vtkIdType point = this->PointOf(3 * t + k);
      this->S.StripTriangles.push_back(point >= 0 ? point : map[in[k]]);
    }
  }
}

//------------------------------------------------------------------------------
bool vtkApertureMeshSurface::Set(vtkApertureSurface& surface, vtkPolyData* input,
  const double origin[3], double featureAngle, std::string& error)
{
  const vtkIdType n = input->GetNumberOfPoints();
  const vtkIdType corners = input->GetPolys()->GetNumberOfConnectivityIds() +
    input->GetStrips()->GetNumberOfConnectivityIds();
  if (n >= static_cast<vtkIdType>(vtkApertureSurface::NoVertex) ||
    corners >= static_cast<vtkIdType>(vtkApertureSurface::NoVertex) / 3)
  {
    error = "more than 2^32 points, or more than 2^32 / 3 polygon and strip corners";
    return false;
  }
  error = vtkApertureCellCheck::FindBadCell(input);
  if (!error.empty())
  {
    return false;
  }
  surface.Reset(n);
  std::copy_n(origin, 3, surface.Origin);
  Build build(surface, input);
  build.Weld();
  build.Triangulate();
  build.SelectGeometry();
  build.FindIncident();
  build.Orient();
  vtkApertureMemory::Assign(build.TriPoint, build.TriInput.size(), vtkApertureSurface::NoVertex);
  vtkApertureMemory::Assign(build.VertexFirstPoint, build.VertexInput.size(), vtkIdType(-1));
  surface.Reserve(static_cast<vtkIdType>(build.VertexInput.size())); // most vertices: 1 point
  const double cosAngle = std::cos(vtkMath::RadiansFromDegrees(featureAngle));
  vtkDataArray* given = vtkApertureSurface::GivenNormals(input);
  surface.NormalsComputed = given == nullptr;
  if (given)
  {
    build.SidesFromNormals(given, cosAngle);
  }
  else
  {
    build.SidesFromCreases(cosAngle);
  }
  build.MapInputPoints();
  if (given)
  {
    surface.CountFlippedNormals();
  }
  return true;
}
