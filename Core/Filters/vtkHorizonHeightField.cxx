/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkHorizonHeightField.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkHorizonHeightField.h"

#include "vtkApertureMemory.h"
#include "vtkApertureValidMask.h"
#include "vtkHorizonApertures.h"
#include "vtkHorizonLighting.h"

#include "vtkApertureSMP.h"
#include "vtkArrayDispatch.h"
#include "vtkDataArray.h"
#include "vtkDataArrayRange.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <locale>
#include <new>
#include <sstream>
#include <vector>

namespace
{
// An array of `tuples` tuples in `unit`, or nullptr when it cannot be allocated. Huge pages
// where the sweeps add to it texel by texel along their lines (fewer TLB misses); not for the
// horizons, written whole cache lines at a time, where the huge pages' first touch only cost
// (BenchmarkTerrain --section 6: 1.20 times the sweep without them, 1.12-1.15 with small pages).
vtkSmartPointer<vtkFloatArray> NewArray(
  const char* name, int components, vtkIdType tuples, const char* unit, bool hugePages = true)
{
  auto array = vtkSmartPointer<vtkFloatArray>::New();
  array->SetName(name);
  array->GetInformation()->Set(vtkDataArray::UNITS_LABEL(), unit);
  array->SetNumberOfComponents(components);
  if (!array->Allocate(components * tuples))
  {
    return nullptr;
  }
  array->SetNumberOfTuples(tuples);
  if (hugePages)
  {
    vtkApertureMemory::AdviseHugePages(array->GetPointer(0), sizeof(float) * components * tuples);
  }
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

// Copies component 0 of an array over the texels of `window` (i0, i1, j0, j1), i fastest, as
// `value(v)` gives them, in the array's own type.
template <typename T, typename Convert>
struct CopyWindowWorker
{
  vtkImageData* Image;
  const int* Window;
  std::vector<T>& Out;
  Convert Value;

  template <typename Array>
  void operator()(Array* array) const
  {
    const auto values = vtk::DataArrayTupleRange(array);
    const vtkIdType nx = this->Window[1] - this->Window[0] + 1;
    const vtkIdType ny = this->Window[3] - this->Window[2] + 1;
    this->Out.resize(nx * ny);
    vtkApertureSMP::For(0, ny,
      [&](vtkIdType first, vtkIdType last)
      {
        for (vtkIdType r = first; r < last; ++r)
        {
          int ijk[3] = { this->Window[0], this->Window[2] + static_cast<int>(r),
            this->Image->GetExtent()[4] };
          const vtkIdType start = this->Image->ComputePointId(ijk);
          for (vtkIdType i = 0; i < nx; ++i)
          {
            this->Out[r * nx + i] = this->Value(static_cast<double>(values[start + i][0]));
          }
        }
      });
  }
};

template <typename T, typename Convert>
void CopyWindow(
  vtkImageData* image, vtkDataArray* array, const int window[4], std::vector<T>& out, Convert value)
{
  const CopyWindowWorker<T, Convert> worker{ image, window, out, value };
  if (!vtkArrayDispatch::Dispatch::Execute(array, worker))
  {
    worker(array);
  }
}

// Whether `window` is the whole of the image's rows and columns.
bool WholeImage(vtkImageData* image, const int window[4])
{
  const int* extent = image->GetExtent();
  return window[0] == extent[0] && window[1] == extent[1] && window[2] == extent[2] &&
    window[3] == extent[3];
}

// The heights the sweeps read (scaled) and their valid flags (nullptr without a mask): the
// arrays themselves when they cover the window as the sweeps read them (float heights, unscaled;
// an unsigned char mask), else copies in `z` and `valid`, read in the arrays' own types.
void WindowHeights(vtkImageData* image, vtkDataArray* heights, double scale, const int window[4],
  std::vector<float>& z, std::vector<unsigned char>& valid, vtkHorizonApertures::Grid& grid)
{
  const bool whole = WholeImage(image, window);
  auto* floats = vtkFloatArray::SafeDownCast(heights);
  if (whole && floats && floats->GetNumberOfComponents() == 1 && scale == 1.0)
  {
    grid.Heights = floats->GetPointer(0);
  }
  else
  {
    CopyWindow(
      image, heights, window, z, [scale](double h) { return static_cast<float>(h * scale); });
    grid.Heights = z.data();
  }
  vtkDataArray* mask = image->GetPointData()->GetArray(vtkApertureValidMask::Name());
  auto* bytes = vtkUnsignedCharArray::SafeDownCast(mask);
  grid.Valid = nullptr;
  if (whole && bytes && bytes->GetNumberOfComponents() == 1)
  {
    grid.Valid = bytes->GetPointer(0);
  }
  else if (mask)
  {
    CopyWindow(image, mask, window, valid,
      [](double m) { return static_cast<unsigned char>(m != 0.0 ? 1 : 0); });
    grid.Valid = valid.data();
  }
}

// Turns n unit vectors from the grid frame into world coordinates.
void ToWorld(vtkImageData* image, float* vectors, vtkIdType n)
{
  double axes[3][3];
  if (!WorldAxes(image, axes))
  {
    return;
  }
  vtkApertureSMP::For(0, n,
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

// The texels the sweeps read for `extent`: grown by the search radius, within the image (which
// may hold more than the pipeline asked for); false, with `error`, for an extent outside it.
bool SweepWindow(vtkImageData* image, const int extent[6], double maximumDistance, int fill,
  int window[4], std::string& error)
{
  const int* whole = image->GetExtent();
  const int halo = vtkHorizonHeightField::Halo(maximumDistance, image->GetSpacing(), fill);
  for (int k = 0; k < 4; ++k)
  {
    const int grown = k % 2 ? extent[k] + halo : extent[k] - halo;
    window[k] = halo < 0 ? whole[k] : k % 2 ? std::min(whole[k], grown) : std::max(whole[k], grown);
  }
  if (window[1] < window[0] || window[3] < window[2] || extent[0] < whole[0] ||
    extent[1] > whole[1] || extent[2] < whole[2] || extent[3] > whole[3])
  {
    error = "The extent asked for lies outside the image.";
    return false;
  }
  return true;
}

// Copies of the window's heights and masks, where the sweeps need them.
struct Storage
{
  std::vector<float> Z;
  std::vector<unsigned char> Valid, Receives;
};

// The nearest valid texel from t along (di, dj) within `distance` steps: its height and steps;
// false without one.
bool NearestValid(const std::vector<float>& z, const std::vector<unsigned char>& valid,
  vtkIdType nx, vtkIdType ny, vtkIdType t, const int way[2], int distance, double& height,
  int& steps)
{
  const vtkIdType i = t % nx, j = t / nx;
  for (steps = 1; steps <= distance; ++steps)
  {
    const vtkIdType a = i + steps * way[0], b = j + steps * way[1];
    if (a < 0 || a >= nx || b < 0 || b >= ny)
    {
      return false;
    }
    if (valid[a + b * nx])
    {
      height = z[a + b * nx];
      return true;
    }
  }
  return false;
}

// A height for no-data texel t from the valid texels within `distance` steps along the four
// grid lines through it (rows, columns, diagonals): on each line with a valid texel on both
// sides, the linear interpolation between them (exact on planes), weighted by 1/span²; with
// none, the one-sided nearest texels weighted by 1/d². NaN where no valid texel is in reach.
double FillValue(const std::vector<float>& z, const std::vector<unsigned char>& valid, vtkIdType nx,
  vtkIdType ny, vtkIdType t, int distance)
{
  static const int lines[4][2] = { { 1, 0 }, { 0, 1 }, { 1, 1 }, { 1, -1 } };
  double sums[2] = { 0.0, 0.0 }, weights[2] = { 0.0, 0.0 }; // two-sided, one-sided
  for (const auto& line : lines)
  {
    const int back[2] = { -line[0], -line[1] };
    const double length = std::sqrt(double(line[0] * line[0] + line[1] * line[1]));
    double h[2];
    int d[2];
    const bool found[2] = { NearestValid(z, valid, nx, ny, t, line, distance, h[0], d[0]),
      NearestValid(z, valid, nx, ny, t, back, distance, h[1], d[1]) };
    if (found[0] && found[1])
    {
      const double w = 1.0 / (length * length * (d[0] + d[1]) * (d[0] + d[1]));
      sums[0] += w * (h[0] * d[1] + h[1] * d[0]) / (d[0] + d[1]);
      weights[0] += w;
    }
    for (int k = 0; k < 2; ++k)
    {
      const double w = found[k] ? 1.0 / (length * length * d[k] * d[k]) : 0.0;
      sums[1] += w * (found[k] ? h[k] : 0.0);
      weights[1] += w;
    }
  }
  const int use = weights[0] > 0.0 ? 0 : 1;
  return weights[use] > 0.0 ? sums[use] / weights[use] : std::numeric_limits<double>::quiet_NaN();
}

// No-data as the settings take it (see Settings::NoDataAs), on copies of the window's heights
// and masks: walls are valid texels that do not receive; filled texels valid ones.
void TreatNoData(
  const vtkHorizonHeightField::Settings& settings, Storage& s, vtkHorizonApertures::Grid& grid)
{
  if (settings.NoDataAs == vtkHorizonHeightField::Settings::Open)
  {
    return; // the sweeps read no-data themselves: nothing to copy
  }
  const vtkIdType n = grid.Nx * grid.Ny;
  std::vector<unsigned char> valid(n);
  double highest = -std::numeric_limits<double>::infinity();
  for (vtkIdType t = 0; t < n; ++t)
  {
    valid[t] = (!grid.Valid || grid.Valid[t]) && std::isfinite(grid.Heights[t]);
    highest = valid[t] ? std::max(highest, double(grid.Heights[t])) : highest;
  }
  if (std::count(valid.begin(), valid.end(), 0) == 0)
  {
    return;
  }
  if (grid.Heights != s.Z.data())
  {
    s.Z.assign(grid.Heights, grid.Heights + n);
  }
  const double wall = std::isfinite(settings.WallHeight) ? settings.WallHeight : highest;
  vtkApertureSMP::For(0, n,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType t = first; t < last; ++t)
      {
        s.Z[t] = valid[t] ? s.Z[t]
          : settings.NoDataAs == vtkHorizonHeightField::Settings::Wall
          ? static_cast<float>(wall)
          : static_cast<float>(FillValue(s.Z, valid, grid.Nx, grid.Ny, t, settings.FillDistance));
      }
    });
  s.Valid.resize(n); // a fill can leave holes wider than its reach
  std::transform(s.Z.begin(), s.Z.end(), s.Valid.begin(),
    [](float z) { return static_cast<unsigned char>(std::isfinite(z)); });
  s.Receives = settings.NoDataAs == vtkHorizonHeightField::Settings::Wall ? valid : s.Valid;
  grid.Heights = s.Z.data();
  grid.Valid = s.Valid.data();
  grid.Receives = s.Receives.data();
}

// The sweeps' grid of `window` (copies in `storage` where needed), computing `extent`.
bool MakeGrid(vtkImageData* image, vtkDataArray* heights, const int extent[6], const int window[4],
  const vtkHorizonHeightField::Settings& settings, Storage& storage,
  vtkHorizonApertures::Grid& grid, std::string& error)
{
  grid.Nx = window[1] - window[0] + 1;
  grid.Ny = window[3] - window[2] + 1;
  try
  {
    WindowHeights(image, heights, settings.HeightScale, window, storage.Z, storage.Valid, grid);
    TreatNoData(settings, storage, grid);
  }
  catch (const std::bad_alloc&)
  {
    error = "There is not enough memory for the " + std::to_string(grid.Nx) + " x " +
      std::to_string(grid.Ny) + " texels' heights; set a MaximumDistance and stream in tiles.";
    return false;
  }
  grid.Dx = std::abs(image->GetSpacing()[0]);
  grid.Dy = std::abs(image->GetSpacing()[1]);
  grid.Sectors = settings.Sectors;
  grid.SectorRotation = vtkMath::RadiansFromDegrees(settings.SectorRotation);
  grid.EarthRadius = settings.EarthRadius;
  grid.MaximumDistance = settings.MaximumDistance;
  const vtkIdType local[4] = { extent[0] - window[0], extent[1] - window[0], extent[2] - window[2],
    extent[3] - window[2] };
  std::copy(local, local + 4, grid.OutputExtent);
  grid.Origin[0] = window[0];
  grid.Origin[1] = window[2];
  return true;
}

// A sector's component name: "Az" and the azimuth of its middle in degrees, counter-clockwise
// from the grid's i axis (east on a north-up DEM), as GeoTIFF band names show it.
std::string SectorName(int k, int sectors, double rotation)
{
  std::ostringstream name;
  name.imbue(std::locale::classic());
  name << "Az" << std::setprecision(6) << vtkHorizonLighting::SectorAzimuth(k, sectors, rotation);
  return name.str();
}

// The output arrays of Compute(), allocated, filled through Buffers() and added to the output.
struct Results
{
  vtkSmartPointer<vtkFloatArray> Bent, Radius, Normals, Occlusion, Horizons;
  vtkSmartPointer<vtkFloatArray> Products[4]; // sky-view factors, openness
  vtkNew<vtkUnsignedCharArray> Mask;

  // Normals only when they are to be added: the sweeps can do without.
  bool Allocate(const vtkHorizonHeightField::Settings& settings, bool normals, vtkIdType texels)
  {
    this->Bent = NewArray(settings.BentNormalName, 3, texels, "1");
    this->Radius = NewArray(settings.RadiusName, 1, texels, "radian");
    bool allocated = this->Bent && this->Radius;
    auto optional =
      [&](bool wanted, const char* name, int components, const char* unit, bool hugePages = true)
    {
      auto array = wanted ? NewArray(name, components, texels, unit, hugePages) : nullptr;
      allocated = allocated && (!wanted || array);
      return array;
    };
    this->Normals = optional(normals, "Normals", 3, "1");
    this->Occlusion = optional(settings.AmbientOcclusion, settings.OcclusionName, 1, "1");
    this->Horizons =
      optional(settings.Horizons, settings.HorizonName, settings.Sectors, "radian", false);
    this->Products[0] = optional(settings.SkyViewFactor, "SkyViewFactor", 1, "1");
    this->Products[1] = optional(settings.SkyViewFactorCosine, "SkyViewFactorCosine", 1, "1");
    this->Products[2] = optional(settings.PositiveOpenness, "PositiveOpenness", 1, "degree");
    this->Products[3] = optional(settings.NegativeOpenness, "NegativeOpenness", 1, "degree");
    for (int k = 0; this->Horizons && k < settings.Sectors; ++k)
    {
      this->Horizons->SetComponentName(
        k, SectorName(k, settings.Sectors, settings.SectorRotation).c_str());
    }
    this->Mask->SetName(vtkApertureValidMask::Name());
    if (!allocated || !this->Mask->Allocate(texels))
    {
      return false;
    }
    this->Mask->SetNumberOfTuples(texels);
    return true;
  }

  vtkHorizonApertures::Buffers Buffers() const
  {
    auto pointer = [](vtkFloatArray* a) { return a ? a->GetPointer(0) : nullptr; };
    vtkHorizonApertures::Buffers buffers{ pointer(this->Bent), pointer(this->Radius),
      pointer(this->Occlusion), pointer(this->Normals), this->Mask->GetPointer(0),
      pointer(this->Horizons) };
    buffers.SkyViewFactor = pointer(this->Products[0]);
    buffers.SkyViewFactorCosine = pointer(this->Products[1]);
    buffers.PositiveOpenness = pointer(this->Products[2]);
    buffers.NegativeOpenness = pointer(this->Products[3]);
    return buffers;
  }

  // Directions to world coordinates, arrays into `output`; returns the no-data texels.
  vtkIdType AddTo(vtkImageData* image, vtkPointData* output)
  {
    const vtkIdType texels = this->Radius->GetNumberOfTuples();
    ToWorld(image, this->Bent->GetPointer(0), texels);
    output->AddArray(this->Bent);
    output->AddArray(this->Radius);
    if (this->Occlusion)
    {
      output->AddArray(this->Occlusion);
    }
    if (this->Horizons)
    {
      output->AddArray(this->Horizons);
    }
    for (const auto& product : this->Products)
    {
      if (product)
      {
        output->AddArray(product);
      }
    }
    if (this->Normals)
    {
      ToWorld(image, this->Normals->GetPointer(0), texels);
      output->SetNormals(this->Normals);
    }
    const unsigned char* mask = this->Mask->GetPointer(0);
    const vtkIdType noData = texels - std::count(mask, mask + texels, 1);
    if (noData > 0 || output->GetArray(vtkApertureValidMask::Name())) // a filled input's holes
    {
      output->AddArray(this->Mask);
    }
    return noData;
  }
};
}

//------------------------------------------------------------------------------
vtkIdType vtkHorizonHeightField::Compute(vtkImageData* image, vtkDataArray* heights,
  const int extent[6], const Settings& settings, vtkPointData* output, std::string& error,
  const std::function<bool(double fraction)>& progress)
{
  int window[4];
  Storage storage;
  vtkHorizonApertures::Grid grid;
  vtkIdType nx = 0, ny = 0;
  const int fill = settings.NoDataAs == Settings::Fill ? settings.FillDistance : 0;
  if (!SweepWindow(image, extent, settings.MaximumDistance, fill, window, error) ||
    !MakeGrid(image, heights, extent, window, settings, storage, grid, error) ||
    !vtkHorizonApertures::GetOutputSize(grid, nx, ny, error))
  {
    return -1;
  }
  Results results; // the normals used, unless the input brings its own
  if (!results.Allocate(settings, settings.Normals && !output->GetNormals(), nx * ny))
  {
    error = "There is not enough memory for the apertures of " + std::to_string(nx * ny) +
      " texels; set a MaximumDistance and stream in tiles.";
    return -1;
  }
  if (!vtkHorizonApertures::Compute(grid, results.Buffers(), error, progress))
  {
    return -1;
  }
  return results.AddTo(image, output);
}

//------------------------------------------------------------------------------
int vtkHorizonHeightField::Halo(double maximumDistance, const double spacing[3], int fill)
{
  const double finer = std::min(std::abs(spacing[0]), std::abs(spacing[1]));
  const double texels = maximumDistance / finer;
  if (!(texels < 1e8)) // no radius, or one wider than any grid
  {
    return -1;
  }
  return static_cast<int>(std::ceil(texels)) + 2 + std::max(fill, 0);
}
