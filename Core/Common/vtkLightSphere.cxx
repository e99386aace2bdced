/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkLightSphere.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkLightSphere.h"

#include "vtkDoubleArray.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

vtkStandardNewMacro(vtkLightSphere);

// Defined here too for C++11/14, where std::min and std::max taking it by reference need a
// definition.
constexpr int vtkLightSphere::MaximumLevel;

namespace
{
using Vector = std::array<double, 3>;
using Triangle = std::array<int, 3>;

Vector Normalized(const Vector& v)
{
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return { v[0] / n, v[1] / n, v[2] / n };
}

Vector Cross(const Vector& a, const Vector& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}

double Dot(const Vector& a, const Vector& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// Solid angle of the spherical triangle (a, b, c) (Van Oosterom and Strackee).
double SphericalTriangleArea(const Vector& a, const Vector& b, const Vector& c)
{
  return 2.0 * std::atan2(std::abs(Dot(a, Cross(b, c))), 1.0 + Dot(a, b) + Dot(b, c) + Dot(c, a));
}

// The octahedron: +x -x +y -y +z -z, and its faces wound outward.
void Octahedron(std::vector<Vector>& vertices, std::vector<Triangle>& faces)
{
  vertices = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } };
  faces.clear();
  for (int sx = 0; sx < 2; ++sx)
  {
    for (int sy = 0; sy < 2; ++sy)
    {
      for (int sz = 0; sz < 2; ++sz)
      {
        const int a = sx, b = 2 + sy, c = 4 + sz;
        faces.push_back((sx + sy + sz) % 2 ? Triangle{ a, c, b } : Triangle{ a, b, c });
      }
    }
  }
}

// One midpoint subdivision; new vertices are appended, so each level extends the previous one.
void Subdivide(std::vector<Vector>& vertices, std::vector<Triangle>& faces)
{
  std::map<std::pair<int, int>, int> midpoints;
  auto midpoint = [&](int i, int j)
  {
    const auto key = std::make_pair(std::min(i, j), std::max(i, j));
    const auto found = midpoints.find(key);
    if (found != midpoints.end())
    {
      return found->second;
    }
    const Vector& p = vertices[i];
    const Vector& q = vertices[j];
    vertices.push_back(Normalized({ p[0] + q[0], p[1] + q[1], p[2] + q[2] }));
    midpoints[key] = static_cast<int>(vertices.size()) - 1;
    return static_cast<int>(vertices.size()) - 1;
  };
  std::vector<Triangle> finer;
  for (const Triangle& f : faces)
  {
    const int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
    finer.push_back({ f[0], ab, ca });
    finer.push_back({ ab, f[1], bc });
    finer.push_back({ ca, bc, f[2] });
    finer.push_back({ ab, bc, ca });
  }
  faces.swap(finer);
}

// The solid angle of each vertex's Voronoi cell: bounded by the circumcentres of the triangles
// around it, in angular order.
std::vector<double> VoronoiAreas(
  const std::vector<Vector>& vertices, const std::vector<Triangle>& faces)
{
  std::vector<Vector> centres;
  std::vector<std::vector<int>> around(vertices.size());
  for (size_t t = 0; t < faces.size(); ++t)
  {
    const Vector& a = vertices[faces[t][0]];
    const Vector& b = vertices[faces[t][1]];
    const Vector& c = vertices[faces[t][2]];
    centres.push_back(Normalized(
      Cross({ b[0] - a[0], b[1] - a[1], b[2] - a[2] }, { c[0] - a[0], c[1] - a[1], c[2] - a[2] })));
    for (int corner : faces[t])
    {
      around[corner].push_back(static_cast<int>(t));
    }
  }
  std::vector<double> areas;
  for (size_t v = 0; v < vertices.size(); ++v)
  {
    const Vector& d = vertices[v];
    const Vector helper = std::abs(d[0]) < 0.9 ? Vector{ 1, 0, 0 } : Vector{ 0, 1, 0 };
    const Vector t1 = Normalized(Cross(d, helper));
    const Vector t2 = Cross(d, t1);
    std::vector<std::pair<double, int>> ordered;
    for (int t : around[v])
    {
      ordered.emplace_back(std::atan2(Dot(centres[t], t2), Dot(centres[t], t1)), t);
    }
    std::sort(ordered.begin(), ordered.end());
    double area = 0.0;
    for (size_t k = 0; k < ordered.size(); ++k)
    {
      area += SphericalTriangleArea(
        d, centres[ordered[k].second], centres[ordered[(k + 1) % ordered.size()].second]);
    }
    areas.push_back(area);
  }
  return areas;
}
}

//------------------------------------------------------------------------------
int vtkLightSphere::GetNumberOfDirections(int level)
{
  level = std::min(std::max(level, 0), MaximumLevel);
  return 4 * (1 << (2 * level)) + 2;
}

//------------------------------------------------------------------------------
void vtkLightSphere::Build()
{
  if (this->BuiltLevel == this->Level)
  {
    return;
  }
  std::vector<Vector> vertices;
  std::vector<Triangle> faces;
  Octahedron(vertices, faces);
  for (int level = 0; level < this->Level; ++level)
  {
    Subdivide(vertices, faces);
  }
  this->Directions.clear();
  for (const Vector& d : vertices)
  {
    this->Directions.insert(this->Directions.end(), d.begin(), d.end());
  }
  this->Weights = VoronoiAreas(vertices, faces);
  this->BuiltLevel = this->Level;
}

//------------------------------------------------------------------------------
bool vtkLightSphere::GetDirection(int j, double direction[3])
{
  this->Build();
  if (j < 0 || j >= static_cast<int>(this->Weights.size()))
  {
    return false;
  }
  std::copy(&this->Directions[3 * j], &this->Directions[3 * j] + 3, direction);
  return true;
}

//------------------------------------------------------------------------------
double vtkLightSphere::GetWeight(int j)
{
  this->Build();
  return j >= 0 && j < static_cast<int>(this->Weights.size()) ? this->Weights[j] : 0.0;
}

//------------------------------------------------------------------------------
vtkDoubleArray* vtkLightSphere::NewDirections()
{
  this->Build();
  vtkDoubleArray* directions = vtkDoubleArray::New();
  directions->SetName("LightDirections");
  directions->SetNumberOfComponents(3);
  directions->SetNumberOfTuples(static_cast<vtkIdType>(this->Weights.size()));
  std::copy(this->Directions.begin(), this->Directions.end(), directions->GetPointer(0));
  return directions;
}

//------------------------------------------------------------------------------
vtkDoubleArray* vtkLightSphere::NewWeights()
{
  this->Build();
  vtkDoubleArray* weights = vtkDoubleArray::New();
  weights->SetName("LightWeights");
  weights->SetNumberOfTuples(static_cast<vtkIdType>(this->Weights.size()));
  std::copy(this->Weights.begin(), this->Weights.end(), weights->GetPointer(0));
  return weights;
}

//------------------------------------------------------------------------------
void vtkLightSphere::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Level: " << this->Level << "\n";
  os << indent << "NumberOfDirections: " << GetNumberOfDirections(this->Level) << "\n";
}
