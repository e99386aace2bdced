/*=========================================================================

  Program:   ApertureLighting
  Module:    TestAperturePrecompute.cxx

  Copyright (c) ApertureLighting developers
  All rights reserved.
  See LICENSE for details.

=========================================================================*/
// vtkAperturePrecompute on scenes with known answers: a plane sees the whole hemisphere, a
// vertex on the crease of a 90 degree concave corner sees half of it, the bottom of a cup sees
// its opening, a sphere is open outside and a box closed inside. Also occluders, composite
// input, MaximumDistance, huge coordinates, kept arrays, progress and abort.

#include "vtkAperturePrecompute.h"
#include "vtkApertureTestHarness.h"
#include "vtkSphericalCap.h"

#include "vtkAppendPolyData.h"
#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkCubeSource.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkReverseSense.h"
#include "vtkSphereSource.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTriangleFilter.h"

#include <cmath>
#include <iostream>
#include <string>

namespace
{
constexpr double Pi = vtkMath::Pi();
using vtkApertureTest::Check;

// A rectangle in the plane through `corner` spanned by u and v, split into nu x nv quads, with
// the given point normal.
void AddRectangle(vtkPoints* points, vtkCellArray* polys, vtkFloatArray* normals,
  const double corner[3], const double u[3], const double v[3], int nu, int nv, const double n[3])
{
  const vtkIdType first = points->GetNumberOfPoints();
  for (int j = 0; j <= nv; ++j)
  {
    for (int i = 0; i <= nu; ++i)
    {
      double p[3];
      for (int k = 0; k < 3; ++k)
      {
        p[k] = corner[k] + u[k] * i / nu + v[k] * j / nv;
      }
      points->InsertNextPoint(p);
      normals->InsertNextTuple(n);
    }
  }
  for (int j = 0; j < nv; ++j)
  {
    for (int i = 0; i < nu; ++i)
    {
      const vtkIdType a = first + i + j * (nu + 1);
      const vtkIdType quad[4] = { a, a + 1, a + 1 + nu + 1, a + nu + 1 };
      polys->InsertNextCell(4, quad);
    }
  }
}

vtkSmartPointer<vtkPolyData> Assemble(vtkPoints* points, vtkCellArray* polys, vtkFloatArray* n)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  pd->SetPolys(polys);
  n->SetName("Normals");
  pd->GetPointData()->SetNormals(n);
  return pd;
}

// Floor z = 0 (x >= 0) and wall x = 0 (z >= 0), both L wide and 2L long, folded from one grid so
// that they share the crease along the y axis. Point normals: +z on the floor, +x on the wall,
// halfway between on the crease. Returns the id of the crease point at the origin.
vtkSmartPointer<vtkPolyData> Corner(double L, vtkIdType* creaseMiddle)
{
  const int ns = 16, ny = 16; // s runs over [-L, L]: wall for s < 0, floor for s > 0
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  for (int j = 0; j <= ny; ++j)
  {
    const double y = -L + 2.0 * L * j / ny;
    for (int i = 0; i <= ns; ++i)
    {
      const double s = -L + 2.0 * L * i / ns;
      points->InsertNextPoint(s > 0 ? s : 0.0, y, s < 0 ? -s : 0.0);
      const double h = std::sqrt(0.5);
      normals->InsertNextTuple3(
        s < 0 ? 1.0 : (s > 0 ? 0.0 : h), 0.0, s > 0 ? 1.0 : (s < 0 ? 0.0 : h));
    }
  }
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < ns; ++i)
    {
      const vtkIdType a = i + j * (ns + 1);
      const vtkIdType quad[4] = { a, a + 1, a + 1 + ns + 1, a + ns + 1 };
      polys->InsertNextCell(4, quad);
    }
  }
  *creaseMiddle = ns / 2 + (ny / 2) * (ns + 1);
  return Assemble(points, polys, normals);
}

// An open cup: bottom disk of radius R at z = 0 fanned around point 0, wall of height H.
vtkSmartPointer<vtkPolyData> Cup(double R, double H, int segments)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  points->InsertNextPoint(0, 0, 0);
  normals->InsertNextTuple3(0, 0, 1);
  for (int level = 0; level <= 1; ++level)
  {
    for (int s = 0; s < segments; ++s)
    {
      const double a = 2.0 * Pi * s / segments;
      points->InsertNextPoint(R * std::cos(a), R * std::sin(a), level * H);
      normals->InsertNextTuple3(-std::cos(a), -std::sin(a), 0.0);
    }
  }
  for (int s = 0; s < segments; ++s)
  {
    const vtkIdType b0 = 1 + s, b1 = 1 + (s + 1) % segments;
    const vtkIdType fan[3] = { 0, b0, b1 };
    const vtkIdType wall[4] = { b0, b0 + segments, b1 + segments, b1 }; // facing the axis
    polys->InsertNextCell(3, fan);
    polys->InsertNextCell(4, wall);
  }
  return Assemble(points, polys, normals);
}

vtkDataArray* Array(vtkDataObject* data, const char* name)
{
  return vtkDataSet::SafeDownCast(data)->GetPointData()->GetArray(name);
}

double AngleTo(vtkDataArray* bent, vtkIdType id, const double direction[3])
{
  double b[3];
  bent->GetTuple(id, b);
  return vtkMath::AngleBetweenVectors(b, direction);
}

void TestPlane()
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  const double corner[3] = { -5, -5, 0 }, u[3] = { 10, 0, 0 }, v[3] = { 0, 10, 0 },
               n[3] = { 0, 0, 1 };
  AddRectangle(points, polys, normals, corner, u, v, 20, 20, n);
  auto plane = Assemble(points, polys, normals);

  vtkNew<vtkAperturePrecompute> filter;
  filter->SetInputData(plane);
  filter->ComputeAmbientOcclusionOn();
  filter->Update();
  vtkDataArray* radius = Array(filter->GetOutput(), "ApertureRadius");
  vtkDataArray* bent = Array(filter->GetOutput(), "BentNormal");
  vtkDataArray* ao = Array(filter->GetOutput(), "AmbientOcclusion");
  double worstRadius = 0.0, worstBent = 0.0, worstAO = 0.0;
  for (vtkIdType i = 0; i < plane->GetNumberOfPoints(); ++i)
  {
    worstRadius = std::max(worstRadius, std::abs(radius->GetTuple1(i) - 0.5 * Pi));
    worstBent = std::max(worstBent, AngleTo(bent, i, n));
    worstAO = std::max(worstAO, std::abs(ao->GetTuple1(i) - 1.0));
  }
  std::cout << "Plane: max |r - pi/2| = " << worstRadius << ", max bent angle = " << worstBent
            << " rad, max |AO - 1| = " << worstAO << "\n";
  Check(worstRadius < 1e-6, "plane sees the whole hemisphere", worstRadius, 0);
  // The stratified mean of 256 directions is within a few mrad of the normal.
  Check(worstBent < 0.01, "plane: bent normal = normal", worstBent, 0);
  Check(worstAO < 0.01, "plane: ambient occlusion 1", worstAO, 0);
}

void TestCorner(const double shift[3], double* radiusOut)
{
  vtkIdType crease;
  auto corner = Corner(100.0, &crease);
  vtkNew<vtkTransform> move;
  move->Translate(shift);
  vtkNew<vtkTransformPolyDataFilter> moved;
  moved->SetInputData(corner);
  moved->SetTransform(move);
  moved->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);

  vtkNew<vtkAperturePrecompute> filter;
  filter->SetInputConnection(moved->GetOutputPort());
  filter->SetNumberOfRays(4096);
  filter->Update();
  const double r = Array(filter->GetOutput(), "ApertureRadius")->GetTuple1(crease);
  const double area = vtkSphericalCap::SolidAngleFromCapRadius(r);
  const double diagonal[3] = { std::sqrt(0.5), 0.0, std::sqrt(0.5) };
  const double angle = AngleTo(Array(filter->GetOutput(), "BentNormal"), crease, diagonal);
  std::cout << "Corner at offset " << shift[0] << ": visible solid angle " << area
            << " (pi = " << Pi << "), bent normal " << vtkMath::DegreesFromRadians(angle)
            << " deg from the 45 deg diagonal\n";
  Check(std::abs(area - Pi) < 0.01 * Pi, "corner crease sees half the hemisphere", area, Pi);
  Check(angle < 0.01, "corner crease: bent normal at 45 degrees", angle, 0);
  *radiusOut = r;
}

void TestCup()
{
  const double R = 1.0, H = 1.5;
  const double alpha = std::atan(R / H);
  vtkNew<vtkAperturePrecompute> filter;
  filter->SetInputData(Cup(R, H, 256));
  filter->SetNumberOfRays(4096);
  filter->Update();
  const double area = vtkSphericalCap::SolidAngleFromCapRadius(
    Array(filter->GetOutput(), "ApertureRadius")->GetTuple1(0));
  const double want = 2.0 * Pi * (1.0 - std::cos(alpha));
  const double up[3] = { 0, 0, 1 };
  const double angle = AngleTo(Array(filter->GetOutput(), "BentNormal"), 0, up);
  std::cout << "Cup bottom: visible solid angle " << area << ", 2 pi (1 - cos alpha) = " << want
            << ", bent normal " << angle << " rad off the axis\n";
  Check(std::abs(area - want) < 0.02 * want, "cup bottom sees its opening", area, want);
  Check(angle < 0.01, "cup bottom: bent normal on the axis", angle, 0);
}

void TestSphereAndBox()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);
  vtkNew<vtkAperturePrecompute> filter;
  filter->SetInputConnection(sphere->GetOutputPort());
  filter->Update();
  double range[2];
  Array(filter->GetOutput(), "ApertureRadius")->GetRange(range);
  std::cout << "Outside a sphere: radius in [" << range[0] << ", " << range[1] << "]\n";
  Check(range[0] > 0.5 * Pi - 1e-6, "outside of a sphere is open", range[0], 0.5 * Pi);

  // Inside a closed box: faces with inward normals.
  vtkNew<vtkCubeSource> cube;
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(cube->GetOutputPort());
  vtkNew<vtkReverseSense> inward;
  inward->SetInputConnection(triangles->GetOutputPort());
  inward->ReverseCellsOn();
  inward->ReverseNormalsOn();
  filter->SetInputConnection(inward->GetOutputPort());
  filter->Update();
  auto* box = vtkPolyData::SafeDownCast(filter->GetOutput());
  Array(box, "ApertureRadius")->GetRange(range);
  double worstBent = 0.0;
  for (vtkIdType i = 0; i < box->GetNumberOfPoints(); ++i)
  {
    double n[3];
    box->GetPointData()->GetNormals()->GetTuple(i, n);
    worstBent = std::max(worstBent, AngleTo(Array(box, "BentNormal"), i, n));
  }
  std::cout << "Inside a closed box: radius in [" << range[0] << ", " << range[1]
            << "], bent normal within " << worstBent << " rad of the normal\n";
  Check(range[1] == 0.0, "inside a closed box is closed", range[1], 0);
  Check(worstBent < 1e-6, "a closed aperture keeps the normal as its axis", worstBent, 0);
}

// Two spheres side by side: as a composite input each shades the other, exactly as when the
// other is given on the occluder port; and each is darker than alone.
void TestOccludersAndComposite()
{
  vtkNew<vtkSphereSource> a;
  a->SetThetaResolution(32);
  a->SetPhiResolution(16);
  vtkNew<vtkSphereSource> b;
  b->SetThetaResolution(32);
  b->SetPhiResolution(16);
  b->SetCenter(1.2, 0, 0);
  a->Update();
  b->Update();

  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(2);
  blocks->SetBlock(0, a->GetOutput());
  blocks->SetBlock(1, b->GetOutput());
  vtkNew<vtkAperturePrecompute> composite;
  composite->SetInputData(blocks);
  composite->Update();
  auto* out = vtkMultiBlockDataSet::SafeDownCast(composite->GetOutputDataObject(0));

  for (int leaf = 0; leaf < 2; ++leaf)
  {
    vtkPolyData* self = leaf == 0 ? a->GetOutput() : b->GetOutput();
    vtkPolyData* other = leaf == 0 ? b->GetOutput() : a->GetOutput();
    vtkNew<vtkAperturePrecompute> withOccluder;
    withOccluder->SetInputData(self);
    withOccluder->AddOccluderData(other);
    withOccluder->Update();
    vtkNew<vtkAperturePrecompute> alone;
    alone->SetInputData(self);
    alone->Update();

    vtkDataArray* fromComposite = Array(out->GetBlock(leaf), "ApertureRadius");
    vtkDataArray* fromOccluder = Array(withOccluder->GetOutput(), "ApertureRadius");
    vtkDataArray* fromAlone = Array(alone->GetOutput(), "ApertureRadius");
    double maxDiff = 0.0, sumOccluded = 0.0, sumAlone = 0.0;
    for (vtkIdType i = 0; i < self->GetNumberOfPoints(); ++i)
    {
      maxDiff =
        std::max(maxDiff, std::abs(fromComposite->GetTuple1(i) - fromOccluder->GetTuple1(i)));
      sumOccluded += fromOccluder->GetTuple1(i);
      sumAlone += fromAlone->GetTuple1(i);
    }
    const vtkIdType n = self->GetNumberOfPoints();
    std::cout << "Sphere " << leaf << ": mean radius alone " << sumAlone / n
              << ", next to the other " << sumOccluded / n
              << ", composite vs occluder port max difference " << maxDiff << "\n";
    Check(maxDiff == 0.0, "composite leaves occlude each other like port-1 occluders", maxDiff, 0);
    Check(sumOccluded < sumAlone - 0.01 * n, "an occluder darkens", sumOccluded, sumAlone);
  }
}

// A wall 2 units away closes part of a plane's hemisphere, unless rays stop before it.
void TestMaximumDistance()
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  const double floorCorner[3] = { -1, -50, 0 }, fu[3] = { 2, 0, 0 }, fv[3] = { 0, 100, 0 };
  const double up[3] = { 0, 0, 1 }, west[3] = { -1, 0, 0 };
  AddRectangle(points, polys, normals, floorCorner, fu, fv, 2, 2, up);
  const double wallCorner[3] = { 2, -50, 0 }, wu[3] = { 0, 0, 50 };
  AddRectangle(points, polys, normals, wallCorner, wu, fv, 2, 2, west);
  auto scene = Assemble(points, polys, normals);
  vtkNew<vtkAperturePrecompute> filter;
  filter->SetInputData(scene);
  filter->Update();
  const vtkIdType middle = 4; // (0, 0, 0) on the floor
  const double near = Array(filter->GetOutput(), "ApertureRadius")->GetTuple1(middle);
  filter->SetMaximumDistance(1.5); // not applied until LimitDistance is on
  filter->Update();
  const double unlimited = Array(filter->GetOutput(), "ApertureRadius")->GetTuple1(middle);
  filter->LimitDistanceOn();
  filter->Update();
  const double far = Array(filter->GetOutput(), "ApertureRadius")->GetTuple1(middle);
  std::cout << "Floor point 2 units from a wall: radius " << near
            << ", with MaximumDistance 1.5: " << far << "\n";
  Check(near < 0.5 * Pi - 0.1, "the wall occludes", near, 0.5 * Pi);
  Check(unlimited == near, "MaximumDistance waits for LimitDistance", unlimited, near);
  Check(std::abs(far - 0.5 * Pi) < 1e-6, "rays stop before the wall", far, 0.5 * Pi);
}

// Every input array is kept, the input is untouched, progress goes 0 -> 1, and an abort
// stops within a batch.
void TestPipelineBehaviour()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(64);
  sphere->Update();
  vtkNew<vtkPolyData> input;
  input->DeepCopy(sphere->GetOutput());
  vtkNew<vtkDoubleArray> pointValues;
  pointValues->SetName("Temperature");
  pointValues->SetNumberOfTuples(input->GetNumberOfPoints());
  pointValues->FillValue(37.0);
  input->GetPointData()->AddArray(pointValues);
  vtkNew<vtkIntArray> cellValues;
  cellValues->SetName("Label");
  cellValues->SetNumberOfTuples(input->GetNumberOfCells());
  cellValues->FillValue(3);
  input->GetCellData()->AddArray(cellValues);
  const vtkMTimeType inputTime = input->GetMTime();
  const int inputArrays = input->GetPointData()->GetNumberOfArrays();

  vtkNew<vtkAperturePrecompute> filter;
  filter->SetInputData(input);
  filter->SetBentNormalArrayName("Bent");
  filter->SetApertureRadiusArrayName("Radius");
  std::vector<double> progress;
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&progress);
  onProgress->SetCallback([](vtkObject*, unsigned long, void* client, void* call)
    { static_cast<std::vector<double>*>(client)->push_back(*static_cast<double*>(call)); });
  filter->AddObserver(vtkCommand::ProgressEvent, onProgress);
  filter->SetNumberOfRays(1024); // 1024 points per batch: several batches
  filter->Update();
  auto* out = vtkPolyData::SafeDownCast(filter->GetOutput());
  Check(out->GetPointData()->GetArray("Temperature") && out->GetCellData()->GetArray("Label") &&
      out->GetPointData()->GetArray("Bent") && out->GetPointData()->GetArray("Radius") &&
      out->GetPointData()->GetNormals(),
    "output keeps the input's arrays and adds its own", 0, 1);
  Check(input->GetMTime() == inputTime &&
      input->GetPointData()->GetNumberOfArrays() == inputArrays &&
      !input->GetPointData()->GetArray("Bent"),
    "the input is not modified", input->GetPointData()->GetNumberOfArrays(), inputArrays);
  bool increasing = progress.size() >= 3 && progress.front() == 0.0 && progress.back() == 1.0;
  for (size_t i = 1; i < progress.size(); ++i)
  {
    increasing = increasing && progress[i] >= progress[i - 1];
  }
  std::cout << progress.size() << " progress events\n";
  Check(increasing, "progress events go from 0 to 1", progress.size(), 3);

  // Abort at the first batch: the filter stops and leaves an empty output.
  int batches = 0;
  vtkNew<vtkCallbackCommand> abort;
  abort->SetClientData(&batches);
  abort->SetCallback(
    [](vtkObject* caller, unsigned long, void* client, void* call)
    {
      if (*static_cast<double*>(call) > 0.0)
      {
        ++*static_cast<int*>(client);
        vtkAlgorithm::SafeDownCast(caller)->SetAbortExecute(1);
      }
    });
  filter->RemoveAllObservers();
  filter->AddObserver(vtkCommand::ProgressEvent, abort);
  filter->SetSeed(1); // modified, so that it runs again
  filter->Update();
  std::cout << "Aborted after " << batches << " batch(es), output has "
            << filter->GetPolyDataOutput()->GetNumberOfPoints() << " points\n";
  Check(batches == 1 && filter->GetPolyDataOutput()->GetNumberOfPoints() == 0,
    "abort stops after the current batch", batches, 1);
}
}

int TestAperturePrecompute(int, char*[])
{
  TestPlane();
  double r0, r1;
  const double here[3] = { 0, 0, 0 }, utm[3] = { 5.0e6, 4.0e6, 1.2e3 };
  TestCorner(here, &r0);
  TestCorner(utm, &r1);
  std::cout << "Corner radius at the origin " << r0 << ", at UTM coordinates " << r1 << "\n";
  Check(std::abs(r0 - r1) < 0.005, "UTM-sized coordinates give the same aperture", r1, r0);
  TestCup();
  TestSphereAndBox();
  TestOccludersAndComposite();
  TestMaximumDistance();
  TestPipelineBehaviour();
  return vtkApertureTest::Result();
}
