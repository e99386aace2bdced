/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkVolumeAperturePrecompute.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkVolumeAperturePrecompute.h"

#include "vtkApertureSMP.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMatrix3x3.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSphericalCap.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkVolumeExtinction.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkVolumeAperturePrecompute);
vtkCxxSetObjectMacro(vtkVolumeAperturePrecompute, VolumeProperty, vtkVolumeProperty);

namespace
{
constexpr double Pi = 3.14159265358979323846;
// The halo a piece asks for, in MaximumDistance: beyond it matter weighs under e^-4.5.
constexpr double HaloPerDistance = 1.5;
// Slices keep two zero voxels around them, so that the bilinear reads of a step of up to one
// voxel sideways need no bounds check.
constexpr int Pad = 2;

// The spherical Fibonacci set: n directions of equal solid angle, symmetric under z -> -z.
std::vector<double> FibonacciDirections(int n)
{
  std::vector<double> d(3 * static_cast<size_t>(n));
  const double golden = Pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i)
  {
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
    d[3 * i] = rho * std::cos(golden * i);
    d[3 * i + 1] = rho * std::sin(golden * i);
    d[3 * i + 2] = z;
  }
  return d;
}

// The sweeps over one aperture grid: σ on the grid, and the sums of T and T ω per voxel.
class ApertureSweeps
{
public:
  ApertureSweeps(
    std::vector<float> sigma, const int dims[3], const double spacing[3], double falloff)
    : Sigma(std::move(sigma))
    , Falloff(falloff)
  {
    std::copy(dims, dims + 3, this->Dims);
    std::copy(spacing, spacing + 3, this->Spacing);
    this->Strides[0] = 1;
    this->Strides[1] = dims[0];
    this->Strides[2] = vtkIdType(dims[0]) * dims[1];
    const size_t n = this->Sigma.size();
    this->Open.assign(n, 0.0f);
    this->Bent.assign(3 * n, 0.0f);
  }

  // Carries τ along `omega` (unit, image axes) through every slice, adding T and T ω to the sums.
  void Sweep(const double omega[3]);

  void Write(vtkImageData* output, const int outExt[6], const int region[6], vtkMatrix3x3* rotation,
    int directions) const;

  std::vector<float> Open; // Σ T
  std::vector<float> Bent; // Σ T ω

private:
  struct Layout
  {
    int M, A, B;          // the major axis and the two others
    int Step;             // +1 or -1 along M: where the ray's next slice is
    int OffsetA, OffsetB; // whole voxels of the step sideways
    float FracA, FracB;   // and the fractions
    float Delta;          // world length of the step
    float Decay;          // e^{-Delta/lambda}
  };
  Layout MakeLayout(const double omega[3]) const;
  void SweepSlice(const Layout& l, int k, const double omega[3], const std::vector<float>& prevS,
    const std::vector<float>& prevE, std::vector<float>& curS, std::vector<float>& curE);

  std::vector<float> Sigma;
  int Dims[3];
  vtkIdType Strides[3];
  double Spacing[3];
  double Falloff; // lambda
};

ApertureSweeps::Layout ApertureSweeps::MakeLayout(const double omega[3]) const
{
  double v[3];
  for (int a = 0; a < 3; ++a)
  {
    v[a] = omega[a] / this->Spacing[a];
  }
  Layout l;
  l.M = 0;
  for (int a = 1; a < 3; ++a)
  {
    l.M = std::abs(v[a]) > std::abs(v[l.M]) ? a : l.M;
  }
  l.A = (l.M + 1) % 3;
  l.B = (l.M + 2) % 3;
  const double major = std::abs(v[l.M]);
  l.Step = v[l.M] > 0.0 ? 1 : -1;
  const double da = v[l.A] / major;
  const double db = v[l.B] / major;
  l.OffsetA = static_cast<int>(std::floor(da));
  l.OffsetB = static_cast<int>(std::floor(db));
  l.FracA = static_cast<float>(da - l.OffsetA);
  l.FracB = static_cast<float>(db - l.OffsetB);
  l.Delta = static_cast<float>(vtkVolumeExtinction::StepLength(omega, this->Spacing));
  l.Decay = static_cast<float>(std::exp(-l.Delta / this->Falloff));
  return l;
}

void ApertureSweeps::Sweep(const double omega[3])
{
  const Layout l = this->MakeLayout(omega);
  const size_t slice = size_t(this->Dims[l.A] + 2 * Pad) * (this->Dims[l.B] + 2 * Pad);
  // Outside is empty: no σ, and light passes (E = 1).
  std::vector<float> prevS(slice, 0.0f), prevE(slice, 1.0f), curS(slice, 0.0f), curE(slice, 1.0f);
  const int n = this->Dims[l.M];
  // The ray's next slice must be done first: sweep against the direction.
  for (int i = 0; i < n; ++i)
  {
    const int k = l.Step > 0 ? n - 1 - i : i;
    this->SweepSlice(l, k, omega, prevS, prevE, curS, curE);
    std::swap(prevS, curS);
    std::swap(prevE, curE);
  }
}

void ApertureSweeps::SweepSlice(const Layout& l, int k, const double omega[3],
  const std::vector<float>& prevS, const std::vector<float>& prevE, std::vector<float>& curS,
  std::vector<float>& curE)
{
  const int na = this->Dims[l.A];
  const int nb = this->Dims[l.B];
  const int row = na + 2 * Pad;
  const float w00 = (1.0f - l.FracA) * (1.0f - l.FracB);
  const float w10 = l.FracA * (1.0f - l.FracB);
  const float w01 = (1.0f - l.FracA) * l.FracB;
  const float w11 = l.FracA * l.FracB;
  const float half = 0.5f * l.Delta;
  const float wx = static_cast<float>(omega[0]);
  const float wy = static_cast<float>(omega[1]);
  const float wz = static_cast<float>(omega[2]);
  const vtkIdType base = k * this->Strides[l.M];
  vtkApertureSMP::For(0, nb,
    [&](int beginB, int endB)
    {
      for (int ib = beginB; ib < endB; ++ib)
      {
        // The ray's next point in the previous slice, (ia + da, ib + db), padded.
        const size_t q = size_t(ib + l.OffsetB + Pad) * row + l.OffsetA + Pad;
        const size_t p = size_t(ib + Pad) * row + Pad;
        vtkIdType voxel = base + ib * this->Strides[l.B];
        for (int ia = 0; ia < na; ++ia, voxel += this->Strides[l.A])
        {
          const size_t qa = q + ia;
          const float sq = w00 * prevS[qa] + w10 * prevS[qa + 1] + w01 * prevS[qa + row] +
            w11 * prevS[qa + row + 1];
          const float eq = w00 * prevE[qa] + w10 * prevE[qa + 1] + w01 * prevE[qa + row] +
            w11 * prevE[qa + row + 1];
          // E = exp(-F), F(p) = sum over j >= 1 of c^j σ(p + jδω) δ, whose first term counts
          // half in τ: the trapezoid rule from the next slice on.
          const float next = std::exp(-l.Decay * half * sq);
          const float t = next * std::pow(eq, l.Decay);
          curS[p + ia] = this->Sigma[voxel];
          curE[p + ia] = next * t;
          this->Open[voxel] += t;
          this->Bent[3 * voxel] += t * wx;
          this->Bent[3 * voxel + 1] += t * wy;
          this->Bent[3 * voxel + 2] += t * wz;
        }
      }
    });
}

// Adds BentNormal and ApertureRadius over `outExt` (within `region`, the sweeps' grid) to
// `output`, the bent normals turned from image axes to world axes by `rotation`.
void ApertureSweeps::Write(vtkImageData* output, const int outExt[6], const int region[6],
  vtkMatrix3x3* rotation, int directions) const
{
  const vtkIdType count = output->GetNumberOfPoints();
  vtkNew<vtkFloatArray> bent;
  bent->SetName("BentNormal");
  bent->SetNumberOfComponents(3);
  bent->SetNumberOfTuples(count);
  vtkNew<vtkFloatArray> radius;
  radius->SetName("ApertureRadius");
  radius->SetNumberOfTuples(count);

  const double cell = 4.0 * Pi / directions;
  vtkApertureSMP::For(0, count,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        int ijk[3];
        vtkVolumeExtinction::ExtentPoint(outExt, i, ijk);
        vtkIdType v = 0;
        for (int a = 2; a >= 0; --a)
        {
          v = v * this->Dims[a] + (ijk[a] - region[2 * a]);
        }
        const double open = this->Open[v];
        const double b[3] = { this->Bent[3 * v], this->Bent[3 * v + 1], this->Bent[3 * v + 2] };
        double unit[3], world[3];
        vtkVolumeExtinction::MeanDirection(open, b, unit);
        rotation->MultiplyPoint(unit, world);
        bent->SetTypedTuple(i,
          std::array<float, 3>{ static_cast<float>(world[0]), static_cast<float>(world[1]),
            static_cast<float>(world[2]) }
            .data());
        const double solid = std::min(open * cell, 4.0 * Pi);
        radius->SetValue(i, static_cast<float>(vtkSphericalCap::CapRadiusFromSolidAngle(solid)));
      }
    });
  output->GetPointData()->AddArray(bent);
  output->GetPointData()->AddArray(radius);
}

// Output extent from the input's whole extent: the indices j with j * step inside it.
void CoarseExtent(const int in[6], int step, int out[6])
{
  for (int a = 0; a < 3; ++a)
  {
    out[2 * a] = static_cast<int>(std::ceil(in[2 * a] / static_cast<double>(step)));
    out[2 * a + 1] = static_cast<int>(std::floor(in[2 * a + 1] / static_cast<double>(step)));
  }
}

}

//------------------------------------------------------------------------------
vtkVolumeAperturePrecompute::vtkVolumeAperturePrecompute()
{
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
}

//------------------------------------------------------------------------------
vtkVolumeAperturePrecompute::~vtkVolumeAperturePrecompute()
{
  this->SetVolumeProperty(nullptr);
}

//------------------------------------------------------------------------------
vtkMTimeType vtkVolumeAperturePrecompute::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  return this->VolumeProperty ? std::max(time, this->VolumeProperty->GetMTime()) : time;
}

//------------------------------------------------------------------------------
double vtkVolumeAperturePrecompute::GetEffectiveMaximumDistance(const double bounds[6]) const
{
  if (this->MaximumDistance > 0.0)
  {
    return this->MaximumDistance;
  }
  return vtkVolumeExtinction::DefaultMaximumDistance(bounds);
}

//------------------------------------------------------------------------------
int vtkVolumeAperturePrecompute::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int whole[6];
  inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
  int coarse[6];
  CoarseExtent(whole, this->ApertureGridStep, coarse);
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), coarse, 6);
  double spacing[3] = { 1.0, 1.0, 1.0 };
  if (inInfo->Has(vtkDataObject::SPACING()))
  {
    inInfo->Get(vtkDataObject::SPACING(), spacing);
  }
  for (double& s : spacing)
  {
    s *= this->ApertureGridStep;
  }
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  outInfo->Set(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT(), 1);
  return 1;
}

//------------------------------------------------------------------------------
void vtkVolumeAperturePrecompute::ComputeHalo(
  const int wholeExtent[6], const double spacing[3], int halo[3]) const
{
  double bounds[6];
  for (int a = 0; a < 3; ++a)
  {
    bounds[2 * a] = wholeExtent[2 * a] * spacing[a];
    bounds[2 * a + 1] = wholeExtent[2 * a + 1] * spacing[a];
  }
  const double distance = HaloPerDistance * this->GetEffectiveMaximumDistance(bounds);
  for (int a = 0; a < 3; ++a)
  {
    // Bad spacings are RequestData's to refuse; here they only must not overflow.
    const double span = wholeExtent[2 * a + 1] - wholeExtent[2 * a];
    const double cells = spacing[a] > 0.0 ? std::ceil(distance / spacing[a]) : span;
    halo[a] = static_cast<int>(std::min(std::isfinite(cells) ? cells : span, std::max(span, 0.0))) +
      this->ApertureGridStep;
  }
}

//------------------------------------------------------------------------------
int vtkVolumeAperturePrecompute::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int whole[6], update[6];
  inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
  outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), update);
  double spacing[3] = { 1.0, 1.0, 1.0 };
  if (inInfo->Has(vtkDataObject::SPACING()))
  {
    inInfo->Get(vtkDataObject::SPACING(), spacing);
  }
  int halo[3];
  this->ComputeHalo(whole, spacing, halo);
  const int step = this->ApertureGridStep;
  int request[6];
  for (int a = 0; a < 3; ++a)
  {
    request[2 * a] = std::max(whole[2 * a], update[2 * a] * step - halo[a]);
    request[2 * a + 1] = std::min(whole[2 * a + 1], update[2 * a + 1] * step + halo[a]);
  }
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), request, 6);
  return 1;
}

//------------------------------------------------------------------------------
int vtkVolumeAperturePrecompute::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0]);
  vtkImageData* output = vtkImageData::GetData(outputVector);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkDataArray* scalars = input ? this->GetInputArrayToProcess(0, inputVector) : nullptr;
  const std::string problem = vtkVolumeExtinction::Check(input, scalars, this->VolumeProperty);
  if (!problem.empty())
  {
    vtkErrorMacro("Cannot compute volume apertures: " << problem << ".");
    return 0;
  }
  const int step = this->ApertureGridStep;
  int inExt[6], wholeIn[6], outExt[6], dims[3];
  input->GetExtent(inExt);
  input->GetDimensions(dims);
  inputVector[0]->GetInformationObject(0)->Get(
    vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), wholeIn);
  outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), outExt);
  double spacing[3];
  input->GetSpacing(spacing);

  // σ on the aperture grid over the whole input piece (the output's extent and its halo).
  int region[6], offset[3], coarseDims[3];
  CoarseExtent(inExt, step, region);
  for (int a = 0; a < 3; ++a)
  {
    offset[a] = region[2 * a] * step - inExt[2 * a];
  }
  std::vector<float> sigma = vtkVolumeExtinction::Decimate(
    vtkVolumeExtinction::Compute(input, scalars, this->VolumeProperty), dims, step, offset,
    coarseDims);
  this->UpdateProgress(0.05);

  double bounds[6];
  for (int a = 0; a < 3; ++a)
  {
    bounds[2 * a] = wholeIn[2 * a] * spacing[a];
    bounds[2 * a + 1] = wholeIn[2 * a + 1] * spacing[a];
  }
  const double distance = this->GetEffectiveMaximumDistance(bounds);
  const double coarseSpacing[3] = { spacing[0] * step, spacing[1] * step, spacing[2] * step };
  const double smallest = std::min({ coarseSpacing[0], coarseSpacing[1], coarseSpacing[2] });
  ApertureSweeps sweeps(std::move(sigma), coarseDims, coarseSpacing,
    std::max(distance, smallest) / vtkVolumeExtinction::FalloffsPerDistance);
  const std::vector<double> directions = FibonacciDirections(this->NumberOfDirections);
  for (int d = 0; d < this->NumberOfDirections; ++d)
  {
    if (this->GetAbortExecute())
    {
      return 1;
    }
    sweeps.Sweep(&directions[3 * d]);
    this->UpdateProgress(0.05 + 0.9 * (d + 1) / this->NumberOfDirections);
  }

  // The output: its update extent of the aperture grid.
  output->SetExtent(outExt);
  output->SetSpacing(coarseSpacing);
  output->SetOrigin(input->GetOrigin());
  output->SetDirectionMatrix(input->GetDirectionMatrix());
  if (step == 1)
  {
    output->GetPointData()->CopyAllocate(input->GetPointData(), output->GetNumberOfPoints());
    output->GetPointData()->CopyStructuredData(input->GetPointData(), inExt, outExt);
  }
  sweeps.Write(output, outExt, region, input->GetDirectionMatrix(), this->NumberOfDirections);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkVolumeAperturePrecompute::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "VolumeProperty: " << this->VolumeProperty << "\n";
  os << indent << "MaximumDistance: " << this->MaximumDistance << "\n";
  os << indent << "NumberOfDirections: " << this->NumberOfDirections << "\n";
  os << indent << "ApertureGridStep: " << this->ApertureGridStep << "\n";
}
