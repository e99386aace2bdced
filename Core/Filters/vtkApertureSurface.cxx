/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureSurface.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureSurface.h"

#include "vtkApertureCellCheck.h"
#include "vtkApertureRaySampler.h"
#include "vtkApertureRayScene.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolygon.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <unordered_map>

namespace
{
constexpr std::uint32_t NoVertex = std::numeric_limits<std::uint32_t>::max();

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

// The key of a receiving point: its world position (+0 and -0 alike) and its side's ordinal.
std::uint64_t PositionKey(const double p[3], unsigned int side)
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

// Union-find over small index sets (the triangles around one vertex).
struct Classes
{
  std::vector<int> Parent;
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
  std::vector<int> Of;
  std::vector<std::array<double, 3>> Sums;
  std::vector<double> Areas;
  double VertexNormal[3] = { 0.0, 0.0, 0.0 };
  double Total = 0.0;
};

// MakeOutput()'s new points: one per input point and receiving point other than its own, in the
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

  // A copy of `cells` whose corners (in connectivity order) use their receiving points'.
  vtkSmartPointer<vtkCellArray> Renumber(vtkCellArray* cells, const std::vector<vtkIdType>& corners)
  {
    auto result = vtkSmartPointer<vtkCellArray>::New();
    result->DeepCopy(cells);
    vtkIdType c = 0;
    vtkIdType npts;
    const vtkIdType* ids;
    std::vector<vtkIdType> renumbered;
    for (vtkIdType cell = 0; cell < result->GetNumberOfCells(); ++cell)
    {
      result->GetCellAtId(cell, npts, ids);
      renumbered.assign(ids, ids + npts);
      for (vtkIdType k = 0; k < npts; ++k, ++c)
      {
        renumbered[k] = this->Point(ids[k], corners[c]);
      }
      result->ReplaceCellAtId(cell, npts, renumbered.data());
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

// The grid's points in world coordinates (3 each), and whether each is finite.
void GridPoints(const Grid& grid, vtkDataArray* heights, double heightScale,
  std::vector<double>& world, std::vector<unsigned char>& finite)
{
  world.resize(3 * grid.Nx * grid.Ny);
  finite.assign(grid.Nx * grid.Ny, 0);
  for (vtkIdType j = 0; j < grid.Ny; ++j)
  {
    for (vtkIdType i = 0; i < grid.Nx; ++i)
    {
      const vtkIdType id = i + j * grid.Nx;
      grid.Point(i, j, heightScale * heights->GetComponent(id, 0), &world[3 * id]);
      finite[id] = IsFinite(&world[3 * id]);
    }
  }
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
}

//------------------------------------------------------------------------------
// The steps of SetPolyData(), with what they share.
struct vtkApertureSurface::Build
{
  vtkApertureSurface& S;
  vtkPolyData* Input;
  vtkIdType N;
  std::vector<double> World;            // input points, 3 each
  std::vector<unsigned char> Finite;    // per input point
  std::vector<std::uint32_t> VertexOf;  // per input point (NoVertex when not finite)
  std::vector<vtkIdType> VertexInput;   // an input point of each vertex
  std::vector<unsigned char> OnSurface; // input point used by a polygon or strip
  // 32-bit where the size limits of SetPolyData() allow: the triangles dominate the memory.
  std::vector<std::uint32_t> TriInput;  // every triangle's input points, 3 each
  std::vector<std::uint32_t> TriCell;   // its polygon or strip
  std::vector<std::uint32_t> TriCorner; // the connectivity index of each corner
  std::vector<vtkIdType> TriPoint;      // the receiving point of each corner (-1: none)
  std::vector<std::uint32_t> Geometry;  // triangles with three distinct vertices
  std::vector<float> FaceNormals;       // unit (or zero) normal of each geometry triangle
  std::vector<float> FaceAreas;
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

  void Weld();
  void Triangulate();
  void AddCellTriangles(vtkIdType npts, const vtkIdType* ids, bool strip,
    std::vector<vtkIdType>& local, vtkIdType cell);
  void SelectGeometry();
  vtkIdType Neighbour(vtkIdType corner, int step) const;
  void Orient();
  bool Consistent() const;
  std::vector<std::vector<std::pair<vtkIdType, bool>>> ManifoldNeighbours() const;
  void FlipPieces(const std::vector<std::vector<std::pair<vtkIdType, bool>>>& next);
  void ComputeFaceNormals();
  void FindIncident();
  void SidesFromCreases(double cosAngle);
  void GroupCreaseFaces(
    const std::uint32_t* corners, int m, double cosAngle, Classes& classes) const;
  void SumSides(const std::uint32_t* corners, int m, Classes& classes, Sides& sides) const;
  void MakeSidePoints(vtkIdType v, const Sides& sides, std::vector<vtkIdType>& pointOfSide);
  void SidesFromNormals(vtkDataArray* normals, double cosAngle);
  vtkIdType AddPoint(vtkIdType vertex, unsigned int side, const double normal[3]);
  void MapInputPoints();
  void PointOfEachInput();
  void CornerPoints();
  void StripTriangles();
};

//------------------------------------------------------------------------------
// Points at the same position become one vertex, numbered in the order of their first point.
void vtkApertureSurface::Build::Weld()
{
  vtkPoints* points = this->Input->GetPoints();
  this->World.resize(3 * this->N);
  this->Finite.assign(this->N, 0);
  std::vector<vtkIdType> order;
  for (vtkIdType i = 0; i < this->N; ++i)
  {
    points->GetPoint(i, &this->World[3 * i]);
    this->Finite[i] = IsFinite(&this->World[3 * i]);
    if (this->Finite[i])
    {
      order.push_back(i);
    }
  }
  const double* w = this->World.data();
  std::sort(order.begin(), order.end(),
    [w](vtkIdType a, vtkIdType b)
    {
      const double* p = w + 3 * a;
      const double* q = w + 3 * b;
      return std::make_tuple(p[0], p[1], p[2], a) < std::make_tuple(q[0], q[1], q[2], b);
    });
  std::vector<vtkIdType> first(this->N, -1);
  for (size_t k = 0; k < order.size(); ++k)
  {
    const bool same = k > 0 && w[3 * order[k]] == w[3 * order[k - 1]] &&
      w[3 * order[k] + 1] == w[3 * order[k - 1] + 1] &&
      w[3 * order[k] + 2] == w[3 * order[k - 1] + 2];
    first[order[k]] = same ? first[order[k - 1]] : order[k];
  }
  this->VertexOf.assign(this->N, NoVertex);
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
  this->S.Vertices.assign(3 * vertices + 1, 0.0f);
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
// Every polygon and strip as triangles of input points, remembering their cell and corners.
void vtkApertureSurface::Build::Triangulate()
{
  this->OnSurface.assign(this->N, 0);
  std::vector<vtkIdType> local;
  vtkIdType cell = 0;
  this->Polygons = this->Input->GetNumberOfPolys();
  for (vtkCellArray* cells : { this->Input->GetPolys(), this->Input->GetStrips() })
  {
    const bool strip = cells == this->Input->GetStrips();
    vtkIdType npts;
    const vtkIdType* ids;
    auto it = vtk::TakeSmartPointer(cells->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++cell)
    {
      it->GetCurrentCell(npts, ids);
      this->AddCellTriangles(npts, ids, strip, local, cell);
      this->Corners += npts;
    }
  }
}

//------------------------------------------------------------------------------
void vtkApertureSurface::Build::AddCellTriangles(
  vtkIdType npts, const vtkIdType* ids, bool strip, std::vector<vtkIdType>& local, vtkIdType cell)
{
  for (vtkIdType k = 0; k < npts; ++k)
  {
    this->OnSurface[ids[k]] = 1;
  }
  local.clear();
  vtkApertureSurface::Triangulate(
    npts, ids, strip, this->Input->GetPoints(), this->Finite.data(), local);
  for (size_t t = 0; t < local.size(); t += 3)
  {
    const vtkIdType* k = &local[t];
    if (this->Finite[ids[k[0]]] && this->Finite[ids[k[1]]] && this->Finite[ids[k[2]]])
    {
      for (int c = 0; c < 3; ++c)
      {
        this->TriInput.push_back(ids[k[c]]);
        this->TriCorner.push_back(this->Corners + k[c]);
      }
      this->TriCell.push_back(cell);
    }
  }
}

//------------------------------------------------------------------------------
void vtkApertureSurface::Triangulate(vtkIdType npts, const vtkIdType* ids, bool strip,
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
    vtkNew<vtkPolygon> polygon;
    vtkNew<vtkIdList> local;
    polygon->Initialize(static_cast<int>(npts), ids, points);
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
void vtkApertureSurface::Build::SelectGeometry()
{
  const vtkIdType triangles = static_cast<vtkIdType>(this->TriCell.size());
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
vtkIdType vtkApertureSurface::Build::Neighbour(vtkIdType corner, int step) const
{
  return this->Vertex(this->Geometry[corner / 3], static_cast<int>((corner % 3 + step) % 3));
}

//------------------------------------------------------------------------------
// Winds the triangles consistently across manifold edges, so that every triangle has a front.
// Each connected piece keeps the winding most of its triangles had.
void vtkApertureSurface::Build::Orient()
{
  if (!this->Consistent())
  {
    this->FlipPieces(this->ManifoldNeighbours());
    this->FindIncident(); // the corners of flipped triangles moved
  }
}

//------------------------------------------------------------------------------
// Consistent when no two triangles leave a vertex along the same edge.
bool vtkApertureSurface::Build::Consistent() const
{
  const vtkIdType vertices = static_cast<vtkIdType>(this->IncidentStart.size()) - 1;
  std::vector<vtkIdType> ends;
  for (vtkIdType v = 0; v < vertices; ++v)
  {
    ends.clear();
    for (vtkIdType c = this->IncidentStart[v]; c < this->IncidentStart[v + 1]; ++c)
    {
      ends.push_back(this->Neighbour(this->Incident[c], 1));
    }
    std::sort(ends.begin(), ends.end());
    if (std::adjacent_find(ends.begin(), ends.end()) != ends.end())
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
// Each geometry triangle's neighbours across manifold edges (v, x), v < x, and whether the two
// run the edge in opposite directions (agree on their winding).
std::vector<std::vector<std::pair<vtkIdType, bool>>> vtkApertureSurface::Build::ManifoldNeighbours()
  const
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
void vtkApertureSurface::Build::FlipPieces(
  const std::vector<std::vector<std::pair<vtkIdType, bool>>>& next)
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
void vtkApertureSurface::Build::ComputeFaceNormals()
{
  this->FaceNormals.assign(3 * this->Geometry.size(), 0.0);
  this->FaceAreas.assign(this->Geometry.size(), 0.0);
  for (size_t g = 0; g < this->Geometry.size(); ++g)
  {
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      const float* v = &this->S.Vertices[3 * this->Vertex(this->Geometry[g], k)];
      std::copy(v, v + 3, p[k]);
    }
    const double e1[3] = { p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2] };
    const double e2[3] = { p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2] };
    double n[3];
    vtkMath::Cross(e1, e2, n);
    const double length = vtkMath::Normalize(n);
    const bool area = length > 0.0; // zero area: no direction
    this->FaceAreas[g] = area ? static_cast<float>(0.5 * length) : 0.0f;
    for (int k = 0; k < 3; ++k)
    {
      this->FaceNormals[3 * g + k] = area ? static_cast<float>(n[k]) : 0.0f;
    }
  }
}

//------------------------------------------------------------------------------
// The geometry triangle corners around each vertex (3 * g + corner).
void vtkApertureSurface::Build::FindIncident()
{
  const vtkIdType vertices = static_cast<vtkIdType>(this->VertexInput.size());
  this->IncidentStart.assign(vertices + 1, 0);
  for (size_t g = 0; g < this->Geometry.size(); ++g)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++this->IncidentStart[this->Vertex(this->Geometry[g], k) + 1];
    }
  }
  std::partial_sum(
    this->IncidentStart.begin(), this->IncidentStart.end(), this->IncidentStart.begin());
  this->Incident.resize(3 * this->Geometry.size());
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
vtkIdType vtkApertureSurface::Build::AddPoint(
  vtkIdType vertex, unsigned int side, const double normal[3])
{
  const vtkIdType id = static_cast<vtkIdType>(this->S.PointVertex.size());
  this->S.PointVertex.push_back(static_cast<std::uint32_t>(vertex));
  this->S.Key.push_back(PositionKey(&this->World[3 * this->VertexInput[vertex]], side));
  double n[3] = { normal[0], normal[1], normal[2] };
  const double length = vtkMath::Normalize(n);
  const bool valid = length > 0.0 && std::isfinite(length);
  this->S.Valid.push_back(valid ? 1 : 0);
  for (int k = 0; k < 3; ++k)
  {
    this->S.Normals->InsertNextValue(valid ? static_cast<float>(n[k]) : 0.0f);
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
void vtkApertureSurface::Build::SidesFromCreases(double cosAngle)
{
  Classes classes;
  Sides sides;
  std::vector<vtkIdType> pointOfSide;
  for (vtkIdType v = 0; v + 1 < static_cast<vtkIdType>(this->IncidentStart.size()); ++v)
  {
    const std::uint32_t* corners = this->Incident.data() + this->IncidentStart[v];
    const int m = static_cast<int>(this->IncidentStart[v + 1] - this->IncidentStart[v]);
    if (m == 0)
    {
      continue; // in no triangle: its points are on no surface, or only in degenerate cells
    }
    this->GroupCreaseFaces(corners, m, cosAngle, classes);
    this->SumSides(corners, m, classes, sides);
    this->MakeSidePoints(v, sides, pointOfSide);
    for (int i = 0; i < m; ++i)
    {
      this->TriPoint[3 * this->Geometry[corners[i] / 3] + corners[i] % 3] =
        pointOfSide[sides.Of[i]];
    }
  }
}

//------------------------------------------------------------------------------
// The m triangles around a vertex (`corners`, 3 * geometry triangle + corner) in classes: those
// of one polygon, and those across an edge whose faces are within the feature angle.
void vtkApertureSurface::Build::GroupCreaseFaces(
  const std::uint32_t* corners, int m, double cosAngle, Classes& classes) const
{
  classes.Reset(m);
  auto triangle = [&](int i) { return this->Geometry[corners[i] / 3]; };
  std::vector<std::pair<vtkIdType, int>> keyed;
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
      const float* na = &this->FaceNormals[corners[keyed[a].second] / 3 * 3];
      const float* nb = &this->FaceNormals[corners[keyed[b].second] / 3 * 3];
      if (vtkMath::Dot(na, na) > 0.0f && vtkMath::Dot(na, nb) >= cosAngle)
      {
        classes.Unite(keyed[a].second, keyed[b].second);
      }
    }
  }
}

//------------------------------------------------------------------------------
// The classes of the m triangles around a vertex as its sides, numbered in the order met.
void vtkApertureSurface::Build::SumSides(
  const std::uint32_t* corners, int m, Classes& classes, Sides& sides) const
{
  sides.Of.resize(m);
  sides.Sums.clear();
  sides.Areas.clear();
  std::fill(sides.VertexNormal, sides.VertexNormal + 3, 0.0);
  sides.Total = 0.0;
  std::vector<int> sideOfRoot(m, -1);
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
    const float* n = &this->FaceNormals[corners[i] / 3 * 3];
    const double area = this->FaceAreas[corners[i] / 3];
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
void vtkApertureSurface::Build::MakeSidePoints(
  vtkIdType v, const Sides& sides, std::vector<vtkIdType>& pointOfSide)
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
  std::vector<size_t> order(sums.size());
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
      pointOfSide[s] = this->AddPoint(v, ordinal++, sums[s].data());
    }
  }
  const double none[3] = { 0.0, 0.0, 0.0 };
  const vtkIdType fallback = pointOfSide[largest] >= 0
    ? pointOfSide[largest]
    : (this->VertexFirstPoint[v] >= 0 ? this->VertexFirstPoint[v]
                                      : this->AddPoint(v, ordinal, none));
  for (vtkIdType& point : pointOfSide)
  {
    point = point >= 0 ? point : fallback;
  }
}

//------------------------------------------------------------------------------
// Given normals: the points welded into a vertex whose normals are within the feature angle are
// one side (a point's normal is never split); its normal is the sum of theirs.
void vtkApertureSurface::Build::SidesFromNormals(vtkDataArray* normals, double cosAngle)
{
  std::vector<vtkIdType> cluster(this->N, -1);
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
      pointOfSide[s] = this->AddPoint(v, static_cast<unsigned int>(s), sums[s].data());
    }
    const double none[3] = { 0.0, 0.0, 0.0 };
    const vtkIdType fallback = sums.empty() ? this->AddPoint(v, 0, none) : pointOfSide.front();
    for (size_t i = 0; i < members.size(); ++i)
    {
      cluster[members[i]] = sideOf[i] >= 0 ? pointOfSide[sideOf[i]] : fallback;
    }
  }
  for (const vtkIdType t : this->Geometry)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->TriPoint[3 * t + k] = cluster[this->TriInput[3 * t + k]];
    }
  }
}

//------------------------------------------------------------------------------
// Each input point's receiving point (the first of its corners'), the corners' for MakeOutput(),
// and the geometry for Embree.
void vtkApertureSurface::Build::MapInputPoints()
{
  this->PointOfEachInput();
  this->CornerPoints();
  if (this->S.BreakStrips)
  {
    this->StripTriangles();
  }
  for (const vtkIdType t : this->Geometry)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->S.Triangles.push_back(static_cast<std::uint32_t>(this->Vertex(t, k)));
      this->S.CornerPoints.push_back(static_cast<std::uint32_t>(this->TriPoint[3 * t + k]));
    }
  }
}

//------------------------------------------------------------------------------
// Each input point's receiving point: the first of its corners' sides, in their order; Invalid
// where not finite or without a normal, NotOnSurface where in no cell.
void vtkApertureSurface::Build::PointOfEachInput()
{
  std::vector<vtkIdType>& map = this->S.InputPoints;
  map.assign(this->N, NotOnSurface);
  for (size_t c = 0; c < this->TriPoint.size(); ++c)
  {
    // The first of its sides, in their order.
    const vtkIdType i = this->TriInput[c];
    if (this->TriPoint[c] >= 0 && (map[i] == NotOnSurface || this->TriPoint[c] < map[i]))
    {
      map[i] = this->TriPoint[c];
    }
  }
  for (vtkIdType i = 0; i < this->N; ++i)
  {
    if (!this->OnSurface[i])
    {
      map[i] = NotOnSurface;
      continue;
    }
    if (!this->Finite[i])
    {
      map[i] = Invalid;
      ++this->S.NonFinitePoints;
      continue;
    }
    if (map[i] == NotOnSurface)
    {
      // Only in degenerate or dropped triangles: the vertex's side, if it has one.
      map[i] = this->VertexFirstPoint[this->VertexOf[i]];
    }
    if (map[i] < 0 || !this->S.Valid[map[i]])
    {
      map[i] = map[i] < 0 ? Invalid : map[i];
      ++this->S.UndefinedNormals;
    }
  }
}

//------------------------------------------------------------------------------
// The cells' corners' receiving points, and whether any of them splits its point or, in a strip,
// has triangles on different sides (the strip is then broken into triangles).
void vtkApertureSurface::Build::CornerPoints()
{
  const std::vector<vtkIdType>& map = this->S.InputPoints;
  std::vector<vtkIdType> corners(this->Corners, -1);
  for (size_t c = 0; c < this->TriPoint.size(); ++c)
  {
    const vtkIdType at = this->TriCorner[c];
    const bool disagree =
      corners[at] >= 0 && this->TriPoint[c] >= 0 && corners[at] != this->TriPoint[c];
    this->S.BreakStrips = this->S.BreakStrips || disagree;
    corners[at] = corners[at] >= 0 ? corners[at] : this->TriPoint[c];
  }
  const vtkIdType polyCorners = this->Input->GetPolys()->GetNumberOfConnectivityIds();
  std::vector<unsigned char> split(this->N, 0);
  vtkIdType c = 0;
  for (vtkCellArray* cells : { this->Input->GetPolys(), this->Input->GetStrips() })
  {
    vtkIdType npts;
    const vtkIdType* ids;
    auto it = vtk::TakeSmartPointer(cells->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      it->GetCurrentCell(npts, ids);
      for (vtkIdType k = 0; k < npts; ++k, ++c)
      {
        corners[c] = corners[c] >= 0 ? corners[c] : map[ids[k]];
        split[ids[k]] |= corners[c] != map[ids[k]] ? 1 : 0;
      }
    }
  }
  this->S.SplitPoints = std::count(split.begin(), split.end(), 1);
  if (this->S.SplitPoints > 0 || this->S.BreakStrips)
  {
    this->S.PolyCorners.assign(corners.begin(), corners.begin() + polyCorners);
    this->S.StripCorners.assign(corners.begin() + polyCorners, corners.end());
  }
}

//------------------------------------------------------------------------------
// Each strip triangle with three distinct points, with its strip and its corners' points.
void vtkApertureSurface::Build::StripTriangles()
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
      this->S.StripTriangles.push_back(
        this->TriPoint[3 * t + k] >= 0 ? this->TriPoint[3 * t + k] : map[in[k]]);
    }
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
const float* vtkApertureSurface::GetNormal(vtkIdType point) const
{
  return this->Normals->GetPointer(3 * point);
}

//------------------------------------------------------------------------------
void vtkApertureSurface::Allocate(vtkIdType inputPoints)
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
  this->InputPoints.assign(inputPoints, NotOnSurface);
  this->PolyCorners.clear();
  this->StripCorners.clear();
  this->StripTriangles.clear();
  this->NormalsComputed = false;
  this->NonFinitePoints = 0;
  this->UndefinedNormals = 0;
  this->FlippedNormals = 0;
  this->SplitPoints = 0;
  this->BreakStrips = false;
}

//------------------------------------------------------------------------------
bool vtkApertureSurface::SetPolyData(
  vtkPolyData* input, const double origin[3], double featureAngle, std::string& error)
{
  const vtkIdType n = input->GetNumberOfPoints();
  const vtkIdType corners = input->GetPolys()->GetNumberOfConnectivityIds() +
    input->GetStrips()->GetNumberOfConnectivityIds();
  if (n >= static_cast<vtkIdType>(NoVertex) || corners >= static_cast<vtkIdType>(NoVertex) / 3)
  {
    error = "more than 2^32 points, or more than 2^32 / 3 polygon and strip corners";
    return false;
  }
  error = vtkApertureCellCheck::FindBadCell(input);
  if (!error.empty())
  {
    return false;
  }
  this->Allocate(n);
  std::copy_n(origin, 3, this->Origin);
  Build build(*this, input);
  build.Weld();
  build.Triangulate();
  build.SelectGeometry();
  build.FindIncident();
  build.Orient();
  build.ComputeFaceNormals();
  build.TriPoint.assign(build.TriInput.size(), -1);
  build.VertexFirstPoint.assign(build.VertexInput.size(), -1);
  const double cosAngle = std::cos(vtkMath::RadiansFromDegrees(featureAngle));
  vtkDataArray* given = UsableNormals(input);
  this->NormalsComputed = given == nullptr;
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
    this->CountFlippedNormals();
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkApertureSurface::SetHeightField(vtkImageData* input, vtkDataArray* heights,
  double heightScale, const double origin[3], std::string& error)
{
  const Grid grid(input);
  const vtkIdType n = grid.Nx * grid.Ny;
  if (n >= static_cast<vtkIdType>(NoVertex))
  {
    error = "more than 2^32 grid points";
    return false;
  }
  this->Allocate(n);
  std::copy_n(origin, 3, this->Origin);
  std::vector<double> world;
  std::vector<unsigned char> finite;
  GridPoints(grid, heights, heightScale, world, finite);
  this->Vertices.assign(3 * n + 1, 0.0f);
  for (vtkIdType id = 0; id < n; ++id)
  {
    for (int k = 0; k < 3 && finite[id]; ++k)
    {
      this->Vertices[3 * id + k] = static_cast<float>(world[3 * id + k] - origin[k]);
    }
    this->NonFinitePoints += finite[id] ? 0 : 1;
  }
  this->Triangles = GridTriangles(grid, finite);
  if (this->Triangles.empty())
  {
    error = "the height field has no finite cell";
    return false;
  }
  this->CornerPoints = this->Triangles;
  this->SetGridPoints(input, world, finite);
  return true;
}

//------------------------------------------------------------------------------
// One receiving point per grid point: the given normal, or the sum of its triangles' normals.
void vtkApertureSurface::SetGridPoints(
  vtkImageData* input, const std::vector<double>& world, const std::vector<unsigned char>& finite)
{
  const vtkIdType n = static_cast<vtkIdType>(finite.size());
  const std::vector<double> sums = this->WindingNormals(n);
  vtkDataArray* given = UsableNormals(input);
  this->NormalsComputed = given == nullptr;
  this->Normals->SetNumberOfTuples(n);
  this->PointVertex.resize(n);
  this->Valid.assign(n, 0);
  this->Key.resize(n);
  for (vtkIdType id = 0; id < n; ++id)
  {
    this->PointVertex[id] = static_cast<std::uint32_t>(id);
    this->Key[id] = PositionKey(&world[3 * id], 0);
    double nrm[3] = { sums[3 * id], sums[3 * id + 1], sums[3 * id + 2] };
    if (given)
    {
      given->GetTuple(id, nrm);
    }
    const double length = vtkMath::Normalize(nrm);
    this->Valid[id] = finite[id] && length > 0.0 && std::isfinite(length);
    for (int k = 0; k < 3; ++k)
    {
      this->Normals->SetValue(3 * id + k, this->Valid[id] ? static_cast<float>(nrm[k]) : 0.0f);
    }
    this->InputPoints[id] = id;
    this->UndefinedNormals += (finite[id] && !this->Valid[id]) ? 1 : 0;
  }
  if (given)
  {
    this->CountFlippedNormals();
  }
}

//------------------------------------------------------------------------------
std::vector<float> vtkApertureSurface::EdgeLengths() const
{
  const vtkIdType vertices = this->GetNumberOfVertices();
  std::vector<float> sum(vertices, 0.0f);
  std::vector<std::uint32_t> count(vertices, 0);
  for (size_t t = 0; t < this->Triangles.size(); t += 3)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t a = this->Triangles[t + k];
      const std::uint32_t b = this->Triangles[t + (k + 1) % 3];
      const float* p = &this->Vertices[3 * size_t(a)];
      const float* q = &this->Vertices[3 * size_t(b)];
      const float length = std::sqrt((q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]) +
        (q[2] - p[2]) * (q[2] - p[2]));
      sum[a] += length;
      sum[b] += length;
      ++count[a];
      ++count[b];
    }
  }
  for (vtkIdType v = 0; v < vertices; ++v)
  {
    sum[v] = count[v] ? sum[v] / count[v] : 0.0f;
  }
  return sum;
}

//------------------------------------------------------------------------------
void vtkApertureSurface::SetRayOffset(double rayOffset)
{
  const std::vector<float> edges = this->EdgeLengths();
  const vtkIdType n = this->GetNumberOfPoints();
  // The mean of each point's triangles' centroids, relative to the point.
  std::vector<double> middle(3 * n, 0.0);
  std::vector<std::uint32_t> count(n, 0);
  for (size_t t = 0; t < this->Triangles.size(); t += 3)
  {
    double centroid[3] = { 0.0, 0.0, 0.0 };
    for (int k = 0; k < 3; ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        centroid[c] += this->Vertices[3 * size_t(this->Triangles[t + k]) + c] / 3.0;
      }
    }
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t point = this->CornerPoints[t + k];
      const float* p = this->GetPosition(point);
      for (int c = 0; c < 3; ++c)
      {
        middle[3 * size_t(point) + c] += centroid[c] - p[c];
      }
      ++count[point];
    }
  }
  this->Offset.resize(n);
  this->Start.resize(3 * n);
  this->Near.resize(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const float* p = this->GetPosition(i);
    const float* normal = this->GetNormal(i);
    const float magnitude = std::max({ std::abs(p[0]), std::abs(p[1]), std::abs(p[2]) });
    const float edge = edges[this->PointVertex[i]];
    const float lift =
      std::max(static_cast<float>(rayOffset) * edge, 64.0f * FLT_EPSILON * magnitude);
    // Along the surface: the middle's tangential part, a third of an edge off for a corner of a
    // fan, makes up to Offset.
    double along[3];
    for (int c = 0; c < 3; ++c)
    {
      along[c] = count[i] ? middle[3 * i + c] / count[i] : 0.0;
    }
    const double normalPart = along[0] * normal[0] + along[1] * normal[1] + along[2] * normal[2];
    const double scale = edge > 0.0f ? 3.0 * lift / edge : 0.0;
    double shift[3];
    for (int c = 0; c < 3; ++c)
    {
      shift[c] = scale * (along[c] - normalPart * normal[c]);
    }
    const double length =
      std::sqrt(shift[0] * shift[0] + shift[1] * shift[1] + shift[2] * shift[2]);
    const double limit = length > lift ? lift / length : 1.0;
    this->Offset[i] = lift;
    this->Near[i] =
      std::max(vtkApertureRayScene::NearZone * lift, vtkApertureRayScene::ContactTolerance * edge);
    for (int c = 0; c < 3; ++c)
    {
      this->Start[3 * i + c] = static_cast<float>(p[c] + lift * normal[c] + limit * shift[c]);
    }
  }
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
void vtkApertureSurface::MakeOutput(
  vtkPolyData* input, vtkPolyData* output, std::vector<vtkIdType>& outputPoints) const
{
  output->ShallowCopy(input);
  outputPoints = this->InputPoints;
  if (this->SplitPoints == 0 && !this->BreakStrips)
  {
    return;
  }
  PointSplitter splitter(input->GetNumberOfPoints(), this->InputPoints, outputPoints);
  vtkSmartPointer<vtkCellArray> polys = splitter.Renumber(input->GetPolys(), this->PolyCorners);
  if (this->BreakStrips)
  {
    // Strips crossing a crease become their triangles, after the polygons.
    for (size_t t = 0; t < this->StripTriangles.size(); t += 7)
    {
      const vtkIdType* triangle = &this->StripTriangles[t + 1];
      const vtkIdType ids[3] = { splitter.Point(triangle[0], triangle[1]),
        splitter.Point(triangle[2], triangle[3]), splitter.Point(triangle[4], triangle[5]) };
      polys->InsertNextCell(3, ids);
    }
    output->SetStrips(vtkSmartPointer<vtkCellArray>::New());
    this->BrokenStripData(input, output);
  }
  else
  {
    output->SetStrips(splitter.Renumber(input->GetStrips(), this->StripCorners));
  }
  output->SetPolys(polys);
  splitter.CopyPoints(input, output);
}

//------------------------------------------------------------------------------
// Cell data when strips became triangles: vertices, lines and polygons as they were, then each
// strip's data on each of its triangles.
void vtkApertureSurface::BrokenStripData(vtkPolyData* input, vtkPolyData* output) const
{
  const vtkIdType before =
    input->GetNumberOfVerts() + input->GetNumberOfLines() + input->GetNumberOfPolys();
  const vtkIdType triangles = static_cast<vtkIdType>(this->StripTriangles.size() / 7);
  vtkNew<vtkCellData> cd;
  cd->CopyAllOn(vtkDataSetAttributes::COPYTUPLE);
  cd->CopyAllocate(input->GetCellData(), before + triangles);
  cd->CopyData(input->GetCellData(), 0, before, 0);
  for (vtkIdType t = 0; t < triangles; ++t)
  {
    cd->CopyData(input->GetCellData(), before + this->StripTriangles[7 * t], before + t);
  }
  output->GetCellData()->ShallowCopy(cd);
}

//------------------------------------------------------------------------------
bool vtkApertureSurface::SetScene(vtkPolyData* input, const std::vector<vtkPolyData*>& occluders,
  double featureAngle, double rayOffset, vtkApertureSurface& receivers,
  std::vector<vtkApertureSurface>& occluderSurfaces, std::string& error)
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
  if (!receivers.SetPolyData(input, origin, featureAngle, problem))
  {
    error = "Cannot use the input: " + problem + ".";
    return false;
  }
  receivers.SetRayOffset(rayOffset);
  occluderSurfaces = std::vector<vtkApertureSurface>(occluders.size());
  vtkIdType triangles = receivers.GetNumberOfTriangles();
  for (size_t i = 0; i < occluders.size(); ++i)
  {
    if (!occluderSurfaces[i].SetPolyData(occluders[i], origin, featureAngle, problem))
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

//------------------------------------------------------------------------------
vtkSmartPointer<vtkFloatArray> vtkApertureSurface::Scatter(const std::string& name, int components,
  const float* begin, const float* end, const std::vector<vtkIdType>& outputPoints,
  const float* open, const float* closed)
{
  const vtkIdType n = static_cast<vtkIdType>(outputPoints.size());
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  array->SetName(name.c_str());
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(n);
  float* out = array->GetPointer(0);
  const vtkIdType points = (end - begin) / components;
  for (vtkIdType o = 0; o < n; ++o)
  {
    const vtkIdType p = outputPoints[o];
    const float* from =
      p >= 0 && p < points ? begin + components * p : (p == Invalid ? closed : open);
    std::copy_n(from, components, out + components * o);
  }
  return array;
}

//------------------------------------------------------------------------------
void vtkApertureSurface::AddComputedNormals(
  vtkPointData* pd, const std::vector<vtkIdType>& outputPoints) const
{
  if (this->NormalsComputed)
  {
    const float none[3] = { 0.0f, 0.0f, 0.0f };
    const float* normals = this->GetNormal(0);
    pd->SetNormals(Scatter(
      "Normals", 3, normals, normals + 3 * this->GetNumberOfPoints(), outputPoints, none, none));
  }
}
