/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkHorizonHeightField.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkHorizonHeightField.h"

#include "vtkHorizonApertures.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <vector>

namespace
{
// An array of `tuples` tuples, or nullptr when it cannot be allocated.
vtkSmartPointer<vtkFloatArray> NewArray(const char* name, int components, vtkIdType tuples)
{
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  if (!array->Allocate(components * tuples))
  {
    return nullptr;
  }
  array->SetNumberOfTuples(tuples);
  return array;
}

// The grid frame's axes in world coordinates: x along i, y along j, z along the third axis.
// False when they are the world's own.
bool WorldAxes(vtkImageData* image, double axes[3][3])
{
  const double* d = image->GetDirectionMatrix()->GetData();
  const double* spacing = image->GetSpacing();
  bool identity = true;
  for (int a = 0; a < 3; ++a)
  {
    const double sign = a < 2 && spacing[a] < 0.0 ? -1.0 : 1.0;
    for (int r = 0; r < 3; ++r)
    {
      axes[a][r] = sign * d[3 * r + a];
      identity = identity && axes[a][r] == (r == a ? 1.0 : 0.0);
    }
  }
  return !identity;
}

// The scaled heights and the valid flags (empty without a mask) of the texels in `window`
// (i0, i1, j0, j1), i fastest.
void CopyWindow(vtkImageData* image, vtkDataArray* heights, double scale, const int window[4],
  std::vector<float>& z, std::vector<unsigned char>& valid)
{
  const vtkIdType nx = window[1] - window[0] + 1, ny = window[3] - window[2] + 1;
  vtkDataArray* mask = image->GetPointData()->GetArray(vtkHorizonHeightField::ValidMaskName());
  z.resize(nx * ny);
  valid.resize(mask ? nx * ny : 0);
  vtkSMPTools::For(0, ny,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType r = first; r < last; ++r)
      {
        int ijk[3] = { window[0], window[2] + static_cast<int>(r), image->GetExtent()[4] };
        const vtkIdType start = image->ComputePointId(ijk);
        for (vtkIdType i = 0; i < nx; ++i)
        {
          z[r * nx + i] = static_cast<float>(heights->GetComponent(start + i, 0) * scale);
          if (mask)
          {
            valid[r * nx + i] = mask->GetComponent(start + i, 0) != 0.0 ? 1 : 0;
          }
        }
      }
    });
}

// Turns n unit vectors from the grid frame into world coordinates.
void ToWorld(vtkImageData* image, float* vectors, vtkIdType n)
{
  double axes[3][3];
  if (!WorldAxes(image, axes))
  {
    return;
  }
  vtkSMPTools::For(0, n,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType i = first; i < last; ++i)
      {
        float* v = vectors + 3 * i;
        const double local[3] = { v[0], v[1], v[2] };
        for (int r = 0; r < 3; ++r)
        {
          v[r] = static_cast<float>(
            local[0] * axes[0][r] + local[1] * axes[1][r] + local[2] * axes[2][r]);
        }
      }
    });
}
}

//------------------------------------------------------------------------------
vtkIdType vtkHorizonHeightField::Compute(vtkImageData* image, vtkDataArray* heights,
  const int extent[6], const Settings& settings, vtkPointData* output, std::string& error,
  const std::function<bool(double fraction)>& progress)
{
  // The texels that can matter: the extent grown by the search radius, within the image (which
  // may hold more than the pipeline asked for).
  const int* whole = image->GetExtent();
  const int halo = Halo(settings.MaximumDistance, image->GetSpacing());
  int window[4];
  for (int k = 0; k < 4; ++k)
  {
    const int grown = k % 2 ? extent[k] + halo : extent[k] - halo;
    window[k] = halo < 0 ? whole[k] : k % 2 ? std::min(whole[k], grown) : std::max(whole[k], grown);
  }
  vtkHorizonApertures::Grid grid;
  grid.Nx = window[1] - window[0] + 1;
  grid.Ny = window[3] - window[2] + 1;
  if (grid.Nx < 1 || grid.Ny < 1 || extent[0] < whole[0] || extent[1] > whole[1] ||
    extent[2] < whole[2] || extent[3] > whole[3])
  {
    error = "The extent asked for lies outside the image.";
    return -1;
  }
  std::vector<float> z;
  std::vector<unsigned char> valid;
  try
  {
    CopyWindow(image, heights, settings.HeightScale, window, z, valid);
  }
  catch (const std::bad_alloc&)
  {
    error = "There is not enough memory for the " + std::to_string(grid.Nx) + " x " +
      std::to_string(grid.Ny) + " texels' heights; set a MaximumDistance and stream in tiles.";
    return -1;
  }
  grid.Heights = z.data();
  grid.Valid = valid.empty() ? nullptr : valid.data();
  grid.Dx = std::abs(image->GetSpacing()[0]);
  grid.Dy = std::abs(image->GetSpacing()[1]);
  grid.Sectors = settings.Sectors;
  grid.MaximumDistance = settings.MaximumDistance;
  const vtkIdType local[4] = { extent[0] - window[0], extent[1] - window[0], extent[2] - window[2],
    extent[3] - window[2] };
  std::copy(local, local + 4, grid.OutputExtent);
  grid.Origin[0] = window[0];
  grid.Origin[1] = window[2];

  vtkIdType nx = 0, ny = 0;
  if (!vtkHorizonApertures::GetOutputSize(grid, nx, ny, error))
  {
    return -1;
  }
  const vtkIdType texels = nx * ny;
  auto bent = NewArray(settings.BentNormalName, 3, texels);
  auto radius = NewArray(settings.RadiusName, 1, texels);
  auto normals = NewArray("Normals", 3, texels);
  vtkSmartPointer<vtkFloatArray> occlusion =
    settings.AmbientOcclusion ? NewArray(settings.OcclusionName, 1, texels) : nullptr;
  vtkNew<vtkUnsignedCharArray> mask;
  mask->SetName(ValidMaskName());
  if (!bent || !radius || !normals || (settings.AmbientOcclusion && !occlusion) ||
    !mask->Allocate(texels))
  {
    error = "There is not enough memory for the apertures of " + std::to_string(texels) +
      " texels; set a MaximumDistance and stream in tiles.";
    return -1;
  }
  mask->SetNumberOfTuples(texels);
  const vtkHorizonApertures::Buffers buffers{ bent->GetPointer(0), radius->GetPointer(0),
    occlusion ? occlusion->GetPointer(0) : nullptr, normals->GetPointer(0), mask->GetPointer(0) };
  if (!vtkHorizonApertures::Compute(grid, buffers, error, progress))
  {
    return -1;
  }
  ToWorld(image, bent->GetPointer(0), texels);
  ToWorld(image, normals->GetPointer(0), texels);
  output->AddArray(bent);
  output->AddArray(radius);
  if (occlusion)
  {
    output->AddArray(occlusion);
  }
  if (!output->GetNormals())
  {
    output->SetNormals(normals); // the normals used, unless the input brings its own
  }
  const vtkIdType noData =
    texels - std::count(mask->GetPointer(0), mask->GetPointer(0) + texels, 1);
  if (noData > 0)
  {
    output->AddArray(mask);
  }
  return noData;
}

//------------------------------------------------------------------------------
int vtkHorizonHeightField::Halo(double maximumDistance, const double spacing[3])
{
  const double finer = std::min(std::abs(spacing[0]), std::abs(spacing[1]));
  const double texels = maximumDistance / finer;
  if (!(texels < 1e8)) // no radius, or one wider than any grid
  {
    return -1;
  }
  return static_cast<int>(std::ceil(texels)) + 2;
}
