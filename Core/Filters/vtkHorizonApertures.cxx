/*=========================================================================

  Program:   ApertureLighting
  Module:    vtkHorizonApertures.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
#include "vtkHorizonApertures.h"

#include "vtkSphericalCap.h"

#include "vtkApertureSMP.h"
#include "vtkMath.h"
#include "vtkSMPThreadLocal.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <new>
#include <vector>

namespace
{
constexpr double Pi = vtkMath::Pi();
constexpr double NoSample = -std::numeric_limits<double>::infinity();
const double NotThere = std::numeric_limits<double>::quiet_NaN();

// Adjacent lines swept together, so that at each major index they touch neighbouring texels.
constexpr vtkIdType LinesPerGroup = 32;

// The grid, checked, with its output extent resolved.
struct Field
{
  const float* Heights;
  const unsigned char* Valid;
  const unsigned char* ReceiveMask;
  vtkIdType Nx, Ny;
  double Spacing[2];
  vtkIdType Extent[4];
  vtkIdType OutNx, OutNy;

  bool IsValid(vtkIdType t) const
  {
    return (!this->Valid || this->Valid[t]) && std::isfinite(this->Heights[t]);
  }

  bool Receives(vtkIdType t) const
  {
    return this->IsValid(t) && (!this->ReceiveMask || this->ReceiveMask[t]);
  }

  // The output index of texel (i, j), or -1 outside the output extent.
  vtkIdType OutputIndex(vtkIdType i, vtkIdType j) const
  {
    if (i < this->Extent[0] || i > this->Extent[1] || j < this->Extent[2] || j > this->Extent[3])
    {
      return -1;
    }
    return (i - this->Extent[0]) + (j - this->Extent[2]) * this->OutNx;
  }
};

bool CheckGrid(const vtkHorizonApertures::Grid& grid, Field& field, std::string& error)
{
  if (!grid.Heights || grid.Nx < 1 || grid.Ny < 1)
  {
    error = "The grid has no heights.";
    return false;
  }
  if (!(grid.Dx > 0.0 && grid.Dy > 0.0 && std::isfinite(grid.Dx) && std::isfinite(grid.Dy)))
  {
    error = "The grid spacing must be positive and finite.";
    return false;
  }
  if (grid.Sectors < 1 || grid.Sectors > 65535 || !(grid.MaximumDistance > 0.0))
  {
    error = "Sectors (at most 65535) and MaximumDistance must be positive.";
    return false;
  }
  if (!std::isfinite(grid.SectorRotation))
  {
    error = "The sector rotation must be finite.";
    return false;
  }
  if (!(grid.EarthRadius >= 0.0 && grid.EarthRadius < VTK_DOUBLE_MAX))
  {
    error = "The Earth radius must be 0 (flat ground) or positive and finite.";
    return false;
  }
  const vtkIdType* e = grid.OutputExtent;
  const bool whole = e[1] < e[0] || e[3] < e[2];
  if (!whole && (e[0] < 0 || e[1] >= grid.Nx || e[2] < 0 || e[3] >= grid.Ny))
  {
    error = "The output extent lies outside the grid.";
    return false;
  }
  field = { grid.Heights, grid.Valid, grid.Receives, grid.Nx, grid.Ny, { grid.Dx, grid.Dy },
    { 0, grid.Nx - 1, 0, grid.Ny - 1 }, 0, 0 };
  if (!whole)
  {
    std::copy(e, e + 4, field.Extent);
  }
  field.OutNx = field.Extent[1] - field.Extent[0] + 1;
  field.OutNy = field.Extent[3] - field.Extent[2] + 1;
  return true;
}

// The normal at texel (i, j) of the triangulated surface that vtkAperturePrecompute's rays see
// (cells split as (i,j)(i+1,j)(i+1,j+1) and (i,j)(i+1,j+1)(i,j+1)): the normalised sum of the
// unit normals of its up to six triangles whose corners are all valid; +z without any.
void TexelNormal(const Field& f, vtkIdType i, vtkIdType j, double n[3])
{
  // Its neighbours around it, counter-clockwise seen from above; triangles are (k, k + 1).
  static const int ring[7][2] = { { 1, 0 }, { 1, 1 }, { 0, 1 }, { -1, 0 }, { -1, -1 }, { 0, -1 },
    { 1, 0 } };
  const vtkIdType t = i + j * f.Nx;
  double offsets[7][3];
  bool there[7];
  for (int k = 0; k < 7; ++k)
  {
    const vtkIdType a = i + ring[k][0], b = j + ring[k][1], u = a + b * f.Nx;
    there[k] = a >= 0 && a < f.Nx && b >= 0 && b < f.Ny && f.IsValid(u);
    offsets[k][0] = ring[k][0] * f.Spacing[0];
    offsets[k][1] = ring[k][1] * f.Spacing[1];
    offsets[k][2] = there[k] ? double(f.Heights[u]) - f.Heights[t] : 0.0;
  }
  n[0] = n[1] = n[2] = 0.0;
  for (int k = 0; k < 6; ++k)
  {
    double m[3];
    vtkMath::Cross(offsets[k], offsets[k + 1], m);
    if (there[k] && there[k + 1] && vtkMath::Normalize(m) > 0.0)
    {
      vtkMath::Add(n, m, n);
    }
  }
  if (vtkMath::Normalize(n) == 0.0)
  {
    n[0] = n[1] = 0.0;
    n[2] = 1.0;
  }
}

// Each output texel's normal where the sweeps read it: three floats, or without them one 32-bit
// word in a float's place (the AO array, which only Finish() writes, or a scratch array): the
// hemispherical octahedral coordinates of the normal (its z is never negative), 16 bits each,
// within 7.5e-5 rad: 4 bytes a texel instead of 12, for a few nanoseconds to decode.
class NormalStore
{
public:
  NormalStore(float* full, float* packed)
    : Full(full)
    , Packed(packed)
  {
  }

  void Set(vtkIdType o, const double n[3]) const
  {
    if (this->Full)
    {
      std::copy(n, n + 3, &this->Full[3 * o]);
      return;
    }
    const double l1 = std::abs(n[0]) + std::abs(n[1]) + std::max(n[2], 0.0);
    long u = std::lround(n[0] / l1 * 32767.0), v = std::lround(n[1] / l1 * 32767.0); // 0 exact
    // Keep one quantum of z: a normal within a quantum (3e-5 rad) of the horizontal, a plane
    // steeper than about 33000:1, made the tangent plane's slope infinite and closed the plane.
    const long excess = std::abs(u) + std::abs(v) - 32766;
    if (excess > 0)
    {
      long& larger = std::abs(u) >= std::abs(v) ? u : v;
      larger -= larger > 0 ? excess : -excess;
    }
    const std::uint32_t word =
      static_cast<std::uint32_t>(u + 32767) | static_cast<std::uint32_t>(v + 32767) << 16;
    std::memcpy(&this->Packed[o], &word, sizeof(word));
  }

  void Get(vtkIdType o, float n[3]) const
  {
    this->GetUnnormalized(o, n);
    const float inverse =
      this->Full ? 1.0f : 1.0f / std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int c = 0; c < 3; ++c)
    {
      n[c] *= inverse;
    }
  }

  // The slope of the tangent plane along the unit direction (x, y), −(n_x x + n_y y) / n_z, from
  // the normal's direction alone (no square root).
  double GetSlope(vtkIdType o, double x, double y) const
  {
    float n[3];
    this->GetUnnormalized(o, n);
    return -(n[0] * x + n[1] * y) / n[2];
  }

private:
  void GetUnnormalized(vtkIdType o, float n[3]) const
  {
    if (this->Full)
    {
      std::copy(&this->Full[3 * o], &this->Full[3 * o] + 3, n);
      return;
    }
    std::uint32_t word;
    std::memcpy(&word, &this->Packed[o], sizeof(word));
    const float step = 1.0f / 32767.0f;
    n[0] = (float(word & 0xffffu) - 32767.0f) * step;
    n[1] = (float(word >> 16) - 32767.0f) * step;
    n[2] = std::max(1.0f - std::abs(n[0]) - std::abs(n[1]), 0.0f);
  }

  float* Full;
  float* Packed;
};

// Normals and valid flags of the output extent; (0, 0, 1) for no-data texels.
void ComputeNormals(const Field& f, const NormalStore& normals, unsigned char* valid)
{
  vtkApertureSMP::For(0, f.OutNy,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType row = first; row < last; ++row)
      {
        const vtkIdType j = f.Extent[2] + row;
        for (vtkIdType i = f.Extent[0]; i <= f.Extent[1]; ++i)
        {
          const vtkIdType t = i + j * f.Nx, o = f.OutputIndex(i, j);
          valid[o] = f.Receives(t) ? 1 : 0;
          double n[3] = { 0.0, 0.0, 1.0 };
          if (valid[o])
          {
            TexelNormal(f, i, j, n);
          }
          normals.Set(o, n);
        }
      }
    });
}

// atan(x) within 5e-10, about three times as fast as the C library's (which took 12% of a sweep):
// reduced to |t| <= tan(π/8), where 10 terms of the series suffice. Without branches, so that
// loops over samples vectorise: t = −1/y above tan(3π/8), (y − 1)/(y + 1) above tan(π/8).
inline double FastAtan(double x)
{
  const double y = std::abs(x);
  const bool high = y > 2.414213562373095, middle = y > 0.41421356237309503;
  const double below = y - 1.0, above = y + 1.0; // both, so that only values are selected
  const double base = high ? 0.5 * Pi : (middle ? 0.25 * Pi : 0.0);
  const double t = (high ? -1.0 : (middle ? below : y)) / (high ? y : (middle ? above : 1.0));
  const double t2 = t * t;
  double series = 1.0 / 19.0;
  for (const double c : { -1.0 / 17.0, 1.0 / 15.0, -1.0 / 13.0, 1.0 / 11.0, -1.0 / 9.0, 1.0 / 7.0,
         -1.0 / 5.0, 1.0 / 3.0, -1.0 })
  {
    series = series * t2 + c;
  }
  return std::copysign(base - t * series, x);
}

// What elevations 0 … a of a sector hold (given sin a, cos a): solid angle and ∫ω dω. `chord`
// is (sin φ1 − sin φ0, cos φ0 − cos φ1), ∫ (cos φ, sin φ) dφ over the sector.
inline void Deficit(
  double dphi, const double chord[2], double a, double sinA, double cosA, double deficit[4])
{
  const double horizontal = 0.5 * (a + sinA * cosA); // ∫ cos² e de over 0 … a
  deficit[0] += dphi * sinA;
  deficit[1] += horizontal * chord[0];
  deficit[2] += horizontal * chord[1];
  deficit[3] += 0.5 * dphi * sinA * sinA;
}

// What elevations 0 … atan(top) of a sector hold (Deficit()), from the slope `top`.
inline void SlopeDeficit(double dphi, const double chord[2], double top, double deficit[4])
{
  const double cosA = 1.0 / std::sqrt(1.0 + top * top);
  Deficit(dphi, chord, FastAtan(top), top * cosA, cosA, deficit);
}

// What a sector adds per texel: its width, ∫ (cos φ, sin φ) dφ over it, its middle direction.
struct Sector
{
  double Dphi, Chord[2], Cos, Sin;

  Sector() = default;
  Sector(int sector, int sectors, double rotation)
  {
    this->Dphi = 2.0 * Pi / sectors;
    const double phi0 = rotation + sector * this->Dphi, phi1 = phi0 + this->Dphi;
    this->Chord[0] = std::sin(phi1) - std::sin(phi0);
    this->Chord[1] = std::cos(phi0) - std::cos(phi1);
    this->Cos = std::cos(phi0 + 0.5 * this->Dphi);
    this->Sin = std::sin(phi0 + 0.5 * this->Dphi);
  }
};

// The lines of a sector, and of its opposite sector (φ + π) when Count is 2: the same lines,
// swept the other way. Line c holds, at major index m, the sample nearest to texel
// (m, c + Nearest[m]) (major, minor), at minor offset Offset[m] from it.
struct Lines
{
  Sector Sectors[2];
  int Index[2]; // the sectors' numbers
  int Count;
  int Major; // 0: i, 1: j
  vtkIdType NMajor, NMinor, MajorStride, MinorStride;
  int Step;         // Sectors[0]'s way along the major axis, +1 or -1
  double Delta;     // world distance between samples
  vtkIdType Window; // samples within MaximumDistance
  // On a curved Earth, Δ²/R: sample a (its major index in the whole DEM) is lowered by
  // Curvature a²/2 before the sweeps (0: flat ground).
  double Curvature;
  vtkIdType Anchor; // the grid's Origin along the major axis
  std::vector<vtkIdType> Nearest;
  std::vector<double> Offset;
  vtkIdType FirstLine, LastLine;

  Lines(const Field& f, const vtkHorizonApertures::Grid& grid, int sector, bool paired);

  // Texel (major, minor) as (i, j).
  void ToIJ(vtkIdType m, vtkIdType n, vtkIdType& i, vtkIdType& j) const
  {
    i = this->Major == 0 ? m : n;
    j = this->Major == 0 ? n : m;
  }

private:
  void SetWindow(double maximumDistance);
};

Lines::Lines(const Field& f, const vtkHorizonApertures::Grid& grid, int sector, bool paired)
{
  // Opposite sectors get their lines from the same one, so that they sample alike.
  const int half = grid.Sectors % 2 == 0 ? grid.Sectors / 2 : grid.Sectors;
  this->Count = paired ? 2 : 1;
  this->Sectors[0] = Sector(sector, grid.Sectors, grid.SectorRotation);
  this->Index[0] = sector;
  this->Index[1] = sector + half;
  if (paired)
  {
    this->Sectors[1] = Sector(sector + half, grid.Sectors, grid.SectorRotation);
  }
  const Sector base(sector % half, grid.Sectors, grid.SectorRotation);
  this->Major = std::abs(base.Cos) / f.Spacing[0] >= std::abs(base.Sin) / f.Spacing[1] ? 0 : 1;
  const double along = this->Major == 0 ? base.Cos : base.Sin;
  const double across = this->Major == 0 ? base.Sin : base.Cos;
  const double tau = // minor texels per major step
    (across * f.Spacing[this->Major]) / (along * f.Spacing[1 - this->Major]);
  this->NMajor = this->Major == 0 ? f.Nx : f.Ny;
  this->NMinor = this->Major == 0 ? f.Ny : f.Nx;
  this->MajorStride = this->Major == 0 ? 1 : f.Nx;
  this->MinorStride = this->Major == 0 ? f.Nx : 1;
  this->Step = (this->Major == 0 ? this->Sectors[0].Cos : this->Sectors[0].Sin) > 0.0 ? 1 : -1;
  this->Delta = f.Spacing[this->Major] / std::abs(along);
  this->Curvature = grid.EarthRadius > 0.0 ? this->Delta * this->Delta / grid.EarthRadius : 0.0;
  this->Anchor = grid.Origin[this->Major];
  this->Nearest.resize(this->NMajor);
  this->Offset.resize(this->NMajor);
  for (vtkIdType m = 0; m < this->NMajor; ++m)
  {
    const double x = double(m + grid.Origin[this->Major]) * tau;
    const double nearest = std::floor(x + 0.5);
    this->Nearest[m] = static_cast<vtkIdType>(nearest);
    // On a texel up to rounding (a diagonal's tau is 1 − 1e-16): exactly, so that the sample
    // does not need a neighbour, which at the grid's edge is not there.
    this->Offset[m] = std::abs(x - nearest) < 1e-9 ? 0.0 : x - nearest;
  }
  const auto range = std::minmax_element(this->Nearest.begin(), this->Nearest.end());
  this->FirstLine = -*range.second;
  this->LastLine = this->NMinor - 1 - *range.first;
  this->SetWindow(grid.MaximumDistance);
}

// The largest w with w Delta <= MaximumDistance; past every line's length: unlimited.
void Lines::SetWindow(double r)
{
  if (!(r < this->Delta * double(this->NMajor + 1)))
  {
    this->Window = this->NMajor + 1;
    return;
  }
  vtkIdType w = static_cast<vtkIdType>(std::floor(r / this->Delta));
  while (double(w + 1) * this->Delta <= r)
  {
    ++w;
  }
  while (w > 0 && double(w) * this->Delta > r)
  {
    --w;
  }
  this->Window = w;
}

// A line's samples in sweep order: sample k at Base[k * Step].
struct Samples
{
  const double* Base;
  vtkIdType Step;

  double operator[](vtkIdType k) const { return this->Base[k * this->Step]; }
};

// A sample on a line: its index in sweep order, as a double (exact), and its height. The hulls
// hold points rather than indices, so that their tests read no heights through an index (the
// pop loop's dependency chain).
struct Point
{
  double X, Z;
};

// A receiver's view along its line: its index X and height.
struct Viewpoint
{
  double X, Height;

  // Whether point a rises at least as high as point b, seen from here.
  bool AtLeast(const Point& a, const Point& b) const
  {
    return (a.Z - this->Height) * (this->X - b.X) >= (b.Z - this->Height) * (this->X - a.X);
  }

  double Slope(const Point& a) const { return (a.Z - this->Height) / (this->X - a.X); }
};

// The steepest slope from a viewpoint to an upper hull, chain(0 … n − 1) from the farthest
// point to the nearest: elevations along it rise to the tangent point and then fall.
template <typename Chain>
double Tangent(const Viewpoint& view, vtkIdType n, Chain chain)
{
  if (n == 0)
  {
    return NoSample;
  }
  vtkIdType low = 0, high = n - 1;
  while (low < high)
  {
    const vtkIdType middle = (low + high) / 2;
    if (view.AtLeast(chain(middle + 1), chain(middle)))
    {
      low = middle + 1;
    }
    else
    {
      high = middle;
    }
  }
  return view.Slope(chain(low));
}

// The distance between two lines' samples in a group's buffers of n samples a line: a whole
// number of cache lines, an odd one, so that a group's lines fall in different sets of the
// cache as Gather() and Scatter() go across them (at a power of two, they all fell in one).
vtkIdType Stride(vtkIdType n)
{
  const vtkIdType lines = (n + 7) / 8;
  return 8 * (lines % 2 == 1 ? lines : lines + 1);
}

// Per-thread buffers: a group's samples (line-major, Stride() apart), and the hulls of one line.
struct Scratch
{
  std::vector<double> Occluder; // interpolated height; NaN: does not occlude
  std::vector<double> Receiver; // the receiving texel's height; NaN: none
  std::vector<double> Tangent;  // the receiver's tangent plane's slope along Sectors[0]'s middle
  // Out: steepest slope per sample step, per sector of the pass (0, 1), and those of the negated
  // samples (2, 3), which give the lowest elevations.
  std::vector<double> Slope[4];
  // Out: what the pass's sectors take from each receiver's hemisphere, Deficit()'s four sums.
  std::vector<float> Deficit[4];
  std::vector<Point> Hull;
  // Suffix hulls of the previous block: a stack, and per sample of the block, where its push
  // wrote (-1: not pushed), what it overwrote, the stack size before it, and the highest
  // occluder of its suffix.
  std::vector<Point> Suffix, Overwritten;
  std::vector<vtkIdType> Position, Size;
  std::vector<double> Highest;
  vtkIdType SuffixFirst = 0, SuffixSize = 0;

  // Sizes the buffers for a pass's groups, when a thread first takes one.
  void Fit(vtkIdType lines, vtkIdType length, vtkIdType window, int sectors, bool lower)
  {
    if (!this->Hull.empty())
    {
      return;
    }
    for (auto* v : { &this->Occluder, &this->Receiver, &this->Tangent, &this->Slope[0] })
    {
      v->resize(lines * Stride(length));
    }
    for (auto& v : this->Deficit)
    {
      v.resize(lines * Stride(length));
    }
    this->Slope[1].resize(sectors == 2 ? lines * Stride(length) : 0);
    this->Slope[2].resize(lower ? lines * Stride(length) : 0);
    this->Slope[3].resize(lower && sectors == 2 ? lines * Stride(length) : 0);
    this->Hull.resize(length);
    for (auto* v : { &this->Suffix, &this->Overwritten })
    {
      v->resize(std::min(window, length));
    }
    for (auto* v : { &this->Position, &this->Size })
    {
      v->resize(std::min(window, length));
    }
    this->Highest.resize(std::min(window, length));
  }
};

// The steepest slope from every receiver of one line to the occluders before it within the
// window (samples in sweep order).
class LineSweep
{
public:
  LineSweep(Scratch& s, vtkIdType window)
    : S(s)
    , Window(window)
  {
  }

  // Sweeps samples 0 … n − 1 in that order, or `reversed`.
  void Run(const double* z, const double* zr, double* slope, vtkIdType n, bool reversed);

private:
  double Prefix(const Viewpoint& view, double occluder, vtkIdType& size);
  void BuildSuffixes(const Samples& z, vtkIdType first, vtkIdType last);
  void Undo(vtkIdType s);

  // No slope to the suffix in range is steeper than its highest occluder at the suffix's
  // nearest (or, below the viewpoint, farthest) distance: most receivers need no search.
  double SuffixBound(const Viewpoint& view, vtkIdType k) const
  {
    const vtkIdType first = k - this->Window, last = this->S.SuffixFirst + this->Window - 1;
    const double rise = this->S.Highest[first - this->S.SuffixFirst] - view.Height;
    return rise / (view.X - double(rise > 0.0 ? last : first));
  }

  Scratch& S;
  vtkIdType Window;
};

void LineSweep::Run(const double* zs, const double* zrs, double* slopes, vtkIdType n, bool reversed)
{
  std::fill(slopes, slopes + n, NoSample);
  if (this->Window < 1)
  {
    return;
  }
  const vtkIdType step = reversed ? -1 : 1, start = reversed ? n - 1 : 0;
  const Samples z{ zs + start, step }, zr{ zrs + start, step };
  bool suffixes = false;
  // Locals, not members, which the compiler would reload and store around every store into the
  // hull that might alias them (as a member, the hull's size cost a fifth of the sweep).
  const vtkIdType window = this->Window;
  vtkIdType hullSize = 0;
  for (vtkIdType k = 0, offset = 0; k < n; ++k, offset = offset + 1 == window ? 0 : offset + 1)
  {
    if (offset == 0)
    {
      hullSize = 0; // a new block: its own hull, and the suffixes of the block before
      if (k > 0)
      {
        this->BuildSuffixes(z, k - window, k);
        suffixes = true;
      }
    }
    else if (suffixes)
    {
      this->Undo(k - window - 1);
    }
    const bool occludes = !std::isnan(z[k]), receives = !std::isnan(zr[k]);
    if (!occludes && !receives)
    {
      continue;
    }
    const Viewpoint view{ double(k), receives ? zr[k] : z[k] };
    double best = this->Prefix(view, z[k], hullSize);
    if (receives && suffixes && best < this->SuffixBound(view, k))
    {
      const Point* stack = this->S.Suffix.data();
      const vtkIdType top = this->S.SuffixSize - 1;
      best = std::max(best,
        Tangent(view, this->S.SuffixSize,
          [stack, top](vtkIdType i) -> const Point& { return stack[top - i]; }));
    }
    slopes[start + k * step] = receives ? best : NoSample;
  }
}

// The steepest slope from a viewpoint to the hull of its block so far (`size` points); one that
// occludes (at height `occluder`, not NaN) is pushed onto it, after popping the points under its
// tangent (the top is then the tangent).
double LineSweep::Prefix(const Viewpoint& view, double occluder, vtkIdType& size)
{
  Point* hull = this->S.Hull.data();
  if (std::isnan(occluder))
  {
    return Tangent(view, size, [hull](vtkIdType i) -> const Point& { return hull[i]; });
  }
  while (size >= 2 && view.AtLeast(hull[size - 2], hull[size - 1]))
  {
    --size;
  }
  const double best = size > 0 ? view.Slope(hull[size - 1]) : NoSample;
  hull[size++] = Point{ view.X, occluder };
  return best;
}

// The upper hulls of all suffixes of samples [first, last), by a backward sweep whose pushes
// Undo() takes back one by one; afterwards the stack is the hull of the whole block.
void LineSweep::BuildSuffixes(const Samples& z, vtkIdType first, vtkIdType last)
{
  Scratch& s = this->S;
  vtkIdType size = 0;
  double highest = NoSample;
  for (vtkIdType k = last - 1; k >= first; --k)
  {
    const vtkIdType r = k - first;
    s.Position[r] = -1;
    highest = std::isnan(z[k]) ? highest : std::max(highest, z[k]);
    s.Highest[r] = highest;
    if (std::isnan(z[k]))
    {
      continue;
    }
    s.Size[r] = size;
    // Pop the leftmost hull point when it is not strictly above the line from k to the next.
    while (size >= 2)
    {
      const Point &t = s.Suffix[size - 1], &u = s.Suffix[size - 2];
      if ((t.Z - z[k]) * (u.X - double(k)) > (u.Z - z[k]) * (t.X - double(k)))
      {
        break;
      }
      --size;
    }
    s.Position[r] = size;
    s.Overwritten[r] = s.Suffix[size];
    s.Suffix[size++] = Point{ double(k), z[k] };
  }
  s.SuffixFirst = first;
  s.SuffixSize = size;
}

// From the hull of the suffix starting at sample k to that of the suffix after it.
void LineSweep::Undo(vtkIdType k)
{
  Scratch& s = this->S;
  const vtkIdType r = k - s.SuffixFirst;
  if (s.Position[r] >= 0)
  {
    s.Suffix[s.Position[r]] = s.Overwritten[r];
    s.SuffixSize = s.Size[r];
  }
}

// What the sweeps give a receiver in one pass: its steepest slopes in world units (one per
// sector, then one per sector of the negated samples; NoSample where not swept), what the
// pass's sectors take from its hemisphere (Deficit()'s sums).
struct Received
{
  const Scratch& S;
  vtkIdType At;
  double PerStep;

  double Slope(int q) const
  {
    return this->S.Slope[q].empty() ? NoSample : this->S.Slope[q][this->At] * this->PerStep;
  }
  float Deficit(int c) const { return this->S.Deficit[c][this->At]; }
};

// Scratch::Deficit of samples [first, first + n) from their slopes and tangents, in a loop
// without branches that the compiler vectorises. Count: the pass's sectors.
template <int Count>
void AddDeficits(const Lines& l, Scratch& s, vtkIdType first, vtkIdType n)
{
  const double perStep = 1.0 / l.Delta;
  const double* slopes[2] = { &s.Slope[0][first], &s.Slope[Count - 1][first] };
  const double* tangent = &s.Tangent[first];
  float* out[4] = { &s.Deficit[0][first], &s.Deficit[1][first], &s.Deficit[2][first],
    &s.Deficit[3][first] };
  for (vtkIdType k = 0; k < n; ++k)
  {
    double deficit[4] = { 0.0, 0.0, 0.0, 0.0 };
    for (int q = 0; q < Count; ++q) // the opposite sector's tangent plane falls the other way
    {
      const double top = std::max(slopes[q][k] * perStep, q == 0 ? tangent[k] : -tangent[k]);
      SlopeDeficit(l.Sectors[q].Dphi, l.Sectors[q].Chord, top, deficit);
    }
    for (int c = 0; c < 4; ++c)
    {
      out[c][k] = static_cast<float>(deficit[c]);
    }
  }
}

// A group of adjacent lines [First, Last) over the major indices where one of them meets the
// grid. Sample k of every line is at major index MajorAt(k), in sweep order.
class Group
{
public:
  Group(const Field& f, const Lines& lines, const NormalStore& normals, vtkIdType first,
    vtkIdType last);

  vtkIdType GetLength() const { return this->Length; }
  vtkIdType GetNumberOfLines() const { return this->Last - this->First; }

  // Fills the scratch with the heights of the group's samples and receivers (lowered by the
  // Earth's curvature).
  void Gather(Scratch& s) const;

  // Sample k's major index in the whole DEM.
  double Position(vtkIdType k) const { return double(this->MajorAt(k) + this->L.Anchor); }

  // Calls sink(output index, Received) for every receiver.
  template <typename Sink>
  void Scatter(const Scratch& s, const Sink& sink) const;

private:
  vtkIdType MajorAt(vtkIdType k) const { return this->L.Step > 0 ? this->High - k : this->Low + k; }
  double Interpolate(vtkIdType t, vtkIdType minor, double offset) const;

  const Field& F;
  const Lines& L;
  const NormalStore& Normals;
  vtkIdType First, Last, Low = 0, High = -1, Length = 0;
};

Group::Group(
  const Field& f, const Lines& lines, const NormalStore& normals, vtkIdType first, vtkIdType last)
  : F(f)
  , L(lines)
  , Normals(normals)
  , First(first)
  , Last(last)
{
  for (vtkIdType m = 0; m < lines.NMajor; ++m)
  {
    if (first + lines.Nearest[m] < lines.NMinor && last - 1 + lines.Nearest[m] >= 0)
    {
      this->Low = this->Length == 0 ? m : this->Low;
      this->High = m;
      this->Length = this->High - this->Low + 1;
    }
  }
}

// The height of a sample whose nearest texel t (valid) is at `minor`; NaN where the other
// texel is needed and is no-data or off the grid.
double Group::Interpolate(vtkIdType t, vtkIdType minor, double offset) const
{
  const float* z = this->F.Heights;
  if (offset == 0.0)
  {
    return z[t];
  }
  const vtkIdType way = offset > 0.0 ? 1 : -1;
  const vtkIdType other = t + way * this->L.MinorStride;
  if (minor + way < 0 || minor + way >= this->L.NMinor || !this->F.IsValid(other))
  {
    return NotThere;
  }
  return z[t] + std::abs(offset) * (double(z[other]) - z[t]);
}

void Group::Gather(Scratch& s) const
{
  const Lines& l = this->L;
  const vtkIdType n = this->Length;
  const vtkIdType stride = Stride(n);
  for (vtkIdType k = 0; k < n; ++k)
  {
    const vtkIdType m = this->MajorAt(k);
    const double offset = l.Offset[m];
    const double drop = 0.5 * l.Curvature * this->Position(k) * this->Position(k);
    for (vtkIdType c = this->First; c < this->Last; ++c)
    {
      const vtkIdType minor = c + l.Nearest[m], at = (c - this->First) * stride + k;
      s.Occluder[at] = s.Receiver[at] = NotThere;
      const vtkIdType t = m * l.MajorStride + minor * l.MinorStride;
      if (minor < 0 || minor >= l.NMinor || !this->F.IsValid(t))
      {
        continue;
      }
      s.Occluder[at] = this->Interpolate(t, minor, offset) - drop;
      vtkIdType i, j;
      l.ToIJ(m, minor, i, j);
      const vtkIdType o = this->F.OutputIndex(i, j);
      if (o < 0)
      {
        continue;
      }
      s.Tangent[at] = this->Normals.GetSlope(o, l.Sectors[0].Cos, l.Sectors[0].Sin);
      s.Receiver[at] = s.Occluder[at];
      if (std::isnan(s.Occluder[at])) // the texel's tangent plane at the sample
      {
        const double rise = this->Normals.GetSlope(o, l.Major, 1 - l.Major); // along the minor axis
        s.Receiver[at] = this->F.Heights[t] + offset * rise * this->F.Spacing[1 - l.Major] - drop;
      }
    }
  }
}

template <typename Sink>
void Group::Scatter(const Scratch& s, const Sink& sink) const
{
  const Lines& l = this->L;
  const vtkIdType n = this->Length;
  const double perStep = 1.0 / l.Delta;
  const vtkIdType stride = Stride(n);
  for (vtkIdType k = 0; k < n; ++k)
  {
    const vtkIdType m = this->MajorAt(k);
    for (vtkIdType c = this->First; c < this->Last; ++c)
    {
      const vtkIdType at = (c - this->First) * stride + k;
      if (!std::isnan(s.Receiver[at]))
      {
        vtkIdType i, j;
        l.ToIJ(m, c + l.Nearest[m], i, j);
        sink(this->F.OutputIndex(i, j), Received{ s, at, perStep });
      }
    }
  }
}

// On a curved Earth the sweeps saw heights w = z − c a²/2 (Gather()). From a receiver at a,
// the slope per step over the curved ground to a sample d steps away, (z − z₀ − c d²/2) / d,
// is the slope to it over w plus c a where the receiver looks toward larger a, minus c a
// toward smaller a: an exact correction, so that the hulls stay exact. `toward`: +1 or −1
// for sample 0's receiver's way; the negated samples' slopes take the opposite sign.
void Uncurve(const Group& group, double curvature, double toward, double* slopes, vtkIdType n)
{
  for (vtkIdType k = 0; k < n; ++k)
  {
    slopes[k] += toward * curvature * group.Position(k);
  }
}

// Sweeps the lines of a group: each line once per sector, and with `lower` once more with its
// samples negated; then what the pass's sectors take from each receiver.
void SweepGroup(Scratch& s, LineSweep& sweep, const Lines& lines, const Group& group, bool lower)
{
  const vtkIdType n = group.GetLength();
  for (vtkIdType line = 0; line < group.GetNumberOfLines(); ++line)
  {
    const vtkIdType c = line * Stride(n); // the line's first sample in the buffers
    double* z = &s.Occluder[c];
    double* zr = &s.Receiver[c];
    for (int k = 0; k < lines.Count; ++k) // the opposite sector sweeps the other way
    {
      sweep.Run(z, zr, &s.Slope[k][c], n, k == 1);
      if (lines.Curvature > 0.0) // Sectors[0] looks toward the major axis' Step
      {
        Uncurve(group, lines.Curvature, k == 0 ? lines.Step : -lines.Step, &s.Slope[k][c], n);
      }
    }
    (lines.Count == 2 ? AddDeficits<2> : AddDeficits<1>)(lines, s, c, n);
    if (!lower)
    {
      continue;
    }
    std::transform(z, z + n, z, std::negate<double>());
    std::transform(zr, zr + n, zr, std::negate<double>());
    for (int k = 0; k < lines.Count; ++k)
    {
      sweep.Run(z, zr, &s.Slope[2 + k][c], n, k == 1);
      if (lines.Curvature > 0.0)
      {
        Uncurve(group, lines.Curvature, k == 0 ? -lines.Step : lines.Step, &s.Slope[2 + k][c], n);
      }
    }
  }
}

// Sweeps all lines of a sector (or pair), groups in parallel; with `lower` also the negated
// heights.
template <typename Sink>
void SweepSector(
  const Field& f, const Lines& lines, const NormalStore& normals, bool lower, const Sink& sink)
{
  const vtkIdType groups = (lines.LastLine - lines.FirstLine + LinesPerGroup) / LinesPerGroup;
  vtkSMPThreadLocal<Scratch> scratch;
  vtkApertureSMP::For(0, groups, 1,
    [&](vtkIdType begin, vtkIdType end)
    {
      Scratch& s = scratch.Local();
      s.Fit(LinesPerGroup, lines.NMajor, lines.Window, lines.Count, lower);
      LineSweep sweep(s, lines.Window);
      for (vtkIdType g = begin; g < end; ++g)
      {
        const vtkIdType first = lines.FirstLine + g * LinesPerGroup;
        const Group group(
          f, lines, normals, first, std::min(first + LinesPerGroup, lines.LastLine + 1));
        const vtkIdType n = group.GetLength();
        if (n == 0)
        {
          continue;
        }
        group.Gather(s);
        SweepGroup(s, sweep, lines, group, lower);
        group.Scatter(s, sink);
      }
    });
}

// The horizons, while the sweeps write them, in the output array itself but sector-major
// within blocks of BlockTexels texels: a pass then writes whole cache lines of its sectors in
// the order it visits texels, where records of S floats would have each pass touch every
// record's lines (1.5 times the sweep's time at 32 sectors), and no buffer besides the output
// is needed. Transpose() turns each block into records when the sweeps are done. (A namespace
// constant, not a static member: std::min odr-uses it, which C++14 would leave undefined.)
constexpr vtkIdType BlockTexels = 1024;

class HorizonBlocks
{
public:
  HorizonBlocks(float* horizons, vtkIdType texels, int sectors)
    : Horizons(horizons)
    , Texels(texels)
    , NumberOfSectors(sectors)
  {
  }

  bool IsWanted() const { return this->Horizons != nullptr; }

  // Where texel o's horizon in sector k goes until Transpose().
  float& At(vtkIdType o, int k) const
  {
    const vtkIdType first = o - o % BlockTexels;
    const vtkIdType size = std::min(BlockTexels, this->Texels - first);
    return this->Horizons[first * this->NumberOfSectors + k * size + (o - first)];
  }

  // Each block from sector-major to records of NumberOfSectors floats.
  void Transpose() const
  {
    if (!this->Horizons)
    {
      return;
    }
    const vtkIdType blocks = (this->Texels + BlockTexels - 1) / BlockTexels;
    const int sectors = this->NumberOfSectors;
    vtkApertureSMP::For(0, blocks,
      [&](vtkIdType begin, vtkIdType end)
      {
        std::vector<float> copy(BlockTexels * sectors);
        for (vtkIdType b = begin; b < end; ++b)
        {
          const vtkIdType first = b * BlockTexels;
          const vtkIdType size = std::min(BlockTexels, this->Texels - first);
          float* block = this->Horizons + first * sectors;
          std::copy(block, block + size * sectors, copy.data());
          for (vtkIdType t = 0; t < size; ++t)
          {
            for (int k = 0; k < sectors; ++k)
            {
              block[t * sectors + k] = copy[k * size + t];
            }
          }
        }
      });
  }

private:
  float* Horizons;
  vtkIdType Texels;
  int NumberOfSectors;
};

// Whether any terrain product is asked for; whether one needs the negated heights' sweeps.
bool WantsProducts(const vtkHorizonApertures::Buffers& out)
{
  return out.SkyViewFactor || out.SkyViewFactorCosine || out.PositiveOpenness ||
    out.NegativeOpenness;
}

// The per-texel deficit sums, in the output arrays until Finish() turns them into outputs; the
// horizons into their blocks. The products' sums likewise: the sky's deficit (solid angle, and
// its projection on the normal), and Σ (π/2 − h) over the sectors with samples, counted in
// `Sampled`.
class Accumulator
{
public:
  Accumulator(const Lines& lines, const vtkHorizonApertures::Buffers& out,
    const NormalStore& normals, const HorizonBlocks& horizons, unsigned short* sampled)
    : Normals(normals)
    , L(lines)
    , Out(out)
    , Horizons(horizons)
    , Sampled(sampled)
  {
  }

  void operator()(vtkIdType o, const Received& r) const
  {
    this->Out.ApertureRadius[o] += r.Deficit(0);
    for (int c = 0; c < 3; ++c)
    {
      this->Out.BentNormals[3 * o + c] += r.Deficit(c + 1);
    }
    for (int k = 0; k < this->L.Count && this->Horizons.IsWanted(); ++k)
    {
      this->Horizons.At(o, this->L.Index[k]) = static_cast<float>(FastAtan(r.Slope(k)));
    }
    if (this->Sampled)
    {
      float n[3];
      this->Normals.Get(o, n);
      const double slopes[4] = { r.Slope(0), r.Slope(1), r.Slope(2), r.Slope(3) };
      this->AddProducts(o, n, slopes);
    }
  }

private:
  void AddProducts(vtkIdType o, const float n[3], const double slopes[4]) const
  {
    const vtkHorizonApertures::Buffers& out = this->Out;
    const bool skies = out.SkyViewFactor || out.SkyViewFactorCosine;
    double sky[4] = { 0.0, 0.0, 0.0, 0.0 }; // elevations 0 … max(h, 0) of the sky
    for (int k = 0; k < this->L.Count; ++k)
    {
      const double h = FastAtan(slopes[k]); // −π/2 without a sample
      if (skies)
      {
        const Sector& sector = this->L.Sectors[k];
        SlopeDeficit(sector.Dphi, sector.Chord, std::max(slopes[k], 0.0), sky);
      }
      if (slopes[k] == NoSample)
      {
        continue;
      }
      ++this->Sampled[o];
      if (out.PositiveOpenness)
      {
        out.PositiveOpenness[o] += static_cast<float>(0.5 * Pi - h);
      }
      if (out.NegativeOpenness)
      {
        out.NegativeOpenness[o] += static_cast<float>(0.5 * Pi - FastAtan(slopes[2 + k]));
      }
    }
    if (out.SkyViewFactor)
    {
      out.SkyViewFactor[o] += static_cast<float>(sky[0]);
    }
    if (out.SkyViewFactorCosine)
    {
      out.SkyViewFactorCosine[o] +=
        static_cast<float>(n[0] * sky[1] + n[1] * sky[2] + n[2] * sky[3]);
    }
  }

  const NormalStore& Normals;
  const Lines& L;
  const vtkHorizonApertures::Buffers& Out;
  const HorizonBlocks& Horizons;
  unsigned short* const Sampled;
};

// The products from their sums; NaN where not valid.
void FinishProducts(
  const vtkHorizonApertures::Buffers& out, vtkIdType o, const float n[3], unsigned short sampled)
{
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const bool valid = out.Valid[o] != 0;
  if (out.SkyViewFactor)
  {
    out.SkyViewFactor[o] =
      valid ? static_cast<float>(1.0 - out.SkyViewFactor[o] / (2.0 * Pi)) : nan;
  }
  if (out.SkyViewFactorCosine)
  {
    const double open = n[2] - out.SkyViewFactorCosine[o] / Pi;
    out.SkyViewFactorCosine[o] =
      valid ? static_cast<float>(vtkMath::ClampValue(open, 0.0, 1.0)) : nan;
  }
  for (float* openness : { out.PositiveOpenness, out.NegativeOpenness })
  {
    if (openness)
    {
      openness[o] = valid && sampled > 0
        ? static_cast<float>(vtkMath::DegreesFromRadians(double(openness[o]) / sampled))
        : nan;
    }
  }
}

// The open hemisphere less the deficits: radius, bent normal, ambient occlusion; no-data texels
// closed. Then the products, with `sampled` sectors per texel (null without products).
// The normal is read before AO is written: AO's array may hold the packed normals.
void Finish(const vtkHorizonApertures::Buffers& out, const NormalStore& normals, vtkIdType texels,
  int sectors, const unsigned short* sampled)
{
  vtkApertureSMP::For(0, texels,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType o = first; o < last; ++o)
      {
        float n[3];
        normals.Get(o, n);
        if (sampled)
        {
          FinishProducts(out, o, n, sampled[o]);
        }
        float* bent = &out.BentNormals[3 * o];
        if (!out.Valid[o])
        {
          out.ApertureRadius[o] = 0.0f;
          if (out.AmbientOcclusion)
          {
            out.AmbientOcclusion[o] = 0.0f;
          }
          std::copy(n, n + 3, bent);
          if (out.Horizons)
          {
            std::fill_n(out.Horizons + o * sectors, sectors, static_cast<float>(0.5 * Pi));
          }
          continue;
        }
        const double solid = 2.0 * Pi - out.ApertureRadius[o];
        double sum[3] = { -bent[0], -bent[1], Pi - bent[2] };
        out.ApertureRadius[o] = static_cast<float>(vtkSphericalCap::CapRadiusFromSolidAngle(solid));
        if (out.AmbientOcclusion)
        {
          const double ao = (n[0] * sum[0] + n[1] * sum[1] + n[2] * sum[2]) / Pi;
          out.AmbientOcclusion[o] = static_cast<float>(vtkMath::ClampValue(ao, 0.0, 1.0));
        }
        if (vtkMath::Normalize(sum) == 0.0)
        {
          std::copy(n, n + 3, sum);
        }
        std::copy(sum, sum + 3, bent);
      }
    });
}
}

//------------------------------------------------------------------------------
bool vtkHorizonApertures::GetOutputSize(
  const Grid& grid, vtkIdType& nx, vtkIdType& ny, std::string& error)
{
  Field f;
  if (!CheckGrid(grid, f, error))
  {
    return false;
  }
  nx = f.OutNx;
  ny = f.OutNy;
  return true;
}

//------------------------------------------------------------------------------
bool vtkHorizonApertures::Compute(const Grid& grid, const Buffers& output, std::string& error,
  const std::function<bool(double fraction)>& progress)
{
  Field f;
  if (!CheckGrid(grid, f, error))
  {
    return false;
  }
  const vtkIdType texels = f.OutNx * f.OutNy;
  const bool products = WantsProducts(output);
  std::vector<unsigned short> sampled;
  std::vector<float> packed; // the normals' home when the caller keeps neither them nor AO
  try
  {
    sampled.resize(products ? texels : 0, 0);
    packed.resize(output.Normals || output.AmbientOcclusion ? 0 : texels);
  }
  catch (const std::bad_alloc&)
  {
    error = "There is not enough memory for the sweeps' own arrays over " + std::to_string(texels) +
      " texels; stream in tiles.";
    return false;
  }
  const NormalStore normals(output.Normals,
    output.Normals              ? nullptr
      : output.AmbientOcclusion ? output.AmbientOcclusion
                                : packed.data());
  ComputeNormals(f, normals, output.Valid);
  std::fill_n(output.BentNormals, 3 * texels, 0.0f);
  std::fill_n(output.ApertureRadius, texels, 0.0f);
  for (float* sum : { output.SkyViewFactor, output.SkyViewFactorCosine, output.PositiveOpenness,
         output.NegativeOpenness })
  {
    if (sum)
    {
      std::fill_n(sum, texels, 0.0f);
    }
  }

  // Opposite sectors share their lines: one pass gathers and scatters both.
  const bool paired = grid.Sectors % 2 == 0;
  const int passes = paired ? grid.Sectors / 2 : grid.Sectors;
  const HorizonBlocks horizons(output.Horizons, texels, grid.Sectors);
  for (int pass = 0; pass < passes; ++pass)
  {
    const Lines lines(f, grid, pass, paired);
    SweepSector(f, lines, normals, output.NegativeOpenness != nullptr,
      Accumulator(lines, output, normals, horizons, products ? sampled.data() : nullptr));
    if (progress && !progress(double(pass + 1) / passes))
    {
      error = "The computation was aborted.";
      return false;
    }
  }
  horizons.Transpose();
  Finish(output, normals, texels, grid.Sectors, products ? sampled.data() : nullptr);
  return true;
}

//------------------------------------------------------------------------------
bool vtkHorizonApertures::Compute(const Grid& grid, Apertures& output, std::string& error,
  const std::function<bool(double fraction)>& progress)
{
  output = Apertures();
  if (!GetOutputSize(grid, output.Nx, output.Ny, error))
  {
    return false;
  }
  const vtkIdType texels = output.Nx * output.Ny;
  output.BentNormals.resize(3 * texels);
  output.ApertureRadius.resize(texels);
  output.AmbientOcclusion.resize(texels);
  output.Normals.resize(3 * texels);
  output.Valid.resize(texels);
  const Buffers buffers{ output.BentNormals.data(), output.ApertureRadius.data(),
    output.AmbientOcclusion.data(), output.Normals.data(), output.Valid.data() };
  if (!Compute(grid, buffers, error, progress))
  {
    output = Apertures();
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkHorizonApertures::ComputeHorizons(
  const Grid& grid, int sector, std::vector<float>& horizons, std::string& error)
{
  Field f;
  if (!CheckGrid(grid, f, error))
  {
    return false;
  }
  if (sector < 0 || sector >= grid.Sectors)
  {
    error = "The sector is not one of the grid's.";
    return false;
  }
  std::vector<float> normals(3 * f.OutNx * f.OutNy);
  std::vector<unsigned char> valid(f.OutNx * f.OutNy);
  const NormalStore store(normals.data(), nullptr);
  ComputeNormals(f, store, valid.data());
  horizons.assign(f.OutNx * f.OutNy, std::numeric_limits<float>::quiet_NaN());
  float* h = horizons.data();
  SweepSector(f, Lines(f, grid, sector, false), store, false,
    [h](vtkIdType o, const Received& r) { h[o] = static_cast<float>(std::atan(r.Slope(0))); });
  return true;
}

//------------------------------------------------------------------------------
void vtkHorizonApertures::AddSectorDeficit(double phi0, double phi1, double a, double deficit[4])
{
  const double chord[2] = { std::sin(phi1) - std::sin(phi0), std::cos(phi0) - std::cos(phi1) };
  Deficit(phi1 - phi0, chord, a, std::sin(a), std::cos(a), deficit);
}
