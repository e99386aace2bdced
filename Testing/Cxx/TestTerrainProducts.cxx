/*=========================================================================

  Program:   ApertureLighting
  Module:    TestTerrainProducts.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// The terrain products of vtkHorizonApertures against their closed forms, in the middle of
// shapes whose horizon h(φ) is known, each integrated over φ numerically (200,000 steps):
// - flat: sky-view factors 1, openness 90°, horizons 0;
// - a plane tilted by 20°: SVF 1 − (1/2π)∫ sin max(e, 0), cosine SVF (1 + cos 20°)/2, openness
//   90° both (the plane's own horizons are its tangent plane);
// - the bottom of a V-shaped valley, h = atan(|cos φ| tan β): SVF, cosine SVF and positive
//   openness at 32 sectors; negative openness only with sectors on the grid's axes and
//   diagonals (elsewhere the nearest samples sit off the kink, see vtkHorizonApertures);
// - a conical pit's centre, h = β: SVF 1 − sin β, cosine SVF cos² β, openness 90° − β and
//   90° + β (8 sectors on axes and diagonals: the apex is a kink too); a cone's peak the
//   reverse;
// - a wall of height H at distance d, h = atan(H cos φ / d) toward it where the ray meets it
//   within the grid, held per sector (the grid's edges cut sectors): SVF, and the horizon of
//   the sector turned onto the wall's normal (SectorRotation) equal to atan(H / d);
// - on a curved Earth of radius R, a sample d away lies d²/2R lower: flat ground's horizon is
//   its nearest sample's, atan(−Δ/2R), its lowest elevation the farthest sample's, and the
//   wall's horizon atan((H − d²/2R)/d);
// - tolerances: 0.5% for the sky-view factors, 0.2° for openness and horizons;
// - edges see fewer sectors (openness over those with samples); no-data texels are NaN; a tile
//   with its halo gives the whole grid's products;
// - vtkAperturePrecompute's no-data as walls: a block of no-data 20 texels away, as a wall of
//   30, gives the horizon atan(30/20) and stays no-data; filled: a square hole in a tilted plane
//   is filled so that its centre sees the plane's (1 + cos s)/2, no hole is left, and a tile
//   (its halo grown by the fill's reach) equals the whole grid.

#include "vtkAperturePrecompute.h"
#include "vtkHorizonApertures.h"

#include "vtkApertureTestHarness.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"

#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

using vtkApertureTest::Check;

namespace
{
constexpr double Pi = vtkMath::Pi();

// A square grid of n × n unit texels, its centre at (c, c).
struct Terrain
{
  vtkIdType N;
  std::vector<float> Z;
  std::vector<unsigned char> Valid;

  Terrain(vtkIdType n, const std::function<double(double x, double y)>& height)
    : N(n)
    , Z(n * n)
    , Valid(n * n, 1)
  {
    const double c = 0.5 * (n - 1);
    for (vtkIdType j = 0; j < n; ++j)
    {
      for (vtkIdType i = 0; i < n; ++i)
      {
        this->Z[i + j * n] = static_cast<float>(height(i - c, j - c));
      }
    }
  }
};

// Every product of the grid's output extent.
struct Products
{
  vtkIdType Nx = 0, Ny = 0;
  std::vector<float> Bent, Radius, Normals, Horizons, Svf, SvfCosine, Positive, Negative;
  std::vector<unsigned char> Valid;

  float At(const std::vector<float>& v, vtkIdType i, vtkIdType j) const { return v[i + j * Nx]; }
};

bool Compute(const vtkHorizonApertures::Grid& grid, Products& p)
{
  std::string error;
  if (!vtkHorizonApertures::GetOutputSize(grid, p.Nx, p.Ny, error))
  {
    return false;
  }
  const vtkIdType n = p.Nx * p.Ny;
  for (auto* v : { &p.Radius, &p.Svf, &p.SvfCosine, &p.Positive, &p.Negative })
  {
    v->resize(n);
  }
  p.Bent.resize(3 * n);
  p.Normals.resize(3 * n);
  p.Horizons.resize(grid.Sectors * n);
  p.Valid.resize(n);
  vtkHorizonApertures::Buffers b{ p.Bent.data(), p.Radius.data(), nullptr, p.Normals.data(),
    p.Valid.data(), p.Horizons.data() };
  b.SkyViewFactor = p.Svf.data();
  b.SkyViewFactorCosine = p.SvfCosine.data();
  b.PositiveOpenness = p.Positive.data();
  b.NegativeOpenness = p.Negative.data();
  const bool ok = vtkHorizonApertures::Compute(grid, b, error);
  Check(ok, "computes: " + error);
  return ok;
}

vtkHorizonApertures::Grid MakeGrid(const Terrain& t, int sectors, double rotation = 0.0)
{
  vtkHorizonApertures::Grid grid;
  grid.Heights = t.Z.data();
  grid.Valid = t.Valid.data();
  grid.Nx = grid.Ny = t.N;
  grid.Sectors = sectors;
  grid.SectorRotation = rotation;
  return grid;
}

// The closed forms of a horizon h(φ) (no clamp) and a normal, by integration over φ.
struct Expected
{
  double Svf = 0.0, SvfCosine = 0.0, Positive = 0.0, Negative = 0.0;
};

Expected Integrate(const std::function<double(double)>& h,
  const std::function<double(double)>& lowest, const double n[3])
{
  const int steps = 200000;
  Expected e;
  for (int s = 0; s < steps; ++s)
  {
    const double phi = 2.0 * Pi * (s + 0.5) / steps, a = std::max(h(phi), 0.0);
    e.Svf += 1.0 - std::sin(a);
    // (1/π) ∫ n·ω cos e de over a … π/2, times 2π per unit of mean: the sector form of SAGA's.
    const double horizontal = 0.5 * (0.5 * Pi - a - std::sin(a) * std::cos(a));
    e.SvfCosine += 2.0 *
      (n[2] * 0.5 * std::cos(a) * std::cos(a) +
        horizontal * (n[0] * std::cos(phi) + n[1] * std::sin(phi)));
    e.Positive += 90.0 - vtkMath::DegreesFromRadians(h(phi));
    e.Negative += 90.0 + vtkMath::DegreesFromRadians(lowest(phi));
  }
  e.Svf /= steps;
  e.SvfCosine /= steps;
  e.Positive /= steps;
  e.Negative /= steps;
  return e;
}

// h held at its value in the middle of each of `sectors` sectors starting at `rotation`: the
// closed form of what sectors can see, where the sectors' discretisation is not the point.
std::function<double(double)> Stepped(
  const std::function<double(double)>& h, int sectors, double rotation)
{
  const double width = 2.0 * Pi / sectors;
  return [=](double phi)
  { return h(rotation + (std::floor((phi - rotation) / width) + 0.5) * width); };
}

void CheckCentre(const std::string& shape, const Products& p, const Expected& e, bool negative)
{
  const vtkIdType c = p.Nx / 2;
  const double svf = p.At(p.Svf, c, c), cosine = p.At(p.SvfCosine, c, c);
  Check(std::abs(svf - e.Svf) <= 0.005 * e.Svf, shape + ": sky-view factor", svf, e.Svf);
  Check(std::abs(cosine - e.SvfCosine) <= 0.005 * e.SvfCosine, shape + ": cosine sky-view factor",
    cosine, e.SvfCosine);
  const double positive = p.At(p.Positive, c, c), lowest = p.At(p.Negative, c, c);
  Check(
    std::abs(positive - e.Positive) <= 0.2, shape + ": positive openness", positive, e.Positive);
  if (negative)
  {
    Check(std::abs(lowest - e.Negative) <= 0.2, shape + ": negative openness", lowest, e.Negative);
  }
}

void TestPlanes()
{
  const double up[3] = { 0.0, 0.0, 1.0 };
  Products flat;
  Compute(MakeGrid(Terrain(65, [](double, double) { return 5.0; }), 32), flat);
  CheckCentre(
    "flat", flat, Integrate([](double) { return 0.0; }, [](double) { return 0.0; }, up), true);
  const vtkIdType c = flat.Nx / 2;
  Check(flat.Horizons[32 * (c + c * flat.Nx)] == 0.0f, "flat: horizon 0");
  // A corner sees a quarter of the sectors: openness still 90°, over those.
  Check(std::abs(flat.Positive[0] - 90.0f) < 1e-3f, "flat: corner openness", flat.Positive[0], 90);

  const double slope = vtkMath::RadiansFromDegrees(20.0), t = std::tan(slope);
  Products tilted;
  Compute(MakeGrid(Terrain(65, [t](double x, double) { return t * x; }), 32), tilted);
  const double n[3] = { -std::sin(slope), 0.0, std::cos(slope) };
  auto plane = [t](double phi) { return std::atan(t * std::cos(phi)); };
  const Expected e = Integrate(plane, plane, n);
  Check(std::abs(e.SvfCosine - 0.5 * (1.0 + std::cos(slope))) < 1e-6,
    "tilted: the integral is the view factor (1 + cos s)/2", e.SvfCosine,
    0.5 * (1.0 + std::cos(slope)));
  CheckCentre("tilted plane", tilted, e, true);
}

void TestValleyAndCones()
{
  const double beta = vtkMath::RadiansFromDegrees(30.0), t = std::tan(beta);
  const double up[3] = { 0.0, 0.0, 1.0 };
  const Terrain valley(129, [t](double x, double) { return t * std::abs(x); });
  auto walls = [t](double phi) { return std::atan(std::abs(std::cos(phi)) * t); };
  const Expected v = Integrate(walls, walls, up);
  Products p32, p8;
  Compute(MakeGrid(valley, 32), p32);
  CheckCentre("valley, 32 sectors", p32, v, false);
  Compute(MakeGrid(valley, 8, -Pi / 8), p8);
  const auto stepped = Stepped(walls, 8, -Pi / 8);
  const Expected v8 = Integrate(stepped, stepped, up);
  CheckCentre("valley, 8 sectors on the axes", p8, v8, true);

  const Terrain pit(129, [t](double x, double y) { return t * std::hypot(x, y); });
  auto rim = [beta](double) { return beta; };
  Compute(MakeGrid(pit, 8, -Pi / 8), p8);
  CheckCentre("pit", p8, Integrate(rim, rim, up), true);
  const vtkIdType c = p8.Nx / 2;
  Check(std::abs(p8.At(p8.Svf, c, c) - (1.0 - std::sin(beta))) < 1e-4, "pit: 1 - sin b");
  Check(
    std::abs(p8.At(p8.SvfCosine, c, c) - std::cos(beta) * std::cos(beta)) < 1e-4, "pit: cos^2 b");

  const Terrain peak(129, [t](double x, double y) { return -t * std::hypot(x, y); });
  auto fall = [beta](double) { return -beta; };
  Compute(MakeGrid(peak, 8, -Pi / 8), p8);
  CheckCentre("peak", p8, Integrate(fall, fall, up), true);
}

void TestWall()
{
  // A wall of height 40 along x = 60, the receiver at the centre of a 257² grid (x = 0): far
  // enough that sampling its edge once per texel along the lines stays within the tolerances.
  const double height = 40.0, distance = 60.0;
  const Terrain wall(257, [&](double x, double) { return x >= distance ? height : 0.0; });
  const double up[3] = { 0.0, 0.0, 1.0 };
  // Rays that leave the grid (|y| > 128) before reaching the wall see nothing.
  auto toward = [&](double phi)
  {
    const bool meets = std::cos(phi) > 0.0 && std::abs(distance * std::tan(phi)) <= 128.0;
    return meets ? std::atan(height * std::cos(phi) / distance) : 0.0;
  };
  Products p;
  Compute(MakeGrid(wall, 32, -Pi / 32), p);
  // The wall's ends at the grid's edges cut sectors: compare sector by sector.
  CheckCentre("wall", p,
    Integrate(
      Stepped(toward, 32, -Pi / 32), [](double) { return 0.0; }, up),
    false);
  const vtkIdType c = p.Nx / 2;
  const double h0 = p.Horizons[32 * (c + c * p.Nx)], want = std::atan(height / distance);
  Check(std::abs(h0 - want) < vtkMath::RadiansFromDegrees(0.2),
    "wall: the sector turned onto its normal sees atan(H / d)", h0, want);
}

// A sphere so small (R = 2000 texels) that its curvature shows on the grid.
void TestCurvedEarth()
{
  const double radius = 2000.0;
  // Flat ground, 8 sectors on the axes (steps of 1) and diagonals (√2), 64 steps to the edge.
  const Terrain ground(129, [](double, double) { return 0.0; });
  vtkHorizonApertures::Grid flat = MakeGrid(ground, 8, -Pi / 8);
  flat.EarthRadius = radius;
  Products p;
  Compute(flat, p);
  const vtkIdType c = p.Nx / 2;
  double positive = 0.0, negative = 0.0, worst = 0.0;
  for (int k = 0; k < 8; ++k)
  {
    const double step = k % 2 ? std::sqrt(2.0) : 1.0, h = std::atan(-step / (2.0 * radius));
    worst = std::max(worst, std::abs(p.Horizons[8 * (c + c * p.Nx) + k] - h));
    positive += (90.0 - vtkMath::DegreesFromRadians(h)) / 8.0;
    negative +=
      (90.0 + vtkMath::DegreesFromRadians(std::atan(-64.0 * step / (2.0 * radius)))) / 8.0;
  }
  Check(worst < 1e-7, "curved flat ground: each horizon is its nearest sample's", worst, 0.0);
  Check(std::abs(p.At(p.Positive, c, c) - positive) < 1e-4, "curved flat ground: positive openness",
    p.At(p.Positive, c, c), positive);
  Check(std::abs(p.At(p.Negative, c, c) - negative) < 1e-4,
    "curved flat ground: negative openness, from the farthest samples", p.At(p.Negative, c, c),
    negative);
  Check(p.At(p.Svf, c, c) == 1.0f, "curved flat ground: the whole sky", p.At(p.Svf, c, c), 1.0);
  // Far from the DEM's origin (a tile's Origin), where each sample lies lower by more: the same
  // (opposite sectors' errors would cancel in the openness' mean near the origin).
  flat.Origin[0] = 3000;
  flat.Origin[1] = 1000;
  Products far;
  Compute(flat, far);
  Check(std::abs(far.At(far.Negative, c, c) - negative) < 1e-4 &&
      std::abs(far.At(far.Positive, c, c) - positive) < 1e-4,
    "curved flat ground far from the origin: the same openness", far.At(far.Negative, c, c),
    negative);

  const double height = 40.0, distance = 60.0;
  const Terrain cliff(257, [&](double x, double) { return x >= distance ? height : 0.0; });
  vtkHorizonApertures::Grid wall = MakeGrid(cliff, 32, -Pi / 32);
  wall.EarthRadius = radius;
  Compute(wall, p);
  const vtkIdType w = p.Nx / 2;
  const double h0 = p.Horizons[32 * (w + w * p.Nx)];
  const double want = std::atan((height - distance * distance / (2.0 * radius)) / distance);
  Check(
    std::abs(h0 - want) < 1e-6, "curved Earth: a wall at d sees atan((H - d^2/2R)/d)", h0, want);
}

void TestNoDataAndTiles()
{
  Terrain hills(
    96, [](double x, double y) { return 10.0 * std::sin(0.2 * x) * std::cos(0.15 * y); });
  hills.Valid[40 + 50 * 96] = 0;
  vtkHorizonApertures::Grid whole = MakeGrid(hills, 16);
  whole.MaximumDistance = 12.0;
  Products all;
  Compute(whole, all);
  Check(std::isnan(all.At(all.Svf, 40, 50)) && std::isnan(all.At(all.Negative, 40, 50)),
    "no-data: products are NaN");
  // A tile and its halo (radius + 2 texels), anchored where it lies in the whole grid.
  const vtkIdType i0 = 30, j0 = 20, halo = 14;
  Terrain window(1, [](double, double) { return 0.0; });
  window.N = 24 + 2 * halo;
  window.Z.assign(window.N * window.N, 0.0f);
  window.Valid.assign(window.N * window.N, 1);
  for (vtkIdType j = 0; j < window.N; ++j)
  {
    for (vtkIdType i = 0; i < window.N; ++i)
    {
      const vtkIdType t = (i0 - halo + i) + (j0 - halo + j) * 96;
      window.Z[i + j * window.N] = hills.Z[t];
      window.Valid[i + j * window.N] = hills.Valid[t];
    }
  }
  vtkHorizonApertures::Grid tile = MakeGrid(window, 16);
  tile.MaximumDistance = 12.0;
  tile.Origin[0] = i0 - halo;
  tile.Origin[1] = j0 - halo;
  const vtkIdType extent[4] = { halo, halo + 23, halo, halo + 23 };
  std::copy(extent, extent + 4, tile.OutputExtent);
  Products part;
  Compute(tile, part);
  double worst = 0.0;
  for (vtkIdType j = 0; j < 24; ++j)
  {
    for (vtkIdType i = 0; i < 24; ++i)
    {
      for (auto v :
        { &Products::Svf, &Products::SvfCosine, &Products::Positive, &Products::Negative })
      {
        const double a = part.At(part.*v, i, j), b = all.At(all.*v, i0 + i, j0 + j);
        worst = std::max(worst, std::isnan(a) && std::isnan(b) ? 0.0 : std::abs(a - b));
      }
    }
  }
  Check(worst < 1e-5, "a tile's products equal the whole grid's", worst, 0.0);
}

// A 129² image of unit texels holding the terrain's heights, NaN where `hole` says.
vtkSmartPointer<vtkImageData> MakeImage(
  const Terrain& t, const std::function<bool(vtkIdType i, vtkIdType j)>& hole)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(static_cast<int>(t.N), static_cast<int>(t.N), 1);
  vtkNew<vtkFloatArray> heights;
  heights->SetName("Elevation");
  heights->SetNumberOfTuples(t.N * t.N);
  for (vtkIdType p = 0; p < t.N * t.N; ++p)
  {
    heights->SetValue(p, hole(p % t.N, p / t.N) ? vtkMath::Nan() : t.Z[p]);
  }
  image->GetPointData()->SetScalars(heights);
  return image;
}

double Value(vtkImageData* image, const char* name, int i, int j, int component = 0)
{
  int ijk[3] = { i, j, 0 };
  return image->GetPointData()->GetArray(name)->GetComponent(image->ComputePointId(ijk), component);
}

void TestNoDataTreatments()
{
  const Terrain flat(129, [](double, double) { return 0.0; });
  vtkNew<vtkAperturePrecompute> walls;
  walls->SetInputData(MakeImage(
    flat, [](vtkIdType i, vtkIdType j) { return i >= 84 && i <= 89 && j >= 54 && j <= 74; }));
  walls->SetNoDataAsToWall();
  walls->SetNoDataWallHeight(30.0);
  walls->ComputeHorizonAnglesOn();
  walls->ComputeSkyViewFactorOn();
  walls->SetSectorRotation(-180.0 / 32);
  walls->Update();
  vtkImageData* out = vtkImageData::SafeDownCast(walls->GetOutputDataObject(0));
  const double h = Value(out, "HorizonAngles", 64, 64, 0), want = std::atan(30.0 / 20.0);
  Check(std::abs(h - want) < vtkMath::RadiansFromDegrees(0.2),
    "walls: atan(30 / 20) toward the "
    "block",
    h, want);
  Check(std::isnan(Value(out, "SkyViewFactor", 86, 60)) &&
      Value(out, "vtkValidPointMask", 86, 60) == 0.0,
    "walls: no-data stays no-data");

  const double slope = vtkMath::RadiansFromDegrees(20.0), tilt = std::tan(slope);
  const Terrain plane(129, [tilt](double x, double) { return tilt * x; });
  auto square = [](vtkIdType i, vtkIdType j)
  { return std::abs(i - 64) <= 4 && std::abs(j - 64) <= 4; };
  vtkNew<vtkAperturePrecompute> filled;
  filled->SetInputData(MakeImage(plane, square));
  filled->SetNoDataAsToFill();
  filled->ComputeSkyViewFactorCosineOn();
  filled->LimitDistanceOn();
  filled->SetMaximumDistance(10.0);
  filled->SetNoDataFillDistance(8);
  filled->Update();
  vtkNew<vtkImageData> whole; // the tile below updates the same output
  whole->DeepCopy(filled->GetOutputDataObject(0));
  out = whole;
  const double cosine = Value(out, "SkyViewFactorCosine", 64, 64),
               sky = 0.5 * (1.0 + std::cos(slope));
  Check(std::abs(cosine - sky) < 0.005 * sky, "filled: the hole's centre sees the plane's sky",
    cosine, sky);
  vtkDataArray* values = out->GetPointData()->GetArray("SkyViewFactorCosine");
  bool holes = false;
  for (vtkIdType p = 0; p < values->GetNumberOfTuples(); ++p)
  {
    holes = holes || std::isnan(values->GetComponent(p, 0));
  }
  Check(!holes, "filled: no hole left");
  // A tile beside the hole: its halo reaches past the hole by the fill's reach.
  filled->UpdateExtent(std::array<int, 6>{ 66, 90, 50, 70, 0, 0 }.data());
  double worst = 0.0;
  for (int j = 50; j <= 70; ++j)
  {
    for (int i = 66; i <= 90; ++i)
    {
      auto* tile = vtkImageData::SafeDownCast(filled->GetOutputDataObject(0));
      const double tiled = Value(tile, "SkyViewFactorCosine", i, j);
      worst = std::max(worst, std::abs(tiled - Value(out, "SkyViewFactorCosine", i, j)));
    }
  }
  Check(worst < 1e-6, "filled: a tile equals the whole grid", worst, 0.0);
}
}

int TestTerrainProducts(int, char*[])
{
  TestPlanes();
  TestValleyAndCones();
  TestWall();
  TestCurvedEarth();
  TestNoDataAndTiles();
  TestNoDataTreatments();
  return vtkApertureTest::Result();
}
