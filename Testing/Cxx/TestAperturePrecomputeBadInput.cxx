/*=========================================================================

  Program:   ApertureLighting
  Module:    TestAperturePrecomputeBadInput.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkAperturePrecompute on bad input: each case gives a clear error (and a failed RequestData) or
// a warning with defined results, never a crash, and leaves the input as it was.

#include "vtkAperturePrecompute.h"
#include "vtkApertureTestHarness.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTestErrorObserver.h"
#include "vtkTriangleFilter.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <string>

namespace
{
constexpr double Pi = vtkMath::Pi();
using vtkApertureTest::Check;

// Runs the filter with observers on it and its executive; returns whether Update succeeded.
struct Run
{
  vtkNew<vtkAperturePrecompute> Filter;
  vtkNew<vtkTest::ErrorObserver> Observer;
  vtkNew<vtkTest::ErrorObserver> ExecutiveObserver;

  explicit Run(vtkDataObject* input)
  {
    this->Filter->SetInputData(input);
    this->Filter->AddObserver(vtkCommand::ErrorEvent, this->Observer);
    this->Filter->AddObserver(vtkCommand::WarningEvent, this->Observer);
    this->Filter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this->ExecutiveObserver);
  }
  bool Update() { return this->Filter->GetExecutive()->Update() != 0; }
  vtkDataArray* Radius()
  {
    return vtkDataSet::SafeDownCast(this->Filter->GetOutputDataObject(0))
      ->GetPointData()
      ->GetArray("ApertureRadius");
  }
};

void ExpectError(vtkDataObject* input, const std::string& message, const std::string& what)
{
  const int arrays = vtkDataSet::SafeDownCast(input)
    ? vtkDataSet::SafeDownCast(input)->GetPointData()->GetNumberOfArrays()
    : 0;
  Run run(input);
  const bool ok = run.Update();
  const bool named =
    run.Observer->GetError() && run.Observer->GetErrorMessage().find(message) != std::string::npos;
  std::cout << what << ": " << (named ? run.Observer->GetErrorMessage() : "(no matching error)");
  Check(!ok && named, what + ": error containing \"" + message + "\"");
  Check(!vtkDataSet::SafeDownCast(input) ||
      vtkDataSet::SafeDownCast(input)->GetPointData()->GetNumberOfArrays() == arrays,
    what + ": input untouched");
}

// A 10 x 10 plane in z = 0, as triangles.
vtkSmartPointer<vtkPolyData> Plane()
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(10, 10);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(plane->GetOutputPort());
  triangles->Update();
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->DeepCopy(triangles->GetOutput());
  pd->GetPointData()->Initialize(); // no normals: computed
  return pd;
}

void TestErrors()
{
  vtkNew<vtkPolyData> empty;
  ExpectError(empty, "empty", "empty polydata");

  vtkNew<vtkPolyData> pointsOnly;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  pointsOnly->SetPoints(points);
  ExpectError(pointsOnly, "no polygons", "points without cells");

  vtkNew<vtkPolyData> lines;
  lines->SetPoints(points);
  vtkNew<vtkCellArray> lineCells;
  const vtkIdType line[3] = { 0, 1, 2 };
  lineCells->InsertNextCell(3, line);
  lines->SetLines(lineCells);
  ExpectError(lines, "no polygons", "only lines");

  vtkNew<vtkImageData> volume;
  volume->SetDimensions(4, 4, 4);
  volume->AllocateScalars(VTK_FLOAT, 1);
  ExpectError(volume, "2D grid", "3D image");

  vtkNew<vtkImageData> noScalars;
  noScalars->SetDimensions(4, 4, 1);
  ExpectError(noScalars, "no point scalars", "image without scalars");

  vtkNew<vtkImageData> rgb;
  rgb->SetDimensions(4, 4, 1);
  rgb->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  ExpectError(rgb, "one component", "image with RGB scalars");

  vtkNew<vtkImageData> line1D;
  line1D->SetDimensions(5, 1, 1);
  line1D->AllocateScalars(VTK_FLOAT, 1);
  ExpectError(line1D, "2D grid", "1D image");

  vtkNew<vtkMultiBlockDataSet> mixed;
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  mixed->SetNumberOfBlocks(2);
  mixed->SetBlock(0, Plane());
  mixed->SetBlock(1, grid);
  ExpectError(mixed, "vtkPolyData leaves", "composite with an unstructured grid");

  // The setters clamp RayOffset but let NaN through.
  Run nanOffset(Plane());
  nanOffset.Filter->SetRayOffset(std::numeric_limits<double>::quiet_NaN());
  Check(!nanOffset.Update() &&
      nanOffset.Observer->GetErrorMessage().find("RayOffset") != std::string::npos,
    "a NaN RayOffset is an error");

  // An Earth radius that is negative, NaN or infinite: an error on a height field, which sweeps
  // horizons over it, and with rays too.
  vtkNew<vtkImageData> dem;
  dem->SetDimensions(8, 8, 1);
  dem->AllocateScalars(VTK_FLOAT, 1);
  dem->GetPointData()->GetScalars()->Fill(0.0);
  const auto mesh = Plane();
  for (const double radius :
    { -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity() })
  {
    for (vtkDataObject* input :
      { static_cast<vtkDataObject*>(dem), static_cast<vtkDataObject*>(mesh) })
    {
      Run earth(input);
      earth.Filter->SetEarthRadius(radius);
      Check(!earth.Update() &&
          earth.Observer->GetErrorMessage().find("Earth radius") != std::string::npos,
        "Earth radius " + std::to_string(radius) + ": an error");
    }
  }

  // Embree refuses a malformed device configuration.
  Run embree(Plane());
  embree.Filter->SetEmbreeConfiguration("threads=banana");
  Check(!embree.Update() && embree.Observer->GetErrorMessage().find("Embree") != std::string::npos,
    "Embree failure reaches vtkErrorMacro");
  std::cout << "Embree failure: " << embree.Observer->GetErrorMessage();
}

void TestWarnings()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();

  // NaN, infinite and vast points (beyond what Embree traces): closed caps with a defined axis,
  // the rest of the plane open.
  auto plane = Plane();
  plane->GetPoints()->SetPoint(60, nan, 0, 0);
  plane->GetPoints()->SetPoint(17, 0, inf, 0);
  plane->GetPoints()->SetPoint(33, 0, 0, -3e38);
  Run nonFinite(plane);
  Check(nonFinite.Update() && nonFinite.Observer->GetWarning() &&
      nonFinite.Observer->GetWarningMessage().find("not finite") != std::string::npos,
    "NaN/Inf points: a warning");
  vtkDataArray* radius = nonFinite.Radius();
  vtkDataArray* bent = vtkDataSet::SafeDownCast(nonFinite.Filter->GetOutputDataObject(0))
                         ->GetPointData()
                         ->GetArray("BentNormal");
  bool rest = true;
  for (vtkIdType i = 0; i < plane->GetNumberOfPoints(); ++i)
  {
    if (i != 60 && i != 17 && i != 33)
    {
      rest = rest && std::abs(radius->GetTuple1(i) - 0.5 * Pi) < 1e-6;
    }
  }
  double axis[3];
  bent->GetTuple(60, axis);
  Check(radius->GetTuple1(60) == 0.0 && radius->GetTuple1(17) == 0.0 &&
      radius->GetTuple1(33) == 0.0 && axis[2] == 1.0,
    "NaN/Inf/vast points get a closed cap around +z");
  Check(rest, "the other points are right");

  // An Earth radius on a mesh: rays over the mesh as it is, and a warning.
  Run curved(Plane());
  curved.Filter->SetEarthRadius(6371000.0);
  Check(
    curved.Update() && curved.Observer->GetWarningMessage().find("curvature") != std::string::npos,
    "an Earth radius with rays: a warning");

  // Degenerate and zero-area triangles: ignored as occluders; points only they use are closed,
  // unless they lie where a vertex of the surface is (then they are that surface point).
  plane = Plane();
  const vtkIdType lonely = plane->GetPoints()->InsertNextPoint(0.23, 0.27, 0.0);
  const vtkIdType welded = plane->GetPoints()->InsertNextPoint(0.2, 0.2, 0.0);
  const vtkIdType degenerate[4][3] = { { 0, 0, 1 }, { 0, 1, 2 }, { lonely, lonely, lonely },
    { welded, welded, welded } };
  for (const auto& cell : degenerate)
  {
    plane->GetPolys()->InsertNextCell(3, cell);
  }
  Run zeroArea(plane);
  Check(zeroArea.Update() &&
      zeroArea.Observer->GetWarningMessage().find("no defined normal") != std::string::npos,
    "degenerate triangles: a warning for the point only they use");
  Check(std::abs(zeroArea.Radius()->GetTuple1(5) - 0.5 * Pi) < 1e-6 &&
      zeroArea.Radius()->GetTuple1(lonely) == 0.0,
    "degenerate triangles: the plane stays open, the lonely point is closed");
  Check(std::abs(zeroArea.Radius()->GetTuple1(welded) - 0.5 * Pi) < 1e-6,
    "a degenerate triangle's point on a surface vertex shares its aperture");

  // Duplicate points and a duplicated surface: rays start above the coincident copy.
  plane = Plane();
  vtkNew<vtkPolyData> doubled;
  vtkNew<vtkPoints> both;
  both->DeepCopy(plane->GetPoints());
  const vtkIdType n = both->GetNumberOfPoints();
  for (vtkIdType i = 0; i < n; ++i)
  {
    both->InsertNextPoint(plane->GetPoint(i));
  }
  vtkNew<vtkCellArray> cells;
  cells->DeepCopy(plane->GetPolys());
  vtkIdType npts;
  const vtkIdType* ids;
  for (plane->GetPolys()->InitTraversal(); plane->GetPolys()->GetNextCell(npts, ids);)
  {
    const vtkIdType copy[3] = { ids[0] + n, ids[1] + n, ids[2] + n };
    cells->InsertNextCell(3, copy);
  }
  doubled->SetPoints(both);
  doubled->SetPolys(cells);
  Run duplicates(doubled);
  double range[2];
  Check(duplicates.Update(), "duplicate surface runs");
  duplicates.Radius()->GetRange(range);
  Check(range[0] > 0.5 * Pi - 1e-6, "a coincident copy of the surface does not close it");

  // Non-manifold edge: three fins sharing the edge x = 0, z in [0, 1].
  vtkNew<vtkPolyData> fins;
  vtkNew<vtkPoints> finPoints;
  finPoints->InsertNextPoint(0, 0, 0);
  finPoints->InsertNextPoint(0, 0, 1);
  vtkNew<vtkCellArray> finCells;
  for (int k = 0; k < 3; ++k)
  {
    const double a = 2.0 * Pi * k / 3.0;
    finPoints->InsertNextPoint(std::cos(a), std::sin(a), 0);
    finPoints->InsertNextPoint(std::cos(a), std::sin(a), 1);
    const vtkIdType quad[4] = { 0, 2 + 2 * k, 3 + 2 * k, 1 };
    finCells->InsertNextCell(4, quad);
  }
  fins->SetPoints(finPoints);
  fins->SetPolys(finCells);
  Run nonManifold(fins);
  Check(nonManifold.Update(), "non-manifold edges run");
  nonManifold.Radius()->GetRange(range);
  Check(std::isfinite(range[0]) && std::isfinite(range[1]) && range[1] <= 0.5 * Pi + 1e-6,
    "non-manifold edges give finite apertures");

  // Given normals that contradict the winding: used as given, with a warning.
  plane = Plane();
  vtkNew<vtkFloatArray> flipped;
  flipped->SetName("Normals");
  flipped->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < plane->GetNumberOfPoints(); ++i)
  {
    flipped->InsertNextTuple3(0, 0, i % 2 ? -1.0 : 1.0);
  }
  plane->GetPointData()->SetNormals(flipped);
  Run inconsistent(plane);
  Check(inconsistent.Update() &&
      inconsistent.Observer->GetWarningMessage().find("against the winding") != std::string::npos,
    "inconsistent normals: a warning");
  Check(std::abs(inconsistent.Radius()->GetTuple1(0) - 0.5 * Pi) < 1e-6,
    "normals along the winding: open");
  std::cout << "Flipped normal's aperture: " << inconsistent.Radius()->GetTuple1(1) << "\n";

  // Normals with too few tuples are ignored and replaced.
  plane = Plane();
  vtkNew<vtkDoubleArray> wrong;
  wrong->SetName("Normals");
  wrong->SetNumberOfComponents(3);
  wrong->SetNumberOfTuples(plane->GetNumberOfPoints() - 7);
  wrong->Fill(0.0);
  plane->GetPointData()->SetNormals(wrong);
  Run wrongSize(plane);
  Check(wrongSize.Update() &&
      vtkDataSet::SafeDownCast(wrongSize.Filter->GetOutputDataObject(0))
          ->GetPointData()
          ->GetNormals()
          ->GetNumberOfTuples() == plane->GetNumberOfPoints() &&
      plane->GetPointData()->GetNormals() == wrong,
    "normals of the wrong size are replaced in the output only");
}

void TestClamping()
{
  vtkNew<vtkAperturePrecompute> filter;
  filter->SetNumberOfRays(0);
  Check(filter->GetNumberOfRays() == 1, "NumberOfRays clamps to 1");
  filter->SetNumberOfRays(1 << 30);
  Check(filter->GetNumberOfRays() == 65536, "NumberOfRays clamps to 65536");
  filter->SetRayOffset(-1.0);
  Check(filter->GetRayOffset() == 0.0, "RayOffset clamps to 0");
  filter->SetRayOffset(7.0);
  Check(filter->GetRayOffset() == 1.0, "RayOffset clamps to 1");
  filter->SetMaximumDistance(-3.0);
  Check(filter->GetMaximumDistance() == 0.0, "MaximumDistance clamps to 0");
  filter->SetSampling(9);
  Check(filter->GetSampling() == vtkAperturePrecompute::RANDOM, "Sampling clamps");
  // One ray per point still gives a defined result.
  filter->SetNumberOfRays(1);
  filter->SetMaximumDistance(VTK_DOUBLE_MAX);
  filter->SetInputData(Plane());
  filter->Update();
  double range[2];
  filter->GetPolyDataOutput()->GetPointData()->GetArray("ApertureRadius")->GetRange(range);
  Check(std::abs(range[0] - 0.5 * Pi) < 1e-6, "one ray per point on a plane: open");
}
}

int TestAperturePrecomputeBadInput(int, char*[])
{
  TestErrors();
  TestWarnings();
  TestClamping();
  return vtkApertureTest::Result();
}
