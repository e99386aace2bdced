/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkVolumeExtinction.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkVolumeExtinction.h"

#include "vtkApertureSMP.h"
#include "vtkApertureText.h"
#include "vtkArrayDispatch.h"
#include "vtkDataArray.h"
#include "vtkDataArrayRange.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace
{
// Entries of the opacity table between the smallest and largest scalar: finer than the 1024 of
// VTK's GPU mapper, so that the table is never what tells the two apart.
constexpr int TableSize = 4096;

struct FiniteWorker
{
  bool Finite = true;
  template <typename ArrayT>
  void operator()(ArrayT* array)
  {
    const auto values = vtk::DataArrayValueRange<1>(array);
    this->Finite =
      std::all_of(values.cbegin(), values.cend(), [](double v) { return std::isfinite(v); });
  }
};

// σ from the scalars through the opacity table (linear between entries).
struct SigmaWorker
{
  const std::vector<double>* Table;
  double Low;
  double Scale;
  float* Sigma;
  template <typename ArrayT>
  void operator()(ArrayT* array)
  {
    const auto values = vtk::DataArrayValueRange<1>(array);
    const std::vector<double>& table = *this->Table;
    vtkApertureSMP::For(0, values.size(),
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          const double x = std::min(std::max((values[i] - this->Low) * this->Scale, 0.0),
            static_cast<double>(TableSize - 1));
          const int k = std::min(static_cast<int>(x), TableSize - 2);
          const double t = x - k;
          this->Sigma[i] = static_cast<float>(table[k] + t * (table[k + 1] - table[k]));
        }
      });
  }
};

bool IsRotation(vtkMatrix3x3* m)
{
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      double dot = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        dot += m->GetElement(k, i) * m->GetElement(k, j);
      }
      if (!(std::abs(dot - (i == j ? 1.0 : 0.0)) < 1e-6))
      {
        return false;
      }
    }
  }
  return true;
}

// Tent weights of a decimation by `step` along one axis, offsets -(step - 1) .. step - 1.
std::vector<double> TentWeights(int step)
{
  std::vector<double> w(2 * step - 1);
  for (int d = -(step - 1); d < step; ++d)
  {
    w[d + step - 1] = (step - std::abs(d)) / (static_cast<double>(step) * step);
  }
  return w;
}

// One axis of the decimation: `in` of dims, every step-th sample from `offset` along `axis`.
std::vector<float> DecimateAxis(
  const std::vector<float>& in, int dims[3], int axis, int step, int offset)
{
  const int n = dims[axis];
  const int m = (n - 1 - offset) / step + 1;
  int out[3] = { dims[0], dims[1], dims[2] };
  out[axis] = m;
  const vtkIdType stride = axis == 0 ? 1 : (axis == 1 ? dims[0] : vtkIdType(dims[0]) * dims[1]);
  const vtkIdType outStride = axis == 0 ? 1 : (axis == 1 ? out[0] : vtkIdType(out[0]) * out[1]);
  const vtkIdType lines = vtkIdType(dims[0]) * dims[1] * dims[2] / n;
  const std::vector<double> weights = TentWeights(step);
  std::vector<float> result(static_cast<size_t>(lines * m));
  vtkApertureSMP::For(0, lines,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType line = begin; line < end; ++line)
      {
        // The line's first sample, in and out: the other two indices are kept.
        const vtkIdType outer = line / stride;
        const vtkIdType inner = line % stride;
        const vtkIdType inBase = outer * stride * n + inner;
        const vtkIdType outBase = outer * outStride * m + inner;
        for (int j = 0; j < m; ++j)
        {
          double sum = 0.0;
          for (int d = -(step - 1); d < step; ++d)
          {
            const int i = offset + j * step + d;
            if (i >= 0 && i < n)
            {
              sum += weights[d + step - 1] * in[inBase + i * stride];
            }
          }
          result[outBase + j * outStride] = static_cast<float>(sum);
        }
      }
    });
  dims[axis] = m;
  return result;
}
}

//------------------------------------------------------------------------------
double vtkVolumeExtinction::DefaultMaximumDistance(const double bounds[6])
{
  double sum = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    sum += (bounds[2 * a + 1] - bounds[2 * a]) * (bounds[2 * a + 1] - bounds[2 * a]);
  }
  return 0.2 * std::sqrt(sum);
}

//------------------------------------------------------------------------------
double vtkVolumeExtinction::StepLength(const double omega[3], const double spacing[3])
{
  double major = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    major = std::max(major, std::abs(omega[a]) / spacing[a]);
  }
  return 1.0 / major;
}

//------------------------------------------------------------------------------
std::string vtkVolumeExtinction::Check(
  vtkImageData* image, vtkDataArray* scalars, vtkVolumeProperty* property)
{
  std::ostringstream why;
  if (!image)
  {
    return "no input volume";
  }
  if (!property)
  {
    return "no volume property: set one with SetVolumeProperty()";
  }
  if (!property->GetScalarOpacity(0))
  {
    return "the volume property has no scalar opacity function";
  }
  int dims[3];
  image->GetDimensions(dims);
  if (dims[0] < 2 || dims[1] < 2 || dims[2] < 2)
  {
    why << "a volume needs at least 2 voxels along each axis, this one has " << dims[0] << " x "
        << dims[1] << " x " << dims[2];
    return why.str();
  }
  if (static_cast<double>(dims[0]) * dims[1] * dims[2] > 2147483647.0)
  {
    why << "a volume of " << dims[0] << " x " << dims[1] << " x " << dims[2]
        << " voxels is more than one piece can hold: stream it in pieces";
    return why.str();
  }
  double spacing[3];
  image->GetSpacing(spacing);
  const double smallest = std::min({ spacing[0], spacing[1], spacing[2] });
  const double largest = std::max({ spacing[0], spacing[1], spacing[2] });
  if (!(smallest > 0.0) || !std::isfinite(largest) || largest > 1e6 * smallest)
  {
    why << "the spacing (" << spacing[0] << ", " << spacing[1] << ", " << spacing[2]
        << ") is not positive, finite and within a factor 1e6 across axes";
    return why.str();
  }
  if (!IsRotation(image->GetDirectionMatrix()))
  {
    return "the volume's direction matrix is not a rotation";
  }
  if (!scalars)
  {
    return "the volume has no point scalars (cell scalars: convert them with "
           "vtkCellDataToPointData)";
  }
  if (scalars->GetNumberOfComponents() != 1)
  {
    why << "the scalars " << vtkApertureText::Quote(scalars->GetName() ? scalars->GetName() : "")
        << " have " << scalars->GetNumberOfComponents()
        << " components: the volume filters take one";
    return why.str();
  }
  if (scalars->GetNumberOfTuples() != image->GetNumberOfPoints())
  {
    return "the scalars do not have one value per voxel";
  }
  FiniteWorker finite;
  if (!vtkArrayDispatch::Dispatch::Execute(scalars, finite))
  {
    finite(scalars);
  }
  if (!finite.Finite)
  {
    return "the scalars hold NaN or infinite values";
  }
  return "";
}

//------------------------------------------------------------------------------
std::vector<float> vtkVolumeExtinction::Compute(
  vtkImageData* image, vtkDataArray* scalars, vtkVolumeProperty* property)
{
  double range[2];
  scalars->GetRange(range, 0);
  const double unit = std::max(property->GetScalarOpacityUnitDistance(0), 1e-30);
  std::vector<double> opacity(TableSize);
  property->GetScalarOpacity(0)->GetTable(range[0], range[1], TableSize, opacity.data());
  std::vector<double> table(TableSize);
  const double most = MaximumOpacity; // a copy: std::min takes references
  std::transform(opacity.begin(), opacity.end(), table.begin(),
    [unit, most](double alpha)
    { return -std::log1p(-std::min(std::max(alpha, 0.0), most)) / unit; });
  std::vector<float> sigma(static_cast<size_t>(image->GetNumberOfPoints()));
  SigmaWorker worker{ &table, range[0],
    range[1] > range[0] ? (TableSize - 1) / (range[1] - range[0]) : 0.0, sigma.data() };
  if (!vtkArrayDispatch::Dispatch::Execute(scalars, worker))
  {
    worker(scalars);
  }
  return sigma;
}

//------------------------------------------------------------------------------
std::vector<float> vtkVolumeExtinction::Decimate(
  const std::vector<float>& sigma, const int dims[3], int step, const int offset[3], int outDims[3])
{
  std::copy(dims, dims + 3, outDims);
  if (step <= 1)
  {
    return sigma;
  }
  std::vector<float> result = DecimateAxis(sigma, outDims, 0, step, offset[0]);
  result = DecimateAxis(result, outDims, 1, step, offset[1]);
  return DecimateAxis(result, outDims, 2, step, offset[2]);
}

//------------------------------------------------------------------------------
void vtkVolumeExtinction::ExtentPoint(const int extent[6], vtkIdType n, int ijk[3])
{
  for (int a = 0; a < 3; ++a)
  {
    const vtkIdType size = extent[2 * a + 1] - extent[2 * a] + 1;
    ijk[a] = extent[2 * a] + static_cast<int>(n % size);
    n /= size;
  }
}

//------------------------------------------------------------------------------
void vtkVolumeExtinction::MeanDirection(double open, const double moment[3], double unit[3])
{
  const double length =
    std::sqrt(moment[0] * moment[0] + moment[1] * moment[1] + moment[2] * moment[2]);
  const bool some = length > 1e-4 * open && length > 0.0;
  for (int a = 0; a < 3; ++a)
  {
    unit[a] = some ? moment[a] / length : (a == 2 ? 1.0 : 0.0);
  }
}

//------------------------------------------------------------------------------
double vtkVolumeExtinction::Sample(
  const float* sigma, const int dims[3], double x, double y, double z)
{
  const double p[3] = { x, y, z };
  int base[3];
  double t[3];
  for (int a = 0; a < 3; ++a)
  {
    if (!(p[a] > -1.0 && p[a] < dims[a]))
    {
      return 0.0;
    }
    base[a] = static_cast<int>(std::floor(p[a]));
    t[a] = p[a] - base[a];
  }
  double sum = 0.0;
  for (int corner = 0; corner < 8; ++corner)
  {
    int index[3];
    double weight = 1.0;
    for (int a = 0; a < 3; ++a)
    {
      const int up = (corner >> a) & 1;
      index[a] = base[a] + up;
      weight *= up ? t[a] : 1.0 - t[a];
    }
    if (index[0] >= 0 && index[0] < dims[0] && index[1] >= 0 && index[1] < dims[1] &&
      index[2] >= 0 && index[2] < dims[2] && weight > 0.0)
    {
      sum += weight * sigma[index[0] + dims[0] * (index[1] + vtkIdType(dims[1]) * index[2])];
    }
  }
  return sum;
}
