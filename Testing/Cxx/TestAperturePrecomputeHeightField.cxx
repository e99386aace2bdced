/*=========================================================================

  Program:   ApertureLighting
  Module:    TestAperturePrecomputeHeightField.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkAperturePrecompute's rays on the Mount Fuji DEM tile: the per-texel result equals the
// per-vertex result on the same surface triangulated; the error against a 4096-ray run falls at
// least as fast as 1/sqrt(N); stratified sampling beats random sampling at equal ray counts. The
// horizons it keeps give back, through vtkHorizonLighting, the caps the sweep summed.

#include "vtkAperturePrecompute.h"
#include "vtkApertureTestHarness.h"
#include "vtkHorizonLighting.h"
#include "vtkSphericalCap.h"
#include "vtkTerrainRGBReader.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkExtractVOI.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkShortArray.h"
#include "vtkTestUtilities.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using vtkApertureTest::Check;

// The tile is about 60 m per pixel; every `step`-th pixel is kept.
vtkSmartPointer<vtkImageData> Fuji(const char* file, int step)
{
  vtkNew<vtkTerrainRGBReader> reader;
  reader->SetFileName(file);
  reader->SetSpacing(60.0, 60.0);
  vtkNew<vtkExtractVOI> sample;
  sample->SetInputConnection(reader->GetOutputPort());
  sample->SetSampleRate(step, step, 1);
  sample->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->ShallowCopy(sample->GetOutput());
  return image;
}

vtkSmartPointer<vtkDataArray> Run(vtkDataObject* input, int rays, int sampling)
{
  vtkNew<vtkAperturePrecompute> filter;
  filter->SetInputData(input);
  filter->SetMethodToRays();
  filter->SetNumberOfRays(rays);
  filter->SetSampling(sampling);
  filter->Update();
  return vtkDataSet::SafeDownCast(filter->GetOutputDataObject(0))
    ->GetPointData()
    ->GetArray("ApertureRadius");
}

// The same surface as a polydata: grid points raised by their heights, each cell split as
// (i,j)(i+1,j)(i+1,j+1) and (i,j)(i+1,j+1)(i,j+1), no normals given.
vtkSmartPointer<vtkPolyData> Triangulate(vtkImageData* image)
{
  int dims[3];
  image->GetDimensions(dims);
  vtkDataArray* heights = image->GetPointData()->GetScalars();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (vtkIdType id = 0; id < image->GetNumberOfPoints(); ++id)
  {
    double p[3];
    image->GetPoint(id, p);
    p[2] += heights->GetTuple1(id);
    points->InsertNextPoint(p);
  }
  vtkNew<vtkCellArray> triangles;
  for (int j = 0; j + 1 < dims[1]; ++j)
  {
    for (int i = 0; i + 1 < dims[0]; ++i)
    {
      const vtkIdType p00 = i + j * dims[0], p10 = p00 + 1, p01 = p00 + dims[0], p11 = p01 + 1;
      const vtkIdType a[3] = { p00, p10, p11 }, b[3] = { p00, p11, p01 };
      triangles->InsertNextCell(3, a);
      triangles->InsertNextCell(3, b);
    }
  }
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->SetPoints(points);
  surface->SetPolys(triangles);
  return surface;
}

void TestTexelsMatchVertices(const char* file)
{
  auto image = Fuji(file, 4);
  vtkNew<vtkAperturePrecompute> perTexel;
  perTexel->SetInputData(image);
  perTexel->SetMethodToRays();
  perTexel->Update();
  vtkImageData* texels = perTexel->GetImageDataOutput();
  int dims[3];
  texels->GetDimensions(dims);
  Check(texels && dims[0] == 128 && dims[1] == 128 && texels->GetPointData()->GetArray("Elevation"),
    "per-texel output is the input grid with its arrays", dims[0], 128);

  vtkNew<vtkAperturePrecompute> perVertex;
  perVertex->SetInputData(Triangulate(image));
  perVertex->Update();
  vtkPolyData* vertices = perVertex->GetPolyDataOutput();

  vtkDataArray* r1 = texels->GetPointData()->GetArray("ApertureRadius");
  vtkDataArray* r2 = vertices->GetPointData()->GetArray("ApertureRadius");
  vtkDataArray* b1 = texels->GetPointData()->GetArray("BentNormal");
  vtkDataArray* b2 = vertices->GetPointData()->GetArray("BentNormal");
  const vtkIdType n = image->GetNumberOfPoints();
  double sum = 0.0, worst = 0.0, worstAngle = 0.0;
  vtkIdType differing = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double d = std::abs(r1->GetTuple1(i) - r2->GetTuple1(i));
    sum += d;
    worst = std::max(worst, d);
    differing += d > 0.0 ? 1 : 0;
    double u[3], v[3];
    b1->GetTuple(i, u);
    b2->GetTuple(i, v);
    worstAngle = std::max(worstAngle, vtkMath::AngleBetweenVectors(u, v));
  }
  std::cout << "Per-texel vs per-vertex on a " << dims[0] << "x" << dims[1]
            << " Fuji grid: mean |dr| = " << sum / n << ", max |dr| = " << worst << ", "
            << differing << " of " << n << " points differ, max bent-normal angle " << worstAngle
            << " rad\n";
  // Only rays that graze an edge to within float rounding of the normals may differ.
  Check(sum / n < 1e-4, "per-texel matches per-vertex (mean)", sum / n, 0);
  Check(differing < n / 100, "per-texel matches per-vertex (count)", differing, 0);

  // HeightScale 0 flattens the terrain: every texel is open.
  perTexel->SetHeightScale(0.0);
  perTexel->Update();
  double range[2];
  perTexel->GetImageDataOutput()->GetPointData()->GetArray("ApertureRadius")->GetRange(range);
  Check(range[0] > 0.5 * vtkMath::Pi() - 1e-6, "HeightScale 0 gives an open plane", range[0],
    0.5 * vtkMath::Pi());
}

double RmsSolidAngleError(vtkDataArray* r, vtkDataArray* reference)
{
  double sum = 0.0;
  for (vtkIdType i = 0; i < r->GetNumberOfTuples(); ++i)
  {
    const double d = vtkSphericalCap::SolidAngleFromCapRadius(r->GetTuple1(i)) -
      vtkSphericalCap::SolidAngleFromCapRadius(reference->GetTuple1(i));
    sum += d * d;
  }
  return std::sqrt(sum / r->GetNumberOfTuples());
}

void TestConvergence(const char* file)
{
  auto image = Fuji(file, 8);
  auto reference = Run(image, 4096, vtkAperturePrecompute::STRATIFIED);
  const int counts[] = { 16, 64, 256, 1024 };
  double slope[2];
  std::vector<double> errors[2];
  for (int sampling : { vtkAperturePrecompute::STRATIFIED, vtkAperturePrecompute::RANDOM })
  {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (int n : counts)
    {
      const double e = RmsSolidAngleError(Run(image, n, sampling), reference);
      errors[sampling].push_back(e);
      const double x = std::log(n), y = std::log(e);
      sx += x;
      sy += y;
      sxx += x * x;
      sxy += x * y;
    }
    slope[sampling] = (4 * sxy - sx * sy) / (4 * sxx - sx * sx);
  }
  std::cout << "RMS solid-angle error against 4096 stratified rays (64x64 Fuji grid):\n"
            << "  rays  stratified  random\n";
  for (int k = 0; k < 4; ++k)
  {
    std::cout << "  " << counts[k] << "  " << errors[0][k] << "  " << errors[1][k] << "\n";
  }
  std::cout << "  log-log slope: stratified " << slope[0] << ", random " << slope[1] << "\n";
  Check(slope[0] <= -0.5, "stratified error falls at least as fast as 1/sqrt(N)", slope[0], -0.5);
  Check(slope[1] <= -0.4, "random error falls like 1/sqrt(N)", slope[1], -0.5);
  for (int k = 0; k < 4; ++k)
  {
    Check(errors[0][k] < errors[1][k], "stratified beats random at equal rays", errors[0][k],
      errors[1][k]);
  }
}

// Horizon sweeps (the default for a height field) against 1024 rays per texel on the tile at
// 240 m: the goals at 4096 rays on the full tile are visible fraction RMS 0.01, bent
// normals 2 degrees and ambient occlusion 0.01 (BenchmarkTerrain prints those); the coarser
// tile and reference get a little more room. With an occluder the filter casts rays.
void TestHorizonsMatchRays(const char* file)
{
  auto image = Fuji(file, 4);
  vtkNew<vtkAperturePrecompute> rays, horizons;
  rays->SetInputData(image);
  rays->SetMethodToRays();
  rays->SetNumberOfRays(1024);
  horizons->SetInputData(image);
  for (vtkAperturePrecompute* f : { rays.Get(), horizons.Get() })
  {
    f->ComputeAmbientOcclusionOn();
    f->Update();
  }
  Check(horizons->GetUsedHorizons() && !rays->GetUsedHorizons(), "default method on a grid",
    horizons->GetUsedHorizons(), 1);
  vtkPointData* a = rays->GetImageDataOutput()->GetPointData();
  vtkPointData* b = horizons->GetImageDataOutput()->GetPointData();
  double squares = 0.0, angles = 0.0, occlusion = 0.0;
  const vtkIdType n = image->GetNumberOfPoints();
  for (vtkIdType t = 0; t < n; ++t)
  {
    const double fa = 1.0 - std::cos(a->GetArray("ApertureRadius")->GetTuple1(t));
    const double fb = 1.0 - std::cos(b->GetArray("ApertureRadius")->GetTuple1(t));
    squares += (fa - fb) * (fa - fb);
    double ba[3], bb[3];
    a->GetArray("BentNormal")->GetTuple(t, ba);
    b->GetArray("BentNormal")->GetTuple(t, bb);
    angles += vtkMath::DegreesFromRadians(vtkMath::AngleBetweenVectors(ba, bb));
    occlusion += std::abs(a->GetArray("AmbientOcclusion")->GetTuple1(t) -
      b->GetArray("AmbientOcclusion")->GetTuple1(t));
  }
  const double rms = std::sqrt(squares / n);
  std::cout << "Horizons (32 sectors) vs 1024 rays, 128 x 128 at 240 m: visible fraction RMS "
            << rms << ", bent normals " << angles / n << " deg mean, AO " << occlusion / n
            << " mean\n";
  Check(rms <= 0.012, "horizons vs rays: visible fraction RMS", rms, 0.012);
  Check(angles / n <= 2.0, "horizons vs rays: mean bent-normal angle (deg)", angles / n, 2.0);
  Check(occlusion / n <= 0.01, "horizons vs rays: mean AO difference", occlusion / n, 0.01);

  horizons->AddOccluderData(Triangulate(image));
  horizons->SetNumberOfRays(4);
  horizons->Update();
  Check(!horizons->GetUsedHorizons(), "with an occluder the filter casts rays", 1, 0);
}

// The kept horizons are what the sweep summed: vtkHorizonLighting's sky through their wedges is
// the sweep's ambient occlusion, and its open fraction the aperture's solid angle; keeping them
// changes no other output.
void TestKeptHorizons(const char* file)
{
  auto image = Fuji(file, 4);
  vtkNew<vtkAperturePrecompute> plain, kept;
  for (vtkAperturePrecompute* f : { plain.Get(), kept.Get() })
  {
    f->SetInputData(image);
    f->SetNumberOfSectors(24);
    f->SetMaximumDistance(3000.0);
    f->ComputeAmbientOcclusionOn();
  }
  kept->ComputeHorizonAnglesOn();
  plain->Update();
  kept->Update();
  vtkPointData* a = plain->GetImageDataOutput()->GetPointData();
  vtkPointData* b = kept->GetImageDataOutput()->GetPointData();
  vtkDataArray* horizons = b->GetArray("HorizonAngles");
  Check(!a->GetArray("HorizonAngles") && horizons && horizons->GetNumberOfComponents() == 24,
    "HorizonAngles only when asked, one component per sector");
  if (!horizons)
  {
    return;
  }
  double worstSky = 0.0, worstOpen = 0.0;
  int changed = 0;
  for (vtkIdType t = 0; t < image->GetNumberOfPoints(); ++t)
  {
    double n[3];
    b->GetNormals()->GetTuple(t, n);
    const double sky = vtkHorizonLighting::SkyTransfer(horizons, t, n, true);
    const double open = vtkHorizonLighting::SkyTransfer(horizons, t, n, false);
    const double r = b->GetArray("ApertureRadius")->GetComponent(t, 0);
    worstSky =
      std::max(worstSky, std::abs(sky - b->GetArray("AmbientOcclusion")->GetComponent(t, 0)));
    worstOpen = std::max(worstOpen, std::abs(open - (1.0 - std::cos(r))));
    changed += r != a->GetArray("ApertureRadius")->GetComponent(t, 0);
    for (int k = 0; k < 24; ++k)
    {
      const double h = horizons->GetComponent(t, k), pole = static_cast<float>(0.5 * vtkMath::Pi());
      changed += !(h >= -pole && h <= pole);
    }
  }
  std::cout << "Kept horizons vs the sweep's sums: AO " << worstSky << ", open fraction "
            << worstOpen << " (max)\n";
  Check(worstSky < 1e-4, "the sky through the kept horizons is the sweep's AO", worstSky, 1e-4);
  Check(worstOpen < 1e-4, "their open fraction is the aperture's", worstOpen, 1e-4);
  Check(changed == 0, "keeping horizons changes no radius and stays within +-pi/2", changed, 0);

  kept->AddOccluderData(Triangulate(image));
  kept->SetNumberOfRays(4);
  kept->Update();
  Check(!kept->GetImageDataOutput()->GetPointData()->GetArray("HorizonAngles"),
    "rays keep no horizons");
}

// The sweeps read float heights in place and other types (here rounded to whole metres, as
// doubles and as shorts, and scaled by 2 instead of stored doubled) through copies: every path
// gives the same apertures, value for value, and the input is left as it was.
void TestHeightTypes(const char* file)
{
  auto image = Fuji(file, 4);
  vtkDataArray* source = image->GetPointData()->GetScalars();
  const vtkIdType n = source->GetNumberOfTuples();
  vtkNew<vtkFloatArray> floats;
  vtkNew<vtkDoubleArray> doubles;
  vtkNew<vtkShortArray> shorts;
  vtkNew<vtkFloatArray> doubled;
  for (vtkIdType t = 0; t < n; ++t)
  {
    const double metres = std::round(source->GetComponent(t, 0));
    floats->InsertNextValue(static_cast<float>(metres));
    doubles->InsertNextValue(metres);
    shorts->InsertNextValue(static_cast<short>(metres / 2.0));
    doubled->InsertNextValue(static_cast<float>(2.0 * std::floor(metres / 2.0)));
  }
  auto radii = [&](vtkDataArray* heights, double scale)
  {
    auto grid = vtkSmartPointer<vtkImageData>::New();
    grid->CopyStructure(image);
    grid->GetPointData()->SetScalars(heights);
    vtkNew<vtkAperturePrecompute> filter;
    filter->SetInputData(grid);
    filter->SetHeightScale(scale);
    filter->Update();
    return vtkSmartPointer<vtkDataArray>(
      filter->GetImageDataOutput()->GetPointData()->GetArray("ApertureRadius"));
  };
  const vtkSmartPointer<vtkDataArray> inPlace = radii(floats, 1.0);
  const vtkSmartPointer<vtkDataArray> fromDoubles = radii(doubles, 1.0);
  const vtkSmartPointer<vtkDataArray> fromShorts = radii(shorts, 2.0);
  const vtkSmartPointer<vtkDataArray> fromDoubled = radii(doubled, 1.0);
  int different = 0, unscaled = 0;
  for (vtkIdType t = 0; t < n; ++t)
  {
    different += inPlace->GetComponent(t, 0) != fromDoubles->GetComponent(t, 0);
    unscaled += fromShorts->GetComponent(t, 0) != fromDoubled->GetComponent(t, 0);
  }
  Check(different == 0, "float heights in place == double heights copied", different, 0);
  Check(unscaled == 0, "short heights scaled by 2 == float heights stored doubled", unscaled, 0);
  Check(floats->GetValue(n / 2) == static_cast<float>(std::round(source->GetComponent(n / 2, 0))),
    "the input heights are left as they were");
}
// ComputeNormals off: no Normals array; the same apertures to the bit by rays on the grid's
// triangulation, within 1e-4 by horizons on the grid (whose sweeps keep the normals packed); the
// normals the sweeps compute are those of the triangles the rays see on the grid.
void TestWithoutNormals(const char* file)
{
  auto image = Fuji(file, 8);
  auto mesh = Triangulate(image);
  vtkSmartPointer<vtkDataArray> swept;
  for (vtkDataObject* input :
    { static_cast<vtkDataObject*>(image), static_cast<vtkDataObject*>(mesh) })
  {
    auto run = [&](bool normals)
    {
      vtkNew<vtkAperturePrecompute> filter;
      filter->SetInputData(input);
      filter->SetNumberOfRays(32);
      filter->ComputeAmbientOcclusionOn();
      filter->SetComputeNormals(normals);
      filter->Update();
      return vtkSmartPointer<vtkDataSet>(vtkDataSet::SafeDownCast(filter->GetOutputDataObject(0)));
    };
    const auto kept = run(true), left = run(false);
    const double tolerance = input == image ? 1e-4 : 0.0;
    int different = 0;
    for (const char* name : { "BentNormal", "ApertureRadius", "AmbientOcclusion" })
    {
      vtkDataArray* a = kept->GetPointData()->GetArray(name);
      vtkDataArray* b = left->GetPointData()->GetArray(name);
      different += !a || !b;
      for (vtkIdType t = 0; a && b && t < a->GetNumberOfTuples(); ++t)
      {
        for (int c = 0; c < a->GetNumberOfComponents(); ++c)
        {
          different += !(std::abs(a->GetComponent(t, c) - b->GetComponent(t, c)) <= tolerance);
        }
      }
    }
    const char* what = input == image ? "horizons" : "rays";
    std::cout << "ComputeNormals off (" << what << "): " << different << " values differ by more "
              << "than " << tolerance << "\n";
    Check(different == 0, std::string(what) + ": the same apertures without normals", different, 0);
    Check(kept->GetPointData()->GetNormals() && !left->GetPointData()->GetNormals(),
      std::string(what) + ": Normals added only when asked");
    if (input == image)
    {
      swept = kept->GetPointData()->GetNormals();
    }
  }
  vtkNew<vtkAperturePrecompute> rays;
  rays->SetInputData(image);
  rays->SetMethodToRays();
  rays->SetNumberOfRays(4);
  rays->Update();
  vtkDataArray* traced = rays->GetImageDataOutput()->GetPointData()->GetNormals();
  double worst = 0.0;
  for (vtkIdType t = 0; swept && traced && t < swept->GetNumberOfTuples(); ++t)
  {
    double a[3], b[3], c[3];
    swept->GetTuple(t, a);
    traced->GetTuple(t, b);
    vtkMath::Cross(a, b, c);
    worst = std::max(worst, std::atan2(vtkMath::Norm(c), vtkMath::Dot(a, b)));
  }
  std::cout << "the sweeps' normals against the rays': " << worst << " rad (max)\n";
  Check(worst < 1e-6, "the sweeps' normals are the rays' triangles' normals", worst, 1e-6);
}
}

int TestAperturePrecomputeHeightField(int argc, char* argv[])
{
  char* file = vtkTestUtilities::ExpandDataFileName(argc, argv, "Data/fuji-terrain-rgb.png");
  TestTexelsMatchVertices(file);
  TestConvergence(file);
  TestHorizonsMatchRays(file);
  TestKeptHorizons(file);
  TestHeightTypes(file);
  TestWithoutNormals(file);
  delete[] file;
  return vtkApertureTest::Result();
}
