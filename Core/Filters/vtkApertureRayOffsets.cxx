/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkApertureRayOffsets.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkApertureRayOffsets.h"

#include "vtkApertureMemory.h"
#include "vtkApertureSurface.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <vector>

namespace
{
// Mean edge lengths of the vertices (the scale of the offsets).
std::vector<float> EdgeLengths(const vtkApertureSurface& surface)
{
  const vtkIdType vertices = surface.GetNumberOfVertices();
  std::vector<float> sum;
  std::vector<std::uint32_t> count;
  vtkApertureMemory::Assign(sum, vertices);
  vtkApertureMemory::Assign(count, vertices);
  for (size_t t = 0; t < surface.Triangles.size(); t += 3)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t a = surface.Triangles[t + k];
      const std::uint32_t b = surface.Triangles[t + (k + 1) % 3];
      const float* p = &surface.Vertices[3 * size_t(a)];
      const float* q = &surface.Vertices[3 * size_t(b)];
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
}

//------------------------------------------------------------------------------
void vtkApertureRayOffsets::Set(vtkApertureSurface& surface, double rayOffset)
{
  const std::vector<float> edges = EdgeLengths(surface);
  const vtkIdType n = surface.GetNumberOfPoints();
  // The mean of each point's triangles' centroids, relative to the point.
  std::vector<double> middle;
  std::vector<std::uint32_t> count;
  vtkApertureMemory::Assign(middle, 3 * n);
  vtkApertureMemory::Assign(count, n);
  for (size_t t = 0; t < surface.Triangles.size(); t += 3)
  {
    double centroid[3] = { 0.0, 0.0, 0.0 };
    for (int k = 0; k < 3; ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        centroid[c] += surface.Vertices[3 * size_t(surface.Triangles[t + k]) + c] / 3.0;
      }
    }
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t point = surface.CornerPoints[t + k];
      const float* p = surface.GetPosition(point);
      for (int c = 0; c < 3; ++c)
      {
        middle[3 * size_t(point) + c] += centroid[c] - p[c];
      }
      ++count[point];
    }
  }
  vtkApertureMemory::Assign(surface.Offset, n);
  vtkApertureMemory::Assign(surface.Start, 3 * n);
  vtkApertureMemory::Assign(surface.Near, n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const float* p = surface.GetPosition(i);
    const float* normal = surface.GetNormal(i);
    const float magnitude = std::max({ std::abs(p[0]), std::abs(p[1]), std::abs(p[2]) });
    const float edge = edges[surface.PointVertex[i]];
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
    surface.Offset[i] = lift;
    surface.Near[i] = std::max(NearZone * lift, ContactTolerance * edge);
    for (int c = 0; c < 3; ++c)
    {
      surface.Start[3 * i + c] = static_cast<float>(p[c] + lift * normal[c] + limit * shift[c]);
    }
  }
}
