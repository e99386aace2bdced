/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkEnvironmentMap.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkEnvironmentMap.h"

#include "vtkApertureSMP.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkEnvironmentMap);

namespace
{
constexpr double Pi = vtkMath::Pi();
// The working image.
constexpr int WorkingWidth = 256;
constexpr int WorkingHeight = 128;

// North, east and up of each up axis (see the class documentation).
void Frame(int up, double north[3], double east[3], double zenith[3])
{
  static const double frames[3][3][3] = { { { 0, 0, 1 }, { 0, 1, 0 }, { 1, 0, 0 } },
    { { 0, 0, -1 }, { 1, 0, 0 }, { 0, 1, 0 } }, { { 0, 1, 0 }, { 1, 0, 0 }, { 0, 0, 1 } } };
  for (int k = 0; k < 3; ++k)
  {
    north[k] = frames[up][0][k];
    east[k] = frames[up][1][k];
    zenith[k] = frames[up][2][k];
  }
}

// A bilinear sample of a latitude-longitude grid of w x h pixels at pixel coordinates (x, y),
// pixel centres at integers, wrapping around in x and clamped in y; at(i, j) is pixel (i, j).
template <typename At>
double SampleLatLong(const At& at, int w, int h, double x, double y)
{
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  const double fx = x - x0, fy = y - y0;
  auto pixel = [&](int i, int j) { return at(((i % w) + w) % w, std::min(h - 1, std::max(0, j))); };
  return (1 - fy) * ((1 - fx) * pixel(x0, y0) + fx * pixel(x0 + 1, y0)) +
    fy * ((1 - fx) * pixel(x0, y0 + 1) + fx * pixel(x0 + 1, y0 + 1));
}

// The nine real spherical harmonics of order 2 at a unit direction.
void Harmonics(const double d[3], double y[9])
{
  const double x = d[0], yy = d[1], z = d[2];
  y[0] = 0.28209479177387814;
  y[1] = 0.4886025119029199 * yy;
  y[2] = 0.4886025119029199 * z;
  y[3] = 0.4886025119029199 * x;
  y[4] = 1.0925484305920792 * x * yy;
  y[5] = 1.0925484305920792 * yy * z;
  y[6] = 0.31539156525252005 * (3.0 * z * z - 1.0);
  y[7] = 1.0925484305920792 * x * z;
  y[8] = 0.5462742152960396 * (x * x - yy * yy);
}
}

//------------------------------------------------------------------------------
vtkEnvironmentMap::vtkEnvironmentMap()
{
  this->FilterTime.Modified();
  std::fill(&this->SH[0][0], &this->SH[0][0] + 27, 0.0);
}

//------------------------------------------------------------------------------
vtkEnvironmentMap::~vtkEnvironmentMap()
{
  this->SetImage(nullptr);
}

//------------------------------------------------------------------------------
void vtkEnvironmentMap::SetImage(vtkImageData* image)
{
  if (this->Image != image)
  {
    vtkImageData* previous = this->Image;
    this->Image = image;
    if (image)
    {
      image->Register(this);
    }
    if (previous)
    {
      previous->UnRegister(this);
    }
    this->FilterTime.Modified();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkEnvironmentMap::SetBlurAngle(double sigma)
{
  sigma = std::min(std::max(sigma, 0.0), 1.0);
  if (this->BlurAngle != sigma)
  {
    this->BlurAngle = sigma;
    this->FilterTime.Modified();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkEnvironmentMap::SetOrientation(const double rotation[9])
{
  if (!std::equal(rotation, rotation + 9, this->Orientation))
  {
    std::copy(rotation, rotation + 9, this->Orientation);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkEnvironmentMap::GetOrientation(double rotation[9])
{
  std::copy(this->Orientation, this->Orientation + 9, rotation);
}

//------------------------------------------------------------------------------
void vtkEnvironmentMap::Local(double u, double v, double d[3])
{
  const double phi = 2.0 * Pi * (u - 0.5), theta = Pi * (v - 0.5);
  d[0] = std::cos(theta) * std::cos(phi);
  d[1] = std::cos(theta) * std::sin(phi);
  d[2] = std::sin(theta);
}

//------------------------------------------------------------------------------
void vtkEnvironmentMap::LocalToImagePoint(const double d[3], double& u, double& v)
{
  u = std::atan2(d[1], d[0]) / (2.0 * Pi) + 0.5;
  v = std::asin(std::min(1.0, std::max(-1.0, d[2]))) / Pi + 0.5;
}

//------------------------------------------------------------------------------
void vtkEnvironmentMap::GetWorldToEnvironment(double matrix[9])
{
  // local = O^T Rz(azimuth)^T F^T world, F = [north east up].
  double north[3], east[3], up[3];
  Frame(this->UpAxis, north, east, up);
  const double a = vtkMath::RadiansFromDegrees(this->Azimuth);
  const double c = std::cos(a), s = std::sin(a);
  // Rz^T F^T: rows (c N + s E), (-s N + c E), U.
  double rows[3][3];
  for (int k = 0; k < 3; ++k)
  {
    rows[0][k] = c * north[k] + s * east[k];
    rows[1][k] = -s * north[k] + c * east[k];
    rows[2][k] = up[k];
  }
  for (int i = 0; i < 3; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      // (O^T)_ij = O_ji.
      matrix[3 * i + k] = this->Orientation[0 + i] * rows[0][k] +
        this->Orientation[3 + i] * rows[1][k] + this->Orientation[6 + i] * rows[2][k];
    }
  }
}

//------------------------------------------------------------------------------
void vtkEnvironmentMap::ToLocal(const double world[3], double local[3])
{
  double m[9];
  this->GetWorldToEnvironment(m);
  for (int i = 0; i < 3; ++i)
  {
    local[i] = m[3 * i] * world[0] + m[3 * i + 1] * world[1] + m[3 * i + 2] * world[2];
  }
}

//------------------------------------------------------------------------------
void vtkEnvironmentMap::ToWorld(const double local[3], double world[3])
{
  // The matrix is orthogonal: its transpose goes back.
  double m[9];
  this->GetWorldToEnvironment(m);
  for (int k = 0; k < 3; ++k)
  {
    world[k] = m[k] * local[0] + m[3 + k] * local[1] + m[6 + k] * local[2];
  }
}

//------------------------------------------------------------------------------
void vtkEnvironmentMap::DirectionOf(double u, double v, double direction[3])
{
  double local[3];
  Local(u, v, local);
  this->ToWorld(local, direction);
}

//------------------------------------------------------------------------------
void vtkEnvironmentMap::ImagePointOf(const double direction[3], double& u, double& v)
{
  double local[3];
  this->ToLocal(direction, local);
  LocalToImagePoint(local, u, v);
}

//------------------------------------------------------------------------------
vtkMTimeType vtkEnvironmentMap::GetImageMTime()
{
  vtkDataArray* scalars = this->Image ? this->Image->GetPointData()->GetScalars() : nullptr;
  return std::max(this->FilterTime.GetMTime(),
    this->Image ? std::max(this->Image->GetMTime(), scalars ? scalars->GetMTime() : 0) : 0);
}

//------------------------------------------------------------------------------
void vtkEnvironmentMap::Update()
{
  // GetImageMTime() is at least 1 (the constructor stamps FilterTime), so 0 means never updated.
  const vtkMTimeType time = this->GetImageMTime();
  if (time <= this->WorkingTime.load(std::memory_order_acquire))
  {
    return;
  }
  std::lock_guard<std::mutex> lock(this->UpdateMutex);
  if (time <= this->WorkingTime.load(std::memory_order_relaxed))
  {
    return;
  }
  this->Rebuild();
  this->WorkingTime.store(time, std::memory_order_release);
}

//------------------------------------------------------------------------------
void vtkEnvironmentMap::Rebuild()
{
  const int w = WorkingWidth, h = WorkingHeight;
  this->Working.assign(static_cast<size_t>(w) * h * 3, 0.0f);
  std::fill(&this->SH[0][0], &this->SH[0][0] + 27, 0.0);
  if (this->PixelDirections.empty())
  {
    this->RowSolidAngle.resize(h);
    for (int j = 0; j < h; ++j)
    {
      this->RowSolidAngle[j] = (2.0 * Pi / w) *
        (std::sin(Pi * ((j + 1.0) / h - 0.5)) - std::sin(Pi * (double(j) / h - 0.5)));
    }
    this->PixelDirections.resize(static_cast<size_t>(w) * h * 3);
    for (int p = 0; p < w * h; ++p)
    {
      Local((p % w + 0.5) / w, (p / w + 0.5) / h, &this->PixelDirections[3 * p]);
    }
  }
  if (this->Resample())
  {
    this->Blur();
    this->ProjectHarmonics();
  }
}

//------------------------------------------------------------------------------
// The mean of the input pixels whose centres fall in each working pixel (weighted by their rows'
// solid angles), or a bilinear sample where the input is the coarser. False without an image.
bool vtkEnvironmentMap::Resample()
{
  vtkDataArray* scalars = this->Image ? this->Image->GetPointData()->GetScalars() : nullptr;
  int dims[3] = { 0, 0, 0 };
  if (this->Image)
  {
    this->Image->GetDimensions(dims);
  }
  if (!scalars || dims[0] < 1 || dims[1] < 1 || scalars->GetNumberOfTuples() < dims[0] * dims[1])
  {
    return false;
  }
  const int w = WorkingWidth, h = WorkingHeight, components = scalars->GetNumberOfComponents();
  std::vector<double> sums(this->Working.size(), 0.0), weights(static_cast<size_t>(w) * h, 0.0);
  if (dims[0] >= w && dims[1] >= h)
  {
    for (int j = 0; j < dims[1]; ++j)
    {
      const double weight = std::cos(Pi * ((j + 0.5) / dims[1] - 0.5));
      const int row = std::min(h - 1, static_cast<int>((j + 0.5) / dims[1] * h));
      for (int i = 0; i < dims[0]; ++i)
      {
        const int column = std::min(w - 1, static_cast<int>((i + 0.5) / dims[0] * w));
        const size_t p = static_cast<size_t>(row) * w + column;
        const vtkIdType id = static_cast<vtkIdType>(j) * dims[0] + i;
        for (int k = 0; k < 3; ++k)
        {
          sums[3 * p + k] += weight * scalars->GetComponent(id, components >= 3 ? k : 0);
        }
        weights[p] += weight;
      }
    }
  }
  for (size_t p = 0; p < weights.size(); ++p)
  {
    const double x = (p % w + 0.5) / w * dims[0] - 0.5, y = (p / w + 0.5) / h * dims[1] - 0.5;
    for (int k = 0; k < 3; ++k)
    {
      auto input = [&](int i, int j) {
        return scalars->GetComponent(
          static_cast<vtkIdType>(j) * dims[0] + i, components >= 3 ? k : 0);
      };
      this->Working[3 * p + k] =
        static_cast<float>(weights[p] > 0.0 ? sums[3 * p + k] / weights[p]
                                            : SampleLatLong(input, dims[0], dims[1], x, y));
    }
  }
  return true;
}

//------------------------------------------------------------------------------
// The Gaussian blur on the sphere: a von Mises-Fisher kernel exp(kappa (cos t - 1)),
// kappa = 1/sigma^2, which is exp(-t^2 / 2 sigma^2) for small angles t, summed over the true
// angles between pixel directions (so the poles and the seam need nothing special); rows and
// columns beyond 4 sigma contribute nothing measurable and are skipped.
void vtkEnvironmentMap::Blur()
{
  if (!(this->BlurAngle > 0.0))
  {
    return;
  }
  const int w = WorkingWidth, h = WorkingHeight;
  const double sigma = this->BlurAngle, kappa = 1.0 / (sigma * sigma);
  const std::vector<float> sharp = this->Working;
  const double* directions = this->PixelDirections.data();
  const int band = static_cast<int>(std::ceil(4.0 * sigma / (Pi / h)));
  vtkApertureSMP::For(0, h,
    [&](vtkIdType first, vtkIdType last)
    {
      for (int row = static_cast<int>(first); row < last; ++row)
      {
        // Two directions dphi apart in azimuth are at least dphi cos(theta) apart, theta the
        // band's latitude farthest from the equator: the columns beyond 4 sigma of that are
        // skipped, and all are kept when the band reaches a pole.
        const double theta = Pi * ((row + 0.5) / h - 0.5);
        const double far = std::min(0.5 * Pi, std::abs(theta) + 4.0 * sigma + Pi / h);
        const double reach =
          far < 0.5 * Pi - 1e-9 ? std::min(Pi, 4.0 * sigma / std::cos(far) + Pi / w) : Pi;
        // Columns on either side that can be within reach (all of them near the poles).
        const int columns = static_cast<int>(std::ceil(reach / (2 * Pi / w)));
        const int from = columns >= w / 2 ? 0 : -columns, to = columns >= w / 2 ? w - 1 : columns;
        for (int column = 0; column < w; ++column)
        {
          const double* d = &directions[3 * (row * w + column)];
          double sum[3] = { 0, 0, 0 }, total = 0.0;
          for (int r = std::max(0, row - band); r <= std::min(h - 1, row + band); ++r)
          {
            for (int dc = from; dc <= to; ++dc)
            {
              const size_t p = static_cast<size_t>(r) * w + ((column + dc) % w + w) % w;
              const double weight = this->RowSolidAngle[r] *
                std::exp(kappa * (vtkMath::Dot(d, &directions[3 * p]) - 1.0));
              for (int k = 0; k < 3; ++k)
              {
                sum[k] += weight * sharp[3 * p + k];
              }
              total += weight;
            }
          }
          for (int k = 0; k < 3; ++k)
          {
            this->Working[3 * (row * w + column) + k] = static_cast<float>(sum[k] / total);
          }
        }
      }
    });
}

//------------------------------------------------------------------------------
// Order-2 spherical harmonics of the (blurred) environment, in its own frame.
void vtkEnvironmentMap::ProjectHarmonics()
{
  const int w = WorkingWidth, h = WorkingHeight;
  for (int p = 0; p < w * h; ++p)
  {
    double y[9];
    Harmonics(&this->PixelDirections[3 * p], y);
    for (int n = 0; n < 9; ++n)
    {
      for (int k = 0; k < 3; ++k)
      {
        this->SH[n][k] += y[n] * this->Working[3 * p + k] * this->RowSolidAngle[p / w];
      }
    }
  }
}

//------------------------------------------------------------------------------
void vtkEnvironmentMap::Radiance(const double direction[3], double rgb[3])
{
  this->Update();
  rgb[0] = rgb[1] = rgb[2] = 0.0;
  if (!this->Image)
  {
    return;
  }
  double u, v;
  this->ImagePointOf(direction, u, v);
  const int w = WorkingWidth, h = WorkingHeight;
  for (int k = 0; k < 3; ++k)
  {
    auto working = [&](int i, int j)
    { return this->Working[3 * (static_cast<size_t>(j) * w + i) + k]; };
    rgb[k] = SampleLatLong(working, w, h, u * w - 0.5, v * h - 0.5);
  }
}

//------------------------------------------------------------------------------
void vtkEnvironmentMap::CellRadiance(vtkDoubleArray* directions, vtkDoubleArray* radiance)
{
  this->Update();
  const vtkIdType k = directions->GetNumberOfTuples();
  radiance->SetNumberOfComponents(3);
  radiance->SetNumberOfTuples(k);
  radiance->Fill(0.0);
  if (!this->Image || k == 0)
  {
    return;
  }
  // The directions in the environment's frame: each working pixel goes to the nearest one.
  std::vector<double> local(3 * k);
  for (vtkIdType j = 0; j < k; ++j)
  {
    double d[3];
    directions->GetTuple(j, d);
    vtkMath::Normalize(d);
    this->ToLocal(d, &local[3 * j]);
  }
  const int w = WorkingWidth, h = WorkingHeight;
  std::vector<int> nearest(static_cast<size_t>(w) * h);
  vtkApertureSMP::For(0, static_cast<vtkIdType>(w) * h,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType p = first; p < last; ++p)
      {
        const double* d = &this->PixelDirections[3 * p];
        double best = -2.0;
        for (vtkIdType j = 0; j < k; ++j)
        {
          const double dot = vtkMath::Dot(d, &local[3 * j]);
          if (dot > best)
          {
            best = dot;
            nearest[p] = static_cast<int>(j);
          }
        }
      }
    });
  std::vector<double> sums(3 * k, 0.0), areas(k, 0.0);
  for (int row = 0; row < h; ++row)
  {
    for (int column = 0; column < w; ++column)
    {
      const size_t p = static_cast<size_t>(row) * w + column;
      const int j = nearest[p];
      for (int c = 0; c < 3; ++c)
      {
        sums[3 * j + c] += this->Working[3 * p + c] * this->RowSolidAngle[row];
      }
      areas[j] += this->RowSolidAngle[row];
    }
  }
  for (vtkIdType j = 0; j < k; ++j)
  {
    double rgb[3];
    if (areas[j] > 0.0)
    {
      for (int c = 0; c < 3; ++c)
      {
        rgb[c] = sums[3 * j + c] / areas[j];
      }
    }
    else
    {
      // A cell smaller than the working pixels: the radiance at its direction.
      double d[3];
      directions->GetTuple(j, d);
      vtkMath::Normalize(d);
      this->Radiance(d, rgb);
    }
    radiance->SetTuple(j, rgb);
  }
}

//------------------------------------------------------------------------------
void vtkEnvironmentMap::Irradiance(const double normal[3], double rgb[3])
{
  this->Update();
  double n[3];
  this->ToLocal(normal, n);
  vtkMath::Normalize(n);
  double y[9];
  Harmonics(n, y);
  // The cosine lobe's coefficients per band: pi, 2 pi / 3, pi / 4.
  static const double band[9] = { Pi, 2 * Pi / 3, 2 * Pi / 3, 2 * Pi / 3, Pi / 4, Pi / 4, Pi / 4,
    Pi / 4, Pi / 4 };
  for (int k = 0; k < 3; ++k)
  {
    rgb[k] = 0.0;
    for (int i = 0; i < 9; ++i)
    {
      rgb[k] += band[i] * this->SH[i][k] * y[i];
    }
    rgb[k] = std::max(0.0, rgb[k]);
  }
}

//------------------------------------------------------------------------------
void vtkEnvironmentMap::CapIrradiance(const double axis[3], double r, double rgb[3])
{
  this->CapSum(axis, r, true, rgb);
}

//------------------------------------------------------------------------------
void vtkEnvironmentMap::CapRadiance(const double axis[3], double r, double rgb[3])
{
  this->CapSum(axis, r, false, rgb);
}

//------------------------------------------------------------------------------
void vtkEnvironmentMap::CapSum(const double axis[3], double r, bool cosine, double rgb[3])
{
  this->Update();
  rgb[0] = rgb[1] = rgb[2] = 0.0;
  if (!this->Image)
  {
    return;
  }
  double a[3];
  this->ToLocal(axis, a);
  vtkMath::Normalize(a);
  const double cosR = std::cos(std::min(std::max(r, 0.0), Pi));
  const int w = WorkingWidth, h = WorkingHeight;
  for (int row = 0; row < h; ++row)
  {
    for (int column = 0; column < w; ++column)
    {
      const size_t p = static_cast<size_t>(row) * w + column;
      const double c = vtkMath::Dot(a, &this->PixelDirections[3 * p]);
      if (c >= cosR)
      {
        for (int k = 0; k < 3; ++k)
        {
          rgb[k] += this->Working[3 * p + k] * this->RowSolidAngle[row] * (cosine ? c : 1.0);
        }
      }
    }
  }
}

//------------------------------------------------------------------------------
vtkImageData* vtkEnvironmentMap::NewCapTable(int columns, int rows, int radii)
{
  return this->NewTable(columns, rows, radii, true);
}

//------------------------------------------------------------------------------
vtkImageData* vtkEnvironmentMap::NewCapRadianceTable(int columns, int rows, int radii)
{
  return this->NewTable(columns, rows, radii, false);
}

//------------------------------------------------------------------------------
vtkImageData* vtkEnvironmentMap::NewTable(int columns, int rows, int radii, bool cosine)
{
  this->Update();
  columns = std::max(1, columns);
  rows = std::max(1, rows);
  radii = std::max(2, radii);
  vtkImageData* table = vtkImageData::New();
  table->SetDimensions(columns, rows, radii);
  vtkNew<vtkFloatArray> values;
  values->SetName(cosine ? "CapIrradiance" : "CapRadiance");
  values->SetNumberOfComponents(3);
  values->SetNumberOfTuples(static_cast<vtkIdType>(columns) * rows * radii);
  values->Fill(0.0);
  table->GetPointData()->SetScalars(values);
  if (!this->Image)
  {
    return table;
  }
  const int w = WorkingWidth, h = WorkingHeight;
  const double* pixels = this->PixelDirections.data();
  const double step = (cosine ? 0.5 * Pi : Pi) / (radii - 1);
  float* out = values->GetPointer(0);
  // For each axis, every pixel within the largest radius adds to the first radius that contains
  // it; the sums then accumulate over the radii.
  vtkApertureSMP::For(0, static_cast<vtkIdType>(columns) * rows,
    [&](vtkIdType first, vtkIdType last)
    {
      std::vector<double> bins(3 * radii);
      for (vtkIdType t = first; t < last; ++t)
      {
        std::fill(bins.begin(), bins.end(), 0.0);
        double a[3];
        Local((t % columns + 0.5) / columns, (t / columns + 0.5) / rows, a);
        for (int row = 0; row < h; ++row)
        {
          for (int column = 0; column < w; ++column)
          {
            const size_t p = static_cast<size_t>(row) * w + column;
            const double c = vtkMath::Dot(a, pixels + 3 * p);
            if (cosine && c <= 0.0)
            {
              continue;
            }
            const double angle = std::acos(std::min(1.0, std::max(-1.0, c)));
            const int bin = std::min(radii - 1, static_cast<int>(std::ceil(angle / step - 1e-12)));
            for (int k = 0; k < 3; ++k)
            {
              bins[3 * bin + k] +=
                this->Working[3 * p + k] * this->RowSolidAngle[row] * (cosine ? c : 1.0);
            }
          }
        }
        double total[3] = { 0, 0, 0 };
        for (int b = 0; b < radii; ++b)
        {
          for (int k = 0; k < 3; ++k)
          {
            total[k] += bins[3 * b + k];
            out[3 * (static_cast<vtkIdType>(b) * columns * rows + t) + k] =
              static_cast<float>(total[k]);
          }
        }
      }
    });
  return table;
}

//------------------------------------------------------------------------------
vtkImageData* vtkEnvironmentMap::NewWedgeTable(
  int azimuths, int elevations, const double frameToWorld[9])
{
  this->Update();
  azimuths = std::max(1, azimuths);
  elevations = std::max(2, elevations);
  vtkImageData* table = vtkImageData::New();
  table->SetDimensions(azimuths + 1, elevations, 3);
  vtkNew<vtkFloatArray> values;
  values->SetName("WedgeIrradiance");
  values->SetNumberOfComponents(3);
  values->SetNumberOfTuples(static_cast<vtkIdType>(azimuths + 1) * elevations * 3);
  values->Fill(0.0);
  table->GetPointData()->SetScalars(values);
  double fromFrame[3][3], toFrame[3][3];
  for (int i = 0; i < 9; ++i)
  {
    fromFrame[i / 3][i % 3] = frameToWorld[i];
  }
  const double determinant = vtkMath::Determinant3x3(fromFrame);
  if (!this->Image || !std::isfinite(determinant) || determinant == 0.0)
  {
    return table;
  }
  vtkMath::Invert3x3(fromFrame, toFrame);
  // bins[(azimuth bin, elevation bin, axis)] (RGB): each sample adds to the bin it falls in.
  const std::vector<double> bins = this->WedgeBins(azimuths, elevations, toFrame);
  // Columns sum the bins below their azimuth, rows those above their elevation.
  float* out = values->GetPointer(0);
  const vtkIdType plane = static_cast<vtkIdType>(azimuths + 1) * elevations;
  for (int a = 0; a < 3; ++a)
  {
    for (int j = elevations - 2; j >= 0; --j)
    {
      for (int i = 1; i <= azimuths; ++i)
      {
        const size_t bin = 3 * (3 * (static_cast<size_t>(i - 1) * elevations + j) + a);
        for (int k = 0; k < 3; ++k)
        {
          const vtkIdType here = a * plane + static_cast<vtkIdType>(j) * (azimuths + 1) + i;
          const double sum = bins[bin + k] + out[3 * (here - 1) + k] +
            out[3 * (here + azimuths + 1) + k] - out[3 * (here + azimuths) + k];
          out[3 * here + k] = static_cast<float>(sum);
        }
      }
    }
  }
  return table;
}

//------------------------------------------------------------------------------
vtkImageData* vtkEnvironmentMap::NewMeanRadianceTable(int columns, int rows, double r)
{
  this->Update();
  columns = std::max(1, columns);
  rows = std::max(1, rows);
  vtkImageData* table = vtkImageData::New();
  table->SetDimensions(columns, rows, 1);
  vtkNew<vtkFloatArray> values;
  values->SetName("MeanRadiance");
  values->SetNumberOfComponents(3);
  values->SetNumberOfTuples(static_cast<vtkIdType>(columns) * rows);
  values->Fill(0.0);
  table->GetPointData()->SetScalars(values);
  if (!this->Image || !(r >= 0.0))
  {
    return table;
  }
  const double cosR = std::cos(std::min(r, Pi));
  const int w = WorkingWidth, h = WorkingHeight;
  float* out = values->GetPointer(0);
  vtkApertureSMP::For(0, static_cast<vtkIdType>(columns) * rows,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType t = first; t < last; ++t)
      {
        double a[3], sum[3] = { 0, 0, 0 }, area = 0.0;
        Local((t % columns + 0.5) / columns, (t / columns + 0.5) / rows, a);
        for (int p = 0; p < w * h; ++p)
        {
          if (vtkMath::Dot(a, &this->PixelDirections[3 * static_cast<size_t>(p)]) >= cosR)
          {
            const double solidAngle = this->RowSolidAngle[p / w];
            for (int k = 0; k < 3; ++k)
            {
              sum[k] += this->Working[3 * static_cast<size_t>(p) + k] * solidAngle;
            }
            area += solidAngle;
          }
        }
        double rgb[3];
        if (area > 0.0)
        {
          for (int k = 0; k < 3; ++k)
          {
            rgb[k] = sum[k] / area;
          }
        }
        else
        {
          // No pixel centre within the cap: the radiance at its axis.
          SampleTable(this->Working.data(), w, h, a, rgb);
        }
        for (int k = 0; k < 3; ++k)
        {
          out[3 * t + k] = static_cast<float>(rgb[k]);
        }
      }
    });
  return table;
}

//------------------------------------------------------------------------------
void vtkEnvironmentMap::SampleTable(
  const float* table, int columns, int rows, const double local[3], double rgb[3])
{
  double u, v;
  LocalToImagePoint(local, u, v);
  for (int k = 0; k < 3; ++k)
  {
    auto at = [&](int i, int j) { return table[3 * (static_cast<size_t>(j) * columns + i) + k]; };
    rgb[k] = SampleLatLong(at, columns, rows, u * columns - 0.5, v * rows - 0.5);
  }
}

//------------------------------------------------------------------------------
std::vector<double> vtkEnvironmentMap::WedgeBins(
  int azimuths, int elevations, const double toFrame[3][3])
{
  const int w = WorkingWidth, h = WorkingHeight, split = 4;
  double toWorld[9];
  this->GetWorldToEnvironment(toWorld); // transposed below: the environment's frame to world
  std::vector<double> bins(9 * static_cast<size_t>(azimuths) * elevations, 0.0);
  const double elevationStep = Pi / (elevations - 1);
  for (int sub = 0; sub < h * split; ++sub)
  {
    const int row = sub / split;
    const double v0 = double(sub) / (h * split), v1 = (sub + 1.0) / (h * split);
    const double solidAngle =
      (2.0 * Pi / (w * split)) * (std::sin(Pi * (v1 - 0.5)) - std::sin(Pi * (v0 - 0.5)));
    for (int column = 0; column < w * split; ++column)
    {
      double local[3], world[3], d[3];
      Local((column + 0.5) / (w * split), 0.5 * (v0 + v1), local);
      for (int k = 0; k < 3; ++k)
      {
        world[k] = toWorld[k] * local[0] + toWorld[3 + k] * local[1] + toWorld[6 + k] * local[2];
      }
      vtkMath::Multiply3x3(toFrame, world, d);
      vtkMath::Normalize(d);
      const double phi = std::atan2(d[1], d[0]);
      const int i = std::min(
        azimuths - 1, static_cast<int>((phi < 0.0 ? phi + 2.0 * Pi : phi) / (2.0 * Pi) * azimuths));
      const double theta = std::asin(std::min(1.0, std::max(-1.0, d[2])));
      const int j = std::min(elevations - 2, static_cast<int>((theta + 0.5 * Pi) / elevationStep));
      const float* radiance = &this->Working[3 * (static_cast<size_t>(row) * w + column / split)];
      for (int a = 0; a < 3; ++a)
      {
        double* bin = &bins[3 * (3 * (static_cast<size_t>(i) * elevations + j) + a)];
        for (int k = 0; k < 3; ++k)
        {
          bin[k] += radiance[k] * d[a] * solidAngle;
        }
      }
    }
  }
  return bins;
}

//------------------------------------------------------------------------------
void vtkEnvironmentMap::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Image: " << this->Image << "\n";
  os << indent << "UpAxis: "
     << "XYZ"[this->UpAxis] << "\n";
  os << indent << "Azimuth: " << this->Azimuth << "\n";
  os << indent << "Orientation: " << this->Orientation[0];
  for (int i = 1; i < 9; ++i)
  {
    os << ", " << this->Orientation[i];
  }
  os << "\n";
  os << indent << "BlurAngle: " << this->BlurAngle << "\n";
}
